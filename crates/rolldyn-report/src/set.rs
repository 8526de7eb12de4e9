//! The report of a `rolldyn run` of bearings on a shaft (a matched set or
//! a `[shaft]`; docs/systems.md, "Dynamics"): its `summary.json` (with a
//! `bearings` array) and its time series of `bearing{i}_…` and `shaft_…`
//! channels.
//!
//! Sections: summary, the bearings (their axial loads against the
//! quasi-static ones, cage speeds, largest contact loads), the axial loads
//! and cage speeds in time, the shaft's motion and orbit, and then as for
//! one bearing the case, solver statistics, energy balance and all summary
//! values ([`crate::run`]).

use crate::run::RunData;
use crate::svg::{Plot, Series};
use crate::{Report, ReportError, Section, cell, read_json};
use rolldyn_io::RunDir;
use serde_json::Value;
use std::path::Path;

/// Whether `summary` is a shaft system's (it lists its bearings).
pub fn is_set_summary(summary: &Value) -> bool {
    summary.get("bearings").is_some_and(Value::is_array) && summary.get("kind").is_some()
}

/// Reads a set's run directory and builds its report.
pub fn report(dir: &Path, case_description: Option<String>) -> Result<Report, ReportError> {
    let summary = read_json(&RunDir::new(dir).summary())?;
    let series_path = RunDir::new(dir).series();
    let window = crate::run::averaging_window(&summary);
    let (series, window_means, orbit) =
        crate::run_data::read_with_orbit(&series_path, window, ["shaft_y_m", "shaft_z_m"])
            .map_err(|e| ReportError::Read {
                path: series_path.display().to_string(),
                message: e.to_string(),
            })?;
    let record = crate::run::read_record(dir)?;
    Ok(build(&RunData {
        summary,
        series,
        slow: None,
        window_means,
        orbit,
        record,
        case_description,
        vibration: None,
        run_up: None,
    }))
}

/// The bearings' summaries.
fn bearings(data: &RunData) -> &[Value] {
    data.summary
        .get("bearings")
        .and_then(Value::as_array)
        .map_or(&[], Vec::as_slice)
}

/// The report of a set's run data.
pub fn build(data: &RunData) -> Report {
    let kind = data.text("kind").unwrap_or("shaft");
    let title = match data.text("title") {
        Some(t) => t.to_string(),
        None => format!("rolldyn run: {} system", kind.replace('_', " ")),
    };
    let subtitle = format!(
        "{} bearings · {} · {} of {} s simulated",
        bearings(data).len(),
        data.text("status").unwrap_or("unknown status"),
        cell(data.number("simulated_time_s")),
        cell(data.number("requested_duration_s")),
    );
    let mut warnings = Vec::new();
    if let Some(e) = data.number("energy_balance_relative_error")
        && e.abs() > 1e-3
    {
        warnings.push(format!(
            "The energy balance closes only to {e:.2e} of the work (a converged run: ≤ 1e-3); tighten solver.relative_tolerance."
        ));
    }
    warnings.extend(
        data.summary
            .get("verify")
            .and_then(crate::run::verify_warning),
    );
    let sections = [
        summary(data),
        table_of_bearings(data),
        in_time(data),
        shaft(data),
        crate::run::case(data),
        crate::run::solver(data),
        crate::run::energy(data),
        crate::run::all_values(data),
    ];
    Report {
        title,
        subtitle,
        warnings,
        sections: sections
            .into_iter()
            .flatten()
            .filter(|s| !s.blocks.is_empty())
            .collect(),
    }
}

fn summary(data: &RunData) -> Option<Section> {
    let mut s = Section::new("summary", "Summary");
    if let Some(error) = data.text("error") {
        s = s.paragraph(format!("The run did not complete: {error}"));
    }
    Some(s.table(
        &["quantity", "value", "summary.json key"],
        crate::run_data::rows(
            data,
            &[
                ("simulated_time_s", "simulated time [s]"),
                ("mounting_preload_n", "mounting preload [N]"),
                ("inner_ring_speed_rpm", "shaft speed [rpm]"),
                ("drive_work_j", "drive work [J]"),
                ("dissipated_energy_j", "dissipated energy [J]"),
                (
                    "energy_balance_relative_error",
                    "energy balance error / largest term [1]",
                ),
            ],
        ),
    ))
}

fn table_of_bearings(data: &RunData) -> Option<Section> {
    let list = bearings(data);
    if list.is_empty() {
        return None;
    }
    let number = |b: &Value, k: &str| cell(b.get(k).and_then(Value::as_f64));
    let rows = list
        .iter()
        .enumerate()
        .map(|(i, b)| {
            vec![
                i.to_string(),
                number(b, "position_m"),
                b.get("orientation")
                    .and_then(Value::as_str)
                    .unwrap_or("?")
                    .to_string(),
                number(b, "quasistatic_axial_load_n"),
                number(b, "mean_axial_load_n"),
                number(b, "mean_cage_speed_rpm"),
                number(b, "largest_inner_load_n"),
                number(b, "largest_outer_load_n"),
            ]
        })
        .collect();
    Some(
        Section::new("bearings", "The bearings")
            .paragraph(
                "Each bearing's axial load (the thrust its balls carry, over the run) against the set's quasi-static solution it started from, its mean cage speed (summary window) and its largest contact loads.",
            )
            .table(
                &[
                    "bearing",
                    "position [m]",
                    "orientation",
                    "quasi-static axial load [N]",
                    "mean axial load [N]",
                    "mean cage speed [rpm]",
                    "largest inner load [N]",
                    "largest outer load [N]",
                ],
                rows,
            ),
    )
}

fn in_time(data: &RunData) -> Option<Section> {
    let count = bearings(data).len();
    let plot = |title: &str, label: &str, suffix: &str| {
        (0..count).fold(Plot::new(title, "time [ms]", label), |plot, i| {
            match data.against_time(
                &format!("bearing{i}_{suffix}"),
                &format!("bearing {i}"),
                1.0,
            ) {
                Some(series) => plot.with(series),
                None => plot,
            }
        })
    };
    Some(
        Section::new("in-time", "Axial loads and cage speeds")
            .figure(plot("Axial load", "axial load [N]", "axial_load_n"))
            .figure(plot("Cage speed", "cage speed [rpm]", "cage_speed_rpm")),
    )
}

fn shaft(data: &RunData) -> Option<Section> {
    let mut section = Section::new("shaft", "The shaft's motion");
    let micro = |name: &str, legend: &str| data.against_time(name, legend, 1e6);
    let mut moves = Plot::new("Shaft displacement", "time [ms]", "displacement [µm]");
    for (name, legend) in [("shaft_x_m", "x"), ("shaft_y_m", "y"), ("shaft_z_m", "z")] {
        if let Some(s) = micro(name, legend) {
            moves = moves.with(s);
        }
    }
    section = section.figure(moves);
    if let Some((y, z)) = &data.orbit {
        let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len().max(1) as f64;
        let (my, mz) = (mean(y), mean(z));
        let y: Vec<f64> = y.iter().map(|v| 1e6 * (v - my)).collect();
        let z: Vec<f64> = z.iter().map(|v| 1e6 * (v - mz)).collect();
        let mut orbit = Plot::new(
            "Shaft orbit about its mean (last samples)",
            "y [µm]",
            "z [µm]",
        )
        .with(Series::line("shaft at the reference point", &y, &z));
        orbit.equal_aspect = true;
        section = section.figure(orbit);
    }
    Some(section)
}
