"""Reports as typed objects: each key of a command's ``--json`` output
(docs/cli.md, units in the key names) is an attribute; lists of numbers
are NumPy arrays, matrices 2-D arrays, objects nested reports and lists of
objects :class:`Table`\\ s (a column per key as a NumPy array, a row per
entry). A report is also the mapping of the CLI's JSON, so
``result["cage_speed_rpm"]`` and ``result == cli_json`` keep working."""

from __future__ import annotations

from typing import Any, Iterator, Mapping, Optional, Sequence, Union

import numpy as np


def _is_number(x: Any) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def _view(value: Any) -> Any:
    """A JSON value as the attribute shows it."""
    if isinstance(value, dict):
        return Report(value)
    if isinstance(value, list):
        if value and all(isinstance(v, dict) for v in value):
            return Table(value)
        if value and all(_is_number(v) or v is None for v in value):
            return np.array([np.nan if v is None else v for v in value], dtype=float)
        if value and all(isinstance(v, list) and all(_is_number(x) for x in v) for v in value) \
                and len({len(v) for v in value}) == 1:
            return np.array(value, dtype=float)
    return value


class Report(Mapping):
    """A command's report: its JSON keys as attributes (``r.cage_speed_rpm``),
    and as a mapping of the raw JSON values (``r["balls"][0]``)."""

    __slots__ = ("_data",)

    def __init__(self, data: Mapping[str, Any]):
        object.__setattr__(self, "_data", dict(data))

    def __getattr__(self, name: str) -> Any:
        try:
            return _view(self._data[name])
        except KeyError:
            raise AttributeError(
                f"{type(self).__name__} has no {name!r}; keys: {', '.join(self._data)}"
            ) from None

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(f"{type(self).__name__} is read-only")

    def __getitem__(self, key: str) -> Any:
        return self._data[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._data)

    def __len__(self) -> int:
        return len(self._data)

    def __dir__(self) -> list:
        return sorted(set(super().__dir__()) | set(self._data))

    def __reduce__(self):
        return (type(self), (self._data,))

    def to_dict(self) -> dict:
        """The raw JSON data (a copy)."""
        return dict(self._data)

    def __repr__(self) -> str:
        keys = ", ".join(list(self._data)[:6])
        more = ", ..." if len(self._data) > 6 else ""
        return f"<rolldyn.{type(self).__name__}: {keys}{more}>"


class Table(Sequence):
    """Rows of a report (``balls``, ``lines``, ``peaks`` ...): ``t[i]`` is a
    row (a :class:`Report`), ``t.load_inner_n`` a column as a NumPy array
    (None → NaN), ``len(t)`` the row count."""

    __slots__ = ("_rows",)

    def __init__(self, rows: Sequence[Mapping[str, Any]]):
        object.__setattr__(self, "_rows", [dict(r) for r in rows])

    @property
    def columns(self) -> list:
        """The keys of the rows, in order of first appearance."""
        seen: dict = {}
        for row in self._rows:
            seen.update(dict.fromkeys(row))
        return list(seen)

    def __getattr__(self, name: str) -> Any:
        if not self._rows or all(name not in r for r in self._rows):
            raise AttributeError(f"Table has no column {name!r}; columns: {', '.join(self.columns)}")
        values = [r.get(name) for r in self._rows]
        if all(_is_number(v) or v is None for v in values):
            return np.array([np.nan if v is None else v for v in values], dtype=float)
        return [_view(v) for v in values]

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("Table is read-only")

    def __getitem__(self, index: Any) -> Any:
        if isinstance(index, slice):
            return Table(self._rows[index])
        return Report(self._rows[index])

    def __len__(self) -> int:
        return len(self._rows)

    def __eq__(self, other: Any) -> bool:
        if isinstance(other, Table):
            return self._rows == other._rows
        return isinstance(other, list) and self._rows == other

    def __reduce__(self):
        return (Table, (self._rows,))

    def __dir__(self) -> list:
        return sorted(set(super().__dir__()) | set(self.columns))

    def to_pandas(self):
        """The rows as a pandas DataFrame (needs pandas)."""
        import pandas as pd
        return pd.DataFrame(self._rows)

    def __repr__(self) -> str:
        return f"<rolldyn.Table: {len(self)} rows x {', '.join(self.columns[:6])}>"


class QuasiStaticResult(Report):
    """``rolldyn quasistatic``: the equilibrium (keys in docs/cli.md). Main
    attributes: ``balls`` (a :class:`Table` per ball: ``load_inner_n``,
    ``contact_angle_outer_deg`` ...), ``stiffness_matrix`` and
    ``compliance_matrix`` (5×5 NumPy arrays over x, y, z, θ_y, θ_z, SI),
    ``cage_speed_rpm``, ``displacement`` (the ring's five displacements),
    ``rating_life``; a bearing set's solution has ``arrangement``."""

    # fields: QuasiStaticResult (scripts/python-report-fields.py)
    speed_rpm: float
    raceway_control: str
    force_x_n: float
    force_y_n: float
    force_z_n: float
    moment_y_n_m: float
    moment_z_n_m: float
    cage_speed_rpm: float
    cage_speed_ratio: float
    axial_displacement_m: float
    radial_displacement_y_m: float
    radial_displacement_z_m: float
    tilt_y_rad: float
    tilt_z_rad: float
    stiffness_n_per_m: Report
    tilt_stiffness_n_m_per_rad: Report
    stiffness_matrix: np.ndarray
    compliance_matrix: np.ndarray
    conventional_stiffness: Report
    radial_load_n: float
    radial_load_angle_deg: float
    first_ball_azimuth_deg: float
    held_displacements: list
    reaction_force_x_n: Optional[float]
    reaction_force_y_n: Optional[float]
    reaction_force_z_n: Optional[float]
    reaction_moment_y_n_m: Optional[float]
    reaction_moment_z_n_m: Optional[float]
    orbital_speed_min_rpm: float
    orbital_speed_max_rpm: float
    iterations: int
    relative_residual: float
    balls: Table
    rating_life: Report
    films: Optional[Table]
    film_in_approach: bool
    stiffness_matrix_without_film: Optional[np.ndarray]
    conventional_stiffness_without_film: Optional[Report]
    modes: Optional[Report]
    fits: Optional[Report]
    arrangement: Report
    # fields: end

    @property
    def displacement(self) -> Optional[np.ndarray]:
        """Ring displacement (x, y, z \\[m\\], θ_y, θ_z \\[rad\\]); None for a
        bearing set (its bearings' are in ``arrangement.bearings``)."""
        keys = ("axial_displacement_m", "radial_displacement_y_m", "radial_displacement_z_m",
                "tilt_y_rad", "tilt_z_rad")
        if not all(k in self._data for k in keys):
            return None
        return np.array([self._data[k] for k in keys], dtype=float)


class PowerResult(Report):
    """``rolldyn power``: friction power by component at the Jones–Harris
    equilibrium (Harris's local method; keys in docs/cli.md)."""

    # fields: PowerResult (scripts/python-report-fields.py)
    speed_rpm: float
    cage_speed_rpm: float
    sliding_friction: float
    hysteresis_coefficient: float
    pocket_friction: float
    inner: Report
    outer: Report
    cage_land_w: float
    ball_pocket_w: float
    ball_drag_w: float
    cage_drag_w: float
    seals_w: float
    churning_w: float
    power_loss_w: float
    friction_torque_n_m: float
    friction_torque_split_n_m: Report
    models: Report
    kind: str
    bearings: Table
    # fields: end


class ThermalResult(Report):
    """``rolldyn thermal``: the bearing's temperatures coupled to its power
    loss, and the warm-up when asked; of a bearing set, every bearing's and
    the preload at the operating temperatures (keys in docs/cli.md)."""

    # fields: ThermalResult (scripts/python-report-fields.py)
    converged: bool
    iterations: int
    history_k: np.ndarray
    temperatures_c: Report
    heat_generated_w: float
    heat_to_ambient_w: float
    heat_to_oil_w: float
    oil_viscosity_pa_s: float
    oil_flow_m3_s: float
    reference_clearance_m: float
    operating_clearance_m: float
    power: Report
    transient: Optional[Table]
    warnings: list
    kind: str
    mounting_preload_n: float
    reference_preload_at_speed_n: float
    operating_preload_at_speed_n: float
    axial_strain: float
    bearings: Table
    # fields: end


class Frequencies(Report):
    """``rolldyn frequencies``: cage, BPFO, BPFI, ball spin and waviness
    lines (keys in docs/cli.md)."""

    # fields: Frequencies (scripts/python-report-fields.py)
    speed_rpm: float
    contact_angle_deg: float
    shaft_hz: float
    cage_hz: float
    cage_speed_rpm: float
    bpfo_hz: float
    bpfi_hz: float
    ball_spin_hz: float
    ball_defect_hz: float
    orders: Report
    waviness: Table
    # fields: end


class ContactResult(Report):
    """``rolldyn contact``: one Hertz contact and its film (keys in
    docs/cli.md), e.g. ``semi_major_m``, ``max_pressure_pa``."""

    # fields: ContactResult (scripts/python-report-fields.py)
    load_n: float
    contact_stiffness_model: str
    effective_modulus_pa: float
    inner: Report
    outer: Report
    # fields: end


class TractionResult(Report):
    """``rolldyn traction``: one contact's traction: forces, spin moment,
    power, stick fraction (keys in docs/cli.md)."""

    # fields: TractionResult (scripts/python-report-fields.py)
    traction_law: str
    ring: str
    contact_angle_deg: float
    load_n: float
    semi_axis_along_m: float
    semi_axis_across_m: float
    rolling_speed_m_s: float
    creepage_longitudinal: float
    creepage_lateral: float
    creepage_spin_1_m: float
    force_x_n: float
    force_y_n: float
    force_n: float
    traction_coefficient: float
    spin_moment_nm: float
    power_w: float
    stick_fraction: Optional[float]
    map_cells: Optional[int]
    method: str
    exact: Optional[Report]
    # fields: end


class SpectrumResult(Report):
    """``rolldyn spectrum``: a channel's spectrum with the bearing's lines
    and named peaks (keys in docs/cli.md)."""

    # fields: SpectrumResult (scripts/python-report-fields.py)
    channel: str
    unit: str
    kind: str
    value_unit: str
    window: str
    sample_rate_hz: float
    samples: int
    from_s: float
    to_s: float
    resolution_hz: float
    band_hz: Optional[np.ndarray]
    band_warning: Optional[str]
    segment: Optional[int]
    segments: Optional[int]
    velocity_rms_mm_s: Optional[float]
    velocity_rms_band_hz: Optional[np.ndarray]
    characteristic: Report
    peaks: Table
    lines: Table
    csv: str
    # fields: end


class Summary(dict):
    """A run's summary (``summary.json``; keys and units in docs/cli.md):
    a dict, so ``summary["mean_cage_speed_rpm"]`` and ``json.dump`` work,
    whose keys are also typed attributes (``summary.mean_cage_speed_rpm``;
    nested objects as :class:`Report`, lists of objects as :class:`Table`,
    lists of numbers as NumPy arrays). A set's or shaft's summary has its
    own keys (docs/cli.md); attributes absent from it raise AttributeError."""

    __slots__ = ()

    # fields: Summary (scripts/python-report-fields.py)
    source: str
    title: str
    status: str
    error: Optional[str]
    requested_duration_s: float
    simulated_time_s: float
    wall_time_s: float
    integrator: str
    relative_tolerance: float
    energy_tolerance: float
    max_step_s: float
    steps: int
    rejected_steps: int
    rhs_evaluations: int
    jacobian_evaluations: int
    jacobian_rhs_evaluations: int
    fast_part_jacobians: int
    factorizations: int
    explicit_steps: int
    integrator_switches: int
    samples: int
    sample_rate_hz: float
    averaging_window_s: np.ndarray
    ball_count: int
    ball_diameter_m: float
    pitch_diameter_m: float
    mean_contact_angle_inner_deg: float
    mean_contact_angle_outer_deg: float
    inner_ring_speed_rpm: float
    final_inner_ring_speed_rpm: float
    mean_cage_speed_rpm: float
    pure_rolling_cage_speed_rpm: float
    cage_speed_ratio: float
    pure_rolling_cage_speed_ratio: float
    cage_sliding_rate: float
    mean_load_inner_n: float
    max_load_inner_n: float
    mean_load_outer_n: float
    max_load_outer_n: float
    mean_slide_to_roll_inner: float
    mean_slide_to_roll_outer: float
    mean_spin_to_roll_inner: float
    mean_spin_to_roll_outer: float
    mean_attitude_deg: float
    mean_yaw_deg: float
    max_abs_yaw_deg: float
    ball_pass_jitter: Optional[float]
    ball_pass_interval_s: Optional[float]
    cage_whirl_radius_mean_m: float
    cage_whirl_radius_max_m: float
    cage_whirl_speed_rpm: float
    cage_whirl_speed_ratio: float
    cage_whirl_sigma: float
    velocity_rms_band_hz: np.ndarray
    inner_ring_velocity_rms_x_mm_s: float
    inner_ring_velocity_rms_y_mm_s: float
    inner_ring_velocity_rms_z_mm_s: float
    outer_ring_velocity_rms_y_mm_s: Optional[float]
    outer_ring_velocity_rms_z_mm_s: Optional[float]
    envelope_lines: Optional[Report]
    waviness_lines: Optional[Report]
    spall_growth: Optional[Table]
    sensor: Optional[Report]
    mean_power_loss_w: float
    mean_dissipated_power_w: float
    mean_sampled_power_loss_w: float
    mean_friction_torque_n_m: float
    mean_sampled_friction_torque_n_m: float
    mean_power_loss_by_component_w: Report
    lubrication_note: Optional[str]
    thermal_coupling: Optional[Report]
    drive_work_j: float
    film_work_j: float
    dissipated_energy_j: float
    mechanical_energy_change_j: float
    energy_balance_error_j: float
    energy_balance_relative_error: float
    accuracy: Report
    kind: str
    mounting_preload_n: float
    bearings: Table
    verify: Optional[Report]
    # fields: end

    def __getattr__(self, name: str) -> Any:
        try:
            return _view(self[name])
        except KeyError:
            raise AttributeError(f"Summary has no {name!r}; keys: {', '.join(self)}") from None

    def __dir__(self) -> list:
        return sorted(set(super().__dir__()) | set(self))


for _cls in (Report, Table, Summary, QuasiStaticResult, PowerResult, ThermalResult, Frequencies,
             ContactResult, TractionResult, SpectrumResult):
    _cls.__module__ = "rolldyn"
del _cls
