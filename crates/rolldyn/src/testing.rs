//! Bearings and configurations of the source papers, built from their
//! printed tables, for tests, benchmarks and examples: the 7008C, 6304 and 7218B geometries,
//! Shan et al. 2023's and the default case's dynamic configurations, and
//! the two adaptive integrators the dynamic validation cases run with.
//! Fixtures of known-valid data: they panic on a bug.

#![allow(clippy::unwrap_used)]

use crate::contact::{HertzModel, NormalForceLaw};
use crate::dynamics::{CageParameters, DragParameters, DynamicsParameters, PocketLaw};
use crate::lubrication::Lubricant;
use crate::material::Material;
use crate::operating::{LoadProfile, Loads, SpeedProfile};
use crate::quasistatic::{
    Conditions, Equilibrium, QuasiStaticSolver, RacewayControl, SolverOptions,
};
use crate::thermal::{ThermalInputs, Walther, bearing::Solid};
use crate::traction::{EhlRheology, ModifiedCoulomb, TractionIntegration, TractionModel};
use crate::{BearingGeometry, Clearance, GeometrySpec};

/// 7008C, Deng et al. 2022 Table 1: d_m 54, D 6.35 mm, Z 22, α₀ 17.7°,
/// r_i 3.493, r_o 3.302 mm.
pub fn spec_7008c() -> GeometrySpec {
    GeometrySpec {
        ball_diameter: 6.35e-3,
        ball_count: 22,
        pitch_diameter: 54e-3,
        inner_groove_curvature: 3.493 / 6.35,
        outer_groove_curvature: 3.302 / 6.35,
        clearance: Clearance::FreeContactAngle(17.7f64.to_radians()),
        preload: false,
    }
}

/// The geometry of [`spec_7008c`].
pub fn bearing_7008c() -> BearingGeometry {
    BearingGeometry::new(&spec_7008c()).expect("Deng et al. 2022 geometry is valid")
}

/// 6304, Shan et al. 2023 Table 1: R_i 13.24, R_o 22.77, r_b 4.76 mm, 7 balls.
/// Groove curvatures are not printed: 0.52 assumed (as the preset).
pub fn bearing_6304() -> BearingGeometry {
    BearingGeometry::new(&GeometrySpec {
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
    .expect("Shan et al. 2023 geometry is valid")
}

/// 7218B as Harris's 218 angular-contact example: D 22.23 mm, Z 16,
/// d_m 125.26 mm, f = 0.5232, α₀ 40° (Zhang et al. 2025 Table 2 gives D, Z, α₀, d_i).
pub fn bearing_7218b() -> BearingGeometry {
    BearingGeometry::new(&GeometrySpec {
        ball_diameter: 22.23e-3,
        ball_count: 16,
        pitch_diameter: 125.26e-3,
        inner_groove_curvature: 0.5232,
        outer_groove_curvature: 0.5232,
        clearance: Clearance::FreeContactAngle(40f64.to_radians()),
        preload: false,
    })
    .expect("7218B geometry is valid")
}

/// The 30 × 62 × 16 angular-contact bearing of Lei et al. 2023 (Table 1:
/// D 9.525 mm, Z 11, d_m 46 mm, α 30°; groove curvatures 0.52 assumed).
pub fn bearing_30x62() -> BearingGeometry {
    BearingGeometry::new(&GeometrySpec {
        ball_diameter: 9.525e-3,
        ball_count: 11,
        pitch_diameter: 46e-3,
        inner_groove_curvature: 0.52,
        outer_groove_curvature: 0.52,
        clearance: Clearance::FreeContactAngle(30f64.to_radians()),
        preload: false,
    })
    .expect("Lei et al. 2023 geometry is valid")
}

/// The thermal network of [`bearing_30x62`] in a steel housing, jet
/// lubricated with 2 l/min of an ISO VG 32 mineral oil at 40 °C, 20 °C
/// ambient (the acbb_30x62 preset's assumed values), and the oil's
/// Walther line (32 cSt at 40 °C, 5.4 cSt at 100 °C, 860 kg/m³).
pub fn thermal_30x62() -> (ThermalInputs, Walther) {
    let g = bearing_30x62();
    let inputs = ThermalInputs {
        bore: 30e-3,
        outside_diameter: 62e-3,
        width: 16e-3,
        ball_diameter: g.ball_diameter,
        pitch_diameter: g.pitch_diameter,
        ball_count: 11,
        ball: Solid::STEEL,
        ring: Solid::STEEL,
        housing: Solid::STEEL,
        housing_diameter: 1.6 * 62e-3,
        housing_width: 32e-3,
        shaft_length: 16e-3,
        ambient_temperature: 293.15,
        oil_inlet_temperature: 313.15,
        oil_flow: 2e-3 / 60.0,
        oil_density: 860.0,
        oil_specific_heat: 1900.0,
        oil_conductivity: 0.13,
        oil_kinematic_viscosity: 32e-6,
        housing_convection: 15.0,
        shaft_convection: 15.0,
        oil_convection: None,
    };
    let walther = Walther::through((313.15, 32e-6 * 860.0), (373.15, 5.4e-6 * 860.0), 860.0)
        .expect("the oil's two viscosities are valid");
    (inputs, walther)
}

/// Shan et al. 2023's steel (Table 1).
pub fn steel_shan_2023() -> Material {
    Material {
        elastic_modulus: 210e9,
        poisson_ratio: 0.3,
        density: 7800.0,
    }
}

/// Shan et al. 2023's dynamic configuration (planar, L–N e = 0.9, modified
/// Coulomb at the contact centre, damped pockets with friction, 8000 rpm,
/// gravity), with the assumed values of the 6304 preset: μ = 0.1,
/// v₁ = 10 mm/s, inner ring + shaft 0.5 kg, cage 5 g, pocket clearance
/// 0.2 mm. `radial_load` acts on the inner ring along z.
pub fn dynamics_6304(radial_load: f64) -> DynamicsParameters {
    let friction = ModifiedCoulomb {
        friction: 0.1,
        stick_speed: 0.0,
        full_speed: 1e-2,
    };
    let cage = CageParameters {
        pocket_friction: friction,
        ..CageParameters::new(
            0.005,
            8.2e-7,
            18.005e-3,
            0.2e-3,
            PocketLaw::Linear {
                stiffness: 1e7,
                damping: 20.0,
            },
        )
    };
    DynamicsParameters {
        normal_law: NormalForceLaw::LankaraniNikravesh { restitution: 0.9 },
        traction: TractionModel::ModifiedCoulomb(friction),
        traction_integration: TractionIntegration::Centre,
        speed: SpeedProfile::Constant(8000.0 * std::f64::consts::TAU / 60.0),
        loads: LoadProfile::Constant(Loads {
            force: [0.0, 0.0, radial_load],
            moment: [0.0, 0.0],
        }),
        gravity: 9.81,
        planar: true,
        ..DynamicsParameters::new(0.5, 1e-4, cage)
    }
}

/// The default case's EHL rheology: Eyring stress τ₀ 5 MPa, limiting
/// shear coefficient Λ_L 0.08, the oil at 40 °C (η₀ 0.0467 Pa·s,
/// α 2.2e-8 1/Pa, Barus).
pub fn ehl_7008c() -> EhlRheology {
    EhlRheology {
        eyring_stress: 5e6,
        limiting_shear_coefficient: 0.08,
        lubricant: Lubricant {
            viscosity: 0.0467,
            pressure_viscosity: 2.2e-8,
            pressure_model: Default::default(),
        },
    }
}

/// The default case's dynamic configuration (7008C, 10 000 rpm,
/// F_x = 200 N, EHL traction τ₀ 5 MPa, Λ_L 0.08 on the 12 × 6 grid, cage
/// with whirl, inner ring 0.5 kg) with `drag`, and its Jones–Harris start
/// (outer control).
pub fn dynamics_7008c(drag: DragParameters) -> (DynamicsParameters, Equilibrium) {
    let g = bearing_7008c();
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
    let cage = CageParameters {
        ..CageParameters::new(
            0.0031,
            2.4e-6,
            27e-3,
            0.175e-3,
            PocketLaw::Linear {
                stiffness: 1e7,
                damping: 20.0,
            },
        )
    };
    let params = DynamicsParameters {
        traction: TractionModel::Ehl(ehl_7008c()),
        traction_integration: TractionIntegration::default(),
        speed: SpeedProfile::Constant(speed),
        loads: LoadProfile::Constant(loads),
        drag,
        ..DynamicsParameters::new(0.5, 1e-4, cage)
    };
    (params, eq)
}

/// Ball and cage drag of the 7008C cases: effective density of the oil
/// (860 kg/m³, Deng et al. 2022 Table 1's ρ_e), C_D 0.5, spin drag 0.05, cage
/// viscous 1e-6 and windage 1e-9 (assumed).
pub fn drag_7008c() -> DragParameters {
    DragParameters {
        effective_density: 860.0,
        ball_drag_coefficient: 0.5,
        ball_spin_drag_coefficient: 0.05,
        cage_viscous: 1e-6,
        cage_windage: 1e-9,
    }
}

/// The 7008C cage's outer-ring guide land, Deng et al. 2022 Table 1: land radius
/// d_co/2 = 28.665 mm, width G 10.1 mm, radial clearance C_g/2 = 0.175 mm,
/// η₀ 0.0467 Pa·s; ε capped at 0.95 with a stop of 1e8 N/m.
pub fn guide_land_7008c() -> crate::dynamics::GuideLand {
    crate::dynamics::GuideLand {
        ring: crate::RingKind::Outer,
        land_radius: 57.33e-3 / 2.0,
        width: 10.1e-3,
        radial_clearance: 0.35e-3 / 2.0,
        viscosity: 0.0467,
        max_eccentricity: 0.95,
        stop_stiffness: 1e8,
    }
}

/// The 6304 preset's dynamic model (Shan et al. 2023, radial load 100 N)
/// and its pure-rolling start.
pub fn model_6304() -> (crate::dynamics::BearingModel, Vec<f64>) {
    let steel = steel_shan_2023();
    let model = crate::dynamics::BearingModel::new(
        &bearing_6304(),
        &steel,
        &steel,
        HertzModel::HertzCircular,
        dynamics_6304(100.0),
    )
    .expect("the 6304 model builds");
    let y0 = model.pure_rolling_state([0.0; 5]);
    (model, y0)
}

/// The default case's 7008C dynamic model (Deng et al. 2022 with the
/// default case's drag) and its Jones–Harris start.
pub fn model_7008c() -> (crate::dynamics::BearingModel, Vec<f64>) {
    let (params, equilibrium) = dynamics_7008c(drag_7008c());
    let steel = Material::STEEL_52100;
    let model = crate::dynamics::BearingModel::new(
        &bearing_7008c(),
        &steel,
        &steel,
        HertzModel::Exact,
        params,
    )
    .expect("the 7008C model builds");
    let y0 = model.state_from_equilibrium(&equilibrium);
    (model, y0)
}

/// The adaptive integrators the dynamic validation cases run with: the
/// explicit DOPRI5 and the stiff ROS34PW2 (both must pass).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Dormand–Prince 5(4).
    Dopri5,
    /// Rosenbrock–W 3(2).
    Ros34pw2,
}

/// Both methods, explicit first.
pub const METHODS: [Method; 2] = [Method::Dopri5, Method::Ros34pw2];

/// An adaptive integrator of `method` for `model` from (0, `y0`).
pub fn integrator(
    method: Method,
    model: &crate::dynamics::BearingModel,
    y0: &[f64],
    relative_tolerance: f64,
    max_step: f64,
) -> crate::integrate::Solver {
    use crate::integrate::{ExplicitRk, ROS34PW2, Rosenbrock, Solver, StepControl};
    match method {
        Method::Dopri5 => Solver::Explicit(Box::new(
            ExplicitRk::builder(&crate::integrate::tableau::DOPRI5)
                .control(StepControl::Adaptive {
                    relative_tolerance,
                    max_step,
                    initial_step: None,
                })
                .build(model, y0)
                .unwrap(),
        )),
        Method::Ros34pw2 => Solver::Rosenbrock(Box::new(
            Rosenbrock::builder(&ROS34PW2)
                .relative_tolerance(relative_tolerance)
                .max_step(max_step)
                .build(model, y0)
                .unwrap(),
        )),
    }
}
