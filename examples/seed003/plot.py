"""Zhang et al. 2020 (C7): central film of the most loaded inner contact against the
inlet distance ratio L, one curve per radial load, with the critical ratio
L* above which the contact is flooded; and, with the film in the normal
approach, the radial natural frequency against L (dashed: dry); and from
the dynamic runs, the inner ring's RMS radial velocity against L (dashed:
dry; dotted: flooded).

    cargo run --release --example seed003      # writes examples/seed003/out
    python3 examples/seed003/plot.py [OUT_DIR]
"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = pathlib.Path(__file__).parent
out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else here / "out"
rows = list(csv.DictReader(open(out / "films.csv")))
rows = [r for r in rows if r["inlet_distance_ratio"] not in ("", "inf")]
fig, (ax, axf, axv) = plt.subplots(1, 3, figsize=(18, 4))
for k, fz in enumerate(sorted({r["radial_load_n"] for r in rows}, key=float)):
    group = [r for r in rows if r["radial_load_n"] == fz]
    ax.plot([float(r["inlet_distance_ratio"]) for r in group], [1e6 * float(r["central_film_m"]) for r in group], "o-", color=f"C{k}", label=f"F_z = {fz} N")
    ax.axvline(float(group[0]["critical_inlet_distance_ratio"]), color=f"C{k}", ls=":", lw=0.8)
ax.set_xlabel("inlet distance ratio L")
ax.set_ylabel("central film h_c [µm]")
ax.set_title("Ceramic 45x75 at 15 000 rpm: starved film (Zhang et al. 2020); dotted: L*")
ax.legend(fontsize=8)
approach = list(csv.DictReader(open(out / "approach.csv")))
approach = [r for r in approach if r["inlet_distance_ratio"] != "inf"]
for k, fz in enumerate(sorted({r["radial_load_n"] for r in approach}, key=float)):
    group = [r for r in approach if r["radial_load_n"] == fz]
    ls = [float(r["inlet_distance_ratio"]) for r in group]
    axf.plot(ls, [float(r["radial_frequency_hz"]) for r in group], "o-", color=f"C{k}", label=f"F_z = {fz} N")
    axf.axhline(float(group[0]["dry_radial_frequency_hz"]), color=f"C{k}", ls="--", lw=0.8)
axf.set_xscale("log")
axf.set_xlabel("inlet distance ratio L")
axf.set_ylabel("radial natural frequency f_z [Hz]")
axf.set_title("film in the approach (dashed: dry)")
axf.legend(fontsize=8)
# Without the dynamic runs (`seed003 OUT static`) the third panel stays empty.
if (out / "vibration.csv").exists():
    vibration = list(csv.DictReader(open(out / "vibration.csv")))
    table = [r for r in vibration if float(r["damping_ratio"]) == 0.05]
    for k, fz in enumerate(sorted({r["radial_load_n"] for r in table}, key=float)):
        group = [r for r in table if r["radial_load_n"] == fz]
        starved = [r for r in group if r["inlet_distance_ratio"] not in ("dry", "inf")]
        axv.plot([float(r["inlet_distance_ratio"]) for r in starved], [1e3 * float(r["velocity_rms_z_m_s"]) for r in starved], "o-", color=f"C{k}", label=f"F_z = {fz} N")
        for r in group:
            if r["inlet_distance_ratio"] in ("dry", "inf"):
                ls = "--" if r["inlet_distance_ratio"] == "dry" else ":"
                axv.axhline(1e3 * float(r["velocity_rms_z_m_s"]), color=f"C{k}", ls=ls, lw=0.8)
    axv.set_xlabel("inlet distance ratio L")
    axv.set_ylabel("inner-ring v_z RMS [mm/s]")
    axv.set_title("dynamic runs, contact damping ratio 0.05 (assumed)")
    axv.legend(fontsize=8)
fig.tight_layout()
fig.savefig(out / "seed003.png", dpi=150)
print(f"wrote {out / 'seed003.png'}")
