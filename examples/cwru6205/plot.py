"""CWRU 6205 with a 0.007 in outer-race fault: envelope spectrum of the
housing accelerometer's record ([sensor]) with the fault's lines, rolldyn's (from the run's
speeds) and CWRU's published BPFO = 3.5848 x shaft frequency.

    python3 examples/cwru6205/plot.py [RUN_DIR]   # default examples/cwru6205/out
"""
import json
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from plotting import label, numbers, output_dir, plt, rows, save  # noqa: E402

run = output_dir(__file__)
name = "spectrum_sensor_acceleration_m_s2_envelope"
spectrum = rows(run / f"{name}.csv")
lines = json.load(open(run / f"{name}.json"))["lines"]
bpfo = next(l["frequency_hz"] for l in lines if l["name"] == "BPFO")
cwru = 3.5848 * 1797 / 60

fig, ax = plt.subplots(figsize=(7, 4))
ax.plot(numbers(spectrum, "frequency_hz"), numbers(spectrum, "value"), lw=1, label="rolldyn envelope spectrum")
for k in range(1, 6):
    ax.axvline(k * bpfo, color="C1", ls="--", lw=0.8, label="k x BPFO (run)" if k == 1 else None)
    ax.axvline(k * cwru, color="k", ls=":", lw=0.8, label="k x BPFO (CWRU, 107.4 Hz)" if k == 1 else None)
ax.set_xlim(0, 700)
label(ax, "frequency [Hz]", "envelope amplitude [m/s²]", "6205 at 1797 rpm, outer-race fault (CWRU drive end)", legend=8)
save(fig, run / "envelope_bpfo.png")
