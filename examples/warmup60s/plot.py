"""A minute of the default 7008C case with its thermal network coupled: the
run-up from 1000 to 10 000 rpm in 2 s and the first minute of the warm-up.
Reads only the channels it plots from the run's Parquet dataset (a
minute at 20 kHz is 1.2 million rows of 362 channels: not loaded whole),
every 100th sample.

    python3 examples/warmup60s/plot.py [RUN_DIR]   # default examples/warmup60s/out
"""
import pathlib
import sys

import pyarrow.dataset as ds

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from plotting import output_dir, plt, save  # noqa: E402

run = output_dir(__file__)
series = ds.dataset(run / "timeseries.parquet", format="parquet")
nodes = ["ball", "inner_ring", "outer_ring", "housing", "oil"]
columns = ["time_s", "inner_ring_speed_rpm", "cage_speed_rpm", "power_total_w"] + [
    f"temperature_{n}_c" for n in nodes
]
data = {c: [] for c in columns}
for batch in series.to_batches(columns=columns):
    for c in columns:
        data[c].extend(batch.column(c).to_numpy()[::100])

fig, (speed, power, heat) = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
speed.plot(data["time_s"], data["inner_ring_speed_rpm"], lw=1, label="inner ring")
speed.plot(data["time_s"], data["cage_speed_rpm"], lw=1, label="cage")
speed.set_ylabel("speed [rpm]")
speed.legend(fontsize=8)
power.plot(data["time_s"], data["power_total_w"], lw=0.6)
power.set_ylabel("friction power [W]")
for n in nodes:
    heat.plot(data["time_s"], data[f"temperature_{n}_c"], lw=1, label=n.replace("_", " "))
heat.set_ylabel("temperature [°C]")
heat.set_xlabel("time [s]")
heat.legend(fontsize=8)
speed.set_title("7008C: run-up and the first minute of the warm-up")
save(fig, run / "warmup.png")
