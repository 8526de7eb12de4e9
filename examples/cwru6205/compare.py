#!/usr/bin/env python3
"""The CWRU example against CWRU's measured drive-end records (0 hp).

Runs examples/cwru6205/case.toml healthy and with the outer-race (6
o'clock), inner-race and ball pits of 0.007, 0.014 and 0.021 in, as the
CWRU matrix does (examples/cwru_matrix), and reads from each run the
housing sensor's RMS, peak, crest factor and kurtosis (summary.json), its
velocity RMS in 10-1000 Hz and its envelope lines in 1.2-4.8 kHz
(`rolldyn spectrum`). Writes docs/data/cwru_simulated.csv and prints each
number against the measured record's (docs/data/cwru_records.csv, made by
scripts/cwru_records.py from the records themselves) with their ratio.
No parameter is fitted to the records: docs/validation.md, "Against CWRU's
measured records", says what the model lacks.

    python3 examples/cwru6205/compare.py [--rolldyn PATH]

Needs only Python 3 and the rolldyn command (default: cargo's release build).
"""
import argparse
import csv
import json
import pathlib
import subprocess
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
CASE = ROOT / "examples/cwru6205/case.toml"
MEASURED = ROOT / "docs/data/cwru_records.csv"
SIMULATED = ROOT / "docs/data/cwru_simulated.csv"

# CWRU's pits: diameter [in] -> length [mm]; depth 0.011 in (0.2794 mm).
SIZES = {0.007: "0.1778 mm", 0.014: "0.3556 mm", 0.021: "0.5334 mm"}
DEPTH = "0.2794 mm"
# CWRU's record numbers, 12 kHz drive end, 0 hp.
RECORDS = {
    ("normal", 0.0): 97,
    ("outer", 0.007): 130, ("outer", 0.014): 197, ("outer", 0.021): 234,
    ("inner", 0.007): 105, ("inner", 0.014): 169, ("inner", 0.021): 209,
    ("ball", 0.007): 118, ("ball", 0.014): 185, ("ball", 0.021): 222,
}


def overrides(fault, diameter):
    """The --set overrides of one CWRU case on the example."""
    if fault == "normal":
        return ["surface.outer.spall=[]"]
    length = SIZES[diameter]
    pit = f'position = "{{}}", length = "{length}", depth = "{DEPTH}"'
    if fault == "outer":
        return [f"surface.outer.spall.0.length={length}"]
    sets = ["surface.outer.spall=[]"]
    if fault == "inner":
        sets.append("surface.inner.spall=[{ " + pit.format("270 deg") + " }]")
    else:
        sets.append("surface.balls.spall=[{ ball = 0, " + pit.format("0 deg") + " }]")
    return sets


def simulate(rolldyn, fault, diameter, work):
    out = work / f"{fault}-{diameter}"
    args = [*rolldyn, "run", str(CASE), "-o", str(out)]
    for s in overrides(fault, diameter):
        args += ["--set", s]
    subprocess.run(args, check=True, capture_output=True)
    sensor = json.loads((out / "summary.json").read_text())["sensor"]
    spectrum = json.loads(subprocess.run(
        [*rolldyn, "spectrum", str(out), "--channel", "sensor_acceleration_m_s2",
         "--kind", "envelope", "--band", "1200:4800 Hz", "--peaks", "5", "--json"],
        check=True, capture_output=True, text=True).stdout)
    lines = ";".join(f"{p['frequency_hz']:.1f}:{p['value']:.3f}:{p['line']}"
                     for p in spectrum["peaks"])
    return {
        "record": RECORDS[(fault, diameter)], "fault": fault, "diameter_in": diameter,
        "rms_ms2": sensor["rms_m_s2"], "peak_ms2": sensor["peak_m_s2"],
        "crest": sensor["crest_factor"], "kurtosis": sensor["kurtosis"],
        "vel_rms_10_1000_mms": spectrum["velocity_rms_mm_s"],
        "env_top5_hz_ms2_line": lines,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rolldyn", help="the rolldyn command (default: cargo run --release)")
    a = parser.parse_args()
    rolldyn = [a.rolldyn] if a.rolldyn else ["cargo", "run", "--release", "--quiet", "--"]
    with open(MEASURED) as f:
        measured = {int(r["record"]): r for r in csv.DictReader(row for row in f if not row.startswith("#"))}
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for (fault, diameter) in RECORDS:
            rows.append(simulate(rolldyn, fault, diameter, pathlib.Path(work)))
    keys = list(rows[0])
    with open(SIMULATED, "w", newline="") as f:
        f.write("# The CWRU example's housing sensor (examples/cwru6205/compare.py), one row per CWRU record\n")
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.4g}" if isinstance(v, float) else v) for k, v in r.items()})
    stats = ["rms_ms2", "peak_ms2", "crest", "kurtosis", "vel_rms_10_1000_mms"]
    print("record fault   in     " + "  ".join(f"{s:>24}" for s in stats))
    for r in rows:
        m = measured[r["record"]]
        cells = [f"{r[s]:8.3g} / {float(m[s]):<8.3g}x{r[s] / float(m[s]):5.2f}" for s in stats]
        print(f"{r['record']:>6} {r['fault']:<7} {r['diameter_in']:<6} " + "  ".join(cells))
        print(f"{'':22}simulated lines {r['env_top5_hz_ms2_line']}")
        print(f"{'':22}measured  lines {m['env_top5_hz_ms2_line']}")
    print(f"wrote {SIMULATED.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
