//! `rolldyn run CASE --sweep speed=… --sweep axial=… -o DIR`: dynamic
//! runs over a grid (first `--sweep` outermost, as `quasistatic
//! --sweep`), in parallel on the machine's cores. Besides the operating
//! point (`speed`, `axial`, `radial`: ranges or lists with units), any
//! case key takes a list of values as `--set` reads them
//! (`--sweep "surface.outer.spall.0.length=0.18 mm,0.36 mm"`); its values
//! label the rows (a labelled dataset of runs). Each point is an
//! ordinary run directory `DIR/point-NNNN/` (its `run.json` holds the
//! point's overrides, so `rolldyn run --resume DIR/point-NNNN` continues
//! an interrupted point); `DIR/sweep.json` and `DIR/sweep.csv` hold one
//! row per point: the swept inputs, the status and every number of the
//! point's `summary.json` (nested keys joined with '.').
//!
//! Deterministic whatever the thread count: each point runs on one
//! thread from its own case, and the table is written in grid order. A
//! Ctrl-C stops the running points (they keep what they computed, as a
//! single run does) and starts no more; their rows say so.

use crate::checkpoint::RunRecord;
use crate::run::run_case;
use crate::run_options::RunOptions;
use crate::sweep_grid::{Swept, parse_sweep};
use crate::{CaseArgs, CaseOverrides, Failure, bad_arg, emit, html_report, load_with};
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use rolldyn::math::random::SplitMix64;
use rolldyn_case::simulation::conditions;
use rolldyn_case::{Case, Override, OverrideSource};
use rolldyn_io::RunDir;
use serde_json::{Map, Value};
use std::fmt::Write;
use std::io::IsTerminal;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};

const RPM: f64 = std::f64::consts::TAU / 60.0;

/// Most points of a dynamic sweep without `--force`.
pub const MAX_RUN_SWEEP_POINTS: usize = 1000;

/// Status of a point the sweep did not start (interrupted before it).
const NOT_STARTED: &str = "not_started";

/// One `--sweep` of a dynamic run.
#[derive(Debug, Clone, PartialEq)]
pub enum RunSweep {
    /// The operating point: speed or a load, in SI.
    Operating(Swept, Vec<f64>),
    /// Any case key, its values as `--set` reads them.
    Key { key: String, values: Vec<String> },
}

/// Parses `speed=…`, `axial=…`, `radial=…` (ranges or lists with units,
/// as `quasistatic --sweep`) or `dotted.key=v1,v2,…` (a list).
pub fn parse_run_sweep(arg: &str) -> Result<RunSweep, String> {
    let (name, spec) = arg.split_once('=').ok_or(
        "expected NAME=VALUES, e.g. speed=0rpm..20000rpm/11 or cage.pocket_friction=0.05,0.1",
    )?;
    let name = name.trim();
    if matches!(name, "speed" | "axial" | "radial") {
        return parse_sweep(arg).map(|(swept, values)| RunSweep::Operating(swept, values));
    }
    if !name.contains('.') {
        return Err(format!(
            "unknown sweep variable \"{name}\"; expected speed, axial, radial or a case key (dotted, as --set: cage.pocket_friction=0.05,0.1)"
        ));
    }
    let values: Vec<String> = spec.split(',').map(|v| v.trim().to_string()).collect();
    if values.iter().any(String::is_empty) {
        return Err(format!(
            "\"{spec}\": a case key takes a list of values separated by commas, e.g. {name}=0.1,0.2"
        ));
    }
    Ok(RunSweep::Key {
        key: name.to_string(),
        values,
    })
}

/// A grid point: the overrides its case loads with, the same changes as
/// its run record keeps them (`rolldyn run --resume` reads the record),
/// and the labels of its case-key sweeps (key, value as given).
#[derive(Debug, Clone, PartialEq)]
pub struct GridPoint {
    /// The base case's overrides with the point's values, typed, in the
    /// order they apply (as [`CaseOverrides::overrides`] orders the
    /// record's).
    pub overrides: Vec<Override>,
    /// The point's overrides as flags and `--set` text.
    pub record: CaseOverrides,
    /// The case-key sweeps' values.
    pub labels: Vec<(String, String)>,
}

impl GridPoint {
    /// A point given by its record alone (the Python package's points).
    pub fn from_record(record: CaseOverrides) -> Result<Self, Failure> {
        Ok(Self {
            overrides: record.overrides()?,
            record,
            labels: Vec::new(),
        })
    }
}

/// A point while the grid is built: its operating flags (speed, axial,
/// radial: the base's or swept) and its case-key values, which the base's
/// other overrides separate.
#[derive(Clone)]
struct Partial {
    operating: [Option<Override>; 3],
    keys: Vec<Override>,
    record: CaseOverrides,
    labels: Vec<(String, String)>,
}

impl Partial {
    fn of(base: &CaseOverrides) -> Self {
        Self {
            operating: base.operating_flags(),
            keys: Vec::new(),
            record: base.clone(),
            labels: Vec::new(),
        }
    }

    /// A case-key value: applied after the base's overrides, recorded as
    /// `--set key=value`, labelled with its text.
    fn with_key(&self, key: &str, value: Override, text: &str) -> Self {
        let mut p = self.clone();
        p.keys.push(value);
        p.record.set.push(format!("{key}={text}"));
        p.labels.push((key.to_string(), text.to_string()));
        p
    }

    /// The point: its operating flags, the base's other overrides
    /// (`rest`), its case-key values.
    fn finish(self, rest: &[Override]) -> GridPoint {
        let mut overrides: Vec<Override> = self.operating.into_iter().flatten().collect();
        overrides.extend_from_slice(rest);
        overrides.extend(self.keys);
        GridPoint {
            overrides,
            record: self.record,
            labels: self.labels,
        }
    }
}

/// The base's overrides other than its operating flags, which a point
/// replaces.
fn rest_of(base: &CaseOverrides) -> Result<Vec<Override>, Failure> {
    CaseOverrides {
        speed: None,
        axial_load: None,
        radial_load: None,
        ..base.clone()
    }
    .overrides()
}

/// A case-key value as `--set` reads it, from `--sweep`.
fn swept_value(key: &str, text: &str) -> Result<Override, Failure> {
    Ok(Override::parse_from(
        &format!("{key}={text}"),
        OverrideSource::Sweep,
    )?)
}

/// The overrides of each grid point: the base ones with the swept values
/// (first sweep outermost). The operating point's values are typed (SI,
/// exact); a case key's values are read as `--set` reads them.
pub fn grid(base: &CaseOverrides, sweeps: &[RunSweep]) -> Result<Vec<GridPoint>, Failure> {
    let mut points = vec![Partial::of(base)];
    for sweep in sweeps {
        let mut next = Vec::with_capacity(points.len());
        for p in &points {
            match sweep {
                RunSweep::Operating(swept, values) => {
                    for &v in values {
                        let mut q = p.clone();
                        // SI: the point runs at exactly the swept value.
                        let (slot, key, unit, recorded) = match swept {
                            Swept::Speed => (0, "operating.speed", "rad/s", &mut q.record.speed),
                            Swept::Axial => (1, "operating.force_x", "N", &mut q.record.axial_load),
                            Swept::Radial => {
                                (2, "operating.force_z", "N", &mut q.record.radial_load)
                            }
                        };
                        let text = format!("{v:?} {unit}");
                        *recorded = Some(text.clone());
                        q.operating[slot] = Some(Override::typed(key, text, OverrideSource::Sweep));
                        next.push(q);
                    }
                }
                RunSweep::Key { key, values } => {
                    for v in values {
                        next.push(p.with_key(key, swept_value(key, v)?, v));
                    }
                }
            }
        }
        points = next;
    }
    let rest = rest_of(base)?;
    Ok(points.into_iter().map(|p| p.finish(&rest)).collect())
}

/// The base's overrides (other than its operating flags) of what an
/// operating-point sweep sets: they apply after the swept flag, so they
/// are refused rather than silently winning over every point.
fn conflicts(base: &CaseOverrides, sweeps: &[RunSweep]) -> Result<(), Failure> {
    for sweep in sweeps {
        let RunSweep::Operating(swept, _) = sweep else {
            continue;
        };
        let (name, keys): (&str, &[&str]) = match swept {
            Swept::Speed => ("speed", &["operating.speed", "operating.speed_profile"]),
            Swept::Axial => ("axial", &["operating.force_x", "operating.displacement_x"]),
            Swept::Radial => (
                "radial",
                &[
                    "operating.force_z",
                    "operating.radial_load",
                    "operating.radial_load_angle",
                ],
            ),
        };
        if let Some(o) = rest_of(base)?
            .iter()
            .find(|o| keys.contains(&o.key.as_str()))
        {
            return Err(Failure::BadInput(format!(
                "{}: sets what `--sweep {name}=…` sweeps; give one of them",
                o.text
            )));
        }
    }
    Ok(())
}

/// `--sample N --seed S`: random points instead of the grid.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Sampling {
    /// Number of runs.
    pub count: usize,
    /// Seed of the draws.
    pub seed: u64,
}

/// The case key an operating-point sweep name stands for.
fn operating_key(name: &str) -> &str {
    match name {
        "speed" => "operating.speed",
        "axial" => "operating.force_x",
        "radial" => "operating.force_z",
        other => other,
    }
}

/// A value with its unit split: `"0.36 mm"` → (0.36, "mm").
fn number_and_unit(text: &str) -> Option<(f64, &str)> {
    let text = text.trim();
    (1..=text.len())
        .rev()
        .filter(|&i| text.is_char_boundary(i))
        .find_map(|i| {
            text[..i]
                .trim()
                .parse::<f64>()
                .ok()
                .map(|v| (v, text[i..].trim()))
        })
}

/// What a `--sweep` draws from with `--sample`.
#[derive(Debug, Clone, PartialEq)]
enum Draw {
    /// Uniform in [low, high], in `unit` (as written).
    Range { low: f64, high: f64, unit: String },
    /// One of the values, each as likely.
    Choice(Vec<String>),
}

/// Parses a sampled sweep: `NAME=LOW..HIGH` (one unit) or `NAME=a,b,c`;
/// NAME is speed, axial, radial or a case key.
fn parse_draw(arg: &str) -> Result<(String, Draw), String> {
    let (name, spec) = arg
        .split_once('=')
        .ok_or("expected NAME=LOW..HIGH or NAME=a,b,c, e.g. speed=1000rpm..2000rpm")?;
    let name = name.trim();
    if !name.contains('.') && !matches!(name, "speed" | "axial" | "radial") {
        return Err(format!(
            "unknown sweep variable \"{name}\"; expected speed, axial, radial or a case key (dotted, as --set)"
        ));
    }
    let key = operating_key(name).to_string();
    if let Some((low, high)) = spec.split_once("..") {
        let bad = || {
            format!(
                "\"{spec}\": a range to draw from is LOW..HIGH with one unit, e.g. 0.1mm..0.5mm"
            )
        };
        let ((low, a), (high, b)) = (
            number_and_unit(low).ok_or_else(bad)?,
            number_and_unit(high).ok_or_else(bad)?,
        );
        if a != b || !low.is_finite() || !high.is_finite() || high < low {
            return Err(bad());
        }
        let unit = a.to_string();
        return Ok((key, Draw::Range { low, high, unit }));
    }
    let values: Vec<String> = spec.split(',').map(|v| v.trim().to_string()).collect();
    if values.iter().any(String::is_empty) {
        return Err(format!("\"{spec}\": a list to choose from is a,b,c"));
    }
    Ok((key, Draw::Choice(values)))
}

/// `count` random points (`--sample`): each sweep drawn in turn, point by
/// point, from one generator (SplitMix64) seeded with `seed`; labelled like the grid's
/// case-key sweeps.
pub fn sample(
    base: &CaseOverrides,
    sweeps: &[String],
    sampling: Sampling,
) -> Result<Vec<GridPoint>, Failure> {
    let draws = sweeps
        .iter()
        .map(|s| parse_draw(s).map_err(|e| bad_arg("--sweep", s, e)))
        .collect::<Result<Vec<_>, _>>()?;
    let rest = rest_of(base)?;
    let mut rng = SplitMix64::new(sampling.seed);
    let mut points = Vec::with_capacity(sampling.count);
    for _ in 0..sampling.count {
        let mut p = Partial::of(base);
        for (key, draw) in &draws {
            p = match draw {
                Draw::Range { low, high, unit } => {
                    let v = low + (high - low) * rng.unit();
                    let sweep = OverrideSource::Sweep;
                    let (text, value) = if unit.is_empty() {
                        (format!("{v:?}"), Override::typed(key, v, sweep))
                    } else {
                        let text = format!("{v:?} {unit}");
                        (text.clone(), Override::typed(key, text, sweep))
                    };
                    p.with_key(key, value, &text)
                }
                Draw::Choice(values) => {
                    let k = (rng.unit() * values.len() as f64) as usize;
                    let text = &values[k.min(values.len() - 1)];
                    p.with_key(key, swept_value(key, text)?, text)
                }
            };
        }
        points.push(p.finish(&rest));
    }
    Ok(points)
}

/// `rolldyn run --sweep`: parses the sweeps, runs the grid (or, with
/// `sampling`, random points), prints a line per point and the totals;
/// with `report`, writes the sweep's report and each point's.
#[allow(clippy::too_many_arguments)]
pub fn command(
    mut case: CaseArgs,
    sweeps: &[String],
    sampling: Option<Sampling>,
    duration: Option<String>,
    output: &str,
    options: &RunOptions,
    report: bool,
) -> Result<(), Failure> {
    let grid_sweeps = match sampling {
        Some(_) => Vec::new(),
        None => sweeps
            .iter()
            .map(|s| parse_run_sweep(s).map_err(|e| bad_arg("--sweep", s, e)))
            .collect::<Result<Vec<_>, _>>()?,
    };
    let count = match sampling {
        Some(s) if s.count == 0 => {
            return Err(bad_arg("--sample", "0", "needs at least one run"));
        }
        Some(s) => s.count,
        None => grid_sweeps
            .iter()
            .map(|s| match s {
                RunSweep::Operating(_, v) => v.len(),
                RunSweep::Key { values, .. } => values.len(),
            })
            .product(),
    };
    if count > MAX_RUN_SWEEP_POINTS && !options.force {
        return Err(Failure::BadInput(format!(
            "--sweep: the grid has {count} runs, above the limit of {MAX_RUN_SWEEP_POINTS}; use fewer points or pass --force"
        )));
    }
    if let Some(d) = duration {
        case.overrides.set.push(format!("solver.duration={d}"));
    }
    case.overrides.overrides()?;
    conflicts(&case.overrides, &grid_sweeps)?;
    let points = match sampling {
        Some(s) => sample(&case.overrides, sweeps, s)?,
        None => grid(&case.overrides, &grid_sweeps)?,
    };
    let (source, text) = case.read()?;
    let dir = Path::new(output);
    let (rows, interrupted) = run(&source, text.as_deref(), &points, dir, options)?;
    let mut out = String::new();
    for row in &rows {
        let _ = writeln!(
            out,
            "{}: {:.1} rpm, F_x {} N, F_z {} N: {}{}",
            row["point"].as_str().unwrap_or("?"),
            row["speed_rpm"].as_f64().unwrap_or(f64::NAN),
            row["force_x_n"],
            row["force_z_n"],
            row["status"].as_str().unwrap_or("?"),
            row.get("mean_cage_speed_rpm")
                .and_then(Value::as_f64)
                .map(|c| format!(", cage {c:.1} rpm"))
                .unwrap_or_default()
        );
    }
    let completed = rows.iter().filter(|r| r["status"] == "completed").count();
    let _ = writeln!(
        out,
        "{} of {} runs completed; wrote {output}/sweep.csv, {output}/sweep.json and {output}/point-*/",
        completed,
        rows.len()
    );
    emit(&out)?;
    if report {
        for row in &rows {
            let point = dir.join(row["point"].as_str().unwrap_or_default());
            if RunDir::new(&point).has_summary() {
                html_report::write(&point)?;
            }
        }
        let path = html_report::write(dir)?;
        emit(&format!("wrote {} (and one per point)\n", path.display()))?;
    }
    if interrupted {
        return Err(Failure::Interrupted(format!(
            "interrupted; {output}/ holds what was computed (rows with status \"interrupted\" or \"{NOT_STARTED}\")"
        )));
    }
    Ok(())
}

/// Runs the grid; writes the point directories, `sweep.json` and
/// `sweep.csv` into `dir`. Returns the rows and whether a Ctrl-C stopped
/// the sweep.
pub fn run(
    source: &str,
    case_text: Option<&str>,
    points: &[GridPoint],
    dir: &Path,
    options: &RunOptions,
) -> Result<(Vec<Map<String, Value>>, bool), Failure> {
    // Every point's case first: bad input fails before any run starts.
    let cases = points
        .iter()
        .map(|p| load_with(source, case_text, &p.overrides))
        .collect::<Result<Vec<_>, _>>()?;
    std::fs::create_dir_all(dir)
        .map_err(|e| Failure::BadInput(format!("cannot create {}: {e}", dir.display())))?;
    remove_stale_points(dir, points.len())?;
    let stop = options.stop_flag();
    let progress = options.progress.clone();
    // The points share the pool: no active helpers (rolldyn::threads).
    let options = RunOptions {
        stop: Some(stop.clone()),
        quiet: true,
        progress: None,
        active_helpers: false,
        ..options.clone()
    };
    // No bar when the caller follows the progress itself (the Python package).
    let bar = (progress.is_none() && std::io::stderr().is_terminal()).then(|| {
        let bar = ProgressBar::new(points.len() as u64);
        bar.set_style(
            ProgressStyle::with_template(
                "[{elapsed_precise}] {wide_bar} {pos}/{len} points ETA {eta}",
            )
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
        );
        bar
    });
    let done = AtomicUsize::new(0);
    let rows = points
        .par_iter()
        .zip(&cases)
        .enumerate()
        .map(|(k, (point, case))| {
            let name = RunDir::point_name(k, points.len());
            let mut row = if stop.load(Ordering::Relaxed) {
                let mut row = inputs_row(&name, case);
                row.insert("status".into(), Value::from(NOT_STARTED));
                row.insert("error".into(), Value::Null);
                row
            } else {
                run_point(&name, source, case_text, &point.record, case, dir, &options)
            };
            for (key, value) in &point.labels {
                row.insert(key.clone(), Value::from(value.as_str()));
            }
            let finished = done.fetch_add(1, Ordering::Relaxed) + 1;
            if let Some(bar) = &bar {
                bar.set_position(finished as u64);
            }
            if let Some(progress) = &progress {
                let fraction = finished as f64 / points.len() as f64;
                progress.store(fraction.to_bits(), Ordering::Relaxed);
            }
            row
        })
        .collect::<Vec<_>>();
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    let label_keys: Vec<&str> = points
        .first()
        .map(|p| p.labels.iter().map(|(k, _)| k.as_str()).collect())
        .unwrap_or_default();
    write_tables_labelled(dir, &rows, &label_keys)?;
    Ok((rows, stop.load(Ordering::Relaxed)))
}

/// [`RunDir::remove_stale_points`], its failure named.
pub fn remove_stale_points(dir: &Path, count: usize) -> Result<(), Failure> {
    RunDir::new(dir).remove_stale_points(count).map_err(|e| {
        Failure::BadInput(format!(
            "cannot remove an earlier sweep's points or run in {}: {e}",
            dir.display()
        ))
    })
}

/// A row's first columns: the point and the operating point it runs at.
fn inputs_row(name: &str, case: &Case) -> Map<String, Value> {
    let at = conditions(case, None);
    let mut row = Map::new();
    row.insert("point".into(), Value::from(name));
    row.insert("speed_rpm".into(), Value::from(at.inner_speed / RPM));
    row.insert("force_x_n".into(), Value::from(at.loads.force[0]));
    row.insert("force_z_n".into(), Value::from(at.loads.force[2]));
    row
}

/// Runs one point into `dir/name` and returns its row: the inputs, the
/// status and error, and the summary's numbers. A failure is a row, not an
/// error: the other points go on.
pub fn run_point(
    name: &str,
    source: &str,
    case_text: Option<&str>,
    overrides: &CaseOverrides,
    case: &Case,
    dir: &Path,
    options: &RunOptions,
) -> Map<String, Value> {
    let mut row = inputs_row(name, case);
    let record = RunRecord::new(
        source.to_string(),
        case_text.map(str::to_string),
        overrides.clone(),
        options.force,
    );
    // Bearings on a shaft run as a system, with their own summary.
    let run = if case.bearing_set().is_some() || case.shaft.is_some() {
        crate::run_set::run(&record, case, &dir.join(name), options)
            .map(|s| serde_json::to_value(&s).unwrap_or(Value::Null))
    } else {
        run_case(&record, case, &dir.join(name), options)
            .map(|s| serde_json::to_value(&s).unwrap_or(Value::Null))
    };
    match run {
        Err(
            Failure::BadInput(m)
            | Failure::Model(m)
            | Failure::Internal(m)
            | Failure::Interrupted(m),
        ) => {
            row.insert("status".into(), Value::from("failed"));
            row.insert("error".into(), Value::from(m));
        }
        Ok(value) => {
            row.insert("status".into(), value["status"].clone());
            row.insert("error".into(), value["error"].clone());
            flatten("", &value, &mut row);
        }
    }
    row
}

/// Adds the numbers of a summary to a row (nested keys joined by '.';
/// arrays by index). Strings other than the status and error are left
/// out: the table is numeric.
fn flatten(prefix: &str, value: &Value, row: &mut Map<String, Value>) {
    match value {
        Value::Object(map) => {
            for (k, v) in map {
                let key = if prefix.is_empty() {
                    k.clone()
                } else {
                    format!("{prefix}.{k}")
                };
                flatten(&key, v, row);
            }
        }
        Value::Array(items) => {
            for (i, v) in items.iter().enumerate() {
                flatten(&format!("{prefix}.{i}"), v, row);
            }
        }
        Value::Number(_) | Value::Null => {
            if !matches!(prefix, "speed_rpm" | "force_x_n" | "force_z_n") {
                row.insert(prefix.to_string(), value.clone());
            }
        }
        Value::String(_) | Value::Bool(_) => {}
    }
}

/// Writes `sweep.json` and `sweep.csv` (columns: the union of the rows'
/// keys in first-seen order).
pub fn write_tables(dir: &Path, rows: &[Map<String, Value>]) -> Result<(), Failure> {
    write_tables_labelled(dir, rows, &[])
}

/// [`write_tables`] with the case-key sweeps' `labels` as columns after
/// the operating point.
pub fn write_tables_labelled(
    dir: &Path,
    rows: &[Map<String, Value>],
    labels: &[&str],
) -> Result<(), Failure> {
    let json = crate::finite::to_json(rows).map_err(|e| Failure::Internal(e.to_string()))?;
    // The point and its inputs first, then the summary's keys.
    let mut columns: Vec<&str> = vec!["point", "speed_rpm", "force_x_n", "force_z_n"];
    columns.extend(labels);
    columns.extend(["status", "error"]);
    for row in rows {
        for key in row.keys() {
            if !columns.contains(&key.as_str()) {
                columns.push(key);
            }
        }
    }
    let mut csv = columns.join(",");
    csv.push('\n');
    for row in rows {
        let cells: Vec<String> = columns
            .iter()
            .map(|c| match row.get(*c) {
                Some(Value::Number(n)) => n.to_string(),
                Some(Value::String(s)) => format!("\"{}\"", s.replace('"', "'")),
                _ => String::new(),
            })
            .collect();
        csv.push_str(&cells.join(","));
        csv.push('\n');
    }
    RunDir::new(dir)
        .write_sweep(&json, &csv)
        .map_err(|e| Failure::BadInput(e.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn draws_are_seeded_in_range_and_labelled() {
        let sweeps = [
            "surface.outer.spall.0.length=0.1 mm..0.5 mm".to_string(),
            "speed=1000 rpm,2000 rpm".to_string(),
        ];
        let at = |seed| {
            let points = sample(
                &CaseOverrides::default(),
                &sweeps,
                Sampling { count: 50, seed },
            );
            points.unwrap_or_else(|_| panic!("the draws parse"))
        };
        let points = at(7);
        assert_eq!(points, at(7));
        assert_ne!(points, at(8));
        let mut speeds = std::collections::BTreeSet::new();
        for GridPoint { record, labels, .. } in &points {
            assert_eq!(labels[0].0, "surface.outer.spall.0.length");
            let (v, unit) = number_and_unit(&labels[0].1).unwrap();
            assert!((0.1..=0.5).contains(&v) && unit == "mm", "{labels:?}");
            assert_eq!(labels[1].0, "operating.speed");
            speeds.insert(labels[1].1.clone());
            assert_eq!(record.set[0], format!("{}={}", labels[0].0, labels[0].1));
        }
        assert_eq!(speeds.len(), 2);
        assert_eq!(number_and_unit("0.36 mm"), Some((0.36, "mm")));
        assert_eq!(number_and_unit("1e-3"), Some((1e-3, "")));
        assert!(parse_draw("surface.outer.spall.0.length=0.1 mm..0.5 in").is_err());
        assert!(parse_draw("temperature=1..2").is_err());
    }

    /// A point's case from its typed overrides is the case its run record
    /// loads (what `--resume` runs): grids over the operating point and a
    /// case key, on bases with flags and `--set`s, and sampled points.
    #[test]
    fn typed_points_load_the_cases_their_records_load() {
        let sweep = |s: &str| parse_run_sweep(s).unwrap();
        let bases = [
            CaseOverrides::default(),
            CaseOverrides {
                speed: Some("3000 rpm".into()),
                radial_load: Some("-500 N".into()),
                set: vec!["cage.pocket_friction=0.2".into()],
                ..CaseOverrides::default()
            },
            CaseOverrides {
                set: vec!["operating.radial_load=\"1 kN\"".into()],
                ..CaseOverrides::default()
            },
        ];
        let sweeps = [
            sweep("speed=1000rpm..5000rpm/3"),
            sweep("radial=-1kN,-2kN"),
            sweep("cage.pocket_friction=0.05,0.1"),
        ];
        let mut checked = 0;
        for base in &bases {
            let sampled = [
                "speed=1000 rpm..2000 rpm".to_string(),
                "axial=100 N,200 N".into(),
            ];
            let sampled = sample(base, &sampled, Sampling { count: 3, seed: 1 }).unwrap();
            let sweeps = if base.set.iter().any(|s| s.starts_with("operating.radial")) {
                &sweeps[..1]
            } else {
                &sweeps[..]
            };
            for point in grid(base, sweeps).unwrap().iter().chain(&sampled) {
                let typed = load_with("test", None, &point.overrides).unwrap_or_else(|_| panic!());
                let recorded = point
                    .record
                    .load_text("test", None)
                    .unwrap_or_else(|_| panic!());
                assert_eq!(typed, recorded, "{:?}", point.record);
                checked += 1;
            }
        }
        assert_eq!(checked, 3 * 3 + 12 * 2 + 3);
    }

    /// A bad value names `--sweep`, not `--set`; a `--set` that would win
    /// over an operating-point sweep is refused.
    #[test]
    fn sweep_values_are_named_as_sweeps() {
        let message = |f: Failure| match f {
            Failure::BadInput(m) => m,
            _ => String::from("not bad input"),
        };
        let points = grid(
            &CaseOverrides::default(),
            &[parse_run_sweep("cage.pocket_friction=abc,0.1").unwrap()],
        )
        .unwrap();
        let error = message(load_with("test", None, &points[0].overrides).unwrap_err());
        assert!(
            error.contains("`--sweep` value `cage.pocket_friction=abc`"),
            "{error}"
        );
        let base = CaseOverrides {
            set: vec!["operating.speed_profile=[]".into()],
            ..CaseOverrides::default()
        };
        let error =
            message(conflicts(&base, &[parse_run_sweep("speed=1rpm,2rpm").unwrap()]).unwrap_err());
        assert!(
            error.contains("sets what `--sweep speed=…` sweeps"),
            "{error}"
        );
        assert!(conflicts(&base, &[parse_run_sweep("axial=1N,2N").unwrap()]).is_ok());
    }
}
