"""rolldyn: ball-bearing dynamics from Python.

The same engine and the same code paths as the ``rolldyn`` command: a case
gives the same numbers here as on the command line. Cases carry explicit
units (``"10000 rpm"``, ``"200 N"``); reports are typed objects whose
attributes are the keys of the CLI's ``--json`` output (units in the
names, docs/cli.md), each declared with its type on the report's class,
with NumPy arrays for vectors, matrices and table columns; time series are pyarrow Tables shared with the engine's memory,
and NumPy arrays per channel.

    >>> import rolldyn
    >>> case = rolldyn.Case.preset("7008C").set("operating.speed", "12000 rpm")
    >>> result = rolldyn.run(case, duration="5 ms")
    >>> result.summary["mean_cage_speed_rpm"]
    >>> result["cage_speed_rpm"]            # NumPy array, .unit == "rpm"
    >>> qs = rolldyn.quasistatic(case)
    >>> qs.balls.load_inner_n               # NumPy array, one value per ball
    >>> qs.stiffness_matrix                 # 5 x 5 NumPy array [N/m, N/rad, ...]

Runs release the GIL. Ctrl-C stops a run cleanly: ``RunInterrupted`` (a
``KeyboardInterrupt``) is raised with the partial result in ``.result``.
``sweep(case, grid, client=...)`` runs a grid of dynamic runs on the
machine's cores, or on a Dask ``distributed`` client when one is given.
"""

from ._api import (
    DEFAULT_SOURCE,
    SERIES_DIR,
    SLOW_SERIES_DIR,
    SWEEP_ALIASES,
    Case,
    Channel,
    Result,
    RunInterrupted,
    SweepResult,
    catalogue,
    contact,
    frequencies,
    power,
    presets,
    quasistatic,
    quasistatic_sweep,
    run,
    spectrum,
    sweep,
    thermal,
    traction,
)
from ._reports import (
    ContactResult,
    Frequencies,
    PowerResult,
    QuasiStaticResult,
    Report,
    SpectrumResult,
    Summary,
    Table,
    ThermalResult,
    TractionResult,
)
from ._rolldyn import CaseError, ModelError, __version__

__all__ = [
    "DEFAULT_SOURCE",
    "SERIES_DIR",
    "SLOW_SERIES_DIR",
    "SWEEP_ALIASES",
    "Case",
    "CaseError",
    "Channel",
    "ContactResult",
    "Frequencies",
    "ModelError",
    "PowerResult",
    "QuasiStaticResult",
    "Report",
    "Result",
    "RunInterrupted",
    "SpectrumResult",
    "Summary",
    "SweepResult",
    "Table",
    "ThermalResult",
    "TractionResult",
    "catalogue",
    "contact",
    "frequencies",
    "power",
    "presets",
    "quasistatic",
    "quasistatic_sweep",
    "run",
    "spectrum",
    "sweep",
    "thermal",
    "traction",
    "__version__",
]

for _name in ("Case", "Channel", "Result", "RunInterrupted", "SweepResult"):
    globals()[_name].__module__ = __name__
del _name
