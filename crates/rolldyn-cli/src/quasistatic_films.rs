//! Films and natural modes of a quasi-static solution for `rolldyn
//! quasistatic` (docs/model.md §4, §7; Zhang et al. 2020): per ball and contact the
//! entrainment speed, flooded and starved Hamrock–Dowson films, Λ,
//! starvation factor and oil-film stiffness (with a `[lubricant]`), and the
//! natural frequencies and mode shapes of the inner ring on the bearing
//! stiffness (with `inner_ring.mass` and `inner_ring.tilt_inertia`). Keys
//! in docs/cli.md.

use rolldyn::lubrication;
use rolldyn::quasistatic::Equilibrium;
use rolldyn::quasistatic::films::equilibrium_films;
use rolldyn::quasistatic::modes::natural_modes;
use rolldyn_case::Case;
use rolldyn_case::simulation::film_inputs;
use serde::Serialize;
use std::fmt::Write as _;

/// Films of one contact.
#[derive(Serialize)]
pub struct ContactFilmRow {
    pub entrainment_speed_m_s: f64,
    pub central_film_m: f64,
    pub minimum_film_m: f64,
    pub flooded_central_film_m: f64,
    pub flooded_minimum_film_m: f64,
    pub starvation_factor: f64,
    /// L (null: fully flooded supply).
    pub inlet_distance_ratio: Option<f64>,
    /// L* (null without a film).
    pub critical_inlet_distance_ratio: Option<f64>,
    /// Λ = h_min/σ (null without roughness).
    pub film_parameter: Option<f64>,
    /// K_oil (null without a film).
    pub film_stiffness_n_per_m: Option<f64>,
    /// Asperity share φ of the load (null without `[model.mixed_lubrication]`).
    pub asperity_share: Option<f64>,
}

/// Films of one ball.
#[derive(Serialize)]
pub struct FilmRow {
    pub azimuth_deg: f64,
    pub inner: ContactFilmRow,
    pub outer: ContactFilmRow,
}

/// One mode.
#[derive(Serialize)]
pub struct ModeRow {
    pub frequency_hz: f64,
    /// Shape over (x, y, z, θ_y, θ_z), largest component 1.
    pub shape: [f64; 5],
}

/// Natural modes of the inner ring.
#[derive(Serialize)]
pub struct ModesReport {
    pub mass_kg: f64,
    pub tilt_inertia_kg_m2: f64,
    /// ‖K − Kᵀ‖/‖K‖ (the symmetric part is used).
    pub stiffness_skew: f64,
    pub modes: Vec<ModeRow>,
}

fn finite(v: f64) -> Option<f64> {
    v.is_finite().then_some(v)
}

impl ContactFilmRow {
    /// The row of a film at entrainment speed `u` \[m/s\].
    pub fn new(f: &lubrication::ContactFilm, u: f64) -> Self {
        Self {
            entrainment_speed_m_s: u,
            central_film_m: f.central,
            minimum_film_m: f.minimum,
            flooded_central_film_m: f.flooded_central,
            flooded_minimum_film_m: f.flooded_minimum,
            starvation_factor: f.starvation_factor,
            inlet_distance_ratio: finite(f.inlet_ratio),
            critical_inlet_distance_ratio: finite(f.critical_ratio),
            film_parameter: f.lambda,
            film_stiffness_n_per_m: finite(f.stiffness),
            asperity_share: None,
        }
    }

    /// The row with the asperity share φ of mixed lubrication at this
    /// contact's load and Hertz ellipse (docs/lubrication.md).
    fn with_share(
        mut self,
        mixed: Option<&rolldyn::traction::mixed::MixedLubrication>,
        contact: &rolldyn::quasistatic::ContactSolution,
        effective_modulus: f64,
    ) -> Self {
        self.asperity_share = mixed.zip(self.film_parameter).map(|(m, lambda)| {
            let e = &contact.hertz;
            let area = std::f64::consts::PI * e.semi_major * e.semi_minor;
            if area > 0.0 {
                m.asperity_share(lambda, contact.load / area, effective_modulus)
            } else {
                0.0
            }
        });
        self
    }

    /// Text lines of the film.
    pub fn text(&self, out: &mut String) {
        let _ = writeln!(
            out,
            "  film at u = {:.3} m/s: h_c {:.4} µm, h_min {:.4} µm (flooded {:.4} / {:.4} µm), starvation factor {:.4}{}{}",
            self.entrainment_speed_m_s,
            self.central_film_m * 1e6,
            self.minimum_film_m * 1e6,
            self.flooded_central_film_m * 1e6,
            self.flooded_minimum_film_m * 1e6,
            self.starvation_factor,
            match (
                self.inlet_distance_ratio,
                self.critical_inlet_distance_ratio
            ) {
                (Some(l), Some(ls)) => format!(" (L {l:.3}, L* {ls:.3})"),
                (None, Some(ls)) => format!(" (flooded; L* {ls:.3})"),
                _ => String::new(),
            },
            self.film_parameter
                .map_or(String::new(), |l| format!(", Λ {l:.3}"))
        );
        if let Some(k) = self.film_stiffness_n_per_m {
            let _ = writeln!(out, "  film stiffness K_oil {k:.4e} N/m");
        }
    }
}

/// The films of `sol` when the case has a lubricant.
pub fn films(case: &Case, sol: &Equilibrium) -> Option<Vec<FilmRow>> {
    let inputs = film_inputs(case)?;
    Some(
        equilibrium_films(&case.bearing.geometry, sol, &inputs)
            .iter()
            .zip(&sol.balls)
            .map(|(f, b)| {
                let row = |k: usize, contact| {
                    ContactFilmRow::new(&f.films[k], f.entrainment_speed[k]).with_share(
                        case.mixed_lubrication.as_ref(),
                        contact,
                        inputs.effective_modulus,
                    )
                };
                FilmRow {
                    azimuth_deg: b.azimuth.to_degrees(),
                    inner: row(0, &b.inner),
                    outer: row(1, &b.outer),
                }
            })
            .collect(),
    )
}

/// The modes of `sol` when the case gives the inner ring's mass and tilt inertia.
pub fn modes(case: &Case, sol: &Equilibrium) -> Option<ModesReport> {
    let (mass, tilt_inertia) = (case.inner_ring_mass?, case.inner_ring_tilt_inertia?);
    let (modes, skew) = natural_modes(&sol.stiffness, mass, tilt_inertia);
    Some(ModesReport {
        mass_kg: mass,
        tilt_inertia_kg_m2: tilt_inertia,
        stiffness_skew: skew,
        modes: modes
            .iter()
            .map(|m| ModeRow {
                frequency_hz: m.frequency,
                shape: m.shape,
            })
            .collect(),
    })
}

/// Text of the films and modes.
pub fn text(films: Option<&[FilmRow]>, modes: Option<&ModesReport>, out: &mut String) {
    if let Some(films) = films {
        let _ = writeln!(
            out,
            "\n  films (Hamrock–Dowson, starved by the supply; Λ = h_min/σ; K_oil = Q/(0.073 h_min)):"
        );
        let _ = writeln!(
            out,
            "  {:>7} {:>9} {:>9} {:>9} {:>7} {:>7} {:>10} {:>9} {:>9} {:>9} {:>7} {:>7} {:>10}",
            "φ deg",
            "u_i m/s",
            "hc_i µm",
            "hmin_i µm",
            "f_s,i",
            "Λ_i",
            "K_oil,i N/m",
            "u_o m/s",
            "hc_o µm",
            "hmin_o µm",
            "f_s,o",
            "Λ_o",
            "K_oil,o N/m"
        );
        let lambda = |l: Option<f64>| l.map_or("—".to_string(), |v| format!("{v:.2}"));
        let stiffness = |k: Option<f64>| k.map_or("—".to_string(), |v| format!("{v:.3e}"));
        for f in films {
            let _ = writeln!(
                out,
                "  {:>7.1} {:>9.3} {:>9.4} {:>9.4} {:>7.3} {:>7} {:>10} {:>9.3} {:>9.4} {:>9.4} {:>7.3} {:>7} {:>10}",
                f.azimuth_deg,
                f.inner.entrainment_speed_m_s,
                f.inner.central_film_m * 1e6,
                f.inner.minimum_film_m * 1e6,
                f.inner.starvation_factor,
                lambda(f.inner.film_parameter),
                stiffness(f.inner.film_stiffness_n_per_m),
                f.outer.entrainment_speed_m_s,
                f.outer.central_film_m * 1e6,
                f.outer.minimum_film_m * 1e6,
                f.outer.starvation_factor,
                lambda(f.outer.film_parameter),
                stiffness(f.outer.film_stiffness_n_per_m),
            );
        }
        let largest = |share: fn(&FilmRow) -> Option<f64>| {
            films
                .iter()
                .filter_map(share)
                .fold(None, |m: Option<f64>, s| Some(m.map_or(s, |m| m.max(s))))
        };
        if let (Some(inner), Some(outer)) = (
            largest(|f| f.inner.asperity_share),
            largest(|f| f.outer.asperity_share),
        ) {
            let _ = writeln!(
                out,
                "  mixed lubrication (Greenwood–Tripp load sharing): asperity share φ of the load up to {inner:.3e} (inner), {outer:.3e} (outer)"
            );
        }
    }
    if let Some(m) = modes {
        let _ = writeln!(
            out,
            "\n  natural modes of the inner ring ({} kg, {:.3e} kg·m² on the bearing stiffness; skew part {:.1e}):",
            m.mass_kg, m.tilt_inertia_kg_m2, m.stiffness_skew
        );
        for mode in &m.modes {
            let s = mode.shape;
            let _ = writeln!(
                out,
                "    {:>10.1} Hz   shape x {:+.3}, y {:+.3}, z {:+.3}, θ_y {:+.3}, θ_z {:+.3}",
                mode.frequency_hz, s[0], s[1], s[2], s[3], s[4]
            );
        }
    }
}
