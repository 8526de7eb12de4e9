//! The integrator of a run: `solver.integrator` resolved (`auto` picks by
//! tolerance), its relative tolerance and largest step with their
//! defaults, and its construction. The stiff integrator's default step
//! resolves the cage's undamped film modes (docs/dynamics.md).

use rolldyn::cage::CageParameters;
use rolldyn::dynamics::BearingModel;
use rolldyn::integrate::tableau::{DOPRI5, RK4};
use rolldyn::integrate::{ExplicitRk, IntegrationError, ROS34PW2, Rosenbrock, Solver, StepControl};
use rolldyn_case::Case;
use rolldyn_case::raw::IntegratorChoice;

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
/// Default relative tolerance of the adaptive integrators.
pub const DEFAULT_RELATIVE_TOLERANCE: f64 = 1e-3;
/// `integrator = "auto"` takes ros34pw2 at relative tolerances from this
/// value up and dopri5 below it: the measured crossover on the benchmark
/// cases (docs/performance.md), where dopri5 is stability-bound and
/// ros34pw2 accuracy-bound.
pub const STIFF_FROM_TOLERANCE: f64 = 3e-4;

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

/// The integrator a run uses, with its tolerance and largest step (the
/// fixed step of rk4), as the summary reports them.
pub(crate) struct SolverSettings {
    choice: IntegratorChoice,
    /// Its name in the summary.
    pub(crate) integrator: &'static str,
    /// None for rk4.
    pub(crate) relative_tolerance: Option<f64>,
    /// Largest step, or rk4's fixed step \[s\].
    pub(crate) max_step: f64,
}

impl SolverSettings {
    /// The case's choices with their defaults; `cage` and `balls` set the
    /// stiff integrator's default step.
    pub(crate) fn of(case: &Case, cage: &CageParameters, balls: usize) -> Self {
        let rtol = case
            .relative_tolerance
            .unwrap_or(DEFAULT_RELATIVE_TOLERANCE);
        let choice = match case.integrator {
            IntegratorChoice::Auto if rtol >= STIFF_FROM_TOLERANCE => IntegratorChoice::Ros34pw2,
            IntegratorChoice::Auto => IntegratorChoice::Dopri5,
            other => other,
        };
        let (integrator, relative_tolerance, max_step) = match choice {
            IntegratorChoice::Rk4 => ("rk4", None, case.time_step.unwrap_or(DEFAULT_RK4_STEP)),
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
        Self {
            choice,
            integrator,
            relative_tolerance,
            max_step,
        }
    }

    /// The case key that sets [`Self::max_step`].
    pub(crate) fn step_key(&self) -> &'static str {
        match self.choice {
            IntegratorChoice::Rk4 => "solver.time_step",
            _ => "solver.max_step",
        }
    }

    /// The integrator, started at t = 0 from `y0`.
    pub(crate) fn build(
        &self,
        model: &BearingModel,
        y0: &[f64],
    ) -> Result<Solver, IntegrationError> {
        let rtol = self
            .relative_tolerance
            .unwrap_or(DEFAULT_RELATIVE_TOLERANCE);
        Ok(match self.choice {
            IntegratorChoice::Rk4 => Solver::Explicit(Box::new(ExplicitRk::new(
                &RK4,
                StepControl::Fixed {
                    step: self.max_step,
                },
                model,
                0.0,
                y0,
            )?)),
            IntegratorChoice::Ros34pw2 => Solver::Rosenbrock(Box::new(Rosenbrock::new(
                &ROS34PW2,
                rtol,
                self.max_step,
                None,
                model,
                0.0,
                y0,
            )?)),
            _ => Solver::Explicit(Box::new(ExplicitRk::new(
                &DOPRI5,
                StepControl::Adaptive {
                    relative_tolerance: rtol,
                    max_step: self.max_step,
                    initial_step: None,
                },
                model,
                0.0,
                y0,
            )?)),
        })
    }
}
