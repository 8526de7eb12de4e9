"""The free 7218B inner ring's least stable mode under dry traction:
growth rate against speed (μ = 0.1) and against friction (10 000 rpm),
from the example's table.

    cargo run --release --example ring_stability   # writes examples/ring_stability/out
    python3 examples/ring_stability/plot.py [OUT_DIR]
"""
import pathlib
import sys


sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from plotting import label, output_dir, plt, save  # noqa: E402

out = output_dir(__file__)
rows = [
    [cell.strip() for cell in line.split("|")]
    for line in open(out / "table.txt")
    if not line.startswith("#")
]
fig, axes = plt.subplots(1, 2, figsize=(11, 4))
for ax, sweep, column, axis in [
    (axes[0], "speed", 1, "inner ring speed [rpm] (μ = 0.1)"),
    (axes[1], "friction", 2, "friction coefficient μ (10 000 rpm)"),
]:
    points = sorted((float(r[column]), float(r[3])) for r in rows if r[0] == sweep)
    ax.plot([p[0] for p in points], [p[1] for p in points], "o-")
    ax.axhline(0.0, color="grey", lw=0.8)
    label(ax, axis, "growth rate σ [1/s]")
    if sweep == "friction":
        ax.set_xscale("log")
fig.suptitle("7218B free inner ring: growth rate of its least stable mode (rolldyn::stability)")
save(fig, out / "ring_stability.png", dpi=120)
