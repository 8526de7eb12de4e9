//! `[shaft]`: several bearings, each a built-in or a catalogue bearing,
//! on one rigid shaft, as written.

use crate::units::*;
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Bearings on one rigid shaft (`rolldyn quasistatic`; docs/systems.md,
/// "General shaft systems"): each bearing a preset or a catalogue
/// bearing at an axial position,
/// the `[operating]` loads at the shaft's reference point x = 0 and more
/// loads at positions. Speed and raceway control from `[operating]` and
/// `[model]`.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawShaft {
    /// The bearings (`[[shaft.bearings]]`), at least one.
    #[serde(default)]
    pub bearings: Vec<RawShaftBearing>,
    /// Forces at axial positions (`[[shaft.loads]]`: gear mesh, unbalance
    /// at rest, a belt pull).
    #[serde(default)]
    pub loads: Vec<RawShaftLoad>,
    /// Outside diameter of a uniform elastic shaft (absent: rigid). With
    /// it the shaft bends between its nodes (Euler–Bernoulli beam) and the
    /// bearings see the misalignment (`rolldyn quasistatic`).
    pub diameter: Option<Quantity<Length>>,
    /// Bore of a hollow elastic shaft (default 0: solid).
    pub bore: Option<Quantity<Length>>,
    /// Young's modulus of the elastic shaft (default 206 GPa, steel).
    pub elastic_modulus: Option<Quantity<Pressure>>,
}

/// Which thrust direction a bearing of a shaft carries.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum RawOrientation {
    /// As built: it carries +x thrust on its inner ring.
    Forward,
    /// Mirrored: it carries −x thrust.
    Reversed,
}

/// How a bearing of a shaft is held axially.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum RawAxial {
    /// Both rings held: it locates the shaft and carries thrust.
    Located,
    /// Its outer ring slides in the housing: no thrust (a deep-groove
    /// bearing as the non-locating one of a fixed–floating pair).
    Floating,
}

/// One bearing on the shaft.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawShaftBearing {
    /// A built-in bearing (`rolldyn presets`): its geometry, materials and
    /// model settings.
    pub preset: Option<String>,
    /// Or a catalogue designation (`rolldyn catalogue`, e.g. "6206"): its
    /// estimated geometry and the generated case's settings
    /// (docs/catalogue.md).
    pub catalogue: Option<String>,
    /// ISO 5753-1 clearance group of a deep-groove catalogue bearing: "C2",
    /// "CN" (default), "C3" or "C4".
    pub clearance_group: Option<String>,
    /// Or the bearing inline (`[shaft.bearings.bearing]`, the keys of
    /// `[bearing]`, which may name a preset or a catalogue bearing and
    /// change its values), with the tables below (default materials and
    /// model settings without them).
    pub bearing: Option<super::RawBearing>,
    /// An inline bearing's materials (`[shaft.bearings.materials]`: the
    /// keys of `[materials]`).
    pub materials: Option<super::RawMaterials>,
    /// An inline bearing's cage (the keys of `[cage]`).
    pub cage: Option<super::RawCage>,
    /// An inline bearing's lubricant (the keys of `[lubricant]`).
    pub lubricant: Option<super::RawLubricant>,
    /// An inline bearing's model settings (the keys of `[model]`).
    pub model: Option<super::RawModel>,
    /// An inline bearing's inner ring (the keys of `[inner_ring]`: in a
    /// run its mass and tilt inertia ride on the shaft).
    pub inner_ring: Option<super::RawInnerRing>,
    /// Axial position of its pitch plane from the shaft's reference point.
    pub position: Quantity<Length>,
    /// "forward" (default: +x thrust on its inner ring) or "reversed".
    pub orientation: Option<RawOrientation>,
    /// "located" (default) or "floating".
    pub axial: Option<RawAxial>,
    /// Friction coefficient of a floating bearing's outer ring in its
    /// housing bore (dynamic runs; default 0.1).
    pub housing_friction: Option<f64>,
    /// Axial offset of its inner ring towards its loaded side at zero
    /// shaft displacement (default 0): the preload displacement of a
    /// bearing set against an opposed one (a ground spacer, a locknut).
    pub preload_offset: Option<Quantity<Length>>,
    /// Its interference fits (`[shaft.bearings.fits]`: the keys of
    /// `[fits]`), applied to its clearance as for a bearing alone.
    pub fits: Option<super::RawFits>,
}

/// A force (and moment) on the shaft at an axial position.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawShaftLoad {
    /// Axial position from the shaft's reference point.
    pub position: Quantity<Length>,
    /// Axial force (default 0).
    pub force_x: Option<Quantity<Force>>,
    /// Force along y (default 0).
    pub force_y: Option<Quantity<Force>>,
    /// Force along z (default 0).
    pub force_z: Option<Quantity<Force>>,
    /// Moment about y there (default 0; a helical gear's axial force off
    /// the axis, a coupling's bending moment).
    pub moment_y: Option<Quantity<Moment>>,
    /// Moment about z there (default 0).
    pub moment_z: Option<Quantity<Moment>>,
    /// A gear mesh's tooth count: the force fluctuates this many times a
    /// shaft revolution (`rolldyn run`; with `mesh_fluctuation`).
    pub mesh_order: Option<f64>,
    /// The fluctuation's amplitude as a fraction of the force, in [0, 1]:
    /// F (1 + ε sin(k θ)) (`rolldyn run`; with `mesh_order`).
    pub mesh_fluctuation: Option<f64>,
}
