//! Friction of contact seals: the lips of a sealed bearing (2RS, RS1, …)
//! rub on the inner ring's land and oppose its turning relative to the
//! outer ring with a friction moment nearly independent of speed and load
//! (SKF 2018, docs/references.md, "frictional moment of seals":
//! M_seal = K_S1 d_s^β + K_S2 per seal, with constants for each seal type
//! and counterface diameter d_s). rolldyn takes the bearing's seal moment
//! M_s as given (both seals together), regularised through zero speed:
//! ```text
//! M = −M_s ω / √(ω² + ω₀²)        (ω: inner-ring speed relative to the outer ring)
//! P = −M ω = M_s ω² / √(ω² + ω₀²) ≥ 0
//! ```
//! In the dynamic model the inner ring's speed is prescribed, so the
//! moment acts on the drive only: it adds to the drive torque and, as
//! dissipation, to the energy balance (docs/model.md §10); Harris's local
//! method (`power::harris`) adds M_s ω to the bearing's power loss. The lips' viscous and temperature
//! dependence, and their drag on the balls' lubricant, are not modelled.

use crate::error::{InvalidParameter, require_non_negative, require_positive};

/// Default transition speed ω₀ of the seal moment: 1 rpm \[rad/s\].
pub const DEFAULT_TRANSITION_SPEED: f64 = std::f64::consts::TAU / 60.0;

/// Friction of the bearing's contact seals.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SealFriction {
    /// Friction moment M_s of all the bearing's seals when turning \[N·m\].
    pub torque: f64,
    /// Speed ω₀ through which the moment turns with the direction of
    /// rotation \[rad/s\].
    pub transition_speed: f64,
}

impl SealFriction {
    /// Seals of moment `torque` \[N·m\] with the default transition speed.
    pub fn new(torque: f64) -> Self {
        Self {
            torque,
            transition_speed: DEFAULT_TRANSITION_SPEED,
        }
    }

    /// Checks the parameters; the error names the field.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        require_non_negative("seal_friction_torque", self.torque)?;
        require_positive("seal_transition_speed", self.transition_speed)
    }

    /// Moment of the seals on the inner ring about its axis at relative
    /// speed `speed` \[rad/s\] (against the rotation) \[N·m\].
    pub fn moment(&self, speed: f64) -> f64 {
        -self.torque * speed / speed.hypot(self.transition_speed)
    }

    /// Power the seals dissipate at `speed` \[W\] (≥ 0).
    pub fn power(&self, speed: f64) -> f64 {
        -self.moment(speed) * speed
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_moment_opposes_the_rotation_and_reaches_the_seal_torque() {
        let seal = SealFriction::new(0.05);
        let speed = 1000.0 * std::f64::consts::TAU / 60.0;
        // At 1000 rpm the regularisation is 5e-7 of the moment.
        assert!((seal.moment(speed) + 0.05).abs() < 1e-7);
        assert!((seal.moment(-speed) - 0.05).abs() < 1e-7);
        assert_eq!(seal.moment(0.0), 0.0);
        for w in [-50.0, -0.1, 0.0, 0.01, 3.0] {
            assert!(seal.power(w) >= 0.0);
            assert!(seal.moment(w).abs() <= 0.05);
        }
        // P = M_s ω (1 − ω₀²/(2ω²) + …): 5e-7 below M_s ω here.
        assert!((seal.power(speed) / (0.05 * speed) - 1.0).abs() < 1e-6);
    }

    #[test]
    fn bad_parameters_are_refused() {
        let mut seal = SealFriction::new(-1.0);
        assert_eq!(seal.validate().unwrap_err().field, "seal_friction_torque");
        seal.torque = 0.1;
        seal.transition_speed = 0.0;
        assert_eq!(seal.validate().unwrap_err().field, "seal_transition_speed");
    }
}
