//! How accurate a run is: the `accuracy` object of `summary.json`, the
//! warning on stderr and the report's banner, and `run --verify` (the same
//! case again at ten times tighter tolerances with the traction's grid
//! refined two-fold each way, and how much the summary's main quantities
//! moved). docs/dynamics.md, "Accuracy at default
//! settings", explains the measures and their limits.

use crate::Failure;
use crate::checkpoint::RunRecord;
use crate::run::{RunOptions, Summary};
use rolldyn_io::write_atomic;
use serde::Serialize;
use std::path::Path;

/// Largest energy-balance error, relative to the drive work, that a run
/// reports as `ok`.
pub const ENERGY_BALANCE_LIMIT: f64 = 1e-3;

/// Largest relative change under `--verify` of the cage speed, the contact
/// loads and the power loss that passes.
pub const VERIFY_LIMIT_MEANS: f64 = 0.01;

/// Largest relative change under `--verify` of the vibration RMS values and
/// the cage-whirl radius that passes.
pub const VERIFY_LIMIT_VIBRATION: f64 = 0.05;

/// Vibration RMS values below this many times the run's velocity
/// tolerance (rtol × 1 mm/s, the integrator's absolute tolerance of the
/// ring velocities) are integration noise, not vibration: `--verify`
/// does not compare them (an axially loaded bearing without defects).
pub const VIBRATION_NOISE_FACTOR: f64 = 10.0;

/// Factor by which `--verify` tightens the tolerances.
pub const VERIFY_TIGHTENING: f64 = 10.0;

/// The `accuracy` object of `summary.json`.
#[derive(Debug, Clone, Serialize)]
pub struct Accuracy {
    /// The energy balance error relative to the drive work (the same value
    /// as the summary's `energy_balance_relative_error`).
    pub energy_balance_relative_error: f64,
    /// The limit above which the status is `warning`.
    pub energy_balance_limit: f64,
    /// `ok` or `warning`.
    pub status: &'static str,
    /// Why the status is `warning` (null when `ok`).
    pub reason: Option<String>,
    /// What to do about it (null when `ok`).
    pub hint: Option<String>,
    /// The `--verify` comparison (null without `--verify`).
    pub verify: Option<Verification>,
}

/// One quantity compared by `--verify`.
#[derive(Debug, Clone, Serialize)]
pub struct Change {
    /// Summary key.
    pub key: std::borrow::Cow<'static, str>,
    /// Value of the run.
    pub value: f64,
    /// Value at the tighter tolerances.
    pub reference: f64,
    /// |value − reference| / |reference|.
    pub relative_change: f64,
    /// The limit it is held to.
    pub limit: f64,
}

/// The result of `run --verify`.
#[derive(Debug, Clone, Serialize)]
pub struct Verification {
    /// Relative tolerance of the verifying run.
    pub relative_tolerance: Option<f64>,
    /// Energy tolerance of the verifying run (null: off).
    pub energy_tolerance: Option<f64>,
    /// The traction's integration grid of the verifying run, refined
    /// two-fold each way, with the run's (null: no grid, e.g. traction at
    /// the contact centre).
    pub traction_grid: Option<String>,
    /// Where the verifying run was written.
    pub directory: String,
    /// Its wall time \[s\].
    pub wall_time_s: f64,
    /// Its energy-balance error relative to the drive work.
    pub energy_balance_relative_error: f64,
    /// The compared quantities.
    pub changes: Vec<Change>,
    /// The largest relative change over the limits, as a fraction of its
    /// limit (≤ 1 passes).
    pub worst_ratio_to_limit: f64,
    /// `ok` or `warning`.
    pub status: &'static str,
}

impl Verification {
    /// The line `rolldyn run --verify` prints: the tighter settings and
    /// the largest change against its limit.
    pub fn line(&self) -> String {
        let worst = self
            .changes
            .iter()
            .max_by(|a, b| (a.relative_change / a.limit).total_cmp(&(b.relative_change / b.limit)));
        format!(
            "verify ({}): at rtol {}{} the largest change is {}; energy balance error {:.2e}\n",
            self.status,
            self.relative_tolerance
                .map_or("-".into(), |r| format!("{r:e}")),
            self.traction_grid
                .as_ref()
                .map_or(String::new(), |g| format!(" and a traction grid of {g}")),
            worst.map_or("none".into(), |c| format!(
                "{} {:.3} % (limit {} %)",
                c.key,
                100.0 * c.relative_change,
                100.0 * c.limit
            )),
            self.energy_balance_relative_error
        )
    }
}

/// The accuracy of a run from its summary's energy balance (relative, and
/// the error and drive work in joules for the message); the integrator and
/// tolerances name what to tighten in the hint.
pub fn assess(
    relative_error: f64,
    error_j: f64,
    drive_j: f64,
    integrator: &str,
    relative_tolerance: Option<f64>,
    energy_tolerance: Option<f64>,
) -> Accuracy {
    let ok = relative_error.abs() <= ENERGY_BALANCE_LIMIT;
    let (reason, hint) = if ok {
        (None, None)
    } else {
        let reason = format!(
            "the energy balance closes to {relative_error:.2e} of the drive work ({error_j:.3e} J of {drive_j:.3e} J), above the {ENERGY_BALANCE_LIMIT:.0e} of a converged run: the integration error is large"
        );
        let hint = match (relative_tolerance, energy_tolerance) {
            (None, _) => format!(
                "{integrator} has a fixed step: take a smaller solver.time_step, or an adaptive solver.integrator"
            ),
            (Some(rtol), Some(eps)) => format!(
                "tighten the tolerances ten-fold (--set solver.relative_tolerance={:e} --set solver.energy_tolerance={:e}) and compare, or run with --verify",
                rtol / VERIFY_TIGHTENING,
                eps / VERIFY_TIGHTENING
            ),
            (Some(rtol), None) => format!(
                "the energy error control is off (solver.energy_tolerance = 0): remove that setting, or tighten solver.relative_tolerance to {:e}; --verify compares",
                rtol / VERIFY_TIGHTENING
            ),
        };
        (Some(reason), Some(hint))
    };
    Accuracy {
        energy_balance_relative_error: relative_error,
        energy_balance_limit: ENERGY_BALANCE_LIMIT,
        status: if ok { "ok" } else { "warning" },
        reason,
        hint,
        verify: None,
    }
}

/// The quantities `--verify` compares, their limits and the magnitude
/// below which a value is not compared.
fn compared(summary: &Summary) -> Vec<(&'static str, f64, f64, f64)> {
    let v = &summary.vibration;
    let (means, vibration) = (VERIFY_LIMIT_MEANS, VERIFY_LIMIT_VIBRATION);
    let zero = 1e-12;
    let noise_mm_s = VIBRATION_NOISE_FACTOR * summary.relative_tolerance.unwrap_or(0.0);
    let mut out = vec![
        (
            "mean_cage_speed_rpm",
            summary.mean_cage_speed_rpm,
            means,
            zero,
        ),
        ("mean_load_inner_n", summary.mean_load_inner_n, means, zero),
        ("max_load_inner_n", summary.max_load_inner_n, means, zero),
        ("mean_load_outer_n", summary.mean_load_outer_n, means, zero),
        ("max_load_outer_n", summary.max_load_outer_n, means, zero),
        // The exact mean (the dissipated energy's increase over the
        // window), not the mean of the sampled components: impacts make
        // those depend on where the samples fall.
        (
            "mean_dissipated_power_w",
            summary.power.mean_dissipated_power_w,
            means,
            zero,
        ),
    ];
    for (key, value) in v.rms_values() {
        out.push((key, value, vibration, noise_mm_s.max(zero)));
    }
    // Envelope lines of a run with a spall; a line below a tenth of the
    // strongest is the spectrum's floor, not a signature.
    if let Some(envelope) = &summary.surface_lines.envelope_lines {
        let strongest = envelope
            .lines
            .iter()
            .map(|l| l.amplitude_m_s2)
            .fold(0.0, f64::max);
        for (line, &(_, key)) in envelope.lines.iter().zip(&crate::vibration::ENVELOPE_LINES) {
            out.push((
                key,
                line.amplitude_m_s2,
                vibration,
                (0.1 * strongest).max(zero),
            ));
        }
    }
    // The housing sensor's record (its noise is the same draw in both runs).
    if let Some(sensor) = &summary.sensor {
        out.push(("sensor.rms_m_s2", sensor.rms_m_s2, vibration, zero));
    }
    // A whirl below the position tolerance (rtol × 1 µm) is noise too.
    let noise_m = 1e-6 * VIBRATION_NOISE_FACTOR * summary.relative_tolerance.unwrap_or(0.0);
    out.push((
        "cage_whirl_radius_mean_m",
        v.cage_whirl_radius_mean_m,
        vibration,
        noise_m.max(zero),
    ));
    out
}

/// Compares a run with its verifying run. Quantities below their noise
/// magnitude in both runs are left out: a planar run's axial vibration, an
/// unloaded ring, the integration noise of a bearing without vibration.
pub fn verify(
    run: &Summary,
    reference: &Summary,
    directory: String,
    energy_tolerance: Option<f64>,
    traction_grid: Option<String>,
) -> Verification {
    let mut changes = Vec::new();
    let mut worst: f64 = 0.0;
    for ((key, value, limit, noise), (_, reference_value, _, _)) in
        compared(run).into_iter().zip(compared(reference))
    {
        let quiet = value.abs() < noise && reference_value.abs() < noise;
        if !value.is_finite() || !reference_value.is_finite() || quiet || reference_value == 0.0 {
            continue;
        }
        let relative_change = (value - reference_value).abs() / reference_value.abs();
        worst = worst.max(relative_change / limit);
        changes.push(Change {
            key: key.into(),
            value,
            reference: reference_value,
            relative_change,
            limit,
        });
    }
    Verification {
        relative_tolerance: reference.relative_tolerance,
        energy_tolerance,
        traction_grid,
        directory,
        wall_time_s: reference.wall_time_s,
        energy_balance_relative_error: reference.energy_balance_relative_error,
        changes,
        worst_ratio_to_limit: worst,
        status: if worst <= 1.0 { "ok" } else { "warning" },
    }
}

/// The overrides that refine a case's traction grid two-fold each way,
/// and its description: FASTSIM's strips and elements, or a stress law's
/// strip grid (left alone beyond the case's limits: FASTSIM's
/// [`rolldyn::traction::fastsim::MAX_DIVISIONS`], 10 000 grid cells).
pub(crate) fn refined_traction_grid(case: &rolldyn_case::Case) -> Option<(Vec<String>, String)> {
    use rolldyn::traction::{TractionIntegration, TractionModel, fastsim::MAX_DIVISIONS};
    match (&case.traction, case.traction_integration) {
        // No grid: the table's error is stated with it (docs/validation.md).
        (TractionModel::None | TractionModel::ExactTable(_), _) => None,
        (TractionModel::Fastsim(f), _) => {
            let (strips, elements) = (2 * f.strips, 2 * f.elements);
            (strips.max(elements) <= MAX_DIVISIONS).then(|| {
                (
                    vec![
                        format!("model.traction.strips={strips}"),
                        format!("model.traction.elements={elements}"),
                    ],
                    format!(
                        "FASTSIM {strips} × {elements} (run: {} × {})",
                        f.strips, f.elements
                    ),
                )
            })
        }
        (_, integration) => {
            let (across, along) = integration.cells()?;
            let (a, b) = (2 * across, 2 * along);
            (a * b <= 10_000).then(|| {
                (
                    // The method too: a case that relies on the default grid
                    // has no such table to amend.
                    vec![
                        format!(
                            "model.traction_integration.method={}",
                            integration.method_name()
                        ),
                        format!("model.traction_integration.across={a}"),
                        format!("model.traction_integration.along={b}"),
                    ],
                    format!(
                        "{}{a} × {b} cells (run: {across} × {along})",
                        match integration {
                            TractionIntegration::Graded { .. } => "graded ",
                            _ => "",
                        }
                    ),
                )
            })
        }
    }
}

/// `--verify`: the run's case again, into `DIR/verify/`, at ten times
/// tighter tolerances (the relative and energy tolerances, or rk4's step)
/// and with the traction's grid refined two-fold each way; the comparison
/// goes into `summary.accuracy.verify` and `summary.json` is written
/// again.
pub(crate) fn verify_run(
    record: &RunRecord,
    dir: &Path,
    options: &RunOptions,
    summary: &mut Summary,
) -> Result<(), Failure> {
    let mut tight = record.clone();
    let sets = &mut tight.overrides.set;
    match summary.relative_tolerance {
        Some(rtol) => {
            sets.push(format!(
                "solver.relative_tolerance={:e}",
                (rtol / VERIFY_TIGHTENING).max(1e-12)
            ));
            if let Some(eps) = summary.energy_tolerance {
                sets.push(format!(
                    "solver.energy_tolerance={:e}",
                    (eps / VERIFY_TIGHTENING).max(1e-9)
                ));
            }
        }
        None => sets.push(format!(
            "solver.time_step={:e} s",
            (summary.max_step_s / VERIFY_TIGHTENING).max(1e-10)
        )),
    }
    let mut case = tight
        .overrides
        .load_text(&tight.source, tight.case_text.as_deref())?;
    let traction_grid = match refined_traction_grid(&case) {
        Some((grid_sets, description)) => {
            tight.overrides.set.extend(grid_sets);
            case = tight
                .overrides
                .load_text(&tight.source, tight.case_text.as_deref())?;
            Some(description)
        }
        None => None,
    };
    let verify_dir = dir.join("verify");
    let quiet = RunOptions {
        resume: false,
        quiet: true,
        progress: None,
        verify: false,
        ..options.clone()
    };
    let reference = crate::run::run_once(&tight, &case, &verify_dir, &quiet)?.summary;
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
    summary.accuracy.verify = Some(verify(
        summary,
        &reference,
        verify_dir.display().to_string(),
        reference.energy_tolerance,
        traction_grid,
    ));
    let json = crate::finite::to_json(&*summary).map_err(|e| Failure::Internal(e.to_string()))?;
    write_atomic(&dir.join("summary.json"), (json + "\n").as_bytes())
        .map_err(|e| Failure::BadInput(e.to_string()))
}

/// The warning for stderr, if the run's accuracy needs one.
pub fn warning(accuracy: &Accuracy) -> Option<String> {
    let mut lines = Vec::new();
    if let (Some(reason), Some(hint)) = (&accuracy.reason, &accuracy.hint) {
        lines.push(format!("warning: {reason}; {hint}"));
    }
    if let Some(v) = accuracy.verify.as_ref().filter(|v| v.status != "ok") {
        let moved: Vec<String> = v
            .changes
            .iter()
            .filter(|c| c.relative_change > c.limit)
            .map(|c| format!("{} by {:.2} %", c.key, 100.0 * c.relative_change))
            .collect();
        lines.push(format!(
            "warning: --verify: at ten times tighter tolerances{} {} moved beyond their limits ({} % for means and loads, {} % for vibration); the results are not converged at these settings",
            if v.traction_grid.is_some() {
                " and a finer traction grid"
            } else {
                ""
            },
            moved.join(", "),
            100.0 * VERIFY_LIMIT_MEANS,
            100.0 * VERIFY_LIMIT_VIBRATION
        ));
    }
    (!lines.is_empty()).then(|| lines.join("\n") + "\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_closed_balance_is_ok_and_an_open_one_warns_with_a_hint() {
        let ok = assess(-5e-4, -5e-7, 1e-3, "ros34pw2", Some(1e-3), Some(1e-4));
        assert_eq!(ok.status, "ok");
        assert!(ok.reason.is_none() && ok.hint.is_none());
        assert!(warning(&ok).is_none());
        let bad = assess(0.25, 2.5e-4, 1e-3, "ros34pw2", Some(1e-3), Some(1e-4));
        assert_eq!(bad.status, "warning");
        let hint = bad.hint.clone().unwrap();
        assert!(hint.contains("solver.relative_tolerance=1e-4"), "{hint}");
        assert!(hint.contains("solver.energy_tolerance=1e-5"), "{hint}");
        let text = warning(&bad).unwrap();
        assert!(
            text.contains("2.50e-1 of the drive work (2.500e-4 J of 1.000e-3 J)"),
            "{text}"
        );
        let fixed = assess(0.25, 2.5e-4, 1e-3, "rk4", None, None);
        assert!(fixed.hint.unwrap().contains("solver.time_step"));
        let off = assess(-0.1, -1e-4, 1e-3, "dopri5", Some(1e-3), None);
        assert!(off.hint.unwrap().contains("energy_tolerance = 0"));
    }
}
