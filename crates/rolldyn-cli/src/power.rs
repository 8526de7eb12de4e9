//! `rolldyn power`: the friction power loss of a case at its Jones–Harris
//! equilibrium by Harris's local method (Lei et al. 2023 §3; docs/power.md), by
//! component, with the friction torque; text or JSON (keys in docs/cli.md).

pub use crate::power_report::PowerReport;
use crate::{CaseArgs, Failure, emit, json};
use clap::Args;
use rolldyn::power::LocalPowerLoss;
use rolldyn::quasistatic::Equilibrium;
use rolldyn_case::Case;
use serde::Serialize;
use std::fmt::Write as _;

/// Arguments of `rolldyn power`.
#[derive(Args, Debug)]
pub struct PowerArgs {
    #[command(flatten)]
    pub case: CaseArgs,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
}

/// Jones–Harris solution and local power loss of a case.
pub fn solve(case: &Case) -> Result<(Equilibrium, LocalPowerLoss), Failure> {
    rolldyn_case::simulation::power_loss(case).map_err(crate::simulation_failure)
}

pub fn command(args: PowerArgs) -> Result<(), Failure> {
    let report = report(&args)?;
    if args.json {
        json(&report)
    } else {
        let mut out = String::new();
        report.text(&mut out);
        emit(&out)
    }
}

/// One bearing of a set's or shaft's `rolldyn power`.
#[derive(Serialize)]
pub struct SystemPowerRow {
    pub position_m: f64,
    pub orientation: &'static str,
    pub power: PowerReport,
}

/// `rolldyn power --json`: one bearing's, or every bearing's of a set or
/// shaft at the system's quasi-static equilibrium.
#[derive(Serialize)]
#[serde(untagged)]
pub enum PowerOutput {
    /// One bearing.
    Bearing(Box<PowerReport>),
    /// Bearings on a shaft.
    System {
        kind: &'static str,
        power_loss_w: f64,
        bearings: Vec<SystemPowerRow>,
    },
}

impl PowerOutput {
    /// The text `rolldyn power` prints.
    pub fn text(&self, out: &mut String) {
        match self {
            Self::Bearing(r) => r.text(out),
            Self::System {
                kind,
                power_loss_w,
                bearings,
            } => {
                let _ = writeln!(
                    out,
                    "Power loss of the {kind} system: {power_loss_w:.4} W in all\n"
                );
                for (i, b) in bearings.iter().enumerate() {
                    let _ = writeln!(
                        out,
                        "Bearing {i} ({}, {:+.1} mm):",
                        b.orientation,
                        b.position_m * 1e3
                    );
                    b.power.text(out);
                    let _ = writeln!(out);
                }
            }
        }
    }
}

/// What `rolldyn power --json` prints.
pub fn report(args: &PowerArgs) -> Result<PowerOutput, Failure> {
    let (_, case) = args.case.load()?;
    let system = system_power(&case)?;
    if let Some(system) = system {
        return Ok(system);
    }
    let (eq, p) = solve(&case)?;
    Ok(PowerOutput::Bearing(Box::new(PowerReport::new(
        &case, &eq, &p,
    )?)))
}

/// Every bearing's power loss at the quasi-static equilibrium of a set
/// or shaft (None for one bearing), by Harris's local method with its own
/// case's inputs.
fn system_power(case: &Case) -> Result<Option<PowerOutput>, Failure> {
    use rolldyn::quasistatic::system::Orientation;
    use rolldyn_case::simulation::{BearingSet, ShaftModel};
    let fail = crate::simulation_failure;
    let (kind, mounted, cases, eq): (_, Vec<_>, Vec<Case>, _) =
        if let Some(set) = BearingSet::from_case(case).map_err(fail)? {
            let eq = set.solve().map_err(fail)?;
            let n = set.system.bearings.len();
            (
                rolldyn_case::case::kind_name(set.arrangement.kind),
                set.system.bearings,
                vec![case.clone(); n],
                eq,
            )
        } else if let Some(shaft) = ShaftModel::from_case(case).map_err(fail)? {
            let eq = shaft.solve().map_err(fail)?;
            (
                "shaft",
                shaft.system.bearings,
                shaft.bearings.into_iter().map(|b| b.case).collect(),
                eq,
            )
        } else {
            return Ok(None);
        };
    let mut bearings = Vec::with_capacity(mounted.len());
    for ((m, bearing_case), state) in mounted.iter().zip(&cases).zip(&eq.bearings) {
        let Some(state) = state else { continue };
        let inputs = bearing_case.local_method_inputs().map_err(crate::invalid)?;
        let loss = rolldyn::power::local_power_loss(&bearing_case.bearing.geometry, state, &inputs);
        bearings.push(SystemPowerRow {
            position_m: m.position,
            orientation: match m.orientation {
                Orientation::Forward => "forward",
                Orientation::Reversed => "reversed",
            },
            power: PowerReport::new(bearing_case, state, &loss)?,
        });
    }
    Ok(Some(PowerOutput::System {
        kind,
        power_loss_w: bearings.iter().map(|b| b.power.power_loss_w).sum(),
        bearings,
    }))
}
