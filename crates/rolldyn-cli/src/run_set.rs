//! `rolldyn run` of bearings on a shaft (a matched set, `[arrangement]`, or
//! a `[shaft]`): every bearing's ball and cage dynamics on the rigid shaft
//! (docs/systems.md, "Dynamics").
//! Writes `DIR/run.json`, `DIR/timeseries.parquet` (each bearing's
//! channels prefixed `bearing{i}_`, then the shaft's and the system's
//! energy) as the run goes, and `DIR/summary.json` at the end (keys in
//! docs/cli.md), with checkpoints as a single bearing's run
//! (`crate::checkpoint`): `--resume` continues an interrupted run, `--until`
//! extends a finished one.

use crate::Failure;
use crate::accuracy::{Change, VERIFY_LIMIT_MEANS, Verification};
use crate::checkpoint::{self, Position, RunRecord};
use crate::pipeline::{Recorder, Start, drive, fresh_dir};
use crate::recorder::Channels;
use crate::run_options::{DEFAULT_SAMPLE_RATE, RunOptions, check_limits, speed_limit};
use crate::run_stats::RunStatistics;

use rolldyn::dynamics::ContactSample;
use rolldyn::dynamics::shaft::ShaftDynamics;
use rolldyn::integrate::{Integrator, RunEnd, Solver};
use rolldyn::quasistatic::system::Orientation;
use rolldyn_case::Case;
use rolldyn_case::case::kind_name;
use rolldyn_case::simulation::SetSimulation;
use rolldyn_io::{RunDir, SeriesWriter, TimeSeries};
use serde::Serialize;
use std::path::Path;

/// The shaft's channels after the bearings' (name, unit).
const SHAFT_CHANNELS: [(&str, &str); 8] = [
    ("shaft_x_m", "m"),
    ("shaft_y_m", "m"),
    ("shaft_z_m", "m"),
    ("shaft_tilt_y_rad", "rad"),
    ("shaft_tilt_z_rad", "rad"),
    ("drive_work_j", "J"),
    ("dissipated_energy_j", "J"),
    ("mechanical_energy_j", "J"),
];

/// One bearing in `summary.json`.
#[derive(Serialize)]
pub struct SetBearingSummary {
    pub position_m: f64,
    pub orientation: &'static str,
    pub quasistatic_axial_load_n: f64,
    pub mean_axial_load_n: f64,
    pub mean_cage_speed_rpm: f64,
    pub mean_inner_load_n: f64,
    pub largest_inner_load_n: f64,
    pub largest_outer_load_n: f64,
    pub drive_work_j: f64,
    pub dissipated_energy_j: f64,
}

/// `DIR/summary.json` of a set's run.
#[derive(Serialize)]
pub struct SetSummary {
    pub status: &'static str,
    pub error: Option<String>,
    pub kind: &'static str,
    pub mounting_preload_n: Option<f64>,
    pub requested_duration_s: f64,
    pub simulated_time_s: f64,
    pub wall_time_s: f64,
    pub integrator: &'static str,
    pub relative_tolerance: Option<f64>,
    pub energy_tolerance: Option<f64>,
    pub steps: u64,
    pub rejected_steps: u64,
    pub rhs_evaluations: u64,
    pub samples: u64,
    pub averaging_window_s: [f64; 2],
    pub inner_ring_speed_rpm: f64,
    pub final_inner_ring_speed_rpm: f64,
    pub mean_cage_speed_rpm: f64,
    pub ball_count: usize,
    pub ball_diameter_m: f64,
    pub pitch_diameter_m: f64,
    pub mean_contact_angle_inner_deg: f64,
    pub mean_contact_angle_outer_deg: f64,
    pub drive_work_j: f64,
    pub dissipated_energy_j: f64,
    pub mechanical_energy_change_j: f64,
    pub energy_balance_relative_error: f64,
    pub bearings: Vec<SetBearingSummary>,
    /// The `--verify` comparison (null without `--verify`).
    pub verify: Option<Verification>,
    /// The compared quantities that have one (each bearing's cage speed
    /// and mean inner load, keyed as `compared_values` keys them) over each half
    /// of the averaging window, for how much they move within it
    /// (`--verify`'s window spread); not written.
    #[serde(skip)]
    pub window_halves: Vec<(String, [f64; 2])>,
}

/// Index of the first recorded channel of `names` called `name`.
fn index_of(series: &TimeSeries, name: &str) -> Option<usize> {
    series.names().iter().position(|n| n == name)
}

/// The combined series of a set's run: time, each bearing's recorded
/// channels but time, its axial load, then the shaft's.
fn combined_series(channels: &[Channels]) -> TimeSeries {
    let mut series = TimeSeries::default();
    series.channel("time_s", "s");
    for (i, c) in channels.iter().enumerate() {
        for (name, unit) in c.recorded.names().iter().zip(c.recorded.units()).skip(1) {
            series.channel(format!("bearing{i}_{name}"), unit.clone());
        }
        series.channel(format!("bearing{i}_axial_load_n"), "N");
    }
    for (name, unit) in SHAFT_CHANNELS {
        series.channel(name, unit);
    }
    series
}

/// Runs the set of `case` into `dir`.
pub fn run(
    record: &RunRecord,
    case: &Case,
    dir: &Path,
    options: &RunOptions,
) -> Result<SetSummary, Failure> {
    let bad = Failure::BadInput;
    let duration = case.duration.ok_or_else(|| {
        bad("solver.duration: missing: give the simulated time (or --duration, e.g. --duration \"0.05 s\")".into())
    })?;
    checkpoint::refuse_completed(dir, options, duration)?;
    let SetSimulation {
        kind,
        mounting_preload,
        mounted,
        quasistatic: cold,
        mut system,
        initial_state: y0,
        settings,
    } = SetSimulation::from_case(case)
        .map_err(crate::simulation_failure)?
        .ok_or_else(|| Failure::Internal("not a bearing set".into()))?;
    let sample_rate = case.sample_rate.unwrap_or(DEFAULT_SAMPLE_RATE);
    let count = system.bearing_count();
    let mut channels: Vec<Channels> = (0..count)
        .map(|i| {
            Channels::new(
                system.bearing(i),
                case.power_per_ball,
                [duration, sample_rate],
                &case.output,
            )
        })
        .collect();
    let series = combined_series(&channels);
    if !options.force {
        check_limits(
            duration,
            settings.max_step,
            settings.step_key(),
            sample_rate,
            series.width(),
        )
        .map_err(bad)?;
    }
    let mut solver = settings
        .build(&system, &y0)
        .map_err(|e| bad(e.to_string()))?;
    let parallel = (0..count).any(|i| system.bearing(i).runs_in_parallel());
    let _helpers = (options.active_helpers && parallel)
        .then(rolldyn::threads::ActiveHelpers::start)
        .flatten();
    let record_hash = record.hash();
    let metadata = [
        ("rolldyn_version", env!("CARGO_PKG_VERSION").to_string()),
        ("case", record.source.clone()),
        ("title", case.title.clone().unwrap_or_default()),
    ];
    let series_dir = RunDir::new(dir).series();
    let mut axial_sums = vec![0.0; count];
    let (start, writer) = if options.resume {
        let mut stats: Vec<&mut RunStatistics> =
            channels.iter_mut().map(|c| &mut c.stats).collect();
        let position = checkpoint::restore_parts(
            dir,
            options.extends.unwrap_or(record_hash),
            &mut solver,
            &mut system,
            &mut stats,
            &mut axial_sums,
        )
        .map_err(bad)?;
        checkpoint::continue_to(record, options, dir, solver.t(), duration)?;
        let writer = SeriesWriter::resume(
            &series_dir,
            &series,
            &metadata,
            position.rows,
            case.output.float32,
        )
        .map_err(|e| bad(format!("--resume: {e}")))?;
        (Start::from(position), writer)
    } else {
        fresh_dir(dir, record)?;
        let writer = SeriesWriter::create(&series_dir, &series, &metadata, case.output.float32)
            .map_err(|e| bad(e.to_string()))?;
        (Start::default(), writer)
    };
    let recording = Recording::new(
        &system,
        channels,
        series.width(),
        axial_sums,
        writer,
        Context {
            kind,
            mounting_preload,
            mounted: &mounted,
            cold: &cold,
            settings: &settings,
            duration,
            balance0: rolldyn::integrate::OdeSystem::energy_balance(&system, 0.0, &y0)
                .unwrap_or_default(),
            dir,
            record_hash,
        },
    );
    drive(
        &mut system,
        &mut solver,
        duration,
        sample_rate,
        start,
        options,
        recording,
    )
}

/// What a set's run records besides the integrator: each bearing's
/// channels (with their statistics), the axial loads' sums, the series;
/// the buffers of a sample; what the summary is written from.
struct Recording<'a> {
    channels: Vec<Channels>,
    axial_sums: Vec<f64>,
    writer: SeriesWriter,
    write_error: Option<rolldyn_io::OutputError>,
    layouts: Vec<rolldyn::dynamics::StateLayout>,
    /// Channels of a bearing's row the shaft's motion replaces: the inner
    /// ring's accelerations and the mechanical energy.
    patch: [Option<usize>; 4],
    own: Vec<f64>,
    rows: Vec<Vec<f64>>,
    contacts: Vec<ContactSample>,
    combined: Vec<f64>,
    loads: Vec<[f64; 5]>,
    /// Column of the inner ring's speed in a bearing's row.
    speed_column: Option<usize>,
    /// The limit the state passed, if it did.
    limit: Option<String>,
    context: Context<'a>,
}

impl<'a> Recording<'a> {
    /// The recording of `system`'s run: its bearings' `channels`, the
    /// combined row's `width`, the axial-load sums (a resumed run's),
    /// the series `writer` and the summary's `context`; buffers sized for
    /// the largest bearing (a shaft's may differ in balls and states).
    fn new(
        system: &ShaftDynamics,
        channels: Vec<Channels>,
        width: usize,
        axial_sums: Vec<f64>,
        writer: SeriesWriter,
        context: Context<'a>,
    ) -> Self {
        let count = system.bearing_count();
        let layouts: Vec<_> = (0..count).map(|i| system.bearing(i).layout()).collect();
        let bearing_series = &channels[0].series;
        // Channels of a bearing's row the shaft's motion replaces: the
        // inner ring's accelerations and the mechanical energy.
        let patch = [
            "inner_ring_acceleration_x_m_s2",
            "inner_ring_acceleration_y_m_s2",
            "inner_ring_acceleration_z_m_s2",
            "mechanical_energy_j",
        ]
        .map(|name| index_of(bearing_series, name));
        Self {
            own: vec![0.0; layouts.iter().map(|l| l.len()).max().unwrap_or(0)],
            rows: vec![Vec::with_capacity(bearing_series.width()); count],
            contacts: vec![
                ContactSample::default();
                layouts.iter().map(|l| l.balls).max().unwrap_or(0)
            ],
            combined: Vec::with_capacity(width),
            loads: vec![[0.0; 5]; count],
            speed_column: index_of(bearing_series, "inner_ring_speed_rpm"),
            limit: None,
            layouts,
            patch,
            channels,
            axial_sums,
            writer,
            write_error: None,
            context,
        }
    }
}

impl Recorder<ShaftDynamics> for Recording<'_> {
    type Summary = SetSummary;

    fn sample(&mut self, s: &ShaftDynamics, t: f64, y: &[f64]) -> bool {
        let patch = self.patch;
        for (i, (c, row)) in self.channels.iter_mut().zip(&mut self.rows).enumerate() {
            let (n, balls) = (self.layouts[i].len(), self.layouts[i].balls);
            let own = &mut self.own[..n];
            s.bearing_state(i, y, own);
            c.fill(s.bearing(i), t, own, row, &mut self.contacts[..balls]);
            self.loads[i] = s.ring_load(i, c.derivative());
            if let Some(k) = patch[3] {
                row[k] = s.bearing_energy(i, t, own);
            }
        }
        let acceleration = s.shaft_acceleration(t, y, &self.loads);
        let combined = &mut self.combined;
        combined.clear();
        combined.push(t);
        for (i, (c, row)) in self.channels.iter_mut().zip(&mut self.rows).enumerate() {
            let ring = s.at_bearing(i, &acceleration);
            for (k, a) in patch[..3].iter().zip(ring) {
                if let Some(k) = k {
                    row[*k] = a;
                }
            }
            c.sink(row);
            combined.extend_from_slice(&c.project(row)[1..]);
            // The bearing's balls push its ring back from its loaded
            // side: the axial load it carries is −F_x.
            combined.push(-self.loads[i][0]);
            self.axial_sums[i] += -self.loads[i][0];
        }
        let sh = s.shaft();
        combined.extend_from_slice(&y[sh..sh + 5]);
        let b = rolldyn::integrate::OdeSystem::energy_balance(s, t, y).unwrap_or_default();
        combined.extend_from_slice(&[b.work, b.dissipated, b.mechanical]);
        if self.write_error.is_none() {
            self.write_error = self.writer.push(combined).err();
        }
        if self.limit.is_none() {
            self.limit = speed_limit(self.speed_column.map_or(0.0, |k| self.rows[0][k]));
        }
        self.write_error.is_none()
    }

    fn limit(&self) -> Option<String> {
        self.limit.clone()
    }

    fn take_write_error(&mut self) -> Option<String> {
        self.write_error.take().map(|e| e.to_string())
    }

    fn rows(&self) -> u64 {
        self.channels[0].rows()
    }

    fn write(
        &mut self,
        system: &ShaftDynamics,
        solver: &Solver,
        end: Option<&RunEnd>,
        position: Option<Position>,
        wall: f64,
    ) -> Result<SetSummary, Failure> {
        let Recording {
            context,
            writer,
            channels,
            axial_sums,
            ..
        } = self;
        writer
            .sync()
            .map_err(|e| Failure::BadInput(e.to_string()))?;
        context.write(system, solver, channels, axial_sums, end, position, wall)
    }
}

/// What a set's summary and checkpoint are written from.
struct Context<'a> {
    kind: Option<rolldyn::quasistatic::system::SetKind>,
    mounting_preload: Option<f64>,
    mounted: &'a [rolldyn::quasistatic::system::MountedBearing],
    cold: &'a rolldyn::quasistatic::system::SystemEquilibrium,
    settings: &'a rolldyn_case::simulation::SolverSettings,
    duration: f64,
    balance0: rolldyn::integrate::EnergyBalance,
    dir: &'a Path,
    record_hash: u64,
}

impl Context<'_> {
    /// Writes the checkpoint (when `position` is given) and
    /// `summary.json`, each atomically, in that order (after the series'
    /// rows); `end` None: a checkpoint during the run (status `partial`).
    #[allow(clippy::too_many_arguments)]
    fn write(
        &self,
        system: &ShaftDynamics,
        solver: &Solver,
        channels: &[Channels],
        axial_sums: &[f64],
        end: Option<&RunEnd>,
        position: Option<Position>,
        wall: f64,
    ) -> Result<SetSummary, Failure> {
        let bytes = position.map(|position| {
            let stats: Vec<&RunStatistics> = channels.iter().map(|c| &c.stats).collect();
            checkpoint::encode_parts(
                self.record_hash,
                position,
                solver,
                system,
                &stats,
                axial_sums,
            )
        });
        let summary = self.summarise(system, solver, channels, axial_sums, end, wall);
        checkpoint::persist(self.dir, bytes, &summary)?;
        Ok(summary)
    }

    fn summarise(
        &self,
        system: &ShaftDynamics,
        solver: &Solver,
        channels: &[Channels],
        axial_sums: &[f64],
        end: Option<&RunEnd>,
        wall: f64,
    ) -> SetSummary {
        let balance = rolldyn::integrate::OdeSystem::energy_balance(system, solver.t(), solver.y())
            .unwrap_or_default();
        let change = balance.mechanical - self.balance0.mechanical;
        // Bearing 0's kinematics for the characteristic lines of
        // `rolldyn spectrum` (as a single bearing's summary gives them).
        let first = channels[0].stats.window();
        let g = system.bearing(0).geometry();
        let stats = solver.stats();
        let samples = channels[0].rows();
        let (status, error) = match end {
            None => (
                "partial",
                Some(format!(
                    "checkpoint at t = {:.6} s of a run in progress (or killed); `rolldyn run --resume {}` continues it",
                    solver.t(),
                    self.dir.display()
                )),
            ),
            Some(RunEnd::Completed) => ("completed", None),
            Some(RunEnd::Interrupted { .. }) => ("interrupted", None),
            Some(RunEnd::Failed { error }) => ("failed", Some(error.to_string())),
        };
        SetSummary {
            status,
            error,
            kind: self.kind.map_or("shaft", kind_name),
            mounting_preload_n: self.mounting_preload,
            requested_duration_s: self.duration,
            simulated_time_s: solver.t(),
            wall_time_s: wall,
            integrator: self.settings.integrator,
            relative_tolerance: self.settings.relative_tolerance,
            energy_tolerance: self.settings.energy_tolerance,
            steps: stats.steps,
            rejected_steps: stats.rejected_steps,
            rhs_evaluations: stats.rhs_evaluations,
            samples,
            averaging_window_s: first.span(),
            inner_ring_speed_rpm: first.mean("inner_ring_speed_rpm"),
            final_inner_ring_speed_rpm: channels[0].stats.last("inner_ring_speed_rpm"),
            mean_cage_speed_rpm: first.mean("cage_speed_rpm"),
            ball_count: g.ball_count,
            ball_diameter_m: g.ball_diameter,
            pitch_diameter_m: g.pitch_diameter,
            mean_contact_angle_inner_deg: first.loaded_mean("contact_angle_inner_deg"),
            mean_contact_angle_outer_deg: first.loaded_mean("contact_angle_outer_deg"),
            drive_work_j: balance.work,
            dissipated_energy_j: balance.dissipated,
            mechanical_energy_change_j: change,
            energy_balance_relative_error: ((balance.work - balance.dissipated) - change).abs()
                / balance
                    .work
                    .abs()
                    .max(balance.dissipated.abs())
                    .max(change.abs())
                    .max(f64::MIN_POSITIVE),
            bearings: channels
                .iter()
                .enumerate()
                .map(|(i, c)| {
                    let m = &self.mounted[i];
                    let w = c.stats.window();
                    SetBearingSummary {
                        position_m: m.position,
                        orientation: match m.orientation {
                            Orientation::Forward => "forward",
                            Orientation::Reversed => "reversed",
                        },
                        quasistatic_axial_load_n: self.cold.bearings[i]
                            .as_ref()
                            .map_or(0.0, |e| e.reaction[0]),
                        mean_axial_load_n: axial_sums[i] / samples.max(1) as f64,
                        mean_cage_speed_rpm: w.mean("cage_speed_rpm"),
                        mean_inner_load_n: w.loaded_mean("load_inner_n"),
                        largest_inner_load_n: w.largest_load("inner"),
                        largest_outer_load_n: w.largest_load("outer"),
                        drive_work_j: c.stats.last("drive_work_j"),
                        dissipated_energy_j: c.stats.last("dissipated_energy_j"),
                    }
                })
                .collect(),
            verify: None,
            window_halves: window_halves(channels),
        }
    }
}

/// Each bearing's cage speed and mean inner load over the two halves of
/// its averaging window (none for a bearing whose window cannot be split;
/// the axial load is a mean over the whole run and has no halves).
fn window_halves(channels: &[Channels]) -> Vec<(String, [f64; 2])> {
    let mut halves = Vec::new();
    for (i, c) in channels.iter().enumerate() {
        if let Some([first, second]) = c.stats.window_halves() {
            halves.push((
                format!("bearings.{i}.mean_cage_speed_rpm"),
                [first.mean("cage_speed_rpm"), second.mean("cage_speed_rpm")],
            ));
            halves.push((
                format!("bearings.{i}.mean_inner_load_n"),
                [
                    first.loaded_mean("load_inner_n"),
                    second.loaded_mean("load_inner_n"),
                ],
            ));
        }
    }
    halves
}

/// The quantities a set's `--verify` compares: each bearing's mean axial
/// load, cage speed and mean inner load, keyed `bearings.{i}.{key}`.
fn compared_values(summary: &SetSummary) -> Vec<(String, f64)> {
    summary
        .bearings
        .iter()
        .enumerate()
        .flat_map(|(i, b)| {
            [
                ("mean_axial_load_n", b.mean_axial_load_n),
                ("mean_cage_speed_rpm", b.mean_cage_speed_rpm),
                ("mean_inner_load_n", b.mean_inner_load_n),
            ]
            .map(|(key, value)| (format!("bearings.{i}.{key}"), value))
        })
        .collect()
}

/// [`run`], then with `options.verify` the case again into `DIR/verify/`
/// at ten times tighter tolerances and a two-fold finer traction grid
/// (as a single bearing's `--verify`), each bearing's mean axial load,
/// cage speed and mean inner load compared (limit 1 %) in the summary's
/// `verify`; when they moved and the run has a grid, a third run with
/// the grid refined alone (`DIR/verify-grid/`) tells the grid's share.
pub fn run_and_verify(
    record: &RunRecord,
    case: &Case,
    dir: &Path,
    options: &RunOptions,
) -> Result<SetSummary, Failure> {
    let mut summary = run(record, case, dir, options)?;
    if !options.verify || summary.status != "completed" {
        return Ok(summary);
    }
    // A set's fixed step is left as it is (its summary does not state it).
    let (tight, tight_case, traction_grid) = crate::accuracy::verifying_case(
        record,
        case,
        crate::accuracy::RunTolerances {
            relative: summary.relative_tolerance,
            energy: summary.energy_tolerance,
            fixed_step: None,
        },
    );
    let verify_dir = dir.join(RunDir::VERIFY);
    let quiet = RunOptions {
        quiet: true,
        progress: None,
        verify: false,
        ..options.clone()
    };
    let reference = run(&tight, &tight_case, &verify_dir, &quiet)?;
    if reference.status != "completed" {
        return Err(Failure::Model(format!(
            "--verify: the run at ten times tighter tolerances in {} ended {}: {}",
            verify_dir.display(),
            reference.status,
            reference.error.unwrap_or_default()
        )));
    }
    let values = compared_values(&summary);
    let mut changes = Vec::new();
    let mut worst: f64 = 0.0;
    for ((key, value), (_, reference_value)) in values.into_iter().zip(compared_values(&reference))
    {
        if reference_value == 0.0 || !value.is_finite() || !reference_value.is_finite() {
            continue;
        }
        let relative_change = (value - reference_value).abs() / reference_value.abs();
        worst = worst.max(relative_change / VERIFY_LIMIT_MEANS);
        let window_spread = Change::window_spread(&summary.window_halves, &key, value);
        changes.push(Change {
            key: key.into(),
            value,
            reference: reference_value,
            relative_change,
            limit: VERIFY_LIMIT_MEANS,
            window_spread,
            grid_change: None,
        });
    }
    let cause = Verification::cause_of(&changes);
    let mut verification = Verification {
        relative_tolerance: reference.relative_tolerance,
        energy_tolerance: reference.energy_tolerance,
        traction_grid,
        directory: verify_dir.display().to_string(),
        wall_time_s: reference.wall_time_s,
        energy_balance_relative_error: reference.energy_balance_relative_error,
        changes,
        worst_ratio_to_limit: worst,
        status: if worst <= 1.0 { "ok" } else { "warning" },
        cause,
    };
    // Whether the grid or the tolerances moved it: the grid refined alone.
    if verification.wants_grid_run() {
        let (record, case) = crate::accuracy::grid_case(record, case);
        let grid = run(&record, &case, &dir.join(RunDir::VERIFY_GRID), &quiet)?;
        if grid.status == "completed" {
            let values = compared_values(&grid);
            verification
                .attribute_to_grid(|key| values.iter().find(|(k, _)| k == key).map(|(_, v)| *v));
        }
    }
    summary.verify = Some(verification);
    crate::checkpoint::persist(dir, None, &summary)?;
    Ok(summary)
}
