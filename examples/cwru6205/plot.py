"""CWRU 6205 with a 0.007 in outer-race fault: envelope spectrum of the
housing accelerometer's record ([sensor]) with the fault's lines, rolldyn's (from the run's
speeds) and CWRU's published BPFO = 3.5848 x shaft frequency.

    python3 examples/cwru6205/plot.py [RUN_DIR]   # default examples/cwru6205/out
"""
import csv
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = pathlib.Path(__file__).parent
run = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else here / "out"
name = "spectrum_sensor_acceleration_m_s2_envelope"
rows = list(csv.DictReader(open(run / f"{name}.csv")))
freq = [float(r["frequency_hz"]) for r in rows]
amp = [float(r["value"]) for r in rows]
lines = json.load(open(run / f"{name}.json"))["lines"]
bpfo = next(l["frequency_hz"] for l in lines if l["name"] == "BPFO")
cwru = 3.5848 * 1797 / 60

fig, ax = plt.subplots(figsize=(7, 4))
ax.plot(freq, amp, lw=1, label="rolldyn envelope spectrum")
for k in range(1, 6):
    ax.axvline(k * bpfo, color="C1", ls="--", lw=0.8, label="k x BPFO (run)" if k == 1 else None)
    ax.axvline(k * cwru, color="k", ls=":", lw=0.8, label="k x BPFO (CWRU, 107.4 Hz)" if k == 1 else None)
ax.set_xlim(0, 700)
ax.set_xlabel("frequency [Hz]")
ax.set_ylabel("envelope amplitude [m/s²]")
ax.set_title("6205 at 1797 rpm, outer-race fault (CWRU drive end)")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(run / "envelope_bpfo.png", dpi=150)
print(f"wrote {run / 'envelope_bpfo.png'}")
