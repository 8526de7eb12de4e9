//! `rolldyn quasistatic`: the static load distribution or Jones–Harris
//! equilibrium of a case (one bearing: `single`; a bearing set or shaft:
//! `set`), and sweeps over speed and loads written as CSV and JSON
//! (`sweep`). Keys are documented in docs/cli.md.

pub mod set;
pub mod single;
pub mod sweep;

pub use crate::sweep_grid::{MAX_SWEEP_POINTS, Swept, parse_sweep};
pub use rolldyn_case::simulation::conditions;
pub use single::{BallRow, QuasiStaticReport, RatingLife, solver};
pub use sweep::{SweepRow, SweepRows, run_sweep, sweep_case, sweep_csv};

use rolldyn::quasistatic::RacewayControl;
use rolldyn_case::Case;
use rolldyn_case::simulation::QuasiStatic;
use serde::Serialize;

/// The `--control` of `rolldyn quasistatic`: a raceway-control hypothesis
/// (None: the case's `model.raceway_control`) or the traction equilibrium.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ControlChoice {
    Raceway(Option<RacewayControl>),
    Traction,
}

impl ControlChoice {
    /// Parses `outer`, `inner`, `harris` or `traction` (None: the case's).
    pub fn parse(text: Option<&str>) -> Result<Self, crate::Failure> {
        Ok(match text {
            None => ControlChoice::Raceway(None),
            Some("outer") => ControlChoice::Raceway(Some(RacewayControl::Outer)),
            Some("inner") => ControlChoice::Raceway(Some(RacewayControl::Inner)),
            Some("harris") => ControlChoice::Raceway(Some(RacewayControl::Harris)),
            Some("traction") => ControlChoice::Traction,
            Some(other) => {
                return Err(crate::bad_arg(
                    "--control",
                    other,
                    "expected outer, inner, harris or traction",
                ));
            }
        })
    }
}

/// One solve as `rolldyn quasistatic` prints it.
#[derive(Serialize)]
#[serde(untagged)]
pub enum QuasiStaticOutput {
    Raceway(Box<QuasiStaticReport>),
    Traction(Box<crate::traction_equilibrium::TractionEquilibriumReport>),
    /// A bearing set (`[arrangement]`).
    Set(Box<set::SetReport>),
}

impl QuasiStaticOutput {
    /// The text `rolldyn quasistatic` prints.
    pub fn to_text(&self) -> String {
        match self {
            QuasiStaticOutput::Raceway(r) => r.to_text(),
            QuasiStaticOutput::Traction(r) => r.to_text(),
            QuasiStaticOutput::Set(r) => r.to_text(),
        }
    }
}

/// Solves the case at its operating point with the chosen control.
pub fn solve(case: &Case, control: ControlChoice) -> Result<QuasiStaticOutput, crate::Failure> {
    use crate::Failure;
    if let Some(model) =
        rolldyn_case::simulation::ShaftModel::from_case(case).map_err(crate::simulation_failure)?
    {
        if let ControlChoice::Raceway(Some(control)) = control {
            let mut model = model;
            model.conditions.control = control;
            return set::SetReport::of_shaft(&model).map(|r| QuasiStaticOutput::Set(Box::new(r)));
        }
        if matches!(control, ControlChoice::Traction) {
            return Err(crate::bad_arg(
                "--control",
                "traction",
                "not with [shaft] (shaft systems are solved with raceway control)",
            ));
        }
        return set::SetReport::of_shaft(&model).map(|r| QuasiStaticOutput::Set(Box::new(r)));
    }
    if let Some(mut set) =
        rolldyn_case::simulation::BearingSet::from_case(case).map_err(crate::simulation_failure)?
    {
        let ControlChoice::Raceway(control) = control else {
            return Err(crate::bad_arg(
                "--control",
                "traction",
                "not with [arrangement] (bearing sets are solved with raceway control)",
            ));
        };
        if let Some(control) = control {
            set.conditions.control = control;
        }
        return set::SetReport::new(case, &set).map(|r| QuasiStaticOutput::Set(Box::new(r)));
    }
    match control {
        ControlChoice::Traction => {
            crate::traction_equilibrium::TractionEquilibriumReport::new(case)
                .map(|r| QuasiStaticOutput::Traction(Box::new(r)))
                .map_err(Failure::BadInput)
        }
        ControlChoice::Raceway(control) => {
            let problem =
                QuasiStatic::from_case(case).map_err(|e| Failure::BadInput(e.to_string()))?;
            let conditions = conditions(case, control);
            let dry = problem
                .solver
                .solve(&conditions, &problem.options)
                .map_err(crate::quasistatic_failure)?;
            let held = case.prescribed_displacement.map(|p| p.is_some());
            let wet = (problem.film_in_approach && problem.films.is_some())
                .then(|| problem.solve_at(&conditions));
            let report = match wet {
                Some(wet) => {
                    let wet = wet.map_err(crate::quasistatic_failure)?;
                    QuasiStaticReport::new(&wet, &conditions, held)
                        .with_films_and_modes(case, &wet)
                        .with_dry_stiffness(&dry)
                }
                None => {
                    QuasiStaticReport::new(&dry, &conditions, held).with_films_and_modes(case, &dry)
                }
            };
            Ok(QuasiStaticOutput::Raceway(Box::new(report)))
        }
    }
}
