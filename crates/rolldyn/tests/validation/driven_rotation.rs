//! A torque-driven inner ring (docs/dynamics.md, "Driven rotation"): its
//! speed a state under Euler's equation J ω̇ = T + M_x.
//!
//! Checks, on the 7008C default configuration (EHL traction on the
//! 12 × 6 grid, drag, F_x = 200 N, 10 000 rpm, Jones–Harris start):
//! * a rotor too heavy to slow down is the prescribed speed (every state
//!   after 1 ms within the integration tolerance);
//! * a run-down's speed loss is the prescribed run's friction impulse over
//!   the inertia, (J + 2 E_k/ω²) Δω = −∫ T_prescribed dt (the prescribed
//!   run's drive work over its speed; E_k the balls' and cage's kinetic
//!   energy, which they give back as they slow with the ring, 4.6 % of J
//!   here), to 2 % (measured 0.6 %: the friction changes with the 0.5 %
//!   the speed falls, and the two runs' states drift apart);
//! * the power balance P_drive − P_dissipated = dE/dt holds at every state
//!   of a spin-up with ½ J ω² in E and T ω as the drive power (the
//!   instantaneous check of docs/validation.md, B2).

use super::b2_power_balance::worst_power_residual;
use super::common::{Method, bearing_7008c, drag_7008c, dynamics_7008c, integrator};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::BearingModel;
use rolldyn::integrate::{Integrator, OdeSystem};
use rolldyn::material::Material;
use rolldyn::operating::TorqueDrive;

const SPEED: f64 = 10_000.0 * std::f64::consts::TAU / 60.0;

/// The 7008C model with `drive` (None: prescribed speed) and its
/// Jones–Harris start.
fn model(drive: Option<TorqueDrive>) -> (BearingModel, Vec<f64>) {
    let (mut params, eq) = dynamics_7008c(drag_7008c());
    params.drive = drive;
    let steel = Material::STEEL_52100;
    let model =
        BearingModel::new(&bearing_7008c(), &steel, &steel, HertzModel::Exact, params).unwrap();
    let y0 = model.state_from_equilibrium(&eq);
    (model, y0)
}

/// The state at `t_end` (ROS34PW2, the default implicit method).
fn run(model: &mut BearingModel, y0: &[f64], t_end: f64) -> Vec<f64> {
    let mut rk = integrator(Method::Ros34pw2, model, y0, 1e-6, 1e-6);
    while rk.t() < t_end {
        rk.step(model, t_end).unwrap();
    }
    rk.y().to_vec()
}

#[test]
fn a_heavy_rotor_turns_at_the_prescribed_speed() {
    let (mut prescribed, y0) = model(None);
    let (mut heavy, z0) = model(Some(TorqueDrive::constant(1e6, 0.0)));
    let l = heavy.layout();
    assert_eq!(z0[l.spin() + 1], SPEED);
    let y = run(&mut prescribed, &y0, 1e-3);
    let z = run(&mut heavy, &z0, 1e-3);
    assert!(
        (z[l.spin() + 1] - SPEED).abs() < 1e-6,
        "{}",
        z[l.spin() + 1]
    );
    assert!((z[l.spin()] - SPEED * 1e-3).abs() < 1e-9);
    let c = prescribed.layout().cage();
    let cage = (z[l.cage() + 5] - y[c + 5]).abs() / y[c + 5];
    assert!(cage < 1e-5, "cage speed differs by {cage:e}");
    for j in 0..l.balls {
        let (b, d) = (prescribed.layout().ball(j), l.ball(j));
        let orbit = (z[d + 2] - y[b + 2]).abs();
        assert!(orbit < 1e-6, "ball {j}'s azimuth differs by {orbit:e} rad");
    }
}

#[test]
fn a_run_down_loses_the_prescribed_runs_friction_impulse() {
    let t_end = 2e-3;
    let (mut prescribed, y0) = model(None);
    let y = run(&mut prescribed, &y0, t_end);
    let (drive_work, _) = prescribed.work(&y);
    // ∫ T dt of the prescribed run: its drive work over its speed.
    let impulse = drive_work / SPEED;
    assert!(impulse > 0.0, "a turning bearing resists: {impulse} N·m·s");
    let inertia = 2.0 * impulse / (0.01 * SPEED);
    let (mut coasting, z0) = model(Some(TorqueDrive::constant(inertia, 0.0)));
    let z = run(&mut coasting, &z0, t_end);
    let loss = SPEED - z[coasting.layout().spin() + 1];
    // The balls and the cage slow with the ring, giving back their kinetic
    // energy E_k ∝ ω²: the ring's inertia is J + 2 E_k/ω².
    let reflected = 2.0 * prescribed.energy(0.0, &y0).kinetic / (SPEED * SPEED);
    let expected = impulse / (inertia + reflected);
    assert!(
        (loss - expected).abs() < 0.02 * expected,
        "speed lost {loss} rad/s, J⁻¹ ∫ T dt = {expected} rad/s"
    );
    let (work, _) = coasting.work(&z);
    assert_eq!(work, 0.0, "no torque, no drive work");
}

#[test]
fn the_power_balance_holds_in_a_spin_up() {
    let drive = TorqueDrive {
        inertia: 2e-4,
        torque: vec![(0.0, 0.05), (1e-4, 2.0)],
    };
    let (mut model, y0) = model(Some(drive));
    let worst = worst_power_residual(&mut model, &y0);
    // Measured 7.5e-8; leaving ½ J ω² out of the energy gives ~1.
    assert!(worst < 1e-5, "worst power residual {worst:e} of the powers");
    let mut dy = vec![0.0; model.dimension()];
    let l = model.layout();
    let p = model.rhs_with_power(1.5e-4, &y0, &mut dy);
    assert_eq!(p.drive_torque, 2.0);
    // The friction torque: the moment of the bearing's forces against the
    // rotation, J ω̇ = T − M_f.
    let omega_rate = dy[l.spin() + 1];
    assert!((2.0 - p.friction_torque - 2e-4 * omega_rate).abs() < 1e-12);
    assert_eq!(dy[l.work()], 2.0 * SPEED);
}
