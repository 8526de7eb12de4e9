//! Temperatures fed back into the bearing (docs/model.md §10): a
//! quasi-static iteration to thermal steady state.
//!
//! Each pass: the Jones–Harris equilibrium of the bearing at its current
//! operating clearance → Harris's local power loss ([`crate::power::harris`])
//! with the guide-land oil at its current viscosity → the bearing network's
//! steady temperatures ([`super::bearing`]) → the oil viscosity at the oil
//! node (Walther, [`super::viscosity`]) and the thermal expansion of rings
//! and balls relative to the reference temperature at which the geometry
//! is given:
//! ```text
//! ΔP_d = α_r [(d_m + D) ΔT_outer ring − (d_m − D) ΔT_inner ring] − 2 α_b D ΔT_ball
//! ```
//! (raceway diameters d_m ± D; a hotter inner ring and balls take up
//! clearance or add preload, a hotter outer ring gives it back). The
//! geometry is rebuilt with the new diametral clearance (the free contact
//! angle follows). The pass repeats until no node temperature changes by
//! more than the tolerance; the convergence history is reported.

use super::bearing::{BearingThermal, HeatSources, ThermalInputs, ThermalSolution};
use super::viscosity::Walther;
use crate::contact::HertzModel;
use crate::error::InvalidParameter;
use crate::geometry::{BearingGeometry, Clearance, GeometrySpec};
use crate::material::Material;
use crate::power::harris::{LocalMethodInputs, LocalPowerLoss, local_power_loss};
use crate::quasistatic::contact_motion::contact_motions;
use crate::quasistatic::{
    Conditions, Equilibrium, QuasiStaticError, QuasiStaticSolver, SolverOptions,
};

/// Why a coupled solve failed.
#[derive(Debug, thiserror::Error)]
pub enum CoupledError {
    /// Bad input, or a clearance the geometry cannot take.
    #[error(transparent)]
    Invalid(#[from] InvalidParameter),
    /// The quasi-static solve failed.
    #[error(transparent)]
    QuasiStatic(#[from] QuasiStaticError),
}

/// Thermal expansion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Expansion {
    /// Ring expansion coefficient α_r \[1/K\] (0: off).
    pub ring: f64,
    /// Ball expansion coefficient α_b \[1/K\].
    pub ball: f64,
    /// Temperature at which the geometry is given \[K\].
    pub reference_temperature: f64,
}

/// Options of the iteration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoupledOptions {
    /// Largest node-temperature change that ends the iteration \[K\].
    pub tolerance: f64,
    /// Most passes.
    pub max_iterations: usize,
}

impl Default for CoupledOptions {
    fn default() -> Self {
        Self {
            tolerance: 0.01,
            max_iterations: 50,
        }
    }
}

/// The converged (or last) pass.
#[derive(Debug, Clone)]
pub struct CoupledSolution {
    /// Quasi-static equilibrium at the operating clearance.
    pub equilibrium: Equilibrium,
    /// Power loss.
    pub power: LocalPowerLoss,
    /// Temperatures.
    pub thermal: ThermalSolution,
    /// Diametral clearance (equivalent) at operating temperature \[m\].
    pub operating_clearance: f64,
    /// Oil dynamic viscosity at the oil node \[Pa·s\].
    pub oil_viscosity: f64,
    /// Largest node-temperature change of each pass \[K\].
    pub history: Vec<f64>,
    /// Whether the last change was within the tolerance.
    pub converged: bool,
}

/// The heat sources and contact data of a solution for the network.
pub fn heat_sources(
    geometry: &BearingGeometry,
    eq: &Equilibrium,
    power: &LocalPowerLoss,
) -> HeatSources {
    let mut h = HeatSources {
        inner_contacts: power.inner.total(),
        outer_contacts: power.outer.total(),
        balls: power.ball_pocket,
        oil: power.cage_land + power.ball_drag + power.cage_drag + power.seals,
        cage_speed: eq.cage_speed(),
        ..Default::default()
    };
    h.set_contact_means(contact_motions(geometry, eq).iter().flat_map(|contacts| {
        contacts.iter().enumerate().filter_map(|(k, m)| {
            m.map(|m| {
                let e = &m.solution.hertz;
                (k, e.semi_major, e.semi_minor, m.entrainment_speed())
            })
        })
    }));
    h
}

/// `geometry` with its equivalent diametral clearance changed by `delta` \[m\].
pub fn with_clearance_change(
    geometry: &BearingGeometry,
    delta: f64,
) -> Result<BearingGeometry, InvalidParameter> {
    let clearance = geometry.equivalent_diametral_clearance() + delta;
    BearingGeometry::new(&GeometrySpec {
        ball_diameter: geometry.ball_diameter,
        ball_count: geometry.ball_count,
        pitch_diameter: geometry.pitch_diameter,
        inner_groove_curvature: geometry.inner.groove_curvature,
        outer_groove_curvature: geometry.outer.groove_curvature,
        clearance: Clearance::Diametral(clearance),
        preload: clearance < 0.0,
    })
}

/// Everything the coupled iteration needs.
#[derive(Debug, Clone)]
pub struct CoupledProblem<'a> {
    /// Geometry at the reference temperature.
    pub geometry: &'a BearingGeometry,
    /// Ball material.
    pub ball: &'a Material,
    /// Ring material.
    pub rings: &'a Material,
    /// Hertz model of the contact tables.
    pub hertz: HertzModel,
    /// Operating point.
    pub conditions: Conditions,
    /// Quasi-static solver options (ball 0's azimuth).
    pub options: SolverOptions,
    /// Local-method inputs (the guide land's viscosity is updated).
    pub power: LocalMethodInputs,
    /// Network inputs (the oil's kinematic viscosity is updated).
    pub thermal: ThermalInputs,
    /// Viscosity–temperature law (None: constant viscosity).
    pub viscosity: Option<Walther>,
    /// Thermal expansion.
    pub expansion: Expansion,
}

/// Iterates to thermal steady state.
pub fn coupled_steady(
    problem: &CoupledProblem,
    options: &CoupledOptions,
) -> Result<CoupledSolution, CoupledError> {
    let p = problem;
    let mut power_inputs = p.power.clone();
    let mut thermal_inputs = p.thermal.clone();
    let reference = p.expansion.reference_temperature;
    let mut temperatures = [reference; 10];
    temperatures[8] = thermal_inputs.ambient_temperature;
    temperatures[9] = thermal_inputs.oil_inlet_temperature;
    // The oil starts at its inlet temperature.
    temperatures[7] = thermal_inputs.oil_inlet_temperature;
    let mut history = Vec::new();
    let mut last: Option<CoupledSolution> = None;
    let mut warm_start: Option<Equilibrium> = None;
    let base = QuasiStaticSolver::new(p.geometry, p.ball, p.rings, p.hertz)?;
    for _ in 0..options.max_iterations {
        let t =
            |name: &str| super::bearing::node_index(name).map_or(reference, |i| temperatures[i]);
        let e = &p.expansion;
        let delta = e.ring
            * ((p.geometry.pitch_diameter + p.geometry.ball_diameter)
                * (t("outer_ring") - reference)
                - (p.geometry.pitch_diameter - p.geometry.ball_diameter)
                    * (t("inner_ring") - reference))
            - 2.0 * e.ball * p.geometry.ball_diameter * (t("ball") - reference);
        let geometry = if delta != 0.0 {
            with_clearance_change(p.geometry, delta)?
        } else {
            p.geometry.clone()
        };
        let solver = base.with_geometry(&geometry)?;
        let eq = match &warm_start {
            Some(previous) => solver.solve_from(previous, &p.conditions, &p.options)?,
            None => solver.solve(&p.conditions, &p.options)?,
        };
        let oil_viscosity = match &p.viscosity {
            Some(w) => w.dynamic(t("oil")),
            None => thermal_inputs.oil_kinematic_viscosity * thermal_inputs.oil_density,
        };
        if let Some(guide) = &mut power_inputs.guide {
            guide.viscosity = oil_viscosity;
        }
        thermal_inputs.oil_kinematic_viscosity = oil_viscosity / thermal_inputs.oil_density;
        let power = local_power_loss(&geometry, &eq, &power_inputs);
        let network = BearingThermal::new(&thermal_inputs, &heat_sources(&geometry, &eq, &power))?;
        let thermal = network.steady()?;
        let change = thermal
            .temperatures
            .iter()
            .zip(&temperatures)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        history.push(change);
        temperatures = thermal.temperatures;
        let converged = change <= options.tolerance;
        last = Some(CoupledSolution {
            operating_clearance: geometry.equivalent_diametral_clearance(),
            equilibrium: eq.clone(),
            power,
            thermal,
            oil_viscosity,
            history: history.clone(),
            converged,
        });
        warm_start = Some(eq);
        if converged {
            break;
        }
    }
    last.ok_or_else(|| {
        InvalidParameter::new("max_iterations", 0.0, "needs at least one pass").into()
    })
}
