//! `rolldyn quasistatic --control traction` and `solver.start =
//! "quasistatic_traction"`: the traction-consistent quasi-static
//! equilibrium (no raceway control; [`rolldyn::dynamics::traction_equilibrium`]),
//! started from the case's Jones–Harris solution. Keys in docs/cli.md.

use rolldyn::dynamics::ContactSample;
use rolldyn::operating::{LoadProfile, SpeedProfile};
use rolldyn_case::Case;
use rolldyn_case::simulation::{self, traction_state};
use serde::Serialize;
use std::fmt::Write as _;

const RPM: f64 = std::f64::consts::TAU / 60.0;

/// One ball of the report.
#[derive(Serialize)]
pub struct TractionBallRow {
    pub azimuth_deg: f64,
    pub load_inner_n: f64,
    pub load_outer_n: f64,
    pub contact_angle_inner_deg: f64,
    pub contact_angle_outer_deg: f64,
    pub orbital_speed_rpm: f64,
    pub attitude_deg: f64,
    pub yaw_deg: f64,
    pub slide_to_roll_inner: f64,
    pub slide_to_roll_outer: f64,
    pub spin_to_roll_inner: f64,
    pub spin_to_roll_outer: f64,
    pub stick_fraction_inner: Option<f64>,
    pub stick_fraction_outer: Option<f64>,
}

/// `rolldyn quasistatic --control traction --json`.
#[derive(Serialize)]
pub struct TractionEquilibriumReport {
    pub speed_rpm: f64,
    pub raceway_control: &'static str,
    pub traction_law: String,
    pub force_x_n: f64,
    pub force_y_n: f64,
    pub force_z_n: f64,
    pub cage_speed_rpm: f64,
    pub cage_speed_ratio: f64,
    pub axial_displacement_m: f64,
    pub radial_displacement_y_m: f64,
    pub radial_displacement_z_m: f64,
    pub tilt_y_rad: f64,
    pub tilt_z_rad: f64,
    pub balls: Vec<TractionBallRow>,
}

impl TractionEquilibriumReport {
    /// Solves the case at its final speed and constant loads.
    pub fn new(case: &Case) -> Result<Self, String> {
        let mut params = case
            .dynamics_parameters()
            .map_err(|e| format!("{}: {}", e.key, e.rule))?;
        let speed = case.speed.as_ref().map_or(0.0, |s| s.final_speed());
        if speed == 0.0 {
            return Err(
                "--control traction needs a speed (operating.speed or --speed): at rest there is no rolling".into(),
            );
        }
        params.speed = SpeedProfile::Constant(speed);
        params.loads = LoadProfile::Constant(case.loads);
        let traction_law = serde_json::to_value(params.traction)
            .ok()
            .and_then(|v| v.get("law").and_then(|l| l.as_str()).map(str::to_string))
            .unwrap_or_else(|| "none".into());
        let model = simulation::model(case, params).map_err(|e| e.to_string())?;
        let y = traction_state(case, &model, 0.0)?;
        let l = model.layout();
        let mut samples = vec![ContactSample::default(); l.balls];
        model.contact_samples(0.0, &y, &mut samples);
        let balls = samples
            .iter()
            .enumerate()
            .map(|(j, s)| {
                let b = l.ball(j);
                let (attitude, yaw) = model.ball_attitude(j, &y);
                TractionBallRow {
                    azimuth_deg: y[b + 2].to_degrees(),
                    load_inner_n: s.inner.load,
                    load_outer_n: s.outer.load,
                    contact_angle_inner_deg: s.inner.angle.to_degrees(),
                    contact_angle_outer_deg: s.outer.angle.to_degrees(),
                    orbital_speed_rpm: y[b + 5] / RPM,
                    attitude_deg: attitude.to_degrees(),
                    yaw_deg: yaw.to_degrees(),
                    slide_to_roll_inner: s.inner.slide_to_roll,
                    slide_to_roll_outer: s.outer.slide_to_roll,
                    spin_to_roll_inner: s.inner.spin_to_roll,
                    spin_to_roll_outer: s.outer.spin_to_roll,
                    stick_fraction_inner: s.inner.creep.map(|c| c.stick_fraction),
                    stick_fraction_outer: s.outer.creep.map(|c| c.stick_fraction),
                }
            })
            .collect();
        let cage = y[l.cage() + 5];
        let r = l.ring();
        Ok(Self {
            speed_rpm: speed / RPM,
            raceway_control: "traction",
            traction_law,
            force_x_n: case.loads.force[0],
            force_y_n: case.loads.force[1],
            force_z_n: case.loads.force[2],
            cage_speed_rpm: cage / RPM,
            cage_speed_ratio: cage / speed,
            axial_displacement_m: y[r],
            radial_displacement_y_m: y[r + 1],
            radial_displacement_z_m: y[r + 2],
            tilt_y_rad: y[r + 3],
            tilt_z_rad: y[r + 4],
            balls,
        })
    }

    pub fn to_text(&self) -> String {
        let mut out = format!(
            "Traction-consistent quasi-static equilibrium at {:.0} rpm ({} traction, no raceway control)\n",
            self.speed_rpm, self.traction_law
        );
        let _ = writeln!(
            out,
            "  loads: F_x {} N, F_y {} N, F_z {} N",
            self.force_x_n, self.force_y_n, self.force_z_n
        );
        let _ = writeln!(
            out,
            "  inner ring: x {:.3} µm, y {:.3} µm, z {:.3} µm, θ_y {:.3e} rad, θ_z {:.3e} rad",
            self.axial_displacement_m * 1e6,
            self.radial_displacement_y_m * 1e6,
            self.radial_displacement_z_m * 1e6,
            self.tilt_y_rad,
            self.tilt_z_rad
        );
        let _ = writeln!(
            out,
            "  cage speed: {:.1} rpm (ω_c/ω_i = {:.5}, mean orbital speed)",
            self.cage_speed_rpm, self.cage_speed_ratio
        );
        let _ = writeln!(
            out,
            "\n  {:>7} {:>10} {:>10} {:>8} {:>8} {:>9} {:>7} {:>7} {:>9} {:>9} {:>8} {:>8}",
            "φ deg",
            "Q_i N",
            "Q_o N",
            "α_i °",
            "α_o °",
            "ω_m rpm",
            "β °",
            "β' °",
            "sl/r i",
            "sl/r o",
            "sp/r i",
            "sp/r o"
        );
        for b in &self.balls {
            let _ = writeln!(
                out,
                "  {:>7.1} {:>10.2} {:>10.2} {:>8.3} {:>8.3} {:>9.1} {:>7.3} {:>7.3} {:>9.2e} {:>9.2e} {:>8.4} {:>8.4}",
                b.azimuth_deg,
                b.load_inner_n,
                b.load_outer_n,
                b.contact_angle_inner_deg,
                b.contact_angle_outer_deg,
                b.orbital_speed_rpm,
                b.attitude_deg,
                b.yaw_deg,
                b.slide_to_roll_inner,
                b.slide_to_roll_outer,
                b.spin_to_roll_inner,
                b.spin_to_roll_outer
            );
        }
        out
    }
}
