//! `[surface]`: raceway and ball waviness and spalls (docs/model.md §6) as written.

use crate::units::*;
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Surface profiles of the raceways and balls (dynamic engine). Absent:
/// perfectly smooth surfaces.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawSurface {
    /// Inner raceway (angles in the ring's own frame: it carries its
    /// surface round with it).
    pub inner: Option<RawRaceSurface>,
    /// Outer raceway (angles from +y towards +z).
    pub outer: Option<RawRaceSurface>,
    /// Balls.
    pub balls: Option<RawBallSurfaces>,
}

/// One raceway's surface.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawRaceSurface {
    /// Radial waviness terms q cos(l θ + η), towards the balls positive
    /// (Deng et al. 2022 eq 1).
    #[serde(default)]
    pub radial_waviness: Vec<RawWavinessTerm>,
    /// Axial waviness terms (groove displaced along +x).
    #[serde(default)]
    pub axial_waviness: Vec<RawWavinessTerm>,
    /// Random radial waviness, added to the terms.
    pub random_radial_waviness: Option<RawRandomWaviness>,
    /// Random axial waviness, added to the terms.
    pub random_axial_waviness: Option<RawRandomWaviness>,
    /// Spalls (`[[surface.outer.spall]]`).
    #[serde(default)]
    pub spall: Vec<RawSpall>,
    /// RMS roughness R_q of the raceway (film parameter Λ).
    pub roughness: Option<Quantity<Length>>,
}

/// Surfaces of the balls.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawBallSurfaces {
    /// Indices of the balls (0-based, ball 0 at +y at the start) that carry
    /// `waviness` and `random_waviness`; default: every ball.
    pub balls: Option<Vec<i64>>,
    /// Waviness terms H(ψ) = Σ w cos(l ψ + η) in the ball's spin angle.
    #[serde(default)]
    pub waviness: Vec<RawWavinessTerm>,
    /// Random ball waviness (each ball draws its own phases from the seed).
    pub random_waviness: Option<RawRandomWaviness>,
    /// Spalls, each on the ball named by its `ball` key.
    #[serde(default)]
    pub spall: Vec<RawSpall>,
    /// RMS roughness R_q of the balls (film parameter Λ).
    pub roughness: Option<Quantity<Length>>,
}

/// One waviness harmonic.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawWavinessTerm {
    /// Order l (waves per circumference), 1 … 10 000.
    pub order: i64,
    /// Amplitude q (≥ 0), e.g. "0.3 um".
    pub amplitude: Quantity<Length>,
    /// Phase η (default 0).
    pub phase: Option<Quantity<Angle>>,
}

/// Random waviness: orders min_order … max_order, amplitude
/// q_l = amplitude (min_order / l)^exponent, phases uniform from `seed`.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawRandomWaviness {
    /// Lowest order (≥ 1).
    pub min_order: i64,
    /// Highest order (≥ min_order, ≤ 10 000).
    pub max_order: i64,
    /// Amplitude at the lowest order.
    pub amplitude: Quantity<Length>,
    /// Exponent of the amplitude decay with order (default 1).
    pub exponent: Option<f64>,
    /// Seed of the phases (default 0).
    pub seed: Option<u64>,
}

/// Edge shape of a spall.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum RawEdge {
    /// A sharp step (the ball bridges it).
    Sharp,
    /// A linear ramp of length `ramp`.
    Ramped,
}

/// A spall (localised defect).
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawSpall {
    /// Angle of the spall centre: on a raceway in the ring's frame from +y
    /// towards +z; on a ball in its spin angle ψ.
    pub position: Quantity<Angle>,
    /// Angular width along the track (give `width` or `length`).
    pub width: Option<Quantity<Angle>>,
    /// Length along the track (give `width` or `length`).
    pub length: Option<Quantity<Length>>,
    /// Depth.
    pub depth: Quantity<Length>,
    /// Centre of the axial band from the groove's mid-plane (raceways; default 0).
    pub axial_position: Option<Quantity<Length>>,
    /// Width of the axial band (raceways; default: the whole groove).
    pub axial_width: Option<Quantity<Length>>,
    /// Edge shape: "sharp" (default) or "ramped".
    pub edge: Option<RawEdge>,
    /// Ramp length of a "ramped" edge.
    pub ramp: Option<Quantity<Length>>,
    /// Ball index (ball spalls only).
    pub ball: Option<i64>,
    /// Growth of the length along the track per second of simulated time
    /// (default 0: constant; needs `length`): a run-to-failure trend.
    pub growth_rate: Option<Quantity<Velocity>>,
}
