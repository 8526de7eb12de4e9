//! Bearings on an elastic shaft (`quasistatic::elastic_shaft`,
//! docs/systems.md, "Elastic shaft"): two 6304 (Shan et al. 2023) 120 mm
//! apart on a solid steel shaft of 20 mm under a 4 kN radial force midway.
//! Whatever the bearings' own compliance, the shaft between them is an
//! Euler–Bernoulli beam on two supports loaded by F midway and by the
//! moments M the tilted bearings return at its ends (Timoshenko & Gere,
//! *Mechanics of Materials*, tables of beam deflections): relative to the
//! chord through the bearing nodes the middle sags by
//! F L³/(48 E I) − M L²/(8 E I) and each end turns by
//! F L²/(16 E I) − M L/(2 E I), the inner rings' misalignment against the
//! outer rings (M from the bearings' solutions; without it the simply
//! supported beam's 89.0 µm and 2.23 mrad). The bearings carry the load
//! (the shaft's internal forces cancel), and a very stiff shaft is the
//! rigid one.

use super::common::{bearing_6304, rel};
use rolldyn::contact::HertzModel;
use rolldyn::material::Material;
use rolldyn::operating::Loads;
use rolldyn::quasistatic::elastic_shaft::{ElasticShaft, ShaftSection};
use rolldyn::quasistatic::system::{MountedBearing, Orientation, ShaftSystem, SystemConditions};
use rolldyn::quasistatic::{QuasiStaticSolver, RacewayControl, SolverOptions};

const SPAN: f64 = 0.12;
const FORCE: f64 = 4000.0;

fn shaft(modulus: f64) -> (ElasticShaft, SystemConditions) {
    let steel = Material::STEEL_52100;
    let solver =
        QuasiStaticSolver::new(&bearing_6304(), &steel, &steel, HertzModel::Exact).unwrap();
    let mount = |position| MountedBearing {
        solver: solver.clone(),
        position,
        orientation: Orientation::Forward,
        axial_offset: 0.0,
        floating: false,
    };
    let system = ShaftSystem {
        bearings: vec![mount(-SPAN / 2.0), mount(SPAN / 2.0)],
    };
    let section = ShaftSection {
        diameter: 0.02,
        bore: 0.0,
        elastic_modulus: modulus,
    };
    let conditions = SystemConditions {
        loads: Loads {
            force: [0.0, 0.0, -FORCE],
            moment: [0.0; 2],
        },
        inner_speed: 0.0,
        control: RacewayControl::Outer,
    };
    (
        ElasticShaft::new(section, system, Vec::new()).unwrap(),
        conditions,
    )
}

#[test]
fn the_shaft_between_two_bearings_bends_as_a_simply_supported_beam() {
    let modulus = 206e9;
    let (elastic, conditions) = shaft(modulus);
    let options = SolverOptions::default();
    let eq = elastic.solve(&conditions, &options).unwrap();
    assert_eq!(eq.nodes, vec![-SPAN / 2.0, 0.0, SPAN / 2.0]);
    let ei = modulus * elastic.section.second_moment();
    let [a, m, b] = [
        &eq.displacements[0],
        &eq.displacements[1],
        &eq.displacements[2],
    ];
    let sag = m[2] - 0.5 * (a[2] + b[2]);
    let chord = (b[2] - a[2]) / SPAN;
    // The moment the left bearing returns to the shaft, against its turn.
    let moment = eq.system.shaft_loads[0][3].abs();
    let beam_sag = -(FORCE * SPAN.powi(3) / 48.0 - moment * SPAN.powi(2) / 8.0) / ei;
    let beam_turn = (FORCE * SPAN.powi(2) / 16.0 - moment * SPAN / 2.0) / ei;
    // θ_y = −dz/dx: the left end turns by +F L²/(16 E I) against the chord.
    let (left, right) = (a[3] + chord, b[3] + chord);
    eprintln!(
        "two 6304 on a 20 mm shaft, 4 kN midway: sag {:.3} µm (beam {:.3} µm), end rotations {:.4e} / {:.4e} rad (beam ±{beam_turn:.4e}), bearing moments {moment:.4} N·m; bearings move {:.3} µm",
        sag * 1e6,
        beam_sag * 1e6,
        left,
        right,
        a[2] * 1e6
    );
    assert!(rel(sag, beam_sag) < 1e-6, "{sag} vs {beam_sag}");
    assert!(rel(left, beam_turn) < 1e-6, "{left} vs {beam_turn}");
    assert!(rel(right, -beam_turn) < 1e-6, "{right} vs {}", -beam_turn);
    // The bearings carry the load: Σ P_iᵀ M_i R_i = F.
    let carried: f64 = eq.system.shaft_loads.iter().map(|s| s[2]).sum();
    assert!(rel(carried, -FORCE) < 1e-8, "{carried}");
    // Each inner ring turns with its node: the bending misalignment.
    let ring = &eq.system.bearings[0].as_ref().unwrap().displacement;
    assert!(rel(ring[3], a[3]) < 1e-9, "{:?} vs {:?}", ring, a);
}

#[test]
fn a_very_stiff_shaft_is_the_rigid_one() {
    let (elastic, conditions) = shaft(206e9 * 1e6);
    let options = SolverOptions::default();
    let eq = elastic.solve(&conditions, &options).unwrap();
    let rigid = elastic.system.solve_general(&conditions, &options).unwrap();
    for k in [2, 3] {
        let (e, r) = (eq.system.displacement[k], rigid.displacement[k]);
        assert!(
            (e - r).abs() <= 1e-5 * rigid.displacement[2].abs().max(1e-12),
            "{k}: {e} vs {r}"
        );
    }
    let (ke, kr) = (eq.system.stiffness[2][2], rigid.stiffness[2][2]);
    assert!(rel(ke, kr) < 1e-4, "{ke} vs {kr}");
}
