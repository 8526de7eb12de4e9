//! `[model]`: the contact, traction and lubrication choices of a case
//! (docs/case-format.md).

use crate::units::*;
use rolldyn::contact::normal_law::NormalForceLaw;
use schemars::{JsonSchema, Schema, SchemaGenerator, json_schema};
use serde::de::{self, MapAccess, Visitor};
use serde::{Deserialize, Deserializer, Serialize};
use std::fmt;

/// Model choices.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawModel {
    /// Normal force law: "material" (default: Hunt & Crossley's damping
    /// with the material's factor d = 0.08 s/m), "hertz" (undamped), or a
    /// table `{ law = "lankarani_nikravesh", restitution = 0.9 }`; laws:
    /// material (dissipation in s/m), lankarani_nikravesh, hunt_crossley,
    /// flores (restitution), viscous (damping in N·s/m, or damping_ratio).
    pub normal_law: Option<NormalLawChoice>,
    /// Hertz contact-stiffness model: "exact" (default), "hamrock_brewe",
    /// "hertz_circular" (Shan et al. 2023 eq 12, planar papers only).
    pub contact_stiffness: Option<rolldyn::contact::HertzModel>,
    /// Lower bound v_floor of the recorded impact speed of the hysteresis
    /// laws (default 1 mm/s).
    pub impact_speed_floor: Option<Quantity<Velocity>>,
    /// Raceway control of the Jones–Harris quasi-static model: "outer"
    /// (default), "inner" or "harris" (per ball, by Harris's criterion).
    pub raceway_control: Option<rolldyn::quasistatic::RacewayControl>,
    /// Traction model of the ball–raceway contacts (dynamic engine):
    /// "none" (default), `{ law = "modified_coulomb", friction = 0.1 }`
    /// (optional stick_speed, full_speed), `{ law = "traction_curve", a = -0.06,
    /// b = 8, c = 60, d = 0.06 }` (optional slip, full_speed) or `{ law = "ehl",
    /// eyring_stress = "5 MPa", limiting_shear_coefficient = 0.08 }` (needs the
    /// `[lubricant]` section) or `{ law = "fastsim", friction = 0.1 }`
    /// (optional strips, elements, bound, regularisation_speed) or
    /// `{ law = "exact_table", friction = 0.1 }` (optional
    /// regularisation_speed).
    pub traction: Option<TractionChoice>,
    /// Traction integration: `{ method = "graded", across = 12, along = 6 }`
    /// (default), `{ method = "grid", across = 12, along = 6 }` (uniform
    /// cells) or `{ method = "centre" }`.
    pub traction_integration: Option<rolldyn::traction::TractionIntegration>,
    /// Elastic-hysteresis coefficient α_h of the rolling resistance
    /// (docs/model.md §3; Lei et al. 2023 eq 21: 0.007 for steel). Default 0 (off).
    pub rolling_hysteresis: Option<f64>,
    /// Planar mode (Shan et al. 2023): axial motion and tilts frozen (default false).
    pub planar: Option<bool>,
    /// Gravity along −z (default false).
    pub gravity: Option<bool>,
    /// The bearing's damping between its rings as a time τ: c = τ k_r,
    /// k_r the bearing's radial stiffness at the case's operating point
    /// (stiffness-proportional damping; default none).
    pub bearing_damping: Option<Quantity<Time>>,
    /// Lubricant film in the normal approach (docs/model.md §4): elastic
    /// compression δ + h, the film a state of each contact following its
    /// steady value (default false; needs a traction law with a lubricant).
    pub film_in_approach: Option<bool>,
    /// Mixed lubrication (docs/model.md §3, model 5): boundary friction on the
    /// asperities' share of each contact's load, from Λ = h_min/σ
    /// (Greenwood–Tripp load sharing; needs traction law ehl and the
    /// surfaces' roughness).
    pub mixed_lubrication: Option<RawMixedLubrication>,
}

/// `[model.mixed_lubrication]`.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawMixedLubrication {
    /// Boundary friction coefficient μ_b of the asperity contacts.
    pub boundary_friction: f64,
    /// Roughness parameter σβη (summit density η, summit radius β).
    pub sigma_beta_eta: f64,
    /// Composite roughness over summit radius, σ/β.
    pub sigma_over_beta: f64,
    /// Slip speed from which the boundary friction is full (default 1 mm/s).
    pub full_speed: Option<Quantity<Velocity>>,
}

/// A traction model as written in the case file.
#[derive(Debug, Clone, Serialize, JsonSchema)]
#[serde(untagged)]
pub enum TractionChoice {
    /// "none".
    Named(String),
    /// A law with parameters.
    Table(RawTraction),
}

/// Traction laws with their parameters.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(tag = "law", rename_all = "snake_case", deny_unknown_fields)]
pub enum RawTraction {
    /// No traction.
    None,
    /// Modified Coulomb (Shan et al. 2023 eqs 14–15).
    ModifiedCoulomb {
        /// Friction coefficient μ ≥ 0.
        friction: f64,
        /// Slip speed below which there is no friction v₀ (default 0).
        stick_speed: Option<Quantity<Velocity>>,
        /// Slip speed from which full friction acts v₁ (default 1 mm/s).
        full_speed: Option<Quantity<Velocity>>,
    },
    /// Traction curve μ(S) = (A + B S) e^{−C S} + D (Lei et al. 2023 eq 18).
    TractionCurve {
        /// A.
        a: f64,
        /// B (per unit of S).
        b: f64,
        /// C ≥ 0 (per unit of S).
        c: f64,
        /// D.
        d: f64,
        /// What S is: "slide_to_roll" (default, |Δv|/|u|) or "slip_speed" (m/s).
        slip: Option<rolldyn::traction::SlipMeasure>,
        /// Slip speed of full traction (regularisation; default 1 mm/s).
        full_speed: Option<Quantity<Velocity>>,
    },
    /// EHL rheology (Deng et al. 2022 eqs 13–15; lubricant from the `[lubricant]` section).
    Ehl {
        /// Eyring stress τ₀.
        eyring_stress: Quantity<Pressure>,
        /// Limiting shear-stress coefficient Λ_L.
        limiting_shear_coefficient: f64,
    },
    /// Kalker's FASTSIM (Zhang et al. 2025 §2.2; G and ν from the materials).
    Fastsim {
        /// Friction coefficient μ ≥ 0.
        friction: f64,
        /// Strips across the rolling direction (default 16).
        strips: Option<usize>,
        /// Elements per strip (default 10).
        elements: Option<usize>,
        /// Traction bound: "parabolic" (default, Kalker's) or "elliptic" (Hertz).
        bound: Option<rolldyn::traction::TractionBound>,
        /// Rolling speed below which the creepages are regularised (default 1 mm/s).
        regularisation_speed: Option<Quantity<Velocity>>,
    },
    /// Kalker's exact theory, tabulated (G and ν from the materials).
    ExactTable {
        /// Friction coefficient μ ≥ 0.
        friction: f64,
        /// Rolling speed below which the creepages are regularised (default 1 mm/s).
        regularisation_speed: Option<Quantity<Velocity>>,
    },
}

impl<'de> Deserialize<'de> for TractionChoice {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = TractionChoice;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("\"none\" or a table { law = \"modified_coulomb\" | \"traction_curve\" | \"ehl\" | \"fastsim\" | \"exact_table\", ... }")
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<TractionChoice, E> {
                match v {
                    "none" => Ok(TractionChoice::Named(v.to_string())),
                    "modified_coulomb" | "traction_curve" | "ehl" | "fastsim" | "exact_table" => {
                        Err(E::custom(format!(
                            "the traction law \"{v}\" needs parameters: write a table, e.g. {}",
                            match v {
                                "ehl" =>
                                    "{ law = \"ehl\", eyring_stress = \"5 MPa\", limiting_shear_coefficient = 0.08 }",
                                "traction_curve" =>
                                    "{ law = \"traction_curve\", a = -0.06, b = 8, c = 60, d = 0.06 }",
                                "fastsim" => "{ law = \"fastsim\", friction = 0.1 }",
                                "exact_table" => "{ law = \"exact_table\", friction = 0.1 }",
                                _ => "{ law = \"modified_coulomb\", friction = 0.1 }",
                            }
                        )))
                    }
                    other => Err(E::custom(format!(
                        "unknown traction law \"{other}\"; expected none, modified_coulomb, traction_curve, ehl, fastsim or exact_table"
                    ))),
                }
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<TractionChoice, A::Error> {
                RawTraction::deserialize(de::value::MapAccessDeserializer::new(map))
                    .map(TractionChoice::Table)
            }
        }
        d.deserialize_any(V)
    }
}

/// A normal law given by name ("hertz") or as a table with parameters,
/// e.g. `{ law = "lankarani_nikravesh", restitution = 0.9 }`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(transparent)]
pub struct NormalLawChoice(pub NormalForceLaw);

impl<'de> Deserialize<'de> for NormalLawChoice {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = NormalLawChoice;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a law name or a table { law = \"...\", ... }")
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<NormalLawChoice, E> {
                match v {
                    "hertz" => Ok(NormalLawChoice(NormalForceLaw::Hertz)),
                    "material" => Ok(NormalLawChoice(NormalForceLaw::MATERIAL)),
                    other if NormalForceLaw::NAMES.contains(&other) => Err(E::custom(format!(
                        "the law \"{other}\" needs parameters: write a table, e.g. {{ law = \"{other}\", {} }}",
                        if other == "viscous" {
                            "damping_ratio = 0.1"
                        } else {
                            "restitution = 0.9"
                        }
                    ))),
                    other => Err(E::custom(format!(
                        "unknown normal law \"{other}\"; expected one of {}",
                        NormalForceLaw::NAMES.join(", ")
                    ))),
                }
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<NormalLawChoice, A::Error> {
                NormalForceLaw::deserialize(de::value::MapAccessDeserializer::new(map))
                    .map(NormalLawChoice)
            }
        }
        d.deserialize_any(V)
    }
}

impl JsonSchema for NormalLawChoice {
    fn schema_name() -> std::borrow::Cow<'static, str> {
        "NormalLawChoice".into()
    }
    fn json_schema(g: &mut SchemaGenerator) -> Schema {
        json_schema!({
            "description": "A normal force law (docs/model.md §2.3).",
            "anyOf": [
                { "type": "string", "enum": ["hertz", "material"] },
                g.subschema_for::<NormalForceLaw>(),
            ]
        })
    }
}
