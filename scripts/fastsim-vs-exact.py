#!/usr/bin/env python3
"""FASTSIM against Kalker's exact theory on one ball-bearing contact.

Runs `rolldyn traction` on an explicit contact (default: a 7218B inner
raceway contact, Q = 2088 N, a = 0.2761 mm along and b = 2.2609 mm across
the rolling direction, steel, mu = 0.1) over creepages and spin: FASTSIM on
its default grid against the exact theory on 24 x 24 and 32 x 32 cells.
Prints a Markdown table of the forces and their difference relative to
mu*Q (docs/validation.md holds its output).

    python3 scripts/fastsim-vs-exact.py [path/to/rolldyn]
"""
import json
import subprocess
import sys

ROLLDYN = sys.argv[1] if len(sys.argv) > 1 else "target/release/rolldyn"
CONTACT = ["--semi-axes", "0.2761 mm,2.2609 mm", "--load", "2088 N",
           "--shear-modulus", "76.923 GPa", "--poisson-ratio", "0.3",
           "--friction", "0.1", "--rolling-speed", "10 m/s"]
MU_Q = 0.1 * 2088.0


def traction(creepages, *extra):
    out = subprocess.run([ROLLDYN, "traction", *CONTACT, "--creepages", creepages,
                          "--json", *extra], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


print("| ξ | η | φ (1/m) | FASTSIM F_x, F_y (N) | exact 32² F_x, F_y (N) | exact 24² F_x, F_y (N) | ΔF/μQ FASTSIM vs exact 32² | stick FASTSIM / exact |")
print("|---|---|---|---|---|---|---|---|")
for xi, eta, phi in [(1e-4, 0, 0), (1e-3, 0, 0), (0, 1e-3, 0), (0, 0, 2), (0, 0, 5), (0, 0, 20),
                     (0, 0, 50), (1e-3, 0, 20), (3e-4, 1e-3, 10), (3e-3, 3e-4, 20), (1e-3, 1e-3, 5)]:
    c = f"{xi},{eta},{phi}"
    f = traction(c)
    e32 = traction(c, "--method", "exact", "--cells", "32")
    e24 = traction(c, "--method", "exact", "--cells", "24")
    dx = f["force_x_n"] - e32["force_x_n"]
    dy = f["force_y_n"] - e32["force_y_n"]
    print(f"| {xi:g} | {eta:g} | {phi:g} | {f['force_x_n']:.2f}, {f['force_y_n']:.2f} "
          f"| {e32['force_x_n']:.2f}, {e32['force_y_n']:.2f} | {e24['force_x_n']:.2f}, {e24['force_y_n']:.2f} "
          f"| {100 * (dx * dx + dy * dy) ** 0.5 / MU_Q:.1f} % | {f['stick_fraction']:.2f} / {e32['stick_fraction']:.2f} |",
          flush=True)
