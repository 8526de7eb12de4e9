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
import pathlib
import sys


sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from plotting import label, numbers, output_dir, plt, rows, save  # noqa: E402

out = output_dir(__file__)
converged = rows(out / "sweep.csv", lambda r: r["converged"] == "true")
speed = numbers(converged, "speed_rpm")
preload = numbers(converged, "preload_n")
axial = numbers(converged, "axial_stiffness_n_per_m", 1e-6)
radial = numbers(converged, "radial_stiffness_z_n_per_m", 1e-6)
cage_ratio = [
    float(r["cage_speeds_rpm"].split(";")[0]) / s if s > 0 else float("nan")
    for r, s in zip(converged, speed)
]

run = out / "run" / "timeseries.parquet"
rows_of_panels = 2 if run.exists() else 1
fig, axes = plt.subplots(rows_of_panels, 3, figsize=(12, 3.6 * rows_of_panels), squeeze=False)
a, b, c = axes[0]
a.plot(speed, preload, "o-", ms=3)
label(a, "shaft speed [rpm]", "preload [N]", "preload (200 N at rest)")
b.plot(speed, axial, "o-", ms=3, label="axial")
b.plot(speed, radial, "s-", ms=3, label="radial")
label(b, "shaft speed [rpm]", "stiffness [N/µm]", "the pair's stiffness", legend=True)
c.plot(speed, cage_ratio, "o-", ms=3)
label(c, "shaft speed [rpm]", "cage / shaft speed", "cage speed ratio (Jones–Harris)")
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
    label(d, "shaft y [µm]", "shaft z [µm]", "shaft orbit (second half of the run)")
    rate = 1.0 / (time[1] - time[0])
    spectrum = 2 * np.abs(np.fft.rfft((z - z.mean()) * np.hanning(len(z)))) / (len(z) / 2)
    freq = np.fft.rfftfreq(len(z), 1.0 / rate)
    e.semilogy(freq, spectrum * 1e3)
    label(e, "frequency [Hz]", "shaft z amplitude [nm]", "shaft vibration spectrum")
    for k in (0, 1):
        f.plot(time, t.column(f"bearing{k}_cage_speed_rpm").to_numpy(), lw=0.8, label=f"bearing {k}")
    label(f, "time [s]", "cage speed [rpm]", "cage speeds in motion", legend=True)
fig.suptitle("7008C back-to-back pair, position preload (rolldyn quasistatic and run)")
save(fig, out / "spindle_pair.png")
