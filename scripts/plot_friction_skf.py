#!/usr/bin/env python3
"""Friction torque of rolldyn's local method against SKF's frictional-moment
model (docs/validation.md, "Friction torque against the catalogue model").

    ROLLDYN_FRICTION_CSV=docs/figures/friction_skf.csv \
        cargo test --release -p rolldyn-case --test friction_catalogue
    python3 scripts/plot_friction_skf.py   # needs matplotlib

Reads docs/figures/friction_skf.csv, writes docs/figures/friction_skf.png:
rolldyn / SKF against speed for both rolling-force fits, the points within
the catalogue model's full-film conditions filled, the others hollow.
"""
import csv
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

root = pathlib.Path(__file__).resolve().parent.parent
rows = list(csv.DictReader(open(root / "docs/figures/friction_skf.csv")))
fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
colours = {"0.01": "tab:red", "0.05": "tab:blue", "0.2": "tab:green"}
for ax, law, title in zip(
    axes,
    ["houpert", "biboulet_houpert"],
    ["Houpert's fits (default)", "Biboulet & Houpert 2010, fully flooded"],
):
    for r in rows:
        if r["law"] != law:
            continue
        compared = r["compared"] == "true"
        colour = colours[r["load_fraction"]]
        ax.scatter(
            float(r["speed_rpm"]),
            float(r["ratio"]),
            s=14,
            facecolors=colour if compared else "none",
            edgecolors=colour,
            alpha=0.8 if compared else 0.35,
        )
    ax.axhspan(0.75, 1.25, color="0.9", zorder=0)
    ax.axhline(1.0, color="0.4", lw=0.8)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("inner-ring speed [r/min]")
    ax.set_title(title)
axes[0].set_ylabel("friction torque, rolldyn / SKF model")
for fraction, colour in colours.items():
    axes[1].scatter([], [], color=colour, s=14, label=f"load {float(fraction) * 100:g} % of C")
axes[1].scatter([], [], facecolors="none", edgecolors="0.3", s=14, label="outside κ ≥ 1, φ_bl ≤ 0.1, n d_m ≤ 5e5")
axes[1].legend(loc="upper left", fontsize=8)
fig.suptitle("6205, 6210, 6305, 7205B, 7310B; oil jet; ν 5–200 mm²/s (band: ±25 %)", fontsize=10)
fig.tight_layout()
fig.savefig(root / "docs/figures/friction_skf.png", dpi=110)
print("wrote docs/figures/friction_skf.png")
