"""A 7008C back-to-back pair with a 200 N mounting preload: the preload,
the set's axial and radial stiffness and the cage speed against speed,
from the sweep the README runs; and, when the README's dynamic run is in
OUT_DIR/run, the shaft's orbit and vibration spectrum in motion.

    cargo run --release -- quasistatic examples/spindle_pair/case.toml \\
        --sweep speed=0rpm..20000rpm/21 -o examples/spindle_pair/out
    cargo run --release -- run examples/spindle_pair/case.toml \\
        --set 'arrangement.unbalance="20 g.mm"' -o examples/spindle_pair/out/run
    python3 examples/spindle_pair/plot.py [OUT_DIR]
"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = pathlib.Path(__file__).parent
out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else here / "out"
rows = [r for r in csv.DictReader(open(out / "sweep.csv")) if r["converged"] == "true"]
speed = [float(r["speed_rpm"]) for r in rows]
preload = [float(r["preload_n"]) for r in rows]
axial = [float(r["axial_stiffness_n_per_m"]) / 1e6 for r in rows]
radial = [float(r["radial_stiffness_z_n_per_m"]) / 1e6 for r in rows]
cage_ratio = [
    float(r["cage_speeds_rpm"].split(";")[0]) / s if s > 0 else float("nan")
    for r, s in zip(rows, speed)
]

run = out / "run" / "timeseries.parquet"
rows_of_panels = 2 if run.exists() else 1
fig, axes = plt.subplots(rows_of_panels, 3, figsize=(12, 3.6 * rows_of_panels), squeeze=False)
a, b, c = axes[0]
a.plot(speed, preload, "o-", ms=3)
a.set_xlabel("shaft speed [rpm]")
a.set_ylabel("preload [N]")
a.set_title("preload (200 N at rest)")
b.plot(speed, axial, "o-", ms=3, label="axial")
b.plot(speed, radial, "s-", ms=3, label="radial")
b.set_xlabel("shaft speed [rpm]")
b.set_ylabel("stiffness [N/µm]")
b.set_title("the pair's stiffness")
b.legend()
c.plot(speed, cage_ratio, "o-", ms=3)
c.set_xlabel("shaft speed [rpm]")
c.set_ylabel("cage / shaft speed")
c.set_title("cage speed ratio (Jones–Harris)")
if run.exists():
    import numpy as np
    import pyarrow.parquet as pq

    t = pq.read_table(run)
    time = t.column("time_s").to_numpy()
    late = time >= time[-1] / 2
    y = t.column("shaft_y_m").to_numpy()[late] * 1e6
    z = t.column("shaft_z_m").to_numpy()[late] * 1e6
    d, e, f = axes[1]
    d.plot(y - y.mean(), z - z.mean(), lw=0.6)
    d.set_aspect("equal")
    d.set_xlabel("shaft y [µm]")
    d.set_ylabel("shaft z [µm]")
    d.set_title("shaft orbit (second half of the run)")
    rate = 1.0 / (time[1] - time[0])
    spectrum = 2 * np.abs(np.fft.rfft((z - z.mean()) * np.hanning(len(z)))) / (len(z) / 2)
    freq = np.fft.rfftfreq(len(z), 1.0 / rate)
    e.semilogy(freq, spectrum * 1e3)
    e.set_xlabel("frequency [Hz]")
    e.set_ylabel("shaft z amplitude [nm]")
    e.set_title("shaft vibration spectrum")
    for k in (0, 1):
        f.plot(time, t.column(f"bearing{k}_cage_speed_rpm").to_numpy(), lw=0.8, label=f"bearing {k}")
    f.set_xlabel("time [s]")
    f.set_ylabel("cage speed [rpm]")
    f.set_title("cage speeds in motion")
    f.legend()
fig.suptitle("7008C back-to-back pair, position preload (rolldyn quasistatic and run)")
fig.tight_layout()
fig.savefig(out / "spindle_pair.png", dpi=150)
print(f"wrote {out / 'spindle_pair.png'}")
