//! `[solver]` and the output sample rate: a run's duration, tolerances,
//! step limits, integrator and start (docs/case-format.md).

use super::{Invalid, checked, positive, positive_number};
use crate::raw::{IntegratorChoice, RawCase, StartChoice};

/// The checked `[solver]` section and `output.sample_rate`.
pub(super) struct Solver {
    pub(super) duration: Option<f64>,
    pub(super) max_step: Option<f64>,
    pub(super) relative_tolerance: Option<f64>,
    pub(super) energy_tolerance: Option<f64>,
    pub(super) sample_rate: Option<f64>,
    pub(super) time_step: Option<f64>,
    pub(super) integrator: IntegratorChoice,
    pub(super) start: StartChoice,
}

/// Checks `[solver]` and `output.sample_rate`.
pub(super) fn solver(raw: &RawCase) -> Result<Solver, Invalid> {
    let s = &raw.solver;
    // Practical limits (docs/case-format.md): below them a run cannot
    // finish (steps at round-off) or cannot be stored.
    let at_least = |min: f64, what: &'static str| {
        move |v: f64| {
            if v >= min {
                Ok(())
            } else {
                Err(format!("must be at least {what}"))
            }
        }
    };
    let duration = checked("solver.duration", &s.duration, positive)?;
    let max_step = checked("solver.max_step", &s.max_step, at_least(1e-9, "1 ns"))?;
    let relative_tolerance = positive_number(
        "solver.relative_tolerance",
        s.relative_tolerance,
        |x| (1e-12..=0.5).contains(&x),
        "must lie in [1e-12, 0.5] (below 1e-12 the steps stall at round-off)",
    )?;
    let energy_tolerance = positive_number(
        "solver.energy_tolerance",
        s.energy_tolerance,
        |x| x == 0.0 || (1e-9..=0.1).contains(&x),
        "must be 0 (off) or lie in [1e-9, 0.1]",
    )?;
    let sample_rate = checked("output.sample_rate", &raw.output.sample_rate, |v| {
        if v > 0.0 && v <= 1e7 {
            Ok(())
        } else {
            Err("must lie in (0, 10 MHz]".to_string())
        }
    })?;
    let time_step = checked("solver.time_step", &s.time_step, at_least(1e-10, "0.1 ns"))?;
    let integrator = s.integrator.unwrap_or(IntegratorChoice::Auto);
    if integrator == IntegratorChoice::Rk4 && time_step.is_none() {
        return Err(Invalid::missing(
            "solver.time_step",
            "the rk4 integrator needs a fixed step, e.g. \"0.5 us\"",
        ));
    }
    Ok(Solver {
        duration,
        max_step,
        relative_tolerance,
        energy_tolerance,
        sample_rate,
        time_step,
        integrator,
        start: s.start.unwrap_or(StartChoice::JonesHarris),
    })
}
