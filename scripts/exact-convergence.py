#!/usr/bin/env python3
"""Convergence of `rolldyn traction --method exact` with its grid, and the
three methods against a fine reference (docs/dynamics.md, "Kalker's exact
theory", the convergence table).

For contacts of the 7218B preset's inner raceway at 10 kN and 10 m/s it
prints, per contact, the force on single grids of 32 ... 128 cells, the
default (32, 48, 64 extrapolated), the table and FASTSIM, and each one's
error against the reference: the same extrapolation on 64, 96 and 128
cells (the finest grids the solver accepts).

    python3 scripts/exact-convergence.py [path/to/rolldyn]

Takes about a minute in a release build (128 cells: ~6 s a contact).
"""

import json
import math
import subprocess
import sys
import tempfile

ROLLDYN = sys.argv[1] if len(sys.argv) > 1 else "target/release/rolldyn"
CONTACTS = [
    ("pure spin φ = 50 1/m", "0,0,50"),
    ("spin φ = 2 1/m", "0,0,2"),
    ("ξ = 1e-4", "1e-4,0,0"),
    ("η = 1e-4", "0,1e-4,0"),
    ("ξ = 2e-4, η = 1e-4, φ = 5 1/m", "2e-4,1e-4,5"),
]
SINGLE = [32, 48, 64, 96, 128]


def traction(case, creepages, *extra):
    out = subprocess.run(
        [ROLLDYN, "traction", case, "--load", "10 kN", "--rolling-speed", "10 m/s",
         "--creepages", creepages, "--json", *extra],
        check=True, capture_output=True, text=True).stdout
    r = json.loads(out)
    return r["force_x_n"], r["force_y_n"]


def richardson(cells, values):
    """The library's rule (traction::exact::extrapolate): F = F0 - C h^p
    through three grids when they converge monotonically at p in [1, 2]."""
    f1, f2, f3 = values
    d12, d23 = f2 - f1, f3 - f2
    if d12 == 0 or d23 == 0 or (d12 > 0) != (d23 > 0):
        return f3
    h1, h2, h3 = (1.0 / n for n in cells)
    ratio_at = lambda p: (h1**p - h2**p) / (h2**p - h3**p)
    lo, hi = 1.0, 2.0
    if not ratio_at(lo) <= d12 / d23 <= ratio_at(hi):
        return f3
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if ratio_at(mid) < d12 / d23 else (lo, mid)
    p = 0.5 * (lo + hi)
    return f3 + d23 * h3**p / (h2**p - h3**p)


def main():
    with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False) as f:
        f.write(subprocess.run([ROLLDYN, "new", "--preset", "7218B"], check=True,
                               capture_output=True, text=True).stdout)
        case = f.name
    print("| contact | force | " + " | ".join(f"{n} cells" for n in SINGLE)
          + " | default (32/48/64) | table | FASTSIM | reference [N] |")
    print("|---" * (len(SINGLE) + 6) + "|")
    for name, creep in CONTACTS:
        single = {n: traction(case, creep, "--method", "exact", "--cells", str(n)) for n in SINGLE}
        default = traction(case, creep, "--method", "exact")
        table = traction(case, creep, "--method", "table")
        fastsim = traction(case, creep, "--method", "fastsim")
        for k, label in enumerate(["F_x", "F_y"]):
            reference = richardson([64, 96, 128], [single[n][k] for n in (64, 96, 128)])
            scale = math.hypot(*single[128])

            def error(v):
                return f"{100 * (v[k] - reference) / scale:+.2f} %"

            cols = [error(single[n]) for n in SINGLE] + [error(default), error(table), error(fastsim)]
            print(f"| {name} | {label} | " + " | ".join(cols) + f" | {reference:.2f} |")


if __name__ == "__main__":
    main()
