//! Tangential (traction) force laws at a ball–raceway or ball–pocket
//! contact (MODEL §3). Each model is a type behind [`TractionLaw`]; the
//! built-in ones are variants of [`TractionModel`], chosen from the case
//! file. This release has the modified Coulomb law of seed 000; the
//! traction curve, EHL rheology and FASTSIM follow (issue 4).

pub mod coulomb;

pub use coulomb::ModifiedCoulomb;
use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

/// A traction law: the tangential force from the normal load and the
/// sliding velocity.
pub trait TractionLaw {
    /// Tangential force on the ball \[N\], opposing `slip` (the tangential
    /// velocity of the ball surface relative to the other body \[m/s\]).
    fn force(&self, normal_load: f64, slip: &Vector3<f64>) -> Vector3<f64>;
}

/// The built-in traction models (case file: `model.traction`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(tag = "law", rename_all = "snake_case", deny_unknown_fields)]
pub enum TractionModel {
    /// No tangential force (frictionless; energy tests).
    #[default]
    None,
    /// Seed 000 eqs 14–15.
    ModifiedCoulomb(ModifiedCoulomb),
}

impl TractionLaw for TractionModel {
    #[inline]
    fn force(&self, normal_load: f64, slip: &Vector3<f64>) -> Vector3<f64> {
        match self {
            Self::None => Vector3::zeros(),
            Self::ModifiedCoulomb(m) => m.force(normal_load, slip),
        }
    }
}
