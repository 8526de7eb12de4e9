//! `rolldyn` — the command-line front end of the rolldyn bearing engine.
//!
//! Exit codes (docs/cli.md): 0 success; 2 user error (case file, override,
//! argument, an output path that cannot be written); 3 the model failed
//! (a quasi-static solve did not converge, a run's integration failed);
//! 130 a run interrupted by Ctrl-C (its files hold what was computed);
//! 1 an internal error.

use clap::{Args, Parser, Subcommand};
use rolldyn_case::presets;
use rolldyn_case::units::{Quantity, Time};
use rolldyn_cli::{
    CaseArgs, CaseOverrides, DEFAULT_RUN_DIR, Failure, bad_arg, catalogue, checkpoint, contact,
    emit, html_report, json, parse_angle, power, quasistatic, report, run, run_options, run_sweep,
    spectrum, thermal, traction,
};
use std::process::ExitCode;

#[derive(Parser)]
#[command(name = "rolldyn", version, about = "Ball-bearing dynamics: cage slip and skidding, contact loads and traction, cage whirl, vibration spectra, friction power and temperatures", long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Validate a case and print the derived geometry, contact constants,
    /// frequencies and assumptions.
    Check {
        #[command(flatten)]
        case: CaseArgs,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Characteristic frequencies: cage, BPFO, BPFI, ball spin, waviness lines.
    Frequencies {
        #[command(flatten)]
        case: CaseArgs,
        /// Contact angle to use, e.g. "15 deg" (default: nominal angle).
        #[arg(long, value_name = "ANGLE", allow_hyphen_values = true)]
        angle: Option<String>,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Hertz contact of one ball on the inner and outer raceway, or of an
    /// explicit contact (--radii, --ball-on-flat); with
    /// --entrainment-speed also the lubricant film (starved, Λ, K_oil).
    Contact(Box<contact::ContactArgs>),
    /// Quasi-static equilibrium: static load distribution (no speed) or the
    /// Jones–Harris model at the case speed; per-ball table, ring
    /// displacement, cage speed, stiffness. With --sweep: a sweep written
    /// as CSV and JSON.
    Quasistatic(Box<QuasistaticArgs>),
    /// Friction power loss at the Jones–Harris equilibrium by Harris's
    /// local method (Lei et al. 2023): hysteresis, differential sliding and spin
    /// per raceway, cage land, ball–pocket, drag; total and friction torque.
    Power(Box<power::PowerArgs>),
    /// Bearing temperatures from the thermal network (Lei et al. 2023), coupled to
    /// the power loss through the oil viscosity and the operating
    /// clearance; --transient adds the warm-up.
    Thermal(Box<thermal::ThermalArgs>),
    /// Dynamic simulation: writes DIR/timeseries.parquet and DIR/summary.json
    /// (also after Ctrl-C). Without CASE: the built-in default (7008C,
    /// 10 000 rpm, F_x = 200 N, EHL traction, 0.05 s).
    Run(Box<RunArgs>),
    /// Write DIR/report.html: one self-contained HTML file (inline SVG, no
    /// network, no script) with the case, summary, solver statistics and
    /// plots of a run directory, or the swept quantities of a sweep
    /// directory.
    Report {
        /// A directory written by `rolldyn run` or by a sweep.
        #[arg(value_name = "DIR")]
        dir: String,
    },
    /// Traction of one ball–raceway contact with the case's traction model
    /// (FASTSIM, Coulomb, curve, EHL), or of an explicit ellipse with
    /// FASTSIM (--semi-axes): forces, spin moment, power, stick fraction;
    /// --map writes FASTSIM's stick/slip map as CSV.
    Traction(Box<traction::TractionArgs>),
    /// Spectrum of one channel of a run (amplitude, Welch PSD or envelope)
    /// with the bearing's characteristic lines from the run's speeds, a
    /// peak list naming the nearest line, and the vibration velocity RMS;
    /// writes `DIR/spectrum_<channel>_<kind>.csv` and `.json`.
    Spectrum(Box<spectrum::SpectrumArgs>),
    /// List the built-in bearings.
    Presets {
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Print a complete, commented case file to start from: a preset, or
    /// a catalogue bearing with estimated internal geometry.
    New {
        /// Preset name (see `rolldyn presets`); default 7008C.
        #[arg(long, conflicts_with = "bearing")]
        preset: Option<String>,
        /// Catalogue designation, e.g. 6205 or 7210B (see `rolldyn
        /// catalogue`; internal geometry estimated, docs/catalogue.md).
        #[arg(long, value_name = "DESIGNATION")]
        bearing: Option<String>,
        /// ISO 5753-1 clearance group of a deep-groove catalogue bearing:
        /// C2, CN (default), C3 or C4.
        #[arg(long, value_name = "GROUP", requires = "bearing")]
        clearance: Option<String>,
    },
    /// List the catalogue bearings (ISO 15 60/62/63 and 70/72/73 series)
    /// with their estimated ball sets and ISO 281/76 ratings.
    Catalogue {
        /// Only this series, e.g. 62 or 72.
        #[arg(long)]
        series: Option<String>,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Print the JSON Schema of the case-file format.
    Schema,
}

/// Arguments of `rolldyn quasistatic`.
#[derive(Args)]
struct QuasistaticArgs {
    #[command(flatten)]
    case: CaseArgs,
    /// Raceway control: outer, inner or harris (default: the case's
    /// model.raceway_control, else outer); or traction: ball speeds from
    /// the force and moment balance with the case's traction model.
    #[arg(long, value_name = "CONTROL")]
    control: Option<String>,
    /// Sweep a variable: speed=0rpm..20000rpm/11 (linear range) or
    /// axial=10N,100N,1kN (list); also radial=... Repeat for a grid.
    #[arg(long, value_name = "NAME=VALUES", allow_hyphen_values = true)]
    sweep: Vec<String>,
    /// Output directory of a sweep (sweep.csv, sweep.json).
    #[arg(short, long, value_name = "DIR", default_value = "quasistatic-sweep")]
    output: String,
    /// Solve a sweep of more than 1 000 000 points.
    #[arg(long)]
    force: bool,
    /// Print JSON instead of text.
    #[arg(long)]
    json: bool,
}

/// Arguments of `rolldyn run`. A prescribed tilt (`--misalignment`) is
/// quasi-static only and refused by a dynamic run, so its help does not
/// offer it; `--fix-tilt` holds both tilts at zero in a run too.
#[derive(Args)]
#[command(mut_arg("misalignment", |a| a.hide(true)))]
struct RunArgs {
    #[command(flatten)]
    case: CaseArgs,
    /// Output directory.
    #[arg(short, long, value_name = "DIR", default_value = DEFAULT_RUN_DIR)]
    output: String,
    /// Simulated time, e.g. "0.01 s" (overrides solver.duration).
    #[arg(long, value_name = "TIME", allow_hyphen_values = true)]
    duration: Option<String>,
    /// Run even when the estimated steps or time-series memory exceed
    /// the limits (docs/cli.md).
    #[arg(long)]
    force: bool,
    /// Continue the interrupted run in DIR (killed, Ctrl-C) from its
    /// last checkpoint, bit-identically; the case comes from
    /// DIR/run.json (give no case, overrides or --output).
    #[arg(long, value_name = "DIR")]
    resume: Option<String>,
    /// With --resume: extend the run (finished or not) to this
    /// simulated time, e.g. "2 s" (its new solver.duration).
    #[arg(long, value_name = "TIME", allow_hyphen_values = true)]
    until: Option<String>,
    /// Wall time between checkpoints (time series, state), e.g.
    /// "10 s"; default 30 s. Never more often than keeps their cost
    /// under 2 % of the run.
    #[arg(long, value_name = "TIME", allow_hyphen_values = true)]
    checkpoint_interval: Option<String>,
    /// Also write DIR/report.html (as `rolldyn report DIR`).
    #[arg(long)]
    report: bool,
    /// After the run, run the case again into DIR/verify/ at ten times
    /// tighter tolerances and a two-fold finer traction grid, and report
    /// how much the cage speed, loads, power loss and vibration RMS
    /// moved (summary.json's accuracy.verify)
    #[arg(long)]
    verify: bool,
    /// Run a sweep: speed=0rpm..20000rpm/5 (linear range) or
    /// axial=100N,1kN (list); also radial=..., and any case key with a
    /// list of values (--set syntax; entries of arrays of tables by
    /// index), e.g. "surface.outer.spall.0.length=0.18 mm,0.36 mm",
    /// whose values label the rows. Repeat for a grid. The points run in
    /// parallel, each into DIR/point-NNNN/, with a combined
    /// DIR/sweep.csv and DIR/sweep.json.
    #[arg(long, value_name = "NAME=VALUES", allow_hyphen_values = true)]
    sweep: Vec<String>,
    /// With --sweep: N runs at random points instead of the grid (Monte
    /// Carlo): each --sweep NAME=LOW..HIGH is drawn uniformly, each list
    /// NAME=a,b,c by choice; the draws are labelled in sweep.csv
    #[arg(long, value_name = "N", requires = "sweep")]
    sample: Option<usize>,
    /// Seed of --sample's draws (the same seed, the same points)
    #[arg(long, value_name = "S", default_value_t = 0, requires = "sample")]
    seed: u64,
}

fn run(cli: Cli) -> Result<(), Failure> {
    match cli.command {
        Command::Check {
            case,
            json: as_json,
        } => {
            let (source, case) = case.load()?;
            let report = report::CheckReport::new(&source, &case).map_err(Failure::BadInput)?;
            if as_json {
                json(&report)
            } else {
                emit(&report.to_text())
            }
        }
        Command::Frequencies {
            case,
            angle,
            json: as_json,
        } => {
            let angle = parse_angle("--angle", angle.as_ref())?;
            let (_, case) = case.load()?;
            let report = report::FrequencyReport::new(&case, angle).map_err(Failure::BadInput)?;
            if as_json {
                json(&report)
            } else {
                emit(&report.to_text())
            }
        }
        Command::Contact(args) => contact::command(*args),
        Command::Quasistatic(args) => quasistatic_command(*args),
        Command::Run(args) => run_command(*args),
        Command::Report { dir } => {
            let path = html_report::write(std::path::Path::new(&dir))?;
            emit(&format!("wrote {}\n", path.display()))
        }
        Command::Traction(args) => traction::command(*args),
        Command::Power(args) => power::command(*args),
        Command::Thermal(args) => thermal::command(*args),
        Command::Spectrum(args) => spectrum::command(*args),
        Command::Presets { json: as_json } => {
            let list: Vec<report::PresetEntry> = presets::PRESETS
                .iter()
                .map(report::PresetEntry::from)
                .collect();
            if as_json {
                json(&list)
            } else {
                let mut text = String::new();
                for p in &list {
                    text.push_str(&format!("{:<15} {}\n", p.name, p.summary));
                }
                emit(&text)
            }
        }
        Command::New {
            preset,
            bearing,
            clearance,
        } => match bearing {
            Some(designation) => emit(&catalogue::case_text(&designation, clearance.as_deref())?),
            None => {
                let preset = preset.unwrap_or_else(|| presets::DEFAULT_PRESET.to_string());
                match presets::find(&preset) {
                    Some(p) => emit(p.text),
                    None => Err(bad_arg(
                        "--preset",
                        &preset,
                        format!("unknown preset; available: {}", presets::names()),
                    )),
                }
            }
        },
        Command::Catalogue {
            series,
            json: as_json,
        } => {
            let list = catalogue::entries(series.as_deref())?;
            if as_json {
                json(&list)
            } else {
                emit(&catalogue::table(&list))
            }
        }
        Command::Schema => json(&rolldyn_case::json_schema()),
    }
}

/// `rolldyn quasistatic`: one solve, or a sweep written as CSV and JSON.
fn quasistatic_command(args: QuasistaticArgs) -> Result<(), Failure> {
    let QuasistaticArgs {
        case,
        control,
        sweep,
        output,
        force,
        json: as_json,
    } = args;
    let control = quasistatic::ControlChoice::parse(control.as_deref())?;
    let sweeps = sweep
        .iter()
        .map(|s| quasistatic::parse_sweep(s).map_err(|e| bad_arg("--sweep", s, e)))
        .collect::<Result<Vec<_>, _>>()?;
    let points = sweeps
        .iter()
        .fold(1f64, |n, (_, values)| n * values.len() as f64);
    if points > quasistatic::MAX_SWEEP_POINTS && !force {
        return Err(Failure::BadInput(format!(
            "--sweep: the grid has {points:.3e} points, above the limit of {:.0e} (time and memory); use fewer points or pass --force",
            quasistatic::MAX_SWEEP_POINTS
        )));
    }
    let (_, case) = case.load()?;
    if sweeps.is_empty() {
        let output = quasistatic::solve(&case, control)?;
        if as_json {
            json(&output)
        } else {
            emit(&output.to_text())
        }
    } else {
        let quasistatic::ControlChoice::Raceway(control) = control else {
            return Err(bad_arg(
                "--control",
                "traction",
                "not with --sweep (solve the points one by one)",
            ));
        };
        let rows = quasistatic::sweep_case(&case, control, &sweeps)?;
        let json_text = rows.write(std::path::Path::new(&output))?;
        if as_json {
            emit(&(json_text + "\n"))
        } else {
            emit(&format!(
                "{}; wrote {output}/sweep.csv and {output}/sweep.json\n",
                rows.summary()
            ))
        }
    }
}

/// `rolldyn run`: one run (of a bearing, a set or a shaft), its
/// resumption or extension, or a sweep of runs.
fn run_command(args: RunArgs) -> Result<(), Failure> {
    if let (Some(t), None) = (&args.until, &args.resume) {
        return Err(bad_arg(
            "--until",
            t,
            "extends a run: give it with --resume DIR",
        ));
    }
    let checkpoint_interval = checkpoint_interval(args.checkpoint_interval.as_deref())?;
    if !args.sweep.is_empty() {
        return run_sweep_command(args, checkpoint_interval);
    }
    let (with_report, verify) = (args.report, args.verify);
    let resuming = args.resume.is_some();
    let (record, output, extends) = run_record(args)?;
    let case = record
        .overrides
        .load_text(&record.source, record.case_text.as_deref())?;
    if let Some(warning) = run::odd_grid_warning(&case) {
        eprintln!("warning: {warning}");
    }
    let dir = std::path::Path::new(&output);
    let options = run_options::RunOptions {
        force: record.force,
        checkpoint_interval,
        resume: resuming,
        extends,
        verify,
        active_helpers: true,
        ..Default::default()
    };
    if case.bearing_set().is_some() || case.shaft.is_some() {
        let summary = rolldyn_cli::run_set::run_and_verify(&record, &case, dir, &options)?;
        print_set_run(summary, &output, with_report)
    } else {
        let summary = run::run_case(&record, &case, dir, &options)?;
        print_run(summary, &output, with_report)
    }
}

/// `--checkpoint-interval` in seconds (default 30 s).
fn checkpoint_interval(arg: Option<&str>) -> Result<f64, Failure> {
    let Some(t) = arg else {
        return Ok(run_options::DEFAULT_CHECKPOINT_INTERVAL);
    };
    let v = Quantity::<Time>::parse(t)
        .map_err(|e| bad_arg("--checkpoint-interval", t, e))?
        .si;
    if !(0.0..=1e6).contains(&v) {
        return Err(bad_arg(
            "--checkpoint-interval",
            t,
            "must lie in [0, 1e6] s",
        ));
    }
    Ok(v)
}

/// `rolldyn run --sweep`.
fn run_sweep_command(args: RunArgs, checkpoint_interval: f64) -> Result<(), Failure> {
    if args.verify {
        return Err(Failure::BadInput(
            "argument --verify: not with --sweep: each point's summary.json holds its accuracy; to verify a point, run its case alone with --verify".into(),
        ));
    }
    if let Some(dir) = args.resume {
        return Err(bad_arg(
            "--resume",
            &dir,
            "not with --sweep: resume one point with --resume DIR/point-NNNN",
        ));
    }
    let options = run_options::RunOptions {
        force: args.force,
        checkpoint_interval,
        ..Default::default()
    };
    let draw = args.sample.map(|count| run_sweep::Sampling {
        count,
        seed: args.seed,
    });
    run_sweep::command(
        args.case,
        &args.sweep,
        draw,
        args.duration,
        &args.output,
        &options,
        args.report,
    )
}

/// The run's record (a new run's, or the one `--resume` continues, with
/// `--until`'s duration), its directory, and the hash of the record an
/// extended run's checkpoint belongs to.
fn run_record(args: RunArgs) -> Result<(checkpoint::RunRecord, String, Option<u64>), Failure> {
    let RunArgs {
        mut case,
        output,
        duration,
        force,
        resume,
        until,
        ..
    } = args;
    let mut extends = None;
    let (record, output) = match resume {
        Some(dir) => {
            let given = case.case.is_some()
                || case.overrides != CaseOverrides::default()
                || duration.is_some()
                || force
                || output != DEFAULT_RUN_DIR;
            if given {
                return Err(bad_arg(
                    "--resume",
                    &dir,
                    "takes the case, overrides, duration and output directory from DIR/run.json; give none of them",
                ));
            }
            let mut record = checkpoint::RunRecord::read(std::path::Path::new(&dir))
                .map_err(Failure::BadInput)?;
            if let Some(t) = &until {
                let v = Quantity::<Time>::parse(t)
                    .map_err(|e| bad_arg("--until", t, e))?
                    .si;
                if !(v.is_finite() && v > 0.0) {
                    return Err(bad_arg("--until", t, "must be a positive time"));
                }
                // The record the checkpoint belongs to, then the
                // extended one (its duration overridden last).
                extends = Some(record.hash());
                record.overrides.set.push(format!("solver.duration={v} s"));
            }
            (record, dir)
        }
        None => {
            if let Some(d) = duration {
                // A time with its unit, refused as every quantity option
                // refuses a bare number.
                Quantity::<Time>::parse(&d).map_err(|e| bad_arg("--duration", &d, e))?;
                case.overrides.set.push(format!("solver.duration={d}"));
            }
            case.overrides.overrides()?;
            let (source, text) = case.read()?;
            (
                checkpoint::RunRecord::new(source, text, case.overrides, force),
                output,
            )
        }
    };
    Ok((record, output, extends))
}

/// Prints a set's or shaft's run (and writes its report when asked).
fn print_set_run(
    summary: rolldyn_cli::run_set::SetSummary,
    output: &str,
    with_report: bool,
) -> Result<(), Failure> {
    let dir = std::path::Path::new(output);
    let mut text = format!(
        "{}: {} system, simulated {:.4} s of {:.4} s in {:.1} s wall ({}: {} steps, {} rejected, {} RHS); energy balance error {:.2e}\n",
        summary.status,
        summary.kind,
        summary.simulated_time_s,
        summary.requested_duration_s,
        summary.wall_time_s,
        summary.integrator,
        summary.steps,
        summary.rejected_steps,
        summary.rhs_evaluations,
        summary.energy_balance_relative_error,
    );
    for (i, b) in summary.bearings.iter().enumerate() {
        text += &format!(
            "  bearing {i} ({}, {:+.1} mm): axial load {:.2} N (quasi-static {:.2} N), cage {:.1} rpm, largest contact loads {:.1} / {:.1} N\n",
            b.orientation,
            b.position_m * 1e3,
            b.mean_axial_load_n,
            b.quasistatic_axial_load_n,
            b.mean_cage_speed_rpm,
            b.largest_inner_load_n,
            b.largest_outer_load_n
        );
    }
    text += &format!(
        "wrote {output}/timeseries.parquet ({} samples) and {output}/summary.json\n",
        summary.samples
    );
    emit(&text)?;
    if let Some(v) = &summary.verify {
        emit(&v.line())?;
        if v.status != "ok" {
            let verdict = if v.cause == Some(rolldyn_cli::accuracy::Cause::Grid) {
                "the finer traction grid alone moves them as much (`grid_change` in summary.json): refine the grid"
            } else {
                "they are not converged at these settings"
            };
            eprintln!(
                "warning: --verify: the set's results moved beyond 1 % at ten times tighter tolerances and a finer traction grid; {verdict}"
            );
        }
    }
    if summary.energy_balance_relative_error > 1e-3 {
        eprintln!(
            "warning: the energy balance closes only to {:.2e} (a converged run: ≤ 1e-3); tighten solver.relative_tolerance",
            summary.energy_balance_relative_error
        );
    }
    let end = (summary.status, summary.error, summary.simulated_time_s);
    finish_run(dir, output, with_report, end, "")
}

/// Prints a bearing's run (and writes its report when asked).
fn print_run(summary: run::Summary, output: &str, with_report: bool) -> Result<(), Failure> {
    let dir = std::path::Path::new(output);
    let text = format!(
        "{}: simulated {:.4} s of {:.4} s in {:.1} s wall ({}: {} steps, {} rejected, {} RHS, {} Jacobians costing {} RHS, {} fast-part Jacobians, {} factorizations)\nmean cage speed {:.1} rpm (pure rolling {:.1} rpm, sliding rate {:+.4}); energy balance error {:.2e} (accuracy {})\nwrote {}/timeseries.parquet ({} samples) and {}/summary.json\n",
        summary.status,
        summary.simulated_time_s,
        summary.requested_duration_s,
        summary.wall_time_s,
        summary.integrator,
        summary.steps,
        summary.rejected_steps,
        summary.rhs_evaluations,
        summary.jacobian_evaluations,
        summary.jacobian_rhs_evaluations,
        summary.fast_part_jacobians,
        summary.factorizations,
        summary.mean_cage_speed_rpm,
        summary.pure_rolling_cage_speed_rpm,
        summary.cage_sliding_rate,
        summary.energy_balance_relative_error,
        summary.accuracy.status,
        output,
        summary.samples,
        output
    );
    emit(&text)?;
    if let Some(sensor) = summary.sensor.as_ref().filter(|s| s.clipped_samples > 0) {
        eprintln!(
            "warning: sensor: {} samples beyond the ADC's range were clipped; raise sensor.full_scale",
            sensor.clipped_samples
        );
    }
    for (k, g) in summary.spall_growth.iter().flatten().enumerate() {
        if g.stalled {
            eprintln!(
                "warning: growing spall {k} reached {:.3} mm of the {:.3} mm its growth_rate asks: a spall grows only while no ball is on it, and once longer than the balls' spacing along its raceway ({:.2} mm on the pitch circle) a ball always is (docs/dynamics.md, \"Spall growth\")",
                g.length_m * 1e3,
                g.asked_length_m * 1e3,
                std::f64::consts::PI * summary.pitch_diameter_m / summary.ball_count as f64 * 1e3
            );
        }
    }
    if let Some(v) = &summary.accuracy.verify {
        emit(&v.line())?;
    }
    if let Some(text) = rolldyn_cli::accuracy::warning(&summary.accuracy) {
        eprint!("{text}");
    }
    // An integration failure has a hint; a state beyond the models'
    // range says what to change itself.
    let hint = if summary
        .error
        .as_deref()
        .is_some_and(|e| e.contains("left the models' range"))
    {
        ""
    } else {
        ". Try a smaller solver.max_step or solver.relative_tolerance, or another solver.integrator"
    };
    let end = (summary.status, summary.error, summary.simulated_time_s);
    finish_run(dir, output, with_report, end, hint)
}

/// The end of every run: its report (asked, or one already there), and
/// the exit its `(status, error, simulated time)` gives: a failed run 3
/// (with `hint`), an interrupted one 130 (Ctrl-C).
fn finish_run(
    dir: &std::path::Path,
    output: &str,
    with_report: bool,
    (status, error, reached): (&str, Option<String>, f64),
    hint: &str,
) -> Result<(), Failure> {
    if let Some(path) = html_report::refresh(dir, with_report)? {
        emit(&format!("wrote {}\n", path.display()))?;
    }
    match status {
        "failed" => Err(Failure::Model(format!(
            "{}; the files hold the run up to t = {reached:.6} s{hint}",
            error.unwrap_or_default(),
        ))),
        "interrupted" => Err(Failure::Interrupted(format!(
            "interrupted at t = {reached:.6} s; {output}/ holds what was computed; `rolldyn run --resume {output}` continues the run",
        ))),
        _ => Ok(()),
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    // The command runs on a thread of rayon's pool, so that the engine's
    // parallel passes over the balls hand work to the other threads
    // without waking this one from outside the pool each time.
    match rayon::scope(|_| run(cli)) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::BadInput(msg)) => {
            eprintln!("error: {msg}");
            ExitCode::from(2)
        }
        Err(Failure::Model(msg)) => {
            eprintln!("error: {msg}");
            ExitCode::from(3)
        }
        Err(Failure::Interrupted(msg)) => {
            eprintln!("{msg}");
            ExitCode::from(130)
        }
        Err(Failure::Internal(msg)) => {
            eprintln!("error: {msg}");
            ExitCode::from(1)
        }
    }
}
