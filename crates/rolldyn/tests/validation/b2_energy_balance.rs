//! B2: with dissipation on, drive work = Δ(mechanical energy) + dissipated
//! energy over a run, to 1e-3 relative or better (MODEL §10). The drive
//! work and the dissipation are integrated as states of the model, so the
//! balance closes to integrator accuracy.
//!
//! Configuration: seed 000's 6304 in planar mode with clearance (P_d =
//! 20 µm), Lankarani–Nikravesh contact (e = 0.9), modified Coulomb traction
//! (μ = 0.1) at the contact centres, damped pockets with friction, radial
//! load 100 N, inner ring at 8000 rpm, started at rest relative to pure
//! rolling: contacts open and close, balls skid and impact.

use rolldyn::contact::{HertzModel, NormalForceLaw};
use rolldyn::dynamics::{BearingModel, CageParameters, DynamicsParameters};
use rolldyn::integrate::tableau::DOPRI5;
use rolldyn::integrate::{ExplicitRk, StepControl};
use rolldyn::material::Material;
use rolldyn::operating::{Loads, SpeedProfile};
use rolldyn::traction::{ModifiedCoulomb, TractionIntegration, TractionModel};
use rolldyn::{BearingGeometry, Clearance, GeometrySpec};

#[test]
fn b2_drive_work_balances_energy_and_dissipation() {
    let g = BearingGeometry::new(&GeometrySpec {
        ball_diameter: 9.52e-3,
        ball_count: 7,
        pitch_diameter: 0.0,
        inner_groove_curvature: 0.52,
        outer_groove_curvature: 0.52,
        clearance: Clearance::RacewayDiameters {
            inner: 26.48e-3,
            outer: 45.54e-3,
        },
        preload: false,
    })
    .unwrap();
    let steel = Material {
        elastic_modulus: 210e9,
        poisson_ratio: 0.3,
        density: 7800.0,
    };
    let friction = ModifiedCoulomb {
        friction: 0.1,
        stick_speed: 0.0,
        full_speed: 1e-2,
    };
    let params = DynamicsParameters {
        inner_ring_mass: 0.1,
        inner_ring_tilt_inertia: 1e-5,
        cage: CageParameters {
            mass: 0.005,
            inertia: 8.2e-7,
            pitch_radius: 18.005e-3,
            pocket_clearance: 0.2e-3,
            pocket_stiffness: 1e7,
            pocket_damping: 20.0,
            pocket_friction: friction,
            whirl: true,
        },
        normal_law: NormalForceLaw::LankaraniNikravesh { restitution: 0.9 },
        impact_speed_floor: 1e-3,
        traction: TractionModel::ModifiedCoulomb(friction),
        traction_integration: TractionIntegration::Centre,
        speed: SpeedProfile::Constant(8000.0 * std::f64::consts::TAU / 60.0),
        loads: Loads {
            force: [0.0, 0.0, 100.0],
            moment: [0.0, 0.0],
        },
        gravity: 9.81,
        planar: true,
    };
    let mut model =
        BearingModel::new(&g, &steel, &steel, HertzModel::HertzCircular, params).unwrap();
    // Balls and cage at rest: the inner ring must accelerate them by friction.
    let mut y0 = model.pure_rolling_state([0.0; 5]);
    let l = model.layout();
    for j in 0..l.balls {
        let b = l.ball(j);
        y0[b + 5] = 0.0;
        y0[b + 6] = 0.0;
    }
    y0[l.cage() + 5] = 0.0;
    let e0 = model.energy(0.0, &y0).total();
    let control = StepControl::Adaptive {
        relative_tolerance: 1e-7,
        max_step: 1e-5,
        initial_step: None,
    };
    let mut rk = ExplicitRk::new(&DOPRI5, control, &model, 0.0, &y0).unwrap();
    let t_end = 0.01;
    while rk.t() < t_end {
        rk.step(&mut model, t_end).unwrap();
    }
    let y = rk.y();
    let e1 = model.energy(t_end, y).total();
    let (drive, dissipated) = model.work(y);
    let imbalance = drive - (e1 - e0) - dissipated;
    eprintln!(
        "B2: drive {drive:.6e} J, ΔE {:.6e} J, dissipated {dissipated:.6e} J, imbalance {imbalance:.2e} J ({:.1e} of drive), {} steps",
        e1 - e0,
        (imbalance / drive).abs(),
        rk.stats().steps
    );
    assert!(
        drive > 0.0 && dissipated > 0.0 && e1 > e0,
        "the ring accelerates the balls and friction dissipates"
    );
    assert!(
        (imbalance / drive).abs() < 1e-3,
        "energy balance off by {imbalance} J"
    );
}
