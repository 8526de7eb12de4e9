//! Tangential (traction) stresses at a ball–raceway contact and their
//! integration over the Hertz ellipse (MODEL §3).
//!
//! A traction model is a **stress law** τ(p, slip, h): the shear stress on
//! the ball at a point of the contact with Hertz pressure p, local sliding
//! velocity `slip` (ball material relative to ring material) and film
//! thickness h. [`ellipse`] integrates it over the contact ellipse on the
//! deformed surface, or evaluates it once at the centre. Built-in laws are
//! variants of [`TractionModel`], chosen from the case file; each lives in
//! its own file behind [`TractionLaw`].

pub mod coulomb;
pub mod curve;
pub mod ehl;
pub mod ellipse;

pub use coulomb::ModifiedCoulomb;
pub use curve::{SlipMeasure, TractionCurve};
pub use ehl::EhlRheology;
pub use ellipse::{ContactPatch, TractionIntegration, TractionResult};
use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

/// Contact-level conditions a stress law may need besides the local
/// pressure and slip (one value per contact).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactConditions {
    /// Central film thickness h \[m\] (0 when no film model is active).
    pub film: f64,
    /// Entrainment (rolling) speed |u| at the contact centre \[m/s\] (MODEL §3).
    pub entrainment_speed: f64,
}

/// A traction stress law.
pub trait TractionLaw {
    /// Shear stress on the ball \[Pa\] (tangential vector) at Hertz pressure
    /// `pressure` \[Pa\] and local `slip` \[m/s\] (tangential), under the
    /// contact's `conditions`; it opposes the slip.
    fn shear_stress(
        &self,
        pressure: f64,
        slip: &Vector3<f64>,
        conditions: &ContactConditions,
    ) -> Vector3<f64>;
}

/// The built-in traction models (case file: `model.traction`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
#[serde(tag = "law", rename_all = "snake_case", deny_unknown_fields)]
pub enum TractionModel {
    /// No tangential stress (frictionless; energy tests).
    #[default]
    None,
    /// Seed 000 eqs 14–15: τ = −c_d(|v|) μ p v/|v|.
    ModifiedCoulomb(ModifiedCoulomb),
    /// Seed 004 eq 18: μ(S) = (A + B S) e^{−C S} + D.
    TractionCurve(TractionCurve),
    /// Seed 001 eqs 13–15: Eyring shear with limiting shear stress.
    Ehl(EhlRheology),
}

impl TractionModel {
    /// Whether the model needs the film thickness (and so a lubricant).
    pub fn needs_film(&self) -> bool {
        matches!(self, Self::Ehl(_))
    }

    /// Whether the stress law uses the entrainment speed.
    pub fn needs_entrainment(&self) -> bool {
        matches!(self, Self::Ehl(_) | Self::TractionCurve(_))
    }

    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), crate::InvalidParameter> {
        match self {
            Self::None => Ok(()),
            Self::ModifiedCoulomb(m) => m.validate(),
            Self::TractionCurve(c) => c.validate(),
            Self::Ehl(e) => e.validate(),
        }
    }
}

impl TractionLaw for TractionModel {
    #[inline]
    fn shear_stress(
        &self,
        pressure: f64,
        slip: &Vector3<f64>,
        conditions: &ContactConditions,
    ) -> Vector3<f64> {
        match self {
            Self::None => Vector3::zeros(),
            Self::ModifiedCoulomb(m) => m.shear_stress(pressure, slip, conditions),
            Self::TractionCurve(c) => c.shear_stress(pressure, slip, conditions),
            Self::Ehl(e) => e.shear_stress(pressure, slip, conditions),
        }
    }
}
