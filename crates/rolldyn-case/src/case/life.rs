//! `[life]` in SI, and the conditions of the modified rating lives built
//! from the whole case (lubricant, materials).

use super::{Case, Invalid, positive_number};
use crate::raw::RawLife;
use rolldyn::life::LifeConditions;

/// `[life]`, checked.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Life {
    /// Contamination factor e_C, if given.
    pub contamination_factor: Option<f64>,
    /// Viscosity ratio κ, if given.
    pub viscosity_ratio: Option<f64>,
}

/// Largest viscosity ratio accepted (the formulas hold it at 4).
pub const MAX_VISCOSITY_RATIO: f64 = 100.0;

pub(super) fn life(raw: &RawLife) -> Result<Life, Invalid> {
    Ok(Life {
        contamination_factor: positive_number(
            "life.contamination_factor",
            raw.contamination_factor,
            |v| (0.0..=1.0).contains(&v),
            "must lie in [0, 1] (ISO 281 Table 13)",
        )?,
        viscosity_ratio: positive_number(
            "life.viscosity_ratio",
            raw.viscosity_ratio,
            |v| v > 0.0 && v <= MAX_VISCOSITY_RATIO,
            "must lie in (0, 100]",
        )?,
    })
}

impl Case {
    /// Conditions of the modified lives: e_C and κ from `[life]`, the
    /// operating kinematic viscosity ν = η/ρ of the lubricant (density
    /// default [`super::DEFAULT_OIL`]), and whether the bearing is hybrid
    /// (the balls' Young's modulus more than 10 % from the rings').
    pub fn life_conditions(&self) -> LifeConditions {
        let (density, _, _) = self.oil_properties();
        let (ball, rings) = (
            self.materials.ball.material.elastic_modulus,
            self.materials.rings.material.elastic_modulus,
        );
        LifeConditions {
            contamination_factor: self.life.contamination_factor,
            kinematic_viscosity: self.lubricant.as_ref().map(|l| l.viscosity / density),
            viscosity_ratio: self.life.viscosity_ratio,
            hybrid: (ball / rings - 1.0).abs() > 0.1,
        }
    }
}
