"""Zhang et al. 2020 (C7): central film of the most loaded inner contact against the
inlet distance ratio L, one curve per radial load, with the critical ratio
L* above which the contact is flooded; and, with the film in the normal
approach, the radial natural frequency against L (dashed: dry); and from
the dynamic runs, the inner ring's RMS radial velocity against L (dashed:
dry; dotted: flooded).

    cargo run --release --example seed003      # writes examples/seed003/out
    python3 examples/seed003/plot.py [OUT_DIR]
"""
import pathlib
import sys


sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from plotting import label, numbers, output_dir, plt, rows, save  # noqa: E402

out = output_dir(__file__)
films = rows(out / "films.csv", lambda r: r["inlet_distance_ratio"] not in ("", "inf"))
fig, (ax, axf, axv) = plt.subplots(1, 3, figsize=(18, 4))
for k, fz in enumerate(sorted({r["radial_load_n"] for r in films}, key=float)):
    group = [r for r in films if r["radial_load_n"] == fz]
    ax.plot(numbers(group, "inlet_distance_ratio"), numbers(group, "central_film_m", 1e6), "o-", color=f"C{k}", label=f"F_z = {fz} N")
    ax.axvline(float(group[0]["critical_inlet_distance_ratio"]), color=f"C{k}", ls=":", lw=0.8)
label(ax, "inlet distance ratio L", "central film h_c [µm]", "Ceramic 45x75 at 15 000 rpm: starved film (Zhang et al. 2020); dotted: L*", legend=8)
approach = rows(out / "approach.csv", lambda r: r["inlet_distance_ratio"] != "inf")
for k, fz in enumerate(sorted({r["radial_load_n"] for r in approach}, key=float)):
    group = [r for r in approach if r["radial_load_n"] == fz]
    axf.plot(numbers(group, "inlet_distance_ratio"), numbers(group, "radial_frequency_hz"), "o-", color=f"C{k}", label=f"F_z = {fz} N")
    axf.axhline(float(group[0]["dry_radial_frequency_hz"]), color=f"C{k}", ls="--", lw=0.8)
axf.set_xscale("log")
label(axf, "inlet distance ratio L", "radial natural frequency f_z [Hz]", "film in the approach (dashed: dry)", legend=8)
# Without the dynamic runs (`seed003 OUT static`) the third panel stays empty.
if (out / "vibration.csv").exists():
    table = rows(out / "vibration.csv", lambda r: float(r["damping_ratio"]) == 0.05)
    for k, fz in enumerate(sorted({r["radial_load_n"] for r in table}, key=float)):
        group = [r for r in table if r["radial_load_n"] == fz]
        starved = [r for r in group if r["inlet_distance_ratio"] not in ("dry", "inf")]
        axv.plot(numbers(starved, "inlet_distance_ratio"), numbers(starved, "velocity_rms_z_m_s", 1e3), "o-", color=f"C{k}", label=f"F_z = {fz} N")
        for r in group:
            if r["inlet_distance_ratio"] in ("dry", "inf"):
                ls = "--" if r["inlet_distance_ratio"] == "dry" else ":"
                axv.axhline(1e3 * float(r["velocity_rms_z_m_s"]), color=f"C{k}", ls=ls, lw=0.8)
    label(axv, "inlet distance ratio L", "inner-ring v_z RMS [mm/s]", "dynamic runs, contact damping ratio 0.05 (assumed)", legend=8)
save(fig, out / "seed003.png")
