"""Shan et al. 2023 Fig. 6: mean cage speed of the 6304 at 8000 rpm against the
radial load W, from `rolldyn run --sweep` (README), with the measured
2940 rpm and the paper's largest deviation (4.24 %).

    python3 examples/seed000/plot.py [SWEEP_DIR]   # default examples/seed000/sweep
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from plotting import label, numbers, output_dir, plt, rows, save  # noqa: E402

sweep = output_dir(__file__, "sweep")
completed = rows(sweep / "sweep.csv", lambda r: r["status"] == "completed")
load = [abs(w) for w in numbers(completed, "force_z_n")]

fig, ax = plt.subplots(figsize=(6, 4))
ax.plot(load, numbers(completed, "mean_cage_speed_rpm"), "o-", label="rolldyn, mean over the averaging window")
ax.plot(load, numbers(completed, "pure_rolling_cage_speed_rpm"), "--", label="pure rolling (solved contact angles)")
ax.axhline(2940, color="k", lw=1, label="measured (Shan et al. 2023 §3)")
ax.axhspan(2940 * (1 - 0.0424), 2940 * (1 + 0.0424), color="0.9", label="paper's model: within 4.24 %")
label(ax, "radial load W [N]", "cage speed [rpm]", "6304 at 8000 rpm (Shan et al. 2023 Fig. 6)", legend=8)
save(fig, sweep / "fig6_cage_speed.png")
