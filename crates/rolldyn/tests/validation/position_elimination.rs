//! The factorization's elimination of positions (`integrate::linear`,
//! `BlockSplit::rate_of`): a state q whose rate is another state v
//! (f_q = y_v) has the unit row e_v in the Jacobian, so σ x_q − x_v = r_q
//! and the stage equations reduce to the velocities (Hairer & Wanner II,
//! §IV.8: RADAU5's and RODAS's option for y′ᵢ = y_{i+M2}).
//!
//! * In every configuration that changes which states move (free rings
//!   and whirling cage; planar motion; a housing; a sliding outer ring; a
//!   torque drive), each position the model declares has exactly that
//!   row in its finite-difference Jacobian, and no other state of the
//!   same kind (a position whose rate is its velocity) is left out.
//! * On those Jacobians the reduced factorization solves σI − J to
//!   round-off, and agrees with the factorization that keeps every state.

use super::common::{
    bearing_6304, bearing_7008c, drag_7008c, dynamics_6304, dynamics_7008c, steel_shan_2023,
};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::{BearingModel, OuterRing, SlidingRing, Support};
use rolldyn::integrate::jacobian::{JacobianWork, finite_difference};
use rolldyn::integrate::linear::{BlockJacobian, BlockLu};
use rolldyn::integrate::{BlockSplit, OdeSystem};
use rolldyn::material::Material;
use rolldyn::operating::TorqueDrive;

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

fn jacobian(model: &BearingModel, y: &[f64]) -> BlockJacobian {
    let t = 1e-4;
    let mut f = vec![0.0; y.len()];
    model.rhs(t, y, &mut f);
    let mut jac = BlockJacobian::zeros(model.block_layout());
    finite_difference(model, t, y, &f, &mut jac, &mut JacobianWork::new(model));
    jac
}

#[test]
fn declared_positions_have_their_velocitys_unit_row() {
    for (name, model, y) in configurations() {
        let jac = jacobian(&model, &y);
        let n = y.len();
        let mut declared = 0;
        for q in 0..n {
            let unit_row_of =
                |v: usize| (0..n).all(|c| jac.get(q, c) == f64::from(u8::from(c == v)));
            match model.rate_of(q) {
                Some(v) => {
                    declared += 1;
                    assert!(
                        unit_row_of(v),
                        "{name}: state {q} declared the position of {v}"
                    );
                }
                // Every moving position is declared: a row that is some
                // state's unit row (a frozen state's row is zero).
                None => assert!(
                    !(0..n).any(|v| v != q && unit_row_of(v)),
                    "{name}: state {q} is a position not declared"
                ),
            }
        }
        assert!(declared > 0, "{name}");
    }
}

#[test]
fn the_reduced_factorization_solves_the_full_system() {
    for (name, model, y) in configurations() {
        let jac = jacobian(&model, &y);
        let layout = jac.layout();
        let n = layout.dimension();
        let mut reduced = BlockLu::with_structure(layout, |s| model.inert(s), |s| model.rate_of(s));
        let mut kept = BlockLu::with_inert(layout, |s| model.inert(s));
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
            // Residual relative to the row's scale |σ x_i| + Σ|J_ic x_c| + |r_i|.
            for i in 0..n {
                let scale = (sigma * x[i]).abs()
                    + (0..n).map(|c| (jac.get(i, c) * x[c]).abs()).sum::<f64>()
                    + rhs[i].abs();
                let residual = (sigma * x[i] - jx[i] - rhs[i]).abs();
                assert!(
                    residual <= 1e-12 * scale,
                    "{name}, σ {sigma}, state {i}: residual {residual:e} of {scale:e}"
                );
                let norm = x_kept.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                assert!(
                    (x[i] - x_kept[i]).abs() <= 1e-9 * norm,
                    "{name}, σ {sigma}, state {i}: {} against {}",
                    x[i],
                    x_kept[i]
                );
            }
        }
    }
}
