//! An outer ring sliding axially in its bore (a floating bearing's;
//! `dynamics::SlidingRing`, docs/systems.md, "Dynamics").
//!
//! On the 7008C default configuration (EHL traction on the 12 × 6 grid,
//! drag, 10 000 rpm, Jones–Harris start under F_x = 200 N):
//! * without friction nothing holds the bearing axially: the axial
//!   momentum of inner ring, balls and outer ring grows by the applied
//!   thrust, Σ m ẋ = F_x t (Newton's second law for the system), to 1e-6
//!   of F_x t (measured 2e-14) over 0.2 ms, in which the outer ring slides
//!   21 µm: the cage has no axial motion in this model, so the test stops
//!   before the balls reach their pockets' walls (87.5 µm a side);
//! * with friction (μ = 0.1, a ring of 0.1 kg) the power balance
//!   P_drive − P_dissipated = dE/dt holds at every state of a ring set
//!   sliding at 5 mm/s, the bore's friction among the dissipation.

use super::b2_power_balance::worst_power_residual;
use super::common::{Method, bearing_7008c, drag_7008c, dynamics_7008c, integrator};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::{BearingModel, SlidingRing};
use rolldyn::integrate::Integrator;
use rolldyn::material::Material;

fn model(friction: f64) -> (BearingModel, Vec<f64>) {
    let (mut params, eq) = dynamics_7008c(drag_7008c());
    params.sliding_outer_ring = Some(SlidingRing {
        mass: 0.1,
        friction,
    });
    let steel = Material::STEEL_52100;
    let model =
        BearingModel::new(&bearing_7008c(), &steel, &steel, HertzModel::Exact, params).unwrap();
    let y0 = model.state_from_equilibrium(&eq);
    (model, y0)
}

/// Axial momentum of the inner ring, the balls and the sliding outer ring.
fn axial_momentum(model: &BearingModel, y: &[f64]) -> f64 {
    let l = model.layout();
    let p = model.parameters();
    let balls: f64 = (0..l.balls).map(|j| y[l.ball(j) + 3]).sum();
    p.inner_ring_mass * y[l.ring() + 5]
        + model.ball_mass() * balls
        + p.sliding_outer_ring.map_or(0.0, |r| r.mass) * y[l.slide() + 1]
}

#[test]
fn a_free_sliding_ring_takes_the_thrust_as_momentum() {
    let (mut model, y0) = model(0.0);
    let thrust = model.parameters().loads.at(0.0).force[0];
    assert_eq!(axial_momentum(&model, &y0), 0.0);
    let mut rk = integrator(Method::Ros34pw2, &model, &y0, 1e-6, 1e-5);
    let t_end = 2e-4;
    while rk.t() < t_end {
        rk.step(&mut model, t_end).unwrap();
    }
    let p = axial_momentum(&model, rk.y());
    assert!(
        (p - thrust * t_end).abs() < 1e-6 * thrust * t_end,
        "momentum {p} N·s against F_x t = {} N·s",
        thrust * t_end
    );
    // The whole bearing moves off along the thrust.
    assert!(rk.y()[model.layout().slide()] > 0.0);
}

#[test]
fn the_power_balance_holds_with_the_bores_friction() {
    let (mut model, mut y0) = model(0.1);
    y0[model.layout().slide() + 1] = 5e-3;
    let worst = worst_power_residual(&mut model, &y0);
    assert!(worst < 1e-5, "worst power residual {worst:e} of the powers");
}
