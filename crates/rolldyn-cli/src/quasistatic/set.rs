//! `rolldyn quasistatic` of a case with `[arrangement]`: a matched bearing
//! set on one rigid shaft (docs/systems.md). The set's preload, lift-off
//! load and stiffness, each bearing's full quasi-static report and rating
//! life, and the system life; sweeps over speed and the shaft loads. Keys
//! in docs/cli.md.

use super::single::QuasiStaticReport;
use crate::sweep_grid::{Swept, grid};
use crate::{Failure, simulation_failure};
use rayon::prelude::*;
use rolldyn::operating::Loads;
use rolldyn::quasistatic::Conditions;
use rolldyn::quasistatic::system::{
    MountedBearing, Orientation, SystemConditions, SystemEquilibrium,
};
use rolldyn_case::Case;
use rolldyn_case::case::{Preload, kind_name};
use rolldyn_case::simulation::{BearingSet, ShaftModel};
use serde::Serialize;
use std::fmt::Write as _;

const RPM: f64 = std::f64::consts::TAU / 60.0;

/// Weibull slope of ball bearings in the series-system life rule.
pub const WEIBULL_SLOPE: f64 = 10.0 / 9.0;

/// The life of bearings in series (each must survive):
/// L = (Σ L_i^−e)^−1/e with e = 10/9 for ball bearings (ISO/TR 1281-1;
/// Harris & Kotzalas 2006). None if any life is unknown; infinite lives
/// drop out.
pub fn system_life(lives: &[Option<f64>]) -> Option<f64> {
    let mut sum = 0.0;
    for life in lives {
        let l = (*life)?;
        if l.is_finite() {
            sum += l.powf(-WEIBULL_SLOPE);
        }
    }
    (sum > 0.0).then(|| sum.powf(-1.0 / WEIBULL_SLOPE))
}

/// One bearing of the set.
#[derive(Serialize)]
pub struct SetBearingRow {
    /// Axial position of its pitch plane from the shaft reference point.
    pub position_m: f64,
    /// "forward" (carries +x thrust) or "reversed".
    pub orientation: &'static str,
    /// The axial load it carries, ≥ 0 on its loaded side.
    pub axial_load_n: f64,
    /// Its radial load.
    pub radial_load_n: f64,
    /// Its load on the shaft about the reference point (F_x, F_y, F_z
    /// \[N\], M_y, M_z \[N·m\]); on an elastic shaft about its own node.
    pub shaft_load: [f64; 5],
    /// The tilt of its inner ring against its outer ring, √(θ_y² + θ_z²)
    /// \[rad\] (on an elastic shaft: with the shaft's bending).
    pub misalignment_rad: f64,
    /// Its quasi-static report in its own frame, its loads being what the
    /// shaft applies to it; null where the external load has unloaded it
    /// (beyond lift-off).
    pub quasistatic: Option<Box<QuasiStaticReport>>,
}

/// A node of an elastic shaft.
#[derive(Serialize)]
pub struct ShaftNode {
    /// Axial position from the reference point \[m\].
    pub position_m: f64,
    /// Its displacement (x, y, z \[m\], θ_y, θ_z \[rad\]).
    pub displacement: [f64; 5],
}

/// `arrangement` in `rolldyn quasistatic --json`.
#[derive(Serialize)]
pub struct ArrangementReport {
    /// The set's kind, or "shaft" for a `[shaft]` system.
    pub kind: &'static str,
    /// Distance between a set's pitch planes (null for a `[shaft]`).
    pub spacing_m: Option<f64>,
    /// The preload as given: force (at rest) or displacement.
    pub preload_given: String,
    /// Axial offset of each inner ring that sets the preload.
    pub preload_offset_m: f64,
    /// Bearing 0's axial load without external load at this speed (null
    /// without preload).
    pub preload_n: Option<f64>,
    /// External axial load that unloads the opposed bearing, at rest
    /// (null for tandem sets or without preload).
    pub lift_off_axial_load_n: Option<f64>,
    /// Shaft displacement at the reference point (x, y, z \[m\], θ_y, θ_z
    /// \[rad\]).
    pub shaft_displacement: [f64; 5],
    pub axial_stiffness_n_per_m: f64,
    /// The set's stiffness at the reference point (rows and columns x, y,
    /// z, θ_y, θ_z; N/m, N/rad, N·m/m, N·m/rad).
    pub stiffness_matrix: [[f64; 5]; 5],
    /// Its inverse (null where singular).
    pub compliance_matrix: Option<[[f64; 5]; 5]>,
    pub iterations: usize,
    /// An elastic shaft's nodes (null for a rigid shaft).
    pub shaft_nodes: Option<Vec<ShaftNode>>,
    pub bearings: Vec<SetBearingRow>,
    /// Series-system lives (null where a bearing's life is unknown).
    pub system_basic_rating_life_h: Option<f64>,
    pub system_reference_rating_life_h: Option<f64>,
    pub system_modified_reference_rating_life_h: Option<f64>,
}

/// `rolldyn quasistatic --json` of a set.
#[derive(Serialize)]
pub struct SetReport {
    pub speed_rpm: f64,
    pub raceway_control: rolldyn::quasistatic::RacewayControl,
    pub force_x_n: f64,
    pub force_y_n: f64,
    pub force_z_n: f64,
    pub moment_y_n_m: f64,
    pub moment_z_n_m: f64,
    pub arrangement: ArrangementReport,
}

fn compliance(k: &[[f64; 5]; 5]) -> Option<[[f64; 5]; 5]> {
    let m = nalgebra::SMatrix::<f64, 5, 5>::from_fn(|i, j| k[i][j]);
    m.try_inverse()
        .map(|c| std::array::from_fn(|i| std::array::from_fn(|j| c[(i, j)])))
}

/// Each bearing's row: its loads and its quasi-static report (from its
/// own case: rating life, films, modes) at the system's equilibrium.
fn bearing_rows<'a>(
    mounted: impl Iterator<Item = (&'a MountedBearing, &'a Case)>,
    eq: &SystemEquilibrium,
    c: &SystemConditions,
) -> Vec<SetBearingRow> {
    mounted
        .zip(&eq.bearings)
        .zip(&eq.shaft_loads)
        .map(|(((b, case), sol), share)| {
            let quasistatic = sol.as_ref().map(|sol| {
                let r = sol.reaction;
                let conditions = Conditions {
                    loads: Loads {
                        force: [r[0], r[1], r[2]],
                        moment: [r[3], r[4]],
                    },
                    inner_speed: c.inner_speed,
                    control: c.control,
                };
                Box::new(
                    QuasiStaticReport::new(sol, &conditions, [false; 5])
                        .with_films_and_modes(case, sol),
                )
            });
            SetBearingRow {
                position_m: b.position,
                orientation: match b.orientation {
                    Orientation::Forward => "forward",
                    Orientation::Reversed => "reversed",
                },
                axial_load_n: sol.as_ref().map_or(0.0, |s| s.reaction[0]),
                radial_load_n: sol
                    .as_ref()
                    .map_or(0.0, |s| s.reaction[1].hypot(s.reaction[2])),
                shaft_load: *share,
                misalignment_rad: sol
                    .as_ref()
                    .map_or(0.0, |s| s.displacement[3].hypot(s.displacement[4])),
                quasistatic,
            }
        })
        .collect()
}

impl ArrangementReport {
    /// The system's part of the report: displacement, stiffness, the
    /// bearings and the series lives; no set, spacing or preload (a
    /// `[shaft]` system: kind "shaft").
    fn of_system(eq: &SystemEquilibrium, bearings: Vec<SetBearingRow>) -> Self {
        let lives = |pick: fn(&super::single::RatingLife) -> Option<f64>| {
            let each: Vec<Option<f64>> = bearings
                .iter()
                .map(|b| match &b.quasistatic {
                    Some(q) => q.rating_life.as_ref().and_then(pick),
                    // Unloaded: it does not fail.
                    None => Some(f64::INFINITY),
                })
                .collect();
            system_life(&each)
        };
        Self {
            kind: "shaft",
            spacing_m: None,
            preload_given: "none".into(),
            preload_offset_m: 0.0,
            preload_n: None,
            lift_off_axial_load_n: None,
            shaft_displacement: eq.displacement,
            axial_stiffness_n_per_m: eq.stiffness[0][0],
            stiffness_matrix: eq.stiffness,
            compliance_matrix: compliance(&eq.stiffness),
            iterations: eq.iterations,
            shaft_nodes: None,
            system_basic_rating_life_h: lives(|r| r.basic_rating_life_h),
            system_reference_rating_life_h: lives(|r| r.reference_rating_life_h),
            system_modified_reference_rating_life_h: lives(|r| r.modified_reference_rating_life_h),
            bearings,
        }
    }
}

impl SetReport {
    /// Solves the case's set at its operating point.
    pub fn new(case: &Case, set: &BearingSet) -> Result<Self, Failure> {
        let eq = set.solve().map_err(simulation_failure)?;
        let preload = set.preload_at_speed().map_err(simulation_failure)?;
        let lift_off = set.lift_off_load().map_err(simulation_failure)?;
        Ok(Self::of(case, set, &eq, preload, lift_off))
    }

    fn of(
        case: &Case,
        set: &BearingSet,
        eq: &SystemEquilibrium,
        preload: Option<f64>,
        lift_off: Option<f64>,
    ) -> Self {
        let mounted = set.system.bearings.iter().map(|b| (b, case));
        let bearings = bearing_rows(mounted, eq, &set.conditions);
        let arrangement = ArrangementReport {
            kind: kind_name(set.arrangement.kind),
            spacing_m: Some(set.arrangement.spacing),
            preload_given: match set.arrangement.preload {
                Preload::None => "none".into(),
                Preload::Force(f) => format!("{f} N at rest"),
                Preload::Displacement(d) => format!("{} um", d * 1e6),
            },
            preload_offset_m: set.offset,
            preload_n: preload,
            lift_off_axial_load_n: lift_off,
            ..ArrangementReport::of_system(eq, bearings)
        };
        Self::at(&set.conditions, arrangement)
    }

    /// Solves the case's `[shaft]` system at its operating point.
    pub fn of_shaft(model: &ShaftModel) -> Result<Self, Failure> {
        let elastic = model.solve_elastic().map_err(simulation_failure)?;
        let eq = match &elastic {
            Some(e) => e.system.clone(),
            None => model.solve().map_err(simulation_failure)?,
        };
        let mounted = model.bearings.iter().map(|b| (&b.mounted, &b.case));
        let bearings = bearing_rows(mounted, &eq, &model.conditions);
        Ok(Self::at(
            &model.conditions,
            ArrangementReport {
                shaft_nodes: elastic.map(|e| {
                    e.nodes
                        .iter()
                        .zip(&e.displacements)
                        .map(|(x, u)| ShaftNode {
                            position_m: *x,
                            displacement: *u,
                        })
                        .collect()
                }),
                ..ArrangementReport::of_system(&eq, bearings)
            },
        ))
    }

    fn at(c: &SystemConditions, arrangement: ArrangementReport) -> Self {
        Self {
            speed_rpm: c.inner_speed / RPM,
            raceway_control: c.control,
            force_x_n: c.loads.force[0],
            force_y_n: c.loads.force[1],
            force_z_n: c.loads.force[2],
            moment_y_n_m: c.loads.moment[0],
            moment_z_n_m: c.loads.moment[1],
            arrangement,
        }
    }

    /// The text `rolldyn quasistatic` prints.
    pub fn to_text(&self) -> String {
        let a = &self.arrangement;
        let mut out = String::new();
        let f =
            |v: Option<f64>, unit: &str| v.map_or("—".to_string(), |v| format!("{v:.2} {unit}"));
        match a.spacing_m {
            Some(spacing) => {
                let _ = writeln!(
                    out,
                    "Bearing set: {}, pitch planes {:.2} mm apart, at {:.0} rpm ({:?} raceway control)",
                    a.kind,
                    spacing * 1e3,
                    self.speed_rpm,
                    self.raceway_control
                );
            }
            None => {
                let _ = writeln!(
                    out,
                    "Shaft with {} bearings, at {:.0} rpm ({:?} raceway control)",
                    a.bearings.len(),
                    self.speed_rpm,
                    self.raceway_control
                );
            }
        }
        let _ = writeln!(
            out,
            "  shaft loads about the reference point: F_x {} N, F_y {} N, F_z {} N, M_y {} N·m, M_z {} N·m",
            self.force_x_n, self.force_y_n, self.force_z_n, self.moment_y_n_m, self.moment_z_n_m
        );
        if a.spacing_m.is_some() {
            let _ = writeln!(
                out,
                "  preload {} (offset {:.3} µm per ring): {} at this speed; lift-off axial load {} (at rest)",
                a.preload_given,
                a.preload_offset_m * 1e6,
                f(a.preload_n, "N"),
                f(a.lift_off_axial_load_n, "N")
            );
        }
        let u = a.shaft_displacement;
        let _ = writeln!(
            out,
            "  shaft: x {:.3} µm, y {:.3} µm, z {:.3} µm, θ_y {:.3e} rad, θ_z {:.3e} rad",
            u[0] * 1e6,
            u[1] * 1e6,
            u[2] * 1e6,
            u[3],
            u[4]
        );
        let k = a.stiffness_matrix;
        let _ = writeln!(
            out,
            "  stiffness: axial {:.4e} N/m, radial {:.4e} / {:.4e} N/m, tilt {:.4e} / {:.4e} N·m/rad",
            k[0][0], k[1][1], k[2][2], k[3][3], k[4][4]
        );
        bearing_table(a, &mut out);
        shaft_nodes_text(a, &mut out);
        let _ = writeln!(
            out,
            "  system life (bearings in series, e = 10/9): L10 {}, L10r {}, L10mr {}",
            f(a.system_basic_rating_life_h, "h"),
            f(a.system_reference_rating_life_h, "h"),
            f(a.system_modified_reference_rating_life_h, "h")
        );
        out
    }
}

/// The table of the set's bearings: position, faces, loads, the most
/// loaded ball's loads and contact angles.
fn bearing_table(a: &ArrangementReport, out: &mut String) {
    let _ = writeln!(
        out,
        "  bearing  position mm  faces  axial N     radial N    max Q_i N   max Q_o N   α_i °    α_o °"
    );
    for (i, b) in a.bearings.iter().enumerate() {
        // An unloaded bearing has no contact angle: a dash.
        let angle = |a: Option<f64>| a.map_or("—".to_string(), |a| format!("{a:.2}"));
        let (qi, qo, ai, ao) =
            b.quasistatic
                .as_ref()
                .map_or((0.0, 0.0, angle(None), angle(None)), |q| {
                    let max = |g: fn(&super::single::BallRow) -> f64| {
                        q.balls.iter().map(g).fold(0.0, f64::max)
                    };
                    // The contact angles of the most loaded ball (an
                    // unloaded ball's are those of open contacts).
                    let top = q
                        .balls
                        .iter()
                        .max_by(|a, b| a.load_inner_n.total_cmp(&b.load_inner_n));
                    (
                        max(|r| r.load_inner_n),
                        max(|r| r.load_outer_n),
                        angle(top.map(|r| r.contact_angle_inner_deg)),
                        angle(top.map(|r| r.contact_angle_outer_deg)),
                    )
                });
        let _ = writeln!(
            out,
            "  {i:<7}  {:>11.2}  {:<5}  {:>10.2}  {:>10.2}  {:>10.2}  {:>10.2}  {:>7}  {:>7}{}",
            b.position_m * 1e3,
            if b.orientation == "forward" {
                "+x"
            } else {
                "−x"
            },
            b.axial_load_n,
            b.radial_load_n,
            qi,
            qo,
            ai,
            ao,
            if b.quasistatic.is_none() {
                "  (unloaded beyond lift-off)"
            } else {
                ""
            }
        );
    }
}

/// An elastic shaft's node displacements and the inner rings'
/// misalignments.
fn shaft_nodes_text(a: &ArrangementReport, out: &mut String) {
    if let Some(nodes) = &a.shaft_nodes {
        let _ = writeln!(
            out,
            "  elastic shaft: node  position mm   y µm       z µm       θ_y rad      θ_z rad"
        );
        for (n, node) in nodes.iter().enumerate() {
            let u = node.displacement;
            let _ = writeln!(
                out,
                "                 {n:<4}  {:>11.2}  {:>9.3}  {:>9.3}  {:>11.3e}  {:>11.3e}",
                node.position_m * 1e3,
                u[1] * 1e6,
                u[2] * 1e6,
                u[3],
                u[4]
            );
        }
        let _ = writeln!(
            out,
            "  misalignment of the inner rings (shaft bending and tilt): {}",
            a.bearings
                .iter()
                .enumerate()
                .map(|(i, b)| format!("{i}: {:.3e} rad", b.misalignment_rad))
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
}

/// One point of a set's sweep.
#[derive(Serialize)]
pub struct SetSweepRow {
    pub speed_rpm: f64,
    pub force_x_n: f64,
    pub force_z_n: f64,
    pub converged: bool,
    pub preload_n: Option<f64>,
    pub axial_displacement_m: Option<f64>,
    pub axial_stiffness_n_per_m: Option<f64>,
    pub radial_stiffness_z_n_per_m: Option<f64>,
    pub tilt_stiffness_y_n_m_per_rad: Option<f64>,
    /// Each bearing's axial load, in the set's order.
    pub axial_loads_n: Option<Vec<f64>>,
    /// Each bearing's cage speed (null for an unloaded bearing).
    pub cage_speeds_rpm: Option<Vec<Option<f64>>>,
    pub error: Option<String>,
}

/// The set at every point of the grid (speed, F_x, F_z); the preload
/// offset stays that of the case (set at rest); the preload at speed,
/// which the loads do not change, once per speed.
pub fn run_sweep(set: &BearingSet, sweeps: &[(Swept, Vec<f64>)]) -> Vec<SetSweepRow> {
    let (system, options) = (&set.system, &set.options);
    sweep_rows(
        set.conditions,
        [0.0; 3],
        sweeps,
        |c, near| {
            near.and_then(|(n, start)| system.solve_predicted(start, n, c, options).ok())
                .map_or_else(|| system.solve(c, options), Ok)
                .map_err(|e| e.to_string())
        },
        |speed| {
            BearingSet {
                conditions: SystemConditions {
                    inner_speed: speed,
                    ..set.conditions
                },
                ..set.clone()
            }
            .preload_at_speed()
            .map_err(|e| e.to_string())
        },
    )
}

/// A `[shaft]` system at every point of the grid (speed, and the
/// `[operating]` F_x, F_z at the reference point, on top of the
/// `[[shaft.loads]]` (`shaft_loads`, their resultant forces); no preload.
pub fn run_shaft_sweep(
    model: &ShaftModel,
    shaft_loads: [f64; 3],
    sweeps: &[(Swept, Vec<f64>)],
) -> Vec<SetSweepRow> {
    let (system, options) = (&model.system, &model.options);
    sweep_rows(
        model.conditions,
        shaft_loads,
        sweeps,
        |c, near| {
            near.and_then(|(n, start)| system.solve_predicted(start, n, c, options).ok())
                .map_or_else(|| system.solve_general(c, options), Ok)
                .map_err(|e| e.to_string())
        },
        |_| Ok(None),
    )
}

/// The grid's points solved by `solve`: the rows of the innermost sweep in
/// parallel, each point of a row from the previous one's equilibrium and
/// from the shaft displacement extrapolated through the last two (the same
/// equilibria as cold solves to the solvers' tolerances; the rows are
/// fixed by the grid, so the results do not depend on the thread count);
/// `preload` once per distinct speed. A swept load is added to `fixed`
/// (loads the sweep does not set; the rows report the swept value).
fn sweep_rows<S, P>(
    base: SystemConditions,
    fixed: [f64; 3],
    sweeps: &[(Swept, Vec<f64>)],
    solve: S,
    preload: P,
) -> Vec<SetSweepRow>
where
    S: Fn(
            &SystemConditions,
            Option<(&SystemEquilibrium, [f64; 5])>,
        ) -> Result<SystemEquilibrium, String>
        + Sync,
    P: Fn(f64) -> Result<Option<f64>, String> + Sync,
{
    let points = grid(base, sweeps, |c, swept, v| match swept {
        Swept::Speed => c.inner_speed = v,
        Swept::Axial => c.loads.force[0] = fixed[0] + v,
        Swept::Radial => c.loads.force[2] = fixed[2] + v,
    });
    let mut speeds: Vec<f64> = points.iter().map(|c| c.inner_speed).collect();
    speeds.sort_by(f64::total_cmp);
    speeds.dedup();
    let preloads: Vec<Result<Option<f64>, String>> =
        speeds.par_iter().map(|&speed| preload(speed)).collect();
    let preload_at = |speed: f64| preloads[speeds.partition_point(|&s| s < speed)].clone();
    let row_len = sweeps.last().map_or(1, |(_, values)| values.len().max(1));
    points
        .par_chunks(row_len)
        .flat_map_iter(|row| {
            let mut near: Option<SystemEquilibrium> = None;
            let mut before: Option<[f64; 5]> = None;
            let mut out = Vec::with_capacity(row.len());
            for c in row {
                // Newton from the line through the last two points.
                let guess = near.as_ref().map(|n| {
                    let start = before.map_or(n.displacement, |b| {
                        std::array::from_fn(|k| 2.0 * n.displacement[k] - b[k])
                    });
                    (n, start)
                });
                let solved = solve(c, guess).and_then(|eq| Ok((eq, preload_at(c.inner_speed)?)));
                let mut row = SetSweepRow {
                    speed_rpm: c.inner_speed / RPM,
                    force_x_n: c.loads.force[0] - fixed[0],
                    force_z_n: c.loads.force[2] - fixed[2],
                    converged: solved.is_ok(),
                    preload_n: None,
                    axial_displacement_m: None,
                    axial_stiffness_n_per_m: None,
                    radial_stiffness_z_n_per_m: None,
                    tilt_stiffness_y_n_m_per_rad: None,
                    axial_loads_n: None,
                    cage_speeds_rpm: None,
                    error: solved.as_ref().err().cloned(),
                };
                if let Ok((eq, preload)) = solved {
                    row.preload_n = preload;
                    row.axial_displacement_m = Some(eq.displacement[0]);
                    row.axial_stiffness_n_per_m = Some(eq.stiffness[0][0]);
                    row.radial_stiffness_z_n_per_m = Some(eq.stiffness[2][2]);
                    row.tilt_stiffness_y_n_m_per_rad = Some(eq.stiffness[3][3]);
                    row.axial_loads_n = Some(
                        eq.bearings
                            .iter()
                            .map(|b| b.as_ref().map_or(0.0, |b| b.reaction[0]))
                            .collect(),
                    );
                    row.cage_speeds_rpm = Some(
                        eq.bearings
                            .iter()
                            .map(|b| b.as_ref().map(|b| b.cage_speed() / RPM))
                            .collect(),
                    );
                    before = near.as_ref().map(|n| n.displacement);
                    near = Some(eq);
                }
                out.push(row);
            }
            out
        })
        .collect()
}

/// The sweep as CSV (one row per point; the bearings' axial loads joined
/// by `;`).
pub fn sweep_csv(rows: &[SetSweepRow]) -> String {
    let mut out = String::from(
        "speed_rpm,force_x_n,force_z_n,converged,preload_n,axial_displacement_m,axial_stiffness_n_per_m,radial_stiffness_z_n_per_m,tilt_stiffness_y_n_m_per_rad,axial_loads_n,cage_speeds_rpm,error\n",
    );
    let f = |v: Option<f64>| v.map_or(String::new(), |v| format!("{v:e}"));
    for r in rows {
        let _ = writeln!(
            out,
            "{},{},{},{},{},{},{},{},{},{},{},\"{}\"",
            r.speed_rpm,
            r.force_x_n,
            r.force_z_n,
            r.converged,
            f(r.preload_n),
            f(r.axial_displacement_m),
            f(r.axial_stiffness_n_per_m),
            f(r.radial_stiffness_z_n_per_m),
            f(r.tilt_stiffness_y_n_m_per_rad),
            r.axial_loads_n.as_ref().map_or(String::new(), |v| v
                .iter()
                .map(|x| format!("{x:e}"))
                .collect::<Vec<_>>()
                .join(";")),
            r.cage_speeds_rpm.as_ref().map_or(String::new(), |v| v
                .iter()
                .map(|x| x.map_or(String::new(), |x| format!("{x:e}")))
                .collect::<Vec<_>>()
                .join(";")),
            r.error.as_deref().unwrap_or("").replace('"', "'")
        );
    }
    out
}
