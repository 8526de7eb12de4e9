"""Lei et al. 2023 (C8): friction power and outer-ring temperature of the
30x62x16 angular-contact bearing against speed, rolldyn against the
paper's values.

    cargo run --release --example seed004      # writes examples/seed004/out
    python3 examples/seed004/plot.py [OUT_DIR]
"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = pathlib.Path(__file__).parent
out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else here / "out"
rows = list(csv.DictReader(open(out / "power_temperature.csv")))
speed = [float(r["speed_rpm"]) for r in rows]


def column(name):
    return [float(r[name]) if r[name] not in ("", "nan") else float("nan") for r in rows]


fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
a.plot(speed, column("total_w"), "o-", label="rolldyn total")
a.plot(speed, column("inner_w"), "s-", label="rolldyn inner")
a.plot(speed, column("outer_w"), "^-", label="rolldyn outer")
a.plot(speed, column("paper_inner_w"), "s--", label="Lei et al. 2023 inner")
a.plot(speed, column("paper_outer_w"), "^--", label="Lei et al. 2023 outer")
a.set_xlabel("speed [rpm]")
a.set_ylabel("friction power [W]")
a.legend(fontsize=8)
b.plot(speed, column("outer_ring_c"), "o-", label="rolldyn")
b.plot(speed, column("paper_outer_ring_c"), "s--", label="Lei et al. 2023 network")
b.plot(speed, column("paper_fe_outer_ring_c"), "^:", label="Lei et al. 2023 FE")
b.set_xlabel("speed [rpm]")
b.set_ylabel("outer-ring temperature [°C]")
b.legend(fontsize=8)
fig.tight_layout()
fig.savefig(out / "seed004.png", dpi=150)
print(f"wrote {out / 'seed004.png'}")
