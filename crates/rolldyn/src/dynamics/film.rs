//! The lubricant film of the ball–raceway contacts (docs/model.md §4): the steady
//! film the EHL traction sees, and the film in the normal approach.
//!
//! Steady film: the Hamrock–Dowson central film at the contact's load,
//! entrainment speed and curvature, starved by the ring's supply
//! ([`crate::lubrication`]).
//!
//! Film in the normal approach (option `film_in_approach`, docs/model.md §4): the
//! elastic approach is δ_el = δ + h(Q), Q = K_c δ_el^{3/2}, solved by Newton
//! at every evaluation ([`crate::lubrication::approach::FilmLaw`] gives h
//! and dh/dQ). A contact is closed while δ + h(0) > 0: it carries load
//! through its film before the surfaces overlap. Normal damping acts on the
//! bodies' approach rate δ̇. The contact stores
//! V = (2/5) K_c δ_el^{5/2} − Q h + ∫₀^Q h dq (`dynamics::energy`), and
//! ∂V/∂δ = Q.
//!
//! **The film's work.** At fixed Q, V still changes when the law moves:
//! with the entrainment speed u and the contact angle. That change,
//! P_film = ∂/∂t ∫₀^Q h dq at fixed Q, is the work the film does on the
//! contact (drawn from the entrainment). It is accumulated, and the energy
//! balance reads drive + film work = ΔE + dissipated energy. The rate is
//! taken along the motion. A central difference moves the ball's states
//! by its derivatives, the rings' positions by their velocities, and time.
//! The rings' accelerations are not known while a ball is evaluated, so the
//! ball passes ∂(∫h)/∂(ring velocity) to the border, which multiplies it by
//! the accelerations. The check is `b2_energy_balance` with the film
//! (tests/validation/c7_film_in_approach.rs): P_drive + P_film −
//! P_dissipated = dE/dt at every state.

use super::coupling::{BallCoupling, add_to};
use super::elements::Elements;
use super::motion::{BallMotion, RingMotion, Spin, tilt_axis_y};
use crate::contact::{ContactTable, Curvature, HertzCoefficients, TorusContact};
use crate::geometry::RingKind;
use crate::lubrication::approach::{FilmGeometry, FilmLaw};
use crate::lubrication::{ContactFilm, FilmConditions, contact_film};
use nalgebra::Vector3;

/// Index of a ring's contact in a ball's pair (inner 0, outer 1).
pub(super) fn contact_index(ring: &RingMotion) -> usize {
    match ring.raceway.kind {
        RingKind::Inner => 0,
        RingKind::Outer => 1,
    }
}

/// A closed contact with the film in the approach.
#[derive(Debug, Clone, Copy)]
pub(super) struct FilmApproach {
    /// The film law at this state.
    pub(super) law: FilmLaw,
    /// Elastic approach δ_el = δ + h \[m\].
    pub(super) elastic_approach: f64,
    /// Elastic load Q = K_c δ_el^{3/2} \[N\].
    pub(super) load: f64,
    /// Central film h(Q) \[m\].
    pub(super) film: f64,
}

impl FilmApproach {
    /// Stored energy V = (2/5) K_c δ_el^{5/2} − Q h + ∫₀^Q h dq \[J\].
    pub(super) fn energy(&self) -> f64 {
        0.4 * self.load * self.elastic_approach - self.load * self.film
            + self.law.integral(self.load)
    }
}

/// What a closed contact's film passes to the power of the films: its
/// elastic load, and where the entrainment speed meets the ring's velocity.
#[derive(Debug, Clone, Copy)]
pub(super) struct FilmWork {
    /// The film law at this state.
    pub(super) law: FilmLaw,
    /// Elastic load Q \[N\].
    pub(super) load: f64,
    /// Entrainment speed u \[m/s\].
    pub(super) speed: f64,
    /// Unit entrainment direction ê.
    pub(super) direction: Vector3<f64>,
    /// Contact point P \[m\].
    pub(super) point: Vector3<f64>,
}

impl Elements {
    /// Entrainment velocity of a contact at point P with normal n: the mean
    /// surface velocity of ball and ring relative to the contact point, in
    /// the tangent plane (docs/model.md §3).
    ///
    /// The contact point moves with the ball's azimuth frame:
    /// v_P = q̇ + φ̇ e_x × (P − q). Taking the ball-centre velocity q̇ for v_P would miss
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

    pub(super) fn curvature(&self, ring: &RingMotion, contact_angle: f64) -> Curvature {
        Curvature::of_raceway(
            &ring.raceway,
            self.geometry.ball_diameter,
            self.geometry.pitch_diameter,
            contact_angle,
        )
    }

    /// Steady film of a contact with `ring` at contact angle α, entrainment
    /// speed u \[m/s\] and load Q \[N\] (Hertz semi-axis b at that load),
    /// starved by the ring's supply; None without a lubricant.
    pub(super) fn steady_film(
        &self,
        ring: &RingMotion,
        hertz: &HertzCoefficients,
        contact_angle: f64,
        entrainment_speed: f64,
        load: f64,
        semi_minor: f64,
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
                semi_minor,
                // Zhang et al. 2020 eq 27: the inner ring throws the supply film.
                ring_speed: ring.shaft_speed,
            },
        ))
    }

    /// The film law of a contact with `ring` at contact angle α and
    /// entrainment speed u (None without a lubricant, or with a supply the
    /// law refuses, which [`BearingModel::new`] has ruled out).
    pub(super) fn film_law(
        &self,
        ring: &RingMotion,
        hertz: &HertzCoefficients,
        contact_angle: f64,
        entrainment_speed: f64,
    ) -> Option<FilmLaw> {
        let lubricant = self.params.traction.lubricant()?;
        FilmLaw::new(
            lubricant,
            &self.params.film_supply[contact_index(ring)],
            &FilmGeometry {
                entrainment_speed,
                rolling_radius: self.curvature(ring, contact_angle).rolling_radius,
                effective_modulus: self.effective_modulus,
                ellipticity: hertz.ellipticity,
                semi_minor_coefficient: hertz.semi_minor_coefficient,
            },
        )
        .ok()
    }

    /// The fixed point δ_el = δ + h(K_c δ_el^{3/2}) of a contact with
    /// geometric overlap δ (`geometry.penetration`, surfaces included);
    /// None when open (δ + h(0) ≤ 0).
    pub(super) fn film_approach(
        &self,
        ring: &RingMotion,
        hertz: &HertzCoefficients,
        geometry: &TorusContact,
        entrainment_speed: f64,
    ) -> Option<FilmApproach> {
        let law = self.film_law(ring, hertz, geometry.contact_angle, entrainment_speed)?;
        let a = law.elastic_approach(hertz.stiffness, geometry.penetration)?;
        Some(FilmApproach {
            law,
            elastic_approach: a.approach,
            load: a.load,
            film: a.film,
        })
    }

    /// ∫₀^Q h dq of ball `ball`'s contact with `ring` for a given elastic
    /// load Q, under the film law of that state (0 when the geometry is
    /// degenerate) \[N·m\].
    fn film_integral(
        &self,
        ring: &RingMotion,
        table: &ContactTable,
        ball: &BallMotion,
        load: f64,
    ) -> f64 {
        let Some((geometry, _)) = self.race_geometry_any(ring, ball) else {
            return 0.0;
        };
        let hertz = table.at(geometry.contact_angle);
        let u = Self::entrainment(ring, ball, &geometry.contact_point, &geometry.normal).norm();
        self.film_law(ring, &hertz, geometry.contact_angle, u)
            .map_or(0.0, |law| law.integral(load))
    }

    /// The power of the films of ball j's closed contacts along the motion,
    /// without the rings' accelerations: ∂/∂t ∫₀^Q h dq with the ball's
    /// states moved by `dy_ball`, the rings' positions by their velocities,
    /// and time (module doc) \[W\].
    fn film_power(
        &self,
        t: f64,
        y: &[f64],
        j: usize,
        dy_ball: &[f64],
        loads: [Option<f64>; 2],
    ) -> f64 {
        if loads.iter().all(Option::is_none) {
            return 0.0;
        }
        let l = self.layout;
        let eps = 1e-9;
        let b = l.ball(j);
        let len = l.ball_len();
        let (r, o) = (l.ring(), l.outer());
        // A prescribed rotation at t + s; a driven one (refused with the
        // film in the approach, `Elements::new`) would move at its speed.
        let spin = self.spin(t, y);
        let spin_along = |s: f64| {
            if l.driven {
                Spin {
                    angle: spin.angle + s * spin.speed,
                    ..spin
                }
            } else {
                self.spin(t + s, y)
            }
        };
        let integral_at = |s: f64| {
            let mut block = [0.0; super::layout::StateLayout::BALL + 1];
            for k in 0..len {
                block[k] = y[b + k] + s * dy_ball[k];
            }
            let mut ring = [0.0; super::layout::StateLayout::RING];
            ring.copy_from_slice(&y[r..r + 10]);
            for k in 0..5 {
                ring[k] += s * y[r + 5 + k];
            }
            let mut outer = [0.0; super::layout::StateLayout::OUTER];
            outer.copy_from_slice(&y[o..o + 4]);
            outer[0] += s * y[o + 2];
            outer[1] += s * y[o + 3];
            // (A sliding outer ring is refused with the film in the approach.)
            let (inner_ring, outer_ring) =
                self.ring_motion_of(spin_along(s), &ring, &outer, [0.0; 2]);
            let (ball, _) = self.ball_motion_of(j, &block[..len]);
            let mut total = 0.0;
            if let Some(q) = loads[0] {
                total += self.film_integral(&inner_ring, &self.inner_table, &ball, q);
            }
            if let Some(q) = loads[1] {
                total += self.film_integral(&outer_ring, &self.outer_table, &ball, q);
            }
            total
        };
        (integral_at(eps) - integral_at(-eps)) / (2.0 * eps)
    }

    /// Stored energy of ball `ball`'s contact with `ring` with the film in
    /// the approach ([`FilmApproach::energy`]; 0 when open) \[J\].
    pub(super) fn film_contact_energy(
        &self,
        ring: &RingMotion,
        table: &ContactTable,
        ball: &BallMotion,
    ) -> f64 {
        let Some((geometry, _)) = self.race_geometry_any(ring, ball) else {
            return 0.0;
        };
        let hertz = table.at(geometry.contact_angle);
        let u = Self::entrainment(ring, ball, &geometry.contact_point, &geometry.normal).norm();
        self.film_approach(ring, &hertz, &geometry, u)
            .map_or(0.0, |a| a.energy())
    }

    /// Adds ball j's share of the films' power to `out`: the power along
    /// the motion without the rings' accelerations, and the gradients the
    /// border multiplies by them (module doc). `dy_ball`: the ball's
    /// derivatives.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn add_film_work(
        &self,
        t: f64,
        y: &[f64],
        j: usize,
        dy_ball: &[f64],
        film_work: &[Option<FilmWork>; 2],
        inner: &RingMotion,
        out: &mut BallCoupling,
    ) {
        if film_work.iter().all(Option::is_none) {
            return;
        }
        let loads = film_work.map(|w| w.map(|w| w.load));
        out.film_power = self.film_power(t, y, j, dy_ball, loads);
        if let Some(w) = &film_work[0] {
            let tilt_y = tilt_axis_y(y[self.layout.ring() + 4]);
            add_to(
                &mut out.ring_velocity_gradient,
                &w.inner_ring_gradient(&inner.centre, &tilt_y),
            );
        }
        if let Some(w) = &film_work[1] {
            add_to(&mut out.outer_velocity_gradient, &w.outer_ring_gradient());
        }
    }
}

impl FilmWork {
    /// ∂(∫₀^Q h)/∂u at fixed Q \[N·s\] (0 at rest).
    fn speed_gradient(&self) -> f64 {
        if self.speed > 0.0 {
            self.law.integral_speed_derivative(self.load) / self.speed
        } else {
            0.0
        }
    }

    /// ∂(∫₀^Q h)/∂(ring velocity y, z, …): the inner ring's translational
    /// velocity (x, y, z) and tilt rates (θ̇_y, θ̇_z) about `centre`, with
    /// `tilt_axis_y` the tilted y axis. u = |ê·(…+ ½ v_ring + ½ ω × (P − c))|.
    pub(super) fn inner_ring_gradient(
        &self,
        centre: &Vector3<f64>,
        tilt_axis_y: &Vector3<f64>,
    ) -> [f64; 5] {
        let g = 0.5 * self.speed_gradient();
        let arm = self.point - centre;
        [
            g * self.direction.x,
            g * self.direction.y,
            g * self.direction.z,
            g * self.direction.dot(&tilt_axis_y.cross(&arm)),
            g * self.direction.dot(&Vector3::z().cross(&arm)),
        ]
    }

    /// The same for the outer ring's velocity (y, z).
    pub(super) fn outer_ring_gradient(&self) -> [f64; 2] {
        let g = 0.5 * self.speed_gradient();
        [g * self.direction.y, g * self.direction.z]
    }
}
