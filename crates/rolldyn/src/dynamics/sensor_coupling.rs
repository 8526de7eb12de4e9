//! The sensor chain ([`crate::signal::sensor`]) advanced alongside a run:
//! the force the bearing carries into the housing at every accepted step
//! drives the housing's modes, and the run's samples read the acquired
//! acceleration.
//!
//! The housing force is the outer ring's support force when the ring sits
//! on a housing spring–damper, else the sum of the balls' forces on the
//! outer raceway: their normal loads with the surfaces' forces (a spall's
//! edges), without the traction (tangential, at most the friction
//! coefficient times the load, and along the rolling direction rather than
//! the radial one the sensor reads). The cage's guide-land contact is left
//! out.

use super::model::BearingModel;
use super::race_contact::Want;
use crate::error::InvalidParameter;
use crate::signal::sensor::{SensorChain, SensorSample, SensorSpec};
use nalgebra::Vector3;

impl BearingModel {
    /// Attaches the sensor `spec` to this model's run from time `t0` and
    /// state `y0` (the housing starts statically loaded by the force there).
    pub fn attach_sensor(
        &mut self,
        spec: SensorSpec,
        t0: f64,
        y0: &[f64],
    ) -> Result<(), InvalidParameter> {
        let force = self.housing_force(y0, self.outer_raceway_force(t0, y0));
        self.sensor = Some(Box::new(SensorChain::new(spec, t0, force)?));
        Ok(())
    }

    /// The sensor chain, if the run has one.
    pub fn sensor(&self) -> Option<&SensorChain> {
        self.sensor.as_deref()
    }

    /// The sensor's sample at the run's sample time `t`.
    pub fn sensor_sample(&self, t: f64) -> Option<SensorSample> {
        self.sensor.as_ref().and_then(|s| s.sample(t))
    }

    /// The force the housing support carries from the outer ring at state
    /// `y` \[N\] (None for a fixed outer ring).
    pub fn support_force(&self, y: &[f64]) -> Option<Vector3<f64>> {
        let o = self.elements.layout.outer();
        self.elements.params.outer_ring.as_ref().map(|ring| {
            -ring.housing.force(
                &Vector3::new(0.0, y[o], y[o + 1]),
                &Vector3::new(0.0, y[o + 2], y[o + 3]),
            )
        })
    }

    /// The housing force (y, z) at state `y`, given the balls' summed
    /// force on the outer raceway `raceway` (used for a fixed outer ring).
    pub(super) fn housing_force(&self, y: &[f64], raceway: Vector3<f64>) -> [f64; 2] {
        let f = self.support_force(y).unwrap_or(raceway);
        [f.y, f.z]
    }

    /// The balls' summed force on the outer raceway at (`t`, `y`),
    /// without traction (as the accepted steps sum it).
    fn outer_raceway_force(&self, t: f64, y: &[f64]) -> Vector3<f64> {
        let (_, outer) = self.elements.ring_motion(t, y);
        (0..self.elements.layout.balls)
            .filter_map(|j| {
                let (ball, _) = self.elements.ball_kinematics(j, y);
                self.elements.race_contact(
                    &outer,
                    &self.elements.outer_table,
                    &self.episodes[j][1],
                    &ball,
                    Want::Penetration,
                )
            })
            .map(|c| c.surface.ring_force - c.force)
            .sum()
    }

    /// The sensor's update at an accepted step with the balls' summed force
    /// on the outer raceway `raceway`.
    pub(super) fn sensor_update(&mut self, t: f64, y: &[f64], raceway: Vector3<f64>) {
        if self.sensor.is_some() {
            let force = self.housing_force(y, raceway);
            if let Some(sensor) = self.sensor.as_mut() {
                sensor.advance(t, force);
            }
        }
    }
}
