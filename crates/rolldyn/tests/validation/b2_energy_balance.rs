//! B2: with dissipation on, drive work = Δ(mechanical energy) + dissipated
//! energy over a run, to 1e-3 relative or better (MODEL §10). The drive
//! work and the dissipation are integrated as states of the model, so the
//! balance closes to integrator accuracy.

use super::common::{bearing_6304, bearing_7008c, dynamics_7008c, seed000_dynamics, steel_seed000};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::{BearingModel, DragParameters};
use rolldyn::integrate::tableau::DOPRI5;
use rolldyn::integrate::{ExplicitRk, StepControl};
use rolldyn::material::Material;

/// Integrates `model` from `y0` to `t_end`; returns (drive, ΔE, dissipated).
fn balance(mut model: BearingModel, y0: &[f64], t_end: f64, rtol: f64) -> (f64, f64, f64) {
    let e0 = model.energy(0.0, y0).total();
    let control = StepControl::Adaptive {
        relative_tolerance: rtol,
        max_step: 1e-5,
        initial_step: None,
    };
    let mut rk = ExplicitRk::new(&DOPRI5, control, &model, 0.0, y0).unwrap();
    while rk.t() < t_end {
        rk.step(&mut model, t_end).unwrap();
    }
    let (drive, dissipated) = model.work(rk.y());
    (drive, model.energy(rk.t(), rk.y()).total() - e0, dissipated)
}

/// Seed 000's 6304 in planar mode with clearance (P_d = 20 µm), L–N
/// contact, modified Coulomb traction at the contact centres, damped
/// pockets with friction, gravity, radial load 100 N, 8000 rpm, balls and
/// cage started at rest: contacts open and close, balls skid and impact.
#[test]
fn b2_drive_work_balances_energy_and_dissipation() {
    let g = bearing_6304();
    let mut params = seed000_dynamics(100.0);
    params.inner_ring_mass = 0.1;
    params.inner_ring_tilt_inertia = 1e-5;
    let steel = steel_seed000();
    let model = BearingModel::new(&g, &steel, &steel, HertzModel::HertzCircular, params).unwrap();
    let mut y0 = model.pure_rolling_state([0.0; 5]);
    let l = model.layout();
    for j in 0..l.balls {
        y0[l.ball(j) + 5] = 0.0;
        y0[l.ball(j) + 6] = 0.0;
    }
    y0[l.cage() + 5] = 0.0;
    let (drive, delta, dissipated) = balance(model, &y0, 0.01, 1e-7);
    let imbalance = drive - delta - dissipated;
    eprintln!(
        "B2: drive {drive:.6e} J, ΔE {delta:.6e} J, dissipated {dissipated:.6e} J, imbalance {:.1e} of the drive",
        (imbalance / drive).abs()
    );
    assert!(
        drive > 0.0 && dissipated > 0.0 && delta > 0.0,
        "the ring accelerates the balls and friction dissipates"
    );
    assert!(
        (imbalance / drive).abs() < 1e-3,
        "energy balance off by {imbalance} J"
    );
}

/// B2 in 3-D with EHL traction integrated on the ellipse grid (spin
/// friction couples on balls and rings) and ball and cage drag on: 7008C,
/// 10 000 rpm, 200 N, 1 ms from the Jones–Harris state. Guards the traction
/// couple's reaction on the ring (missing it broke the balance by ~50 %)
/// and the drag power.
#[test]
fn b2_energy_balance_with_ehl_grid_traction() {
    let drag = DragParameters {
        effective_density: 860.0,
        ball_drag_coefficient: 0.5,
        ball_spin_drag_coefficient: 0.05,
        cage_viscous: 1e-6,
        cage_windage: 1e-9,
    };
    let (params, eq) = dynamics_7008c(drag);
    let steel = Material::STEEL_52100;
    let model =
        BearingModel::new(&bearing_7008c(), &steel, &steel, HertzModel::Exact, params).unwrap();
    let y0 = model.state_from_equilibrium(&eq);
    let (drive, delta, dissipated) = balance(model, &y0, 1e-3, 1e-6);
    let imbalance = drive - delta - dissipated;
    let scale = drive.abs().max(dissipated.abs());
    eprintln!(
        "B2 (3-D, EHL grid, drag): drive {drive:.4e} J, ΔE {delta:.4e} J, dissipated {dissipated:.4e} J, imbalance {:.1e} of the larger",
        imbalance / scale
    );
    assert!(dissipated > 0.0);
    assert!((imbalance / scale).abs() < 1e-3, "imbalance {imbalance}");
}
