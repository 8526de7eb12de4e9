//! The report of a sweep directory: `sweep.json`, an array with one
//! object per point (`rolldyn quasistatic --sweep`, `rolldyn run
//! --sweep`).
//!
//! The swept inputs are the columns `speed_rpm`, `force_x_n` and
//! `force_z_n` that take more than one value. The one that changes
//! fastest from row to row (the last `--sweep`) is the abscissa; each
//! combination of the others is a series. Every other numeric column that
//! is not constant is plotted against it, one figure per quantity, with
//! its unit from the column name (docs/cli.md).

use crate::svg::{Plot, Series};
use crate::{Report, ReportError, Section, cell, read_json};
use rolldyn_io::RunDir;
use serde_json::{Map, Value};
use std::path::Path;

/// Input columns a sweep can vary, with their axis labels.
const INPUTS: [(&str, &str); 3] = [
    ("speed_rpm", "inner-ring speed [rpm]"),
    ("force_x_n", "axial load F_x [N]"),
    ("force_z_n", "radial load F_z [N]"),
];

/// Reads a sweep directory and builds its report.
pub fn report(dir: &Path) -> Result<Report, ReportError> {
    let path = RunDir::new(dir).file(RunDir::SWEEP_JSON);
    let rows = match read_json(&path)? {
        Value::Array(rows) => rows
            .into_iter()
            .filter_map(|r| match r {
                Value::Object(map) => Some(map),
                _ => None,
            })
            .collect::<Vec<_>>(),
        _ => {
            return Err(ReportError::Read {
                path: path.display().to_string(),
                message: "expected an array of points".into(),
            });
        }
    };
    Ok(build(&rows, &dir.display().to_string()))
}

fn number(row: &Map<String, Value>, key: &str) -> Option<f64> {
    row.get(key).and_then(Value::as_f64)
}

/// Whether a point succeeded (`converged` of a quasi-static sweep,
/// `status` of a dynamic one).
fn succeeded(row: &Map<String, Value>) -> bool {
    match (row.get("converged"), row.get("status")) {
        (Some(Value::Bool(b)), _) => *b,
        (_, Some(Value::String(s))) => s == "completed",
        _ => true,
    }
}

/// The report of a sweep's rows.
pub fn build(rows: &[Map<String, Value>], source: &str) -> Report {
    let varying: Vec<(&str, &str)> = INPUTS
        .iter()
        .copied()
        .filter(|(key, _)| distinct(rows, key) > 1)
        .collect();
    // The abscissa: the input that changes most often between rows.
    let abscissa = varying
        .iter()
        .copied()
        .max_by_key(|(key, _)| {
            rows.windows(2)
                .filter(|w| number(&w[0], key) != number(&w[1], key))
                .count()
        })
        .unwrap_or(INPUTS[0]);
    let others: Vec<(&str, &str)> = varying
        .iter()
        .copied()
        .filter(|(k, _)| *k != abscissa.0)
        .collect();
    let failed = rows.iter().filter(|r| !succeeded(r)).count();

    let mut points = Section::new("points", "Points").paragraph(format!(
        "{} points, {} failed (their outputs are left out of the plots). Swept: {}.",
        rows.len(),
        failed,
        if varying.is_empty() {
            "nothing".to_string()
        } else {
            varying
                .iter()
                .map(|(_, label)| *label)
                .collect::<Vec<_>>()
                .join(", ")
        }
    ));
    let table = rows
        .iter()
        .enumerate()
        .map(|(k, r)| {
            let mut row = vec![k.to_string()];
            row.extend(INPUTS.iter().map(|(key, _)| cell(number(r, key))));
            row.push(if succeeded(r) { "ok" } else { "failed" }.into());
            row.push(r.get("error").and_then(Value::as_str).unwrap_or("").into());
            row
        })
        .collect();
    points = points.table(
        &[
            "point",
            "speed [rpm]",
            "F_x [N]",
            "F_z [N]",
            "result",
            "error",
        ],
        table,
    );

    // Outputs: numeric, not an input, not constant over the successful points.
    let mut outputs: Vec<String> = Vec::new();
    for r in rows {
        for (key, v) in r {
            if v.is_number()
                && !INPUTS.iter().any(|(k, _)| k == key)
                && !outputs.iter().any(|o| o == key)
            {
                outputs.push(key.clone());
            }
        }
    }
    outputs.retain(|key| {
        let values: Vec<f64> = rows
            .iter()
            .filter(|r| succeeded(r))
            .filter_map(|r| number(r, key))
            .filter(|v| v.is_finite())
            .collect();
        values.iter().any(|v| *v != values[0])
    });
    let mut figures = Section::new("quantities", "Quantities against the swept variables");
    for key in &outputs {
        let mut plot = Plot::new(key.as_str(), abscissa.1, key.as_str());
        for group in groups(rows, &others) {
            let (x, y): (Vec<f64>, Vec<f64>) = group
                .members
                .iter()
                .map(|r| {
                    let y = if succeeded(r) {
                        number(r, key).unwrap_or(f64::NAN)
                    } else {
                        f64::NAN
                    };
                    (number(r, abscissa.0).unwrap_or(f64::NAN), y)
                })
                .unzip();
            let mut series = Series::markers(group.label, &x, &y);
            if x.len() > 1 {
                series.style = crate::svg::Style::Line;
            }
            plot = plot.with(series);
        }
        figures = figures.figure(plot);
    }
    Report {
        title: "rolldyn sweep".into(),
        subtitle: format!("{source} · {} points", rows.len()),
        warnings: unconverged(rows),
        sections: vec![points, figures],
    }
}

/// The banner for points whose energy balance did not close.
fn unconverged(rows: &[Map<String, Value>]) -> Vec<String> {
    let warned: Vec<&str> = rows
        .iter()
        .filter(|r| {
            let balance = r
                .get("accuracy.energy_balance_relative_error")
                .and_then(Value::as_f64);
            let limit = r
                .get("accuracy.energy_balance_limit")
                .and_then(Value::as_f64);
            matches!((balance, limit), (Some(b), Some(l)) if b.abs() > l)
        })
        .map(|r| r.get("point").and_then(Value::as_str).unwrap_or("?"))
        .collect();
    if warned.is_empty() {
        return Vec::new();
    }
    vec![format!(
        "{} of {} points are not converged at their settings (their energy balance does not close to accuracy.energy_balance_limit of the drive work): {}",
        warned.len(),
        rows.len(),
        warned.join(", ")
    )]
}

fn distinct(rows: &[Map<String, Value>], key: &str) -> usize {
    let mut values: Vec<f64> = rows.iter().filter_map(|r| number(r, key)).collect();
    values.sort_by(f64::total_cmp);
    values.dedup();
    values.len()
}

/// Points sharing the values of the non-abscissa inputs, in row order.
struct Group<'a> {
    label: String,
    members: Vec<&'a Map<String, Value>>,
}

fn groups<'a>(rows: &'a [Map<String, Value>], others: &[(&str, &str)]) -> Vec<Group<'a>> {
    let mut out: Vec<(Vec<Option<f64>>, Group<'a>)> = Vec::new();
    for r in rows {
        let key: Vec<Option<f64>> = others.iter().map(|(k, _)| number(r, k)).collect();
        match out.iter_mut().find(|(k, _)| *k == key) {
            Some((_, g)) => g.members.push(r),
            None => {
                let label = others
                    .iter()
                    .zip(&key)
                    .map(|((_, label), v)| format!("{label} = {}", cell(*v)))
                    .collect::<Vec<_>>()
                    .join(", ");
                out.push((
                    key,
                    Group {
                        label: if label.is_empty() {
                            "all points".into()
                        } else {
                            label
                        },
                        members: vec![r],
                    },
                ));
            }
        }
    }
    out.into_iter().map(|(_, g)| g).collect()
}
