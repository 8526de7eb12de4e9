#!/usr/bin/env python3
"""The 6304 preset (Shan et al. 2023) in Exudyn, and a side-by-side timing
against `rolldyn run` on the same case.

    pip install exudyn numpy          # Exudyn 1.13.6 was measured
    cargo build --release
    python3 scripts/exudyn_6304.py                # both, 3 pairs, medians
    python3 scripts/exudyn_6304.py --pairs 5 --duration 0.2
    python3 scripts/exudyn_6304.py --set solver.energy_tolerance=0
                                        # rolldyn with the error control
                                        # Exudyn has: the states' only

The model is the preset's (rolldyn new --preset 6304), built from Exudyn's
own items so that Exudyn's C++ core does all the work (no Python in the
time loop):

* planar: 7 balls, the inner ring and the cage as 2-D rigid bodies
  (NodeRigidBody2D); the outer ring is the ground;
* ball–raceway contacts: ObjectContactSphereSphere, the inner raceway a
  sphere of the raceway's radius, the outer a hollow sphere; Hertz force
  K δ^1.5 with the preset's K_c (hertz_circular, Shan et al. 2023 eq 12:
  9.103e9 and 1.1935e10 N/m^1.5, as `rolldyn check` prints them);
  dissipation by Exudyn's Hunt–Crossley model (impactModel 1), its
  restitution chosen so that its hysteresis factor 3(1 − e)/2 equals the
  Lankarani–Nikravesh factor 3(1 − e²)/4 of the preset's e = 0.9;
  friction μ = 0.1, linear up to 10 mm/s (the preset's modified Coulomb);
* ball–pocket contacts: the same item with the pocket a hollow sphere of
  radius r_b + C_p/2 on the cage, linear stiffness 1e7 N/m, damping
  20 N·s/m, friction 0.1 linear up to 1 mm/s (the preset's pocket law);
* the inner ring turns at 8000 rpm (held by a huge polar inertia: the
  explicit solvers take no velocity constraints) and is free to move
  radially under F = 100 N and its weight;
  the cage turns freely about a fixed centre (the preset has no cage
  whirl); gravity on balls and ring;
* start: pure rolling (balls on the pitch circle, orbit and spin speeds of
  pure rolling, cage at the cage speed), as the preset's `start`;
* integration: Exudyn's DOPRI5 with automatic step size at the given
  relative tolerance (default 1e-3, the preset's), no solution file.

It prints the wall time of each run and the mean cage speed over the
second half, and the ratio of the median wall times. Differences in the
cage speed of a few 0.1 % come from the two codes' contact details
(Hunt–Crossley against Lankarani–Nikravesh, Exudyn's friction
regularisation, its start), not from the integration.
"""

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

# The preset's data (rolldyn new --preset 6304; rolldyn check for K_c).
BALLS = 7
BALL_RADIUS = 4.76e-3
INNER_RACEWAY_RADIUS = 13.24e-3
OUTER_RACEWAY_RADIUS = 22.77e-3
PITCH_RADIUS = 0.5 * (INNER_RACEWAY_RADIUS + OUTER_RACEWAY_RADIUS)
DENSITY = 7800.0
INNER_STIFFNESS = 9.103279e9  # N/m^1.5
OUTER_STIFFNESS = 1.193479e10
RESTITUTION_LN = 0.9
FRICTION = 0.1
FRICTION_SPEED = 10e-3  # m/s
POCKET_CLEARANCE = 0.2e-3  # diametral
POCKET_STIFFNESS = 1e7
POCKET_DAMPING = 20.0
POCKET_FRICTION = 0.1
POCKET_FRICTION_SPEED = 1e-3
CAGE_MASS = 5e-3
CAGE_INERTIA = 8.2e-7
RING_MASS = 0.5
SPEED_RPM = 8000.0
RADIAL_LOAD = 100.0
GRAVITY = 9.81


def exudyn_run(duration, rtol):
    """Builds and runs the Exudyn model; returns (wall s, mean cage rpm)."""
    import exudyn as exu
    import numpy as np
    from exudyn.itemInterface import (
        MarkerBodyRigid,
        MarkerNodeCoordinate,
        MarkerNodeRigid,
        NodeGenericData,
        NodePointGround,
        NodeRigidBody2D,
        LoadForceVector,
        ObjectConnectorCoordinate,
        ObjectContactSphereSphere,
        ObjectGround,
        ObjectRigidBody2D,
        SensorNode,
    )

    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    ground = mbs.AddObject(ObjectGround())
    ground_marker = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground, localPosition=[0, 0, 0]))
    ground_node = mbs.AddNode(NodePointGround())
    ground_coordinate = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=ground_node, coordinate=0))

    omega_i = SPEED_RPM * 2 * math.pi / 60
    omega_c = omega_i * INNER_RACEWAY_RADIUS / (2 * PITCH_RADIUS)
    ball_mass = DENSITY * 4 / 3 * math.pi * BALL_RADIUS**3
    ball_inertia = 0.4 * ball_mass * BALL_RADIUS**2

    # Inner ring: moves in the plane; turns at the shaft speed, held there
    # by a polar inertia so large (1e3 kg m²) that the friction torques
    # (< 0.1 N m) change its speed by less than 1e-5 rad/s over the run
    # (Exudyn's explicit solvers take no velocity constraints).
    ring = mbs.AddNode(NodeRigidBody2D(referenceCoordinates=[0, 0, 0], initialVelocities=[0, 0, omega_i]))
    mbs.AddObject(ObjectRigidBody2D(mass=RING_MASS, inertia=1e3, nodeNumber=ring))
    ring_marker = mbs.AddMarker(MarkerNodeRigid(nodeNumber=ring))
    mbs.AddLoad(LoadForceVector(markerNumber=ring_marker, loadVector=[0, -RADIAL_LOAD - RING_MASS * GRAVITY, 0]))

    # Cage: turns about its fixed centre.
    cage = mbs.AddNode(NodeRigidBody2D(referenceCoordinates=[0, 0, 0], initialVelocities=[0, 0, omega_c]))
    cage_body = mbs.AddObject(ObjectRigidBody2D(mass=CAGE_MASS, inertia=CAGE_INERTIA, nodeNumber=cage))
    for k in (0, 1):
        coordinate = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=cage, coordinate=k))
        mbs.AddObject(ObjectConnectorCoordinate(markerNumbers=[ground_coordinate, coordinate]))

    hunt_crossley_restitution = 1 - (1 - RESTITUTION_LN**2) / 2
    for j in range(BALLS):
        angle = 2 * math.pi * j / BALLS
        c, s = math.cos(angle), math.sin(angle)
        spin = -omega_c * PITCH_RADIUS / BALL_RADIUS
        v = omega_c * PITCH_RADIUS
        ball = mbs.AddNode(NodeRigidBody2D(referenceCoordinates=[PITCH_RADIUS * c, PITCH_RADIUS * s, 0], initialVelocities=[-v * s, v * c, spin]))
        mbs.AddObject(ObjectRigidBody2D(mass=ball_mass, inertia=ball_inertia, nodeNumber=ball))
        ball_marker = mbs.AddMarker(MarkerNodeRigid(nodeNumber=ball))
        mbs.AddLoad(LoadForceVector(markerNumber=ball_marker, loadVector=[0, -ball_mass * GRAVITY, 0]))
        pocket = mbs.AddMarker(MarkerBodyRigid(bodyNumber=cage_body, localPosition=[PITCH_RADIUS * c, PITCH_RADIUS * s, 0]))
        for other, radius, hollow, stiffness, exponent, damping, model, friction, zone in (
            (ring_marker, INNER_RACEWAY_RADIUS, False, INNER_STIFFNESS, 1.5, 0.0, 1, FRICTION, FRICTION_SPEED),
            (ground_marker, OUTER_RACEWAY_RADIUS, True, OUTER_STIFFNESS, 1.5, 0.0, 1, FRICTION, FRICTION_SPEED),
            (pocket, BALL_RADIUS + POCKET_CLEARANCE / 2, True, POCKET_STIFFNESS, 1.0, POCKET_DAMPING, 0, POCKET_FRICTION, POCKET_FRICTION_SPEED),
        ):
            data = mbs.AddNode(NodeGenericData(initialCoordinates=[0.1, 0, 0, 0], numberOfDataCoordinates=4))
            mbs.AddObject(
                ObjectContactSphereSphere(
                    markerNumbers=[ball_marker, other],
                    nodeNumber=data,
                    spheresRadii=[BALL_RADIUS, radius],
                    isHollowSphere1=hollow,
                    contactStiffness=stiffness,
                    contactStiffnessExponent=exponent,
                    contactDamping=damping,
                    impactModel=model,
                    restitutionCoefficient=hunt_crossley_restitution,
                    dynamicFriction=friction,
                    frictionProportionalZone=zone,
                )
            )

    sensor = mbs.AddSensor(SensorNode(nodeNumber=cage, storeInternal=True, outputVariableType=exu.OutputVariableType.AngularVelocity))
    mbs.Assemble()
    settings = exu.SimulationSettings()
    settings.timeIntegration.endTime = duration
    settings.timeIntegration.numberOfSteps = int(duration / 1e-6)
    settings.timeIntegration.verboseMode = int(os.environ.get("EXUDYN_VERBOSE", "0"))
    settings.timeIntegration.automaticStepSize = True
    settings.timeIntegration.minimumStepSize = 1e-12
    settings.timeIntegration.relativeTolerance = rtol
    settings.timeIntegration.absoluteTolerance = rtol * 1e-6
    # The cage centre's ground constraints are eliminated (explicit solver).
    settings.timeIntegration.explicit.eliminateConstraints = True
    settings.timeIntegration.explicit.computeMassMatrixInversePerBody = True
    settings.solution.file.write = False
    settings.solution.sensors.writePeriod = duration / 2000
    settings.show.statistics = False
    settings.show.computationTime = False
    start = time.perf_counter()
    exu.SolveDynamic(mbs, settings, solverType=exu.DynamicSolverType.DOPRI5)
    wall = time.perf_counter() - start
    values = np.array(mbs.GetSensorStoredData(sensor))
    half = values[values[:, 0] >= duration / 2]
    cage_rpm = float(np.mean(half[:, 3])) * 60 / (2 * math.pi)
    return wall, cage_rpm


def rolldyn_run(exe, duration, out, overrides):
    """`rolldyn new --preset 6304 | rolldyn run - [--set K=V ...]`; returns
    (wall s, cage rpm, steps, energy balance)."""
    case = subprocess.run([exe, "new", "--preset", "6304"], check=True, capture_output=True, text=True).stdout
    sets = [arg for kv in overrides for arg in ("--set", kv)]
    start = time.perf_counter()
    subprocess.run([exe, "run", "-", "--duration", f"{duration} s", "-o", out, *sets], input=case, check=True, capture_output=True, text=True)
    wall = time.perf_counter() - start
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    return wall, summary["mean_cage_speed_rpm"], summary["steps"], summary["energy_balance_relative_error"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--pairs", type=int, default=3, help="alternating runs of each (default 3)")
    parser.add_argument("--duration", type=float, default=0.2, help="simulated time [s] (default 0.2)")
    parser.add_argument("--rtol", type=float, default=1e-3, help="Exudyn's relative tolerance (default 1e-3)")
    parser.add_argument("--rolldyn", default=os.path.join(os.path.dirname(__file__), "..", "target", "release", "rolldyn"))
    parser.add_argument("--exudyn-only", action="store_true")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", help="override for rolldyn's case (repeatable), e.g. solver.energy_tolerance=0")
    args = parser.parse_args()
    import exudyn

    overrides = " ".join(f"--set {kv}" for kv in args.set) or "its defaults"
    print(f"Exudyn {exudyn.__version__}, {args.duration} s simulated, 6304 preset, whole runs (rolldyn as a process, {overrides})")
    rolldyn_walls, exudyn_walls = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for k in range(args.pairs):
            if not args.exudyn_only:
                wall, rpm, steps, balance = rolldyn_run(args.rolldyn, args.duration, os.path.join(tmp, f"r{k}"), args.set)
                rolldyn_walls.append(wall)
                print(f"  rolldyn: {wall:7.3f} s  mean cage speed (its window)  {rpm:8.1f} rpm  ({steps} steps, energy balance {balance:+.1e})")
            wall, rpm = exudyn_run(args.duration, args.rtol)
            exudyn_walls.append(wall)
            print(f"  Exudyn:  {wall:7.3f} s  mean cage speed (second half) {rpm:8.1f} rpm")
    if rolldyn_walls:
        r, e = statistics.median(rolldyn_walls), statistics.median(exudyn_walls)
        print(f"median: rolldyn {r:.3f} s, Exudyn {e:.3f} s: rolldyn {e / r:.1f}x faster")


if __name__ == "__main__":
    sys.exit(main())
