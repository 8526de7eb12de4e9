//! `rolldyn report DIR` and `rolldyn run --report`: the self-contained
//! HTML report of a run or sweep directory (`DIR/report.html`), built by
//! the `rolldyn-report` crate. For a run the case is re-read from
//! `DIR/run.json` and described as `rolldyn check` describes it.

use crate::Failure;
use crate::checkpoint::RunRecord;
use rolldyn_io::RunDir;
use rolldyn_report::report_for;
use std::path::{Path, PathBuf};

/// The case of a run directory as `rolldyn check` describes it (None when
/// the directory has no readable `run.json`, e.g. a sweep).
fn case_description(dir: &Path) -> Option<String> {
    let record = RunRecord::read(dir).ok()?;
    let case = record
        .overrides
        .load_text(&record.source, record.case_text.as_deref())
        .ok()?;
    crate::report::CheckReport::new(&record.source, &case)
        .ok()
        .map(|r| r.to_text())
}

/// Writes `DIR/report.html` atomically; returns its path.
pub fn write(dir: &Path) -> Result<PathBuf, Failure> {
    let report =
        report_for(dir, case_description(dir)).map_err(|e| Failure::BadInput(e.to_string()))?;
    let path = RunDir::new(dir).report();
    rolldyn_io::write_atomic(&path, report.to_html().as_bytes())
        .map_err(|e| Failure::BadInput(e.to_string()))?;
    Ok(path)
}

/// After a run into `dir`: writes `DIR/report.html` when `asked`, and
/// rewrites one already there (an earlier run's, or the run's before
/// `--resume … --until`), which would otherwise describe another run.
/// Returns the path written, if any.
pub fn refresh(dir: &Path, asked: bool) -> Result<Option<PathBuf>, Failure> {
    if asked || RunDir::new(dir).report().is_file() {
        write(dir).map(Some)
    } else {
        Ok(None)
    }
}
