//! `[life]`: inputs of the modified rating lives (ISO 281 §9.3,
//! ISO/TS 16281) as written.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Rating-life settings (`rolldyn quasistatic`; docs/quasistatic.md).
/// Absent: the basic and reference lives only.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawLife {
    /// Contamination factor e_C in [0, 1] (ISO 281 Table 13: 1 extreme
    /// cleanliness, 0.6–0.5 normal cleanliness, 0.3–0.1 typical
    /// contamination for D_pw < 100 mm). Needed for the modified lives.
    pub contamination_factor: Option<f64>,
    /// Viscosity ratio κ = ν/ν₁ in (0, 100], instead of the one computed
    /// from the lubricant's viscosity and density.
    pub viscosity_ratio: Option<f64>,
}
