"""The Python API of rolldyn (imported by ``rolldyn/__init__.py``, which
exports only the public names)."""

from __future__ import annotations

import itertools
import os
import shutil
import tempfile
from pathlib import Path
from typing import Any, Callable, Iterable, Mapping, Optional, Sequence, Union

import numpy as np
import pyarrow as pa

from . import _rolldyn
from ._rolldyn import CaseError, ModelError

#: Source name of the built-in default case (as the CLI names it).
DEFAULT_SOURCE = "built-in default case (7008C)"

#: Short names of swept inputs, as in ``rolldyn run --sweep``.
SWEEP_ALIASES = {
    "speed": "operating.speed",
    "axial": "operating.force_x",
    "radial": "operating.force_z",
}

Progress = Optional[Callable[[float], Any]]

#: A value with its unit, as in case files (``"200 N"``, ``"10 m/s"``).
Quantity = str


def _value_text(value: Any) -> str:
    """A flag's value as the CLI reads its text (a load, a sweep's values)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float, np.integer, np.floating)):
        return repr(value.item() if isinstance(value, np.generic) else value)
    if isinstance(value, str):
        return value
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    raise CaseError(f"value {value!r}: expected a string with its unit, a number or a bool")


def _plain(value: Any, key: str) -> Any:
    """A case value as it crosses into Rust, typed: a bool, int, float or
    string (a string read as ``--set`` reads its text), or a list or dict
    of them; NumPy scalars and arrays become Python's."""
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    if isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, (list, tuple)):
        return [_plain(v, key) for v in value]
    if isinstance(value, Mapping) and all(isinstance(k, str) for k in value):
        return {k: _plain(v, key) for k, v in value.items()}
    raise CaseError(f"override {key}={value!r} (Case.set): expected a string with its unit, "
                    "a number, a bool, or a list or dict of them")


def _values(values: Union[Mapping[str, Any], Iterable[Any]]) -> list:
    """``(key, value)`` pairs of :meth:`Case.set`, the aliases resolved,
    from a mapping, from ``(key, value)`` pairs, or from ``"KEY=VALUE"``
    texts as ``rolldyn --set`` takes them."""
    items = values.items() if isinstance(values, Mapping) else values
    out = []
    for item in items:
        if isinstance(item, str):
            key, sep, value = item.partition("=")
            if not sep:
                raise CaseError(f"override {item!r}: expected KEY=VALUE or a (key, value) pair")
            item = (key.strip(), value.strip())
        try:
            key, value = item
        except (TypeError, ValueError):
            raise CaseError(f"override {item!r}: expected KEY=VALUE or a (key, value) pair") \
                from None
        key = SWEEP_ALIASES.get(key, key)
        out.append((key, _plain(value, key)))
    return out


class Case:
    """A validated case: its source, its TOML text and its values.

    Build one with :meth:`default`, :meth:`preset`, :meth:`load` or
    :meth:`from_toml`; change values with :meth:`set` (validated at once,
    as ``rolldyn --set`` is). A bad value raises :class:`CaseError` with
    the CLI's message (key, value, rule). Cases pickle (for Dask).
    """

    def __init__(self, source: str = DEFAULT_SOURCE, text: Optional[str] = None,
                 values: Union[Mapping[str, Any], Sequence[Any]] = ()):
        self._source = str(source)
        self._text = text
        self._values = _values(values)
        self.describe()  # validates

    @classmethod
    def default(cls) -> "Case":
        """The built-in default case (7008C at 10 000 rpm, F_x = 200 N)."""
        return cls()

    @classmethod
    def preset(cls, name: str) -> "Case":
        """A built-in bearing (see :func:`presets`), as ``rolldyn new --preset``."""
        return cls(f"preset {name}", _rolldyn.preset_text(name))

    @classmethod
    def catalogue(cls, designation: str, clearance: Optional[str] = None) -> "Case":
        """A catalogue bearing (ISO 15 60/62/63, 70/72/73) with estimated
        internal geometry, as ``rolldyn new --bearing DESIGNATION
        --clearance GROUP``: e.g. ``Case.catalogue("6205", clearance="C3")``
        or ``Case.catalogue("7210B")``. See :func:`catalogue` and
        docs/catalogue.md."""
        return cls(f"catalogue {designation}", _rolldyn.catalogue_text(designation, clearance))

    @classmethod
    def load(cls, path: Union[str, os.PathLike]) -> "Case":
        """A case file (TOML)."""
        try:
            text = Path(path).read_text(encoding="utf-8")
        except OSError as e:
            raise CaseError(f"cannot read case file {path}: {e}") from None
        return cls(str(path), text)

    @classmethod
    def from_toml(cls, text: str, source: str = "<string>") -> "Case":
        """A case from its TOML text."""
        return cls(source, text)

    def set(self, key: str, value: Any) -> "Case":
        """Overrides one value, e.g. ``set("operating.speed", "10000 rpm")``;
        ``speed``, ``axial`` and ``radial`` stand for the operating speed and
        loads. Validated at once (the case is unchanged on error). Returns
        the case, so calls chain."""
        values = _values({key: value})
        _rolldyn.check(self._source, self._text, self._values + values)
        self._values.extend(values)
        return self

    def copy(self) -> "Case":
        """An independent copy."""
        new = object.__new__(Case)
        new._source, new._text, new._values = self._source, self._text, list(self._values)
        return new

    def with_values(self, values: Mapping[str, Any]) -> "Case":
        """A copy with several values set, validated together: keys that
        need each other go in one call, e.g. ``{"operating.drive_torque":
        "0 N.m", "operating.rotor_inertia": "1e-4 kg.m^2"}``."""
        values = _values(values)
        _rolldyn.check(self._source, self._text, self._values + values)
        new = self.copy()
        new._values.extend(values)
        return new

    def describe(self) -> dict:
        """``rolldyn check --json``: derived geometry, contact constants,
        frequencies and the assumptions made."""
        return _rolldyn.check(self._source, self._text, self._values)

    @property
    def source(self) -> str:
        return self._source

    @property
    def text(self) -> Optional[str]:
        """The TOML text (None for the built-in default case)."""
        return self._text

    @property
    def values(self) -> list:
        """The values set, ``(key, value)`` in order, as given (NumPy
        values as Python's). They cross into the engine typed, a string on
        its own read as ``--set`` reads it (``"9"`` is the number 9, as
        ``run.json`` records it)."""
        return list(self._values)

    @property
    def overrides(self) -> list:
        """The values as ``rolldyn --set KEY=VALUE`` texts, in order: the
        same case on the command line."""
        return _rolldyn.set_texts(self._values)

    def _args(self) -> tuple:
        return self._source, self._text, list(self._values)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Case) and self._args() == other._args()

    def __repr__(self) -> str:
        extra = f", values={self._values!r}" if self._values else ""
        return f"Case({self._source!r}{extra})"


def _case(case: Optional[Case]) -> Case:
    if case is None:
        return Case()
    if not isinstance(case, Case):
        raise TypeError(f"case: expected rolldyn.Case, got {type(case).__name__}")
    return case


def presets() -> dict:
    """The built-in bearings: name -> one-line description with its source."""
    return dict(_rolldyn.preset_names())


def catalogue(series: Optional[str] = None) -> list:
    """``rolldyn catalogue --json``: the catalogue bearings (or one series,
    e.g. ``"62"``) with their estimated ball sets and ISO 281/76 ratings,
    one dict per bearing (units in the keys)."""
    return _rolldyn.catalogue_entries(series)


def frequencies(case: Optional[Case] = None, angle: Optional[str] = None) -> "Frequencies":
    """``rolldyn frequencies --json``: cage, BPFO, BPFI, ball spin and
    waviness lines (at ``angle``, e.g. ``"15 deg"``; default the nominal)."""
    return Frequencies(_rolldyn.frequencies(*_case(case)._args(), angle))


def _text(value: Any) -> Optional[str]:
    """A value with its unit as the CLI reads it (None stays None)."""
    return None if value is None else _value_text(value)


def contact(load: Quantity, case: Optional[Case] = None, *, angle: Optional[Quantity] = None,
            entrainment_speed: Optional[Quantity] = None, radii: Optional[str] = None,
            ball_on_flat: Optional[Quantity] = None,
            inlet_distance_ratio: Optional[float] = None) -> "ContactResult":
    """``rolldyn contact --json``: Hertz contact of one ball on the case's
    raceways (``angle="20 deg"``), or of an explicit contact
    (``radii="2.8 mm,20 mm"`` or ``ball_on_flat="19.05 mm"``); with
    ``entrainment_speed="1 m/s"`` (and ``inlet_distance_ratio``) the
    lubricant film too."""
    return ContactResult(_rolldyn.contact(
        *_case(case)._args(), _value_text(load), _text(angle), _text(entrainment_speed),
        _text(radii), _text(ball_on_flat), inlet_distance_ratio))


def power(case: Optional[Case] = None) -> "PowerResult":
    """``rolldyn power --json``: friction power by component at the
    Jones–Harris equilibrium (Harris's local method, Lei et al. 2023)."""
    return PowerResult(_rolldyn.power_report(*_case(case)._args()))


def thermal(case: Optional[Case] = None, transient: Optional[Quantity] = None,
            steps: Optional[int] = None) -> "ThermalResult":
    """``rolldyn thermal --json``: bearing temperatures coupled to the power
    loss; ``transient="30 min"`` adds the warm-up (``steps`` time steps,
    default 600)."""
    return ThermalResult(_rolldyn.thermal_report(
        *_case(case)._args(), _text(transient), steps))


def traction(case: Optional[Case] = None, *, rolling_speed: Quantity,
             ring: Optional[str] = None, load: Optional[Quantity] = None,
             approach: Optional[Quantity] = None, angle: Optional[Quantity] = None,
             creepages: Optional[str] = None, slip: Optional[str] = None,
             spin: Optional[Quantity] = None, semi_axes: Optional[str] = None,
             shear_modulus: Optional[Quantity] = None, poisson_ratio: Optional[float] = None,
             friction: Optional[float] = None, method: Optional[str] = None,
             cells: Optional[Union[int, str]] = None,
             map: Optional[Union[str, os.PathLike]] = None) -> "TractionResult":
    """``rolldyn traction --json``: one contact's traction with the case's
    traction model, e.g. ``traction(case, load="500 N",
    rolling_speed="10 m/s", creepages="1e-3,0,5", map="map.csv")``;
    ``method="exact"`` (Kalker's exact theory: by default three grids extrapolated
    to zero cell size; ``cells`` one grid) or ``"table"``.
    The keywords are the CLI's flags (docs/cli.md); None keeps its
    default."""
    return TractionResult(_rolldyn.traction_report(
        *_case(case)._args(), _value_text(rolling_speed), ring, _text(load), _text(approach),
        _text(angle), _text(creepages), _text(slip), _text(spin), _text(semi_axes),
        _text(shear_modulus), poisson_ratio, friction, method, _text(cells), _text(map)))


def spectrum(directory: Union[str, os.PathLike], channel: str, *, kind: Optional[str] = None,
             window: Optional[str] = None, segment: Optional[int] = None,
             overlap: Optional[float] = None, band: Optional[str] = None,
             start: Optional[float] = None, harmonics: Optional[int] = None,
             peaks: Optional[int] = None) -> "SpectrumResult":
    """``rolldyn spectrum DIR --json``: amplitude, Welch PSD, envelope
    spectrum or spectrogram of a run's channel (``kind="envelope"``,
    ``band="2 kHz:8 kHz"``, ``start`` the CLI's ``--from`` in s, ...), with
    the bearing's lines and the nearest line of each peak; writes
    ``spectrum_<channel>_<kind>.csv`` and ``.json`` into the run
    directory."""
    return SpectrumResult(_rolldyn.spectrum_report(
        str(directory), channel, kind, window, segment, overlap, band, start, harmonics, peaks))


def quasistatic(case: Optional[Case] = None, control: Optional[str] = None) -> "QuasiStaticResult":
    """``rolldyn quasistatic --json``: static load distribution or
    Jones–Harris equilibrium. ``control``: ``outer``, ``inner``, ``harris``
    or ``traction`` (default: the case's). Raises :class:`ModelError`
    when the solve does not converge."""
    return QuasiStaticResult(_rolldyn.quasistatic_solve(*_case(case)._args(), control))


def _sweep_arg(name: str, values: Union[str, Iterable[Any]]) -> str:
    text = values if isinstance(values, str) else ",".join(_value_text(v) for v in values)
    return f"{name}={text}"


def quasistatic_sweep(case: Optional[Case], grid: Mapping[str, Union[str, Iterable[Any]]],
                      control: Optional[str] = None) -> "SweepResult":
    """``rolldyn quasistatic --sweep``: ``grid`` maps ``speed``, ``axial`` or
    ``radial`` to a range (``"0rpm..20000rpm/11"``) or a list of values;
    the first key is outermost. One row per point (failed points have
    ``converged`` False and an ``error``)."""
    args = [_sweep_arg(k, v) for k, v in grid.items()]
    rows = _rolldyn.quasistatic_sweep(*_case(case)._args(), args, control)
    return SweepResult(rows, None)


# The run directory's dataset names (defined once, in rolldyn-io's RunDir).
SERIES_DIR: str = _rolldyn.SERIES_DIR
SLOW_SERIES_DIR: str = _rolldyn.SLOW_SERIES_DIR


def _dataset(directory: str, name: str = SERIES_DIR):
    """The run's time series: a Parquet dataset of part files, read lazily
    (docs/cli.md)."""
    import pyarrow.dataset as ds
    return ds.dataset(os.path.join(directory, name), format="parquet")


class Channel(np.ndarray):
    """A time-series channel: a NumPy array with its ``name`` and ``unit``."""

    def __new__(cls, values: np.ndarray, name: str, unit: str) -> "Channel":
        obj = np.asarray(values).view(cls)
        obj.name, obj.unit = name, unit
        return obj

    def __array_finalize__(self, obj: Any) -> None:
        self.name = getattr(obj, "name", None)
        self.unit = getattr(obj, "unit", None)


class Result:
    """A dynamic run: ``summary`` (a :class:`Summary`: the run's
    summary.json as a dict with typed attributes),
    ``result[name]`` (a :class:`Channel`: NumPy array with ``.unit``, read
    from disk one channel at a time) and ``timeseries`` (the whole series as
    a pyarrow Table, each field's unit in its metadata; read on first use,
    which for a long run can be large: prefer ``result[name]`` or
    :meth:`dataset`)."""

    def __init__(self, summary: dict, directory: Optional[str],
                 timeseries: Optional[pa.Table] = None):
        self.summary = Summary(summary)
        self.directory = directory
        self._table = timeseries
        self._schema = timeseries.schema if timeseries is not None else None

    @classmethod
    def load(cls, directory: Union[str, os.PathLike]) -> "Result":
        """Opens a run directory written by ``rolldyn run`` or :func:`run`."""
        summary = _rolldyn.open_run(str(directory))
        return cls(summary, str(directory))

    def dataset(self):
        """The time series as a ``pyarrow.dataset.Dataset`` (streams: scan
        it by columns, rows or batches without loading it whole)."""
        if self.directory is None:
            raise CaseError("dataset: this run has no directory; run with output=DIR")
        return _dataset(self.directory)

    @property
    def timeseries(self) -> pa.Table:
        if self._table is None:
            self._table = self.dataset().to_table()
        return self._table

    @property
    def schema(self) -> pa.Schema:
        if self._schema is None:
            self._schema = self.timeseries.schema if self.directory is None \
                else self.dataset().schema
        return self._schema

    @property
    def slow_timeseries(self) -> Optional[pa.Table]:
        """The channels recorded at ``output.slow_rate`` with their own
        ``time_s`` (None when the run has none)."""
        if self.directory is None or not os.path.isdir(
                os.path.join(self.directory, SLOW_SERIES_DIR)):
            return None
        return _dataset(self.directory, SLOW_SERIES_DIR).to_table()

    @property
    def status(self) -> str:
        """``completed``, ``interrupted`` or ``failed``."""
        return self.summary["status"]

    def _slow_schema(self) -> Optional[pa.Schema]:
        if self.directory is None or not os.path.isdir(
                os.path.join(self.directory, SLOW_SERIES_DIR)):
            return None
        return _dataset(self.directory, SLOW_SERIES_DIR).schema

    @property
    def channels(self) -> list:
        """Every channel, those recorded at the slow rate last."""
        slow = self._slow_schema()
        return self.schema.names + ([] if slow is None else slow.names[1:])

    @property
    def units(self) -> dict:
        """Channel name -> unit."""
        fields = list(self.schema) + list(self._slow_schema() or [])
        return {f.name: (f.metadata or {}).get(b"unit", b"").decode() for f in fields}

    def __getitem__(self, name: str) -> Channel:
        """A channel; one recorded at the slow rate comes from
        ``timeseries_slow.parquet`` (its times: ``slow_timeseries["time_s"]``)."""
        if name not in self.schema.names:
            slow = self._slow_schema()
            if slow is not None and name in slow.names:
                column = _dataset(self.directory, SLOW_SERIES_DIR).to_table(columns=[name]).column(name)
                return Channel(column.to_numpy(), name, self.units[name])
            raise KeyError(f"{name}: no such channel; channels: {', '.join(self.channels)}")
        table = self._table if self._table is not None \
            else self.dataset().to_table(columns=[name])
        column = table.column(name)
        values = column.chunk(0).to_numpy(zero_copy_only=True) if column.num_chunks == 1 \
            else column.to_numpy()
        return Channel(values, name, self.units[name])

    def to_pandas(self):
        """The time series as a pandas DataFrame (needs pandas)."""
        return self.timeseries.to_pandas()

    def spectrum(self, channel: str, **options: Any) -> "SpectrumResult":
        """:func:`spectrum` of this run (needs its directory: ``output=``)."""
        if self.directory is None:
            raise CaseError("spectrum: this run has no directory; run with output=DIR")
        return spectrum(self.directory, channel, **options)

    def report(self) -> str:
        """Writes ``report.html`` into the run directory; returns its path."""
        if self.directory is None:
            raise CaseError("report: this run has no directory; run with output=DIR")
        return _rolldyn.report(self.directory)

    def __repr__(self) -> str:
        s = self.summary
        return (f"<rolldyn.Result {s['status']}: {s['simulated_time_s']:.4g} s simulated, "
                f"{s['samples']} samples x {len(self.channels)} channels>")


class RunInterrupted(KeyboardInterrupt):
    """Ctrl-C stopped a run or sweep; ``.result`` holds what was computed
    (a :class:`Result` or :class:`SweepResult`)."""

    def __init__(self, result: Any):
        super().__init__("interrupted; the partial result is in .result")
        self.result = result


class _Directory:
    """The output directory of a run: the given one, or a temporary one
    removed when done."""

    def __init__(self, output: Optional[Union[str, os.PathLike]]):
        self.given = output is not None
        self.path = str(output) if self.given else tempfile.mkdtemp(prefix="rolldyn-")

    def __enter__(self) -> "_Directory":
        return self

    def __exit__(self, *exc: Any) -> None:
        if not self.given:
            shutil.rmtree(self.path, ignore_errors=True)


def _with_duration(case: Case, duration: Optional[str]) -> Case:
    return case if duration is None else case.copy().set("solver.duration", duration)


def run(case: Optional[Case] = None, duration: Optional[str] = None, *,
        output: Optional[Union[str, os.PathLike]] = None, force: bool = False,
        progress: Progress = None, verify: bool = False) -> Result:
    """``rolldyn run``: simulates the case (``duration`` e.g. ``"0.01 s"``
    overrides ``solver.duration``). With ``output`` the run directory is
    kept (timeseries.parquet, summary.json, run.json); otherwise a
    temporary one is used and removed. ``progress(fraction)`` is called
    about ten times a second. A failed integration returns a result with
    status ``failed`` and the ``error`` in the summary, as the CLI's files
    do. ``summary["accuracy"]`` says how accurate the run is; with
    ``verify=True`` the case also runs at ten times tighter tolerances
    (``--verify``) and ``summary["accuracy"]["verify"]`` holds the
    changes. A case with ``[arrangement]`` runs its bearings on their
    shaft (the set's summary and channels, docs/cli.md; no ``verify``)."""
    case = _with_duration(_case(case), duration)
    with _Directory(output) as d:
        summary, interrupted = _rolldyn.run(
            *case._args(), d.path, force, progress, verify)
        if d.given:
            result = Result(summary, d.path)
        else:
            # The temporary directory goes: read the series now.
            result = Result(summary, None, _dataset(d.path).to_table())
    if interrupted:
        raise RunInterrupted(result)
    return result


class SweepResult:
    """Rows of a sweep, one dict per point: the point, its swept values, its
    status and error, and the numbers of its summary (nested keys joined
    with '.'); as in ``sweep.json``."""

    def __init__(self, rows: list, directory: Optional[str]):
        self.rows = rows
        self.directory = directory

    @property
    def table(self) -> pa.Table:
        return pa.Table.from_pylist(self.rows)

    def to_pandas(self):
        return self.table.to_pandas()

    def signals(self):
        """Every point's time series as one lazily read Parquet dataset
        (``pyarrow.dataset.Dataset``) with a ``point`` column, the key of
        :attr:`table`'s rows: the labelled dataset of a sweep. Needs the
        sweep's ``output`` directory. ``signals().to_table(columns=["point",
        "time_s", "sensor_acceleration_m_s2"], filter=ds.field("point") ==
        "point-0003")`` reads one channel of one point."""
        if self.directory is None:
            raise ValueError("signals(): the sweep kept no run directories; pass output=")
        import pyarrow.dataset as ds
        series = [os.path.join(self.directory, r["point"], SERIES_DIR) for r in self.rows]
        files = sorted(
            os.path.join(path, name)
            for path in series if os.path.isdir(path)
            for name in os.listdir(path) if name.endswith(".parquet"))
        partitioning = ds.DirectoryPartitioning(pa.schema([("point", pa.string())]))
        return ds.dataset(files, format="parquet", partitioning=partitioning,
                          partition_base_dir=self.directory)

    def column(self, name: str) -> np.ndarray:
        """One column over the points (NaN where a point has no value)."""
        return np.array([np.nan if r.get(name) is None else r[name] for r in self.rows])

    def __len__(self) -> int:
        return len(self.rows)

    def __iter__(self):
        return iter(self.rows)

    def __getitem__(self, k: int) -> dict:
        return self.rows[k]

    def __repr__(self) -> str:
        return f"<rolldyn.SweepResult {len(self.rows)} points>"


def _grid_points(grid: Mapping[str, Iterable[Any]]) -> tuple:
    """The grid's columns and each point's overrides (first key outermost)."""
    if not grid:
        raise CaseError("grid: give at least one key with a list of values")
    keys = list(grid)
    values = []
    for key in keys:
        v = grid[key]
        if isinstance(v, (str, bytes)) or not isinstance(v, Iterable):
            raise CaseError(f"grid {key}: expected a list of values, got {v!r}")
        v = list(v)
        if not v:
            raise CaseError(f"grid {key}: no values")
        values.append(v)
    points = list(itertools.product(*values))
    overrides = [_values(dict(zip(keys, p))) for p in points]
    return keys, points, overrides


def _sampled_points(grid: Mapping[str, Any], count: int, seed: int) -> tuple:
    """``count`` random points (``rolldyn run --sweep … --sample``): a
    range text ``"0.1 mm..0.5 mm"`` is drawn uniformly, a list by choice."""
    if not grid:
        raise CaseError("grid: give at least one key with a range or a list of values")
    if count < 1:
        raise CaseError(f"sample {count}: needs at least one run")
    specs = []
    for key, v in grid.items():
        if isinstance(v, str):
            if ".." not in v:
                raise CaseError(f"grid {key}: with sample=, a text is a range LOW..HIGH, got {v!r}")
            specs.append(f"{key}={v}")
        else:
            specs.append(f"{key}=" + ",".join(_value_text(x) for x in v))
    drawn = _rolldyn.sample_points(specs, count, seed)
    return list(grid), [tuple(labels) for _, labels in drawn], [sets for sets, _ in drawn]


def _with_inputs(row: dict, keys: list, point: tuple) -> dict:
    """The row with the grid's values after the point name."""
    out = {"point": row["point"]}
    for k, x in zip(keys, point):
        out[k] = x.item() if isinstance(x, np.generic) else x
    out.update((k, v) for k, v in row.items() if k != "point")
    return out


def _dask_point(name: str, source: str, text: Optional[str], sets: list,
                output: Optional[str], force: bool) -> dict:
    """One sweep point on a Dask worker (the same row as a local sweep)."""
    with _Directory(output) as d:
        return _rolldyn.run_point(name, source, text, sets, d.path, force)


def sweep(case: Optional[Case], grid: Mapping[str, Iterable[Any]], client: Any = None, *,
          duration: Optional[str] = None, output: Optional[Union[str, os.PathLike]] = None,
          force: bool = False, progress: Progress = None, sample: Optional[int] = None,
          seed: int = 0) -> SweepResult:
    """Dynamic runs over a grid: ``grid`` maps case keys (or ``speed``,
    ``axial``, ``radial``) to lists of values, e.g. ``{"speed": ["5000 rpm",
    "10000 rpm"], "axial": ["100 N", "1 kN"]}``; the first key is
    outermost. Without ``client`` the points run in parallel on this
    machine's cores (as ``rolldyn run --sweep``); with a Dask
    ``distributed.Client`` they run as its tasks. The rows are the same
    either way (but for ``wall_time_s``). With ``output`` each point's run
    directory ``output/point-NNNN`` and ``sweep.json``/``sweep.csv`` are
    kept (on a cluster ``output`` must be a shared file system), and the
    point directories an earlier, larger sweep left there, or an earlier
    single run's files, are removed. With
    ``sample=N`` the sweep runs N random points instead of the grid
    (``--sample N --seed S``): a range text ``"0.1 mm..0.5 mm"`` is drawn
    uniformly, a list by choice; the rows hold the drawn values."""
    case = _with_duration(_case(case), duration)
    keys, points, overrides = _grid_points(grid) if sample is None \
        else _sampled_points(grid, sample, seed)
    for sets in overrides:  # every point's case is valid before any runs
        _rolldyn.check(case._source, case._text, case._values + sets)
    if client is None:
        with _Directory(output) as d:
            rows, interrupted = _rolldyn.run_points(
                *case._args(), overrides, d.path, force, progress)
    else:
        source, text, base = case._args()
        names = [_rolldyn.point_name(k, len(points)) for k in range(len(points))]
        out = None if output is None else str(output)
        if out is not None:
            os.makedirs(out, exist_ok=True)
            _rolldyn.remove_stale_points(out, len(points))
        futures = client.map(
            _dask_point, names, [source] * len(points), [text] * len(points),
            [base + sets for sets in overrides], [out] * len(points),
            [force] * len(points), pure=False)
        interrupted = False
        try:
            if progress is not None:
                from distributed import as_completed
                for done, _ in enumerate(as_completed(futures), 1):
                    progress(done / len(futures))
            rows = client.gather(futures)
        except KeyboardInterrupt:
            # Keep the finished points; the others are cancelled (a task
            # already running on a worker finishes there, unreported).
            interrupted = True
            rows = [f.result() if f.status == "finished"
                    else {"point": name, "status": "not_started", "error": None}
                    for f, name in zip(futures, names)]
            client.cancel([f for f in futures if f.status != "finished"])
        if out is not None:
            _rolldyn.write_sweep_tables(out, rows)
    result = SweepResult([_with_inputs(r, keys, p) for r, p in zip(rows, points)],
                         None if output is None else str(output))
    if interrupted:
        raise RunInterrupted(result)
    return result


from ._reports import (  # noqa: E402  (the reports use nothing above)
    ContactResult, Frequencies, PowerResult, QuasiStaticResult, SpectrumResult, Summary,
    ThermalResult, TractionResult,
)
