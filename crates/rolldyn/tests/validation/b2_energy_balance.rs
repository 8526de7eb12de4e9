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
use rolldyn::dynamics::{BearingModel, CageParameters, DragParameters, DynamicsParameters};
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
        drag: DragParameters::default(),
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

/// B2 in 3-D with EHL traction integrated on the ellipse grid (spin
/// friction couples on balls and rings) and ball and cage drag on: 7008C,
/// 10 000 rpm, 200 N, 1 ms from the Jones–Harris state. Guards the traction
/// couple's reaction on the ring (missing it broke the balance by ~50 %)
/// and the drag power.
#[test]
fn b2_energy_balance_with_ehl_grid_traction() {
    use rolldyn::lubrication::Lubricant;
    use rolldyn::quasistatic::{Conditions, QuasiStaticSolver, RacewayControl, SolverOptions};
    use rolldyn::traction::EhlRheology;
    let g = super::common::bearing_7008c();
    let steel = Material::STEEL_52100;
    let speed = 10_000.0 * std::f64::consts::TAU / 60.0;
    let loads = Loads {
        force: [200.0, 0.0, 0.0],
        moment: [0.0; 2],
    };
    let qs = QuasiStaticSolver::new(&g, &steel, &steel, HertzModel::Exact).unwrap();
    let eq = qs
        .solve(
            &Conditions {
                loads,
                inner_speed: speed,
                control: RacewayControl::Outer,
            },
            &SolverOptions::default(),
        )
        .unwrap();
    let params = DynamicsParameters {
        inner_ring_mass: 0.5,
        inner_ring_tilt_inertia: 1e-4,
        cage: CageParameters {
            mass: 0.0031,
            inertia: 2.4e-6,
            pitch_radius: 27e-3,
            pocket_clearance: 0.175e-3,
            pocket_stiffness: 1e7,
            pocket_damping: 20.0,
            pocket_friction: ModifiedCoulomb {
                friction: 0.05,
                stick_speed: 0.0,
                full_speed: 1e-3,
            },
            whirl: true,
        },
        normal_law: NormalForceLaw::Hertz,
        impact_speed_floor: 1e-3,
        traction: TractionModel::Ehl(EhlRheology {
            eyring_stress: 5e6,
            limiting_shear_coefficient: 0.08,
            lubricant: Lubricant {
                viscosity: 0.0467,
                pressure_viscosity: 2.2e-8,
            },
        }),
        traction_integration: TractionIntegration::Grid {
            across: 12,
            along: 6,
        },
        speed: SpeedProfile::Constant(speed),
        loads,
        gravity: 0.0,
        planar: false,
        drag: DragParameters {
            effective_density: 860.0,
            ball_drag_coefficient: 0.5,
            ball_spin_drag_coefficient: 0.05,
            cage_viscous: 1e-6,
            cage_windage: 1e-9,
        },
    };
    let mut model = BearingModel::new(&g, &steel, &steel, HertzModel::Exact, params).unwrap();
    let y0 = model.state_from_equilibrium(&eq);
    let e0 = model.energy(0.0, &y0).total();
    let control = StepControl::Adaptive {
        relative_tolerance: 1e-6,
        max_step: 1e-5,
        initial_step: None,
    };
    let mut rk = ExplicitRk::new(&DOPRI5, control, &model, 0.0, &y0).unwrap();
    while rk.t() < 1e-3 {
        rk.step(&mut model, 1e-3).unwrap();
    }
    let (drive, dissipated) = model.work(rk.y());
    let delta = model.energy(rk.t(), rk.y()).total() - e0;
    let imbalance = drive - delta - dissipated;
    let scale = drive.abs().max(dissipated.abs());
    eprintln!(
        "B2 (3-D, EHL grid): drive {drive:.4e} J, ΔE {delta:.4e} J, dissipated {dissipated:.4e} J, imbalance {:.1e} of the larger",
        imbalance / scale
    );
    assert!(dissipated > 0.0);
    assert!((imbalance / scale).abs() < 1e-3, "imbalance {imbalance}");
}
