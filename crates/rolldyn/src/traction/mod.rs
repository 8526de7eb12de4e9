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
pub mod ehl;
pub mod ellipse;

pub use coulomb::ModifiedCoulomb;
pub use ehl::EhlRheology;
pub use ellipse::{ContactPatch, TractionIntegration, TractionResult};
use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

/// A traction stress law.
pub trait TractionLaw {
    /// Shear stress on the ball \[Pa\] (tangential vector) at Hertz pressure
    /// `pressure` \[Pa\], local `slip` \[m/s\] (tangential) and film thickness
    /// `film` \[m\]; it opposes the slip.
    fn shear_stress(&self, pressure: f64, slip: &Vector3<f64>, film: f64) -> Vector3<f64>;
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
    /// Seed 001 eqs 13–15: Eyring shear with limiting shear stress.
    Ehl(EhlRheology),
}

impl TractionModel {
    /// Whether the model needs the film thickness (and so a lubricant).
    pub fn needs_film(&self) -> bool {
        matches!(self, Self::Ehl(_))
    }
}

impl TractionLaw for TractionModel {
    #[inline]
    fn shear_stress(&self, pressure: f64, slip: &Vector3<f64>, film: f64) -> Vector3<f64> {
        match self {
            Self::None => Vector3::zeros(),
            Self::ModifiedCoulomb(m) => m.shear_stress(pressure, slip, film),
            Self::Ehl(e) => e.shear_stress(pressure, slip, film),
        }
    }
}
