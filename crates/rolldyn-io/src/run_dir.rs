//! The run directory: what `rolldyn run` writes, and what `report`,
//! `spectrum`, `--resume` and the Python package read back.
//!
//! ```text
//! DIR/run.json                  the run's record: case text, overrides, options (written first)
//! DIR/timeseries.parquet/       the time series, a dataset of part files (crate doc)
//! DIR/timeseries_slow.parquet/  slow channels (thermal network, spall lengths), when present
//! DIR/checkpoint.bin            state and statistics at the last checkpoint (until the run ends)
//! DIR/summary.json              the summary, rewritten at every checkpoint and at the end
//! DIR/report.html               the HTML report (`--report`, `rolldyn report`)
//! DIR/sweep.json, sweep.csv     a sweep's table (a sweep's directory instead of the above)
//! DIR/point-NNNN/               a sweep's points, each a run directory
//! ```
//!
//! A directory holds one run or one sweep: a run written into a sweep's
//! directory removes the sweep ([`RunDir::remove_sweep`]), a sweep written
//! into a run's removes the run ([`RunDir::remove_run`]), so that what a
//! report or `--resume` finds there is the last one's.
//!
//! The names are defined here once; every writer and reader of a run
//! directory goes through [`RunDir`]. Files other than the dataset are
//! written whole and atomically ([`write_atomic`]).

use crate::{InputError, OutputError, write_atomic};
use std::path::{Path, PathBuf};

/// A run directory (it need not exist yet).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RunDir {
    path: PathBuf,
}

impl RunDir {
    /// The run's record (case text, overrides, options).
    pub const RECORD: &'static str = "run.json";
    /// The checkpoint (state and statistics).
    pub const CHECKPOINT: &'static str = "checkpoint.bin";
    /// The summary.
    pub const SUMMARY: &'static str = "summary.json";
    /// The time series (a Parquet dataset: a directory of part files).
    pub const SERIES: &'static str = "timeseries.parquet";
    /// The slow channels' time series (a dataset like [`Self::SERIES`]).
    pub const SLOW_SERIES: &'static str = "timeseries_slow.parquet";
    /// The HTML report.
    pub const REPORT: &'static str = "report.html";
    /// A sweep's table as JSON.
    pub const SWEEP_JSON: &'static str = "sweep.json";
    /// A sweep's table as CSV.
    pub const SWEEP_CSV: &'static str = "sweep.csv";
    /// The start of a sweep's point directories' names (`point-` and
    /// digits).
    pub const POINT_PREFIX: &'static str = "point-";
    /// `--verify`'s run at tighter tolerances and a finer grid (a run
    /// directory of its own inside this one).
    pub const VERIFY: &'static str = "verify";
    /// `--verify`'s run with only the traction grid refined.
    pub const VERIFY_GRID: &'static str = "verify-grid";

    /// The run directory at `path`.
    pub fn new(path: impl Into<PathBuf>) -> Self {
        Self { path: path.into() }
    }

    /// The directory itself.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The path of one of the directory's files (one of the constants).
    pub fn file(&self, name: &str) -> PathBuf {
        self.path.join(name)
    }

    /// `run.json`.
    pub fn record(&self) -> PathBuf {
        self.file(Self::RECORD)
    }

    /// `checkpoint.bin`.
    pub fn checkpoint(&self) -> PathBuf {
        self.file(Self::CHECKPOINT)
    }

    /// `summary.json`.
    pub fn summary(&self) -> PathBuf {
        self.file(Self::SUMMARY)
    }

    /// The time series dataset.
    pub fn series(&self) -> PathBuf {
        self.file(Self::SERIES)
    }

    /// The slow channels' dataset.
    pub fn slow_series(&self) -> PathBuf {
        self.file(Self::SLOW_SERIES)
    }

    /// `report.html`.
    pub fn report(&self) -> PathBuf {
        self.file(Self::REPORT)
    }

    /// Whether the directory holds a summary (a run wrote it).
    pub fn has_summary(&self) -> bool {
        self.summary().is_file()
    }

    /// Whether the directory holds a sweep's table.
    pub fn has_sweep(&self) -> bool {
        self.file(Self::SWEEP_JSON).is_file()
    }

    /// Writes the summary atomically (the JSON text and a final newline).
    pub fn write_summary(&self, json: &str) -> Result<(), OutputError> {
        write_atomic(&self.summary(), (json.to_owned() + "\n").as_bytes())
    }

    /// Writes a sweep's table, `sweep.json` and `sweep.csv`, each
    /// atomically.
    pub fn write_sweep(&self, json: &str, csv: &str) -> Result<(), OutputError> {
        self.write(Self::SWEEP_JSON, json.as_bytes())?;
        self.write(Self::SWEEP_CSV, csv.as_bytes())
    }

    /// Writes one of the directory's files atomically.
    pub fn write(&self, name: &str, bytes: &[u8]) -> Result<(), OutputError> {
        write_atomic(&self.file(name), bytes)
    }

    /// Reads one of the directory's text files whole.
    pub fn read_text(&self, name: &str) -> Result<String, InputError> {
        let path = self.file(name);
        std::fs::read_to_string(&path).map_err(|source| InputError::Io {
            path: path.display().to_string(),
            source,
        })
    }

    /// Removes one of the directory's files if it is there.
    pub fn remove(&self, name: &str) -> std::io::Result<()> {
        match std::fs::remove_file(self.file(name)) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(e),
            _ => Ok(()),
        }
    }

    /// Removes the runs an earlier `--verify` made inside this directory
    /// ([`Self::VERIFY`], [`Self::VERIFY_GRID`]): a fresh run's summary
    /// would not name them, and they would be taken for its own. A
    /// directory of either name that is not a run directory (no
    /// [`Self::RECORD`] in it) is not rolldyn's and is left alone.
    pub fn remove_verify_runs(&self) -> std::io::Result<()> {
        self.remove_runs_named(|name| name == Self::VERIFY || name == Self::VERIFY_GRID)
    }

    /// Whether `name` is a sweep's point directory's name: `point-` and
    /// digits.
    pub fn is_point_name(name: &str) -> bool {
        name.strip_prefix(Self::POINT_PREFIX)
            .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
    }

    /// The directory name of point `k` of a sweep of `count` points:
    /// `point-NNNN` (at least four digits, all of the same width).
    pub fn point_name(k: usize, count: usize) -> String {
        let width = count.saturating_sub(1).to_string().len().max(4);
        format!("{}{k:0width$}", Self::POINT_PREFIX)
    }

    /// Prepares this directory for a sweep of `count` points: removes the
    /// point directories an earlier, larger sweep left that this one does
    /// not write again, and an earlier single run's files
    /// ([`Self::remove_run`]).
    pub fn remove_stale_points(&self, count: usize) -> std::io::Result<()> {
        // Ours: `point-` and the number k < count, written at this width.
        let ours = |name: &str| {
            name.strip_prefix(Self::POINT_PREFIX)
                .and_then(|n| n.parse::<usize>().ok())
                .is_some_and(|k| k < count && Self::point_name(k, count) == name)
        };
        self.remove_runs_named(|name| Self::is_point_name(name) && !ours(name))?;
        self.remove_run()
    }

    /// Removes an earlier sweep written into this directory: its tables,
    /// its report and its point run directories. A fresh run's files would
    /// otherwise sit beside them, and a report would describe the sweep.
    pub fn remove_sweep(&self) -> std::io::Result<()> {
        if !self.has_sweep() {
            return Ok(());
        }
        for name in [Self::SWEEP_JSON, Self::SWEEP_CSV, Self::REPORT] {
            self.remove(name)?;
        }
        self.remove_runs_named(Self::is_point_name)
    }

    /// Removes an earlier single run written into this directory (one with
    /// a [`Self::RECORD`]): its record, series, checkpoint, summary,
    /// report and `--verify` runs, before a sweep writes its points here.
    pub fn remove_run(&self) -> std::io::Result<()> {
        if !self.record().is_file() {
            return Ok(());
        }
        for dataset in [Self::SERIES, Self::SLOW_SERIES] {
            match std::fs::remove_dir_all(self.file(dataset)) {
                Err(e) if e.kind() != std::io::ErrorKind::NotFound => return Err(e),
                _ => {}
            }
        }
        for name in [Self::CHECKPOINT, Self::SUMMARY, Self::REPORT, Self::RECORD] {
            self.remove(name)?;
        }
        self.remove_verify_runs()
    }

    /// Removes the run directories in this directory whose names `stale`
    /// accepts (a sweep's points it does not write again, an earlier
    /// `--verify`'s runs). Only run directories (with a [`Self::RECORD`])
    /// are removed: a user's folder of such a name stays.
    pub fn remove_runs_named(&self, stale: impl Fn(&str) -> bool) -> std::io::Result<()> {
        let entries = match std::fs::read_dir(&self.path) {
            Ok(entries) => entries,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(()),
            Err(e) => return Err(e),
        };
        for entry in entries {
            let entry = entry?;
            let run = RunDir::new(entry.path());
            let named = entry.file_name().to_str().is_some_and(&stale);
            if named && run.record().is_file() {
                std::fs::remove_dir_all(run.path())?;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_atomic_summary() {
        let dir = std::env::temp_dir().join(format!("rolldyn-run-dir-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let run = RunDir::new(&dir);
        assert_eq!(run.series(), dir.join("timeseries.parquet"));
        assert_eq!(run.record(), dir.join("run.json"));
        assert!(!run.has_summary());
        run.write_summary("{}").unwrap();
        assert!(run.has_summary());
        assert_eq!(run.read_text(RunDir::SUMMARY).unwrap(), "{}\n");
        run.remove(RunDir::SUMMARY).unwrap();
        run.remove(RunDir::SUMMARY).unwrap();
        assert!(!run.has_summary());
        assert!(matches!(
            run.read_text(RunDir::SUMMARY),
            Err(InputError::Io { .. })
        ));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn an_earlier_runs_verify_runs_are_removed_and_nothing_else() {
        let dir = std::env::temp_dir().join(format!("rolldyn-verify-dirs-{}", std::process::id()));
        let run = RunDir::new(&dir);
        let verify = RunDir::new(run.file(RunDir::VERIFY));
        std::fs::create_dir_all(verify.series()).unwrap();
        verify.write(RunDir::RECORD, b"{}").unwrap();
        // A folder of the other name that rolldyn did not write.
        let other = run.file(RunDir::VERIFY_GRID);
        std::fs::create_dir_all(&other).unwrap();
        std::fs::write(other.join("notes.txt"), "mine").unwrap();
        run.remove_verify_runs().unwrap();
        assert!(!verify.path().exists());
        assert!(other.join("notes.txt").is_file());
        run.remove_verify_runs().unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_run_and_a_sweep_each_remove_the_other_from_their_directory() {
        let dir = std::env::temp_dir().join(format!("rolldyn-run-or-sweep-{}", std::process::id()));
        let run = RunDir::new(&dir);
        // An earlier sweep: tables, report, two points and a user's folder.
        std::fs::create_dir_all(&dir).unwrap();
        run.write_sweep("[]", "").unwrap();
        run.write(RunDir::REPORT, b"<html>").unwrap();
        for point in ["point-0000", "point-0001"] {
            std::fs::create_dir_all(run.file(point)).unwrap();
            RunDir::new(run.file(point))
                .write(RunDir::RECORD, b"{}")
                .unwrap();
        }
        std::fs::create_dir_all(run.file("point-notes")).unwrap();
        run.remove_sweep().unwrap();
        assert!(!run.has_sweep() && !run.file(RunDir::SWEEP_CSV).exists());
        assert!(!run.report().exists() && !run.file("point-0000").exists());
        assert!(run.file("point-notes").is_dir());
        // An earlier single run: record, series, summary, checkpoint.
        run.write(RunDir::RECORD, b"{}").unwrap();
        std::fs::create_dir_all(run.series()).unwrap();
        std::fs::write(run.series().join("part-0.parquet"), b"x").unwrap();
        run.write_summary("{}").unwrap();
        run.write(RunDir::CHECKPOINT, b"x").unwrap();
        run.remove_run().unwrap();
        for gone in [run.record(), run.series(), run.summary(), run.checkpoint()] {
            assert!(!gone.exists(), "{}", gone.display());
        }
        assert!(run.file("point-notes").is_dir());
        // Nothing of either: nothing to do.
        run.remove_run().unwrap();
        run.remove_sweep().unwrap();
        assert!(RunDir::is_point_name("point-0012") && !RunDir::is_point_name("point-"));
        assert!(!RunDir::is_point_name("point-12a") && !RunDir::is_point_name("points-1"));
        assert_eq!(RunDir::point_name(3, 12), "point-0003");
        assert_eq!(RunDir::point_name(3, 12_000), "point-00003");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
