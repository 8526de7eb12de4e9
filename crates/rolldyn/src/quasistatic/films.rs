//! Lubricant films of a quasi-static solution (docs/model.md §4; Zhang et al. 2020 §2.3):
//! per contact the entrainment speed from the solved ball and ring motion,
//! the flooded and starved Hamrock–Dowson films, Λ and K_oil.
//!
//! The entrainment speed is the dynamic model's, from
//! [`super::contact_motion`] (docs/dynamics.md).
//!
//! [`QuasiStaticSolver::solve_with_films`]: the equilibrium with the film
//! in the normal approach (docs/model.md §4, `lubrication::approach`). Each contact's
//! film law (entrainment speed and curvature) is taken from the previous
//! solution, starting from the dry one, and the solve is repeated until the
//! loads settle. Its bearing stiffness has the films' compliance in series
//! with Hertz; the law's own dependence on the displacements (through u
//! and α) is left out of the derivatives.

use super::contact_motion::{all_contact_motions, contact_motions};
use super::{Conditions, Equilibrium, QuasiStaticError, QuasiStaticSolver, SolverOptions};
use crate::contact::Curvature;
use crate::geometry::{BearingGeometry, RingKind};
use crate::lubrication::approach::{FilmGeometry, FilmLaw};
use crate::lubrication::{ContactFilm, FilmConditions, Lubricant, Supply, contact_film};

/// Re-solves of [`QuasiStaticSolver::solve_with_films`] at most.
pub const FILM_ITERATIONS: usize = 20;

/// Relative change of the largest load at which the film iteration stops.
pub const FILM_TOLERANCE: f64 = 1e-8;

impl QuasiStaticSolver {
    /// The equilibrium with the film in the normal approach (module doc):
    /// each contact's film from the previous solution's entrainment
    /// speed and contact angle, repeated until the loads change by less than
    /// [`FILM_TOLERANCE`] of the largest. At rest there is no film and this
    /// is [`Self::solve`]. An oil-flow supply is refused.
    pub fn solve_with_films(
        &self,
        conditions: &Conditions,
        options: &SolverOptions,
        inputs: &FilmInputs,
    ) -> Result<Equilibrium, QuasiStaticError> {
        let mut eq = self.solve(conditions, options)?;
        for iteration in 0..FILM_ITERATIONS {
            let laws = self.film_laws(&eq, inputs)?;
            if iteration == 0 {
                // A thick film on light loads is a large preload: reach it
                // from the dry solution with the films scaled up; then the
                // laws of that solution.
                eq = self.continue_in_film(&eq, &laws, conditions, options)?;
                continue;
            }
            let next = self.with_films(laws).solve_from(&eq, conditions, options)?;
            let largest = next
                .balls
                .iter()
                .map(|b| b.inner.load.max(b.outer.load))
                .fold(0.0, f64::max);
            let change = next
                .balls
                .iter()
                .zip(&eq.balls)
                .map(|(a, b)| {
                    (a.inner.load - b.inner.load)
                        .abs()
                        .max((a.outer.load - b.outer.load).abs())
                })
                .fold(0.0, f64::max);
            eq = next;
            if change <= FILM_TOLERANCE * largest {
                return Ok(eq);
            }
        }
        Err(QuasiStaticError::Unsupported {
            reason: format!(
                "the film in the approach did not settle in {FILM_ITERATIONS} re-solves"
            ),
        })
    }

    /// From the solution `dry` to the one with the films `laws`: in one
    /// solve, or where that fails with the films times a factor growing
    /// from 0 to 1, each solve started from the last, a failed step halved
    /// (down to 1/64).
    fn continue_in_film(
        &self,
        dry: &Equilibrium,
        laws: &[[Option<FilmLaw>; 2]],
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Result<Equilibrium, QuasiStaticError> {
        let scaled = |factor: f64| {
            self.with_films(
                laws.iter()
                    .map(|pair| pair.map(|law| law.map(|l| l.scaled(factor))))
                    .collect(),
            )
        };
        let (mut eq, mut factor, mut step): (Equilibrium, f64, f64) = (dry.clone(), 0.0, 1.0);
        while factor < 1.0 {
            let next = (factor + step).min(1.0);
            match scaled(next).solve_from(&eq, conditions, options) {
                Ok(solved) => {
                    eq = solved;
                    factor = next;
                }
                Err(e) if step <= 1.0 / 64.0 => return Err(e),
                Err(_) => step *= 0.5,
            }
        }
        Ok(eq)
    }

    /// The film laws of the contacts of `eq`.
    fn film_laws(
        &self,
        eq: &Equilibrium,
        inputs: &FilmInputs,
    ) -> Result<Vec<[Option<FilmLaw>; 2]>, QuasiStaticError> {
        let g = self.geometry();
        let mut out = Vec::with_capacity(eq.balls.len());
        // Open contacts too: a film may close them.
        for contacts in all_contact_motions(g, eq) {
            let mut laws = [None, None];
            for (k, motion) in contacts.iter().enumerate() {
                let Some(m) = motion else { continue };
                let angle = m.contact.contact_angle;
                let ring = if k == 0 {
                    RingKind::Inner
                } else {
                    RingKind::Outer
                };
                let hertz = self.table(ring).at(angle);
                let curvature =
                    Curvature::of_raceway(m.raceway, g.ball_diameter, g.pitch_diameter, angle);
                let law = FilmLaw::new(
                    &inputs.lubricant,
                    &inputs.supply[k],
                    &FilmGeometry {
                        entrainment_speed: m.entrainment_speed(),
                        rolling_radius: curvature.rolling_radius,
                        effective_modulus: inputs.effective_modulus,
                        ellipticity: hertz.ellipticity,
                        semi_minor_coefficient: hertz.semi_minor_coefficient,
                    },
                )
                .map_err(|e| QuasiStaticError::Unsupported {
                    reason: e.to_string(),
                })?;
                laws[k] = Some(law);
            }
            out.push(laws);
        }
        Ok(out)
    }
}

/// What the films need besides the solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmInputs {
    /// The lubricant.
    pub lubricant: Lubricant,
    /// Supply of the inner and outer raceway contacts.
    pub supply: [Supply; 2],
    /// Composite roughness σ of the inner and outer contacts \[m\] (0: no Λ).
    pub roughness: [f64; 2],
    /// Effective modulus E' \[Pa\].
    pub effective_modulus: f64,
}

/// Films of one ball: inner, outer contact, with their entrainment speeds \[m/s\].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BallFilms {
    /// Inner and outer contact films.
    pub films: [ContactFilm; 2],
    /// Inner and outer entrainment speeds u \[m/s\].
    pub entrainment_speed: [f64; 2],
}

/// The films of every ball of `eq` (zero films for unloaded contacts).
pub fn equilibrium_films(
    geometry: &BearingGeometry,
    eq: &Equilibrium,
    inputs: &FilmInputs,
) -> Vec<BallFilms> {
    contact_motions(geometry, eq)
        .iter()
        .map(|contacts| {
            let mut out = BallFilms::default();
            for (k, motion) in contacts.iter().enumerate() {
                let Some(m) = motion else { continue };
                let u = m.entrainment_speed();
                let solution = m.solution;
                let curvature = Curvature::of_raceway(
                    m.raceway,
                    geometry.ball_diameter,
                    geometry.pitch_diameter,
                    solution.contact_angle,
                );
                let hertz = solution.hertz;
                out.entrainment_speed[k] = u;
                out.films[k] = contact_film(
                    &inputs.lubricant,
                    &inputs.supply[k],
                    inputs.roughness[k],
                    &FilmConditions {
                        entrainment_speed: u,
                        load: solution.load,
                        rolling_radius: curvature.rolling_radius,
                        effective_modulus: inputs.effective_modulus,
                        ellipticity: hertz.semi_major / hertz.semi_minor,
                        semi_minor: hertz.semi_minor,
                        ring_speed: eq.inner_speed,
                    },
                );
            }
            out
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::HertzModel;
    use crate::lubrication::PressureViscosity;
    use crate::material::{Material, effective_modulus};
    use crate::operating::Loads;
    use crate::quasistatic::{Conditions, QuasiStaticSolver, RacewayControl, SolverOptions};

    /// Under pure axial load at speed, outer control: the outer contact rolls
    /// without spin, so its entrainment speed is the classical pure-rolling
    /// one, (d_m/2 + (D/2) cos α_o) ω_m … checked against the ball's own
    /// surface speed at the contact; and the films follow Hamrock–Dowson.
    #[test]
    fn entrainment_and_films_at_a_jones_harris_state() {
        let g = crate::testing::bearing_7008c();
        let steel = Material::STEEL_52100;
        let qs = QuasiStaticSolver::new(&g, &steel, &steel, HertzModel::Exact).unwrap();
        let speed = 10_000.0 * std::f64::consts::TAU / 60.0;
        let eq = qs
            .solve(
                &Conditions {
                    loads: Loads {
                        force: [200.0, 0.0, 0.0],
                        moment: [0.0; 2],
                    },
                    inner_speed: speed,
                    control: RacewayControl::Outer,
                },
                &SolverOptions::default(),
            )
            .unwrap();
        let inputs = FilmInputs {
            lubricant: Lubricant {
                viscosity: 0.0467,
                pressure_viscosity: 2.2e-8,
                pressure_model: PressureViscosity::Barus,
            },
            supply: [Supply::Flooded, Supply::InletDistance(1.3)],
            roughness: [0.1e-6, 0.1e-6],
            effective_modulus: effective_modulus(&steel, &steel),
        };
        let films = equilibrium_films(&g, &eq, &inputs);
        assert_eq!(films.len(), 22);
        let f = &films[0];
        let ball = &eq.balls[0];
        // Outer ring fixed, no slip at the outer contact (outer control):
        // the ball surface at the outer contact moves at −v_P relative to the
        // contact point, so u = |v_P| = ω_m × (radius of the contact point).
        let alpha_o = ball.outer.contact_angle;
        let r_contact = ball.radial_position + 0.5 * g.ball_diameter * alpha_o.cos();
        let expected = ball.orbital_speed * r_contact;
        assert!(
            (f.entrainment_speed[1] / expected - 1.0).abs() < 1e-3,
            "{} vs {expected}",
            f.entrainment_speed[1]
        );
        // Flooded inner film is Hamrock–Dowson at that speed; the outer is starved.
        assert_eq!(f.films[0].starvation_factor, 1.0);
        assert!(f.films[1].starvation_factor < 1.0);
        assert!(f.films[0].central > 1e-8 && f.films[0].central < 2e-6);
        assert!(f.films[0].lambda.unwrap() > 0.0);
        // All balls alike under pure axial load.
        for b in &films {
            assert!((b.films[0].central / f.films[0].central - 1.0).abs() < 1e-9);
        }
    }
}
