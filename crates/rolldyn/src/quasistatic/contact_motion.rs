//! Motion at the raceway contacts of a quasi-static solution (docs/model.md §3),
//! as the dynamic model sees it: the contact point, the relative angular
//! velocity of ball and ring, the entrainment velocity and the rolling
//! direction. Films ([`super::films`]) and the local power-loss method
//! ([`crate::power::harris`]) are built on it.
//!
//! ```text
//! v_P = q̇ + ω_m e_x × (P − q),   u = ½[(v_b − v_P) + (v_ring − v_P)]_t,   Ω = ω_b − ω_ring
//! ```
//! with the ball centre q at (x, r, φ), q̇ = r ω_m e_t, the ball's angular
//! velocity ω_x e_x + ω_r e_r, and the inner ring turning at ω_i about its
//! (displaced, tilted) axis; the outer ring is fixed. P is the exact torus
//! contact of docs/model.md §2.1 at the solved ring displacement.

use super::{ContactSolution, Equilibrium};
use crate::contact::{GrooveCircle, RingPose, TorusContact};
use crate::geometry::{BearingGeometry, Raceway};
use nalgebra::Vector3;

/// One loaded raceway contact of a quasi-static solution.
#[derive(Debug, Clone, Copy)]
pub struct ContactMotion<'a> {
    /// The raceway.
    pub raceway: &'a Raceway,
    /// The solution's contact (load, angle, Hertz results).
    pub solution: &'a ContactSolution,
    /// Exact contact geometry at the solved displacement.
    pub contact: TorusContact,
    /// Sliding velocity of ball material over ring material at P \[m/s\].
    pub slip: Vector3<f64>,
    /// Ω = ω_b − ω_ring \[rad/s\].
    pub relative_spin: Vector3<f64>,
    /// Entrainment velocity, tangential part \[m/s\].
    pub entrainment: Vector3<f64>,
    /// Unit rolling direction at P (azimuthal, tangent to the contact).
    pub rolling_direction: Vector3<f64>,
}

impl ContactMotion<'_> {
    /// Entrainment (rolling) speed |u| \[m/s\].
    pub fn entrainment_speed(&self) -> f64 {
        self.entrainment.norm()
    }

    /// Spin of the ball relative to the ring about the contact normal
    /// ω_s = Ω·n \[rad/s\].
    pub fn spin(&self) -> f64 {
        self.relative_spin.dot(&self.contact.normal)
    }

    /// Rolling rate of the ball relative to the ring about the axis across
    /// the rolling direction, n × e_roll \[rad/s\].
    pub fn rolling_rate(&self) -> f64 {
        let axis = self.contact.normal.cross(&self.rolling_direction);
        self.relative_spin.dot(&axis)
    }
}

/// The loaded contacts of every ball of `eq`: per ball, inner and outer
/// (None where unloaded).
pub fn contact_motions<'a>(
    geometry: &'a BearingGeometry,
    eq: &'a Equilibrium,
) -> Vec<[Option<ContactMotion<'a>>; 2]> {
    motions(geometry, eq, false)
}

/// [`contact_motions`] of every contact, loaded or not: an open contact's
/// point is the ball's nearest point to the groove (None only where the
/// geometry is degenerate).
pub fn all_contact_motions<'a>(
    geometry: &'a BearingGeometry,
    eq: &'a Equilibrium,
) -> Vec<[Option<ContactMotion<'a>>; 2]> {
    motions(geometry, eq, true)
}

fn motions<'a>(
    geometry: &'a BearingGeometry,
    eq: &'a Equilibrium,
    open_too: bool,
) -> Vec<[Option<ContactMotion<'a>>; 2]> {
    let d = eq.displacement;
    let pose = RingPose {
        translation: Vector3::new(d[0], d[1], d[2]),
        tilt_y: d[3],
        tilt_z: d[4],
    };
    let inner_axis = pose.rotation() * Vector3::x();
    let rings = [
        (
            &geometry.inner,
            GrooveCircle::of(&geometry.inner, &pose),
            pose.translation,
            eq.inner_speed * inner_axis,
        ),
        (
            &geometry.outer,
            GrooveCircle::of(&geometry.outer, &RingPose::default()),
            Vector3::zeros(),
            Vector3::zeros(),
        ),
    ];
    eq.balls
        .iter()
        .map(|ball| {
            let (s, c) = ball.azimuth.sin_cos();
            let (ex, er, et) = (
                Vector3::x(),
                Vector3::new(0.0, c, s),
                Vector3::new(0.0, -s, c),
            );
            let q = ball.axial_position * ex + ball.radial_position * er;
            let v = ball.radial_position * ball.orbital_speed * et;
            let w = ball.spin_axial * ex + ball.spin_radial * er;
            let mut out = [None, None];
            for (k, ((raceway, circle, centre, omega), solution)) in
                rings.iter().zip([&ball.inner, &ball.outer]).enumerate()
            {
                if solution.load <= 0.0 && !open_too {
                    continue;
                }
                let Some(contact) = circle.contact(&q, geometry.ball_diameter, 0.0) else {
                    continue;
                };
                let p = contact.contact_point;
                let n = contact.normal;
                let v_p = v + ball.orbital_speed * ex.cross(&(p - q));
                let ball_surface = v + w.cross(&(p - q));
                let ring_surface = omega.cross(&(p - centre));
                let e = 0.5 * ((ball_surface - v_p) + (ring_surface - v_p));
                let azimuthal = Vector3::new(0.0, -p.z, p.y);
                let along = azimuthal - azimuthal.dot(&n) * n;
                out[k] = Some(ContactMotion {
                    raceway,
                    solution,
                    contact,
                    slip: ball_surface - ring_surface,
                    relative_spin: w - omega,
                    entrainment: e - e.dot(&n) * n,
                    rolling_direction: along.try_normalize(0.0).unwrap_or(et),
                });
            }
            out
        })
        .collect()
}
