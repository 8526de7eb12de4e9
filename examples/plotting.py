"""What the examples' plot.py scripts share: the output directory from the
command line, CSV columns as numbers, headless matplotlib, axis labels and
the figure written where the run is.

A plot.py imports it from the examples directory:

    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
    from plotting import ...
"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # headless: the scripts write files, they show nothing
import matplotlib.pyplot as plt  # noqa: E402


def output_dir(script, default="out"):
    """The directory the command line names, else `default` beside `script`."""
    if len(sys.argv) > 1:
        return pathlib.Path(sys.argv[1])
    return pathlib.Path(script).parent / default


def rows(path, keep=None):
    """The rows of a CSV file as dicts, those `keep` accepts where given."""
    with open(path, newline="") as f:
        return [r for r in csv.DictReader(f) if keep is None or keep(r)]


def numbers(rows, name, scale=1.0):
    """Column `name` of `rows` as floats times `scale` (blank or "nan": NaN)."""
    return [scale * float(r[name]) if r[name] not in ("", "nan") else float("nan") for r in rows]


def label(ax, xlabel, ylabel, title=None, legend=None):
    """Axis labels, a title where given, and a legend where `legend` is
    True (matplotlib's font size) or a font size."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if title is not None:
        ax.set_title(title)
    if legend is True:
        ax.legend()
    elif legend is not None:
        ax.legend(fontsize=legend)


def save(fig, path, dpi=150):
    """Lays out `fig`, writes it to `path` and says so."""
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    print(f"wrote {path}")
