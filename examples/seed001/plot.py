"""Deng et al. 2022 Fig. 10b (C3) and Table 2 (C4) from the example's output:
cage speed ratio against axial load with its pure-rolling value, and the
inner-ring acceleration spectra of the waviness families.

    cargo run --release --example seed001      # writes examples/seed001/out
    python3 examples/seed001/plot.py [OUT_DIR]
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from plotting import label, numbers, output_dir, plt, rows, save  # noqa: E402

out = output_dir(__file__)
c3 = rows(out / "c3.csv")
load = numbers(c3, "axial_load_n")
fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
a.plot(load, numbers(c3, "cage_speed_ratio"), "o-", label="rolldyn")
a.plot(load, numbers(c3, "pure_rolling_cage_speed_ratio"), "--", label="pure rolling")
label(a, "axial load F_x [N]", "cage speed ratio ω_c/ω_i", "C3: Deng et al. 2022 Fig. 10b", legend=True)
for path in sorted(out.glob("spectrum_*.csv")):
    spectrum = rows(path)
    b.semilogy(
        numbers(spectrum, "frequency_hz"),
        [max(v, 1e-9) for v in numbers(spectrum, "acceleration_m_s2")],
        lw=0.8,
        label=path.stem.removeprefix("spectrum_"),
    )
b.set_xlim(0, 4000)
label(b, "frequency [Hz]", "acceleration amplitude [m/s²]", "C4: waviness lines (Deng et al. 2022 Table 2)", legend=6)
save(fig, out / "seed001.png")
