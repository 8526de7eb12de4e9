//! The run pipeline: one driver for every dynamic run, of one bearing
//! (`run`), a bearing set or a shaft (`run_set`). The driver integrates
//! with `rolldyn::integrate::run_from` and owns what every run does the
//! same way: the stop flag (Ctrl-C, a sweep's shared flag, a part that
//! could not be written), the progress bar and the progress a caller
//! polls, the checkpoint cadence (the interval asked, and at least 50
//! times what the last checkpoint took), and the final write with the
//! position a resumed run continues from. What a run records and writes
//! is its [`Recorder`]: the driver calls it at every sample, at
//! checkpoints and at the end.
//!
//! The shape is that of an event loop with its handler (rapier's physics
//! pipeline and event handler, diffsol's solver loop and callbacks): the
//! loop is written once, the runs differ only in their handlers.

use crate::Failure;
use crate::checkpoint::{Position, RunRecord};
use crate::run_options::{CHECKPOINT_COST_FACTOR, RunOptions};
use indicatif::{ProgressBar, ProgressStyle};
use rolldyn::integrate::{
    IntegrationError, Integrator, OdeSystem, RunEnd, Sampling, Solver, run_from,
};
use rolldyn_io::RunDir;
use std::cell::RefCell;
use std::io::IsTerminal;
use std::path::Path;
use std::sync::atomic::Ordering;
use std::time::Instant;

/// What a run records of its samples and writes at checkpoints and at its
/// end.
pub trait Recorder<S> {
    /// The summary written at checkpoints and at the end.
    type Summary;
    /// Records the sample at time `t` (state `y`). Returns false when the
    /// run must stop (its time series cannot be written; the error is
    /// [`Recorder::take_write_error`]'s).
    fn sample(&mut self, system: &S, t: f64, y: &[f64]) -> bool;
    /// The error that stopped the recording, if one did.
    fn take_write_error(&mut self) -> Option<String>;
    /// A limit the recorded state has passed (the run then stops and
    /// ends `failed` with this reason); None while within.
    fn limit(&self) -> Option<String> {
        None
    }
    /// Rows of the time series recorded so far.
    fn rows(&self) -> u64;
    /// Writes the time series' rows not yet on disk, the checkpoint (when
    /// `position` is given) and the summary, each atomically, in that
    /// order; `end` is None for a checkpoint during the run.
    fn write(
        &mut self,
        system: &S,
        solver: &Solver,
        end: Option<&RunEnd>,
        position: Option<Position>,
        wall: f64,
    ) -> Result<Self::Summary, Failure>;
}

/// Where a run starts: a fresh run at sample 0, a resumed one where its
/// checkpoint left it.
#[derive(Debug, Clone, Copy, Default)]
pub struct Start {
    /// Index of the next sample to record.
    pub next_sample: u64,
    /// Wall time spent before (a resumed run's) \[s\].
    pub wall_before: f64,
}

impl From<Position> for Start {
    fn from(p: Position) -> Self {
        Self {
            next_sample: p.next_sample,
            wall_before: p.wall_time,
        }
    }
}

/// Prepares `dir` for a fresh run: created, an older run's checkpoint
/// removed (it is no longer valid), and the runs its `--verify` made, an
/// earlier sweep's tables and points removed, the run's record written.
pub fn fresh_dir(dir: &Path, record: &RunRecord) -> Result<(), Failure> {
    let bad = Failure::BadInput;
    std::fs::create_dir_all(dir)
        .map_err(|e| bad(format!("cannot create {}: {e}", dir.display())))?;
    let run_dir = RunDir::new(dir);
    run_dir.remove(RunDir::CHECKPOINT).map_err(|e| {
        bad(format!(
            "cannot remove {}: {e}",
            run_dir.checkpoint().display()
        ))
    })?;
    run_dir.remove_verify_runs().map_err(|e| {
        bad(format!(
            "cannot remove an earlier run's {} or {} in {}: {e}",
            RunDir::VERIFY,
            RunDir::VERIFY_GRID,
            dir.display()
        ))
    })?;
    run_dir.remove_sweep().map_err(|e| {
        bad(format!(
            "cannot remove an earlier sweep's tables and points in {}: {e}",
            dir.display()
        ))
    })?;
    let text = record.to_json().map_err(Failure::Internal)?;
    run_dir
        .write(RunDir::RECORD, text.as_bytes())
        .map_err(|e| bad(e.to_string()))
}

/// The progress bar of a run on a terminal (none when `quiet`).
fn progress_bar(quiet: bool) -> Option<ProgressBar> {
    (!quiet && std::io::stderr().is_terminal()).then(|| {
        let bar = ProgressBar::new(1000);
        bar.set_style(
            ProgressStyle::with_template(
                "{spinner} [{elapsed_precise}] {wide_bar} {msg} ETA {eta}",
            )
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
        );
        bar
    })
}

/// Runs `system` with `solver` to `duration`, sampling at `sample_rate`
/// from `start`, with `recorder` recording and writing. Returns the
/// summary of the final write; `Err` when a checkpoint or the time series
/// could not be written (the checkpoint before, if any, resumes the run).
pub fn drive<S: OdeSystem, R: Recorder<S>>(
    system: &mut S,
    solver: &mut Solver,
    duration: f64,
    sample_rate: f64,
    start: Start,
    options: &RunOptions,
    recorder: R,
) -> Result<R::Summary, Failure> {
    let stop = options.stop_flag();
    let bar = progress_bar(options.quiet);
    let recorder = RefCell::new(recorder);
    let begun = Instant::now();
    let wall = || start.wall_before + begun.elapsed().as_secs_f64();
    let mut last_draw = 0.0;
    // A fresh run delivers sample 0 before its first step.
    let mut next_sample = start.next_sample + u64::from(!options.resume);
    let mut last_checkpoint = Instant::now();
    let mut checkpoint_cost = 0.0;
    let mut checkpoint_error = None;
    let sampling = Sampling {
        t0: 0.0,
        rate: sample_rate,
        next: start.next_sample,
    };
    let report = run_from(
        system,
        solver,
        duration,
        sampling,
        &stop,
        |s, t, y| {
            let mut recorder = recorder.borrow_mut();
            if !recorder.sample(s, t, y) || recorder.limit().is_some() {
                stop.store(true, Ordering::Relaxed);
            }
        },
        |s, solver, next| {
            next_sample = next;
            let t = solver.t();
            if t - last_draw >= duration / 1000.0 {
                last_draw = t;
                if let Some(bar) = &bar {
                    bar.set_position((1000.0 * t / duration) as u64);
                    bar.set_message(format!("t = {t:.4} s"));
                }
                if let Some(progress) = &options.progress {
                    progress.store((t / duration).to_bits(), Ordering::Relaxed);
                }
            }
            let since = last_checkpoint.elapsed().as_secs_f64();
            if checkpoint_error.is_none()
                && since
                    >= options
                        .checkpoint_interval
                        .max(CHECKPOINT_COST_FACTOR * checkpoint_cost)
            {
                let begun = Instant::now();
                let wall = wall();
                let mut recorder = recorder.borrow_mut();
                let position = Position {
                    next_sample: next,
                    rows: recorder.rows(),
                    wall_time: wall,
                };
                checkpoint_error = recorder.write(s, solver, None, Some(position), wall).err();
                checkpoint_cost = begun.elapsed().as_secs_f64();
                last_checkpoint = Instant::now();
            }
        },
    );
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    if let Some(e) = checkpoint_error {
        return Err(e);
    }
    let wall = wall();
    let mut recorder = recorder.into_inner();
    if let Some(e) = recorder.take_write_error() {
        return Err(Failure::BadInput(format!(
            "{e}; the run stopped at t = {:.6} s (the checkpoint before it, if any, resumes it)",
            solver.t()
        )));
    }
    // A state beyond the models' range ends the run as failed.
    let end = match recorder.limit() {
        Some(reason) => RunEnd::Failed {
            error: IntegrationError::Limit {
                t: solver.t(),
                reason,
            },
        },
        None => report.end,
    };
    // An interrupted or completed run keeps a checkpoint at its last step
    // (to continue, or to extend with `--until`); a failed one keeps its
    // last periodic checkpoint.
    let position = (!matches!(end, RunEnd::Failed { .. })).then(|| Position {
        next_sample,
        rows: recorder.rows(),
        wall_time: wall,
    });
    let summary = recorder.write(system, solver, Some(&end), position, wall)?;
    if let Some(progress) = &options.progress {
        progress.store(
            (solver.t().min(duration) / duration).to_bits(),
            Ordering::Relaxed,
        );
    }
    Ok(summary)
}
