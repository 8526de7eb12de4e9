//! The lubricant film of the ball–raceway contacts (MODEL §4): the steady
//! film the EHL traction sees, and the film in the normal approach.
//!
//! Steady film: Hamrock–Dowson central film at the contact's load,
//! entrainment speed and curvature, starved by the ring's supply
//! ([`crate::lubrication`]).
//!
//! Film in the normal approach (option `film_in_approach`): each ball
//! carries the film h of its inner and outer contact as states. The
//! geometry adds h to the penetration, δ_el = δ + h, and h relaxes to its
//! steady value at rate |u|/b ([`crate::lubrication::approach`]). The
//! film's rate adds to the approach rate, so normal damping acts on δ̇_el.
//! The total contact force Q times ḣ is the power the film does on the
//! contact. It is accumulated as the film work, and the energy balance reads
//! drive work + film work = ΔE + dissipated energy.

use super::model::{BallMotion, BearingModel, RingMotion};
use crate::contact::{ContactTable, Curvature, HertzCoefficients};
use crate::geometry::RingKind;
use crate::lubrication::approach::{floor_load, relaxation_rate};
use crate::lubrication::{ContactFilm, FilmConditions, contact_film};
use nalgebra::Vector3;

/// Index of a ring's contact in a ball's pair (inner 0, outer 1).
pub(super) fn contact_index(ring: &RingMotion) -> usize {
    match ring.raceway.kind {
        RingKind::Inner => 0,
        RingKind::Outer => 1,
    }
}

impl BearingModel {
    /// Entrainment velocity of a contact at point P with normal n: the mean
    /// surface velocity of ball and ring relative to the contact point, in
    /// the tangent plane (MODEL §3).
    ///
    /// The contact point moves with the ball's azimuth frame:
    /// v_P = q̇ + φ̇ e_x × (P − q). MODEL §3 writes q̇ for v_P, which misses
    /// φ̇ e_x × (P − q): a factor 1/(1 ± γ cos α) on |u|, 12 % on the 7008C.
    pub(super) fn entrainment(
        ring: &RingMotion,
        ball: &BallMotion,
        point: &Vector3<f64>,
        normal: &Vector3<f64>,
    ) -> Vector3<f64> {
        let (q, v) = (&ball.centre, &ball.velocity);
        let ball_surface = v + ball.omega.cross(&(point - q));
        let ring_surface = ring.velocity + ring.omega.cross(&(point - ring.centre));
        let contact_velocity = v + ball.orbital_rate * Vector3::x().cross(&(point - q));
        let e = 0.5 * ((ball_surface - contact_velocity) + (ring_surface - contact_velocity));
        e - e.dot(normal) * normal
    }

    /// Steady film of a contact with `ring` at contact angle α, entrainment
    /// speed u \[m/s\] and load Q \[N\], starved by the ring's supply; None
    /// without a lubricant.
    pub(super) fn steady_film(
        &self,
        ring: &RingMotion,
        hertz: &HertzCoefficients,
        contact_angle: f64,
        entrainment_speed: f64,
        load: f64,
    ) -> Option<ContactFilm> {
        let lubricant = self.params.traction.lubricant()?;
        let curvature = self.curvature(ring, contact_angle);
        Some(contact_film(
            lubricant,
            &self.params.film_supply[contact_index(ring)],
            0.0,
            &FilmConditions {
                entrainment_speed,
                load,
                rolling_radius: curvature.rolling_radius,
                effective_modulus: self.effective_modulus,
                ellipticity: hertz.ellipticity,
                semi_minor: hertz.at_load(load).semi_minor,
                // Seed 003 eq 27: the inner ring throws the supply film.
                ring_speed: ring.shaft_speed,
            },
        ))
    }

    fn curvature(&self, ring: &RingMotion, contact_angle: f64) -> Curvature {
        Curvature::of_raceway(
            &ring.raceway,
            self.geometry.ball_diameter,
            self.geometry.pitch_diameter,
            contact_angle,
        )
    }

    /// Steady film h_ss \[m\] and relaxation rate |u|/b \[1/s\] of a contact
    /// carrying the elastic load Q_el = K_c δ_el^{3/2} (0 when open), both
    /// at the load max(Q_el, Q_f) ([`crate::lubrication::approach`]); the
    /// film's rate is ḣ = (|u|/b)(h_ss − h).
    pub(super) fn film_target(
        &self,
        ring: &RingMotion,
        hertz: &HertzCoefficients,
        contact_angle: f64,
        entrainment_speed: f64,
        elastic_load: f64,
    ) -> (f64, f64) {
        let rolling_radius = self.curvature(ring, contact_angle).rolling_radius;
        let load = elastic_load.max(floor_load(self.effective_modulus, rolling_radius));
        let steady = self
            .steady_film(ring, hertz, contact_angle, entrainment_speed, load)
            .map_or(0.0, |f| f.central);
        (
            steady,
            relaxation_rate(entrainment_speed, hertz.at_load(load).semi_minor),
        )
    }

    /// [`Self::film_target`] of ball `ball`'s contact with `ring` as the
    /// state stands: closed (δ + h > 0) or open. An open contact's film
    /// relaxes towards the steady film at the floor load, with the
    /// entrainment of the nearest points of ball and groove.
    pub(super) fn film_target_of(
        &self,
        ring: &RingMotion,
        table: &ContactTable,
        ball: &BallMotion,
    ) -> (f64, f64) {
        let Some((geometry, _)) = self.race_geometry_any(ring, ball) else {
            return (0.0, 0.0);
        };
        let hertz = table.at(geometry.contact_angle);
        let u = Self::entrainment(ring, ball, &geometry.contact_point, &geometry.normal).norm();
        let penetration = geometry.penetration.max(0.0);
        let elastic = hertz.stiffness * penetration * penetration.sqrt();
        self.film_target(ring, &hertz, geometry.contact_angle, u, elastic)
    }

    /// Film rate ḣ \[m/s\] of an open contact ([`Self::film_target_of`]).
    pub(super) fn open_film_rate(
        &self,
        ring: &RingMotion,
        table: &ContactTable,
        ball: &BallMotion,
    ) -> f64 {
        let (steady, rate) = self.film_target_of(ring, table, ball);
        rate * (steady - ball.film[contact_index(ring)])
    }

    /// Work the films have done on the contacts, accumulated in state `y`
    /// \[J\] (0 without the film in the approach).
    pub fn film_work(&self, y: &[f64]) -> f64 {
        let l = self.layout;
        if l.ball_films { y[l.work() + 2] } else { 0.0 }
    }

    /// Sets each contact's film in `y` to its steady value at time t: the
    /// fixed point h = h_ss(K_c (δ + h)^{3/2}) of MODEL §4, so that a run
    /// starts with its films in place. Nothing without the film states.
    pub fn settle_films(&self, t: f64, y: &mut [f64]) {
        let l = self.layout;
        if !l.ball_films {
            return;
        }
        let (inner, outer) = self.ring_motion(t, y);
        for j in 0..l.balls {
            let f = l.ball(j) + l.film_offset();
            for (k, (ring, table)) in [(&inner, &self.inner_table), (&outer, &self.outer_table)]
                .into_iter()
                .enumerate()
            {
                // h ← h_ss(h) contracts by about 0.1 h/δ_el (the film's
                // compliance against Hertz'): rounding in a few dozen
                // iterations at worst.
                for _ in 0..100 {
                    let (ball, _) = self.ball_kinematics(j, y);
                    let (steady, _) = self.film_target_of(ring, table, &ball);
                    let change = steady - y[f + k];
                    y[f + k] = steady;
                    if change.abs() <= 1e-14 * steady.abs() {
                        break;
                    }
                }
            }
        }
    }
}
