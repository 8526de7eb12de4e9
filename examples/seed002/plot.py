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


def running_mean(values, width):
    """Mean over `width` samples centred on each (the pure-rolling ratio
    follows each ball's attitude, which wobbles sample to sample)."""
    half = width // 2
    sums = [0.0]
    for v in values:
        sums.append(sums[-1] + v)
    out = []
    for i in range(len(values)):
        lo, hi = max(0, i - half), min(len(values), i + half + 1)
        out.append((sums[hi] - sums[lo]) / (hi - lo))
    return out


for colour, path in zip(["tab:blue", "tab:red", "tab:green"], sorted(out.glob("timeseries_mu*.csv"))):
    rows = list(csv.DictReader(open(path)))
    t = [float(r["time_s"]) for r in rows]
    mu = path.stem.removeprefix("timeseries_mu")
    step = (t[-1] - t[0]) / max(len(t) - 1, 1)
    pure = running_mean([float(r["pure_rolling_cage_speed_ratio"]) for r in rows], max(1, round(0.02 / step)))
    ax.plot(t, pure, "--", color=colour, lw=1, label=f"pure rolling, μ = {mu} (20 ms mean)")
    ax.plot(t, [float(r["cage_speed_ratio"]) for r in rows], color=colour, lw=1.2, label=f"rolldyn, μ = {mu}")
ax.set_xlabel("time [s]")
ax.set_ylabel("cage speed ratio ω_c/ω_i")
ax.set_title("7218B start-up (Zhang et al. 2025)")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(out / "seed002.png", dpi=150)
print(f"wrote {out / 'seed002.png'}")
