//! Drives an integrator to an end time, sampling the solution at a fixed
//! rate by dense output (independent of the steps), honouring a stop flag
//! (Ctrl-C) and reporting progress. Knows nothing of files or terminals:
//! samples and progress go to callbacks (observers).

use super::step_control::{IntegrationError, IntegrationStats};
use super::{Integrator, OdeSystem};
use std::sync::atomic::{AtomicBool, Ordering};

/// How a run ended.
#[derive(Debug, Clone, PartialEq)]
pub enum RunEnd {
    /// Reached the end time.
    Completed,
    /// The stop flag was raised; the samples so far are valid.
    Interrupted {
        /// Time reached \[s\].
        t: f64,
    },
    /// The integrator failed; the samples so far are valid.
    Failed {
        /// Why.
        error: IntegrationError,
    },
}

/// Result of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct RunReport {
    /// How it ended.
    pub end: RunEnd,
    /// Integrator counters.
    pub stats: IntegrationStats,
    /// Samples delivered.
    pub samples: usize,
}

/// Where a run's samples lie: at `t0 + i / sample_rate` for i = 0, 1, …;
/// `next` is the index of the next sample to deliver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sampling {
    /// Time of sample 0 (the run's start) \[s\].
    pub t0: f64,
    /// Samples per second \[Hz\].
    pub rate: f64,
    /// Index of the next sample to deliver.
    pub next: u64,
}

/// Integrates `system` with `integrator` to `t_end`, calling
/// `on_sample(system, t, y)`
/// at t0, t0 + Δ, … (Δ = 1/`sample_rate`, the last sample at or before
/// t_end) and `on_progress(t)` after each step. Stops early, cleanly, when
/// `stop` is raised.
pub fn run<S: OdeSystem, I: Integrator>(
    system: &mut S,
    integrator: &mut I,
    t_end: f64,
    sample_rate: f64,
    stop: &AtomicBool,
    mut on_sample: impl FnMut(&S, f64, &[f64]),
    mut on_progress: impl FnMut(f64),
) -> RunReport {
    let sampling = Sampling {
        t0: integrator.t(),
        rate: sample_rate,
        next: 0,
    };
    run_from(
        system,
        integrator,
        t_end,
        sampling,
        stop,
        &mut on_sample,
        |_, i: &I, _| on_progress(i.t()),
    )
}

/// Integrates from the integrator's current point to `t_end`, delivering
/// the samples of `sampling` from index `sampling.next` on (those at or
/// before the current time first: sample 0 of a fresh run). After each
/// accepted step `on_step(system, integrator, next)` sees the whole state
/// and the index of the next sample: between two calls nothing else
/// changes, so a checkpoint taken there and restored with
/// `Sampling { next, .. }` continues the run bit for bit.
pub fn run_from<S: OdeSystem, I: Integrator>(
    system: &mut S,
    integrator: &mut I,
    t_end: f64,
    sampling: Sampling,
    stop: &AtomicBool,
    mut on_sample: impl FnMut(&S, f64, &[f64]),
    mut on_step: impl FnMut(&S, &I, u64),
) -> RunReport {
    let dt = 1.0 / sampling.rate;
    let mut buffer = vec![0.0; system.dimension()];
    let mut index = sampling.next;
    let mut samples = 0usize;
    let sample_time = |i: u64| sampling.t0 + i as f64 * dt;
    // Samples due at the current point (sample 0 of a fresh run).
    while sample_time(index) <= integrator.t() * (1.0 + 1e-15)
        && sample_time(index) <= t_end * (1.0 + 1e-12)
    {
        if sample_time(index) == integrator.t() {
            on_sample(system, sample_time(index), integrator.y());
        } else {
            integrator.interpolate(sample_time(index), &mut buffer);
            on_sample(system, sample_time(index), &buffer);
        }
        samples += 1;
        index += 1;
    }
    let end = loop {
        if integrator.t() >= t_end {
            break RunEnd::Completed;
        }
        if stop.load(Ordering::Relaxed) {
            break RunEnd::Interrupted { t: integrator.t() };
        }
        if let Err(error) = integrator.step(system, t_end) {
            break RunEnd::Failed { error };
        }
        while sample_time(index) <= integrator.t() * (1.0 + 1e-15)
            && sample_time(index) <= t_end * (1.0 + 1e-12)
        {
            integrator.interpolate(sample_time(index), &mut buffer);
            on_sample(system, sample_time(index), &buffer);
            samples += 1;
            index += 1;
        }
        on_step(system, integrator, index);
    };
    RunReport {
        end,
        stats: integrator.stats(),
        samples,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrate::tableau::DOPRI5;
    use crate::integrate::test_systems::Decay;
    use crate::integrate::{ExplicitRk, StepControl};

    #[test]
    fn samples_on_the_grid_independent_of_steps() {
        let mut sys = Decay;
        let control = StepControl::Adaptive {
            relative_tolerance: 1e-9,
            max_step: 0.37,
            initial_step: None,
        };
        let mut rk = ExplicitRk::builder(&DOPRI5)
            .control(control)
            .build(&sys, &[1.0])
            .unwrap();
        let mut got = Vec::new();
        let stop = AtomicBool::new(false);
        let report = run(
            &mut sys,
            &mut rk,
            2.0,
            10.0,
            &stop,
            |_, t, y| got.push((t, y[0])),
            |_| {},
        );
        assert_eq!(report.end, RunEnd::Completed);
        assert_eq!(got.len(), 21);
        for (i, (t, y)) in got.iter().enumerate() {
            assert!((t - 0.1 * i as f64).abs() < 1e-12);
            assert!((y - (-t).exp()).abs() < 1e-8, "t {t}: {y}");
        }
    }

    #[test]
    fn stop_flag_ends_cleanly() {
        let mut sys = Decay;
        let control = StepControl::Fixed { step: 0.01 };
        let mut rk = ExplicitRk::builder(&crate::integrate::tableau::RK4)
            .control(control)
            .build(&sys, &[1.0])
            .unwrap();
        let stop = AtomicBool::new(false);
        let mut n = 0;
        let report = run(
            &mut sys,
            &mut rk,
            10.0,
            100.0,
            &stop,
            |_, _, _| n += 1,
            |t| {
                if t > 1.0 {
                    stop.store(true, Ordering::Relaxed);
                }
            },
        );
        assert!(matches!(report.end, RunEnd::Interrupted { t } if t > 1.0 && t < 1.1));
        assert_eq!(n, report.samples);
        assert!(report.samples >= 100);
    }
}
