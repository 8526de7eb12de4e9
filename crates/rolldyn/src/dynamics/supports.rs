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

/// The outer ring on a housing spring–damper (Zhang et al. 2025 eqs 14–15): radial
/// translation (y_o, z_o) only.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OuterRing {
    /// Mass of the outer ring (with what moves with it) \[kg\].
    pub mass: f64,
    /// Radial housing stiffness and damping (the x entries are unused).
    pub housing: Support,
}
