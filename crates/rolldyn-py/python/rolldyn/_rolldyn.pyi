"""Type stubs of the native module ``rolldyn._rolldyn`` (the Rust engine
behind the Python API in ``rolldyn/_api.py``). Every function takes a
case as ``(source, text, values)``: its source name, its TOML text (None:
the built-in default case or the file named by ``source``) and its values
set, ``(key, value)`` pairs typed as a case file holds them (a number, a
bool, a string with its unit, a list or dict of them; a string on its own
is read as ``--set`` reads its text). Reports come back as Python dicts and
lists, built from the engine's report types directly (no JSON text in
between): the keys and values of the CLI's ``--json`` output (keys and
units in docs/cli.md)."""

from typing import Any, Callable, Optional

Json = dict[str, Any]
#: A case's values set: ``(key, value)`` in order.
Values = list[tuple[str, Any]]

__version__: str
SERIES_DIR: str
SLOW_SERIES_DIR: str

class CaseError(ValueError):
    """Bad input: names the file, line, key, value and rule."""

class ModelError(RuntimeError):
    """The model has no solution at this point (e.g. no equilibrium)."""

def preset_names() -> list[tuple[str, str]]: ...
def preset_text(name: str) -> str: ...
def catalogue_text(designation: str, clearance: Optional[str] = None) -> str: ...
def catalogue_entries(series: Optional[str] = None) -> list[Json]: ...
def check(source: str, text: Optional[str], values: Values) -> Json: ...
def frequencies(source: str, text: Optional[str], values: Values, angle: Optional[str]) -> Json: ...
def contact(
    source: str,
    text: Optional[str],
    values: Values,
    load: str,
    angle: Optional[str] = None,
    entrainment_speed: Optional[str] = None,
    radii: Optional[str] = None,
    ball_on_flat: Optional[str] = None,
    inlet_distance_ratio: Optional[float] = None,
) -> Json: ...
def power_report(source: str, text: Optional[str], values: Values) -> Json: ...
def thermal_report(
    source: str,
    text: Optional[str],
    values: Values,
    transient: Optional[str] = None,
    steps: Optional[int] = None,
) -> Json: ...
def traction_report(
    source: str,
    text: Optional[str],
    values: Values,
    rolling_speed: str,
    ring: Optional[str] = None,
    load: Optional[str] = None,
    approach: Optional[str] = None,
    angle: Optional[str] = None,
    creepages: Optional[str] = None,
    slip: Optional[str] = None,
    spin: Optional[str] = None,
    semi_axes: Optional[str] = None,
    shear_modulus: Optional[str] = None,
    poisson_ratio: Optional[float] = None,
    friction: Optional[float] = None,
    method: Optional[str] = None,
    cells: Optional[str] = None,
    map: Optional[str] = None,
) -> Json: ...
def spectrum_report(
    directory: str,
    channel: str,
    kind: Optional[str] = None,
    window: Optional[str] = None,
    segment: Optional[int] = None,
    overlap: Optional[float] = None,
    band: Optional[str] = None,
    start: Optional[float] = None,
    harmonics: Optional[int] = None,
    peaks: Optional[int] = None,
) -> Json: ...
def quasistatic_solve(source: str, text: Optional[str], values: Values, control: Optional[str]) -> Json: ...
def quasistatic_sweep(
    source: str, text: Optional[str], values: Values, sweeps: list[str], control: Optional[str]
) -> list[Json]: ...
def run(
    source: str,
    text: Optional[str],
    values: Values,
    directory: str,
    force: bool,
    progress: Optional[Callable[[float], Any]],
    verify: bool,
) -> tuple[Json, bool]: ...
def open_run(directory: str) -> Json: ...
def run_points(
    source: str,
    text: Optional[str],
    values: Values,
    points: list[Values],
    directory: str,
    force: bool,
    progress: Optional[Callable[[float], Any]],
) -> tuple[list[Json], bool]: ...
def run_point(
    name: str, source: str, text: Optional[str], values: Values, directory: str, force: bool
) -> Json: ...
def point_name(k: int, count: int) -> str: ...
def sample_points(sweeps: list[str], count: int, seed: int) -> list[tuple[Values, list[str]]]: ...
def set_texts(values: Values) -> list[str]: ...
def write_sweep_tables(directory: str, rows: list[Json]) -> None: ...
def remove_stale_points(directory: str, count: int) -> None: ...
def report(directory: str) -> str: ...
