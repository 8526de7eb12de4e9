//! `rolldyn thermal`: bearing temperatures (Lei et al. 2023 §4; docs/thermal.md).
//! The coupled quasi-static iteration to thermal steady state (Jones–Harris
//! → local power loss → thermal network → oil viscosity and operating
//! clearance) with its convergence history; with `--transient`, the
//! warm-up from the reference temperature at the converged heat sources.
//! Text or JSON (keys in docs/cli.md).

pub mod set;

use crate::power_report::PowerReport;
use crate::thermal_nodes::temperatures;
use crate::{CaseArgs, Failure, bad_arg, emit, json};
use clap::Args;
use rolldyn::thermal::BearingThermal;
use rolldyn::thermal::coupled::{CoupledSolution, heat_sources};
use rolldyn_case::Case;
use rolldyn_case::units::{Quantity, Time};
use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// Time steps of the transient by default.
pub const DEFAULT_STEPS: usize = 600;

/// Arguments of `rolldyn thermal` (`Default`: the command line's defaults,
/// the built-in case).
#[derive(Args, Debug)]
pub struct ThermalArgs {
    #[command(flatten)]
    pub case: CaseArgs,
    /// Also the warm-up from the reference temperature over this time,
    /// e.g. "30 min" (heat sources of the steady state, held constant).
    #[arg(long, value_name = "TIME", allow_hyphen_values = true)]
    pub transient: Option<String>,
    /// Time steps of the transient.
    #[arg(long, default_value_t = DEFAULT_STEPS, allow_hyphen_values = true)]
    pub steps: usize,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
}

impl Default for ThermalArgs {
    fn default() -> Self {
        Self {
            case: CaseArgs::default(),
            transient: None,
            steps: DEFAULT_STEPS,
            json: false,
        }
    }
}

/// One sample of the transient.
#[derive(Serialize)]
pub struct TransientRow {
    pub time_s: f64,
    pub temperatures_c: BTreeMap<&'static str, f64>,
}

/// `rolldyn thermal --json`.
#[derive(Serialize)]
pub struct ThermalReport {
    pub converged: bool,
    pub iterations: usize,
    /// Largest node-temperature change per pass \[K\].
    pub history_k: Vec<f64>,
    pub temperatures_c: BTreeMap<&'static str, f64>,
    pub heat_generated_w: f64,
    pub heat_to_ambient_w: f64,
    pub heat_to_oil_w: f64,
    pub oil_viscosity_pa_s: f64,
    pub oil_flow_m3_s: f64,
    pub reference_clearance_m: f64,
    pub operating_clearance_m: f64,
    pub power: PowerReport,
    pub transient: Option<Vec<TransientRow>>,
    /// What makes the steady state doubtful (printed at the end).
    pub warnings: Vec<String>,
}

/// The warnings of a thermal steady state: an iteration that did not
/// converge (`history_k`: each pass's largest change), a part beyond the
/// temperature no steel bearing runs at, and a bearing whose heat leaves
/// only by the housing and shaft to still air (no oil flow).
pub fn warnings<'a>(
    (converged, history_k): (bool, &[f64]),
    temperatures_c: impl Iterator<Item = (&'a str, f64)>,
    heat_w: f64,
    oil_flow_m3_s: f64,
) -> Vec<String> {
    let mut warnings = Vec::new();
    if !converged {
        warnings.push(format!(
            "not converged: after {} passes the temperatures still change by {:.3e} K a pass (the tolerance is 0.01 K); they are the last pass's",
            history_k.len(),
            history_k.last().copied().unwrap_or(f64::NAN)
        ));
    }
    if let Some(limit) = crate::run_options::temperature_limit(temperatures_c) {
        warnings.push(format!(
            "{limit}: the steady state is outside the model (oil and steel data); cool the bearing (thermal.oil_flow, thermal.housing_convection) or lower the speed or load"
        ));
    }
    if oil_flow_m3_s == 0.0 && heat_w > 0.0 {
        warnings.push(format!(
            "no oil flow: all {heat_w:.1} W leave through the housing and the shaft to still air; a circulating or jet-lubricated bearing sets thermal.oil_flow"
        ));
    }
    warnings
}

/// The coupled steady state of a case.
pub fn solve(case: &Case) -> Result<CoupledSolution, Failure> {
    rolldyn_case::simulation::thermal_steady_state(case).map_err(crate::simulation_failure)
}

pub fn command(args: ThermalArgs) -> Result<(), Failure> {
    let report = report(&args)?;
    if args.json {
        return json(&report);
    }
    emit(&report.to_text())
}

/// `rolldyn thermal`'s output: one bearing's, or a bearing set's.
#[derive(Serialize)]
#[serde(untagged)]
pub enum ThermalOutput {
    /// One bearing.
    Bearing(Box<ThermalReport>),
    /// A set (`[arrangement]`).
    Set(set::SetThermalReport),
}

impl ThermalOutput {
    /// The text `rolldyn thermal` prints.
    pub fn to_text(&self) -> String {
        match self {
            Self::Bearing(r) => r.to_text(),
            Self::Set(r) => r.to_text(),
        }
    }
}

/// What `rolldyn thermal --json` prints.
pub fn report(args: &ThermalArgs) -> Result<ThermalOutput, Failure> {
    let (_, case) = args.case.load()?;
    if case.bearing_set().is_some() || case.shaft.is_some() {
        if let Some(t) = &args.transient {
            return Err(bad_arg(
                "--transient",
                t,
                "the warm-up is computed for one bearing; bearings on a shaft give their steady state only",
            ));
        }
    }
    if let Some(report) = set::report(&case)? {
        return Ok(ThermalOutput::Set(report));
    }
    Ok(ThermalOutput::Bearing(Box::new(bearing_report(
        args, &case,
    )?)))
}

/// One bearing's report.
fn bearing_report(args: &ThermalArgs, case: &Case) -> Result<ThermalReport, Failure> {
    let duration = args
        .transient
        .as_deref()
        .map(|t| {
            Quantity::<Time>::parse(t)
                .map(|q| q.si)
                .map_err(|e| bad_arg("--transient", t, e))
                .and_then(|d| {
                    if d > 0.0 && d.is_finite() {
                        Ok(d)
                    } else {
                        Err(bad_arg("--transient", t, "must be a positive time"))
                    }
                })
        })
        .transpose()?;
    if !(1..=1_000_000).contains(&args.steps) {
        return Err(bad_arg(
            "--steps",
            &args.steps.to_string(),
            "must lie in [1, 1000000]",
        ));
    }
    let s = solve(case)?;
    let inputs = case.thermal_inputs().map_err(crate::invalid)?;
    let transient = match duration {
        None => None,
        Some(d) => {
            let mut thermal = inputs.clone();
            thermal.oil_kinematic_viscosity = s.oil_viscosity / thermal.oil_density;
            let heat = heat_sources(&case.bearing.geometry, &s.equilibrium, &s.power);
            let network = BearingThermal::new(&thermal, &heat)
                .map_err(|e| Failure::BadInput(e.to_string()))?;
            let mut start = [case.thermal.expansion.reference_temperature; 10];
            start[8] = thermal.ambient_temperature;
            start[9] = thermal.oil_inlet_temperature;
            let samples = 20.min(args.steps);
            let mut rows = Vec::new();
            let mut state = start;
            for k in 1..=samples {
                let from = (k - 1) * args.steps / samples;
                let to = k * args.steps / samples;
                let span = d * (to - from) as f64 / args.steps as f64;
                let next = network
                    .transient(&state, span, to - from)
                    .map_err(|e| Failure::BadInput(e.to_string()))?;
                state = next.temperatures;
                rows.push(TransientRow {
                    time_s: d * to as f64 / args.steps as f64,
                    temperatures_c: temperatures(&state),
                });
            }
            Some(rows)
        }
    };
    let temperatures_c = temperatures(&s.thermal.temperatures);
    Ok(ThermalReport {
        warnings: warnings(
            (s.converged, &s.history),
            temperatures_c.iter().map(|(n, t)| (*n, *t)),
            s.power.total(),
            inputs.oil_flow,
        ),
        converged: s.converged,
        iterations: s.history.len(),
        history_k: s.history.clone(),
        temperatures_c,
        heat_generated_w: s.power.total(),
        heat_to_ambient_w: s.thermal.to_ambient,
        heat_to_oil_w: s.thermal.to_oil,
        oil_viscosity_pa_s: s.oil_viscosity,
        oil_flow_m3_s: inputs.oil_flow,
        reference_clearance_m: case.bearing.geometry.equivalent_diametral_clearance(),
        operating_clearance_m: s.operating_clearance,
        power: PowerReport::new(case, &s.equilibrium, &s.power)?,
        transient,
    })
}

impl ThermalReport {
    /// The text `rolldyn thermal` prints.
    pub fn to_text(&self) -> String {
        let report = self;
        let mut out = String::new();
        let _ = writeln!(
            out,
            "Thermal steady state ({} after {} passes; last change {:.2e} K)",
            if report.converged {
                "converged"
            } else {
                "NOT converged"
            },
            report.iterations,
            report.history_k.last().copied().unwrap_or(0.0)
        );
        for (node, t) in &report.temperatures_c {
            let _ = writeln!(out, "  {node:<14} {t:>8.2} °C");
        }
        let _ = writeln!(
            out,
            "  heat {:.3} W: {:.3} W to ambient, {:.3} W to the oil ({:.3} L/min); oil viscosity {:.4} Pa·s",
            report.heat_generated_w,
            report.heat_to_ambient_w,
            report.heat_to_oil_w,
            report.oil_flow_m3_s * 6e4,
            report.oil_viscosity_pa_s
        );
        let _ = writeln!(
            out,
            "  diametral clearance {:.2} µm at the reference temperature, {:.2} µm operating\n",
            report.reference_clearance_m * 1e6,
            report.operating_clearance_m * 1e6
        );
        report.power.text(&mut out);
        for warning in &report.warnings {
            let _ = writeln!(out, "  warning: {warning}");
        }
        if let Some(rows) = &report.transient {
            let _ = writeln!(out, "\nWarm-up from the reference temperature:");
            let _ = writeln!(
                out,
                "  {:>10} {:>9} {:>9} {:>9} {:>9} {:>9}",
                "t s", "ball", "inner", "outer", "housing", "oil"
            );
            for r in rows {
                let t = |n: &str| r.temperatures_c.get(n).copied().unwrap_or(f64::NAN);
                let _ = writeln!(
                    out,
                    "  {:>10.1} {:>9.2} {:>9.2} {:>9.2} {:>9.2} {:>9.2}",
                    r.time_s,
                    t("ball"),
                    t("inner_ring"),
                    t("outer_ring"),
                    t("housing"),
                    t("oil")
                );
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::warnings;

    #[test]
    fn warnings_say_what_makes_a_steady_state_doubtful() {
        let cool = [("ball", 60.0), ("outer_ring", 55.0)];
        // Converged, cool, with an oil flow: nothing to say.
        assert!(warnings((true, &[1.0, 0.001]), cool.into_iter(), 40.0, 1e-5).is_empty());
        let w = warnings((false, &[3.0, 2.5]), cool.into_iter(), 40.0, 1e-5);
        assert_eq!(w.len(), 1);
        assert!(w[0].starts_with("not converged: after 2 passes"), "{w:?}");
        let w = warnings((true, &[0.001]), [("ball", 400.0)].into_iter(), 2e3, 0.0);
        assert_eq!(w.len(), 2, "{w:?}");
        assert!(w[0].contains("ball is at 400.0 °C") && w[1].contains("no oil flow"));
        // No heat: nothing leaves by any path worth a warning.
        assert!(warnings((true, &[0.0]), cool.into_iter(), 0.0, 0.0).is_empty());
    }
}
