"""The features table of the CWRU test matrix (examples/cwru_matrix/run.sh):
one row per run with its labels (fault, position, size, load) and its
features: the envelope spectrum's amplitude at the bearing's lines (from
`rolldyn spectrum --kind envelope`) and, when pyarrow is installed, the
RMS, kurtosis and crest factor of the signal over the averaging window.

    python3 examples/cwru_matrix/features.py OUT      # writes OUT/features.csv
"""

import csv
import json
import math
import os
import sys

CHANNEL = "sensor_acceleration_m_s2"
SPECTRUM = f"spectrum_{CHANNEL}_envelope"
# CWRU's motor loads and the shaft speeds it reports at them.
LOAD_HP = {1797.0: 0, 1772.0: 1, 1750.0: 2, 1730.0: 3}
# Raceway angle of an outer-race pit (ball azimuth from +y towards +z;
# the load acts along -z) as CWRU's clock position.
OCLOCK = {"270 deg": 6, "0 deg": 3, "90 deg": 12}
INCH = 25.4


def envelope_features(point):
    """Amplitudes of the envelope spectrum at the characteristic lines: the
    largest bin within one resolution of each line."""
    with open(os.path.join(point, SPECTRUM + ".json")) as f:
        spectrum = json.load(f)
    with open(os.path.join(point, SPECTRUM + ".csv")) as f:
        rows = [(float(r["frequency_hz"]), float(r["value"])) for r in csv.DictReader(f)]
    c = spectrum["characteristic"]
    lines = {
        "f_r": c["shaft_hz"],
        "f_c": c["cage_hz"],
        "bpfo": c["bpfo_hz"],
        "bpfi": c["bpfi_hz"],
        "bpfi_minus_f_r": c["bpfi_hz"] - c["shaft_hz"],
        "bpfi_plus_f_r": c["bpfi_hz"] + c["shaft_hz"],
        "2bsf": 2.0 * c["ball_spin_hz"],
        "2bsf_minus_f_c": 2.0 * c["ball_spin_hz"] - c["cage_hz"],
        "2bsf_plus_f_c": 2.0 * c["ball_spin_hz"] + c["cage_hz"],
    }
    width = spectrum["resolution_hz"]
    out = {}
    for name, hz in lines.items():
        near = [v for f, v in rows if abs(f - hz) <= width]
        out[f"env_{name}_m_s2"] = max(near) if near else float("nan")
    top = max(rows[1:], key=lambda r: r[1])
    out["env_peak_hz"] = top[0]
    return out, spectrum["from_s"]


def signal_features(point, start):
    """RMS, kurtosis and crest factor of the channel from `start` on
    (None without pyarrow)."""
    try:
        import pyarrow.dataset as ds
    except ImportError:
        return {}
    table = ds.dataset(os.path.join(point, "timeseries.parquet")).to_table(
        columns=["time_s", CHANNEL])
    t = table.column("time_s").to_pylist()
    x = [v for tv, v in zip(t, table.column(CHANNEL).to_pylist()) if tv >= start]
    mean = sum(x) / len(x)
    d = [v - mean for v in x]
    var = sum(v * v for v in d) / len(d)
    rms = math.sqrt(var)
    return {
        "rms_m_s2": rms,
        "kurtosis": sum(v ** 4 for v in d) / len(d) / var ** 2 if var > 0 else float("nan"),
        "crest_factor": max(abs(v) for v in d) / rms if rms > 0 else float("nan"),
    }


def main(out):
    table = []
    for fault in ["healthy", "outer", "inner", "ball"]:
        with open(os.path.join(out, fault, "sweep.json")) as f:
            points = json.load(f)
        for p in points:
            size = next((v for k, v in p.items() if k.endswith("spall.0.length")), None)
            position = p.get("surface.outer.spall.0.position", "270 deg" if fault == "outer" else None)
            row = {
                "fault": fault,
                "position_oclock": OCLOCK.get(position, "") if fault == "outer" else "",
                "size_in": round(float(size.split()[0]) / INCH, 3) if size else 0.0,
                "load_hp": LOAD_HP.get(round(p["speed_rpm"], 1), ""),
                "speed_rpm": p["speed_rpm"],
                "status": p["status"],
                "point": os.path.join(fault, p["point"]),
            }
            point = os.path.join(out, fault, p["point"])
            features, start = envelope_features(point)
            row.update(features)
            row.update(signal_features(point, start))
            table.append(row)
    path = os.path.join(out, "features.csv")
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0]))
        w.writeheader()
        w.writerows(table)
    print(f"wrote {path}: {len(table)} runs")
    # Which characteristic line leads the envelope spectrum, by fault.
    for fault in ["outer", "inner", "ball"]:
        rows = [r for r in table if r["fault"] == fault]
        keys = ["env_bpfo_m_s2", "env_bpfi_m_s2", "env_2bsf_m_s2", "env_f_r_m_s2"]
        leads = {}
        for r in rows:
            lead = max(keys, key=lambda k: r[k])
            leads[lead] = leads.get(lead, 0) + 1
        print(f"  {fault:<6} largest of BPFO/BPFI/2xBSF/f_r: "
              + ", ".join(f"{k[4:-5]} {n}/{len(rows)}" for k, n in sorted(leads.items())))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "examples/cwru_matrix/out")
