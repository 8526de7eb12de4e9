"""Zhang et al. 2025 (C5/C6): cage speed ratio against time during the 7218B
speed ramp, for each friction coefficient the example runs.

    cargo run --release --example seed002      # writes examples/seed002/out
    python3 examples/seed002/plot.py [OUT_DIR]
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from plotting import label, numbers, output_dir, plt, rows, save  # noqa: E402

out = output_dir(__file__)
fig, ax = plt.subplots(figsize=(7, 4))


def running_mean(values, width):
    """Mean over `width` samples centred on each (the pure-rolling ratio
    follows each ball's attitude, which wobbles sample to sample)."""
    half = width // 2
    sums = [0.0]
    for v in values:
        sums.append(sums[-1] + v)
    means = []
    for i in range(len(values)):
        lo, hi = max(0, i - half), min(len(values), i + half + 1)
        means.append((sums[hi] - sums[lo]) / (hi - lo))
    return means


for colour, path in zip(["tab:blue", "tab:red", "tab:green"], sorted(out.glob("timeseries_mu*.csv"))):
    series = rows(path)
    t = numbers(series, "time_s")
    mu = path.stem.removeprefix("timeseries_mu")
    step = (t[-1] - t[0]) / max(len(t) - 1, 1)
    pure = running_mean(numbers(series, "pure_rolling_cage_speed_ratio"), max(1, round(0.02 / step)))
    ax.plot(t, pure, "--", color=colour, lw=1, label=f"pure rolling, μ = {mu} (20 ms mean)")
    ax.plot(t, numbers(series, "cage_speed_ratio"), color=colour, lw=1.2, label=f"rolldyn, μ = {mu}")
label(ax, "time [s]", "cage speed ratio ω_c/ω_i", "7218B start-up (Zhang et al. 2025)", legend=8)
save(fig, out / "seed002.png")
