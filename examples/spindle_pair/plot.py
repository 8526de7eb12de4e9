"""A 7008C back-to-back pair with a 200 N mounting preload: the preload,
the set's axial and radial stiffness and the cage speed against speed,
from the sweep the README runs.

    cargo run --release -- quasistatic examples/spindle_pair/case.toml \\
        --sweep speed=0rpm..20000rpm/21 -o examples/spindle_pair/out
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

fig, (a, b, c) = plt.subplots(1, 3, figsize=(12, 3.6))
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
fig.suptitle("7008C back-to-back pair, position preload (rolldyn quasistatic)")
fig.tight_layout()
fig.savefig(out / "spindle_pair.png", dpi=150)
print(f"wrote {out / 'spindle_pair.png'}")
