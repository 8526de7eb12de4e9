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
    /// The quasi-static solve failed at a warm pass: the parts' expansion
    /// has changed the clearance from the one the case gives.
    #[error(
        "thermal steady state, pass {pass}: with the hottest part at {:.1} °C the operating diametral clearance is {:.2} µm ({:.2} µm at the reference temperature): {source}",
        hottest - 273.15,
        clearance * 1e6,
        reference_clearance * 1e6
    )]
    Warm {
        /// The pass (1: the first) \[-\].
        pass: usize,
        /// The hottest node's temperature \[K\].
        hottest: f64,
        /// Equivalent diametral clearance at the pass's temperatures \[m\].
        clearance: f64,
        /// The same at the reference temperature \[m\].
        reference_clearance: f64,
        /// Why the solve failed.
        source: QuasiStaticError,
    },
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
        oil: power.cage_land + power.ball_drag + power.cage_drag + power.seals + power.churning,
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

/// `geometry` with its equivalent diametral clearance changed by `delta` \[m\],
/// in the parametrization it was given in: an angular-contact bearing
/// given by its free contact angle (grooves offset so that the balls touch
/// at x = 0) keeps that form with the free contact angle of the new
/// clearance, cos α₀ = 1 − P_d/(2(f_i + f_o − 1)D); a bearing given by its
/// clearance or raceway diameters (grooves centred) takes the new
/// diametral clearance.
pub fn with_clearance_change(
    geometry: &BearingGeometry,
    delta: f64,
) -> Result<BearingGeometry, InvalidParameter> {
    let clearance = geometry.equivalent_diametral_clearance() + delta;
    let (clearance, preload) = match geometry.clearance {
        Clearance::FreeContactAngle(_) => {
            let cos = 1.0 - clearance / (2.0 * geometry.total_curvature() * geometry.ball_diameter);
            if !(clearance > 0.0 && cos > 0.0) {
                return Err(InvalidParameter::new(
                    "free_contact_angle",
                    format!("operating diametral clearance {clearance} m"),
                    "the thermal expansion closes the clearance of a bearing given by its free contact angle (its balls would be preloaded radially); give the bearing by its diametral_clearance instead",
                ));
            }
            (Clearance::FreeContactAngle(cos.acos()), false)
        }
        _ => (Clearance::Diametral(clearance), clearance < 0.0),
    };
    BearingGeometry::new(&GeometrySpec {
        ball_diameter: geometry.ball_diameter,
        ball_count: geometry.ball_count,
        pitch_diameter: geometry.pitch_diameter,
        inner_groove_curvature: geometry.inner.groove_curvature,
        outer_groove_curvature: geometry.outer.groove_curvature,
        clearance,
        preload,
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

/// The node temperatures an iteration starts from: every part at the
/// reference temperature, the oil at its inlet temperature.
pub fn start_temperatures(problem: &CoupledProblem) -> [f64; 10] {
    let mut temperatures = [problem.expansion.reference_temperature; 10];
    temperatures[8] = problem.thermal.ambient_temperature;
    temperatures[9] = problem.thermal.oil_inlet_temperature;
    temperatures[7] = problem.thermal.oil_inlet_temperature;
    temperatures
}

/// Node `name`'s temperature in `temperatures` (ordered as
/// [`super::bearing::NODES`]) \[K\].
pub fn node_temperature(temperatures: &[f64; 10], name: &str) -> f64 {
    super::bearing::node_index(name).map_or(f64::NAN, |i| temperatures[i])
}

/// The bearing's geometry `g` (at the reference temperature) at node
/// `temperatures`: the diametral clearance changed by the rings' and
/// balls' expansion `e` from the reference temperature (module doc).
pub fn operating_geometry(
    g: &BearingGeometry,
    e: &Expansion,
    temperatures: &[f64; 10],
) -> Result<BearingGeometry, InvalidParameter> {
    let rise = |name| node_temperature(temperatures, name) - e.reference_temperature;
    let delta = e.ring
        * ((g.pitch_diameter + g.ball_diameter) * rise("outer_ring")
            - (g.pitch_diameter - g.ball_diameter) * rise("inner_ring"))
        - 2.0 * e.ball * g.ball_diameter * rise("ball");
    if delta != 0.0 {
        with_clearance_change(g, delta)
    } else {
        Ok(g.clone())
    }
}

/// One pass's heat: the local power loss of equilibrium `eq` with the oil
/// at its viscosity at node `temperatures`, and the network's steady
/// temperatures from it.
pub struct HeatPass {
    /// Power loss.
    pub power: LocalPowerLoss,
    /// The network's steady state.
    pub thermal: ThermalSolution,
    /// Oil dynamic viscosity at the oil node \[Pa·s\].
    pub oil_viscosity: f64,
}

/// The heat pass of `problem`'s bearing with operating `geometry` at
/// equilibrium `eq`, the oil at its node temperature in `temperatures`.
pub fn heat_pass(
    problem: &CoupledProblem,
    geometry: &BearingGeometry,
    eq: &Equilibrium,
    temperatures: &[f64; 10],
) -> Result<HeatPass, CoupledError> {
    let mut power_inputs = problem.power.clone();
    let mut thermal_inputs = problem.thermal.clone();
    let oil_viscosity = match &problem.viscosity {
        Some(w) => w.dynamic(node_temperature(temperatures, "oil")),
        None => thermal_inputs.oil_kinematic_viscosity * thermal_inputs.oil_density,
    };
    if let Some(guide) = &mut power_inputs.guide {
        guide.viscosity = oil_viscosity;
    }
    if let Some(churning) = &mut power_inputs.churning {
        churning.viscosity = oil_viscosity;
    }
    // The contacts' inlets at the mean of the ball's and the rings'
    // temperatures (as in a coupled dynamic run), with the law's slope there.
    if let (Some(w), Some(rolling)) = (&problem.viscosity, &mut power_inputs.rolling_resistance) {
        let t = |n| node_temperature(temperatures, n);
        let inlet = 0.5 * (t("ball") + 0.5 * (t("inner_ring") + t("outer_ring")));
        rolling.set_viscosity(w.dynamic(inlet), Some(w.temperature_coefficient(inlet)));
    }
    thermal_inputs.oil_kinematic_viscosity = oil_viscosity / thermal_inputs.oil_density;
    let power = local_power_loss(geometry, eq, &power_inputs);
    let network = BearingThermal::new(&thermal_inputs, &heat_sources(geometry, eq, &power))?;
    Ok(HeatPass {
        power,
        thermal: network.steady()?,
        oil_viscosity,
    })
}

/// Largest change between two sets of node temperatures \[K\].
pub fn largest_change(a: &[f64; 10], b: &[f64; 10]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max)
}

/// The fixed-point iteration T ← F(T) of the coupled passes, relaxed where
/// it does not contract.
///
/// The heat grows with the oil's viscosity and the viscosity falls steeply
/// with temperature (Walther), so at high speed a pass can overshoot: a
/// hot pass thins the oil, the next pass is cold, and plain substitution
/// alternates between the two without end (the default 7008C case at
/// 10 000 r/min with a two-point viscosity law: 20 → 677 → 57 → 420 … °C).
/// While each pass at least halves the change the update is the pass
/// itself (T ← F(T), so a contracting iteration is untouched); from the
/// first pass that does not, Aitken's dynamic relaxation (Irons & Tuck
/// 1969; Küttler & Wall 2008, eq 44) takes over:
/// ```text
/// r_n = F(T_n) − T_n,   ω_n = −ω_{n−1} r_{n−1}·(r_n − r_{n−1}) / |r_n − r_{n−1}|²,
/// T_{n+1} = T_n + ω_n r_n,   ω_n ∈ [0.01, 1]
/// ```
/// which for a scalar linear map is the secant step to its fixed point.
#[derive(Debug, Clone, Default)]
pub struct Relaxation {
    previous: Option<(Vec<f64>, f64)>,
    relaxing: bool,
    omega: f64,
}

impl Relaxation {
    /// Moves `current` (T_n, updated in place) towards the pass's
    /// `mapped` temperatures F(T_n).
    pub fn update(&mut self, current: &mut [f64], mapped: &[f64]) {
        let residual: Vec<f64> = mapped
            .iter()
            .zip(current.iter())
            .map(|(f, t)| f - t)
            .collect();
        let size = residual.iter().fold(0.0_f64, |m, r| m.max(r.abs()));
        if let Some((previous, previous_size)) = &self.previous {
            if !self.relaxing && size > 0.5 * previous_size {
                self.relaxing = true;
                self.omega = 1.0;
            }
            if self.relaxing {
                let (mut dot, mut norm) = (0.0, 0.0);
                for (r, p) in residual.iter().zip(previous) {
                    dot += p * (r - p);
                    norm += (r - p) * (r - p);
                }
                if norm > 0.0 {
                    self.omega = (-self.omega * dot / norm).clamp(0.01, 1.0);
                }
            }
        }
        let omega = if self.relaxing { self.omega } else { 1.0 };
        for (t, r) in current.iter_mut().zip(&residual) {
            *t += omega * r;
        }
        self.previous = Some((residual, size));
    }
}

/// Most halvings of a pass's temperature step when the equilibrium at the
/// new operating clearance is not found.
const MAX_BACKTRACKS: usize = 8;

/// Iterates to thermal steady state.
pub fn coupled_steady(
    problem: &CoupledProblem,
    options: &CoupledOptions,
) -> Result<CoupledSolution, CoupledError> {
    let p = problem;
    let mut temperatures = start_temperatures(p);
    let mut history = Vec::new();
    let mut last: Option<CoupledSolution> = None;
    let mut warm_start: Option<Equilibrium> = None;
    let base = QuasiStaticSolver::new(p.geometry, p.ball, p.rings, p.hertz)?;
    let mut relaxation = Relaxation::default();
    // The temperatures of the last pass whose equilibrium was found.
    let mut solved = temperatures;
    for _ in 0..options.max_iterations {
        let mut backtracks = 0;
        let (geometry, eq) = loop {
            let attempt = operating_geometry(p.geometry, &p.expansion, &temperatures)
                .map_err(CoupledError::from)
                .and_then(|geometry| {
                    let solver = base.with_geometry(&geometry)?;
                    let eq = match &warm_start {
                        Some(previous) => solver.solve_from(previous, &p.conditions, &p.options)?,
                        None => solver.solve(&p.conditions, &p.options)?,
                    };
                    Ok((geometry, eq))
                });
            match attempt {
                Ok(found) => break found,
                // A large step of the temperatures (the first pass from
                // cold) can move the clearance past where the equilibrium
                // continues from the last one: halve the step back.
                Err(_) if warm_start.is_some() && backtracks < MAX_BACKTRACKS => {
                    backtracks += 1;
                    for (t, s) in temperatures.iter_mut().zip(&solved) {
                        *t = 0.5 * (*t + s);
                    }
                }
                Err(CoupledError::QuasiStatic(source)) if warm_start.is_some() => {
                    return Err(CoupledError::Warm {
                        pass: history.len() + 1,
                        hottest: temperatures.iter().copied().fold(f64::MIN, f64::max),
                        clearance: operating_geometry(p.geometry, &p.expansion, &temperatures)
                            .map_or(f64::NAN, |g| g.equivalent_diametral_clearance()),
                        reference_clearance: p.geometry.equivalent_diametral_clearance(),
                        source,
                    });
                }
                Err(e) => return Err(e),
            }
        };
        solved = temperatures;
        let pass = heat_pass(p, &geometry, &eq, &temperatures)?;
        let change = largest_change(&pass.thermal.temperatures, &temperatures);
        history.push(change);
        relaxation.update(&mut temperatures, &pass.thermal.temperatures);
        let converged = change <= options.tolerance;
        last = Some(CoupledSolution {
            operating_clearance: geometry.equivalent_diametral_clearance(),
            equilibrium: eq.clone(),
            power: pass.power,
            thermal: pass.thermal,
            oil_viscosity: pass.oil_viscosity,
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

#[cfg(test)]
mod tests {
    use super::Relaxation;

    /// Iterates `map` from `start` with the relaxation; the passes taken
    /// to a change below 1e-9 (None if 200 do not reach it).
    fn iterate(map: impl Fn(f64) -> f64, start: f64) -> (Option<usize>, f64) {
        let mut relaxation = Relaxation::default();
        let mut t = [start];
        for pass in 1..=200 {
            let mapped = [map(t[0])];
            if (mapped[0] - t[0]).abs() < 1e-9 {
                return (Some(pass), t[0]);
            }
            relaxation.update(&mut t, &mapped);
        }
        (None, t[0])
    }

    #[test]
    fn an_overshooting_iteration_reaches_its_fixed_point() {
        // F(T) = 400 − 3 (T − 100): slope −3, plain substitution diverges
        // in growing alternation; the fixed point is T = 175.
        let map = |t: f64| 400.0 - 3.0 * (t - 100.0);
        let mut plain = 20.0;
        for _ in 0..10 {
            plain = map(plain);
        }
        assert!((plain - 175.0).abs() > 1e4, "plain substitution diverges");
        let (passes, t) = iterate(map, 20.0);
        assert!(passes.is_some_and(|n| n <= 6), "{passes:?}");
        assert!((t - 175.0).abs() < 1e-9, "{t}");
        // A nonlinear overshoot of the heat–viscosity kind: the heat falls
        // as exp(−T/30) of the temperature it is computed at.
        let map = |t: f64| 20.0 + 2000.0 * (-(t - 20.0) / 30.0).exp();
        let (passes, t) = iterate(map, 20.0);
        assert!(passes.is_some(), "not converged at {t}");
        assert!((map(t) - t).abs() < 1e-9);
    }

    #[test]
    fn a_contracting_iteration_is_plain_substitution() {
        // Slope 0.3: each pass shrinks the change, so each update is the
        // pass itself and the iterates are F's.
        let map = |t: f64| 50.0 + 0.3 * t;
        let mut relaxation = Relaxation::default();
        let (mut t, mut plain) = ([20.0], 20.0);
        for _ in 0..30 {
            let mapped = [map(t[0])];
            relaxation.update(&mut t, &mapped);
            plain = map(plain);
            assert_eq!(t[0], plain);
        }
    }
}
