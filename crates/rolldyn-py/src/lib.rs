//! `rolldyn._rolldyn`: the native half of the Python package `rolldyn`
//! (the Python half is `python/rolldyn/__init__.py`, which users import).
//!
//! Every function runs exactly the code of the `rolldyn` command
//! (`rolldyn_cli`, the application layer), so a case gives the same
//! numbers from Python as from the CLI. A case crosses the boundary as its
//! source name, its TOML text (None: the built-in default case) and its
//! values set from Python, typed (`(key, value)` pairs: numbers, bools,
//! strings with their units, lists, dicts), as `run.json` records them;
//! reports come back as
//! Python dicts and lists built from the engine's report types (the keys
//! and values of the CLI's `--json` output, docs/cli.md; no JSON text in
//! between); time
//! series stay in the run directory's Parquet dataset, which the Python
//! half reads with pyarrow, a column at a time.
//!
//! Runs and sweeps release the GIL. They execute on a worker thread while
//! the calling thread waits in slices of 100 ms: between slices it takes
//! the GIL to check for a Ctrl-C (which raises the stop flag the engine
//! polls at every step, so the run ends cleanly and keeps what it
//! computed) and to call the progress callback.

use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyString;
use rolldyn_case::catalogue::CatalogueBearing;
use rolldyn_case::{Case, Override, presets};
use rolldyn_cli::checkpoint::RunRecord;
use rolldyn_cli::contact::{ContactArgs, evaluate};
use rolldyn_cli::power::{self, PowerArgs};
use rolldyn_cli::quasistatic::{self, ControlChoice};
use rolldyn_cli::report::{CheckReport, FrequencyReport};
use rolldyn_cli::run::run_case_series;
use rolldyn_cli::run_options::RunOptions;
use rolldyn_cli::spectrum::{self, SpectrumArgs};
use rolldyn_cli::thermal::{self, ThermalArgs};
use rolldyn_cli::traction::{self, TractionArgs};
use rolldyn_cli::{CaseArgs, CaseOverrides, CaseValue, Failure, finite, parse_angle, run_sweep};
use std::path::Path;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::time::Duration;

create_exception!(
    _rolldyn,
    CaseError,
    PyValueError,
    "Bad input: a case file, an override or an argument (the CLI's exit code 2). The message names the key, the value and the rule."
);
create_exception!(
    _rolldyn,
    ModelError,
    PyRuntimeError,
    "The model failed: a quasi-static solve did not converge (the CLI's exit code 3)."
);

/// How long the calling thread waits for a run between two looks at
/// Ctrl-C and the progress callback.
const POLL: Duration = Duration::from_millis(100);

fn to_py(failure: Failure) -> PyErr {
    match failure {
        Failure::BadInput(m) => CaseError::new_err(m),
        Failure::Model(m) => ModelError::new_err(m),
        Failure::Interrupted(m) | Failure::Internal(m) => PyRuntimeError::new_err(m),
    }
}

/// A report in memory in the data model of the CLI's `--json` output
/// (objects, arrays, numbers, strings, null), not as text: fixed-size
/// arrays become lists as in the JSON, and a non-finite number becomes
/// null with the CLI's warning (`rolldyn_cli::finite`: a bug to report).
fn in_memory<T: serde::Serialize>(value: &T) -> Result<serde_json::Value, Failure> {
    if let Some(path) = finite::non_finite(value) {
        eprintln!(
            "warning: non-finite number at {path} given as None (a rolldyn bug: please report it with the case)"
        );
    }
    serde_json::to_value(value).map_err(|e| Failure::Internal(e.to_string()))
}

/// A report as Python objects (dicts, lists, floats, ints, strings, None):
/// the keys and values the CLI's `--json` prints.
fn to_python<T: serde::Serialize>(py: Python<'_>, value: &T) -> PyResult<Py<PyAny>> {
    let value = in_memory(value).map_err(to_py)?;
    pythonize::pythonize(py, &value)
        .map(Bound::unbind)
        .map_err(|e| PyRuntimeError::new_err(e.to_string()))
}

/// A case's values from Python, `(key, value)` pairs as `Case.set` keeps
/// them.
type Values<'py> = Vec<(String, Bound<'py, PyAny>)>;

/// Python's values typed as a case file holds them: numbers, bools, lists
/// and dicts cross as they are (a string inside them stays a string); a
/// string on its own is read as `--set` reads its text (`"10000 rpm"`, or
/// a TOML value: `"22"`, `"{ law = \"hertz\" }"`).
fn case_values(values: Values<'_>) -> PyResult<Vec<CaseValue>> {
    values
        .into_iter()
        .map(|(key, value)| {
            let value = if value.is_instance_of::<PyString>() {
                Override::value_from_text(value.extract::<String>()?.trim())
            } else {
                pythonize::depythonize::<toml::Value>(&value).map_err(|e| {
                    CaseError::new_err(format!(
                        "override `{key}={value}` (Case.set): {e}; expected a number, a bool, a string with its unit, or a list or dict of them"
                    ))
                })?
            };
            // run.json records the values, and JSON has no NaN or infinity.
            if finite::non_finite(&value).is_some() {
                return Err(CaseError::new_err(format!(
                    "override `{key}={value}` (Case.set): a number must be finite"
                )));
            }
            Ok(CaseValue { key, value })
        })
        .collect()
}

fn overrides(values: Values<'_>) -> PyResult<CaseOverrides> {
    Ok(CaseOverrides {
        values: case_values(values)?,
        ..Default::default()
    })
}

/// Loads and validates a case: its source name, text (None: the built-in
/// default) and values.
fn load(source: &str, text: Option<&str>, values: Values<'_>) -> PyResult<Case> {
    overrides(values)?.load_text(source, text).map_err(to_py)
}

/// Names and one-line descriptions of the built-in bearings.
#[pyfunction]
fn preset_names() -> Vec<(&'static str, &'static str)> {
    presets::PRESETS
        .iter()
        .map(|p| (p.name, p.summary))
        .collect()
}

/// The case-file text of a preset.
#[pyfunction]
fn preset_text(name: &str) -> PyResult<&'static str> {
    presets::find(name).map(|p| p.text).ok_or_else(|| {
        CaseError::new_err(format!(
            "preset {name}: unknown preset; available: {}",
            presets::names()
        ))
    })
}

/// Validates the case; returns `rolldyn check --json`.
#[pyfunction]
#[pyo3(signature = (source, text, values))]
fn check(
    py: Python<'_>,
    source: &str,
    text: Option<&str>,
    values: Values<'_>,
) -> PyResult<Py<PyAny>> {
    let case = load(source, text, values)?;
    let report = CheckReport::new(source, &case).map_err(CaseError::new_err)?;
    to_python(py, &report)
}

/// `rolldyn frequencies --json`.
#[pyfunction]
#[pyo3(signature = (source, text, values, angle=None))]
fn frequencies(
    py: Python<'_>,
    source: &str,
    text: Option<&str>,
    values: Values<'_>,
    angle: Option<String>,
) -> PyResult<Py<PyAny>> {
    let angle = parse_angle("angle", angle.as_ref()).map_err(to_py)?;
    let case = load(source, text, values)?;
    let report = FrequencyReport::new(&case, angle).map_err(CaseError::new_err)?;
    to_python(py, &report)
}

/// The case of a typed function: its source, text and overrides.
fn case_args(source: String, text: Option<String>, values: Values<'_>) -> PyResult<CaseArgs> {
    Ok(CaseArgs {
        case: None,
        overrides: overrides(values)?,
        given: Some((source, text)),
    })
}

/// `rolldyn contact --json`.
#[pyfunction]
#[pyo3(signature = (source, text, values, load, angle=None, entrainment_speed=None, radii=None, ball_on_flat=None, inlet_distance_ratio=None))]
#[allow(clippy::too_many_arguments)]
fn contact(
    py: Python<'_>,
    source: String,
    text: Option<String>,
    values: Values<'_>,
    load: String,
    angle: Option<String>,
    entrainment_speed: Option<String>,
    radii: Option<String>,
    ball_on_flat: Option<String>,
    inlet_distance_ratio: Option<f64>,
) -> PyResult<Py<PyAny>> {
    let args = ContactArgs {
        case: case_args(source, text, values)?,
        load,
        angle,
        entrainment_speed,
        radii,
        ball_on_flat,
        inlet_distance_ratio,
        ..Default::default()
    };
    let report = py
        .detach(|| {
            let (_, case) = args.case.load()?;
            evaluate(&args, &case)
        })
        .map_err(to_py)?;
    to_python(py, &report)
}

/// `rolldyn power --json`.
#[pyfunction]
#[pyo3(signature = (source, text, values))]
fn power_report(
    py: Python<'_>,
    source: String,
    text: Option<String>,
    values: Values<'_>,
) -> PyResult<Py<PyAny>> {
    let args = PowerArgs {
        case: case_args(source, text, values)?,
        json: true,
    };
    let report = py.detach(|| power::report(&args)).map_err(to_py)?;
    to_python(py, &report)
}

/// `rolldyn thermal --json` (`--transient`, `--steps`: None keeps the
/// CLI's default).
#[pyfunction]
#[pyo3(signature = (source, text, values, transient=None, steps=None))]
fn thermal_report(
    py: Python<'_>,
    source: String,
    text: Option<String>,
    values: Values<'_>,
    transient: Option<String>,
    steps: Option<usize>,
) -> PyResult<Py<PyAny>> {
    let defaults = ThermalArgs::default();
    let args = ThermalArgs {
        case: case_args(source, text, values)?,
        transient,
        steps: steps.unwrap_or(defaults.steps),
        ..defaults
    };
    let report = py.detach(|| thermal::report(&args)).map_err(to_py)?;
    to_python(py, &report)
}

/// `rolldyn traction --json`: every flag of the command as a keyword
/// (None keeps the CLI's default).
#[pyfunction]
#[pyo3(signature = (source, text, values, rolling_speed, ring=None, load=None, approach=None, angle=None, creepages=None, slip=None, spin=None, semi_axes=None, shear_modulus=None, poisson_ratio=None, friction=None, method=None, cells=None, map=None))]
#[allow(clippy::too_many_arguments)]
fn traction_report(
    py: Python<'_>,
    source: String,
    text: Option<String>,
    values: Values<'_>,
    rolling_speed: String,
    ring: Option<String>,
    load: Option<String>,
    approach: Option<String>,
    angle: Option<String>,
    creepages: Option<String>,
    slip: Option<String>,
    spin: Option<String>,
    semi_axes: Option<String>,
    shear_modulus: Option<String>,
    poisson_ratio: Option<f64>,
    friction: Option<f64>,
    method: Option<String>,
    cells: Option<String>,
    map: Option<String>,
) -> PyResult<Py<PyAny>> {
    let defaults = TractionArgs::default();
    let args = TractionArgs {
        case: case_args(source, text, values)?,
        ring: ring.unwrap_or(defaults.ring),
        load,
        approach,
        angle,
        rolling_speed,
        creepages,
        slip,
        spin,
        semi_axes,
        shear_modulus,
        poisson_ratio,
        friction,
        method: method.unwrap_or(defaults.method),
        cells,
        map,
        ..defaults
    };
    let report = py.detach(|| traction::report(&args)).map_err(to_py)?;
    to_python(py, &report)
}

/// `rolldyn spectrum DIR --json` (None keeps the CLI's default).
#[pyfunction]
#[pyo3(signature = (directory, channel, kind=None, window=None, segment=None, overlap=None, band=None, start=None, harmonics=None, peaks=None))]
#[allow(clippy::too_many_arguments)]
fn spectrum_report(
    py: Python<'_>,
    directory: String,
    channel: String,
    kind: Option<String>,
    window: Option<String>,
    segment: Option<usize>,
    overlap: Option<f64>,
    band: Option<String>,
    start: Option<f64>,
    harmonics: Option<usize>,
    peaks: Option<usize>,
) -> PyResult<Py<PyAny>> {
    let defaults = SpectrumArgs::default();
    let args = SpectrumArgs {
        dir: directory,
        channel: Some(channel),
        kind: kind.unwrap_or(defaults.kind),
        window: window.unwrap_or(defaults.window),
        segment,
        overlap: overlap.unwrap_or(defaults.overlap),
        band,
        from: start,
        harmonics: harmonics.unwrap_or(defaults.harmonics),
        peaks: peaks.unwrap_or(defaults.peaks),
        ..defaults
    };
    let report = py.detach(|| spectrum::report(&args)).map_err(to_py)?;
    to_python(py, &report)
}

/// `rolldyn quasistatic --json`.
#[pyfunction]
#[pyo3(signature = (source, text, values, control=None))]
fn quasistatic_solve(
    py: Python<'_>,
    source: &str,
    text: Option<&str>,
    values: Values<'_>,
    control: Option<String>,
) -> PyResult<Py<PyAny>> {
    let control = ControlChoice::parse(control.as_deref()).map_err(to_py)?;
    let case = load(source, text, values)?;
    let output = py.detach(|| quasistatic::solve(&case, control).map_err(to_py))?;
    to_python(py, &output)
}

/// `rolldyn quasistatic --sweep … --json`: the rows of the sweep.
#[pyfunction]
#[pyo3(signature = (source, text, values, sweeps, control=None))]
fn quasistatic_sweep(
    py: Python<'_>,
    source: &str,
    text: Option<&str>,
    values: Values<'_>,
    sweeps: Vec<String>,
    control: Option<String>,
) -> PyResult<Py<PyAny>> {
    let ControlChoice::Raceway(control) =
        ControlChoice::parse(control.as_deref()).map_err(to_py)?
    else {
        return Err(CaseError::new_err(
            "control traction: not with a sweep (solve the points one by one)",
        ));
    };
    let sweeps = sweeps
        .iter()
        .map(|s| quasistatic::parse_sweep(s).map_err(|e| format!("sweep {s}: {e}")))
        .collect::<Result<Vec<_>, _>>()
        .map_err(CaseError::new_err)?;
    let case = load(source, text, values)?;
    let rows = py
        .detach(|| quasistatic::sweep_case(&case, control, &sweeps))
        .map_err(to_py)?;
    to_python(py, &rows)
}

/// Options of a run from Python: its own stop flag (never the process's
/// Ctrl-C handler: Python owns SIGINT) and progress fraction, no bar.
fn run_options(force: bool, verify: bool) -> (RunOptions, Arc<AtomicBool>, Arc<AtomicU64>) {
    let stop = Arc::new(AtomicBool::new(false));
    let fraction = Arc::new(AtomicU64::new(0f64.to_bits()));
    let options = RunOptions {
        force,
        checkpoint_interval: rolldyn_cli::run_options::DEFAULT_CHECKPOINT_INTERVAL,
        stop: Some(stop.clone()),
        quiet: true,
        progress: Some(fraction.clone()),
        verify,
        ..Default::default()
    };
    (options, stop, fraction)
}

/// Runs `work` on a worker thread (in rayon's pool) with the GIL released; meanwhile, every
/// [`POLL`], checks for Ctrl-C (raising `stop`) and calls `callback` with
/// the fraction in `progress`. Returns the work's result and whether a
/// Ctrl-C stopped it.
fn watched<T: Send>(
    py: Python<'_>,
    stop: &AtomicBool,
    progress: &AtomicU64,
    callback: Option<&Bound<'_, PyAny>>,
    work: impl FnOnce() -> T + Send,
) -> PyResult<(T, bool)> {
    let mut interrupted = false;
    let result = std::thread::scope(|scope| -> PyResult<T> {
        // The work runs on a thread of rayon's pool (as the CLI does), so
        // the engine's parallel passes over the balls stay inside the pool.
        let worker = scope.spawn(|| rayon::scope(|_| work()));
        let mut last = f64::NAN;
        loop {
            let finished = py.detach(|| {
                let begun = std::time::Instant::now();
                while !worker.is_finished() && begun.elapsed() < POLL {
                    std::thread::sleep(Duration::from_millis(2));
                }
                worker.is_finished()
            });
            if !interrupted && py.check_signals().is_err() {
                // The KeyboardInterrupt is replaced by the partial result
                // (the Python side raises `RunInterrupted`).
                interrupted = true;
                stop.store(true, Ordering::Relaxed);
            }
            if let Some(callback) = callback {
                let fraction = f64::from_bits(progress.load(Ordering::Relaxed));
                if fraction != last || finished {
                    last = fraction;
                    if let Err(e) = callback.call1((fraction,)) {
                        // An exception in the callback stops the run; it
                        // is raised once the worker has ended.
                        stop.store(true, Ordering::Relaxed);
                        let _ = py.detach(|| worker.join());
                        return Err(e);
                    }
                }
            }
            if finished {
                return py
                    .detach(|| worker.join())
                    .map_err(|_| PyRuntimeError::new_err("the run panicked"));
            }
        }
    })?;
    Ok((result, interrupted))
}

/// `rolldyn run`: runs the case into `directory` (with `verify`, also at
/// ten times tighter tolerances into `directory/verify`, as `--verify`).
/// Returns the summary (a dict) and whether a Ctrl-C
/// stopped the run.
#[pyfunction]
#[pyo3(signature = (source, text, values, directory, force=false, progress=None, verify=false))]
#[allow(clippy::too_many_arguments)]
fn run(
    py: Python<'_>,
    source: String,
    text: Option<String>,
    values: Values<'_>,
    directory: &str,
    force: bool,
    progress: Option<Bound<'_, PyAny>>,
    verify: bool,
) -> PyResult<(Py<PyAny>, bool)> {
    let overrides = overrides(values)?;
    let case = overrides
        .load_text(&source, text.as_deref())
        .map_err(to_py)?;
    let record = RunRecord::new(source, text, overrides, force);
    let (mut options, stop, fraction) = run_options(force, verify);
    // One run: the pool's other threads wait actively (rolldyn::threads;
    // one set per process, so concurrent runs from several Python threads
    // stay safe).
    options.active_helpers = true;
    let dir = Path::new(directory);
    // A bearing set runs on its shaft (its own summary, docs/cli.md).
    let set = case.bearing_set().is_some() || case.shaft.is_some();
    let (summary, interrupted) = watched(py, &stop, &fraction, progress.as_ref(), || {
        if set {
            rolldyn_cli::run_set::run_and_verify(&record, &case, dir, &options)
                .and_then(|s| in_memory(&s))
        } else {
            run_case_series(&record, &case, dir, &options).and_then(|o| in_memory(&o.summary))
        }
    })?;
    Ok((to_python(py, &summary.map_err(to_py)?)?, interrupted))
}

/// Opens a run directory: its summary (a dict); checks that its time series
/// reads (the channels, not the samples).
#[pyfunction]
fn open_run(py: Python<'_>, directory: &str) -> PyResult<Py<PyAny>> {
    let dir = Path::new(directory);
    let summary = std::fs::read_to_string(rolldyn_io::RunDir::new(dir).summary())
        .map_err(|e| CaseError::new_err(format!("{directory}: no summary.json: {e}")))?;
    let summary: serde_json::Value = serde_json::from_str(&summary)
        .map_err(|e| CaseError::new_err(format!("{directory}: summary.json: {e}")))?;
    rolldyn_io::read_schema(&rolldyn_io::RunDir::new(dir).series())
        .map_err(|e| CaseError::new_err(e.to_string()))?;
    to_python(py, &summary)
}

/// `rolldyn run --sweep`: runs the points (each a list of overrides added
/// to the case's) in parallel into `directory/point-NNNN/`, writes
/// `sweep.json` and `sweep.csv`, and returns the rows (dicts) and whether
/// a Ctrl-C stopped the sweep. Progress: the fraction of points done.
#[pyfunction]
#[pyo3(signature = (source, text, values, points, directory, force=false, progress=None))]
#[allow(clippy::too_many_arguments)]
fn run_points(
    py: Python<'_>,
    source: String,
    text: Option<String>,
    values: Values<'_>,
    points: Vec<Values<'_>>,
    directory: &str,
    force: bool,
    progress: Option<Bound<'_, PyAny>>,
) -> PyResult<(Py<PyAny>, bool)> {
    let base = case_values(values)?;
    let points = points
        .into_iter()
        .map(|p| {
            let mut values = base.clone();
            values.extend(case_values(p)?);
            let record = CaseOverrides {
                values,
                ..Default::default()
            };
            run_sweep::GridPoint::from_record(record).map_err(to_py)
        })
        .collect::<PyResult<Vec<_>>>()?;
    let (options, stop, fraction) = run_options(force, false);
    let dir = Path::new(directory);
    let (rows, interrupted) = watched(py, &stop, &fraction, progress.as_ref(), || {
        run_sweep::run(&source, text.as_deref(), &points, dir, &options)
    })?;
    let (rows, _) = rows.map_err(to_py)?;
    Ok((to_python(py, &rows)?, interrupted))
}

/// A sampled point's values and the drawn values' labels.
type SampledPoint = (Vec<(String, Py<PyAny>)>, Vec<String>);

/// `rolldyn run --sweep … --sample COUNT --seed SEED`'s random points:
/// each point's typed values `(key, value)` and the drawn values as text
/// (in sweep order).
#[pyfunction]
fn sample_points(
    py: Python<'_>,
    sweeps: Vec<String>,
    count: usize,
    seed: u64,
) -> PyResult<Vec<SampledPoint>> {
    let sampling = run_sweep::Sampling { count, seed };
    let points = run_sweep::sample(&CaseOverrides::default(), &sweeps, sampling).map_err(to_py)?;
    points
        .into_iter()
        .map(|p| {
            let values = p
                .overrides
                .into_iter()
                .map(|o| Ok((o.key, to_python(py, &o.value)?)))
                .collect::<PyResult<Vec<_>>>()?;
            Ok((values, p.labels.into_iter().map(|(_, v)| v).collect()))
        })
        .collect()
}

/// One point of a sweep (a Dask task): runs the case with the point's
/// overrides into `directory/name` and returns its row (a dict), the same
/// row `run_points` gives.
#[pyfunction]
#[pyo3(signature = (name, source, text, values, directory, force=false))]
#[allow(clippy::too_many_arguments)]
fn run_point(
    py: Python<'_>,
    name: &str,
    source: &str,
    text: Option<&str>,
    values: Values<'_>,
    directory: &str,
    force: bool,
) -> PyResult<Py<PyAny>> {
    let overrides = overrides(values)?;
    let case = overrides.load_text(source, text).map_err(to_py)?;
    let (options, stop, fraction) = run_options(force, false);
    let dir = Path::new(directory);
    let (row, _) = watched(py, &stop, &fraction, None, || {
        run_sweep::run_point(name, source, text, &overrides, &case, dir, &options)
    })?;
    to_python(py, &row)
}

/// Each value's `--set KEY=VALUE` text (`Case.overrides`).
#[pyfunction]
fn set_texts(values: Values<'_>) -> PyResult<Vec<String>> {
    Ok(case_values(values)?
        .iter()
        .map(CaseValue::set_text)
        .collect())
}

/// The directory name of point `k` of `count` (`point-NNNN`).
#[pyfunction]
fn point_name(k: usize, count: usize) -> String {
    rolldyn_io::RunDir::point_name(k, count)
}

/// Removes the point directories an earlier, larger sweep left in
/// `directory`, and an earlier single run's files there (as `rolldyn run
/// --sweep` does before its points run).
#[pyfunction]
fn remove_stale_points(directory: &str, count: usize) -> PyResult<()> {
    run_sweep::remove_stale_points(Path::new(directory), count).map_err(to_py)
}

/// Writes `sweep.json` and `sweep.csv` of rows (dicts) into `directory`.
#[pyfunction]
fn write_sweep_tables(directory: &str, rows: &Bound<'_, PyAny>) -> PyResult<()> {
    let rows: Vec<serde_json::Map<String, serde_json::Value>> =
        pythonize::depythonize(rows).map_err(|e| CaseError::new_err(e.to_string()))?;
    run_sweep::write_tables(Path::new(directory), &rows).map_err(to_py)
}

/// The case text of a catalogue bearing (as `rolldyn new --bearing`).
#[pyfunction]
#[pyo3(signature = (designation, clearance=None))]
fn catalogue_text(designation: &str, clearance: Option<&str>) -> PyResult<String> {
    let bearing = CatalogueBearing::lookup(designation, clearance)
        .map_err(|e| CaseError::new_err(e.to_string()))?;
    bearing
        .case_text()
        .map_err(|e| ModelError::new_err(format!("{}: {e}", bearing.designation)))
}

/// `rolldyn catalogue --json` (all, or one series such as "62").
#[pyfunction]
#[pyo3(signature = (series=None))]
fn catalogue_entries(py: Python<'_>, series: Option<&str>) -> PyResult<Py<PyAny>> {
    to_python(py, &rolldyn_cli::catalogue::entries(series).map_err(to_py)?)
}

/// Writes `directory/report.html` (as `rolldyn report`); returns its path.
#[pyfunction]
fn report(directory: &str) -> PyResult<String> {
    rolldyn_cli::html_report::write(Path::new(directory))
        .map(|p| p.display().to_string())
        .map_err(to_py)
}

#[pymodule]
fn _rolldyn(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("CaseError", m.py().get_type::<CaseError>())?;
    m.add("ModelError", m.py().get_type::<ModelError>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    // The run directory's names, from the one place that defines them.
    m.add("SERIES_DIR", rolldyn_io::RunDir::SERIES)?;
    m.add("SLOW_SERIES_DIR", rolldyn_io::RunDir::SLOW_SERIES)?;
    m.add_function(wrap_pyfunction!(preset_names, m)?)?;
    m.add_function(wrap_pyfunction!(preset_text, m)?)?;
    m.add_function(wrap_pyfunction!(catalogue_text, m)?)?;
    m.add_function(wrap_pyfunction!(catalogue_entries, m)?)?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(frequencies, m)?)?;
    m.add_function(wrap_pyfunction!(contact, m)?)?;
    m.add_function(wrap_pyfunction!(power_report, m)?)?;
    m.add_function(wrap_pyfunction!(thermal_report, m)?)?;
    m.add_function(wrap_pyfunction!(traction_report, m)?)?;
    m.add_function(wrap_pyfunction!(spectrum_report, m)?)?;
    m.add_function(wrap_pyfunction!(quasistatic_solve, m)?)?;
    m.add_function(wrap_pyfunction!(quasistatic_sweep, m)?)?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(open_run, m)?)?;
    m.add_function(wrap_pyfunction!(run_points, m)?)?;
    m.add_function(wrap_pyfunction!(run_point, m)?)?;
    m.add_function(wrap_pyfunction!(point_name, m)?)?;
    m.add_function(wrap_pyfunction!(set_texts, m)?)?;
    m.add_function(wrap_pyfunction!(sample_points, m)?)?;
    m.add_function(wrap_pyfunction!(write_sweep_tables, m)?)?;
    m.add_function(wrap_pyfunction!(remove_stale_points, m)?)?;
    m.add_function(wrap_pyfunction!(report, m)?)?;
    Ok(())
}
