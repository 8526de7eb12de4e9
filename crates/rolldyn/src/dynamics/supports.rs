//! Spring–damper supports of the rings (Zhang et al. 2025 eqs 14–15).

use crate::error::{InvalidParameter, require_non_negative};
use nalgebra::Vector3;

/// A spring–damper between a ring and ground, per axis (x, y, z).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Support {
    /// Stiffness per axis \[N/m\].
    pub stiffness: [f64; 3],
    /// Damping per axis \[N·s/m\].
    pub damping: [f64; 3],
}

impl Support {
    /// Force on the ring for displacement `x` and velocity `v` (its
    /// negative is what the support carries: the housing force).
    pub fn force(&self, x: &Vector3<f64>, v: &Vector3<f64>) -> Vector3<f64> {
        -Vector3::from(self.stiffness).component_mul(x)
            - Vector3::from(self.damping).component_mul(v)
    }

    /// Elastic energy ½ Σ k x².
    pub(super) fn energy(&self, x: &Vector3<f64>) -> f64 {
        0.5 * Vector3::from(self.stiffness).dot(&x.component_mul(x))
    }

    /// Dissipated power Σ c v².
    pub(super) fn dissipation(&self, v: &Vector3<f64>) -> f64 {
        Vector3::from(self.damping).dot(&v.component_mul(v))
    }

    pub(super) fn validate(&self, field: &'static str) -> Result<(), InvalidParameter> {
        for v in self.stiffness.iter().chain(&self.damping) {
            require_non_negative(field, *v)?;
        }
        Ok(())
    }
}

/// Sliding speed below which a sliding outer ring's friction is
/// proportional to its speed (the regularized Coulomb law's stick speed)
/// \[m/s\].
pub const STICK_SPEED: f64 = 1e-3;

/// An outer ring that slides axially in its housing bore (a floating
/// bearing's), against Coulomb friction μ N with N the radial load it puts
/// on the bore, regularized below [`STICK_SPEED`]:
/// F = −μ N ẋ / √(ẋ² + v_s²).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlidingRing {
    /// Mass of the ring (with what slides with it) \[kg\].
    pub mass: f64,
    /// Friction coefficient μ of the ring in its bore.
    pub friction: f64,
}

impl SlidingRing {
    /// The bore's axial friction force on the ring at sliding speed
    /// `speed` under radial load `radial` \[N\].
    pub fn friction_force(&self, speed: f64, radial: f64) -> f64 {
        -self.friction * radial * speed / speed.hypot(STICK_SPEED)
    }

    pub(super) fn validate(&self) -> Result<(), InvalidParameter> {
        crate::error::require_positive("sliding_ring_mass", self.mass)?;
        require_non_negative("housing_friction", self.friction)
    }
}

/// The outer ring on a housing spring–damper (Zhang et al. 2025 eqs 14–15): radial
/// translation (y_o, z_o) only.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OuterRing {
    /// Mass of the outer ring (with what moves with it) \[kg\].
    pub mass: f64,
    /// Radial housing stiffness and damping (the x entries are unused).
    pub housing: Support,
}
