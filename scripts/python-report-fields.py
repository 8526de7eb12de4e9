#!/usr/bin/env python3
"""The typed fields of the Python package's report classes, from the CLI's
own ``--json`` outputs (crates/rolldyn-py/python/rolldyn/_reports.py).

Runs every report command on a few cases (the default case, a preloaded
pair, a dry deep-groove bearing with a spall and a sensor, the 7218B with
FASTSIM and the exact theory) and writes, between the ``# fields:``
markers of each class, one annotation per top-level key with the type
the report's attribute gives (float, int, str, bool, Report, Table,
np.ndarray, list), Optional where a key can be null (a key a set's
report lacks raises AttributeError there: the set's own keys are
declared beside the single bearing's). The package's test
``test_report_classes_declare_their_fields`` checks the same outputs
against the declarations, so a key added to a report without its field
fails there; this script rewrites them.

    python3 scripts/python-report-fields.py [path/to/rolldyn]
"""

import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
ROLLDYN = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "target/release/rolldyn")
REPORTS = ROOT / "crates/rolldyn-py/python/rolldyn/_reports.py"

CASES = {
    "default": [],
    "pair": [str(ROOT / "examples/spindle_pair/case.toml")],
    "cwru": [str(ROOT / "examples/cwru6205/case.toml")],
}
TRACTION = ["--load", "500 N", "--rolling-speed", "10 m/s", "--creepages", "1e-3,0,2"]
FASTSIM = ["--set", 'model.traction={ law = "fastsim", friction = 0.1 }']


def cli(*args):
    out = subprocess.run([ROLLDYN, *args, "--json"], capture_output=True, text=True)
    if out.returncode != 0:
        raise SystemExit(f"rolldyn {' '.join(args)}: {out.stderr.strip()}")
    return json.loads(out.stdout)


def outputs(directory):
    """Class name -> list of reports (dicts) of the commands behind it."""
    got = {k: [] for k in ("QuasiStaticResult", "PowerResult", "ThermalResult", "Frequencies",
                           "ContactResult", "TractionResult", "SpectrumResult", "Summary")}
    for name, case in CASES.items():
        got["QuasiStaticResult"].append(cli("quasistatic", *case))
        got["PowerResult"].append(cli("power", *case))
        got["ThermalResult"].append(cli("thermal", *case))
        got["Frequencies"].append(cli("frequencies", *case))
        run = Path(directory) / name
        subprocess.run([ROLLDYN, "run", *case, "--duration", "2 ms", "-o", str(run), "--force"],
                       check=True, capture_output=True)
        got["Summary"].append(json.loads((run / "summary.json").read_text()))
        if name == "default":
            got["ContactResult"].append(cli("contact", "--load", "500 N"))
            got["SpectrumResult"].append(cli("spectrum", str(run), "--channel", "cage_speed_rpm"))
    got["ThermalResult"].append(cli("thermal", "--transient", "10 s"))
    got["TractionResult"] += [
        cli("traction", *TRACTION),
        cli("traction", *TRACTION, *FASTSIM, "--method", "exact", "--cells", "8"),
        cli("traction", *TRACTION, *FASTSIM, "--method", "table"),
    ]
    return got


# Keys null on every case above (they need options those cases do not
# set): their types as docs/cli.md states them.
NULL_ONLY = {
    "reaction_force_x_n": "float", "reaction_force_y_n": "float", "reaction_force_z_n": "float",
    "reaction_moment_y_n_m": "float", "reaction_moment_z_n_m": "float",
    "stiffness_matrix_without_film": "np.ndarray", "conventional_stiffness_without_film": "Report",
    "modes": "Report", "fits": "Report", "map_cells": "int", "exact": "Report",
    "band_hz": "np.ndarray", "segment": "int", "segments": "int", "velocity_rms_mm_s": "float",
    "velocity_rms_band_hz": "np.ndarray", "error": "str", "ball_pass_jitter": "float",
    "ball_pass_interval_s": "float", "outer_ring_velocity_rms_y_mm_s": "float",
    "outer_ring_velocity_rms_z_mm_s": "float", "envelope_lines": "Report",
    "waviness_lines": "Report", "spall_growth": "Table", "thermal_coupling": "Report",
    "verify": "Report", "transient": "Report", "stick_fraction": "float",
}


def kind(value):
    """The attribute's Python type for a JSON value (``_reports._view``)."""
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, int):
        return "int"
    if isinstance(value, float):
        return "float"
    if isinstance(value, str):
        return "str"
    if isinstance(value, dict):
        return "Report"
    if isinstance(value, list):
        if value and all(isinstance(v, dict) for v in value):
            return "Table"
        if value and all(isinstance(v, (int, float)) and not isinstance(v, bool) or v is None
                         for v in value):
            return "np.ndarray"
        if value and all(isinstance(v, list) for v in value):
            return "np.ndarray"
        return "list"
    return None


def fields(reports):
    """Key -> annotation over the reports, in first-seen order."""
    seen, nullable = {}, set()
    for report in reports:
        for key, value in report.items():
            types = seen.setdefault(key, [])
            k = kind(value)
            if k is None:
                nullable.add(key)
            elif k not in types:
                types.append(k)
    out = {}
    for key, types in seen.items():
        if "int" in types and "float" in types:
            types = [t for t in types if t != "int"]
        if "list" in types and len(types) > 1:  # an empty list beside its kind
            types = [t for t in types if t != "list"]
        if not types and key in NULL_ONLY:
            types = [NULL_ONLY[key]]
        t = types[0] if len(types) == 1 else ("Any" if not types else f"Union[{', '.join(types)}]")
        out[key] = f"Optional[{t}]" if key in nullable and t != "Any" else t
    return out


def main():
    with tempfile.TemporaryDirectory() as directory:
        got = outputs(directory)
    text = REPORTS.read_text()
    for cls, reports in got.items():
        block = "".join(f"    {k}: {t}\n" for k, t in fields(reports).items())
        pattern = re.compile(
            rf"(    # fields: {cls} \(scripts/python-report-fields.py\)\n).*?(    # fields: end\n)",
            re.S)
        if not pattern.search(text):
            raise SystemExit(f"{REPORTS}: no fields markers in class {cls}")
        text = pattern.sub(lambda m: m.group(1) + block + m.group(2), text)
    REPORTS.write_text(text)
    print(f"{REPORTS}: fields of {len(got)} classes written")


if __name__ == "__main__":
    main()
