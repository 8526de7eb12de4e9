"""A run-down of the default 7008C case: the motor off at 10 000 rpm, the
rotor (1.2e-4 kg.m^2) slowing under the bearing's friction. Plots the
speed, the friction torque a coast-down test would infer, -J dw/dt over
10 ms windows, against the bearing's friction torque channel and the
steady friction torque of prescribed-speed runs, and the cage speed ratio.

    cargo run --release -- run examples/run_down/case.toml -o examples/run_down/out/run_down
    for s in 9500 8500 7800; do
        cargo run --release -- run --speed "$s rpm" --duration "0.2 s" -o examples/run_down/out/steady_$s
    done
    python3 examples/run_down/plot.py [OUT_DIR]   # default examples/run_down/out
"""
import json
import math
import pathlib
import sys

import pyarrow.dataset as ds

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from plotting import label, output_dir, plt, save  # noqa: E402

out = output_dir(__file__)
INERTIA = 1.2e-4  # operating.rotor_inertia of case.toml [kg m^2]
RPM = 2 * math.pi / 60

columns = ["time_s", "inner_ring_speed_rpm", "cage_speed_rpm", "friction_torque_n_m"]
table = ds.dataset(out / "run_down" / "timeseries.parquet", format="parquet").to_table(
    columns=columns
)
data = {c: table.column(c).to_numpy() for c in columns}
t, speed = data["time_s"], data["inner_ring_speed_rpm"]

# What a coast-down rig measures: -J dw/dt, here over 10 ms windows,
# beside the mean of the bearing's friction torque over the same window.
window = max(1, int(round(0.01 / (t[1] - t[0]))))
coast_speed, coast_torque, channel = [], [], []
for a in range(0, len(t) - window, window):
    b = a + window
    coast_speed.append(0.5 * (speed[a] + speed[b]))
    coast_torque.append(-INERTIA * (speed[b] - speed[a]) * RPM / (t[b] - t[a]))
    channel.append(data["friction_torque_n_m"][a : b + 1].mean())

steady = []
for d in sorted(out.glob("steady_*")):
    summary = json.loads((d / "summary.json").read_text())
    steady.append((summary["inner_ring_speed_rpm"], summary["mean_friction_torque_n_m"]))

fig, (ax_speed, ax_torque, ax_cage) = plt.subplots(1, 3, figsize=(13, 3.8))
ax_speed.plot(t, speed)
label(ax_speed, "time [s]", "inner-ring speed [rpm]", "run-down from 10 000 rpm")

ax_torque.plot(coast_speed, coast_torque, "o", ms=3, label="coast-down: −J dω/dt")
ax_torque.plot(coast_speed, channel, "-", label="friction torque channel")
if steady:
    s, m = zip(*steady)
    ax_torque.plot(s, m, "s", ms=6, label="prescribed speed, 0.2 s")
label(ax_torque, "inner-ring speed [rpm]", "friction torque [N·m]", "friction torque", legend=8)

ax_cage.plot(t[1:], data["cage_speed_rpm"][1:] / speed[1:])
label(ax_cage, "time [s]", "cage / inner-ring speed", "cage speed ratio")

save(fig, out / "run_down.png", dpi=120)
