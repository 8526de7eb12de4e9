//! The lubricant film in the normal approach (MODEL §4, option
//! `film_in_approach`; seed 003 §2.3).
//!
//! A film of central thickness h_c separates the surfaces, so for a given
//! geometric overlap δ the bodies are compressed by δ_el = δ + h_c and
//! Q = K_c (δ + h_c)^{3/2}; a contact carries load through its film before
//! the surfaces overlap. h_c (Hamrock–Dowson, starved by the ring's supply)
//! is taken from the previous accepted step, as MODEL §4 allows: within a
//! step each contact is then an ordinary elastic contact with a fixed
//! offset, and the film is updated after every accepted step (the
//! integrator re-evaluates the right-hand side). The film's dependence on
//! load gives the series compliance 1/K_c + 1/K_oil in effect.
//!
//! **Energy.** h_c depends on the entrainment speed, so the film is not a
//! conservative spring: each update changes the contact's elastic energy
//! by 0.4 K_c [(δ + h_new)^{5/2} − (δ + h_old)^{5/2}] at fixed geometry.
//! That energy comes from the lubricant's entrainment (ultimately the
//! drive) and is accumulated as the film work (`film_work`, J) so that the
//! balance reads drive + film work = ΔE + dissipated (B2 with the film).

use super::model::BearingModel;
use super::race_contact::Want;
use crate::geometry::RingKind;

impl BearingModel {
    /// Film offset of ball j's contact with `ring` \[m\].
    pub(super) fn film_offset(&self, ball: usize, ring: RingKind) -> f64 {
        match ring {
            RingKind::Inner => self.films[ball][0],
            RingKind::Outer => self.films[ball][1],
        }
    }

    /// Sets every contact's film at the start state (t, y), so that a run
    /// starts with its films in place; the film work starts at zero.
    pub fn initialise_films(&mut self, t: f64, y: &[f64]) {
        if self.params.film_in_approach {
            self.update_films(t, y);
            self.film_work = 0.0;
        }
    }

    /// Energy the film updates have put into the contacts so far \[J\].
    pub fn film_work(&self) -> f64 {
        self.film_work
    }

    /// Updates every contact's film to the accepted state (t, y) and
    /// accumulates the energy change; true when a film changed.
    pub(super) fn update_films(&mut self, t: f64, y: &[f64]) -> bool {
        let (inner, outer) = self.ring_motion(t, y);
        let mut changed = false;
        for j in 0..self.layout.balls {
            let (ball, _) = self.ball_kinematics(j, y);
            for (k, (ring, table)) in [(&inner, &self.inner_table), (&outer, &self.outer_table)]
                .into_iter()
                .enumerate()
            {
                let old = self.films[j][k];
                let contact =
                    self.race_contact(ring, table, &self.episodes[j][k], &ball, Want::Output);
                let (new, energy_change) = match contact {
                    Some(c) => {
                        let new = c.output.film;
                        // Geometric overlap without the film, then the
                        // elastic energy with the old and the new film.
                        let geometric = c.geometry.penetration - old;
                        let k_c = table.stiffness(c.geometry.contact_angle);
                        let energy = |h: f64| 0.4 * k_c * (geometric + h).max(0.0).powf(2.5);
                        (new, energy(new) - energy(old))
                    }
                    // Open: the film is gone (its energy was zero already).
                    None => (0.0, 0.0),
                };
                if new != old {
                    self.films[j][k] = new;
                    self.film_work += energy_change;
                    changed = true;
                }
            }
        }
        changed
    }
}
