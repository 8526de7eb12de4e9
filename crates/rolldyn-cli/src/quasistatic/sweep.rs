//! `rolldyn quasistatic --sweep`: the grid of speeds and loads (first
//! sweep outermost), solved for the case's bearing (warm-started, in
//! parallel) or for its bearing set, and its rows as CSV and JSON. Keys in
//! docs/cli.md.

use super::set;
use super::single::{RPM, RatingLife, solver};
use crate::sweep_grid::{Swept, grid};
use rolldyn::operating::Loads;
use rolldyn::power::local_power_loss;
use rolldyn::quasistatic::{QuasiStaticError, RacewayControl, sweep};
use rolldyn_case::Case;
use rolldyn_case::simulation::conditions;
use serde::Serialize;
use std::fmt::Write as _;

/// One row of a sweep result.
#[derive(Serialize)]
pub struct SweepRow {
    pub speed_rpm: f64,
    pub force_x_n: f64,
    pub force_z_n: f64,
    pub converged: bool,
    pub error: Option<String>,
    pub cage_speed_rpm: Option<f64>,
    pub axial_displacement_m: Option<f64>,
    pub radial_displacement_z_m: Option<f64>,
    pub max_load_inner_n: Option<f64>,
    pub max_load_outer_n: Option<f64>,
    pub contact_angle_inner_deg: Option<f64>,
    pub contact_angle_outer_deg: Option<f64>,
    pub stiffness_axial_n_per_m: Option<f64>,
    pub stiffness_radial_z_n_per_m: Option<f64>,
    /// Harris's local power loss (null without a sliding friction).
    pub power_loss_w: Option<f64>,
    pub friction_torque_n_m: Option<f64>,
    /// ISO 281 basic rating life (null where not covered).
    pub basic_rating_life_h: Option<f64>,
    /// ISO/TS 16281 basic reference rating life (null where not solved).
    pub reference_rating_life_h: Option<f64>,
    /// Modified reference rating life (null without `life.contamination_factor`).
    pub modified_reference_rating_life_h: Option<f64>,
    /// Where the point is refused: the least axial load its solution
    /// branch needs at this radial load and speed (null otherwise).
    pub least_axial_load_n: Option<f64>,
}

impl SweepRow {
    /// Refused: the axial load is below the least its branch needs.
    pub fn refused(&self) -> bool {
        self.least_axial_load_n.is_some()
    }
}

/// Builds the grid (first sweep outermost) and solves it.
pub fn run_sweep(
    case: &Case,
    control: Option<RacewayControl>,
    sweeps: &[(Swept, Vec<f64>)],
) -> Result<Vec<SweepRow>, String> {
    let solver = solver(case)?;
    let base = conditions(case, control);
    let points = grid(base, sweeps, |c, swept, v| match swept {
        Swept::Speed => c.inner_speed = v,
        Swept::Axial => c.loads.force[0] = v,
        Swept::Radial => c.loads.force[2] = v,
    });
    let results = sweep(&solver, &points, &case.solver_options(), true);
    // The local power loss where the case allows it (docs/power.md).
    let power_inputs = case.local_method_inputs().ok();
    Ok(points
        .iter()
        .zip(results)
        .map(|(p, r)| {
            let Loads { force, .. } = p.loads;
            let mut row = SweepRow {
                speed_rpm: p.inner_speed / RPM,
                force_x_n: force[0],
                force_z_n: force[2],
                converged: r.is_ok(),
                error: r.as_ref().err().map(|e| e.to_string()),
                cage_speed_rpm: None,
                axial_displacement_m: None,
                radial_displacement_z_m: None,
                max_load_inner_n: None,
                max_load_outer_n: None,
                contact_angle_inner_deg: None,
                contact_angle_outer_deg: None,
                stiffness_axial_n_per_m: None,
                stiffness_radial_z_n_per_m: None,
                power_loss_w: None,
                friction_torque_n_m: None,
                basic_rating_life_h: None,
                reference_rating_life_h: None,
                modified_reference_rating_life_h: None,
                least_axial_load_n: match &r {
                    Err(QuasiStaticError::AxialLoadTooSmall {
                        least_axial_load, ..
                    }) => Some(*least_axial_load),
                    _ => None,
                },
            };
            let life = RatingLife::new(case, &p.loads, p.inner_speed, r.as_ref().ok());
            row.basic_rating_life_h = life.basic_rating_life_h;
            row.reference_rating_life_h = life.reference_rating_life_h;
            row.modified_reference_rating_life_h = life.modified_reference_rating_life_h;
            if let Ok(sol) = r {
                let top = sol
                    .balls
                    .iter()
                    .max_by(|a, b| a.inner.load.total_cmp(&b.inner.load));
                row.cage_speed_rpm = Some(sol.cage_speed() / RPM);
                row.axial_displacement_m = Some(sol.displacement[0]);
                row.radial_displacement_z_m = Some(sol.displacement[2]);
                row.max_load_inner_n = top.map(|b| b.inner.load);
                row.max_load_outer_n = sol.balls.iter().map(|b| b.outer.load).reduce(f64::max);
                row.contact_angle_inner_deg = top.map(|b| b.inner.contact_angle.to_degrees());
                row.contact_angle_outer_deg = top.map(|b| b.outer.contact_angle.to_degrees());
                row.stiffness_axial_n_per_m = Some(sol.stiffness[0][0]);
                row.stiffness_radial_z_n_per_m = Some(sol.stiffness[2][2]);
                if let Some(inputs) = &power_inputs {
                    let p = local_power_loss(&case.bearing.geometry, &sol, inputs);
                    row.power_loss_w = Some(p.total());
                    row.friction_torque_n_m = Some(p.friction_torque());
                }
            }
            row
        })
        .collect())
}

/// CSV text of sweep rows (header + one line per point).
pub fn sweep_csv(rows: &[SweepRow]) -> String {
    let mut out = String::from(
        "speed_rpm,force_x_n,force_z_n,converged,cage_speed_rpm,axial_displacement_m,radial_displacement_z_m,max_load_inner_n,max_load_outer_n,contact_angle_inner_deg,contact_angle_outer_deg,stiffness_axial_n_per_m,stiffness_radial_z_n_per_m,power_loss_w,friction_torque_n_m,basic_rating_life_h,reference_rating_life_h,modified_reference_rating_life_h,error,least_axial_load_n\n",
    );
    let f = |v: Option<f64>| v.map(|x| format!("{x:e}")).unwrap_or_default();
    for r in rows {
        let _ = writeln!(
            out,
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},\"{}\",{}",
            r.speed_rpm,
            r.force_x_n,
            r.force_z_n,
            r.converged,
            f(r.cage_speed_rpm),
            f(r.axial_displacement_m),
            f(r.radial_displacement_z_m),
            f(r.max_load_inner_n),
            f(r.max_load_outer_n),
            f(r.contact_angle_inner_deg),
            f(r.contact_angle_outer_deg),
            f(r.stiffness_axial_n_per_m),
            f(r.stiffness_radial_z_n_per_m),
            f(r.power_loss_w),
            f(r.friction_torque_n_m),
            f(r.basic_rating_life_h),
            f(r.reference_rating_life_h),
            f(r.modified_reference_rating_life_h),
            r.error.as_deref().unwrap_or("").replace('"', "'"),
            f(r.least_axial_load_n)
        );
    }
    out
}

/// The rows of `rolldyn quasistatic --sweep`: of one bearing, or of a
/// bearing set (`[arrangement]`).
#[derive(Serialize)]
#[serde(untagged)]
pub enum SweepRows {
    Bearing(Vec<SweepRow>),
    Set(Vec<set::SetSweepRow>),
}

impl SweepRows {
    /// `sweep.csv`.
    pub fn csv(&self) -> String {
        match self {
            Self::Bearing(rows) => sweep_csv(rows),
            Self::Set(rows) => set::sweep_csv(rows),
        }
    }

    /// Writes `DIR/sweep.csv` and `DIR/sweep.json` (created); returns the
    /// JSON text.
    pub fn write(&self, dir: &std::path::Path) -> Result<String, crate::Failure> {
        std::fs::create_dir_all(dir).map_err(|e| {
            crate::Failure::BadInput(format!("cannot create {}: {e}", dir.display()))
        })?;
        let json =
            crate::finite::to_json(self).map_err(|e| crate::Failure::Internal(e.to_string()))?;
        rolldyn_io::RunDir::new(dir)
            .write_sweep(&json, &self.csv())
            .map_err(|e| crate::Failure::BadInput(e.to_string()))?;
        Ok(json)
    }

    /// The summary line (without the files written).
    pub fn summary(&self) -> String {
        match self {
            Self::Bearing(rows) => {
                let refused = rows.iter().filter(|r| r.refused()).count();
                let failed = rows.iter().filter(|r| !r.converged).count() - refused;
                format!(
                    "{} points solved ({refused} refused: below the least axial load their branch needs, in the least_axial_load_n column; {failed} failed; reasons in the error column)",
                    rows.len()
                )
            }
            Self::Set(rows) => format!(
                "{} points of the bearing set solved ({} failed; reasons in the error column)",
                rows.len(),
                rows.iter().filter(|r| !r.converged).count()
            ),
        }
    }
}

/// The case over a grid of speed and loads: its bearing, its set or its
/// shaft system.
pub fn sweep_case(
    case: &Case,
    control: Option<RacewayControl>,
    sweeps: &[(Swept, Vec<f64>)],
) -> Result<SweepRows, crate::Failure> {
    if let Some(mut model) =
        rolldyn_case::simulation::ShaftModel::from_case(case).map_err(crate::simulation_failure)?
    {
        if model.elastic.is_some() {
            return Err(crate::Failure::BadInput(
                "shaft.diameter: an elastic shaft solves one operating point at a time (no --sweep yet); drop shaft.diameter to sweep the rigid shaft".into(),
            ));
        }
        if let Some(control) = control {
            model.conditions.control = control;
        }
        let shaft_loads: [f64; 3] =
            std::array::from_fn(|k| model.conditions.loads.force[k] - case.loads.force[k]);
        return Ok(SweepRows::Set(set::run_shaft_sweep(
            &model,
            shaft_loads,
            sweeps,
        )));
    }
    match rolldyn_case::simulation::BearingSet::from_case(case)
        .map_err(crate::simulation_failure)?
    {
        Some(mut set) => {
            if let Some(control) = control {
                set.conditions.control = control;
            }
            Ok(SweepRows::Set(set::run_sweep(&set, sweeps)))
        }
        None => run_sweep(case, control, sweeps)
            .map(SweepRows::Bearing)
            .map_err(crate::Failure::BadInput),
    }
}
