//! The report of a `rolldyn run` directory: `summary.json`,
//! `timeseries.parquet` and `run.json` (how the run was asked for).
//!
//! Sections, in order: summary, case and assumptions, solver statistics,
//! cage speed against pure rolling, contact loads and angles per ball,
//! slide- and spin-to-roll, cage orbit, vibration (a run with a spall:
//! [`crate::vibration`]), energy balance, friction power
//! (and temperatures when a thermal network was coupled), all summary
//! values. Each is one function of [`SECTIONS`]; a section whose channels
//! the run did not record is left out.

use crate::svg::{Plot, Series, Style};
use crate::{Block, Report, ReportError, Section, cell, read_json};
use rolldyn_io::{TimeSeries, float_columns, for_each_batch, read_schema, row_count};
use serde_json::Value;
use std::collections::{HashMap, VecDeque};
use std::path::Path;

/// File names of a run directory.
pub const SUMMARY_FILE: &str = "summary.json";
/// The time series' file name.
pub const TIMESERIES_FILE: &str = "timeseries.parquet";
/// The channels recorded at `output.slow_rate`, when there are any.
pub const SLOW_TIMESERIES_FILE: &str = "timeseries_slow.parquet";
/// How the run was asked for (case text, overrides).
pub const RECORD_FILE: &str = "run.json";

/// What the sections read.
pub struct RunData {
    /// `summary.json`.
    pub summary: Value,
    /// `timeseries.parquet`'s channels for the plots: every sample, or for
    /// a long record the extremes of [`PLOT_ROWS`]/2 equal buckets (what
    /// a plot of it shows); the other balls' channels are left out.
    pub series: TimeSeries,
    /// The channels recorded at `output.slow_rate`
    /// (`timeseries_slow.parquet`), reduced alike, when there are any.
    pub slow: Option<TimeSeries>,
    /// Each channel's mean over the summary's averaging window.
    pub window_means: HashMap<String, f64>,
    /// The cage centre's (y, z) over the last [`PLOT_ROWS`] samples.
    pub orbit: Option<(Vec<f64>, Vec<f64>)>,
    /// `run.json`, when present.
    pub record: Option<Value>,
    /// The case as `rolldyn check` describes it, when known.
    pub case_description: Option<String>,
    /// Time and the inner ring's vertical acceleration over the averaging
    /// window, unreduced, for a run with a spall ([`crate::vibration`]).
    pub vibration: Option<crate::vibration::Record>,
    /// The same over the whole run (its last
    /// [`crate::vibration::MAX_SAMPLES`]) when the shaft speed changes.
    pub run_up: Option<crate::vibration::Record>,
}

impl RunData {
    fn number(&self, key: &str) -> Option<f64> {
        self.summary.get(key).and_then(Value::as_f64)
    }

    fn text(&self, key: &str) -> Option<&str> {
        self.summary.get(key).and_then(Value::as_str)
    }

    /// The series that holds channel `name` (the slow one for a channel
    /// recorded at the slow rate).
    fn series_of(&self, name: &str) -> Option<&TimeSeries> {
        std::iter::once(&self.series)
            .chain(self.slow.as_ref())
            .find(|s| s.column(name).is_some_and(|c| !c.is_empty()))
    }

    pub(crate) fn channel(&self, name: &str) -> Option<&[f64]> {
        self.series_of(name)?.column(name)
    }

    /// The times of channel `name`'s samples.
    pub(crate) fn time_of(&self, name: &str) -> &[f64] {
        self.series_of(name)
            .and_then(|s| s.column("time_s"))
            .unwrap_or(&[])
    }

    fn ball_count(&self) -> usize {
        (0..)
            .take_while(|j| {
                self.window_means
                    .contains_key(&format!("ball{j}_load_inner_n"))
            })
            .count()
    }

    /// Mean of a channel over the summary's averaging window.
    fn window_mean(&self, name: &str) -> Option<f64> {
        self.window_means.get(name).copied()
    }

    /// Per-ball window means of a per-ball channel (`ball{j}_{suffix}`).
    fn per_ball(&self, suffix: &str) -> Vec<f64> {
        (0..self.ball_count())
            .map(|j| {
                self.window_mean(&format!("ball{j}_{suffix}"))
                    .unwrap_or(f64::NAN)
            })
            .collect()
    }

    /// A channel against time in milliseconds.
    fn against_time(&self, name: &str, legend: &str, scale: f64) -> Option<Series> {
        let t: Vec<f64> = self.time_of(name).iter().map(|t| 1e3 * t).collect();
        let y: Vec<f64> = self.channel(name)?.iter().map(|v| scale * v).collect();
        Some(Series::line(legend, &t, &y))
    }
}

/// A section builder: `None` when the run has nothing for it.
type SectionBuilder = fn(&RunData) -> Option<Section>;

/// The run report's sections in page order. A new model's section is one
/// more function here.
pub const SECTIONS: [SectionBuilder; 11] = [
    summary,
    case,
    solver,
    cage_speed,
    contacts,
    slip,
    cage_orbit,
    crate::vibration::section,
    energy,
    power,
    all_values,
];

/// Reads a run directory and builds its report.
pub fn report(dir: &Path, case_description: Option<String>) -> Result<Report, ReportError> {
    let summary = read_json(&dir.join(SUMMARY_FILE))?;
    let series_path = dir.join(TIMESERIES_FILE);
    let window = match summary.get("averaging_window_s") {
        Some(Value::Array(w)) if w.len() == 2 => [
            w[0].as_f64().unwrap_or(f64::NAN),
            w[1].as_f64().unwrap_or(f64::NAN),
        ],
        _ => [f64::NAN; 2],
    };
    let read = |path: &Path| {
        read_for_plots(path, window).map_err(|e| ReportError::Read {
            path: path.display().to_string(),
            message: e.to_string(),
        })
    };
    let (series, mut window_means, orbit) = read(&series_path)?;
    let slow_path = dir.join(SLOW_TIMESERIES_FILE);
    let slow = if slow_path.is_dir() {
        let (slow, means, _) = read(&slow_path)?;
        for (name, mean) in means {
            window_means.entry(name).or_insert(mean);
        }
        Some(slow)
    } else {
        None
    };
    let (vibration, run_up) =
        crate::vibration::read_records(&series_path, &summary, &series, window).map_err(|e| {
            ReportError::Read {
                path: series_path.display().to_string(),
                message: e.to_string(),
            }
        })?;
    let record = dir
        .join(RECORD_FILE)
        .is_file()
        .then(|| read_json(&dir.join(RECORD_FILE)))
        .transpose()?;
    Ok(build(&RunData {
        summary,
        series,
        slow,
        window_means,
        orbit,
        record,
        case_description,
        vibration,
        run_up,
    }))
}

/// Most rows of a channel the report holds (see [`RunData::series`]).
pub const PLOT_ROWS: usize = 16_384;

/// The report's own channel: the energy balance's error W + F − D − ΔE
/// row by row \[J\].
const BALANCE_ERROR: &str = "energy_balance_error_j";

/// Whether a channel is another ball's than ball 0 (window means only).
fn other_ball(name: &str) -> bool {
    name.strip_prefix("ball")
        .and_then(|rest| rest.split_once('_'))
        .is_some_and(|(j, _)| j != "0")
}

/// One pass over the time series at `path`, one batch in memory: the
/// channels to plot (reduced to bucket extremes when longer than
/// [`PLOT_ROWS`]), every channel's mean over `window` (finite values with
/// t in it) and the cage orbit's last [`PLOT_ROWS`] samples.
#[allow(clippy::type_complexity)]
pub fn read_for_plots(
    path: &Path,
    [t0, t1]: [f64; 2],
) -> Result<
    (
        TimeSeries,
        HashMap<String, f64>,
        Option<(Vec<f64>, Vec<f64>)>,
    ),
    rolldyn_io::InputError,
> {
    let all = read_schema(path)?;
    let rows = row_count(path)? as usize;
    let names = all.names().to_vec();
    let plotted: Vec<usize> = (0..names.len())
        .filter(|&i| !other_ball(&names[i]))
        .collect();
    let mut series = TimeSeries::default();
    for &i in &plotted {
        series.channel(names[i].clone(), all.units()[i].clone());
    }
    let index = |name: &str| names.iter().position(|n| n == name);
    // The energy balance's error is computed row by row, before any
    // reduction (extremes of its terms at different instants would not
    // difference to it).
    let balance = match (
        index("drive_work_j"),
        index("dissipated_energy_j"),
        index("mechanical_energy_j"),
    ) {
        (Some(w), Some(d), Some(e)) => {
            series.channel(BALANCE_ERROR, "J");
            Some((w, index("film_work_j"), d, e))
        }
        _ => None,
    };
    let width = series.width();
    let mut first_energy = None;
    let time = index("time_s");
    let orbit_columns = (
        names.iter().position(|n| n == "cage_y_m"),
        names.iter().position(|n| n == "cage_z_m"),
    );
    // Rows per bucket; each bucket gives two rows (its extremes in order).
    let bucket = if rows > PLOT_ROWS {
        rows.div_ceil(PLOT_ROWS / 2)
    } else {
        1
    };
    // Per plotted channel: (min, its row, max, its row) over the bucket.
    let mut extremes = vec![(f64::INFINITY, 0usize, f64::NEG_INFINITY, 0usize); width];
    let mut in_bucket = 0usize;
    let mut sums = vec![(0.0f64, 0usize); names.len()];
    let mut orbit = VecDeque::new();
    let mut row = vec![0.0; width];
    let mut second = vec![0.0; width];
    let mut values = Vec::with_capacity(width);
    let mut seen = 0usize;
    let mut flush = |extremes: &mut [(f64, usize, f64, usize)], series: &mut TimeSeries| {
        for (k, e) in extremes.iter().enumerate() {
            let (first, last) = if e.1 <= e.3 { (e.0, e.2) } else { (e.2, e.0) };
            row[k] = first;
            second[k] = last;
        }
        series.push(&row);
        series.push(&second);
        extremes.fill((f64::INFINITY, 0, f64::NEG_INFINITY, 0));
    };
    for_each_batch(path, None, |batch| {
        let columns = float_columns(batch)?;
        for r in 0..batch.num_rows() {
            let t = time.map_or(f64::NAN, |i| columns[i][r]);
            if t >= t0 && t <= t1 {
                for (sum, column) in sums.iter_mut().zip(&columns) {
                    if column[r].is_finite() {
                        sum.0 += column[r];
                        sum.1 += 1;
                    }
                }
            }
            if let (Some(y), Some(z)) = orbit_columns {
                if orbit.len() == PLOT_ROWS {
                    orbit.pop_front();
                }
                orbit.push_back((columns[y][r], columns[z][r]));
            }
            values.clear();
            values.extend(plotted.iter().map(|&i| columns[i][r]));
            if let Some((w, f, d, e)) = balance {
                let e0 = *first_energy.get_or_insert(columns[e][r]);
                let film = f.map_or(0.0, |f| columns[f][r]);
                values.push(columns[w][r] + film - columns[d][r] - (columns[e][r] - e0));
            }
            if bucket == 1 {
                series.push(&values);
            } else {
                for (e, &v) in extremes.iter_mut().zip(&values) {
                    // NaN never compares: a bucket of NaN stays a gap.
                    if v < e.0 {
                        (e.0, e.1) = (v, seen);
                    }
                    if v > e.2 {
                        (e.2, e.3) = (v, seen);
                    }
                }
                in_bucket += 1;
                if in_bucket == bucket {
                    flush(&mut extremes, &mut series);
                    in_bucket = 0;
                }
            }
            seen += 1;
        }
        Ok(())
    })?;
    if in_bucket > 0 {
        flush(&mut extremes, &mut series);
    }
    let means = names
        .iter()
        .zip(&sums)
        .filter(|(_, (_, n))| *n > 0)
        .map(|(name, (sum, n))| (name.clone(), sum / *n as f64))
        .collect();
    let orbit = (!orbit.is_empty()).then(|| orbit.into_iter().unzip());
    Ok((series, means, orbit))
}

/// The report of a run's data.
pub fn build(data: &RunData) -> Report {
    let title = data
        .text("title")
        .map(str::to_string)
        .unwrap_or_else(|| "rolldyn run".into());
    let subtitle = format!(
        "{} · {} · {} of {} s simulated",
        data.text("source").unwrap_or("unknown source"),
        data.text("status").unwrap_or("unknown status"),
        cell(data.number("simulated_time_s")),
        cell(data.number("requested_duration_s")),
    );
    Report {
        title,
        subtitle,
        warnings: accuracy_warnings(data),
        sections: SECTIONS
            .iter()
            .filter_map(|f| f(data))
            .filter(|s| !s.blocks.is_empty())
            .collect(),
    }
}

/// The banner of a run that is not converged: its `accuracy` object's
/// reason and hint, and a failed `--verify`.
fn accuracy_warnings(data: &RunData) -> Vec<String> {
    let Some(accuracy) = data.summary.get("accuracy") else {
        return Vec::new();
    };
    let text = |v: &Value, key: &str| v.get(key).and_then(Value::as_str).map(str::to_string);
    let mut out = Vec::new();
    if text(accuracy, "status").as_deref() == Some("warning") {
        out.push(format!(
            "{}. {}.",
            sentence(&text(accuracy, "reason").unwrap_or_default()),
            sentence(&text(accuracy, "hint").unwrap_or_default())
        ));
    }
    if let Some(verify) = accuracy
        .get("verify")
        .filter(|v| text(v, "status").as_deref() == Some("warning"))
    {
        let moved: Vec<String> = verify
            .get("changes")
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
            .filter(|c| {
                let f = |k: &str| c.get(k).and_then(Value::as_f64).unwrap_or(0.0);
                f("relative_change") > f("limit")
            })
            .map(|c| {
                format!(
                    "{} by {:.2} %",
                    text(c, "key").unwrap_or_default(),
                    100.0
                        * c.get("relative_change")
                            .and_then(Value::as_f64)
                            .unwrap_or(0.0)
                )
            })
            .collect();
        out.push(format!(
            "At ten times tighter tolerances (--verify) {} moved beyond their limits: the results are not converged at these settings.",
            moved.join(", ")
        ));
    }
    out
}

/// `text` with its first letter in upper case.
fn sentence(text: &str) -> String {
    let mut chars = text.chars();
    chars
        .next()
        .map(|c| c.to_uppercase().chain(chars).collect())
        .unwrap_or_default()
}

fn rows(data: &RunData, keys: &[(&str, &str)]) -> Vec<Vec<String>> {
    keys.iter()
        .filter(|(key, _)| data.summary.get(*key).is_some())
        .map(|(key, label)| vec![label.to_string(), cell(data.number(key)), key.to_string()])
        .collect()
}

fn summary(data: &RunData) -> Option<Section> {
    let mut s = Section::new("summary", "Summary");
    if let Some(error) = data.text("error") {
        s = s.paragraph(format!("The run did not complete: {error}"));
    }
    Some(s.table(
        &["quantity", "value", "summary.json key"],
        rows(
            data,
            &[
                ("simulated_time_s", "simulated time [s]"),
                ("inner_ring_speed_rpm", "inner-ring speed [rpm]"),
                ("mean_cage_speed_rpm", "mean cage speed [rpm]"),
                (
                    "pure_rolling_cage_speed_rpm",
                    "pure-rolling cage speed [rpm]",
                ),
                ("cage_sliding_rate", "cage sliding rate [1]"),
                ("mean_load_inner_n", "mean inner load [N]"),
                ("max_load_inner_n", "largest inner load [N]"),
                ("mean_load_outer_n", "mean outer load [N]"),
                ("max_load_outer_n", "largest outer load [N]"),
                (
                    "mean_contact_angle_inner_deg",
                    "mean inner contact angle [deg]",
                ),
                (
                    "mean_contact_angle_outer_deg",
                    "mean outer contact angle [deg]",
                ),
                ("mean_power_loss_w", "mean friction power [W]"),
                ("mean_friction_torque_n_m", "mean friction torque [N·m]"),
                (
                    "energy_balance_relative_error",
                    "energy balance error / drive work [1]",
                ),
            ],
        ),
    ))
}

fn case(data: &RunData) -> Option<Section> {
    let mut s = Section::new("case", "Case and assumptions");
    if let Some(record) = &data.record {
        let source = record.get("source").and_then(Value::as_str).unwrap_or("?");
        s = s.paragraph(format!("Case: {source}."));
        let overrides: Vec<String> = match record.get("overrides") {
            Some(Value::Object(map)) => map
                .iter()
                .filter_map(|(k, v)| match v {
                    Value::Null | Value::Bool(false) => None,
                    Value::Array(items) if items.is_empty() => None,
                    Value::Array(items) => Some(
                        items
                            .iter()
                            .map(|i| format!("--{k} {}", i.as_str().unwrap_or("?")))
                            .collect::<Vec<_>>()
                            .join(" "),
                    ),
                    Value::Bool(true) => Some(format!("--{}", k.replace('_', "-"))),
                    other => Some(format!(
                        "--{} {}",
                        k.replace('_', "-"),
                        other.as_str().map_or(other.to_string(), str::to_string)
                    )),
                })
                .collect(),
            _ => Vec::new(),
        };
        if !overrides.is_empty() {
            s = s.paragraph(format!("Command-line overrides: {}", overrides.join(" ")));
        }
        if let Some(text) = record.get("case_text").and_then(Value::as_str) {
            s.blocks.push(Block::Pre {
                summary: "Case file as read".into(),
                text: text.to_string(),
            });
        }
    }
    if let Some(description) = &data.case_description {
        s.blocks.push(Block::Pre {
            summary:
                "Derived geometry, contact constants, frequencies and assumptions (rolldyn check)"
                    .into(),
            text: description.clone(),
        });
    }
    (!s.blocks.is_empty()).then_some(s)
}

fn solver(data: &RunData) -> Option<Section> {
    let mut table = rows(
        data,
        &[
            ("relative_tolerance", "relative tolerance"),
            ("max_step_s", "largest step [s]"),
            ("steps", "accepted steps"),
            ("rejected_steps", "rejected steps"),
            ("rhs_evaluations", "right-hand-side evaluations"),
            ("jacobian_evaluations", "Jacobians"),
            ("jacobian_rhs_evaluations", "RHS evaluations for Jacobians"),
            ("factorizations", "factorizations"),
            ("samples", "samples recorded"),
            ("sample_rate_hz", "sample rate [Hz]"),
            ("wall_time_s", "wall time [s]"),
        ],
    );
    if let (Some(wall), Some(t)) = (data.number("wall_time_s"), data.number("simulated_time_s"))
        && t > 0.0
    {
        table.push(vec![
            "wall time per simulated second [s]".into(),
            cell(Some(wall / t)),
            "wall_time_s / simulated_time_s".into(),
        ]);
    }
    let integrator = data.text("integrator").unwrap_or("?");
    Some(
        Section::new("solver", "Solver statistics")
            .paragraph(format!("Integrator: {integrator}."))
            .table(&["quantity", "value", "summary.json key"], table),
    )
}

fn cage_speed(data: &RunData) -> Option<Section> {
    let cage = data.against_time("cage_speed_rpm", "cage", 1.0)?;
    let mut plot = Plot::new("Cage speed", "time [ms]", "speed [rpm]").with(cage);
    if let (Some(ratio), Some(inner)) = (
        data.channel("pure_rolling_cage_speed_ratio"),
        data.channel("inner_ring_speed_rpm"),
    ) {
        let t: Vec<f64> = data
            .time_of("pure_rolling_cage_speed_ratio")
            .iter()
            .map(|t| 1e3 * t)
            .collect();
        // Only when both are sampled alike (not one at the slow rate).
        let pure: Vec<f64> = if ratio.len() == inner.len() {
            ratio.iter().zip(inner).map(|(r, n)| r * n).collect()
        } else {
            Vec::new()
        };
        plot = plot.with(Series::new(
            "pure rolling (solved contact angles)",
            &t,
            &pure,
            Style::Dashed,
        ));
    }
    Some(
        Section::new("cage", "Cage speed against pure rolling")
            .paragraph(format!(
                "Mean cage speed {} rpm against {} rpm in pure rolling with the solved contact angles: sliding rate {} (positive: the cage lags).",
                cell(data.number("mean_cage_speed_rpm")),
                cell(data.number("pure_rolling_cage_speed_rpm")),
                cell(data.number("cage_sliding_rate"))
            ))
            .figure(plot),
    )
}

fn ball_plot(data: &RunData, title: &str, y_label: &str, channels: &[(&str, &str)]) -> Plot {
    let index: Vec<f64> = (0..data.ball_count()).map(|j| j as f64).collect();
    channels.iter().fold(
        Plot::new(title, "ball", y_label),
        |plot, (suffix, legend)| {
            plot.with(Series::markers(*legend, &index, &data.per_ball(suffix)))
        },
    )
}

fn ball0_history(data: &RunData, title: &str, y_label: &str, channels: &[(&str, &str)]) -> Plot {
    channels.iter().fold(
        Plot::new(title, "time [ms]", y_label),
        |plot, (suffix, legend)| match data.against_time(&format!("ball0_{suffix}"), legend, 1.0) {
            Some(s) => plot.with(s),
            None => plot,
        },
    )
}

fn contacts(data: &RunData) -> Option<Section> {
    if data.ball_count() == 0 {
        return None;
    }
    let loads = [("load_inner_n", "inner"), ("load_outer_n", "outer")];
    let angles = [
        ("contact_angle_inner_deg", "inner"),
        ("contact_angle_outer_deg", "outer"),
    ];
    Some(
        Section::new("contacts", "Contact loads and angles per ball")
            .paragraph("Per ball: means over the averaging window of the summary (ball 0 starts at the +y axis).")
            .figure(ball_plot(data, "Mean contact load per ball", "load [N]", &loads))
            .figure(ball_plot(data, "Mean contact angle per ball", "angle [deg]", &angles))
            .figure(ball0_history(data, "Contact loads of ball 0", "load [N]", &loads)),
    )
}

fn slip(data: &RunData) -> Option<Section> {
    if data.ball_count() == 0 {
        return None;
    }
    let slide = [
        ("slide_to_roll_inner", "inner"),
        ("slide_to_roll_outer", "outer"),
    ];
    let spin = [
        ("spin_to_roll_inner", "inner"),
        ("spin_to_roll_outer", "outer"),
    ];
    Some(
        Section::new("slip", "Slide- and spin-to-roll")
            .figure(ball_plot(
                data,
                "Mean slide-to-roll ratio per ball",
                "slide/roll [1]",
                &slide,
            ))
            .figure(ball_plot(
                data,
                "Mean spin-to-roll ratio per ball",
                "spin/roll [1]",
                &spin,
            ))
            .figure(ball0_history(
                data,
                "Slide-to-roll of ball 0",
                "slide/roll [1]",
                &slide,
            )),
    )
}

fn cage_orbit(data: &RunData) -> Option<Section> {
    let (y, z) = data.orbit.as_ref()?;
    let y: Vec<f64> = y.iter().map(|v| 1e6 * v).collect();
    let z: Vec<f64> = z.iter().map(|v| 1e6 * v).collect();
    let mut plot = Plot::new("Cage centre orbit", "y [µm]", "z [µm]").with(Series::line(
        "cage centre",
        &y,
        &z,
    ));
    plot.equal_aspect = true;
    Some(
        Section::new("orbit", "Cage orbit")
            .table(
                &["quantity", "value", "summary.json key"],
                rows(
                    data,
                    &[
                        ("cage_whirl_radius_mean_m", "mean whirl radius [m]"),
                        ("cage_whirl_radius_max_m", "largest whirl radius [m]"),
                        ("cage_whirl_speed_rpm", "whirl speed [rpm]"),
                        ("cage_whirl_speed_ratio", "whirl speed / cage speed [1]"),
                        ("cage_whirl_sigma", "whirl stability ratio σ [1]"),
                    ],
                ),
            )
            .figure(plot),
    )
}

fn energy(data: &RunData) -> Option<Section> {
    let drive = data.channel("drive_work_j")?;
    let dissipated = data.channel("dissipated_energy_j")?;
    let mechanical = data.channel("mechanical_energy_j")?;
    // Runs written before the film in the approach have no film channel.
    let zeros = vec![0.0; drive.len()];
    let film = data.channel("film_work_j").unwrap_or(&zeros);
    let t: Vec<f64> = data
        .time_of("drive_work_j")
        .iter()
        .map(|t| 1e3 * t)
        .collect();
    let e0 = mechanical.first().copied().unwrap_or(0.0);
    let change: Vec<f64> = mechanical.iter().map(|e| e - e0).collect();
    let error = data.channel(BALANCE_ERROR)?;
    Some(
        Section::new("energy", "Energy balance")
            .paragraph("Work of the drive W plus the films' work F (film in the approach, else 0) = dissipated energy D + change of mechanical energy ΔE; the error W + F − D − ΔE measures the integration.")
            .table(
                &["quantity", "value", "summary.json key"],
                rows(
                    data,
                    &[
                        ("drive_work_j", "drive work [J]"),
                        ("film_work_j", "film work [J]"),
                        ("dissipated_energy_j", "dissipated energy [J]"),
                        ("mechanical_energy_change_j", "change of mechanical energy [J]"),
                        ("energy_balance_error_j", "balance error [J]"),
                        ("energy_balance_relative_error", "balance error / drive work [1]"),
                    ],
                ),
            )
            .figure(
                Plot::new("Energy", "time [ms]", "energy [J]")
                    .with(Series::line("drive work W", &t, drive))
                    .with(Series::line("film work F", &t, film))
                    .with(Series::line("dissipated D", &t, dissipated))
                    .with(Series::line("mechanical change ΔE", &t, &change)),
            )
            .figure(Plot::new("Energy balance error W − D − ΔE", "time [ms]", "error [J]").with(Series::line("error", &t, error))),
    )
}

fn power(data: &RunData) -> Option<Section> {
    let Some(Value::Object(components)) = data.summary.get("mean_power_loss_by_component_w") else {
        return None;
    };
    let table = components
        .iter()
        .map(|(name, v)| vec![name.replace('_', " "), cell(v.as_f64())])
        .collect();
    let mut s = Section::new("power", "Friction power")
        .table(&["component", "mean power [W]"], table)
        .figure(
            Plot::new("Friction power", "time [ms]", "power [W]").with(data.against_time(
                "power_total_w",
                "total",
                1.0,
            )?),
        );
    let temperatures: Vec<Series> = data
        .series
        .names()
        .iter()
        .filter_map(|n| {
            let node = n.strip_prefix("temperature_")?.strip_suffix("_c")?;
            data.against_time(n, node, 1.0)
        })
        .collect();
    if !temperatures.is_empty() {
        s = s.figure(temperatures.into_iter().fold(
            Plot::new("Temperatures", "time [ms]", "temperature [°C]"),
            Plot::with,
        ));
    }
    Some(s)
}

fn all_values(data: &RunData) -> Option<Section> {
    let Value::Object(map) = &data.summary else {
        return None;
    };
    let mut table = Vec::new();
    for (key, value) in map {
        flatten(key, value, &mut table);
    }
    Some(
        Section::new("values", "All summary values")
            .paragraph("Every key of summary.json; units are in the key names (docs/cli.md).")
            .table(&["summary.json key", "value"], table),
    )
}

fn flatten(key: &str, value: &Value, out: &mut Vec<Vec<String>>) {
    match value {
        Value::Object(map) => {
            for (k, v) in map {
                flatten(&format!("{key}.{k}"), v, out);
            }
        }
        Value::Number(n) => out.push(vec![key.into(), cell(n.as_f64())]),
        Value::Null => out.push(vec![key.into(), "—".into()]),
        Value::String(s) => out.push(vec![key.into(), s.clone()]),
        Value::Bool(b) => out.push(vec![key.into(), b.to_string()]),
        Value::Array(items) => out.push(vec![
            key.into(),
            items
                .iter()
                .map(|v| v.as_f64().map_or(v.to_string(), |x| cell(Some(x))))
                .collect::<Vec<_>>()
                .join(", "),
        ]),
    }
}
