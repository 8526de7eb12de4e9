//! Exact ball–torus contact geometry (docs/model.md §2.1).
//!
//! A raceway groove is a torus: the surface at distance r_g (groove radius)
//! from its groove-curvature-centre circle (centre c, unit axis a, radius
//! ρ). For a ball of diameter D centred at q the point of the circle nearest
//! q is
//! ```text
//! v = (q − c) − ((q − c)·a) a,     p = c + ρ v/|v|
//! ```
//! and with d = |q − p|, n = (q − p)/d (groove centre → ball centre):
//! ```text
//! penetration  δ = d − (r_g − D/2) + w         (w: surface height, docs/model.md §6)
//! contact point P = q + (D/2) n
//! contact angle α: sin α = |n·a|
//! ```
//! Exact for any ring translation and tilt; it reduces to Shan et al. 2023 eqs 6–7
//! in planar mode and to Deng et al. 2022 eqs 2–6 for small ring displacements
//! (validation case A5). The ball sits inside the groove's tube for both
//! rings, so the same formula serves inner and outer raceways.

use crate::geometry::Raceway;
use nalgebra::{Rotation3, Unit, Vector3};

/// Rigid pose of a ring: translation of its centre and small-or-large tilts
/// about the global y and z axes (x is the bearing axis). The rotation is
/// R = R_z(θ_z) R_y(θ_y), exact (no small-angle approximation).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RingPose {
    /// Ring-centre displacement (x, y, z) \[m\].
    pub translation: Vector3<f64>,
    /// Tilt about the y axis θ_y \[rad\].
    pub tilt_y: f64,
    /// Tilt about the z axis θ_z \[rad\].
    pub tilt_z: f64,
}

impl RingPose {
    /// The rotation matrix of the tilts (the identity, without sines and
    /// cosines, when both are zero: a planar model's rings never tilt).
    pub fn rotation(&self) -> Rotation3<f64> {
        if self.tilt_y == 0.0 && self.tilt_z == 0.0 {
            return Rotation3::identity();
        }
        Rotation3::from_axis_angle(&Vector3::z_axis(), self.tilt_z)
            * Rotation3::from_axis_angle(&Vector3::y_axis(), self.tilt_y)
    }

    /// The ring's unit axis, R x̂.
    pub fn axis(&self) -> Unit<Vector3<f64>> {
        Unit::new_unchecked(self.rotation() * Vector3::x())
    }
}

/// A groove-curvature-centre circle placed in the global frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GrooveCircle {
    /// Centre of the circle \[m\].
    pub centre: Vector3<f64>,
    /// Unit axis of the ring.
    pub axis: Unit<Vector3<f64>>,
    /// Radius of the circle ρ \[m\].
    pub radius: f64,
    /// Groove (torus tube) radius r_g \[m\].
    pub groove_radius: f64,
}

impl GrooveCircle {
    /// The groove-centre circle of `raceway` on a ring at `pose`.
    pub fn of(raceway: &Raceway, pose: &RingPose) -> Self {
        Self::with_axis(raceway, &pose.translation, pose.axis())
    }

    /// The groove-centre circle of `raceway` on a ring centred at
    /// `translation` with unit axis `axis` (from [`RingPose::axis`]).
    pub fn with_axis(
        raceway: &Raceway,
        translation: &Vector3<f64>,
        axis: Unit<Vector3<f64>>,
    ) -> Self {
        Self {
            centre: translation + raceway.groove_centre_axial * axis.into_inner(),
            axis,
            radius: raceway.groove_centre_radius,
            groove_radius: raceway.groove_radius,
        }
    }

    /// Contact of a ball of diameter `ball_diameter` centred at `ball_centre`
    /// with this groove, with surface height `surface_height` (positive
    /// raises the raceway into the ball). `None` when the geometry is
    /// degenerate: the ball centre on the ring axis or on the circle itself
    /// (no defined normal; never reached by a ball in its groove).
    pub fn contact(
        &self,
        ball_centre: &Vector3<f64>,
        ball_diameter: f64,
        surface_height: f64,
    ) -> Option<TorusContact> {
        let rel = ball_centre - self.centre;
        let a = self.axis.into_inner();
        let radial = rel - rel.dot(&a) * a;
        let radial_norm = radial.norm();
        if radial_norm <= f64::EPSILON * self.radius {
            return None;
        }
        let nearest = self.centre + (self.radius / radial_norm) * radial;
        let to_ball = ball_centre - nearest;
        let distance = to_ball.norm();
        if distance <= f64::EPSILON * self.radius {
            return None;
        }
        let normal = to_ball / distance;
        let sin_alpha = normal.dot(&a).abs().min(1.0);
        Some(TorusContact {
            penetration: distance - (self.groove_radius - 0.5 * ball_diameter) + surface_height,
            normal,
            contact_point: ball_centre + 0.5 * ball_diameter * normal,
            groove_centre: nearest,
            contact_angle: sin_alpha.asin(),
        })
    }
}

/// Result of the exact torus contact (docs/model.md §2.1). δ ≤ 0 means no contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TorusContact {
    /// Penetration δ \[m\] (positive: overlap).
    pub penetration: f64,
    /// Unit normal n from the groove centre towards the ball centre.
    pub normal: Vector3<f64>,
    /// Contact point P on the ball surface \[m\].
    pub contact_point: Vector3<f64>,
    /// Nearest point p of the groove-centre circle \[m\].
    pub groove_centre: Vector3<f64>,
    /// Contact angle α \[rad\], in [0, π/2].
    pub contact_angle: f64,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::test_bearing;

    #[test]
    fn free_angle_contact_touches_at_alpha0() {
        let g = test_bearing(22);
        for phi in [0.0, 1.0, 2.5, 4.0] {
            let q = Vector3::new(0.0, 27e-3 * f64::cos(phi), 27e-3 * f64::sin(phi));
            for race in [&g.inner, &g.outer] {
                let c = GrooveCircle::of(race, &RingPose::default())
                    .contact(&q, g.ball_diameter, 0.0)
                    .unwrap();
                assert!(c.penetration.abs() < 1e-15);
                assert!((c.contact_angle - 17.7f64.to_radians()).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn tilt_rotates_axis_exactly() {
        let pose = RingPose {
            tilt_y: 0.3,
            ..Default::default()
        };
        let a = pose.rotation() * Vector3::x();
        assert!((a - Vector3::new(0.3f64.cos(), 0.0, -0.3f64.sin())).norm() < 1e-15);
    }
}
