//! The case file as written: TOML structure, key names, units. Everything
//! here is syntax; [`crate::case`] turns it into a checked
//! [`crate::Case`] in SI units. Unknown keys are errors (typos!).
//!
//! The doc comments of these types are the reference of the case format:
//! `rolldyn schema` exports them as a JSON Schema and `docs/case-format.md`
//! lists them with units and defaults.

use crate::units::*;
use schemars::{JsonSchema, Schema, SchemaGenerator, json_schema};
use serde::de::{self, MapAccess, Visitor};
use serde::{Deserialize, Deserializer, Serialize};
use std::collections::BTreeMap;
use std::fmt;

mod arrangement;
mod fits;
mod life;
mod model;
mod sensor;
mod shaft;
mod surface;
mod thermal;
pub use arrangement::*;
pub use fits::*;
pub use life::*;
pub use model::*;
pub use sensor::*;
pub use shaft::*;
pub use surface::*;
pub use thermal::*;

/// A rolldyn case file.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawCase {
    /// Free-text title of the case.
    pub title: Option<String>,
    /// Bearing internal geometry (a preset, or the full geometry).
    #[serde(default)]
    pub bearing: RawBearing,
    /// Cage geometry and inertia (used by the dynamic engine).
    #[serde(default)]
    pub cage: RawCage,
    /// Inner ring (with what turns with it) for the dynamic engine.
    #[serde(default)]
    pub inner_ring: RawInnerRing,
    /// Outer ring on a housing spring–damper (dynamic engine; absent: fixed).
    pub outer_ring: Option<RawOuterRing>,
    /// Drag of the air–oil mixture on balls and cage (dynamic engine).
    #[serde(default)]
    pub drag: RawDrag,
    /// Friction of contact seals (dynamic engine; absent: an open bearing).
    pub seals: Option<RawSeals>,
    /// An accelerometer on the housing and its acquisition (dynamic
    /// engine; absent: no sensor channels).
    pub sensor: Option<RawSensor>,
    /// Materials of balls and rings.
    #[serde(default)]
    pub materials: RawMaterials,
    /// Lubricant properties (used by EHL traction, films and thermal models).
    pub lubricant: Option<RawLubricant>,
    /// How the bearing is lubricated: method, oil level, the contacts'
    /// EHL rolling resistance (absent: no method, rolling resistance on
    /// with a lubricant).
    pub lubrication: Option<RawLubrication>,
    /// Speeds and loads.
    #[serde(default)]
    pub operating: RawOperating,
    /// Model choices.
    #[serde(default)]
    pub model: RawModel,
    /// Raceway and ball waviness and spalls (dynamic engine).
    #[serde(default)]
    pub surface: RawSurface,
    /// Friction power loss by Harris's local method (`rolldyn power`).
    #[serde(default)]
    pub power: RawPower,
    /// Thermal network (`rolldyn thermal`).
    #[serde(default)]
    pub thermal: RawThermal,
    /// Rating-life settings (`rolldyn quasistatic`).
    #[serde(default)]
    pub life: RawLife,
    /// A matched set of the bearing on one shaft (absent: one bearing).
    pub arrangement: Option<RawArrangement>,
    /// Several built-in bearings on one rigid shaft (absent: one bearing).
    pub shaft: Option<RawShaft>,
    /// Interference fits on the shaft and in the housing (absent: the
    /// clearance as given).
    pub fits: Option<RawFits>,
    /// Time-integration settings (used by `rolldyn run`).
    #[serde(default)]
    pub solver: RawSolver,
    /// Output settings (used by `rolldyn run`).
    #[serde(default)]
    pub output: RawOutput,
    /// Values that were assumed rather than taken from a source, by dotted
    /// key, with the reason: `"bearing.inner_groove_curvature" = "not given
    /// in the paper; Harris's typical value"`. `rolldyn check` lists them.
    #[serde(default)]
    pub assumptions: BTreeMap<String, String>,
}

/// Bearing geometry. Give a `preset`, or D, Z, the groove curvatures and
/// exactly one clearance parametrization: (a) `free_contact_angle` with
/// `pitch_diameter`, (b) `diametral_clearance` with `pitch_diameter`, or
/// (c) `inner_raceway_diameter` + `outer_raceway_diameter` (pitch diameter
/// derived). Keys given next to a preset override the preset's values.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawBearing {
    /// Name of a built-in bearing (`rolldyn presets` lists them).
    pub preset: Option<String>,
    /// A catalogue designation instead (`rolldyn catalogue` lists them,
    /// e.g. "6205", "7210B"): its estimated geometry and cage
    /// (docs/catalogue.md).
    pub catalogue: Option<String>,
    /// ISO 5753-1 clearance group of a deep-groove catalogue bearing: "C2",
    /// "CN" (default), "C3" or "C4".
    pub clearance_group: Option<String>,
    /// Designation, free text (e.g. "7008C").
    pub designation: Option<String>,
    /// Ball diameter D.
    pub ball_diameter: Option<Quantity<Length>>,
    /// Number of balls Z (3 ≤ Z ≤ 1000).
    pub ball_count: Option<i64>,
    /// Pitch diameter d_m (parametrizations a and b).
    pub pitch_diameter: Option<Quantity<Length>>,
    /// Inner groove curvature factor f_i = r_i/D, in (0.5, 1).
    pub inner_groove_curvature: Option<f64>,
    /// Outer groove curvature factor f_o = r_o/D, in (0.5, 1).
    pub outer_groove_curvature: Option<f64>,
    /// Inner groove radius r_i (alternative to `inner_groove_curvature`).
    pub inner_groove_radius: Option<Quantity<Length>>,
    /// Outer groove radius r_o (alternative to `outer_groove_curvature`).
    pub outer_groove_radius: Option<Quantity<Length>>,
    /// (a) Free (initial) contact angle α₀, in [0°, 60°].
    pub free_contact_angle: Option<Quantity<Angle>>,
    /// (b) Diametral clearance P_d (negative only with `preload = true`).
    pub diametral_clearance: Option<Quantity<Length>>,
    /// (c) Inner raceway (groove-bottom) diameter d_i.
    pub inner_raceway_diameter: Option<Quantity<Length>>,
    /// (c) Outer raceway (groove-bottom) diameter d_o.
    pub outer_raceway_diameter: Option<Quantity<Length>>,
    /// Allow a negative clearance (interference, preloaded set). Default false.
    pub preload: Option<bool>,
    /// Bore diameter d (boundary dimension, informational).
    pub bore: Option<Quantity<Length>>,
    /// Outside diameter (boundary dimension, informational).
    pub outside_diameter: Option<Quantity<Length>>,
    /// Ring width (boundary dimension, informational).
    pub width: Option<Quantity<Length>>,
}

/// Cage data (docs/model.md §5). All optional until the dynamic engine needs them.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawCage {
    /// How the cage is guided: "outer_ring", "inner_ring" or "ball".
    pub guidance: Option<CageGuidance>,
    /// Pocket clearance C_p (diametral, ball to pocket).
    pub pocket_clearance: Option<Quantity<Length>>,
    /// Cage bore (small) diameter.
    pub inner_diameter: Option<Quantity<Length>>,
    /// Cage outside (large) diameter.
    pub outer_diameter: Option<Quantity<Length>>,
    /// Guide-land width G.
    pub guide_land_width: Option<Quantity<Length>>,
    /// Guide clearance C_g (diametral, cage to guiding land).
    pub guide_clearance: Option<Quantity<Length>>,
    /// Cage mass.
    pub mass: Option<Quantity<Mass>>,
    /// Cage polar moment of inertia about the bearing axis.
    pub inertia: Option<Quantity<Inertia>>,
    /// Pocket shape: "cylindrical" (default; no radial guidance by the
    /// balls) or "spherical".
    pub pocket_shape: Option<rolldyn::cage::PocketShape>,
    /// Ball–pocket normal force law: "linear" (default; Zhang et al. 2025 eq 6),
    /// "hertz" (Deng et al. 2022 eq 29; K_bc from the ball and pocket curvatures and
    /// `cage.material`) or "gupta_film" (Deng et al. 2022 eqs 26–28).
    pub pocket_law: Option<PocketLawChoice>,
    /// Ball–pocket contact stiffness k (linear law, Zhang et al. 2025 eq 6).
    pub pocket_stiffness: Option<Quantity<Stiffness>>,
    /// Ball–pocket contact damping c.
    pub pocket_damping: Option<Quantity<Damping>>,
    /// Film force at the pocket wall F_w of the gupta_film law (default
    /// 11 N, Deng et al. 2022 eq 28).
    pub pocket_wall_force: Option<Quantity<Force>>,
    /// Squeeze-film damping of the pocket oil film (default false; needs
    /// `[lubricant]`; a rolldyn extension, docs/dynamics.md).
    pub pocket_squeeze_film: Option<bool>,
    /// Least oil film in the pocket for the squeeze damping (default
    /// 1 µm, of the order of the pocket's composite roughness).
    pub pocket_min_film: Option<Quantity<Length>>,
    /// Which side of the pocket film carries pressure in the squeeze
    /// damping: "vapour" (default; the opened side's suction held down
    /// to the tension), "half_sommerfeld" (the opened side cavitates) or
    /// "full_film".
    pub pocket_squeeze_cavitation: Option<rolldyn::cage::SqueezeCavitation>,
    /// Largest suction the pocket film holds with "vapour" cavitation:
    /// ambient less the oil's vapour pressure (default 101.325 kPa).
    pub pocket_squeeze_tension: Option<Quantity<Pressure>>,
    /// Cage material (needed by the hertz and gupta_film pocket laws).
    pub material: Option<MaterialChoice>,
    /// Unbalance m_u e of the cage (mass × radius), at the cage angle.
    pub unbalance: Option<Quantity<Unbalance>>,
    /// Ball–pocket friction coefficient μ_p (default 0.05).
    pub pocket_friction: Option<f64>,
    /// Whether the cage centre may whirl (default true; false: rotation only).
    pub whirl: Option<bool>,
}

/// Drag of the air–oil mixture (Deng et al. 2022 eqs 10–12, 24, 36, corrected;
/// docs/dynamics.md). All off by default.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawDrag {
    /// Effective density of the air–oil mixture ρ_e.
    pub effective_density: Option<Quantity<Density>>,
    /// Ball drag coefficient C_D (orbital motion).
    pub ball_drag_coefficient: Option<f64>,
    /// Ball spin drag coefficient C_n.
    pub ball_spin_drag_coefficient: Option<f64>,
    /// Cage viscous drag c₁ (torque per angular speed).
    pub cage_viscous: Option<Quantity<RotationalDamping>>,
    /// Cage windage drag c₂ (torque per squared angular speed).
    pub cage_windage: Option<Quantity<WindageCoefficient>>,
}

/// The lubrication method.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Method {
    /// Not stated: no churning (what a case without `[lubrication]` gets).
    #[default]
    None,
    /// An oil bath (give `lubrication.oil_level`).
    OilBath,
    /// An oil jet.
    OilJet,
    /// Air–oil (oil–air) or oil mist.
    AirOil,
    /// Grease, after its run-in.
    Grease,
}

/// How the bearing is lubricated (docs/lubrication.md, "Lubrication method
/// and churning", "Rolling resistance").
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawLubrication {
    /// "none" (default: no churning), "oil_bath", "oil_jet", "air_oil",
    /// "grease".
    pub method: Option<Method>,
    /// An oil bath's level above the lowest point of the outer ring's
    /// raceway (SKF's H).
    pub oil_level: Option<Quantity<Length>>,
    /// EHL rolling resistance of the lubricated contacts:
    /// "houpert" (default with a `[lubricant]`), "biboulet_houpert" or
    /// "none".
    pub rolling_resistance: Option<RollingResistanceChoice>,
    /// Aihara's inlet-heating reduction of the rolling resistance (default
    /// true).
    pub inlet_heating: Option<bool>,
}

/// The EHL rolling-resistance law.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum RollingResistanceChoice {
    /// Houpert's fits (Biboulet & Houpert 2010, Part 2 eqs 28–29) with
    /// inlet heating and starvation.
    Houpert,
    /// Biboulet & Houpert 2010 eq 32 (fully flooded), the same reductions.
    BibouletHoupert,
    /// None.
    None,
}

/// Contact seals rubbing on the inner ring (docs/dynamics.md, "Seals").
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawSeals {
    /// Friction moment of all the bearing's seals together (both sides).
    pub friction_torque: Option<Quantity<Moment>>,
    /// Speed through which the moment turns with the rotation (default 1 rpm).
    pub transition_speed: Option<Quantity<AngularSpeed>>,
}

/// The inner ring as the dynamic engine sees it (ring plus shaft).
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawInnerRing {
    /// Mass of everything that moves with the inner ring. Default: the
    /// ring alone, from bore, raceway diameter, width and ring density.
    pub mass: Option<Quantity<Mass>>,
    /// Transverse (tilt) moment of inertia. Default: that of the ring annulus.
    pub tilt_inertia: Option<Quantity<Inertia>>,
    /// Radial (y, z) stiffness of a support between ring and ground (Zhang et al. 2025
    /// eqs 11–13; default 0: free).
    pub support_radial_stiffness: Option<Quantity<Stiffness>>,
    /// Axial (x) support stiffness (default 0).
    pub support_axial_stiffness: Option<Quantity<Stiffness>>,
    /// Radial support damping (default 0).
    pub support_radial_damping: Option<Quantity<Damping>>,
    /// Axial support damping (default 0).
    pub support_axial_damping: Option<Quantity<Damping>>,
}

/// The outer ring on a housing spring–damper (Zhang et al. 2025 eqs 14–15): radial
/// translation (y_o, z_o).
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawOuterRing {
    /// Mass of the outer ring (with what moves with it).
    pub mass: Quantity<Mass>,
    /// Radial housing stiffness.
    pub housing_stiffness: Quantity<Stiffness>,
    /// Radial housing damping (default 0).
    pub housing_damping: Option<Quantity<Damping>>,
}

/// Ball–pocket normal force law (docs/model.md §5).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum PocketLawChoice {
    /// k δ + c δ̇ beyond the clearance (Zhang et al. 2025 eq 6).
    Linear,
    /// K_bc δ^{3/2} + c δ̇ beyond the clearance (Deng et al. 2022 eq 29).
    Hertz,
    /// F_w d/c inside the clearance, F_w + Hertz beyond (Deng et al. 2022 eqs 26–28).
    GuptaFilm,
}

/// Cage guidance.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum CageGuidance {
    /// Guided on a land of the outer ring.
    OuterRing,
    /// Guided on a land of the inner ring.
    InnerRing,
    /// Guided by the balls.
    Ball,
}

/// Materials: a preset name ("steel_52100", "silicon_nitride") or a table.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawMaterials {
    /// Ball material. Default: the preset's, else steel_52100.
    pub ball: Option<MaterialChoice>,
    /// Ring material (inner and outer). Default: the preset's, else steel_52100.
    pub rings: Option<MaterialChoice>,
}

/// A material given by name or by its properties.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum MaterialChoice {
    /// A built-in material: "steel_52100" or "silicon_nitride".
    Named(String),
    /// Explicit properties.
    Custom(RawMaterial),
}

/// Explicit material properties.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawMaterial {
    /// Name for reports.
    pub name: Option<String>,
    /// Young's modulus E.
    pub elastic_modulus: Quantity<Pressure>,
    /// Poisson's ratio ν, in (−1, 0.5).
    pub poisson_ratio: f64,
    /// Density ρ.
    pub density: Quantity<Density>,
}

/// Accepts a material name or a table while keeping the table's own error
/// messages (serde's untagged enums would replace them with "did not match
/// any variant").
impl<'de> Deserialize<'de> for MaterialChoice {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = MaterialChoice;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a material name (\"steel_52100\", \"silicon_nitride\") or a table with elastic_modulus, poisson_ratio, density")
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<MaterialChoice, E> {
                Ok(MaterialChoice::Named(v.to_string()))
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<MaterialChoice, A::Error> {
                RawMaterial::deserialize(de::value::MapAccessDeserializer::new(map))
                    .map(MaterialChoice::Custom)
            }
        }
        d.deserialize_any(V)
    }
}

impl JsonSchema for MaterialChoice {
    fn schema_name() -> std::borrow::Cow<'static, str> {
        "MaterialChoice".into()
    }
    fn json_schema(g: &mut SchemaGenerator) -> Schema {
        json_schema!({
            "description": "A built-in material name or explicit properties.",
            "anyOf": [
                { "type": "string", "enum": ["steel_52100", "silicon_nitride"] },
                g.subschema_for::<RawMaterial>(),
            ]
        })
    }
}

/// Lubricant properties at the reference temperature.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawLubricant {
    /// Name for reports.
    pub name: Option<String>,
    /// Dynamic viscosity η₀ at atmospheric pressure and `temperature`.
    pub viscosity: Quantity<Viscosity>,
    /// Pressure–viscosity coefficient α_p (Barus).
    pub pressure_viscosity: Quantity<PressureViscosity>,
    /// Density.
    pub density: Option<Quantity<Density>>,
    /// Thermal conductivity.
    pub thermal_conductivity: Option<Quantity<ThermalConductivity>>,
    /// Specific heat capacity.
    pub specific_heat: Option<Quantity<SpecificHeat>>,
    /// Temperature at which `viscosity` holds.
    pub temperature: Option<Quantity<Temperature>>,
    /// Pressure–viscosity law of the EHL traction: "barus" (default) or
    /// "roelands".
    pub pressure_viscosity_model: Option<rolldyn::lubrication::PressureViscosity>,
    /// Starvation: inlet distance ratio L = X_b/b of both rings' contacts
    /// (> 1; absent: fully flooded; Zhang et al. 2020 eqs 28–30).
    pub inlet_distance_ratio: Option<f64>,
    /// Inlet distance ratio of the inner-raceway contacts only.
    pub inlet_distance_ratio_inner: Option<f64>,
    /// Inlet distance ratio of the outer-raceway contacts only.
    pub inlet_distance_ratio_outer: Option<f64>,
    /// Starvation from an oil supply flow Q_v instead (Zhang et al. 2020 eqs 26–27;
    /// needs `density`).
    pub oil_flow: Option<Quantity<VolumeFlow>>,
    /// A second viscosity point for the viscosity–temperature law (Walther,
    /// ASTM D341; with `temperature` and `density`): its dynamic viscosity…
    pub second_viscosity: Option<Quantity<Viscosity>>,
    /// … and its temperature.
    pub second_temperature: Option<Quantity<Temperature>>,
}

/// Operating conditions: inner-ring speed and loads on the inner ring
/// (frame: x along the bearing axis, y and z radial).
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawOperating {
    /// Constant inner-ring speed.
    pub speed: Option<Quantity<AngularSpeed>>,
    /// Piecewise-linear inner-ring speed table (alternative to `speed`):
    /// `[{ time = "0 s", speed = "1000 rpm" }, ...]`, times increasing.
    pub speed_profile: Option<Vec<RawSpeedPoint>>,
    /// Axial force F_x on the inner ring (positive loads the balls).
    pub force_x: Option<Quantity<Force>>,
    /// Radial force F_y on the inner ring.
    pub force_y: Option<Quantity<Force>>,
    /// Radial force F_z on the inner ring.
    pub force_z: Option<Quantity<Force>>,
    /// Moment M_y on the inner ring.
    pub moment_y: Option<Quantity<Moment>>,
    /// Moment M_z on the inner ring.
    pub moment_z: Option<Quantity<Moment>>,
    /// Radial load by magnitude (instead of `force_y`, `force_z`)…
    pub radial_load: Option<Quantity<Force>>,
    /// … and direction in the radial plane, from +y towards +z (default
    /// 90°: along +z, as `--radial-load`).
    pub radial_load_angle: Option<Quantity<Angle>>,
    /// Azimuth of ball 0 from +y towards +z (default 0; quasi-static solves
    /// and the Jones–Harris start of a run).
    pub first_ball_azimuth: Option<Quantity<Angle>>,
    /// Hold the inner ring's tilts at zero (quasi-static; the moments that
    /// hold them are reported).
    pub fixed_tilt: Option<bool>,
    /// Prescribed tilt θ_y of the inner ring (a misalignment; quasi-static),
    /// instead of `moment_y`.
    pub tilt_y: Option<Quantity<Angle>>,
    /// Prescribed tilt θ_z, instead of `moment_z`.
    pub tilt_z: Option<Quantity<Angle>>,
    /// Prescribed axial displacement x, instead of `force_x` (quasi-static).
    pub displacement_x: Option<Quantity<Length>>,
    /// Prescribed radial displacement y, instead of `force_y`.
    pub displacement_y: Option<Quantity<Length>>,
    /// Prescribed radial displacement z, instead of `force_z`.
    pub displacement_z: Option<Quantity<Length>>,
    /// Piecewise-linear load table (alternative to the constant loads;
    /// dynamic runs): `[{ time = "0 s", force_x = "200 N" }, ...]`, times
    /// increasing, missing components 0.
    pub load_profile: Option<Vec<RawLoadPoint>>,
    /// A constant torque driving the inner ring (dynamic runs): its speed
    /// is then the run's outcome, `speed` the speed at the start.
    pub drive_torque: Option<Quantity<Moment>>,
    /// A piecewise-linear drive torque instead: `[{ time = "0 s", torque
    /// = "0.2 N.m" }, ...]`, times increasing.
    pub drive_torque_profile: Option<Vec<RawTorquePoint>>,
    /// Polar moment of inertia of everything turning with the inner ring
    /// (ring, shaft, rotor), for a drive torque.
    pub rotor_inertia: Option<Quantity<Inertia>>,
    /// A rotating unbalance on the inner ring, mass × radius (e.g. "20
    /// g.mm"): its force turns with the ring in a dynamic run.
    pub unbalance: Option<Quantity<Unbalance>>,
    /// Its direction on the ring at t = 0, from +y towards +z (default 0).
    pub unbalance_phase: Option<Quantity<Angle>>,
}

/// One point of a drive-torque table.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawTorquePoint {
    /// Time of the point.
    pub time: Quantity<Time>,
    /// Drive torque at that time.
    pub torque: Quantity<Moment>,
}

/// One point of a load table.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawLoadPoint {
    /// Time of the point.
    pub time: Quantity<Time>,
    /// Axial force F_x.
    pub force_x: Option<Quantity<Force>>,
    /// Radial force F_y.
    pub force_y: Option<Quantity<Force>>,
    /// Radial force F_z.
    pub force_z: Option<Quantity<Force>>,
    /// Moment M_y.
    pub moment_y: Option<Quantity<Moment>>,
    /// Moment M_z.
    pub moment_z: Option<Quantity<Moment>>,
}

/// One point of a speed profile.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawSpeedPoint {
    /// Time of the point.
    pub time: Quantity<Time>,
    /// Inner-ring speed at that time.
    pub speed: Quantity<AngularSpeed>,
}

/// Time-integration settings (read by `rolldyn run`, which arrives with
/// the dynamic engine; validated now).
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawSolver {
    /// Simulated time.
    pub duration: Option<Quantity<Time>>,
    /// Relative error tolerance of adaptive integrators (default 1e-3).
    pub relative_tolerance: Option<f64>,
    /// Error allowed in the energy balance per unit of energy turned over
    /// in a step (default 1e-4; 0 turns the energy error control off).
    pub energy_tolerance: Option<f64>,
    /// Largest step the integrator may take.
    pub max_step: Option<Quantity<Time>>,
    /// "auto" (default: ros34pw2 and dopri5 switched by measured cost,
    /// docs/dynamics.md), "ros34pw2" (stiff),
    /// "dopri5" (explicit) or "rk4" (fixed step).
    pub integrator: Option<IntegratorChoice>,
    /// Step of the fixed-step integrator (rk4).
    pub time_step: Option<Quantity<Time>>,
    /// Initial state: "jones_harris" (default), "quasistatic_traction"
    /// (Zhang et al. 2025 §3.1) or "pure_rolling".
    pub start: Option<StartChoice>,
}

/// Time integrator.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum IntegratorChoice {
    /// ros34pw2, handing over to dopri5 where that is cheaper by measured
    /// cost (after spall impacts; `rolldyn::integrate::switching`).
    Auto,
    /// Linearly implicit Rosenbrock–W 3(2) (Rang & Angermann) for stiff
    /// systems: block-structured Jacobian, reused across steps.
    Ros34pw2,
    /// Adaptive Dormand–Prince 5(4) with dense output.
    Dopri5,
    /// Classical Runge–Kutta 4 with a fixed step (`solver.time_step`).
    Rk4,
}

/// Initial state of a dynamic run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum StartChoice {
    /// The Jones–Harris quasi-static solution at the start speed.
    JonesHarris,
    /// Balls at the pitch circle with pure-rolling speeds.
    PureRolling,
    /// The traction-consistent quasi-static state: ball speeds from the
    /// force and moment balance with the case's traction model (Zhang et al. 2025
    /// §3.1's tribological start), from the Jones–Harris solution.
    QuasistaticTraction,
}

/// Output settings (read by `rolldyn run`).
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawOutput {
    /// Sample rate of the recorded time series.
    pub sample_rate: Option<Quantity<Frequency>>,
    /// Output directory.
    pub directory: Option<String>,
    /// Record each ball's dissipated power at its inner and outer contact
    /// (`ball{j}_power_inner_w`, `…_outer_w`; default false).
    pub power_per_ball: Option<bool>,
    /// Channel groups to record: "rings", "cage", "balls", "contacts",
    /// "energy", "power", "thermal" (default all).
    pub channels: Option<Vec<String>>,
    /// Balls whose per-ball channels are recorded (default all).
    pub balls: Option<Vec<i64>>,
    /// Storage precision of the samples (default float64).
    pub precision: Option<RawPrecision>,
    /// Channel groups recorded at `slow_rate` into a second dataset
    /// (`timeseries_slow.parquet`) instead of at the sample rate.
    pub slow_channels: Option<Vec<String>>,
    /// Sample rate of the slow channels.
    pub slow_rate: Option<Quantity<Frequency>>,
}

/// Storage precision of the recorded samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum RawPrecision {
    /// 64-bit floats (16 significant digits).
    Float64,
    /// 32-bit floats (7 significant digits): half the size.
    Float32,
}
