//! Nothing lost: the files that let `rolldyn run --resume DIR` continue
//! an interrupted run bit-identically.
//!
//! * `DIR/run.json` ([`RunRecord`]): how the run was asked for — the case
//!   text as read (not its path: the file may change), the command-line
//!   overrides and `--force`. Written once, before the integration starts.
//! * `DIR/checkpoint.bin`: the integrator's and the model's complete state
//!   ([`rolldyn::integrate::Checkpoint`]), the index of the next sample,
//!   the number of rows of `timeseries.parquet` that belong to it and the
//!   wall time so far, tied to `run.json` by a hash.
//!
//! A checkpoint writes the rows of `timeseries.parquet` not yet on disk
//! (the dataset's last, growing part: [`rolldyn_io::SeriesWriter::sync`]),
//! `checkpoint.bin` and `summary.json` (status `partial`), each
//! atomically and in that order: after a kill at any moment the dataset
//! holds at least the checkpoint's rows, and a resume keeps exactly those
//! and replays them into the summary's statistics.

use crate::Failure;
use crate::run_options::RunOptions;
use crate::run_stats::RunStatistics;
use rolldyn::dynamics::BearingModel;
use rolldyn::integrate::{Checkpoint, Solver, StateReader, StateWriter};
use rolldyn_io::RunDir;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// Version of `run.json` and `checkpoint.bin` (2: with the summary's
/// statistics; 3: with the fast part's Jacobian refresh and the ball
/// passages; 4: the rings' displacements, not velocities, in the kept
/// vibration signal).
const FORMAT: u64 = 4;
/// First part of a checkpoint.
const TAG: &str = "rolldyn-run-checkpoint";

/// `run.json`: how a run was asked for.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct RunRecord {
    /// File format version.
    pub format: u64,
    /// rolldyn version that started the run.
    pub rolldyn_version: String,
    /// Where the case came from (file name, `<stdin>`, built-in default).
    pub source: String,
    /// The case text as read; null for the built-in default case.
    pub case_text: Option<String>,
    /// Command-line overrides in the order applied (`--speed`, `--set`, …).
    pub overrides: crate::CaseOverrides,
    /// Whether the run was started with `--force`.
    pub force: bool,
}

impl RunRecord {
    /// A record of a new run.
    pub fn new(
        source: String,
        case_text: Option<String>,
        overrides: crate::CaseOverrides,
        force: bool,
    ) -> Self {
        Self {
            format: FORMAT,
            rolldyn_version: env!("CARGO_PKG_VERSION").to_string(),
            source,
            case_text,
            overrides,
            force,
        }
    }

    /// The record's JSON text.
    pub fn to_json(&self) -> Result<String, String> {
        serde_json::to_string_pretty(self)
            .map(|t| t + "\n")
            .map_err(|e| e.to_string())
    }

    /// Reads `DIR/run.json`.
    pub fn read(dir: &Path) -> Result<Self, String> {
        let path = RunDir::new(dir).record();
        let text = std::fs::read_to_string(&path).map_err(|e| {
            format!(
                "--resume {}: cannot read {}: {e} (only a directory written by `rolldyn run` can be resumed)",
                dir.display(),
                path.display()
            )
        })?;
        let record: Self = serde_json::from_str(&text).map_err(|e| {
            format!(
                "--resume {}: {} is not a run record: {e}",
                dir.display(),
                path.display()
            )
        })?;
        if record.format != FORMAT {
            let this = env!("CARGO_PKG_VERSION");
            // Builds of one version can differ in format: name the build
            // then, not the version twice.
            let (writer, reader) = if record.rolldyn_version == this {
                (format!("another build of rolldyn {this}"), "this build")
            } else {
                (
                    format!("rolldyn {}", record.rolldyn_version),
                    "this rolldyn",
                )
            };
            return Err(format!(
                "--resume {}: run record format {} written by {writer} ({reader} reads format {FORMAT}); resume it with the build that started it, or run the case again",
                dir.display(),
                record.format,
            ));
        }
        Ok(record)
    }

    /// A hash of the record that ties a checkpoint to it (FNV-1a of the
    /// JSON text).
    pub fn hash(&self) -> u64 {
        let text = self.to_json().unwrap_or_default();
        text.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
            (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
        })
    }
}

/// Where a checkpoint leaves the run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Position {
    /// Index of the next sample.
    pub next_sample: u64,
    /// Rows of the time series that belong to the checkpoint.
    pub rows: u64,
    /// Wall time spent so far \[s\].
    pub wall_time: f64,
}

/// The bytes of a checkpoint.
pub fn encode(
    record_hash: u64,
    position: Position,
    solver: &Solver,
    model: &BearingModel,
    stats: &RunStatistics,
) -> Vec<u8> {
    encode_parts(record_hash, position, solver, model, &[stats], &[])
}

/// The bytes of a checkpoint of any system: its state (`model`), one
/// statistics accumulator per recorded part, and `extra` numbers the run
/// accumulates itself (none for one bearing: the format stays as it was).
pub fn encode_parts(
    record_hash: u64,
    position: Position,
    solver: &Solver,
    model: &dyn Checkpoint,
    stats: &[&RunStatistics],
    extra: &[f64],
) -> Vec<u8> {
    let mut w = StateWriter::new();
    w.tag(TAG);
    w.u64(FORMAT);
    w.u64(record_hash);
    w.u64(position.next_sample);
    w.u64(position.rows);
    w.f64(position.wall_time);
    solver.save(&mut w);
    model.save(&mut w);
    for s in stats {
        s.save(&mut w);
    }
    if !extra.is_empty() {
        w.f64s(extra);
    }
    w.into_bytes()
}

/// Writes a run's checkpoint (when given) and then its `summary.json`,
/// each atomically, in that order: a summary never describes a checkpoint
/// that is not there yet.
pub fn persist(
    dir: &Path,
    checkpoint: Option<Vec<u8>>,
    summary: &impl serde::Serialize,
) -> Result<(), Failure> {
    let bad = |e: rolldyn_io::OutputError| Failure::BadInput(e.to_string());
    if let Some(bytes) = checkpoint {
        RunDir::new(dir)
            .write(RunDir::CHECKPOINT, &bytes)
            .map_err(bad)?;
    }
    let json = crate::finite::to_json(summary).map_err(|e| Failure::Internal(e.to_string()))?;
    RunDir::new(dir).write_summary(&json).map_err(bad)
}

/// Restores `solver` and `model` (built from the same record) from
/// `DIR/checkpoint.bin`; returns where it leaves the run.
pub fn restore(
    dir: &Path,
    record_hash: u64,
    solver: &mut Solver,
    model: &mut BearingModel,
    stats: &mut RunStatistics,
) -> Result<Position, String> {
    restore_parts(dir, record_hash, solver, model, &mut [stats], &mut [])
}

/// [`restore`] of a checkpoint written by [`encode_parts`] (the same
/// number of statistics and extras).
pub fn restore_parts(
    dir: &Path,
    record_hash: u64,
    solver: &mut Solver,
    model: &mut dyn Checkpoint,
    stats: &mut [&mut RunStatistics],
    extra: &mut [f64],
) -> Result<Position, String> {
    let path = RunDir::new(dir).checkpoint();
    let bytes = std::fs::read(&path).map_err(|e| {
        format!(
            "--resume {}: cannot read {}: {e} (a completed run has none)",
            dir.display(),
            path.display()
        )
    })?;
    let bad = |e: rolldyn::integrate::CheckpointError| {
        format!("--resume {}: {}: {e}", dir.display(), path.display())
    };
    let mut r = StateReader::new(&bytes);
    r.tag(TAG).map_err(bad)?;
    if r.u64().map_err(bad)? != FORMAT {
        return Err(format!(
            "--resume {}: checkpoint of another format",
            dir.display()
        ));
    }
    if r.u64().map_err(bad)? != record_hash {
        return Err(format!(
            "--resume {}: {} does not belong to {} (changed since the checkpoint)",
            dir.display(),
            path.display(),
            RunDir::RECORD
        ));
    }
    let position = Position {
        next_sample: r.u64().map_err(bad)?,
        rows: r.u64().map_err(bad)?,
        wall_time: r.f64().map_err(bad)?,
    };
    solver.restore(&mut r).map_err(bad)?;
    model.restore(&mut r).map_err(bad)?;
    for s in stats.iter_mut() {
        s.restore(&mut r).map_err(bad)?;
    }
    if !extra.is_empty() {
        r.f64s_into("the run's accumulators", extra).map_err(bad)?;
    }
    if !r.is_done() {
        return Err(format!(
            "--resume {}: {} has trailing bytes",
            dir.display(),
            path.display()
        ));
    }
    Ok(position)
}

/// Refuses, before any model is built, to resume a run whose summary
/// says it completed (its time is reached; `--until` extends it): the
/// refusal [`continue_to`] gives after the restore, without the cost of
/// building the model (a set's quasi-static start). Runs that did not
/// complete, and extensions, go on to the restore.
pub fn refuse_completed(dir: &Path, options: &RunOptions, duration: f64) -> Result<(), Failure> {
    if !options.resume || options.extends.is_some() {
        return Ok(());
    }
    let summary: Option<serde_json::Value> = RunDir::new(dir)
        .read_text(RunDir::SUMMARY)
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok());
    let reached = summary
        .as_ref()
        .filter(|s| s["status"] == "completed")
        .and_then(|s| s["simulated_time_s"].as_f64());
    match reached {
        Some(reached) if reached >= duration => Err(Failure::BadInput(format!(
            "--resume {}: the run is complete (t = {reached} s); `--until T` extends it",
            dir.display()
        ))),
        _ => Ok(()),
    }
}

/// Whether a run restored at time `reached` may go on to `duration`: a
/// resumed run must not be complete, an extended one (`--until`) must
/// go beyond; an extension's checkpoints belong to the extended record
/// from now on, so `DIR/run.json` is written again.
pub fn continue_to(
    record: &RunRecord,
    options: &RunOptions,
    dir: &Path,
    reached: f64,
    duration: f64,
) -> Result<(), Failure> {
    let bad = Failure::BadInput;
    match options.extends {
        Some(_) if reached >= duration => Err(bad(format!(
            "--until {duration} s: the run in {} is already at t = {reached} s; extend it beyond that",
            dir.display()
        ))),
        Some(_) => {
            let text = record.to_json().map_err(Failure::Internal)?;
            RunDir::new(dir)
                .write(RunDir::RECORD, text.as_bytes())
                .map_err(|e| bad(e.to_string()))
        }
        None if reached >= duration => Err(bad(format!(
            "--resume {}: the run is complete (t = {reached} s); `--until T` extends it",
            dir.display()
        ))),
        None => Ok(()),
    }
}
