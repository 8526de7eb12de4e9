"""Shan et al. 2023 Fig. 6: mean cage speed of the 6304 at 8000 rpm against the
radial load W, from `rolldyn run --sweep` (README), with the measured
2940 rpm and the paper's largest deviation (4.24 %).

    python3 examples/seed000/plot.py [SWEEP_DIR]   # default examples/seed000/sweep
"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = pathlib.Path(__file__).parent
sweep = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else here / "sweep"
rows = [r for r in csv.DictReader(open(sweep / "sweep.csv")) if r["status"] == "completed"]
load = [abs(float(r["force_z_n"])) for r in rows]
cage = [float(r["mean_cage_speed_rpm"]) for r in rows]
rolling = [float(r["pure_rolling_cage_speed_rpm"]) for r in rows]

fig, ax = plt.subplots(figsize=(6, 4))
ax.plot(load, cage, "o-", label="rolldyn, mean over the averaging window")
ax.plot(load, rolling, "--", label="pure rolling (solved contact angles)")
ax.axhline(2940, color="k", lw=1, label="measured (Shan et al. 2023 §3)")
ax.axhspan(2940 * (1 - 0.0424), 2940 * (1 + 0.0424), color="0.9", label="paper's model: within 4.24 %")
ax.set_xlabel("radial load W [N]")
ax.set_ylabel("cage speed [rpm]")
ax.set_title("6304 at 8000 rpm (Shan et al. 2023 Fig. 6)")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sweep / "fig6_cage_speed.png", dpi=150)
print(f"wrote {sweep / 'fig6_cage_speed.png'}")
