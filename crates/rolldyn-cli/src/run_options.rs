//! How a run runs: its options (checkpoints, stop flag, progress,
//! `--verify`), and the limits a run is refused beyond without `--force`.
//! Shared by the single-bearing driver (`run`) and the set and shaft
//! driver (`run_set`).

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

pub use rolldyn_case::case::DEFAULT_SAMPLE_RATE;

/// Most steps a run may need at least (duration / largest step) before
/// it is refused without `--force`.
pub const MAX_STEPS: f64 = 1e9;
/// Most disk space the recorded samples may take (uncompressed; Parquet's
/// compression usually halves it) before a run is refused without
/// `--force` \[bytes\]. The series is written as the run goes, so this
/// guards the disk against a mistyped sample rate, not the memory.
pub const MAX_SERIES_BYTES: f64 = 32.0 * 1024.0 * 1024.0 * 1024.0;

/// Largest Hertz pressure a run accepts without `--force` \[Pa\]: 2.4 times
/// ISO 76's static limit for ball bearings (4.2 GPa, permanent deformation
/// of 10⁻⁴ D), i.e. 13.5 times the load at that limit. Beyond it no bearing
/// steel or ceramic carries the load elastically, the Hertz and EHL models
/// do not apply, and the stiff contacts make the integration crawl.
pub const MAX_CONTACT_PRESSURE: f64 = 10e9;

/// The largest shaft speed a run may reach \[rpm\]: the case's input limit
/// (`rolldyn_case::case::MAX_SPEED`).
pub const MAX_SPEED_RPM: f64 = rolldyn_case::case::MAX_SPEED * 60.0 / std::f64::consts::TAU;

/// The limit a driven ring's speed `speed_rpm` has passed, if it has:
/// the ±10⁶ rpm a case accepts holds during the run too (the run's end
/// names the time).
pub fn speed_limit(speed_rpm: f64) -> Option<String> {
    (speed_rpm.abs() > MAX_SPEED_RPM || speed_rpm.is_nan()).then(|| {
        format!(
            "the inner ring turns at {speed_rpm:.4e} rpm, beyond the ±{MAX_SPEED_RPM:.0e} rpm a case may give (a drive torque too large for the rotor's inertia, or a run-away)"
        )
    })
}

/// The hottest a part of a thermally coupled run may become \[°C\]: the
/// highest of the common bearing steels' maximum operating temperatures
/// (AISI M50 315 °C; AISI 52100 177 °C; Harris & Kotzalas 2006,
/// *Essential Concepts*, bearing steels). Beyond it no steel bearing
/// keeps its hardness and the oil's viscosity law is far outside its
/// data: the run has run away (or starts from a case no bearing runs at).
pub const MAX_RUN_TEMPERATURE_C: f64 = 315.0;

/// The limit the hottest of a coupled run's part temperatures
/// `temperatures_c` (node name, °C) has passed, if it has.
pub fn temperature_limit<'a>(
    temperatures_c: impl Iterator<Item = (&'a str, f64)>,
) -> Option<String> {
    let (node, hottest) = temperatures_c
        .map(|(node, c)| (node, if c.is_nan() { f64::INFINITY } else { c }))
        .max_by(|a, b| a.1.total_cmp(&b.1))?;
    (hottest > MAX_RUN_TEMPERATURE_C).then(|| {
        format!(
            "the {node} is at {hottest:.1} °C, beyond the {MAX_RUN_TEMPERATURE_C:.0} °C no steel bearing runs at (M50's maximum operating temperature): a thermal run-away, or a case hotter than any bearing runs"
        )
    })
}

/// Refuses a run that cannot finish or whose time series cannot fit:
/// at least `duration / step` steps, `duration × rate` rows of `channels`.
pub fn check_limits(
    duration: f64,
    step: f64,
    step_key: &str,
    rate: f64,
    channels: usize,
) -> Result<(), String> {
    let steps = duration / step;
    if steps > MAX_STEPS {
        return Err(format!(
            "{step_key}: the run needs at least {steps:.2e} steps (solver.duration / {step_key}), above the limit of {MAX_STEPS:.0e}; shorten the run, raise the step, or pass --force"
        ));
    }
    let bytes = (duration * rate + 1.0) * channels as f64 * 8.0;
    if bytes > MAX_SERIES_BYTES {
        return Err(format!(
            "output.sample_rate: the time series would take {:.1} GiB on disk before compression ({:.2e} rows × {channels} channels), above the limit of {:.0} GiB; lower the sample rate, shorten the run, or pass --force",
            bytes / 1024f64.powi(3),
            duration * rate + 1.0,
            MAX_SERIES_BYTES / 1024f64.powi(3)
        ));
    }
    Ok(())
}

/// Wall time between checkpoints when `--checkpoint-interval` is not
/// given \[s\].
pub const DEFAULT_CHECKPOINT_INTERVAL: f64 = 30.0;
/// A checkpoint waits at least this many times as long as the last one
/// took, so that checkpoints cost at most ~2 % of a run.
pub const CHECKPOINT_COST_FACTOR: f64 = 50.0;

/// How `run_case` runs.
#[derive(Debug, Clone, Default)]
pub struct RunOptions {
    /// Skip the step and memory limits.
    pub force: bool,
    /// Wall time between checkpoints \[s\].
    pub checkpoint_interval: f64,
    /// Continue from `DIR/checkpoint.bin` instead of starting.
    pub resume: bool,
    /// With `resume`: the run is extended (`--until`); the checkpoint
    /// belongs to the record of this hash (the record before the new
    /// duration), and the extended record replaces `DIR/run.json`.
    pub extends: Option<u64>,
    /// The flag that stops the run (a sweep shares one among its points);
    /// None: a Ctrl-C handler of its own.
    pub stop: Option<Arc<AtomicBool>>,
    /// No progress bar (a sweep draws one for all its points).
    pub quiet: bool,
    /// Where the run reports its progress: the fraction of the duration
    /// simulated, as `f64::to_bits` (the Python package reads it from
    /// another thread for its progress callback).
    pub progress: Option<Arc<AtomicU64>>,
    /// After a completed run, run the case again into `DIR/verify/` at ten
    /// times tighter tolerances and a two-fold finer traction grid, and
    /// report the changes in the summary's `accuracy.verify`.
    pub verify: bool,
    /// Keep the pool's other threads waiting actively while the run
    /// integrates, when its passes over the balls run in parallel
    /// ([`rolldyn::threads`]): for a run that has the pool to itself (one
    /// `rolldyn run`), never for the points of a sweep, which share it.
    pub active_helpers: bool,
}

impl RunOptions {
    /// The flag that stops the run: the given one, or a new one raised by
    /// Ctrl-C.
    pub fn stop_flag(&self) -> Arc<AtomicBool> {
        match &self.stop {
            Some(stop) => stop.clone(),
            None => {
                let stop = Arc::new(AtomicBool::new(false));
                let handler = stop.clone();
                // A second handler cannot be installed in the same process; ignore.
                let _ = ctrlc::set_handler(move || handler.store(true, Ordering::Relaxed));
                stop
            }
        }
    }
}
