//! The integrator of a case's run: `solver.integrator` resolved (`auto`
//! switches between ros34pw2 and dopri5 by their measured cost,
//! `rolldyn::integrate::switching`), its relative tolerance and largest
//! step with their defaults, and its construction. The stiff integrator's default step
//! resolves the cage's undamped film modes (docs/dynamics.md).

use crate::Case;
use crate::raw::IntegratorChoice;
use rolldyn::cage::CageParameters;
use rolldyn::integrate::OdeSystem;
use rolldyn::integrate::tableau::{DOPRI5, RK4};
use rolldyn::integrate::{
    DEFAULT_ENERGY_TOLERANCE, ExplicitRk, IntegrationError, ROS34PW2, Rosenbrock, Solver,
    StepControl, Switching,
};

/// Default largest step of the explicit adaptive integrator \[s\].
pub const DEFAULT_MAX_STEP: f64 = 1e-5;
/// Default largest step of the stiff integrator \[s\]: a tenth of a
/// millisecond, below the ball-pass periods of the presets (≥ 0.3 ms).
pub const DEFAULT_STIFF_MAX_STEP: f64 = 1e-4;
/// Default fixed step of rk4 \[s\].
pub const DEFAULT_RK4_STEP: f64 = 1e-7;
/// Steps per period of the cage's undamped film modes that the stiff
/// integrator takes at least: ROS34PW2's stability function then damps
/// such a mode by 0.9 % a period, 0.15 % of critical damping (8 steps:
/// 6 %, 1 %; `integrate::rosenbrock` test).
pub const STEPS_PER_FILM_PERIOD: f64 = 16.0;
/// The explicit method's relative tolerance within `auto`, as a share of
/// the case's. Where `auto` hands over to dopri5 its step is bounded by
/// stability (the traction slopes), not accuracy, so a tighter tolerance
/// costs few steps (the deep spall of docs/dynamics.md: the same steps at
/// rtol 1e-3 and 1e-5); at the case's tolerance the error control lets the
/// stiff slip modes hover at the tolerance at the stability limit, and dry
/// friction dissipates that noise: the CWRU example's mean dissipated
/// power came out 9 % low with 1/100, 4 % with 1/1000, of a dopri5 run at
/// rtol 1e-6.
pub const AUTO_EXPLICIT_TOLERANCE_SHARE: f64 = 1e-3;

/// Default relative tolerance of the adaptive integrators.
pub const DEFAULT_RELATIVE_TOLERANCE: f64 = 1e-3;

/// Default largest step of the stiff integrator for a cage: 0.1 ms, or
/// 1/16 of the period of the cage's undamped rattle on `gupta_film`
/// pocket films ([`CageParameters::film_frequency`]). With longer steps
/// the L-stable integrator damps that mode numerically and can hide it:
/// the default case with film pockets rattled at 3.6–3.8 kHz with 30 µs
/// steps or rtol 1e-4 and whirled smoothly with 50 µs steps
/// (docs/dynamics.md).
pub fn stiff_max_step(cage: &CageParameters, balls: usize) -> f64 {
    cage.film_frequency(balls)
        .map_or(DEFAULT_STIFF_MAX_STEP, |f| {
            DEFAULT_STIFF_MAX_STEP.min(1.0 / (STEPS_PER_FILM_PERIOD * f))
        })
}

/// The energy tolerance of runs with spalls. Where a ball meets a pit's
/// edge the contact opens and closes within a step, and both solutions of
/// that step carry nearly the same error, so the energy estimate sees too
/// little of it: at the general default 1e-4 a 0.533 × 0.2 mm inner-race
/// pit of the 6205 at 1 kN and 1772 rpm closed its 20 ms balance to
/// 0.9–1.2e-3 (depending on the end time and on round-off), at 5e-5 to
/// ≤ 1.4e-4 for 2 % more steps (docs/dynamics.md, "Accuracy at default
/// settings").
pub const SPALL_ENERGY_TOLERANCE: f64 = 5e-5;

/// The integrator a run uses, with its tolerance and largest step (the
/// fixed step of rk4), as the summary reports them.
#[derive(Debug, Clone)]
pub struct SolverSettings {
    choice: IntegratorChoice,
    /// Its name in the summary.
    pub integrator: &'static str,
    /// None for rk4.
    pub relative_tolerance: Option<f64>,
    /// Largest step, or rk4's fixed step \[s\].
    pub max_step: f64,
    /// Tolerance of the energy-balance error control; None: off (rk4, or
    /// `solver.energy_tolerance = 0`).
    pub energy_tolerance: Option<f64>,
}

impl SolverSettings {
    /// The case's choices with their defaults; `cage` and `balls` set the
    /// stiff integrator's default step.
    pub fn of(case: &Case, cage: &CageParameters, balls: usize) -> Self {
        let rtol = case
            .relative_tolerance
            .unwrap_or(DEFAULT_RELATIVE_TOLERANCE);
        // `auto` runs ros34pw2 and dopri5 each where it is cheaper: dopri5
        // was 34× dearer at 500 rpm, where the EHL traction slopes bound
        // its step, and 4× cheaper after spall impacts, where ros34pw2 must
        // resolve undamped ringing (docs/performance.md, "Accuracy at
        // default settings"). Its largest step is the stiff method's.
        let choice = case.integrator;
        let (integrator, relative_tolerance, max_step) = match choice {
            IntegratorChoice::Rk4 => ("rk4", None, case.time_step.unwrap_or(DEFAULT_RK4_STEP)),
            IntegratorChoice::Auto => (
                "auto",
                Some(rtol),
                case.max_step.unwrap_or_else(|| stiff_max_step(cage, balls)),
            ),
            IntegratorChoice::Ros34pw2 => (
                "ros34pw2",
                Some(rtol),
                case.max_step.unwrap_or_else(|| stiff_max_step(cage, balls)),
            ),
            _ => (
                "dopri5",
                Some(rtol),
                case.max_step.unwrap_or(DEFAULT_MAX_STEP),
            ),
        };
        let default_energy_tolerance = if case.surface.spalls().next().is_some() {
            SPALL_ENERGY_TOLERANCE
        } else {
            DEFAULT_ENERGY_TOLERANCE
        };
        let energy_tolerance = relative_tolerance
            .and(Some(
                case.energy_tolerance.unwrap_or(default_energy_tolerance),
            ))
            .filter(|&e| e > 0.0);
        Self {
            choice,
            integrator,
            relative_tolerance,
            max_step,
            energy_tolerance,
        }
    }

    /// The case key that sets [`Self::max_step`].
    pub fn step_key(&self) -> &'static str {
        match self.choice {
            IntegratorChoice::Rk4 => "solver.time_step",
            _ => "solver.max_step",
        }
    }

    /// The integrator, started at t = 0 from `y0`.
    pub fn build(&self, model: &impl OdeSystem, y0: &[f64]) -> Result<Solver, IntegrationError> {
        let rtol = self
            .relative_tolerance
            .unwrap_or(DEFAULT_RELATIVE_TOLERANCE);
        Ok(match self.choice {
            IntegratorChoice::Rk4 => Solver::Explicit(Box::new(
                ExplicitRk::builder(&RK4)
                    .control(StepControl::Fixed {
                        step: self.max_step,
                    })
                    .build(model, y0)?,
            )),
            IntegratorChoice::Ros34pw2 => {
                Solver::Rosenbrock(Box::new(self.stiff(model, y0, rtol, self.max_step)?))
            }
            IntegratorChoice::Auto => Solver::Switching(Box::new(Switching::new(
                self.stiff(model, y0, rtol, self.max_step)?,
                self.explicit(
                    model,
                    y0,
                    rtol * AUTO_EXPLICIT_TOLERANCE_SHARE,
                    self.max_step.min(DEFAULT_MAX_STEP),
                )?,
            ))),
            IntegratorChoice::Dopri5 => {
                Solver::Explicit(Box::new(self.explicit(model, y0, rtol, self.max_step)?))
            }
        })
    }

    /// ROS34PW2 with the energy control, if on.
    fn stiff(
        &self,
        model: &impl OdeSystem,
        y0: &[f64],
        rtol: f64,
        max_step: f64,
    ) -> Result<Rosenbrock, IntegrationError> {
        Rosenbrock::builder(&ROS34PW2)
            .relative_tolerance(rtol)
            .max_step(max_step)
            .energy_tolerance(self.energy_tolerance)
            .build(model, y0)
    }

    /// DOPRI5 with the energy control, if on.
    fn explicit(
        &self,
        model: &impl OdeSystem,
        y0: &[f64],
        rtol: f64,
        max_step: f64,
    ) -> Result<ExplicitRk, IntegrationError> {
        ExplicitRk::builder(&DOPRI5)
            .relative_tolerance(rtol)
            .max_step(max_step)
            .energy_tolerance(self.energy_tolerance)
            .build(model, y0)
    }
}
