//! The quasi-static analyses of a case: its Jones–Harris equilibrium (with
//! the film in the normal approach when the case asks), the friction power
//! by Harris's local method and the coupled thermal steady state
//! (docs/quasistatic.md, docs/power.md, docs/thermal.md).

use super::SimulationError;
use crate::Case;
use rolldyn::RingKind;
use rolldyn::lubrication::Lubricant;
use rolldyn::material::effective_modulus;
use rolldyn::power::{LocalPowerLoss, local_power_loss};
use rolldyn::quasistatic::films::FilmInputs;
use rolldyn::quasistatic::{
    Conditions, Equilibrium, QuasiStaticError, QuasiStaticSolver, RacewayControl, SolverOptions,
};
use rolldyn::thermal::coupled::{
    CoupledError, CoupledOptions, CoupledProblem, CoupledSolution, coupled_steady,
};

/// A case's quasi-static problem: the solver with the case's bearing,
/// materials and Hertz model, its operating point and solver options.
#[derive(Debug, Clone)]
pub struct QuasiStatic {
    /// The solver (contact tables of the case's bearing).
    pub solver: QuasiStaticSolver,
    /// The case's final speed (0 without one), loads and raceway control.
    pub conditions: Conditions,
    /// The case's `[solver]` options of the quasi-static solve.
    pub options: SolverOptions,
    /// What the films need, with a `[lubricant]`.
    pub films: Option<FilmInputs>,
    /// Whether the film enters the normal approach (`model.film_in_approach`).
    pub film_in_approach: bool,
}

impl QuasiStatic {
    /// The quasi-static problem of `case` at its own operating point.
    pub fn from_case(case: &Case) -> Result<Self, SimulationError> {
        Ok(Self {
            solver: QuasiStaticSolver::new(
                &case.bearing.geometry,
                &case.materials.ball.material,
                &case.materials.rings.material,
                case.contact_stiffness,
            )?,
            conditions: conditions(case, None),
            options: case.solver_options(),
            films: film_inputs(case),
            film_in_approach: case.film_in_approach,
        })
    }

    /// The same problem under another raceway control.
    pub fn with_control(mut self, control: RacewayControl) -> Self {
        self.conditions.control = control;
        self
    }

    /// The equilibrium at `conditions`: with the film in the normal
    /// approach when the case asks for it and has a lubricant, else dry.
    pub fn solve_at(&self, conditions: &Conditions) -> Result<Equilibrium, QuasiStaticError> {
        match (&self.films, self.film_in_approach) {
            (Some(inputs), true) => self
                .solver
                .solve_with_films(conditions, &self.options, inputs),
            _ => self.solver.solve(conditions, &self.options),
        }
    }

    /// The equilibrium at the case's operating point.
    pub fn solve(&self) -> Result<Equilibrium, QuasiStaticError> {
        self.solve_at(&self.conditions)
    }
}

/// Operating point of a case: its final speed (0 without one), its loads
/// and `control` (default: the case's raceway control).
pub fn conditions(case: &Case, control: Option<RacewayControl>) -> Conditions {
    Conditions {
        loads: case.loads,
        inner_speed: case.speed.as_ref().map_or(0.0, |s| s.final_speed()),
        control: control.unwrap_or(case.raceway_control),
    }
}

/// What the films need from the case (None without a `[lubricant]`).
pub fn film_inputs(case: &Case) -> Option<FilmInputs> {
    let lub = case.lubricant.as_ref()?;
    Some(FilmInputs {
        lubricant: Lubricant {
            viscosity: lub.viscosity,
            pressure_viscosity: lub.pressure_viscosity,
            pressure_model: lub.pressure_viscosity_model,
        },
        supply: lub.supply,
        roughness: [
            case.surface.composite_roughness(RingKind::Inner),
            case.surface.composite_roughness(RingKind::Outer),
        ],
        effective_modulus: effective_modulus(
            &case.materials.ball.material,
            &case.materials.rings.material,
        ),
    })
}

/// The Jones–Harris equilibrium of a case (dry) and its friction power by
/// Harris's local method.
pub fn power_loss(case: &Case) -> Result<(Equilibrium, LocalPowerLoss), SimulationError> {
    super::single_bearing(case, "the power loss")?;
    let inputs = case.local_method_inputs()?;
    let problem = QuasiStatic::from_case(case)?;
    let equilibrium = problem
        .solver
        .solve(&problem.conditions, &problem.options)?;
    let power = local_power_loss(&case.bearing.geometry, &equilibrium, &inputs);
    Ok((equilibrium, power))
}

/// The coupled thermal steady state of a case: Jones–Harris, local power
/// loss, thermal network, oil viscosity and operating clearance, iterated.
pub fn thermal_steady_state(case: &Case) -> Result<CoupledSolution, SimulationError> {
    super::single_bearing(case, "the thermal network")?;
    coupled_steady(&coupled_problem(case)?, &CoupledOptions::default()).map_err(coupled_failure)
}

/// The coupled iteration's inputs from a case (its bearing, materials,
/// operating point, power and network inputs, viscosity law, expansion).
pub fn coupled_problem(case: &Case) -> Result<CoupledProblem<'_>, SimulationError> {
    Ok(CoupledProblem {
        geometry: &case.bearing.geometry,
        ball: &case.materials.ball.material,
        rings: &case.materials.rings.material,
        hertz: case.contact_stiffness,
        conditions: conditions(case, None),
        options: case.solver_options(),
        power: case.local_method_inputs()?,
        thermal: case.thermal_inputs()?,
        viscosity: case.lubricant.as_ref().and_then(|l| l.viscosity_law),
        expansion: case.thermal.expansion,
    })
}

/// A coupled iteration's failure as the case's.
pub fn coupled_failure(e: CoupledError) -> SimulationError {
    match e {
        CoupledError::QuasiStatic(q) => SimulationError::QuasiStatic(q),
        CoupledError::Invalid(p) => SimulationError::Thermal(p),
        warm @ CoupledError::Warm { .. } => SimulationError::WarmEquilibrium(warm),
    }
}
