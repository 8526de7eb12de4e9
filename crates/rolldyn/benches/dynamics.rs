//! `cargo bench -p rolldyn --bench dynamics`: wall time, steps and RHS
//! evaluations of the issue-4 benchmark cases with the explicit
//! Dormand–Prince integrator on one core:
//! (a) seed 000's 6304 (planar, L–N, modified Coulomb at the contact
//!     centre, W = 100 N, 8000 rpm), 0.2 s simulated;
//! (b) the 7008C at 10 000 rpm, F_x = 200 N, EHL traction on the 12 × 6
//!     ellipse grid, cage whirl, from the Jones–Harris state, 0.05 s.
//! Targets of issue 4: (a) ≤ 20 s, (b) ≤ 60 s. Figures in docs/performance.md.

use rolldyn::contact::{HertzModel, NormalForceLaw};
use rolldyn::dynamics::{BearingModel, CageParameters, DragParameters, DynamicsParameters};
use rolldyn::integrate::tableau::DOPRI5;
use rolldyn::integrate::{ExplicitRk, StepControl};
use rolldyn::lubrication::Lubricant;
use rolldyn::material::Material;
use rolldyn::operating::{Loads, SpeedProfile};
use rolldyn::quasistatic::{Conditions, QuasiStaticSolver, RacewayControl, SolverOptions};
use rolldyn::traction::{EhlRheology, ModifiedCoulomb, TractionIntegration, TractionModel};
use rolldyn::{BearingGeometry, Clearance, GeometrySpec};
use std::time::Instant;

const RPM: f64 = std::f64::consts::TAU / 60.0;

fn run(name: &str, mut model: BearingModel, y0: &[f64], t_end: f64, rtol: f64) {
    let control = StepControl::Adaptive {
        relative_tolerance: rtol,
        max_step: 1e-5,
        initial_step: None,
    };
    let mut rk = ExplicitRk::new(&DOPRI5, control, &model, 0.0, y0).expect("integrator");
    let start = Instant::now();
    while rk.t() < t_end {
        if let Err(e) = rk.step(&mut model, t_end) {
            println!("{name}: stopped: {e}");
            break;
        }
    }
    let s = rk.stats();
    println!(
        "{name:<52} {:>7.2} s wall for {t_end} s simulated: {} steps, {} rejected, {} RHS evaluations",
        start.elapsed().as_secs_f64(),
        s.steps,
        s.rejected_steps,
        s.rhs_evaluations
    );
}

fn main() {
    // (a) seed 000, assumed parameters as in tests/validation/c1_seed000.rs.
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
    .expect("6304");
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
        inner_ring_mass: 0.5,
        inner_ring_tilt_inertia: 1e-4,
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
        speed: SpeedProfile::Constant(8000.0 * RPM),
        loads: Loads {
            force: [0.0, 0.0, -100.0],
            moment: [0.0; 2],
        },
        gravity: 9.81,
        planar: true,
        drag: DragParameters::default(),
    };
    let model =
        BearingModel::new(&g, &steel, &steel, HertzModel::HertzCircular, params).expect("model");
    let y0 = model.pure_rolling_state([0.0; 5]);
    run(
        "(a) 6304 seed 000, W 100 N, 8000 rpm, rtol 1e-6",
        model,
        &y0,
        0.2,
        1e-6,
    );

    // (b) 7008C default case with EHL traction from the J–H state.
    let g = BearingGeometry::new(&GeometrySpec {
        ball_diameter: 6.35e-3,
        ball_count: 22,
        pitch_diameter: 54e-3,
        inner_groove_curvature: 3.493 / 6.35,
        outer_groove_curvature: 3.302 / 6.35,
        clearance: Clearance::FreeContactAngle(17.7f64.to_radians()),
        preload: false,
    })
    .expect("7008C");
    let steel = Material::STEEL_52100;
    let speed = 10_000.0 * RPM;
    let loads = Loads {
        force: [200.0, 0.0, 0.0],
        moment: [0.0; 2],
    };
    let qs = QuasiStaticSolver::new(&g, &steel, &steel, HertzModel::Exact).expect("qs");
    let eq = qs
        .solve(
            &Conditions {
                loads,
                inner_speed: speed,
                control: RacewayControl::Outer,
            },
            &SolverOptions::default(),
        )
        .expect("J-H");
    let params = DynamicsParameters {
        inner_ring_mass: 0.5,
        inner_ring_tilt_inertia: 1e-4,
        cage: CageParameters {
            mass: 0.01,
            inertia: 5e-6,
            pitch_radius: 27e-3,
            pocket_clearance: 0.175e-3,
            pocket_stiffness: 1e7,
            pocket_damping: 20.0,
            pocket_friction: ModifiedCoulomb {
                friction: 0.05,
                stick_speed: 0.0,
                full_speed: 1e-2,
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
        drag: DragParameters::default(),
    };
    let model = BearingModel::new(&g, &steel, &steel, HertzModel::Exact, params).expect("model");
    let y0 = model.state_from_equilibrium(&eq);
    run(
        "(b) 7008C 10 000 rpm, 200 N, EHL 12×6 grid, rtol 1e-5",
        model,
        &y0,
        0.05,
        1e-5,
    );
}
