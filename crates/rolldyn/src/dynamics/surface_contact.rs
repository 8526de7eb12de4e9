//! Raceway and ball surfaces in the ball–raceway contacts (docs/model.md §6), and
//! the step limit that keeps the integrator from stepping over a spall.
//!
//! The approach grows by the surface's Δδ (see [`crate::surface`]). Δδ
//! depends on the contact's angle on the ring, θ = azimuth of (q − c) − θ_ring
//! (exact for an untilted ring: the contact point lies in the ball centre's
//! meridian plane; the ring tilt's effect on θ is second order and left
//! out), and on the ball's spin angle ψ. So that the contact stays
//! conservative, the load Q also acts through the generalised forces of Δδ:
//!
//! ```text
//! ring surface, slope s = ∂Δδ/∂θ:   ∂θ/∂q = e_t/r′,  ∂θ/∂c = −e_t/r′,  ∂θ/∂θ_ring = −1
//!   ball: −Q s e_t/r′ at its centre;  ring: +Q s e_t/r′ through the ball centre
//!   (its moment about the ring axis is Q s, the reaction of the drive)
//! ball surface, slope s_b = ∂Δδ/∂ψ, ψ̇ = |ω_b − φ̇ e_x| = ω̂·(ω_b − φ̇ e_x):
//!   ball: moment −Q s_b ω̂ and orbital force Q s_b ω̂_x / r e_t
//! ```
//! (r′: distance of the ball centre from the ring axis, e_t the azimuthal
//! direction there; r the ball's orbit radius.) The approach rate gets the
//! matching s θ̇ + s_b ψ̇, so the power of these forces is exactly Q times
//! the surface's share of δ̇ and the energy balance (B2) closes. The
//! ball-surface forces have no reaction on the rings: they are of the order
//! of the surface slope times the load (mN for micrometre waviness) and
//! average to zero over a ball turn; this is the price of the scalar spin
//! angle ψ of Deng et al. 2022 in place of a full ball orientation.

use super::elements::Elements;
use super::layout::StateLayout;
use super::motion::{BallMotion, RingMotion};
use crate::contact::{Curvature, TorusContact};
use crate::geometry::RingKind;
use crate::surface::{BALL_CONTACT_SEPARATION, RacePoint, Spall, SpallSite};
use nalgebra::Vector3;
use std::f64::consts::TAU;

/// Steps the integrator must take at least while a contact crosses a spall.
pub const STEPS_PER_SPALL: f64 = 8.0;

/// What the surfaces do to one contact, per newton of normal load.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct SurfaceEffect {
    /// Δδ \[m\].
    pub(super) approach: f64,
    /// dΔδ/dt along the motion \[m/s\].
    pub(super) approach_rate: f64,
    /// Force on the ball at its centre per unit load \[-\].
    pub(super) ball_force: Vector3<f64>,
    /// Moment on the ball per unit load \[m\].
    pub(super) ball_moment: Vector3<f64>,
    /// Force on the ring per unit load, acting through the ball centre \[-\].
    pub(super) ring_force: Vector3<f64>,
}

impl SurfaceEffect {
    /// The forces and moment at normal load `load` (the per-unit-load
    /// ones times the load).
    pub(super) fn scaled(self, load: f64) -> Self {
        Self {
            ball_force: load * self.ball_force,
            ball_moment: load * self.ball_moment,
            ring_force: load * self.ring_force,
            ..self
        }
    }
}

impl Elements {
    /// The surfaces' effect on a contact of `geometry` (penetration without
    /// the surface); None when both surfaces are smooth.
    pub(super) fn surface_effect(
        &self,
        ring: &RingMotion,
        ball: &BallMotion,
        geometry: &TorusContact,
    ) -> Option<SurfaceEffect> {
        let surfaces = &self.params.surface;
        let race = match ring.raceway.kind {
            RingKind::Inner => &surfaces.inner,
            RingKind::Outer => &surfaces.outer,
        };
        let ball_surface = surfaces.balls.get(ball.index).filter(|b| !b.is_smooth());
        if race.is_smooth() && ball_surface.is_none() {
            return None;
        }
        let d = self.geometry.ball_diameter;
        // The spalls' track radius and bridging radius R_x at the nominal
        // contact angle, not the contact's: Δδ then depends on the surface
        // angles alone, and the slope forces below are its whole gradient
        // (with the contact's own radii the drop also moved with the ball's
        // radial position, a force the contact does not apply: an inner-race
        // pit leaked up to ~10 mW into the energy balance of a 6205 at 1 kN).
        let nominal_angle = self.geometry.nominal_contact_angle();
        let bridging_radius = Curvature::of_raceway(
            &ring.raceway,
            d,
            self.geometry.pitch_diameter,
            nominal_angle,
        )
        .rolling_radius;
        let track_radius = self.nominal_track_radius(ring.raceway.kind);
        let mut effect = SurfaceEffect::default();
        if !race.is_smooth() {
            let rel = ball.centre - ring.centre;
            let radial = Vector3::new(0.0, rel.y, rel.z);
            let r = radial.norm();
            let e_r = radial / r;
            let e_t = Vector3::x().cross(&e_r);
            let axis = ring.circle.axis.into_inner();
            let n = geometry.normal;
            let a = race.approach(&RacePoint {
                angle: rel.z.atan2(rel.y) - ring.spin_angle,
                axial: (geometry.contact_point - ring.circle.centre).dot(&axis),
                track_radius,
                radial_projection: n.dot(&e_r).abs(),
                axial_projection: -n.dot(&axis),
                bridging_radius,
            });
            let d_angle = e_t / r;
            effect.approach += a.value;
            effect.approach_rate +=
                a.slope * (d_angle.dot(&(ball.velocity - ring.velocity)) - ring.spin_speed);
            effect.ball_force -= a.slope * d_angle;
            effect.ring_force += a.slope * d_angle;
        }
        if let Some(surface) = ball_surface {
            let relative = ball.omega - ball.orbital_rate * Vector3::x();
            let rate = relative.norm();
            let psi = match ring.raceway.kind {
                RingKind::Inner => ball.spin_angle,
                RingKind::Outer => ball.spin_angle + BALL_CONTACT_SEPARATION,
            };
            let a = surface.approach(psi, 0.5 * d, bridging_radius);
            effect.approach += a.value;
            if rate > 0.0 {
                let axis = relative / rate;
                let q = ball.centre;
                let orbit = q.y.hypot(q.z);
                let e_t = Vector3::new(0.0, -q.z, q.y) / orbit;
                effect.approach_rate += a.slope * rate;
                effect.ball_moment -= a.slope * axis;
                effect.ball_force += (a.slope * axis.x / orbit) * e_t;
            }
        }
        Some(effect)
    }

    /// Largest step from (t, y) that cannot carry a contact across a spall
    /// unseen: up to the spall's entry edge, and at most 1/[`STEPS_PER_SPALL`]
    /// of the crossing time while crossing (or when the entry is nearer).
    /// Angles from the ball azimuth and spin angle at the nominal track radii;
    /// infinite without spalls.
    pub(super) fn spall_step_limit(&self, t: f64, y: &[f64]) -> f64 {
        let mut limit = f64::INFINITY;
        if self.params.surface.spalls().next().is_none() {
            return limit;
        }
        let tracks = self.spall_tracks(t, y);
        for (site, spall) in self.params.surface.spalls() {
            for j in 0..self.layout.balls {
                for (angle, rate, track) in self.spall_track_contacts(&tracks, y, site, j) {
                    if rate != 0.0 {
                        limit = limit.min(time_to_cross(spall, angle, rate, track));
                    }
                }
            }
        }
        limit
    }

    /// Whether a contact centre of any ball lies on `spall` at `site` (with
    /// a tenth of its half-width to spare) at (t, y): as
    /// [`Self::spall_step_limit`] places them.
    pub(super) fn spall_is_loaded(
        &self,
        t: f64,
        y: &[f64],
        site: SpallSite,
        spall: &Spall,
    ) -> bool {
        let tracks = self.spall_tracks(t, y);
        (0..self.layout.balls).any(|j| {
            self.spall_track_contacts(&tracks, y, site, j)
                .iter()
                .any(|&(angle, rate, track)| {
                    let half = spall.half_angle(track);
                    rate != 0.0
                        && crate::surface::spall::wrap(angle - spall.position).abs() < 1.1 * half
                })
        })
    }

    /// Radius of a raceway's track at the nominal contact angle \[m\].
    fn nominal_track_radius(&self, kind: RingKind) -> f64 {
        let g = &self.geometry;
        let radial = 0.5 * g.ball_diameter * g.nominal_contact_angle().cos();
        match kind {
            RingKind::Inner => 0.5 * g.pitch_diameter - radial,
            RingKind::Outer => 0.5 * g.pitch_diameter + radial,
        }
    }

    /// What places the contacts on the spalls' tracks at time `t`.
    fn spall_tracks(&self, t: f64, y: &[f64]) -> SpallTracks {
        let g = &self.geometry;
        let spin = self.spin(t, y);
        let half_d = 0.5 * g.ball_diameter;
        SpallTracks {
            inner_angle: spin.angle,
            inner_speed: spin.speed,
            inner_track: self.nominal_track_radius(RingKind::Inner),
            outer_track: self.nominal_track_radius(RingKind::Outer),
            half_d,
        }
    }

    /// Ball j's contacts on the track of a spall at `site`: (angle on the
    /// track, its rate, the track's radius) at the nominal track radii; a
    /// zero rate marks no contact (one on a raceway, two on its own ball).
    fn spall_track_contacts(
        &self,
        tracks: &SpallTracks,
        y: &[f64],
        site: SpallSite,
        j: usize,
    ) -> [(f64, f64, f64); 2] {
        let l = self.layout;
        let half_d = tracks.half_d;
        let b = l.ball(j);
        let (azimuth, orbital) = (y[b + 2], y[b + 5]);
        let none = (0.0, 0.0, 0.0);
        match site {
            SpallSite::Inner => [
                (
                    azimuth - tracks.inner_angle,
                    orbital - tracks.inner_speed,
                    tracks.inner_track,
                ),
                none,
            ],
            SpallSite::Outer => [(azimuth, orbital, tracks.outer_track), none],
            SpallSite::Ball(k) if k == j && l.ball_spin_angle => {
                let relative = Vector3::new(y[b + 6] - orbital, y[b + 7], y[b + 8]);
                let psi = y[b + StateLayout::SPIN_ANGLE];
                let rate = relative.norm();
                [
                    (psi, rate, half_d),
                    (psi + BALL_CONTACT_SEPARATION, rate, half_d),
                ]
            }
            SpallSite::Ball(_) => [none, none],
        }
    }
}

/// The shaft's angle and speed at a time and the nominal track radii
/// (inner race, outer race, ball).
struct SpallTracks {
    inner_angle: f64,
    inner_speed: f64,
    inner_track: f64,
    outer_track: f64,
    half_d: f64,
}

/// Step limit for one contact at `angle` moving at `rate` on a track of
/// radius `track` towards or over `spall`.
fn time_to_cross(spall: &Spall, angle: f64, rate: f64, track: f64) -> f64 {
    let half = spall.half_angle(track);
    let crossing = 2.0 * half / rate.abs() / STEPS_PER_SPALL;
    let offset = crate::surface::spall::wrap(angle - spall.position);
    if offset.abs() < half {
        return crossing;
    }
    // Angle still to go to the entry edge, in the direction of motion.
    let direction = rate.signum();
    let to_entry = (-(offset * direction) - half).rem_euclid(TAU);
    (to_entry / rate.abs()).max(crossing)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::{Edge, SpallSize};

    #[test]
    fn the_step_limit_reaches_the_entry_edge_and_resolves_the_crossing() {
        let spall = Spall {
            position: 1.0,
            size: SpallSize::Angle(0.02),
            depth: 1e-5,
            axial_position: 0.0,
            axial_width: None,
            edge: Edge::Sharp,
            growth_rate: 0.0,
        };
        let crossing = 0.02 / 10.0 / STEPS_PER_SPALL;
        // 0.5 rad before the entry edge at 10 rad/s: 0.05 s to go.
        let before = 1.0 - 0.01 - 0.5;
        assert!((time_to_cross(&spall, before, 10.0, 0.02) - 0.05).abs() < 1e-12);
        // Moving the other way: almost a full turn to go.
        let back = time_to_cross(&spall, before, -10.0, 0.02);
        assert!((back - (TAU - 0.5 - 0.02) / 10.0).abs() < 1e-12, "{back}");
        // Inside, and just before the edge: the crossing resolution.
        assert_eq!(time_to_cross(&spall, 1.0, 10.0, 0.02), crossing);
        assert_eq!(time_to_cross(&spall, 0.99 - 1e-6, 10.0, 0.02), crossing);
    }
}
