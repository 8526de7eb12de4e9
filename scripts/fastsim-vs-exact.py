#!/usr/bin/env python3
"""FASTSIM against Kalker's exact theory over creepage, spin and the ellipse ratio.

Runs `rolldyn traction` on explicit contacts: Q = 2088 N, steel (G =
76.923 GPa, nu = 0.3), mu = 0.1, V = 10 m/s, semi-axis across the rolling
direction b = 2.2609 mm and along it a = g*b for g = a/b in RATIOS (0.122 is
a 7218B inner-raceway contact). Creepages are given normalised by the
linear theory's saturation, xi* = G c^2 C11 xi / (3 mu Q), likewise eta* with
C22 and phi* = G c^3 C23 phi / (3 mu Q) (c^2 = ab; the slopes G c^2 C_ij are
FASTSIM's at vanishing creepage, which is Kalker's linear theory). FASTSIM
runs on its default grid, the exact theory on --cells (default 32).

Writes a CSV of every point (stdout) and, with --plot FILE, a figure of
|F_FASTSIM - F_exact| / (mu Q) per point and ratio.

    python3 scripts/fastsim-vs-exact.py [--rolldyn PATH] [--cells N] [--plot FILE] > map.csv
"""
import argparse
import json
import subprocess

RATIOS = [0.122, 0.25, 0.5, 1.0]
ACROSS = 2.2609e-3
LOAD, MU, G, NU = 2088.0, 0.1, 76.923e9, 0.3
# (xi*, eta*, phi*): each creepage alone, spin alone, and combinations.
POINTS = [(0.1, 0, 0), (0.5, 0, 0), (0, 0.1, 0), (0, 0.5, 0), (0, 0, 0.1), (0, 0, 0.5),
          (0, 0, 2.0), (0.3, 0, 0.5), (0, 0.3, 0.5), (0, 0.3, -0.5), (0.2, 0.2, 0.2),
          (0.5, 0.5, 1.0)]


def traction(rolldyn, along, creepages, *extra):
    args = [rolldyn, "traction", "--semi-axes", f"{along} m,{ACROSS} m", "--load", f"{LOAD} N",
            "--shear-modulus", f"{G} Pa", "--poisson-ratio", str(NU), "--friction", str(MU),
            "--rolling-speed", "10 m/s", "--creepages", ",".join(f"{c:.6e}" for c in creepages),
            "--json", *extra]
    return json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rolldyn", default="target/release/rolldyn")
    ap.add_argument("--cells", default="32")
    ap.add_argument("--plot")
    opt = ap.parse_args()
    mu_q = MU * LOAD
    rows = []
    print("ratio,xi_star,eta_star,phi_star,xi,eta,phi_1_m,fastsim_fx_n,fastsim_fy_n,exact_fx_n,exact_fy_n,"
          "error_over_mu_q,fastsim_stick,exact_stick")
    for g in RATIOS:
        along = g * ACROSS
        tiny = 1e-7
        # Linear slopes: G c^2 C11, G c^2 C22 (per unit creepage), G c^3 C23 (per 1/m).
        k11 = -traction(opt.rolldyn, along, (tiny, 0, 0))["force_x_n"] / tiny
        k22 = -traction(opt.rolldyn, along, (0, tiny, 0))["force_y_n"] / tiny
        k23 = traction(opt.rolldyn, along, (0, 0, tiny))["force_y_n"] / tiny
        for xs, es, ps in POINTS:
            c = (3 * mu_q * xs / k11, 3 * mu_q * es / k22, 3 * mu_q * ps / k23)
            f = traction(opt.rolldyn, along, c)
            e = traction(opt.rolldyn, along, c, "--method", "exact", "--cells", opt.cells)
            err = ((f["force_x_n"] - e["force_x_n"]) ** 2 + (f["force_y_n"] - e["force_y_n"]) ** 2) ** 0.5 / mu_q
            rows.append((g, (xs, es, ps), err))
            print(f"{g},{xs},{es},{ps},{c[0]:.4e},{c[1]:.4e},{c[2]:.4e},{f['force_x_n']:.4f},{f['force_y_n']:.4f},"
                  f"{e['force_x_n']:.4f},{e['force_y_n']:.4f},{err:.4f},{f['stick_fraction']:.3f},"
                  f"{e['stick_fraction']:.3f}", flush=True)
    if opt.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(9, 4))
        labels = [f"{p[0]:g},{p[1]:g},{p[2]:g}" for p in POINTS]
        width = 0.8 / len(RATIOS)
        for k, g in enumerate(RATIOS):
            errs = [100 * r[2] for r in rows if r[0] == g]
            ax.bar([i + k * width for i in range(len(POINTS))], errs, width, label=f"a/b = {g:g}")
        ax.set_xticks([i + 0.4 - width / 2 for i in range(len(POINTS))], labels, rotation=45, ha="right")
        ax.set_xlabel("normalised creepages ξ*, η*, φ*")
        ax.set_ylabel("|F_FASTSIM − F_exact| / μQ  [%]")
        ax.set_title(f"FASTSIM (16 × 10) against the exact theory ({opt.cells} × {opt.cells} cells)")
        ax.legend()
        fig.tight_layout()
        fig.savefig(opt.plot, dpi=110)


if __name__ == "__main__":
    main()
