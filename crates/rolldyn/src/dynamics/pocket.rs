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
    /// Ball-centre offset from the pocket centre \[m\].
    pub(super) offset: f64,
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
        let angle = y[c + 2] + std::f64::consts::TAU * j as f64 / self.layout.balls as f64;
        let axis = Vector3::new(0.0, angle.cos(), angle.sin());
        let pocket = centre + cage.pitch_radius * axis;
        let rel = q - pocket;
        let perp = match cage.pocket_shape {
            PocketShape::Cylindrical => rel - rel.dot(&axis) * axis,
            PocketShape::Spherical => rel,
        };
        let offset = perp.norm();
        let half_clearance = 0.5 * cage.pocket_clearance;
        let squeezed = cage.pocket_squeeze.is_some() && offset > 0.0;
        if !squeezed && !cage.pocket_law.acts(offset, half_clearance) {
            return None;
        }
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
            offset,
            dissipation: (normal - law.elastic) * rate - friction.dot(&slip_t),
            friction_power: -friction.dot(&slip_t),
        })
    }
}
