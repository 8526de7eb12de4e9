//! The motion of the bodies at a state: each ball's centre, velocity and
//! angular velocity with its azimuth frame, and each ring's pose, groove
//! circle and surface velocities (docs/model.md §1). The force elements
//! take these values; nothing here evaluates a force.

use super::elements::Elements;
use super::layout::StateLayout;
use crate::cage::GuideLand;
use crate::contact::{GrooveCircle, RingPose};
use crate::geometry::{Raceway, RingKind};
use nalgebra::{Rotation3, Vector3};

/// Kinematic state of a ball (global frame).
pub(super) struct BallMotion {
    /// Ball index j.
    pub(super) index: usize,
    /// Spin angle ψ \[rad\] (0 when the balls carry no surface).
    pub(super) spin_angle: f64,
    pub(super) centre: Vector3<f64>,
    pub(super) velocity: Vector3<f64>,
    pub(super) omega: Vector3<f64>,
    /// Orbital rate φ̇ of its azimuth frame \[rad/s\].
    pub(super) orbital_rate: f64,
    /// Orbital angle φ \[rad\] and its cosine and sine.
    pub(super) azimuth: (f64, f64, f64),
}

/// Kinematic state of a ring for contact evaluation.
pub(super) struct RingMotion {
    pub(super) raceway: Raceway,
    pub(super) circle: GrooveCircle,
    pub(super) centre: Vector3<f64>,
    pub(super) velocity: Vector3<f64>,
    /// Angular velocity of the ring material (spin + tilt rates).
    pub(super) omega: Vector3<f64>,
    /// Angular velocity of the ring's frame (tilt rates only).
    pub(super) omega_frame: Vector3<f64>,
    /// Angle the ring has turned about its axis θ_ring \[rad\].
    pub(super) spin_angle: f64,
    /// Spin speed of the ring about its axis \[rad/s\].
    pub(super) spin_speed: f64,
    /// The ring's (tilted) axis, unit.
    pub(super) axis: Vector3<f64>,
    /// Inner-ring (shaft) speed \[rad/s\] (the oil-flow supply, docs/model.md §4).
    pub(super) shaft_speed: f64,
}

/// The inner ring's rotation about its axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Spin {
    /// Speed \[rad/s\].
    pub(super) speed: f64,
    /// Angle turned since t = 0 \[rad\].
    pub(super) angle: f64,
}

impl Elements {
    /// The inner ring's rotation at `t`: its states for a torque-driven
    /// ring, else the prescribed profile's.
    pub(super) fn spin(&self, t: f64, y: &[f64]) -> Spin {
        if self.layout.driven {
            let s = self.layout.spin();
            Spin {
                angle: y[s],
                speed: y[s + 1],
            }
        } else {
            Spin {
                speed: self.params.speed.speed_at(t),
                angle: self.params.speed.angle_at(t),
            }
        }
    }

    /// A sliding outer ring's axial position and velocity (zeros when it
    /// is held).
    pub(super) fn outer_slide(&self, y: &[f64]) -> [f64; 2] {
        if self.layout.sliding {
            let s = self.layout.slide();
            [y[s], y[s + 1]]
        } else {
            [0.0; 2]
        }
    }

    pub(super) fn ring_motion(&self, t: f64, y: &[f64]) -> (RingMotion, RingMotion) {
        let (r, o) = (self.layout.ring(), self.layout.outer());
        self.ring_motion_of(
            self.spin(t, y),
            &y[r..r + StateLayout::RING],
            &y[o..o + StateLayout::OUTER],
            self.outer_slide(y),
        )
    }

    /// [`Self::ring_motion`] from the inner ring's rotation, its 10 states,
    /// the outer ring's 4 and its axial slide (position, velocity).
    pub(super) fn ring_motion_of(
        &self,
        spin: Spin,
        ring: &[f64],
        outer: &[f64],
        slide: [f64; 2],
    ) -> (RingMotion, RingMotion) {
        let y = ring;
        let r = 0;
        let pose = RingPose {
            translation: Vector3::new(y[r], y[r + 1], y[r + 2]),
            tilt_y: y[r + 3],
            tilt_z: y[r + 4],
        };
        let omega_frame = y[r + 9] * Vector3::z() + y[r + 8] * tilt_axis_y(pose.tilt_z);
        let unit_axis = pose.axis();
        let axis = unit_axis.into_inner();
        let spin_speed = spin.speed;
        let inner = RingMotion {
            raceway: self.geometry.inner,
            circle: GrooveCircle::with_axis(&self.geometry.inner, &pose.translation, unit_axis),
            centre: pose.translation,
            velocity: Vector3::new(y[r + 5], y[r + 6], y[r + 7]),
            omega: spin_speed * axis + omega_frame,
            omega_frame,
            spin_angle: if self.params.surface.inner.is_smooth() {
                0.0
            } else {
                spin.angle
            },
            spin_speed,
            axis,
            shaft_speed: spin_speed,
        };
        let (y, o) = (outer, 0);
        let outer_pose = RingPose {
            translation: Vector3::new(slide[0], y[o], y[o + 1]),
            ..RingPose::default()
        };
        let outer = RingMotion {
            raceway: self.geometry.outer,
            circle: GrooveCircle::of(&self.geometry.outer, &outer_pose),
            centre: outer_pose.translation,
            velocity: Vector3::new(slide[1], y[o + 2], y[o + 3]),
            omega: Vector3::zeros(),
            omega_frame: Vector3::zeros(),
            spin_angle: 0.0,
            spin_speed: 0.0,
            axis: Vector3::x(),
            shaft_speed: spin_speed,
        };
        (inner, outer)
    }

    /// Ball centre, velocity and angular velocity (global), and its frame.
    #[allow(clippy::type_complexity)]
    pub(super) fn ball_kinematics(&self, j: usize, y: &[f64]) -> (BallMotion, [Vector3<f64>; 3]) {
        let b = self.layout.ball(j);
        self.ball_motion_of(j, &y[b..b + self.layout.ball_len()])
    }

    /// [`Self::ball_kinematics`] from ball j's block of states.
    #[allow(clippy::type_complexity)]
    pub(super) fn ball_motion_of(
        &self,
        j: usize,
        block: &[f64],
    ) -> (BallMotion, [Vector3<f64>; 3]) {
        let (y, b) = (block, 0);
        let (s, c) = y[b + 2].sin_cos();
        let ex = Vector3::x();
        let er = Vector3::new(0.0, c, s);
        let et = Vector3::new(0.0, -s, c);
        let q = y[b] * ex + y[b + 1] * er;
        let v = y[b + 3] * ex + y[b + 4] * er + y[b + 1] * y[b + 5] * et;
        let w = y[b + 6] * ex + y[b + 7] * er + y[b + 8] * et;
        (
            BallMotion {
                index: j,
                spin_angle: if self.layout.ball_spin_angle {
                    y[b + StateLayout::SPIN_ANGLE]
                } else {
                    0.0
                },
                centre: q,
                velocity: v,
                omega: w,
                orbital_rate: y[b + 5],
                azimuth: (y[b + 2], c, s),
            },
            [ex, er, et],
        )
    }

    /// Centre (radial plane), centre velocity and land speed of the guiding ring.
    pub(super) fn guide_ring(
        &self,
        guide: &GuideLand,
        t: f64,
        y: &[f64],
    ) -> (Vector3<f64>, Vector3<f64>, f64) {
        match guide.ring {
            RingKind::Outer => {
                let o = self.layout.outer();
                (
                    Vector3::new(0.0, y[o], y[o + 1]),
                    Vector3::new(0.0, y[o + 2], y[o + 3]),
                    0.0,
                )
            }
            RingKind::Inner => {
                let r = self.layout.ring();
                (
                    Vector3::new(0.0, y[r + 1], y[r + 2]),
                    Vector3::new(0.0, y[r + 6], y[r + 7]),
                    self.spin(t, y).speed,
                )
            }
        }
    }
}

/// The inner ring's tilted y axis R_z(θ_z) e_y, about which the tilt rate
/// θ̇_y turns it (docs/model.md §1).
pub(super) fn tilt_axis_y(tilt_z: f64) -> Vector3<f64> {
    if tilt_z == 0.0 {
        return Vector3::y();
    }
    Rotation3::from_axis_angle(&Vector3::z_axis(), tilt_z) * Vector3::y()
}
