//! The factorization's elimination of positions (`integrate::linear`,
//! `BlockSplit::rate_of`): a state q whose rate is another state v
//! (f_q = y_v) has the unit row e_v in the Jacobian, so σ x_q − x_v = r_q
//! and the stage equations reduce to the velocities (the option M1, M2 of
//! Hairer & Wanner's RADAU5 and RODAS codes, Hairer & Wanner II).
//!
//! * In the configurations that change which states move (the 7008C's
//!   free rings and whirling cage; with a housing, a sliding outer ring
//!   and a torque drive; the planar 6304; the 7008C pair on its shaft),
//!   each position the model declares has exactly that row in its
//!   finite-difference Jacobian, and no undeclared state has a unit row.
//! * On those Jacobians the reduced factorization solves σI − J to
//!   round-off, and agrees with the factorization that keeps every state.

use super::common::{
    bearing_6304, bearing_7008c, drag_7008c, dynamics_6304, dynamics_7008c, steel_shan_2023,
};
use super::shaft_dynamics::{pair_on_its_shaft, preloaded_pair};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::shaft::ShaftDynamics;
use rolldyn::dynamics::{BearingModel, OuterRing, SlidingRing, Support};
use rolldyn::integrate::OdeSystem;
use rolldyn::integrate::jacobian::{JacobianWork, finite_difference};
use rolldyn::integrate::linear::{BlockJacobian, BlockLu};
use rolldyn::material::Material;
use rolldyn::operating::TorqueDrive;
use rolldyn::quasistatic::SolverOptions;

/// The configurations, named, each with a state a little off its start
/// (the cage turned and moved, the ring moved) so that pockets, housing
/// and supports all act.
fn configurations() -> Vec<(&'static str, BearingModel, Vec<f64>)> {
    let steel = Material::STEEL_52100;
    let angular = |change: &dyn Fn(&mut rolldyn::dynamics::DynamicsParameters)| {
        let (mut params, eq) = dynamics_7008c(drag_7008c());
        change(&mut params);
        let model =
            BearingModel::new(&bearing_7008c(), &steel, &steel, HertzModel::Exact, params).unwrap();
        let y = model.state_from_equilibrium(&eq);
        (model, y)
    };
    let mut out = Vec::new();
    let (model, y) = angular(&|_| {});
    out.push(("7008C default", model, y));
    let (model, y) = angular(&|p| {
        p.outer_ring = Some(OuterRing {
            mass: 0.2,
            housing: Support {
                stiffness: [0.0, 5e7, 5e7],
                damping: [0.0, 200.0, 200.0],
            },
        });
        p.sliding_outer_ring = Some(SlidingRing {
            mass: 0.1,
            friction: 0.1,
        });
        p.drive = Some(TorqueDrive::constant(1e-3, 0.0));
    });
    out.push(("7008C housing, sliding ring, torque drive", model, y));
    let steel = steel_shan_2023();
    let model = BearingModel::new(
        &bearing_6304(),
        &steel,
        &steel,
        HertzModel::HertzCircular,
        dynamics_6304(100.0),
    )
    .unwrap();
    let y = model.pure_rolling_state([0.0, 0.0, 2e-6, 0.0, 0.0]);
    out.push(("6304 planar", model, y));
    for (_, model, y) in &mut out {
        let l = model.layout();
        y[l.cage() + 2] += 0.05e-3 / 20e-3;
        y[l.cage()] += 2e-6;
        y[l.ring() + 1] += 1e-6;
    }
    out
}

/// The bearing pair on its shaft (two bearings' balls and borders, the
/// shaft's states), a little off its operating point.
fn shaft() -> (ShaftDynamics, Vec<f64>) {
    let (set, conditions, model) = preloaded_pair();
    let eq = set.solve(&conditions, &SolverOptions::default()).unwrap();
    let system = pair_on_its_shaft(&set, &model);
    let mut y = system.initial_state(&eq).unwrap();
    // The shaft moved by 1 µm along y.
    y[system.shaft() + 1] += 1e-6;
    (system, y)
}

fn jacobian<S: OdeSystem>(system: &S, y: &[f64]) -> BlockJacobian {
    let t = 1e-4;
    let mut f = vec![0.0; y.len()];
    system.rhs(t, y, &mut f);
    let mut jac = BlockJacobian::zeros(system.blocks().unwrap().block_layout());
    finite_difference(system, t, y, &f, &mut jac, &mut JacobianWork::new(system));
    jac
}

/// Every declared position has its velocity's unit row; no other state
/// has a unit row.
fn positions_declared<S: OdeSystem>(name: &str, system: &S, y: &[f64]) {
    let split = system.blocks().unwrap();
    let jac = jacobian(system, y);
    let n = y.len();
    let mut declared = 0;
    for q in 0..n {
        let unit_row_of = |v: usize| (0..n).all(|c| jac.get(q, c) == f64::from(u8::from(c == v)));
        match split.rate_of(q) {
            Some(v) => {
                declared += 1;
                assert!(
                    unit_row_of(v),
                    "{name}: state {q} declared the position of {v}"
                );
            }
            None => assert!(
                !(0..n).any(|v| v != q && unit_row_of(v)),
                "{name}: state {q} is a position not declared"
            ),
        }
    }
    assert!(declared > 0, "{name}");
}

/// The reduced factorization against the one that keeps every position.
fn solves_the_full_system<S: OdeSystem>(name: &str, system: &S, y: &[f64]) {
    let split = system.blocks().unwrap();
    let jac = jacobian(system, y);
    let layout = jac.layout();
    let n = layout.dimension();
    let mut reduced = BlockLu::with_structure(layout, |s| split.inert(s), |s| split.rate_of(s));
    let mut kept = BlockLu::with_inert(layout, |s| split.inert(s));
    assert!(
        reduced.kept_states().0 < kept.kept_states().0,
        "{name}: positions eliminated"
    );
    let rhs: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin()).collect();
    for sigma in [1e3, 1e5, 1e7] {
        reduced.factor(&jac, sigma).unwrap();
        kept.factor(&jac, sigma).unwrap();
        let (mut x, mut x_kept) = (rhs.clone(), rhs.clone());
        reduced.solve(&mut x);
        kept.solve(&mut x_kept);
        let mut jx = vec![0.0; n];
        jac.multiply(&x, &mut jx);
        let norm = x_kept.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for i in 0..n {
            // Residual relative to the row's scale |σ x_i| + Σ|J_ic x_c| + |r_i|.
            let scale = (sigma * x[i]).abs()
                + (0..n).map(|c| (jac.get(i, c) * x[c]).abs()).sum::<f64>()
                + rhs[i].abs();
            let residual = (sigma * x[i] - jx[i] - rhs[i]).abs();
            assert!(
                residual <= 1e-12 * scale,
                "{name}, σ {sigma}, state {i}: residual {residual:e} of {scale:e}"
            );
            assert!(
                (x[i] - x_kept[i]).abs() <= 1e-9 * norm,
                "{name}, σ {sigma}, state {i}: {} against {}",
                x[i],
                x_kept[i]
            );
        }
    }
}

#[test]
fn declared_positions_have_their_velocitys_unit_row() {
    for (name, model, y) in configurations() {
        positions_declared(name, &model, &y);
    }
    let (system, y) = shaft();
    positions_declared("7008C pair on its shaft", &system, &y);
}

#[test]
fn the_reduced_factorization_solves_the_full_system() {
    for (name, model, y) in configurations() {
        solves_the_full_system(name, &model, &y);
    }
    let (system, y) = shaft();
    solves_the_full_system("7008C pair on its shaft", &system, &y);
}
