//! Modified Coulomb friction (Shan et al. 2023 eqs 14–15; docs/model.md §3, model 1), as a
//! stress and, integrated at uniform slip, as a force:
//! ```text
//! τ = −c_d(|v|) μ p v/|v|,   F_T = −c_d(|v|) μ Q v/|v|,
//! c_d = 0 for |v| ≤ v₀,  (|v| − v₀)/(v₁ − v₀) for v₀ < |v| < v₁,  1 for |v| ≥ v₁
//! ```
//! The ramp regularises the sign function (the force is continuous in the
//! slip, as stiff integrators need). Shan et al. 2023 does not print v₀, v₁; the
//! defaults (v₀ = 0, v₁ = 1 mm/s) are documented in docs/dynamics.md.

use super::{ContactConditions, TractionLaw};
use crate::error::InvalidParameter;
use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

/// Parameters of the modified Coulomb law.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct ModifiedCoulomb {
    /// Friction coefficient μ ≥ 0.
    pub friction: f64,
    /// Slip speed below which there is no friction, v₀ \[m/s\] (default 0).
    #[serde(default)]
    pub stick_speed: f64,
    /// Slip speed from which full friction acts, v₁ \[m/s\] (default 1e-3).
    #[serde(default = "default_full_speed")]
    pub full_speed: f64,
}

fn default_full_speed() -> f64 {
    1e-3
}

impl ModifiedCoulomb {
    /// Checks μ ≥ 0 and 0 ≤ v₀ < v₁.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        super::require_friction("friction", self.friction)?;
        if !(self.stick_speed >= 0.0
            && self.full_speed > self.stick_speed
            && self.full_speed.is_finite())
        {
            return Err(InvalidParameter::new(
                "full_speed",
                self.full_speed,
                format!("need 0 ≤ stick_speed ({}) < full_speed", self.stick_speed),
            ));
        }
        Ok(())
    }

    /// The dynamic correction factor c_d(|v|).
    #[inline]
    pub fn correction(&self, speed: f64) -> f64 {
        ((speed - self.stick_speed) / (self.full_speed - self.stick_speed)).clamp(0.0, 1.0)
    }
}

impl ModifiedCoulomb {
    /// The friction force for a normal force Q at uniform slip (pockets).
    #[inline]
    pub fn force(&self, normal_load: f64, slip: &Vector3<f64>) -> Vector3<f64> {
        self.shear_stress(normal_load, slip, &ContactConditions::default())
    }
}

impl TractionLaw for ModifiedCoulomb {
    /// g = c_d(|v|) μ p / |v|.
    #[inline]
    fn stress_ratio(
        &self,
        pressure: f64,
        _term: f64,
        speed: f64,
        _conditions: &ContactConditions,
    ) -> f64 {
        if speed <= self.stick_speed || pressure <= 0.0 {
            return 0.0;
        }
        self.correction(speed) * self.friction * pressure / speed
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ramp_and_saturation() {
        let m = ModifiedCoulomb {
            friction: 0.1,
            stick_speed: 1e-4,
            full_speed: 1e-3,
        };
        assert_eq!(
            m.force(100.0, &Vector3::new(5e-5, 0.0, 0.0)),
            Vector3::zeros()
        );
        let half = m.force(100.0, &Vector3::new(5.5e-4, 0.0, 0.0));
        assert!((half.x + 5.0).abs() < 1e-12, "{half:?}");
        let full = m.force(100.0, &Vector3::new(0.0, -2.0, 0.0));
        assert!((full.y - 10.0).abs() < 1e-12);
        assert!(m.validate().is_ok());
        assert!(
            ModifiedCoulomb {
                friction: 0.1,
                stick_speed: 1e-3,
                full_speed: 1e-3
            }
            .validate()
            .is_err()
        );
    }
}
