//! Ball–pocket contact (docs/model.md §5).
//!
//! Ball–pocket (docs/model.md §5; [`crate::cage::pocket`]): cylindrical or
//! spherical pockets at the cage pitch radius, `linear`, `hertz` or
//! `gupta_film` normal law, modified-Coulomb friction on the slip at the
//! contact point, and optionally the oil film's squeeze damping
//! ([`crate::cage::squeeze`]). Friction follows the law's normal force
//! only: the squeeze film is a pressure, its shear is left out.

use super::elements::Elements;
use super::motion::BallMotion;
use crate::cage::PocketShape;
use nalgebra::Vector3;

/// One evaluated ball–pocket contact.
pub(super) struct PocketContact {
    /// Force on the ball \[N\].
    pub(super) force: Vector3<f64>,
    /// Its normal part (the pocket law's force, elastic and damping, plus
    /// the squeeze film's, which is negative when the ball leaves the wall)
    /// \[N\].
    pub(super) normal_force: f64,
    /// Moment on the ball about its centre \[N·m\].
    pub(super) moment: Vector3<f64>,
    /// Contact point on the ball \[m\].
    pub(super) point: Vector3<f64>,
    /// Dissipated power: damping and friction \[W\].
    pub(super) dissipation: f64,
    /// The friction's part of `dissipation` \[W\].
    pub(super) friction_power: f64,
}

impl Elements {
    /// Offset of ball j's centre from its pocket's centre (the pocket's
    /// axis, or its centre point for a spherical pocket), and that offset
    /// as a vector \[m\]. The pocket's direction is the ball's azimuth
    /// turned by the small angle Δ between them ([`turn`]).
    fn pocket_offset(&self, j: usize, y: &[f64], ball: &BallMotion) -> (f64, Vector3<f64>) {
        let cage = &self.params.cage;
        let c = self.layout.cage();
        let centre = Vector3::new(0.0, y[c], y[c + 1]);
        let (phi, cos_phi, sin_phi) = ball.azimuth;
        let pitch = std::f64::consts::TAU * j as f64 / self.layout.balls as f64;
        let (cos_delta, sin_delta) = turn((y[c + 2] - phi) + pitch);
        let axis = Vector3::new(
            0.0,
            cos_delta * cos_phi - sin_delta * sin_phi,
            cos_delta * sin_phi + sin_delta * cos_phi,
        );
        let rel = ball.centre - (centre + cage.pitch_radius * axis);
        let perp = match cage.pocket_shape {
            PocketShape::Cylindrical => rel - rel.dot(&axis) * axis,
            PocketShape::Spherical => rel,
        };
        (perp.norm(), perp)
    }

    /// Elastic energy of ball j's pocket contact \[J\].
    pub(super) fn pocket_energy(&self, j: usize, y: &[f64], ball: &BallMotion) -> f64 {
        let cage = &self.params.cage;
        let (offset, _) = self.pocket_offset(j, y, ball);
        cage.pocket_law.energy(offset, 0.5 * cage.pocket_clearance)
    }

    /// Whether ball j's pocket contact acts: the law's force or the
    /// squeeze film's.
    pub(super) fn pocket_acts(&self, j: usize, y: &[f64], ball: &BallMotion) -> bool {
        self.pocket_acts_at(self.pocket_offset(j, y, ball).0)
    }

    /// Whether a pocket contact acts at the ball's offset `offset` from
    /// the pocket's centre.
    fn pocket_acts_at(&self, offset: f64) -> bool {
        let cage = &self.params.cage;
        let squeezed = cage.pocket_squeeze.is_some() && offset > 0.0;
        squeezed || cage.pocket_law.acts(offset, 0.5 * cage.pocket_clearance)
    }

    /// Pocket contact of ball j, if closed.
    pub(super) fn pocket_contact(
        &self,
        j: usize,
        y: &[f64],
        ball: &BallMotion,
    ) -> Option<PocketContact> {
        let (q, v, w) = (&ball.centre, &ball.velocity, &ball.omega);
        let cage = &self.params.cage;
        let c = self.layout.cage();
        let centre = Vector3::new(0.0, y[c], y[c + 1]);
        let velocity = Vector3::new(0.0, y[c + 3], y[c + 4]);
        let spin = y[c + 5] * Vector3::x();
        let (offset, perp) = self.pocket_offset(j, y, ball);
        if !self.pocket_acts_at(offset) {
            return None;
        }
        let half_clearance = 0.5 * cage.pocket_clearance;
        let n = perp / offset;
        let point = q + 0.5 * self.geometry.ball_diameter * n;
        let pocket_point_velocity = velocity + spin.cross(&(q - centre));
        let rate = (v - pocket_point_velocity).dot(&n);
        let law = cage.pocket_law.force(offset, half_clearance, rate);
        let squeeze = cage.pocket_squeeze.map_or(0.0, |s| {
            s.force(cage.pocket_shape, offset, half_clearance, rate)
        });
        let normal = law.total + squeeze;
        let arm = point - q;
        let slip = (v + w.cross(&arm)) - (velocity + spin.cross(&(point - centre)));
        let slip_t = slip - slip.dot(&n) * n;
        let friction = cage.pocket_friction.force(law.total, &slip_t);
        Some(PocketContact {
            force: -normal * n + friction,
            normal_force: normal,
            moment: arm.cross(&friction),
            point,
            dissipation: (normal - law.elastic) * rate - friction.dot(&slip_t),
            friction_power: -friction.dot(&slip_t),
        })
    }
}

/// cos Δ and sin Δ: by their Taylor series for |Δ| ≤ 1/16, where the
/// first terms left out (Δ¹²/12!, Δ¹¹/11!) are below 1e-22 and 1e-20,
/// else by the library. A ball sits within a pocket clearance of its
/// pocket's angle (Δ of order 10⁻²), so the library's call is saved on
/// every evaluation. The series are summed in pairs of terms (Estrin's
/// scheme) to keep the chain of dependent operations short.
fn turn(delta: f64) -> (f64, f64) {
    if delta.abs() > 0.0625 {
        return (delta.cos(), delta.sin());
    }
    let d2 = delta * delta;
    let d4 = d2 * d2;
    let cos = 1.0
        + d2 * (-1.0 / 2.0)
        + d4 * (1.0 / 24.0 + d2 * (-1.0 / 720.0))
        + (d4 * d4) * (1.0 / 40_320.0 + d2 * (-1.0 / 3_628_800.0));
    let sin = delta
        + delta
            * (d2 * (-1.0 / 6.0)
                + d4 * (1.0 / 120.0 + d2 * (-1.0 / 5_040.0))
                + (d4 * d4) * (1.0 / 362_880.0));
    (cos, sin)
}

#[cfg(test)]
mod tests {
    use super::turn;

    #[test]
    fn turn_is_cos_and_sin_to_an_ulp() {
        for k in -1000..=1000 {
            let delta = 0.1 * k as f64 / 1000.0;
            let (cos, sin) = turn(delta);
            assert!((cos - delta.cos()).abs() <= f64::EPSILON, "cos {delta}");
            assert!(
                (sin - delta.sin()).abs() <= f64::EPSILON * delta.abs().max(1e-300),
                "sin {delta}"
            );
        }
    }
}
