//! `[fits]`: the interference fits of the rings on the shaft and in the
//! housing, as written.

use crate::units::*;
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Interference fits (docs/quasistatic.md, "Fits"): the inner ring pressed
/// on its shaft grows, the outer ring pressed into its housing shrinks,
/// and the bearing's clearance falls by both (thick-walled cylinders of
/// the rings' material; Harris & Kotzalas 2006). Needs `bearing.bore`,
/// `bearing.outside_diameter` and a diametral clearance or raceway
/// diameters.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawFits {
    /// Effective diametral interference of the inner ring on the shaft
    /// (≥ 0; default 0: a loose or transition fit).
    pub shaft_interference: Option<Quantity<Length>>,
    /// Or the shaft's ISO 286 tolerance class (e.g. "k5", "m6"): the
    /// probable interference on a ring of ISO 492 normal class.
    pub shaft_tolerance: Option<String>,
    /// Bore of a hollow shaft (default 0: solid).
    pub shaft_bore: Option<Quantity<Length>>,
    /// Effective diametral interference of the outer ring in the housing
    /// (≥ 0; default 0).
    pub housing_interference: Option<Quantity<Length>>,
    /// Or the housing's ISO 286 tolerance class (e.g. "H7", "M7").
    pub housing_tolerance: Option<String>,
    /// Outside diameter of the housing around the ring (default: a housing
    /// much larger than the ring).
    pub housing_outside_diameter: Option<Quantity<Length>>,
}
