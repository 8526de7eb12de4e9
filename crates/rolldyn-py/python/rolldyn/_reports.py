"""Reports as typed objects: each key of a command's ``--json`` output
(docs/cli.md, units in the key names) is an attribute; lists of numbers
are NumPy arrays, matrices 2-D arrays, objects nested reports and lists of
objects :class:`Table`\\ s (a column per key as a NumPy array, a row per
entry). A report is also the mapping of the CLI's JSON, so
``result["cage_speed_rpm"]`` and ``result == cli_json`` keep working."""

from __future__ import annotations

from typing import Any, Iterator, Mapping, Optional, Sequence

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

    balls: Table
    stiffness_matrix: np.ndarray
    compliance_matrix: np.ndarray
    cage_speed_rpm: float
    rating_life: Report

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


class ThermalResult(Report):
    """``rolldyn thermal``: the bearing's temperatures coupled to its power
    loss, and the warm-up when asked; of a bearing set, every bearing's and
    the preload at the operating temperatures (keys in docs/cli.md)."""


class Frequencies(Report):
    """``rolldyn frequencies``: cage, BPFO, BPFI, ball spin and waviness
    lines (keys in docs/cli.md)."""


class ContactResult(Report):
    """``rolldyn contact``: one Hertz contact and its film (keys in
    docs/cli.md), e.g. ``semi_major_m``, ``max_pressure_pa``."""


class TractionResult(Report):
    """``rolldyn traction``: one contact's traction: forces, spin moment,
    power, stick fraction (keys in docs/cli.md)."""


class SpectrumResult(Report):
    """``rolldyn spectrum``: a channel's spectrum with the bearing's lines
    and named peaks (keys in docs/cli.md)."""


for _cls in (Report, Table, QuasiStaticResult, PowerResult, ThermalResult, Frequencies,
             ContactResult, TractionResult, SpectrumResult):
    _cls.__module__ = "rolldyn"
del _cls
