//! Prescribed ring displacements (issue 16): a fixed tilt or misalignment
//! instead of a free ring.
//!
//! * The reaction reported is the load that holds the displacement: solved
//!   again with the ring free and that reaction applied, the ring takes the
//!   prescribed displacement and the same load distribution (1e-6 of the
//!   displacement scale, 1e-6 of the loads).
//! * Where the free ring does not tilt (pure axial load), fixing the tilt
//!   at zero changes nothing and needs no reaction.
//! * The stiffness stays the full matrix of the free bearing.
//!
//! 7008C at rest and at 10 000 rpm, 7218B at rest; F_x with F_z.

use super::common::{bearing_7008c, bearing_7218b, rel};
use rolldyn::BearingGeometry;
use rolldyn::contact::HertzModel;
use rolldyn::material::Material;
use rolldyn::operating::Loads;
use rolldyn::quasistatic::{Conditions, QuasiStaticSolver, RacewayControl, SolverOptions};

const RPM: f64 = std::f64::consts::TAU / 60.0;

fn conditions(fx: f64, fz: f64, moment: [f64; 2], rpm: f64) -> Conditions {
    Conditions {
        loads: Loads {
            force: [fx, 0.0, fz],
            moment,
        },
        inner_speed: rpm * RPM,
        control: RacewayControl::Outer,
    }
}

fn held(tilt_y: f64, tilt_z: f64) -> SolverOptions {
    SolverOptions {
        prescribed_displacement: [None, None, None, Some(tilt_y), Some(tilt_z)],
        ..Default::default()
    }
}

fn check(g: &BearingGeometry, fx: f64, fz: f64, rpm: f64, tilt_y: f64) {
    let s = QuasiStaticSolver::new(
        g,
        &Material::STEEL_52100,
        &Material::STEEL_52100,
        HertzModel::Exact,
    )
    .unwrap();
    let fixed = s
        .solve(&conditions(fx, fz, [0.0; 2], rpm), &held(tilt_y, 0.0))
        .unwrap();
    assert_eq!(fixed.displacement[3], tilt_y);
    assert_eq!(fixed.displacement[4], 0.0);
    let r = fixed.reaction;
    assert_eq!(
        [r[0], r[1], r[2]],
        [0.0; 3],
        "free displacements need no reaction"
    );
    let free = s
        .solve(
            &conditions(fx, fz, [r[3], r[4]], rpm),
            &SolverOptions::default(),
        )
        .unwrap();
    let scale = fixed.displacement[..3]
        .iter()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    for k in 0..3 {
        assert!(
            (free.displacement[k] - fixed.displacement[k]).abs() < 1e-6 * scale,
            "u[{k}]: free {} vs fixed {}",
            free.displacement[k],
            fixed.displacement[k]
        );
    }
    let lever = 0.5 * g.pitch_diameter;
    for k in 3..5 {
        assert!(
            (free.displacement[k] - fixed.displacement[k]).abs() < 1e-6 * scale / lever,
            "θ[{k}]: free {} vs fixed {}",
            free.displacement[k],
            fixed.displacement[k]
        );
    }
    let top = fixed.balls.iter().map(|b| b.inner.load).fold(0.0, f64::max);
    for (a, b) in fixed.balls.iter().zip(&free.balls) {
        assert!((a.inner.load - b.inner.load).abs() < 1e-6 * top);
    }
    for i in 0..5 {
        for j in 0..5 {
            let k = fixed.stiffness[i][j];
            assert!(
                (k - free.stiffness[i][j]).abs() <= 1e-6 * fixed.stiffness[0][0].abs(),
                "K[{i}][{j}]: {k} vs {}",
                free.stiffness[i][j]
            );
        }
    }
    eprintln!(
        "fixed tilt {tilt_y:e} rad, F_x {fx} N, F_z {fz} N, {rpm} rpm: holding moment M_y {:.4} N·m, M_z {:.2e} N·m",
        r[3], r[4]
    );
}

#[test]
fn reaction_holds_the_prescribed_tilt() {
    check(&bearing_7008c(), 200.0, 300.0, 0.0, 0.0);
    check(&bearing_7008c(), 200.0, 300.0, 10_000.0, 0.0);
    check(&bearing_7008c(), 500.0, 100.0, 10_000.0, 2e-4);
    check(&bearing_7218b(), 10_000.0, 10_000.0, 0.0, 0.0);
}

#[test]
fn zero_tilt_under_axial_load_needs_no_moment() {
    let g = bearing_7008c();
    let s = QuasiStaticSolver::new(
        &g,
        &Material::STEEL_52100,
        &Material::STEEL_52100,
        HertzModel::Exact,
    )
    .unwrap();
    let c = conditions(300.0, 0.0, [0.0; 2], 10_000.0);
    let free = s.solve(&c, &SolverOptions::default()).unwrap();
    let fixed = s.solve(&c, &held(0.0, 0.0)).unwrap();
    assert!(
        fixed.reaction.iter().all(|m| m.abs() < 1e-6),
        "{:?}",
        fixed.reaction
    );
    assert!(rel(free.displacement[0], fixed.displacement[0]) < 1e-9);
}
