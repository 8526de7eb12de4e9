#!/usr/bin/env python3
"""Work–precision of `rolldyn run`: the cost of an answer against its error
(docs/performance.md, "Work and precision").

For each case it runs the integrators (auto, the default; ROS34PW2;
DOPRI5) at relative tolerances 1e-2 … 1e-5 with the energy tolerance a
tenth of it, and a reference by ROS34PW2 at 1e-6 / 1e-7; and the case at
its own settings (the defaults' marker). Error: the largest relative
difference from the reference among the outputs users read (mean cage
speed, mean and largest inner loads, mean friction power, the inner
ring's velocity RMS; with a housing sensor its RMS; with a spall the
envelope's BPFO line). Cost: wall time (one thread), steps and
right-hand sides (stages and Jacobian columns). With --exudyn, the 6304
in Exudyn 1.13.6 (scripts/exudyn_6304.py: its DOPRI5 at rtol 1e-2 … 1e-5
against its own run at 1e-7; its error is the cage speed's only, the one
output that script reads).

    cargo build --release
    RAYON_NUM_THREADS=1 python3 scripts/work-precision.py [--cases 6304,default] [--exudyn] \\
        [--figure docs/figures/work-precision.png]
    python3 scripts/work-precision.py --defaults-only --reference-integrator auto \\
        --cases "6205 outer pit,6205 inner pit,6205 ball pit"  # also 6203, 6206
    # docs/figures/work-precision-pit-ramp.png: the two runs' --raw files merged
    # ({"results": {...both...}}), then --from-raw FILE --figure F
    RAYON_NUM_THREADS=1 python3 scripts/work-precision.py --cases "6205 outer pit" \\
        --reference-integrator auto --raw A.json   # about 10 minutes
    RAYON_NUM_THREADS=1 python3 scripts/work-precision.py --cases "7218B ramp" --raw B.json  # about 1 hour

Prints a Markdown table per case. About 50 minutes on one thread for the
6304 and the default case over 1 s (the default case's reference at
rtol 1e-6 alone 16); Exudyn adds about 10 minutes.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
TOLERANCES = [1e-2, 1e-3, 1e-4, 1e-5]
REFERENCE = 1e-6
INTEGRATORS = ["auto", "ros34pw2", "dopri5"]

# case name -> (how to get its text, extra run arguments)
CASES = {
    "6304": (["new", "--preset", "6304"], ["--duration", "1 s"]),
    "default": (["new"], ["--duration", "1 s"]),
    "spalled 6205": (["new", "--preset", "6205"], [
        "--duration", "0.1 s",
        "--set", 'surface.outer.spall=[{ position = "270 deg", length = "0.533 mm", depth = "0.28 mm" }]',
        "--set", "operating.force_z=1 kN"]),
    # Zhang et al. 2025's speed ramp (examples/seed002) as the 7218B preset
    # writes it: the idle and most of the ramp, 1.2 s, FASTSIM 48 x 20.
    "7218B ramp": (["new", "--preset", "7218B"], []),
}
# The fault matrix's pits (D_w/15 long, D_w/28 deep, at the load zone's
# centre) on the mounted 6205 under 1 kN at 1772 rpm, 0.2 s: whether the
# defaults converge where users look (docs/validation.md, "Fault signatures
# at defaults").
# The same pits (D_w/15 × D_w/28) on the 6203 under 1 kN at 1772 rpm and on
# the 6206 at its defaults (1 kN, 3000 rpm).
PITS = {
    "6205": ('position = "90 deg", length = "0.5293 mm", depth = "0.2836 mm"',
             ["--speed", "1772 rpm", "--set", "operating.force_z=1 kN"]),
    "6203": ('position = "90 deg", length = "0.4497 mm", depth = "0.2409 mm"',
             ["--speed", "1772 rpm", "--set", "operating.force_z=1 kN"]),
    "6206": ('position = "90 deg", length = "0.635 mm", depth = "0.3402 mm"', []),
}
for bearing, (pit, conditions) in PITS.items():
    for fault, key in [("outer", "surface.outer.spall"), ("inner", "surface.inner.spall"),
                       ("ball", "surface.balls.spall")]:
        ball = "ball = 0, " if fault == "ball" else ""
        CASES[f"{bearing} {fault} pit"] = (["new", "--preset", bearing], [
            "--duration", "0.2 s", *conditions,
            "--set", f"{key}=[{{ {ball}{pit} }}]"])


def outputs(summary, spalled, all_outputs=False):
    """The outputs users read, by name; with all_outputs also the largest
    outer load, the housing sensor's peak and every envelope line. A
    smooth bearing's envelope lines are the floor of its noise, not a
    signature: they count only with a spall."""
    out = {
        "cage speed": summary["mean_cage_speed_rpm"],
        "mean inner load": summary["mean_load_inner_n"],
        "largest inner load": summary["max_load_inner_n"],
        "friction power": summary["mean_power_loss_w"],
        "velocity RMS": summary["inner_ring_velocity_rms_z_mm_s"],
    }
    if summary.get("sensor"):
        out["sensor RMS"] = summary["sensor"]["rms_m_s2"]
    if all_outputs:
        out["largest outer load"] = summary["max_load_outer_n"]
        if summary.get("sensor"):
            out["sensor peak"] = summary["sensor"]["peak_m_s2"]
    lines = (summary.get("envelope_lines") or {}).get("lines") or [] if spalled else []
    for line in lines:
        if all_outputs or line["name"] == "BPFO":
            out[f"{line['name']} line"] = line["amplitude_m_s2"]
    return out


def run(exe, text, extra, integrator, rtol, all_outputs=False):
    """One run; integrator None: the case's own settings (its defaults)."""
    with tempfile.TemporaryDirectory() as out:
        sets = [] if integrator is None else [
            "--set", f"solver.integrator={integrator}",
            "--set", f"solver.relative_tolerance={rtol:g}",
            "--set", f"solver.energy_tolerance={rtol / 10:g}"]
        start = time.perf_counter()
        done = subprocess.run([exe, "run", "-", "-o", out, *extra, *sets], input=text,
                              capture_output=True, text=True)
        wall = time.perf_counter() - start
        if done.returncode != 0:
            print(f"run failed ({' '.join(extra + sets)}): {done.stderr.strip()[-400:]}",
                  file=sys.stderr)
            return None
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
    return {
        "wall": wall,
        "steps": summary["steps"],
        "rhs": summary["rhs_evaluations"] + summary["jacobian_rhs_evaluations"],
        "outputs": outputs(summary, any("spall" in a for a in extra), all_outputs),
    }


def error(result, reference):
    """Largest relative difference over the outputs, and which."""
    worst = (0.0, "")
    for name, value in reference["outputs"].items():
        got = result["outputs"].get(name)
        if got is None or value == 0:
            continue
        e = abs(got / value - 1)
        worst = max(worst, (e, name))
    return worst


def exudyn_points():
    sys.path.insert(0, os.path.join(ROOT, "scripts"))
    import exudyn_6304
    reference = exudyn_6304.exudyn_run(0.2, 1e-7)[1]
    points = []
    for rtol in TOLERANCES:
        wall, rpm = exudyn_6304.exudyn_run(0.2, rtol)
        points.append((rtol, wall, abs(rpm / reference - 1)))
    return reference, points


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rolldyn", default=os.path.join(ROOT, "target", "release", "rolldyn"))
    parser.add_argument("--cases", default="6304,default")
    parser.add_argument("--exudyn", action="store_true")
    parser.add_argument("--figure")
    parser.add_argument("--reference-integrator", default="ros34pw2",
                        help="the reference's integrator (ROS34PW2 at 1e-6 collapses its step at "
                             "a pit's edge in the load zone: auto there)")
    parser.add_argument("--defaults-only", action="store_true",
                        help="only the case's defaults against the reference, with every output "
                             "(largest outer load, the sensor, every envelope line)")
    parser.add_argument("--cost", choices=["wall", "rhs"], default="rhs",
                        help="the figure's cost axis: wall time or right-hand sides (default; "
                             "independent of the machine's load)")
    parser.add_argument("--raw", help="also write every run's cost and outputs to this JSON file")
    parser.add_argument("--from-raw", help="no runs: the tables and figure from a --raw file")
    args = parser.parse_args()
    if args.from_raw:
        with open(args.from_raw) as f:
            raw = json.load(f)
        results = {}
        for name, v in raw["results"].items():
            rows = [(r["integrator"], r["rtol"], r, *error(r, v["reference"])) for r in v["runs"]]
            results[name] = (v["reference"], rows, v["defaults"])
        exudyn = raw.get("exudyn")
    else:
        results = {}
        for name in args.cases.split(","):
            new, extra = CASES[name]
            text = subprocess.run([args.rolldyn, *new], check=True, capture_output=True, text=True).stdout
            reference = run(args.rolldyn, text, extra, args.reference_integrator, REFERENCE,
                            args.defaults_only)
            if reference is None:
                # The reason is on stderr (run's message); no error to measure.
                print(f"\n{name}: the reference run failed; left out", file=sys.stderr)
                continue
            defaults = run(args.rolldyn, text, extra, None, None, args.defaults_only)
            rows = []
            for integrator in [] if args.defaults_only else INTEGRATORS:
                for rtol in TOLERANCES:
                    r = run(args.rolldyn, text, extra, integrator, rtol)
                    if r is not None:
                        rows.append((integrator, rtol, r, *error(r, reference)))
            results[name] = (reference, rows, defaults)
        exudyn = exudyn_points() if args.exudyn else None
    for name, (reference, rows, defaults) in results.items():
        by = "" if args.from_raw else f" {args.reference_integrator}"
        print(f"\n{name}: reference{by} at rtol {REFERENCE:g} "
              f"({reference['wall']:.1f} s, "
              f"{reference['steps']} steps)")
        names = list(reference["outputs"])
        print("| integrator | rtol | wall [s] | steps | RHS | " + " | ".join(names) + " |")
        print("|---" * (5 + len(names)) + "|")
        for integrator, rtol, r in [("defaults", None, defaults)] + [row[:3] for row in rows]:
            errors = [abs(r["outputs"][n] / reference["outputs"][n] - 1) if reference["outputs"][n]
                      else 0.0 for n in names]
            tol = "the case's" if rtol is None else f"{rtol:g}"
            print(f"| {integrator} | {tol} | {r['wall']:.2f} | {r['steps']} | {r['rhs']} | "
                  + " | ".join(f"{100 * x:.3f} %" for x in errors) + " |")
        sys.stdout.flush()
    if exudyn:
        print("\n6304 in Exudyn (DOPRI5), cage speed against its run at 1e-7 "
              f"({exudyn[0]:.2f} rpm)")
        print("| rtol | wall [s] | cage speed error |")
        print("|---|---|---|")
        for rtol, wall, e in exudyn[1]:
            print(f"| {rtol:g} | {wall:.2f} | {100 * e:.4f} % |")
    if args.raw:
        with open(args.raw, "w") as f:
            json.dump({"results": {name: {"reference": ref, "defaults": defaults, "runs": [
                {"integrator": i, "rtol": t, **r} for i, t, r, _, _ in rows]}
                for name, (ref, rows, defaults) in results.items()}, "exudyn": exudyn}, f, indent=1)
    if args.figure:
        plot(results, exudyn, args.figure, args.cost)


def plot(results, exudyn, path, cost):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    fig, axes = plt.subplots(1, len(results), figsize=(5.2 * len(results), 4.2), squeeze=False)
    for ax, (name, (reference, rows, defaults)) in zip(axes[0], results.items()):
        for integrator, marker in zip(INTEGRATORS, "os^"):
            pts = [(max(e, 1e-7), r[cost], rtol) for i, rtol, r, e, _ in rows if i == integrator]
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], marker=marker, label=f"rolldyn {integrator}")
            for e, w, rtol in pts:
                if integrator == "auto":
                    ax.annotate(f"{rtol:g}", (e, w), fontsize=7, xytext=(3, 3), textcoords="offset points")
        ax.plot(max(error(defaults, reference)[0], 1e-7), defaults[cost], "k*", markersize=14,
                label="the case's defaults")
        if name == "6304" and exudyn is not None and cost == "wall":
            ax.loglog([max(p[2], 1e-7) for p in exudyn[1]], [p[1] for p in exudyn[1]], "x--",
                      label="Exudyn DOPRI5 (cage speed only)")
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_xlabel("largest relative error of the outputs")
        ax.set_ylabel("wall time [s], one thread" if cost == "wall" else "right-hand sides (stages and Jacobian columns)")
        ax.set_title(name)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    main()
