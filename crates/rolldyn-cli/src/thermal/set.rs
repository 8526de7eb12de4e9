//! `rolldyn thermal` of a bearing set (`[arrangement]`) or a `[shaft]`:
//! every bearing's coupled thermal steady state with the system's
//! equilibrium in the loop, and a set's preload at the operating
//! temperatures against its preload at the reference temperature (docs/systems.md, "Temperature"; keys in
//! docs/cli.md).

use crate::Failure;
use crate::power_report::PowerReport;
use crate::thermal_nodes::temperatures;
use rolldyn::quasistatic::system::{MountedBearing, Orientation};
use rolldyn_case::Case;
use rolldyn_case::case::{Preload, kind_name};
use rolldyn_case::simulation::{BearingSet, SetThermal, ShaftModel};
use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// One bearing of `rolldyn thermal --json` for a set.
#[derive(Serialize)]
pub struct SetBearingReport {
    pub position_m: f64,
    pub orientation: &'static str,
    pub temperatures_c: BTreeMap<&'static str, f64>,
    pub heat_generated_w: f64,
    pub heat_to_ambient_w: f64,
    pub heat_to_oil_w: f64,
    pub oil_viscosity_pa_s: f64,
    pub reference_clearance_m: f64,
    pub operating_clearance_m: f64,
    pub reference_axial_offset_m: f64,
    pub operating_axial_offset_m: f64,
    pub reference_axial_load_n: f64,
    pub operating_axial_load_n: f64,
    pub power: PowerReport,
}

/// `rolldyn thermal --json` for a case with `[arrangement]`.
#[derive(Serialize)]
pub struct SetThermalReport {
    pub converged: bool,
    pub iterations: usize,
    /// Largest node-temperature change of any bearing per pass \[K\].
    pub history_k: Vec<f64>,
    pub kind: &'static str,
    pub mounting_preload_n: Option<f64>,
    pub reference_preload_at_speed_n: Option<f64>,
    pub operating_preload_at_speed_n: Option<f64>,
    pub axial_strain: f64,
    pub heat_generated_w: f64,
    pub oil_flow_m3_s: f64,
    pub bearings: Vec<SetBearingReport>,
    /// What makes the steady state doubtful (super::warnings).
    pub warnings: Vec<String>,
}

fn axial_load(state: &Option<rolldyn::quasistatic::Equilibrium>) -> f64 {
    state.as_ref().map_or(0.0, MountedBearing::axial_load)
}

/// The report of a set's (`[arrangement]`) or shaft's (`[shaft]`)
/// thermal steady state, None for one bearing.
pub fn report(case: &Case) -> Result<Option<SetThermalReport>, Failure> {
    let fail = crate::simulation_failure;
    if let Some(set) = BearingSet::from_case(case).map_err(fail)? {
        let thermal = set.thermal_steady_state(case).map_err(fail)?;
        let n = set.system.bearings.len();
        let preload = match set.arrangement.preload {
            Preload::Force(f) => Some(f),
            _ => None,
        };
        return build(
            case,
            kind_name(set.arrangement.kind),
            preload,
            &set.system.bearings,
            &vec![case.clone(); n],
            thermal,
        )
        .map(Some);
    }
    if let Some(shaft) = ShaftModel::from_case(case).map_err(fail)? {
        let thermal = shaft.thermal_steady_state(case).map_err(fail)?;
        let cases: Vec<Case> = shaft.bearings.iter().map(|b| b.case.clone()).collect();
        return build(case, "shaft", None, &shaft.system.bearings, &cases, thermal).map(Some);
    }
    Ok(None)
}

/// The report of a system's thermal steady state: `mounted` its bearings
/// with their own `cases`.
fn build(
    case: &Case,
    kind: &'static str,
    mounting_preload: Option<f64>,
    mounted: &[MountedBearing],
    cases: &[Case],
    thermal: SetThermal,
) -> Result<SetThermalReport, Failure> {
    let SetThermal {
        cold,
        hot,
        preload_at_speed,
    } = thermal;
    let inputs = case
        .thermal_inputs()
        .map_err(|e| Failure::BadInput(format!("{}: {}", e.key, e.rule)))?;
    let mut bearings = Vec::with_capacity(hot.bearings.len());
    for (i, b) in hot.bearings.iter().enumerate() {
        let mounted = &mounted[i];
        let state = hot.equilibrium.bearings[i]
            .as_ref()
            .ok_or_else(|| Failure::Model(format!("bearing {i} is unloaded")))?;
        bearings.push(SetBearingReport {
            position_m: mounted.position,
            orientation: match mounted.orientation {
                Orientation::Forward => "forward",
                Orientation::Reversed => "reversed",
            },
            temperatures_c: temperatures(&b.thermal.temperatures),
            heat_generated_w: b.power.total(),
            heat_to_ambient_w: b.thermal.to_ambient,
            heat_to_oil_w: b.thermal.to_oil,
            oil_viscosity_pa_s: b.oil_viscosity,
            reference_clearance_m: cases[i].bearing.geometry.equivalent_diametral_clearance(),
            operating_clearance_m: b.operating_clearance,
            reference_axial_offset_m: mounted.axial_offset,
            operating_axial_offset_m: b.axial_offset,
            reference_axial_load_n: axial_load(&cold.bearings[i]),
            operating_axial_load_n: MountedBearing::axial_load(state),
            power: PowerReport::new(&cases[i], state, &b.power)?,
        });
    }
    let heat_generated_w = bearings.iter().map(|b| b.heat_generated_w).sum();
    let warnings = super::warnings(
        (hot.converged, &hot.history),
        bearings
            .iter()
            .flat_map(|b| b.temperatures_c.iter().map(|(n, t)| (*n, *t))),
        heat_generated_w,
        inputs.oil_flow,
    );
    Ok(SetThermalReport {
        warnings,
        converged: hot.converged,
        iterations: hot.history.len(),
        history_k: hot.history.clone(),
        kind,
        mounting_preload_n: mounting_preload,
        reference_preload_at_speed_n: preload_at_speed.map(|p| p[0]),
        operating_preload_at_speed_n: preload_at_speed.map(|p| p[1]),
        axial_strain: hot.axial_strain,
        heat_generated_w,
        oil_flow_m3_s: inputs.oil_flow,
        bearings,
    })
}

impl SetThermalReport {
    /// The text `rolldyn thermal` prints for a set.
    pub fn to_text(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "Thermal steady state of the {} ({} after {} passes; last change {:.2e} K)",
            if self.kind == "shaft" {
                "shaft system".to_string()
            } else {
                format!("{} set", self.kind)
            },
            if self.converged {
                "converged"
            } else {
                "NOT converged"
            },
            self.iterations,
            self.history_k.last().copied().unwrap_or(0.0)
        );
        if let (Some(cold), Some(hot)) = (
            self.reference_preload_at_speed_n,
            self.operating_preload_at_speed_n,
        ) {
            let mounting = self
                .mounting_preload_n
                .map_or(String::new(), |m| format!("mounted {m:.1} N; "));
            // (x + 0.0 prints a zero without its sign.)
            let (cold, hot) = (cold + 0.0, hot + 0.0);
            let change = if cold > 0.0 {
                format!(" ({:+.1} %)", 100.0 * (hot / cold - 1.0))
            } else {
                " (no preload left at the reference temperature: the clearance takes up the offset)"
                    .to_string()
            };
            let _ = writeln!(
                out,
                "  preload at speed: {mounting}{cold:.1} N at the reference temperature, {hot:.1} N at the operating temperatures{change}"
            );
        }
        let _ = writeln!(
            out,
            "  shaft against housing axial strain {:.3e}; heat {:.3} W in all ({:.3} L/min of oil per bearing)\n",
            self.axial_strain,
            self.heat_generated_w,
            self.oil_flow_m3_s * 6e4
        );
        let names = [
            "ball",
            "inner_ring",
            "outer_ring",
            "shaft",
            "housing",
            "oil",
        ];
        let _ = write!(out, "  {:<28}", "bearing");
        for (i, b) in self.bearings.iter().enumerate() {
            let _ = write!(
                out,
                " {:>16}",
                format!(
                    "{i} ({}, {:+.1} mm)",
                    &b.orientation[..3],
                    b.position_m * 1e3
                )
            );
        }
        let _ = writeln!(out);
        let mut row = |label: &str, value: &dyn Fn(&SetBearingReport) -> f64, digits: usize| {
            let _ = write!(out, "  {label:<28}");
            for b in &self.bearings {
                let _ = write!(out, " {:>16.*}", digits, value(b));
            }
            let _ = writeln!(out);
        };
        for name in names {
            row(&format!("{name} °C"), &|b| b.temperatures_c[name], 2);
        }
        row("heat W", &|b| b.heat_generated_w, 3);
        row(
            "clearance µm (reference)",
            &|b| b.reference_clearance_m * 1e6,
            2,
        );
        row(
            "clearance µm (operating)",
            &|b| b.operating_clearance_m * 1e6,
            2,
        );
        row(
            "offset µm (reference)",
            &|b| b.reference_axial_offset_m * 1e6,
            3,
        );
        row(
            "offset µm (operating)",
            &|b| b.operating_axial_offset_m * 1e6,
            3,
        );
        row("axial load N (reference)", &|b| b.reference_axial_load_n, 1);
        row("axial load N (operating)", &|b| b.operating_axial_load_n, 1);
        for warning in &self.warnings {
            let _ = writeln!(out, "  warning: {warning}");
        }
        out
    }
}
