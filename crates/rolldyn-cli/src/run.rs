//! `rolldyn run`: a dynamic simulation of a case. Writes
//! `DIR/timeseries.parquet` (one row per sample; units in the column
//! metadata), a Parquet dataset of part files written as the run goes
//! ([`rolldyn_io::SeriesWriter`]), and `DIR/summary.json`, whose
//! statistics are accumulated while running ([`crate::run_stats`]): memory
//! does not grow with the simulated time. Also after Ctrl-C or an
//! integration failure the files hold what was computed. A progress bar
//! shows on a terminal. Keys are documented in docs/cli.md.

use crate::Failure;
use crate::accuracy::{RunTolerances, grid_case, verifying_case};
use crate::checkpoint::{self, Position, RunRecord, continue_to};
use crate::pipeline::{Recorder, Start, drive, fresh_dir};
use crate::recorder::Channels;
pub use crate::run_summary::{CreepMeans, Summary};
use crate::run_summary::{SummaryInputs, summarise};
use crate::run_summary::{compared_value, verify};
use rolldyn::dynamics::{BearingModel, ContactSample};
use rolldyn::integrate::{Integrator, RunEnd, Solver};
use rolldyn_case::Case;
use rolldyn_case::simulation::{Simulation, SolverSettings};
use rolldyn_io::{RunDir, SeriesWriter};
use std::path::Path;

use crate::run_options::{
    DEFAULT_SAMPLE_RATE, MAX_CONTACT_PRESSURE, RunOptions, check_limits, speed_limit,
    temperature_limit,
};

/// A warning for a stress law integrated over a strip grid with an odd
/// number of cells along the rolling direction: a cell then sits on each
/// strip's middle, where near pure rolling the slip passes through zero and
/// the law's slope there (the EHL film's Newtonian stiffness, the
/// regularised Coulomb's ramp) is given the whole cell's area. The runs
/// stay right but their steps shrink, up to 60 times measured
/// (docs/dynamics.md).
pub fn odd_grid_warning(case: &Case) -> Option<String> {
    use rolldyn::traction::TractionModel;
    let stress_law = matches!(
        case.traction,
        TractionModel::ModifiedCoulomb(_) | TractionModel::TractionCurve(_) | TractionModel::Ehl(_)
    );
    let (_, along) = case.traction_integration.cells()?;
    (stress_law && along % 2 == 1).then(|| {
        format!(
            "model.traction_integration.along = {along} is odd: the strips' middle cells, where the slip passes through zero near pure rolling, make the contacts stiff and the steps short (up to 60 times as many, docs/dynamics.md); give an even number, e.g. {}",
            along + 1
        )
    })
}

/// The largest contact pressure the case's loads can give, estimated
/// before any solve: Stribeck's maximum ball load 5 F_r/(Z cos α) plus the
/// axial share F_a/(Z sin α) (α the nominal angle, at least 10° so that a
/// deep-groove bearing under axial load is not judged at α = 0), on the
/// more conforming … less conforming raceway (the larger of the two
/// pressures). An estimate for a plausibility limit, not a result.
fn pressure_estimate(case: &Case) -> Option<(f64, f64)> {
    use rolldyn::contact::hertz::{Curvature, HertzCoefficients};
    let g = &case.bearing.geometry;
    let z = g.ball_count as f64;
    let alpha = g.nominal_contact_angle();
    let axial_angle = alpha.max(10f64.to_radians());
    let loads: Vec<rolldyn::operating::Loads> = match &case.load_profile {
        Some(rolldyn::operating::LoadProfile::PiecewiseLinear(points)) => {
            points.iter().map(|p| p.1).collect()
        }
        _ => vec![case.loads],
    };
    let q = loads
        .iter()
        .map(|l| {
            5.0 * l.force[1].hypot(l.force[2]) / (z * alpha.cos())
                + l.force[0].abs() / (z * axial_angle.sin())
        })
        .fold(0.0, f64::max);
    let ep = rolldyn::material::effective_modulus(
        &case.materials.ball.material,
        &case.materials.rings.material,
    );
    let pressure = [rolldyn::RingKind::Inner, rolldyn::RingKind::Outer]
        .into_iter()
        .filter_map(|ring| {
            let c =
                Curvature::of_raceway(g.raceway(ring), g.ball_diameter, g.pitch_diameter, alpha);
            HertzCoefficients::exact(&c, ep)
                .ok()
                .map(|h| h.at_load(q).max_pressure)
        })
        .fold(0.0, f64::max);
    Some((q, pressure))
}

/// A run's summary (its time series is in the run directory).
pub struct RunOutput {
    pub summary: Summary,
}

/// Runs the case (from `record`) and writes the results into `dir`:
/// `run.json` first, then at every checkpoint and at the end the time
/// series, `summary.json` and (unless the run completed) `checkpoint.bin`.
/// Returns the summary; `Err` is bad input or an unwritable directory
/// (exit 2; nothing half-written).
pub fn run_case(
    record: &RunRecord,
    case: &Case,
    dir: &Path,
    options: &RunOptions,
) -> Result<Summary, Failure> {
    run_case_series(record, case, dir, options).map(|o| o.summary)
}

/// As [`run_case`], also running `--verify` when the options ask.
pub fn run_case_series(
    record: &RunRecord,
    case: &Case,
    dir: &Path,
    options: &RunOptions,
) -> Result<RunOutput, Failure> {
    let options = RunOptions {
        stop: Some(options.stop_flag()),
        ..options.clone()
    };
    let mut output = run_once(record, case, dir, &options)?;
    if options.verify && output.summary.status == "completed" {
        verify_run(record, case, dir, &options, &mut output.summary)?;
    }
    Ok(output)
}

/// One run of the case into `dir` ([`run_case_series`] without `--verify`).
pub(crate) fn run_once(
    record: &RunRecord,
    case: &Case,
    dir: &Path,
    options: &RunOptions,
) -> Result<RunOutput, Failure> {
    let bad = Failure::BadInput;
    let source = record.source.as_str();
    // The case's dynamic data first (cheap), then the duration, then the
    // model and its start (quasi-static solves).
    case.dynamics_parameters()
        .map_err(|e| bad(format!("{}: {}", e.key, e.rule)))?;
    let duration = case.duration.ok_or_else(|| bad(
        "solver.duration: missing: give the simulated time (or --duration, e.g. --duration \"0.05 s\")".into(),
    ))?;
    checkpoint::refuse_completed(dir, options, duration)?;
    let g = &case.bearing.geometry;
    let Simulation {
        mut model,
        initial_state: y0,
        settings,
    } = Simulation::from_case(case).map_err(|e| bad(e.to_string()))?;
    let mut channels = Channels::new(
        &model,
        case.power_per_ball,
        [duration, case.sample_rate.unwrap_or(DEFAULT_SAMPLE_RATE)],
        &case.output,
    );
    if !options.force {
        check_limits(
            duration,
            settings.max_step,
            settings.step_key(),
            case.sample_rate.unwrap_or(DEFAULT_SAMPLE_RATE),
            channels.recorded.width(),
        )
        .map_err(bad)?;
        if let Some((q, p)) = pressure_estimate(case).filter(|(_, p)| *p > MAX_CONTACT_PRESSURE) {
            return Err(bad(format!(
                "operating: the loads give a ball load of about {q:.3e} N and a contact pressure of about {:.1} GPa, above the {:.0} GPa where the Hertz and EHL models hold (ISO 76's static limit is 4.2 GPa); check the loads and their units, or pass --force",
                p * 1e-9,
                MAX_CONTACT_PRESSURE * 1e-9
            )));
        }
    }
    let mut solver = settings
        .build(&model, &y0)
        .map_err(|e| bad(e.to_string()))?;
    let _helpers = (options.active_helpers && model.runs_in_parallel())
        .then(rolldyn::threads::ActiveHelpers::start)
        .flatten();
    let sample_rate = case.sample_rate.unwrap_or(DEFAULT_SAMPLE_RATE);
    let record_hash = record.hash();
    let start = if options.resume {
        let position = checkpoint::restore(
            dir,
            options.extends.unwrap_or(record_hash),
            &mut solver,
            &mut model,
            &mut channels.stats,
        )
        .map_err(bad)?;
        continue_to(record, options, dir, solver.t(), duration)?;
        // The summary's statistics came with the checkpoint.
        open_series(&mut channels, dir, record, case, Some(position.rows))?;
        Start::from(position)
    } else {
        fresh_dir(dir, record)?;
        open_series(&mut channels, dir, record, case, None)?;
        Start::default()
    };
    let recorder = Output {
        verify: options.verify,
        source,
        case,
        dir,
        duration,
        settings,
        record_hash,
        row: Vec::with_capacity(channels.series.width()),
        loads: vec![ContactSample::default(); g.ball_count],
        speed_column: channels
            .series
            .names()
            .iter()
            .position(|n| n == "inner_ring_speed_rpm"),
        temperature_columns: channels
            .series
            .names()
            .iter()
            .enumerate()
            .filter_map(|(k, n)| {
                let node = n.strip_prefix("temperature_")?.strip_suffix("_c")?;
                Some((node.replace('_', " "), k))
            })
            .collect(),
        limit: None,
        channels,
    };
    let summary = drive(
        &mut model,
        &mut solver,
        duration,
        sample_rate,
        start,
        options,
        recorder,
    )?;
    Ok(RunOutput { summary })
}

/// Opens the run's datasets: created (an older run's slow channels
/// removed), or continued after `rows` rows of a resumed run.
fn open_series(
    channels: &mut Channels,
    dir: &Path,
    record: &RunRecord,
    case: &Case,
    rows: Option<u64>,
) -> Result<(), Failure> {
    let bad = Failure::BadInput;
    let run_dir = RunDir::new(dir);
    let metadata = [
        ("rolldyn_version", env!("CARGO_PKG_VERSION").to_string()),
        ("case", record.source.clone()),
        ("title", case.title.clone().unwrap_or_default()),
    ];
    let float32 = case.output.float32;
    let open = |path: &Path, series: &rolldyn_io::TimeSeries, rows: Option<u64>| match rows {
        Some(rows) => SeriesWriter::resume(path, series, &metadata, rows, float32)
            .map_err(|e| bad(format!("--resume: {e}"))),
        None => {
            SeriesWriter::create(path, series, &metadata, float32).map_err(|e| bad(e.to_string()))
        }
    };
    channels.writer = Some(open(&run_dir.series(), &channels.recorded, rows)?);
    let slow_dir = run_dir.slow_series();
    match &mut channels.slow {
        Some(slow) => {
            let slow_rows = rows.map(|r| slow.rows_for(r));
            slow.writer = Some(open(&slow_dir, &slow.recorded, slow_rows)?);
        }
        // An older run's slow channels do not belong to this one.
        None if rows.is_none() && slow_dir.exists() => std::fs::remove_dir_all(&slow_dir)
            .map_err(|e| bad(format!("cannot remove {}: {e}", slow_dir.display())))?,
        None => {}
    }
    Ok(())
}

/// What the run's files are written from, and the channels it records.
struct Output<'a> {
    source: &'a str,
    case: &'a Case,
    dir: &'a Path,
    duration: f64,
    settings: SolverSettings,
    record_hash: u64,
    channels: Channels,
    row: Vec<f64>,
    loads: Vec<ContactSample>,
    /// Column of the inner ring's speed in a row.
    speed_column: Option<usize>,
    /// Columns of a coupled run's part temperatures (`temperature_<node>_c`).
    temperature_columns: Vec<(String, usize)>,
    /// The limit the state passed, if it did.
    limit: Option<String>,
    /// `--verify` will compare this run's summary.
    verify: bool,
}

impl Recorder<BearingModel> for Output<'_> {
    type Summary = Summary;

    fn sample(&mut self, model: &BearingModel, t: f64, y: &[f64]) -> bool {
        self.channels
            .record(model, t, y, &mut self.row, &mut self.loads);
        if self.limit.is_none() {
            self.limit =
                speed_limit(self.speed_column.map_or(0.0, |k| self.row[k])).or_else(|| {
                    let row = &self.row;
                    temperature_limit(
                        self.temperature_columns
                            .iter()
                            .map(|(node, k)| (node.as_str(), row[*k])),
                    )
                });
        }
        self.channels.write_error.is_none()
    }

    fn limit(&self) -> Option<String> {
        self.limit.clone()
    }

    fn take_write_error(&mut self) -> Option<String> {
        self.channels.write_error.take().map(|e| e.to_string())
    }

    fn rows(&self) -> u64 {
        self.channels.rows()
    }

    /// The summary says `partial` for a checkpoint during the run.
    fn write(
        &mut self,
        model: &BearingModel,
        solver: &Solver,
        end: Option<&RunEnd>,
        position: Option<Position>,
        wall: f64,
    ) -> Result<Summary, Failure> {
        let channels = &mut self.channels;
        // A checkpoint's summary is built like a final one; its status and
        // error are then replaced below.
        let in_progress = RunEnd::Completed;
        let inputs = SummaryInputs {
            source: self.source,
            case: self.case,
            model,
            stats: &channels.stats,
            duration: self.duration,
            wall,
            settings: &self.settings,
            integration: solver.stats(),
            end: end.unwrap_or(&in_progress),
        };
        // The window's halves only for the run `--verify` compares.
        let mut summary = summarise(&inputs, self.verify && end.is_some());
        if let Solver::Switching(auto) = solver {
            summary.explicit_steps = Some(auto.steps_by_method().1);
            summary.integrator_switches = Some(auto.switches());
        }
        if end.is_none() {
            summary.status = "partial";
            summary.error = Some(format!(
                "checkpoint at t = {:.6} s of a run in progress (or killed); `rolldyn run --resume {}` continues it",
                solver.t(),
                self.dir.display()
            ));
        }
        let bad = |e: String| Failure::BadInput(e);
        if let Some(writer) = &mut channels.writer {
            writer.sync().map_err(|e| bad(e.to_string()))?;
        }
        if let Some(writer) = channels.slow.as_mut().and_then(|s| s.writer.as_mut()) {
            writer.sync().map_err(|e| bad(e.to_string()))?;
        }
        let bytes = position.map(|position| {
            checkpoint::encode(self.record_hash, position, solver, model, &channels.stats)
        });
        checkpoint::persist(self.dir, bytes, &summary)?;
        Ok(summary)
    }
}

/// `--verify`: the run's case again, into `DIR/verify/`, at ten times
/// tighter tolerances (the relative and energy tolerances, or rk4's step)
/// and with the traction's grid refined two-fold each way; the comparison
/// goes into `summary.accuracy.verify` and `summary.json` is written
/// again.
fn verify_run(
    record: &RunRecord,
    case: &Case,
    dir: &Path,
    options: &RunOptions,
    summary: &mut Summary,
) -> Result<(), Failure> {
    let (tight, tight_case, traction_grid) = verifying_case(
        record,
        case,
        RunTolerances {
            relative: summary.relative_tolerance,
            energy: summary.energy_tolerance,
            fixed_step: Some(summary.max_step_s),
        },
    );
    let verify_dir = dir.join(RunDir::VERIFY);
    let quiet = RunOptions {
        resume: false,
        quiet: true,
        progress: None,
        verify: false,
        ..options.clone()
    };
    let reference = run_once(&tight, &tight_case, &verify_dir, &quiet)?.summary;
    if reference.status == "interrupted" {
        return Err(Failure::Interrupted(format!(
            "--verify interrupted; {} holds the completed run, {} what the verifying run computed",
            dir.display(),
            verify_dir.display()
        )));
    }
    if reference.status != "completed" {
        return Err(Failure::Model(format!(
            "--verify: the run at ten times tighter tolerances and a finer traction grid in {} ended {}: {}",
            verify_dir.display(),
            reference.status,
            reference.error.unwrap_or_default()
        )));
    }
    let mut verification = verify(
        summary,
        &reference,
        verify_dir.display().to_string(),
        reference.energy_tolerance,
        traction_grid,
    );
    // Whether the grid or the tolerances moved it: the grid refined alone.
    if verification.wants_grid_run() {
        let (record, case) = grid_case(record, case);
        let grid = run_once(&record, &case, &dir.join(RunDir::VERIFY_GRID), &quiet)?.summary;
        if grid.status == "completed" {
            verification.attribute_to_grid(|key| compared_value(&grid, key));
        }
    }
    summary.accuracy.verify = Some(verification);
    checkpoint::persist(dir, None, &*summary)
}
