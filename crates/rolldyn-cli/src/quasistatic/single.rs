//! One bearing's quasi-static report: its static load distribution or
//! Jones–Harris equilibrium, ball by ball, with stiffness, rating life,
//! films and modes (keys in docs/cli.md).

use rolldyn::life::{self, BallLoads};
use rolldyn::operating::Loads;
use rolldyn::quasistatic::{
    BallSolution, Conditions, Equilibrium, QuasiStaticSolver, RacewayControl,
};
use rolldyn_case::Case;
use rolldyn_case::simulation::QuasiStatic;
pub use rolldyn_case::simulation::conditions;
use serde::Serialize;
use std::fmt::Write as _;

pub(crate) const RPM: f64 = std::f64::consts::TAU / 60.0;

/// The solver for a case.
pub fn solver(case: &Case) -> Result<QuasiStaticSolver, String> {
    QuasiStatic::from_case(case)
        .map(|q| q.solver)
        .map_err(|e| e.to_string())
}

/// One ball in the JSON output.
#[derive(Serialize)]
pub struct BallRow {
    pub azimuth_deg: f64,
    pub load_inner_n: f64,
    pub load_outer_n: f64,
    pub contact_angle_inner_deg: f64,
    pub contact_angle_outer_deg: f64,
    pub orbital_speed_rpm: f64,
    pub spin_speed_rpm: f64,
    pub attitude_deg: f64,
    pub yaw_deg: f64,
    pub spin_to_roll_inner: f64,
    pub spin_to_roll_outer: f64,
    pub semi_major_inner_m: f64,
    pub semi_minor_inner_m: f64,
    pub max_pressure_inner_pa: f64,
    pub semi_major_outer_m: f64,
    pub semi_minor_outer_m: f64,
    pub max_pressure_outer_pa: f64,
    pub control: &'static str,
}

impl From<&BallSolution> for BallRow {
    fn from(b: &BallSolution) -> Self {
        Self {
            azimuth_deg: b.azimuth.to_degrees(),
            load_inner_n: b.inner.load,
            load_outer_n: b.outer.load,
            contact_angle_inner_deg: b.inner.contact_angle.to_degrees(),
            contact_angle_outer_deg: b.outer.contact_angle.to_degrees(),
            orbital_speed_rpm: b.orbital_speed / RPM,
            spin_speed_rpm: b.spin_speed / RPM,
            attitude_deg: b.attitude.to_degrees(),
            yaw_deg: 0.0,
            spin_to_roll_inner: b.inner.spin_to_roll,
            spin_to_roll_outer: b.outer.spin_to_roll,
            semi_major_inner_m: b.inner.hertz.semi_major,
            semi_minor_inner_m: b.inner.hertz.semi_minor,
            max_pressure_inner_pa: b.inner.hertz.max_pressure,
            semi_major_outer_m: b.outer.hertz.semi_major,
            semi_minor_outer_m: b.outer.hertz.semi_minor,
            max_pressure_outer_pa: b.outer.hertz.max_pressure,
            control: b.control.name(),
        }
    }
}

/// Axial and radial stiffness.
#[derive(Serialize)]
pub struct Stiffness {
    pub axial: f64,
    pub radial_y: f64,
    pub radial_z: f64,
}

/// Tilt stiffness.
#[derive(Serialize)]
pub struct TiltStiffness {
    pub y: f64,
    pub z: f64,
}

/// ISO 281 and ISO/TS 16281 ratings and lives (docs/cli.md; null where a
/// standard does not cover the case or a life is infinite).
#[derive(Serialize)]
pub struct RatingLife {
    pub standard: &'static str,
    pub dynamic_load_rating_n: Option<f64>,
    pub static_load_rating_n: Option<f64>,
    pub fatigue_load_limit_n: Option<f64>,
    pub equivalent_load_n: Option<f64>,
    pub basic_rating_life_mrev: Option<f64>,
    pub basic_rating_life_h: Option<f64>,
    pub contamination_factor: Option<f64>,
    pub reference_viscosity_mm2_per_s: Option<f64>,
    pub viscosity_ratio: Option<f64>,
    pub life_modification_factor: Option<f64>,
    pub modified_rating_life_mrev: Option<f64>,
    pub modified_rating_life_h: Option<f64>,
    pub reference_rating_life_mrev: Option<f64>,
    pub reference_rating_life_h: Option<f64>,
    pub reference_equivalent_load_n: Option<f64>,
    pub reference_life_modification_factor: Option<f64>,
    pub modified_reference_rating_life_mrev: Option<f64>,
    pub modified_reference_rating_life_h: Option<f64>,
}

impl RatingLife {
    /// Ratings of `case` under `loads` at `speed` \[rad/s\]; the reference
    /// lives from the ball loads of `solution` where given.
    pub fn new(case: &Case, loads: &Loads, speed: f64, solution: Option<&Equilibrium>) -> Self {
        let rpm = speed / RPM;
        let inner: Vec<f64>;
        let outer: Vec<f64>;
        let balls = match solution {
            Some(sol) => {
                inner = sol.balls.iter().map(|b| b.inner.load).collect();
                outer = sol.balls.iter().map(|b| b.outer.load).collect();
                Some(BallLoads {
                    inner: &inner,
                    outer: &outer,
                })
            }
            None => None,
        };
        let conditions = case.life_conditions();
        let r = life::RatingLife::new(
            &case.bearing.geometry,
            loads.force[1].hypot(loads.force[2]),
            loads.force[0],
            rpm,
            balls,
            &conditions,
        );
        let h = |l: Option<f64>| life::hours(l, rpm);
        Self {
            standard: "ISO 281:2007, ISO 76:2006, ISO/TS 16281:2008",
            dynamic_load_rating_n: r.dynamic_load_rating,
            static_load_rating_n: r.static_load_rating,
            fatigue_load_limit_n: r.fatigue_load_limit,
            equivalent_load_n: r.equivalent_load,
            basic_rating_life_mrev: r.basic_rating_life,
            basic_rating_life_h: h(r.basic_rating_life),
            contamination_factor: conditions.contamination_factor,
            reference_viscosity_mm2_per_s: r.reference_viscosity.map(|v| v * 1e6),
            viscosity_ratio: r.viscosity_ratio,
            life_modification_factor: r.life_modification_factor,
            modified_rating_life_mrev: r.modified_rating_life,
            modified_rating_life_h: h(r.modified_rating_life),
            reference_rating_life_mrev: r.reference_rating_life,
            reference_rating_life_h: h(r.reference_rating_life),
            reference_equivalent_load_n: r.reference_equivalent_load,
            reference_life_modification_factor: r.reference_life_modification_factor,
            modified_reference_rating_life_mrev: r.modified_reference_rating_life,
            modified_reference_rating_life_h: h(r.modified_reference_rating_life),
        }
    }

    /// The text lines of the rating.
    fn text(&self, out: &mut String) {
        let f = |v: Option<f64>, unit: &str, p: usize| {
            v.map_or("—".to_string(), |v| format!("{v:.p$} {unit}"))
        };
        let _ = writeln!(
            out,
            "  rating ({}):\n    C_r {}, C_0r {}, C_u {}\n    P_r {}, L10 {} = {}",
            self.standard,
            f(self.dynamic_load_rating_n, "N", 0),
            f(self.static_load_rating_n, "N", 0),
            f(self.fatigue_load_limit_n, "N", 0),
            f(self.equivalent_load_n, "N", 1),
            f(self.basic_rating_life_mrev, "10^6 rev", 1),
            f(self.basic_rating_life_h, "h", 0)
        );
        let _ = writeln!(
            out,
            "    e_C {}, nu1 {}, kappa {}: a_ISO {}, L10m {} = {}",
            f(self.contamination_factor, "", 2).trim_end(),
            f(self.reference_viscosity_mm2_per_s, "mm^2/s", 1),
            f(self.viscosity_ratio, "", 2).trim_end(),
            f(self.life_modification_factor, "", 3).trim_end(),
            f(self.modified_rating_life_mrev, "10^6 rev", 1),
            f(self.modified_rating_life_h, "h", 0)
        );
        let _ = writeln!(
            out,
            "    ISO/TS 16281 (actual ball loads): L10r {} = {}, P_ref {}, a_ISO {}, L10mr {} = {}",
            f(self.reference_rating_life_mrev, "10^6 rev", 1),
            f(self.reference_rating_life_h, "h", 0),
            f(self.reference_equivalent_load_n, "N", 1),
            f(self.reference_life_modification_factor, "", 3).trim_end(),
            f(self.modified_reference_rating_life_mrev, "10^6 rev", 1),
            f(self.modified_reference_rating_life_h, "h", 0)
        );
    }
}

/// Conventional stiffnesses 1/C_ii (docs/cli.md).
#[derive(Serialize)]
pub struct ConventionalStiffness {
    pub axial_n_per_m: f64,
    pub radial_y_n_per_m: f64,
    pub radial_z_n_per_m: f64,
    pub tilt_y_n_m_per_rad: f64,
    pub tilt_z_n_m_per_rad: f64,
}

impl From<[f64; 5]> for ConventionalStiffness {
    fn from(c: [f64; 5]) -> Self {
        Self {
            axial_n_per_m: c[0],
            radial_y_n_per_m: c[1],
            radial_z_n_per_m: c[2],
            tilt_y_n_m_per_rad: c[3],
            tilt_z_n_m_per_rad: c[4],
        }
    }
}

/// `rolldyn quasistatic --json` output for one operating point.
#[derive(Serialize)]
pub struct QuasiStaticReport {
    pub speed_rpm: f64,
    pub raceway_control: RacewayControl,
    pub force_x_n: f64,
    pub force_y_n: f64,
    pub force_z_n: f64,
    pub moment_y_n_m: f64,
    pub moment_z_n_m: f64,
    pub cage_speed_rpm: f64,
    pub cage_speed_ratio: f64,
    pub axial_displacement_m: f64,
    pub radial_displacement_y_m: f64,
    pub radial_displacement_z_m: f64,
    pub tilt_y_rad: f64,
    pub tilt_z_rad: f64,
    pub stiffness_n_per_m: Stiffness,
    pub tilt_stiffness_n_m_per_rad: TiltStiffness,
    pub stiffness_matrix: [[f64; 5]; 5],
    /// C = K⁻¹ (null where K is singular).
    pub compliance_matrix: Option<[[f64; 5]; 5]>,
    /// 1/C_ii: load–deflection slopes with the other loads held.
    pub conventional_stiffness: Option<ConventionalStiffness>,
    /// Radial load magnitude √(F_y² + F_z²) and direction from +y towards +z.
    pub radial_load_n: f64,
    pub radial_load_angle_deg: f64,
    pub first_ball_azimuth_deg: f64,
    /// Displacements held at a prescribed value (x, y, z, tilt_y, tilt_z).
    pub held_displacements: Vec<&'static str>,
    /// Loads that hold them (null where the displacement is free).
    pub reaction_force_x_n: Option<f64>,
    pub reaction_force_y_n: Option<f64>,
    pub reaction_force_z_n: Option<f64>,
    pub reaction_moment_y_n_m: Option<f64>,
    pub reaction_moment_z_n_m: Option<f64>,
    /// Range of the balls' orbital speeds (cage_speed_rpm is their mean).
    pub orbital_speed_min_rpm: f64,
    pub orbital_speed_max_rpm: f64,
    pub iterations: usize,
    pub relative_residual: f64,
    pub balls: Vec<BallRow>,
    /// ISO 281 basic rating life.
    pub rating_life: Option<RatingLife>,
    /// Per ball films (null without a `[lubricant]`).
    pub films: Option<Vec<crate::quasistatic_films::FilmRow>>,
    /// The film in the normal approach (`model.film_in_approach`): the
    /// solution, its stiffness and the modes carry it.
    pub film_in_approach: bool,
    /// The dry solution's stiffness (null unless `film_in_approach`).
    pub stiffness_matrix_without_film: Option<[[f64; 5]; 5]>,
    /// The dry solution's 1/C_ii (null unless `film_in_approach`, or
    /// where K is singular).
    pub conventional_stiffness_without_film: Option<ConventionalStiffness>,
    /// Natural modes of the inner ring (null without its mass and tilt inertia).
    pub modes: Option<crate::quasistatic_films::ModesReport>,
    /// What `[fits]` did to the clearance (null without fits).
    pub fits: Option<rolldyn_case::case::FitEffect>,
}

impl QuasiStaticReport {
    /// The report of `sol`; `held` marks the prescribed displacements.
    pub fn new(sol: &Equilibrium, conditions: &Conditions, held: [bool; 5]) -> Self {
        let u = sol.displacement;
        let k = sol.stiffness;
        let reaction = |i: usize| held[i].then_some(sol.reaction[i]);
        Self {
            speed_rpm: conditions.inner_speed / RPM,
            raceway_control: conditions.control,
            force_x_n: conditions.loads.force[0],
            force_y_n: conditions.loads.force[1],
            force_z_n: conditions.loads.force[2],
            moment_y_n_m: conditions.loads.moment[0],
            moment_z_n_m: conditions.loads.moment[1],
            cage_speed_rpm: sol.cage_speed() / RPM,
            cage_speed_ratio: if conditions.inner_speed != 0.0 {
                sol.cage_speed() / conditions.inner_speed
            } else {
                0.0
            },
            axial_displacement_m: u[0],
            radial_displacement_y_m: u[1],
            radial_displacement_z_m: u[2],
            tilt_y_rad: u[3],
            tilt_z_rad: u[4],
            stiffness_n_per_m: Stiffness {
                axial: k[0][0],
                radial_y: k[1][1],
                radial_z: k[2][2],
            },
            tilt_stiffness_n_m_per_rad: TiltStiffness {
                y: k[3][3],
                z: k[4][4],
            },
            stiffness_matrix: k,
            compliance_matrix: sol.compliance(),
            conventional_stiffness: sol
                .conventional_stiffness()
                .map(ConventionalStiffness::from),
            radial_load_n: conditions.loads.force[1].hypot(conditions.loads.force[2]),
            radial_load_angle_deg: conditions.loads.force[2]
                .atan2(conditions.loads.force[1])
                .to_degrees(),
            first_ball_azimuth_deg: sol.balls.first().map_or(0.0, |b| b.azimuth.to_degrees()),
            held_displacements: ["x", "y", "z", "tilt_y", "tilt_z"]
                .into_iter()
                .zip(held)
                .filter_map(|(n, h)| h.then_some(n))
                .collect(),
            reaction_force_x_n: reaction(0),
            reaction_force_y_n: reaction(1),
            reaction_force_z_n: reaction(2),
            reaction_moment_y_n_m: reaction(3),
            reaction_moment_z_n_m: reaction(4),
            orbital_speed_min_rpm: sol
                .balls
                .iter()
                .map(|b| b.orbital_speed)
                .fold(f64::INFINITY, f64::min)
                / RPM,
            orbital_speed_max_rpm: sol
                .balls
                .iter()
                .map(|b| b.orbital_speed)
                .fold(f64::NEG_INFINITY, f64::max)
                / RPM,
            iterations: sol.iterations,
            relative_residual: sol.residual,
            balls: sol.balls.iter().map(BallRow::from).collect(),
            rating_life: None,
            films: None,
            film_in_approach: false,
            stiffness_matrix_without_film: None,
            conventional_stiffness_without_film: None,
            modes: None,
            fits: None,
        }
    }

    /// Marks the report as solved with the film in the approach, `dry` being
    /// the same point without it.
    pub fn with_dry_stiffness(mut self, dry: &Equilibrium) -> Self {
        self.film_in_approach = true;
        self.stiffness_matrix_without_film = Some(dry.stiffness);
        self.conventional_stiffness_without_film = dry
            .conventional_stiffness()
            .map(ConventionalStiffness::from);
        self
    }

    /// With the films and natural modes the case allows.
    pub fn with_films_and_modes(mut self, case: &Case, sol: &Equilibrium) -> Self {
        self.rating_life = Some(RatingLife::new(
            case,
            &Loads {
                force: [self.force_x_n, self.force_y_n, self.force_z_n],
                moment: [self.moment_y_n_m, self.moment_z_n_m],
            },
            self.speed_rpm * RPM,
            Some(sol),
        ));
        self.films = crate::quasistatic_films::films(case, sol);
        self.modes = crate::quasistatic_films::modes(case, sol);
        self.fits = case.bearing.fits.clone();
        self
    }

    /// The note under the stiffnesses when a conventional one is negative
    /// (K not positive definite).
    fn negative_stiffness_note(&self, out: &mut String) {
        let negative = [
            &self.conventional_stiffness,
            &self.conventional_stiffness_without_film,
        ]
        .into_iter()
        .flatten()
        .any(|c| {
            [
                c.axial_n_per_m,
                c.radial_y_n_per_m,
                c.radial_z_n_per_m,
                c.tilt_y_n_m_per_rad,
                c.tilt_z_n_m_per_rad,
            ]
            .iter()
            .any(|k| *k < 0.0)
        });
        if negative {
            let _ = writeln!(
                out,
                "  note: a negative 1/C_ii means K is not positive definite: with the other loads held, the equilibrium is not stable in that direction (a small load change there moves the ring to another equilibrium); the diagonal of K is each direction's stiffness with the other displacements held"
            );
        }
    }

    /// The stiffness lines: the diagonal of K, the conventional 1/C_ii
    /// (with and without the film), and the note on a negative one.
    fn stiffness_text(&self, out: &mut String) {
        let _ = writeln!(
            out,
            "  stiffness, diagonal of K (other displacements held): axial {:.4e} N/m, radial y {:.4e} N/m, radial z {:.4e} N/m, tilt {:.4e} / {:.4e} N·m/rad",
            self.stiffness_n_per_m.axial,
            self.stiffness_n_per_m.radial_y,
            self.stiffness_n_per_m.radial_z,
            self.tilt_stiffness_n_m_per_rad.y,
            self.tilt_stiffness_n_m_per_rad.z
        );
        let conventional = |out: &mut String, what: &str, c: &ConventionalStiffness| {
            let _ = writeln!(
                out,
                "  stiffness, 1/C_ii (other loads held){what}: axial {:.4e} N/m, radial y {:.4e} N/m, radial z {:.4e} N/m, tilt {:.4e} / {:.4e} N·m/rad",
                c.axial_n_per_m,
                c.radial_y_n_per_m,
                c.radial_z_n_per_m,
                c.tilt_y_n_m_per_rad,
                c.tilt_z_n_m_per_rad
            );
        };
        if let Some(c) = &self.conventional_stiffness {
            let what = if self.film_in_approach {
                ", film in the approach"
            } else {
                ""
            };
            conventional(out, what, c);
        }
        if let Some(c) = &self.conventional_stiffness_without_film {
            conventional(out, ", without the film", c);
        }
        self.negative_stiffness_note(out);
    }

    /// The table of the balls' loads, angles, speeds and pressures.
    fn ball_table(&self, out: &mut String) {
        let _ = writeln!(
            out,
            "\n  {:>7} {:>10} {:>10} {:>8} {:>8} {:>9} {:>9} {:>7} {:>8} {:>8} {:>8} {:>8}",
            "φ deg",
            "Q_i N",
            "Q_o N",
            "α_i °",
            "α_o °",
            "ω_m rpm",
            "ω_R rpm",
            "β °",
            "s/r i",
            "s/r o",
            "p0_i MPa",
            "p0_o MPa"
        );
        for b in &self.balls {
            let _ = writeln!(
                out,
                "  {:>7.1} {:>10.2} {:>10.2} {:>8.3} {:>8.3} {:>9.1} {:>9.1} {:>7.3} {:>8.4} {:>8.4} {:>8.0} {:>8.0}",
                b.azimuth_deg,
                b.load_inner_n,
                b.load_outer_n,
                b.contact_angle_inner_deg,
                b.contact_angle_outer_deg,
                b.orbital_speed_rpm,
                b.spin_speed_rpm,
                b.attitude_deg,
                b.spin_to_roll_inner,
                b.spin_to_roll_outer,
                b.max_pressure_inner_pa * 1e-6,
                b.max_pressure_outer_pa * 1e-6
            );
        }
    }

    pub fn to_text(&self) -> String {
        let mut out = String::new();
        let kind = if self.speed_rpm == 0.0 {
            "Static load distribution".to_string()
        } else {
            format!(
                "Jones–Harris equilibrium at {:.0} rpm ({:?} raceway control)",
                self.speed_rpm, self.raceway_control
            )
        };
        let _ = writeln!(out, "{kind}");
        let _ = writeln!(
            out,
            "  loads: F_x {} N, F_y {} N, F_z {} N (radial {:.1} N at {:.1}° from +y), M_y {} N·m, M_z {} N·m; ball 0 at {:.1}°",
            self.force_x_n,
            self.force_y_n,
            self.force_z_n,
            self.radial_load_n,
            self.radial_load_angle_deg,
            self.moment_y_n_m,
            self.moment_z_n_m,
            self.first_ball_azimuth_deg
        );
        if let Some(f) = &self.fits {
            let _ = writeln!(
                out,
                "  fits: inner raceway +{:.2} µm, outer raceway −{:.2} µm; diametral clearance {:.2} µm unmounted, {:.2} µm mounted",
                f.inner_raceway_expansion_m * 1e6,
                f.outer_raceway_contraction_m * 1e6,
                f.diametral_clearance_unmounted_m * 1e6,
                f.diametral_clearance_mounted_m * 1e6
            );
        }
        let _ = writeln!(
            out,
            "  inner ring: x {:.3} µm, y {:.3} µm, z {:.3} µm, θ_y {:.3e} rad, θ_z {:.3e} rad",
            self.axial_displacement_m * 1e6,
            self.radial_displacement_y_m * 1e6,
            self.radial_displacement_z_m * 1e6,
            self.tilt_y_rad,
            self.tilt_z_rad
        );
        if !self.held_displacements.is_empty() {
            let r = [
                ("F_x", self.reaction_force_x_n, "N"),
                ("F_y", self.reaction_force_y_n, "N"),
                ("F_z", self.reaction_force_z_n, "N"),
                ("M_y", self.reaction_moment_y_n_m, "N·m"),
                ("M_z", self.reaction_moment_z_n_m, "N·m"),
            ];
            let holding: Vec<String> = r
                .iter()
                .filter_map(|(n, v, u)| v.map(|v| format!("{n} {v:.4} {u}")))
                .collect();
            let _ = writeln!(
                out,
                "  held: {} (the loads that hold them: {})",
                self.held_displacements.join(", "),
                holding.join(", ")
            );
        }
        if self.speed_rpm != 0.0 {
            let _ = writeln!(
                out,
                "  cage speed: {:.1} rpm (ω_c/ω_i = {:.5}; mean of the balls' orbital speeds, {:.1} … {:.1} rpm)",
                self.cage_speed_rpm,
                self.cage_speed_ratio,
                self.orbital_speed_min_rpm,
                self.orbital_speed_max_rpm
            );
        }
        self.stiffness_text(&mut out);
        self.ball_table(&mut out);
        if let Some(r) = &self.rating_life {
            r.text(&mut out);
        }
        crate::quasistatic_films::text(self.films.as_deref(), self.modes.as_ref(), &mut out);
        let _ = writeln!(
            out,
            "\n  converged in {} Newton iterations, relative residual {:.2e}",
            self.iterations, self.relative_residual
        );
        out
    }
}
