"""Deng et al. 2022 Fig. 10b (C3) and Table 2 (C4) from the example's output:
cage speed ratio against axial load with its pure-rolling value, and the
inner-ring acceleration spectra of the waviness families.

    cargo run --release --example seed001      # writes examples/seed001/out
    python3 examples/seed001/plot.py [OUT_DIR]
"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = pathlib.Path(__file__).parent
out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else here / "out"
rows = list(csv.DictReader(open(out / "c3.csv")))
load = [float(r["axial_load_n"]) for r in rows]
fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
a.plot(load, [float(r["cage_speed_ratio"]) for r in rows], "o-", label="rolldyn")
a.plot(load, [float(r["pure_rolling_cage_speed_ratio"]) for r in rows], "--", label="pure rolling")
a.set_xlabel("axial load F_x [N]")
a.set_ylabel("cage speed ratio ω_c/ω_i")
a.set_title("C3: Deng et al. 2022 Fig. 10b")
a.legend()
for path in sorted(out.glob("spectrum_*.csv")):
    spectrum = list(csv.DictReader(open(path)))
    b.semilogy(
        [float(r["frequency_hz"]) for r in spectrum],
        [max(float(r["acceleration_m_s2"]), 1e-9) for r in spectrum],
        lw=0.8,
        label=path.stem.removeprefix("spectrum_"),
    )
b.set_xlim(0, 4000)
b.set_xlabel("frequency [Hz]")
b.set_ylabel("acceleration amplitude [m/s²]")
b.set_title("C4: waviness lines (Deng et al. 2022 Table 2)")
b.legend(fontsize=6)
fig.tight_layout()
fig.savefig(out / "seed001.png", dpi=150)
print(f"wrote {out / 'seed001.png'}")
