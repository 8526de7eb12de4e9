//! The loads that turn or fluctuate with the shaft: a rotating unbalance
//! and harmonic loads (a gear mesh's fluctuation), at the shaft's angle and
//! speed (prescribed, or a torque-driven shaft's states); module doc of
//! `dynamics::shaft`.

use super::{SHAFT_LEN, ShaftDynamics};
use crate::error::InvalidParameter;

/// A load on the shaft that fluctuates with the shaft's angle θ: a gear
/// mesh's, F(θ) = amplitude · sin(order · θ + phase) at `position`, on top
/// of the constant loads (the mesh's mean force among them).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HarmonicLoad {
    /// Axial position on the shaft from the reference point \[m\].
    pub position: f64,
    /// Force amplitude (x, y, z) \[N\].
    pub amplitude: [f64; 3],
    /// Cycles per shaft revolution (a gear's tooth count).
    pub order: f64,
    /// Phase at θ = 0 \[rad\].
    pub phase: f64,
}

/// A rotating unbalance on the shaft.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unbalance {
    /// Mass times eccentricity m_u e \[kg·m\].
    pub amount: f64,
    /// Axial position on the shaft from the reference point \[m\].
    pub position: f64,
}

impl ShaftDynamics {
    /// With a rotating unbalance (at constant speed).
    pub fn with_unbalance(mut self, unbalance: Unbalance) -> Result<Self, InvalidParameter> {
        if !(unbalance.amount.is_finite() && unbalance.amount >= 0.0) {
            return Err(InvalidParameter::new(
                "unbalance",
                unbalance.amount,
                "must be a finite, non-negative mass times radius",
            ));
        }
        if !unbalance.position.is_finite() {
            return Err(InvalidParameter::new(
                "unbalance.position",
                unbalance.position,
                "must be finite",
            ));
        }
        self.unbalance = Some(unbalance);
        Ok(self)
    }

    /// With loads that fluctuate with the shaft's angle (gear meshes).
    pub fn with_harmonic_loads(
        mut self,
        loads: Vec<HarmonicLoad>,
    ) -> Result<Self, InvalidParameter> {
        for l in &loads {
            let finite = l.position.is_finite()
                && l.phase.is_finite()
                && l.amplitude.iter().all(|a| a.is_finite());
            if !(finite && l.order.is_finite() && l.order > 0.0) {
                return Err(InvalidParameter::new(
                    "harmonic load",
                    l.order,
                    "needs a finite position, amplitude and phase and a positive order",
                ));
            }
        }
        self.harmonic_loads = loads;
        Ok(self)
    }

    /// The shaft's rotation (speed, angle) at time `t` from its `state`:
    /// a driven shaft's states, else the prescribed profile's.
    fn rotation(&self, t: f64, state: &[f64]) -> (f64, f64) {
        if self.drive.is_some() {
            (state[SHAFT_LEN + 1], state[SHAFT_LEN])
        } else {
            let speed = &self.bearings[0].model.parameters().speed;
            (speed.speed_at(t), speed.angle_at(t))
        }
    }

    /// The generalized force on the shaft at time `t` (x, y, z, θ_y, θ_z)
    /// of the loads that turn or fluctuate with it: the unbalance and the
    /// harmonic loads (zero without them).
    pub(super) fn rotating_load(&self, t: f64, state: &[f64]) -> [f64; 5] {
        if self.unbalance.is_none() && self.harmonic_loads.is_empty() {
            return [0.0; 5];
        }
        let (omega, angle) = self.rotation(t, state);
        let mut total = [0.0; 5];
        let mut add = |x: f64, f: [f64; 3]| {
            total[0] += f[0];
            total[1] += f[1];
            total[2] += f[2];
            total[3] -= x * f[2];
            total[4] += x * f[1];
        };
        if let Some(u) = self.unbalance {
            let magnitude = u.amount * omega * omega;
            add(
                u.position,
                [0.0, magnitude * angle.cos(), magnitude * angle.sin()],
            );
        }
        for l in &self.harmonic_loads {
            let s = (l.order * angle + l.phase).sin();
            add(l.position, l.amplitude.map(|a| a * s));
        }
        total
    }
}
