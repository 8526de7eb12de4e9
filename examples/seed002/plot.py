"""Zhang et al. 2025 (C5/C6): cage speed ratio against time during the 7218B
speed ramp, for each friction coefficient the example runs.

    cargo run --release --example seed002      # writes examples/seed002/out
    python3 examples/seed002/plot.py [OUT_DIR]
"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = pathlib.Path(__file__).parent
out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else here / "out"
fig, ax = plt.subplots(figsize=(7, 4))
for path in sorted(out.glob("timeseries_mu*.csv")):
    rows = list(csv.DictReader(open(path)))
    t = [float(r["time_s"]) for r in rows]
    ax.plot(t, [float(r["cage_speed_ratio"]) for r in rows], lw=1, label=f"rolldyn, {path.stem.removeprefix('timeseries_')}")
    ax.plot(t, [float(r["pure_rolling_cage_speed_ratio"]) for r in rows], "--", lw=0.8, label="pure rolling")
ax.set_xlabel("time [s]")
ax.set_ylabel("cage speed ratio ω_c/ω_i")
ax.set_title("7218B start-up (Zhang et al. 2025)")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(out / "seed002.png", dpi=150)
print(f"wrote {out / 'seed002.png'}")
