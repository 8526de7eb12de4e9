"""Lei et al. 2023 (C8): friction power and outer-ring temperature of the
30x62x16 angular-contact bearing against speed, rolldyn against the
paper's values.

    cargo run --release --example seed004      # writes examples/seed004/out
    python3 examples/seed004/plot.py [OUT_DIR]
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from plotting import label, numbers, output_dir, plt, rows, save  # noqa: E402

out = output_dir(__file__)
table = rows(out / "power_temperature.csv")
speed = numbers(table, "speed_rpm")


def column(name):
    return numbers(table, name)


fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
a.plot(speed, column("total_w"), "o-", label="rolldyn total")
a.plot(speed, column("inner_w"), "s-", label="rolldyn inner")
a.plot(speed, column("outer_w"), "^-", label="rolldyn outer")
a.plot(speed, column("paper_inner_w"), "s--", label="Lei et al. 2023 inner")
a.plot(speed, column("paper_outer_w"), "^--", label="Lei et al. 2023 outer")
label(a, "speed [rpm]", "friction power [W]", legend=8)
b.plot(speed, column("outer_ring_c"), "o-", label="rolldyn")
b.plot(speed, column("paper_outer_ring_c"), "s--", label="Lei et al. 2023 network")
b.plot(speed, column("paper_fe_outer_ring_c"), "^:", label="Lei et al. 2023 FE")
label(b, "speed [rpm]", "outer-ring temperature [°C]", legend=8)
save(fig, out / "seed004.png")
