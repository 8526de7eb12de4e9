//! `[arrangement]`: a matched set of the case's bearing on one shaft.

use crate::units::*;
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// How the bearings of a matched set are mounted.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum ArrangementKind {
    /// One bearing (the default without `[arrangement]`).
    Single,
    /// A pair, pressure-cone apexes outward ("O", DB): stiff against tilt.
    BackToBack,
    /// A pair, apexes inward ("X", DF): tolerant of misalignment.
    FaceToFace,
    /// A pair sharing one thrust direction (DT); no preload by itself.
    Tandem,
    /// Three bearings, a tandem pair on the −x side and one opposed on
    /// the +x side, apexes outward (TBT): the +x thrust shared by two.
    TandemBackToBack,
    /// Three bearings, a tandem pair on the +x side and one opposed on
    /// the −x side, apexes inward (TFT).
    TandemFaceToFace,
}

/// A matched set of the case's bearing on one rigid shaft
/// (`rolldyn quasistatic`; docs/systems.md). The shaft loads of
/// `[operating]` act at the middle between the bearings.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawArrangement {
    /// The arrangement.
    pub kind: ArrangementKind,
    /// Preload: the axial force through the set at rest without external
    /// load, which each bearing of a pair carries (a triple's single
    /// bearing carries it, each of its tandem pair half); a rigid,
    /// position preload: it changes with speed. Opposed sets only.
    pub preload: Option<Quantity<Force>>,
    /// Or the preload as the axial offset of each bearing's inner ring
    /// towards its loaded side (e.g. "5 um": the spacer difference shared
    /// between the two). Opposed sets only.
    pub preload_displacement: Option<Quantity<Length>>,
    /// Distance between neighbouring bearings' pitch planes (default: the
    /// bearing width, i.e. the rings side by side).
    pub spacing: Option<Quantity<Length>>,
    /// A rotating unbalance on the shaft, mass × radius (e.g. "50 g.mm"):
    /// its force m_u e ω² turns with the shaft in `rolldyn run` (the
    /// quasi-static solution does not see it).
    pub unbalance: Option<Quantity<Unbalance>>,
    /// Where the unbalance sits, from the middle between the bearings
    /// along the shaft's +x (default 0).
    pub unbalance_position: Option<Quantity<Length>>,
}
