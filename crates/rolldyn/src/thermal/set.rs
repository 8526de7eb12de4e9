//! Thermal preload growth of bearings on one shaft (docs/systems.md,
//! "Temperature"): the single bearing's coupled iteration ([`super::coupled`])
//! run for every bearing of a [`ShaftSystem`] at once, with the set's
//! equilibrium in the loop.
//!
//! Each pass: every bearing's operating geometry from its node
//! temperatures (the diametral clearance change of [`super::coupled`]:
//! a hotter inner ring and balls take up clearance, a hotter outer ring
//! gives it back), its rings held where they were mounted (for an
//! angular-contact bearing given by its free contact angle α₀ the preload
//! offset counts from where the balls just touch, so it grows by the
//! change of (f_i + f_o − 1)D sin α₀ as α₀ falls, [`touching_shift`]) and
//! its offset changed by the shaft's growth against the housing's between
//! the bearings → the set's equilibrium →
//! each bearing's local power loss and network → new temperatures, until
//! no node of any bearing changes by more than the tolerance.
//!
//! **Axial growth.** Shaft and housing are taken at the mean of the
//! bearings' shaft and housing nodes and expand from the shaft's
//! reference point: bearing i's inner ring moves against its outer ring by
//! (α_s ΔT_s − α_h ΔT_h) x_i, its pitch plane at x_i. In its own frame
//! (σ_i = +1 as built, −1 mirrored) that adds
//! ```text
//! Δs_i = σ_i x_i (α_s ΔT_s − α_h ΔT_h)
//! ```
//! to its preload offset. A shaft warmer than the housing so unloads a
//! back-to-back pair (its +x bearing sits at −x) and loads a
//! face-to-face pair, while the radial growth of the inner rings loads
//! both: the spindle designer's reason to prefer back to back at speed
//! (Stein & Tu 1994 describe this thermally induced preload of spindle
//! bearings).
//! A floating bearing's outer ring slides, so the growth does not reach
//! it. A common shift of every bearing is taken up by the shaft's free
//! axial motion, so the choice of reference point does not matter.
//!
//! Each bearing has its own network (its own shaft and housing nodes):
//! heat does not pass between the bearings along the shaft or the
//! housing, a limit for bearings far apart at different loads, exact by
//! symmetry for a matched pair under its preload alone.

use super::ThermalSolution;
use super::coupled::{
    CoupledError, CoupledOptions, CoupledProblem, Expansion, Relaxation, heat_pass,
    node_temperature, operating_geometry, start_temperatures,
};
use crate::error::InvalidParameter;
use crate::geometry::BearingGeometry;
use crate::power::harris::LocalPowerLoss;
use crate::quasistatic::SolverOptions;
use crate::quasistatic::system::{
    Orientation, ShaftSystem, SystemConditions, SystemEquilibrium, SystemError,
};

/// Why a set's thermal steady state failed.
#[derive(Debug, thiserror::Error)]
pub enum SetThermalError {
    /// Bad input, a clearance the geometry cannot take, or one bearing's
    /// power or network failed.
    #[error(transparent)]
    Coupled(#[from] CoupledError),
    /// The set has no equilibrium at a pass's temperatures.
    #[error(transparent)]
    System(#[from] SystemError),
    /// A bearing lifted off: its contacts carry nothing, and its network
    /// has no contact to heat.
    #[error(
        "bearing {index} is unloaded at the operating point (lifted off): the set's thermal steady state needs every bearing loaded"
    )]
    Unloaded {
        /// Bearing index (0-based).
        index: usize,
    },
}

impl From<InvalidParameter> for SetThermalError {
    fn from(e: InvalidParameter) -> Self {
        Self::Coupled(e.into())
    }
}

/// Everything the set's iteration needs.
#[derive(Debug, Clone)]
pub struct SetThermalProblem<'a> {
    /// Each bearing's heat model, in the system's order: its geometry at
    /// the reference temperature, power and network inputs, viscosity law
    /// and expansion. Its `conditions` and `options` are not used (the
    /// set's are).
    pub bearings: Vec<CoupledProblem<'a>>,
    /// The bearings on the shaft at the reference temperature, with their
    /// mounting offsets.
    pub system: &'a ShaftSystem,
    /// The set's operating point.
    pub conditions: SystemConditions,
    /// Quasi-static solver options.
    pub options: SolverOptions,
    /// Expansion of the shaft and housing between the bearings.
    pub axial: AxialExpansion,
}

/// Thermal-expansion coefficients of the shaft and the housing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxialExpansion {
    /// Shaft α_s \[1/K\].
    pub shaft: f64,
    /// Housing α_h \[1/K\].
    pub housing: f64,
}

/// One bearing at the converged (or last) pass.
#[derive(Debug, Clone)]
pub struct SetBearingThermal {
    /// Diametral clearance (equivalent) at its temperatures \[m\].
    pub operating_clearance: f64,
    /// Its preload offset at temperature (mounting plus axial growth) \[m\].
    pub axial_offset: f64,
    /// Power loss at the set's equilibrium.
    pub power: LocalPowerLoss,
    /// Its network's temperatures.
    pub thermal: ThermalSolution,
    /// Oil dynamic viscosity at its oil node \[Pa·s\].
    pub oil_viscosity: f64,
}

/// The converged (or last) pass: the mounting and equilibrium at the
/// pass's starting temperatures, the temperatures it ended with (as
/// [`super::coupled::CoupledSolution`]).
#[derive(Debug, Clone)]
pub struct SetThermalSolution {
    /// The set's equilibrium at operating temperature.
    pub equilibrium: SystemEquilibrium,
    /// Each bearing.
    pub bearings: Vec<SetBearingThermal>,
    /// The bearings as mounted at operating temperature (geometry and
    /// offsets): solve it under other loads for the hot preload.
    pub system: ShaftSystem,
    /// The shaft's axial strain against the housing's,
    /// α_s ΔT_s − α_h ΔT_h (positive: the shaft grew more).
    pub axial_strain: f64,
    /// Largest node-temperature change of each pass \[K\].
    pub history: Vec<f64>,
    /// Whether the last change was within the tolerance.
    pub converged: bool,
}

/// The shaft's axial strain against the housing's at the bearings' node
/// `temperatures`: α_s ΔT̄_s − α_h ΔT̄_h, over the bearings' mean shaft
/// and housing temperatures above their `references` \[K\].
pub fn axial_strain(axial: &AxialExpansion, references: &[f64], temperatures: &[[f64; 10]]) -> f64 {
    let n = temperatures.len().max(1) as f64;
    let mean_rise = |name| {
        references
            .iter()
            .zip(temperatures)
            .map(|(r, t)| node_temperature(t, name) - r)
            .sum::<f64>()
            / n
    };
    axial.shaft * mean_rise("shaft") - axial.housing * mean_rise("housing")
}

/// How far the touching position moves towards the loaded side when the
/// bearing's geometry changes from `reference` to `operating` with the
/// rings held where they are \[m\]. A bearing given by its free contact
/// angle has its grooves offset so that its balls just touch at x = 0,
/// the groove centres (f_i + f_o − 1)D sin α₀ apart axially
/// ([`BearingGeometry::nominal_contact_angle`]); a smaller clearance
/// (smaller α₀) brings that position nearer, so the same ring positions
/// are a larger offset. Grooves given centred (by clearance or raceway
/// diameters) have x = 0 at the centred rings: no shift.
pub fn touching_shift(reference: &BearingGeometry, operating: &BearingGeometry) -> f64 {
    let gap = |g: &BearingGeometry| {
        g.total_curvature() * g.ball_diameter * g.nominal_contact_angle().sin()
    };
    gap(reference) - gap(operating)
}

/// The bearings of `system` (at the reference temperature) as mounted at
/// node `temperatures`: each bearing's operating geometry from its
/// reference geometry and expansion in `bearings`, its offset moved by the
/// touching position's shift and by the axial strain `strain` (module
/// doc); with the operating geometries.
pub fn mounted_at(
    system: &ShaftSystem,
    bearings: &[(&BearingGeometry, Expansion)],
    strain: f64,
    temperatures: &[[f64; 10]],
) -> Result<(ShaftSystem, Vec<BearingGeometry>), SetThermalError> {
    let mut system = system.clone();
    let mut geometries = Vec::with_capacity(temperatures.len());
    for ((mounted, (reference, expansion)), t) in
        system.bearings.iter_mut().zip(bearings).zip(temperatures)
    {
        let geometry = operating_geometry(reference, expansion, t)?;
        mounted.solver = mounted.solver.with_geometry(&geometry)?;
        mounted.axial_offset += touching_shift(reference, &geometry);
        if !mounted.floating {
            let sign = match mounted.orientation {
                Orientation::Forward => 1.0,
                Orientation::Reversed => -1.0,
            };
            mounted.axial_offset += sign * mounted.position * strain;
        }
        geometries.push(geometry);
    }
    Ok((system, geometries))
}

/// Iterates the set to thermal steady state from its equilibrium `cold`
/// at the reference temperature.
pub fn set_steady(
    problem: &SetThermalProblem,
    cold: &SystemEquilibrium,
    options: &CoupledOptions,
) -> Result<SetThermalSolution, SetThermalError> {
    let count = problem.system.bearings.len();
    if problem.bearings.len() != count {
        return Err(InvalidParameter::new(
            "bearings",
            problem.bearings.len() as f64,
            "needs one heat model per bearing of the system",
        )
        .into());
    }
    let mut temperatures: Vec<[f64; 10]> =
        problem.bearings.iter().map(start_temperatures).collect();
    let references: Vec<_> = problem
        .bearings
        .iter()
        .map(|b| (b.geometry, b.expansion))
        .collect();
    let reference_temperatures: Vec<_> = problem
        .bearings
        .iter()
        .map(|b| b.expansion.reference_temperature)
        .collect();
    let mut near = cold.clone();
    let mut relaxation = Relaxation::default();
    let mut history = Vec::new();
    let mut last = None;
    for _ in 0..options.max_iterations {
        let strain = axial_strain(&problem.axial, &reference_temperatures, &temperatures);
        let (system, geometries) = mounted_at(problem.system, &references, strain, &temperatures)?;
        let eq = system.solve_near(&near, &problem.conditions, &problem.options)?;
        let mut bearings = Vec::with_capacity(count);
        let mut mapped = Vec::with_capacity(10 * count);
        for (index, ((heat, geometry), state)) in problem
            .bearings
            .iter()
            .zip(&geometries)
            .zip(&eq.bearings)
            .enumerate()
        {
            let state = state.as_ref().ok_or(SetThermalError::Unloaded { index })?;
            let pass = heat_pass(heat, geometry, state, &temperatures[index])?;
            mapped.extend_from_slice(&pass.thermal.temperatures);
            bearings.push(SetBearingThermal {
                operating_clearance: geometry.equivalent_diametral_clearance(),
                axial_offset: system.bearings[index].axial_offset,
                power: pass.power,
                thermal: pass.thermal,
                oil_viscosity: pass.oil_viscosity,
            });
        }
        let mut current: Vec<f64> = temperatures.iter().flatten().copied().collect();
        let change = mapped
            .iter()
            .zip(&current)
            .fold(0.0_f64, |m, (f, t)| m.max((f - t).abs()));
        relaxation.update(&mut current, &mapped);
        for (node_temperatures, relaxed) in temperatures.iter_mut().zip(current.chunks_exact(10)) {
            node_temperatures.copy_from_slice(relaxed);
        }
        history.push(change);
        let converged = change <= options.tolerance;
        last = Some(SetThermalSolution {
            equilibrium: eq.clone(),
            bearings,
            axial_strain: strain,
            system,
            history: history.clone(),
            converged,
        });
        near = eq;
        if converged {
            break;
        }
    }
    last.ok_or_else(|| {
        InvalidParameter::new("max_iterations", 0.0, "needs at least one pass").into()
    })
}
