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

use crate::run_data::{BALANCE_ERROR, rows};
pub use crate::run_data::{PLOT_ROWS, RunData, read_for_plots};
use crate::svg::{Plot, Series, Style};
use crate::{Block, Report, ReportError, Section, cell, read_json};
use rolldyn_io::RunDir;
use serde_json::Value;
use std::path::Path;

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
    let summary = read_json(&RunDir::new(dir).summary())?;
    let series_path = RunDir::new(dir).series();
    let window = averaging_window(&summary);
    let read = |path: &Path| {
        read_for_plots(path, window).map_err(|e| ReportError::Read {
            path: path.display().to_string(),
            message: e.to_string(),
        })
    };
    let (series, mut window_means, orbit) = read(&series_path)?;
    let slow_path = RunDir::new(dir).slow_series();
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
        crate::vibration_data::read_records(&series_path, &summary, &series, window).map_err(
            |e| ReportError::Read {
                path: series_path.display().to_string(),
                message: e.to_string(),
            },
        )?;
    let record = read_record(dir)?;
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

/// The summary's averaging window \[s\] (NaN where absent).
pub(crate) fn averaging_window(summary: &Value) -> [f64; 2] {
    match summary.get("averaging_window_s") {
        Some(Value::Array(w)) if w.len() == 2 => [
            w[0].as_f64().unwrap_or(f64::NAN),
            w[1].as_f64().unwrap_or(f64::NAN),
        ],
        _ => [f64::NAN; 2],
    }
}

/// `DIR/run.json`, when present.
pub(crate) fn read_record(dir: &Path) -> Result<Option<Value>, ReportError> {
    RunDir::new(dir)
        .record()
        .is_file()
        .then(|| read_json(&RunDir::new(dir).record()))
        .transpose()
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
    out.extend(accuracy.get("verify").and_then(verify_warning));
    out
}

/// The banner line of a failed `--verify` (its `status` `warning`): what
/// moved beyond its limit, and why (`cause`); None when it passed.
pub(crate) fn verify_warning(verify: &Value) -> Option<String> {
    let text = |v: &Value, key: &str| v.get(key).and_then(Value::as_str).map(str::to_string);
    if text(verify, "status").as_deref() != Some("warning") {
        return None;
    }
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
    let verdict = match text(verify, "cause").as_deref() {
        Some("window") => {
            "each by no more than between the halves of the averaging window: statistics the window is too short to settle (run longer)"
        }
        Some("grid") => {
            "the finer traction grid alone moves them as much: the results are not converged in the traction grid (refine it)"
        }
        _ => "the results are not converged at these settings",
    };
    Some(format!(
        "At ten times tighter tolerances and a finer traction grid (--verify) {} moved beyond their limits: {verdict}.",
        moved.join(", ")
    ))
}

/// `text` with its first letter in upper case.
fn sentence(text: &str) -> String {
    let mut chars = text.chars();
    chars
        .next()
        .map(|c| c.to_uppercase().chain(chars).collect())
        .unwrap_or_default()
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

pub(crate) fn case(data: &RunData) -> Option<Section> {
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

pub(crate) fn solver(data: &RunData) -> Option<Section> {
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
            ("fast_part_jacobians", "Jacobians of the fast part"),
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
    let section = Section::new("cage", "Cage speed against pure rolling")
        .paragraph(format!(
            "Mean cage speed {} rpm against {} rpm in pure rolling with the solved contact angles: sliding rate {} (positive: the cage lags).",
            cell(data.number("mean_cage_speed_rpm")),
            cell(data.number("pure_rolling_cage_speed_rpm")),
            cell(data.number("cage_sliding_rate"))
        ))
        .figure(plot);
    // A ring that changes speed (a speed profile, a torque drive): its own plot.
    let varies = data.channel("inner_ring_speed_rpm").is_some_and(|v| {
        let (low, high) = v
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| {
                (l.min(*x), h.max(*x))
            });
        high - low > 1e-6 * high.abs().max(low.abs())
    });
    Some(
        match data.against_time("inner_ring_speed_rpm", "inner ring", 1.0) {
            Some(inner) if varies => section
                .figure(Plot::new("Inner-ring speed", "time [ms]", "speed [rpm]").with(inner)),
            _ => section,
        },
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

/// Left out when the cage centre never moves (`cage.whirl = false`).
fn cage_orbit(data: &RunData) -> Option<Section> {
    let (y, z) = data.orbit.as_ref()?;
    if y.iter().chain(z).all(|v| *v == 0.0) {
        return None;
    }
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

pub(crate) fn energy(data: &RunData) -> Option<Section> {
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

pub(crate) fn all_values(data: &RunData) -> Option<Section> {
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
        // A list of objects (the envelope's lines): a row per field of
        // each, numbered, so that no cell holds a whole list.
        Value::Array(items) if items.iter().any(Value::is_object) => {
            for (i, item) in items.iter().enumerate() {
                flatten(&format!("{key}.{i}"), item, out);
            }
        }
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A list of objects becomes a row per field, numbered; a list of
    /// numbers stays one row.
    #[test]
    fn lists_of_objects_are_flattened() {
        let value = serde_json::json!({
            "lines": [{"name": "BPFO", "frequency_hz": 107.4}, {"name": "2xBPFO", "frequency_hz": 214.8}],
            "window_s": [0.1, 0.2]
        });
        let mut rows = Vec::new();
        flatten("envelope_lines", &value, &mut rows);
        let keys: Vec<&str> = rows.iter().map(|r| r[0].as_str()).collect();
        assert_eq!(
            keys,
            [
                "envelope_lines.lines.0.frequency_hz",
                "envelope_lines.lines.0.name",
                "envelope_lines.lines.1.frequency_hz",
                "envelope_lines.lines.1.name",
                "envelope_lines.window_s",
            ]
        );
        assert_eq!(rows[1][1], "BPFO");
        assert!(rows.iter().all(|r| !r[1].contains('{')));
    }
}
