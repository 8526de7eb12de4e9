//! The validated case: SI units, every rule of docs/model.md §2 checked. Built by
//! [`crate::load_case`] from a [`RawCase`]; nothing runs on unchecked input.

use crate::raw::*;
use crate::units::{Dimension, Quantity};
use rolldyn::cage::PocketShape;
use rolldyn::contact::normal_law::DEFAULT_IMPACT_SPEED_FLOOR;
use rolldyn::contact::{HertzModel, NormalForceLaw};
use rolldyn::dynamics::{DragParameters, OuterRing, Support};
use rolldyn::operating::{LoadProfile, Loads, SpeedProfile};
use rolldyn::traction::{TractionIntegration, TractionModel};
use rolldyn::{BearingGeometry, Material};

/// The recorder's rate when the case gives none (`output.sample_rate`)
/// \[Hz\].
pub const DEFAULT_SAMPLE_RATE: f64 = 10_000.0;

mod arrangement;
mod bearing;
mod cage;
mod dynamics;
mod fits;
mod life;
mod lubricant;
mod lubrication;
mod material;
mod operating;
mod output;
mod rings;
mod sensor;
mod shaft;
mod solver;
mod surface;
mod thermal;
pub mod tolerances;
mod traction;
pub use arrangement::{Arrangement, MAX_PRELOAD, MAX_PRELOAD_DISPLACEMENT, Preload, kind_name};
pub use bearing::PARAMETRIZATIONS;
use bearing::bearing;
pub use dynamics::{
    DEFAULT_POCKET_FRICTION, DEFAULT_POCKET_MIN_FILM, GUIDE_MAX_ECCENTRICITY, GUIDE_STOP_STIFFNESS,
    GUPTA_WALL_FORCE, STANDARD_GRAVITY,
};
pub use fits::FitEffect;
pub use life::{Life, MAX_VISCOSITY_RATIO};
pub use lubricant::Lubricant;
use lubricant::lubricant;
pub use lubrication::{Lubrication, Method};
use material::material;
pub use output::{ChannelGroup, OutputSelection};
pub use shaft::{MAX_SHAFT_POSITION, Shaft, ShaftBearing};
pub use thermal::{DEFAULT_AIR_CONVECTION, DEFAULT_OIL, DEFAULT_OIL_VISCOSITY, Power, Thermal};
use traction::traction;

/// A rule broken by one key: the raw material of a [`crate::CaseError`].
#[derive(Debug, Clone, PartialEq)]
pub struct Invalid {
    /// Dotted key.
    pub key: String,
    /// Value as written, if any.
    pub value: Option<String>,
    /// The rule.
    pub rule: String,
}

impl Invalid {
    fn new(key: impl Into<String>, value: Option<String>, rule: impl Into<String>) -> Self {
        Self {
            key: key.into(),
            value,
            rule: rule.into(),
        }
    }
    fn missing(key: &str, what: &str) -> Self {
        Self::new(key, None, format!("missing: {what}"))
    }
}

/// A validated rolldyn case.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    /// Title.
    pub title: Option<String>,
    /// The bearing.
    pub bearing: Bearing,
    /// Cage data (all optional until the dynamic engine).
    pub cage: Cage,
    /// Ball and ring materials.
    pub materials: Materials,
    /// Lubricant, if given.
    pub lubricant: Option<Lubricant>,
    /// Inner-ring speed, if given.
    pub speed: Option<SpeedProfile>,
    /// Constant loads on the inner ring (the quasi-static solvers; the
    /// start of a load table).
    pub loads: Loads,
    /// Load table of a dynamic run, if given.
    pub load_profile: Option<LoadProfile>,
    /// A torque driving the inner ring in a dynamic run (None: the speed
    /// is prescribed).
    pub drive: Option<rolldyn::operating::TorqueDrive>,
    /// A rotating unbalance on the inner ring in a dynamic run.
    pub unbalance: Option<rolldyn::operating::RingUnbalance>,
    /// Spring–damper between inner ring and ground.
    pub inner_support: Support,
    /// Outer ring on a housing spring–damper, if given.
    pub outer_ring: Option<OuterRing>,
    /// Elastic-hysteresis coefficient α_h of the rolling resistance.
    pub rolling_hysteresis: f64,
    /// Normal force law.
    pub normal_law: NormalForceLaw,
    /// Hertz contact-stiffness model.
    pub contact_stiffness: HertzModel,
    /// Impact-speed floor v_floor \[m/s\].
    pub impact_speed_floor: f64,
    /// Raceway control of the quasi-static model.
    pub raceway_control: rolldyn::quasistatic::RacewayControl,
    /// Traction model of the dynamic engine (EHL with the case's lubricant).
    pub traction: TractionModel,
    /// Traction integration over the contact ellipse.
    pub traction_integration: TractionIntegration,
    /// Planar mode.
    pub planar: bool,
    /// Gravity along −z.
    pub gravity: bool,
    /// The bearing's damping between its rings as a time τ \[s\]
    /// (c = τ k_r; None: none).
    pub bearing_damping: Option<f64>,
    /// The lubricant film in the normal approach.
    pub film_in_approach: bool,
    /// Mixed lubrication (`[model.mixed_lubrication]`; None: off).
    pub mixed_lubrication: Option<rolldyn::traction::mixed::MixedLubrication>,
    /// Inner-ring mass \[kg\], if given.
    pub inner_ring_mass: Option<f64>,
    /// Inner-ring tilt inertia \[kg·m²\], if given.
    pub inner_ring_tilt_inertia: Option<f64>,
    /// Time integrator.
    pub integrator: IntegratorChoice,
    /// Fixed step of rk4 \[s\].
    pub time_step: Option<f64>,
    /// Initial state of a dynamic run.
    pub start: StartChoice,
    /// Drag of the air–oil mixture.
    pub drag: DragParameters,
    /// Friction of contact seals (None: an open bearing).
    pub seals: Option<rolldyn::dynamics::SealFriction>,
    /// How the bearing is lubricated (`[lubrication]`).
    pub lubrication: Lubrication,
    /// The accelerometer on the housing and its acquisition (None: no
    /// sensor), acquiring at the output's sample rate.
    pub sensor: Option<rolldyn::signal::sensor::SensorSpec>,
    /// Raceway and ball surfaces (waviness, spalls).
    pub surface: rolldyn::surface::SurfaceModel,
    /// Simulated time \[s\], if given.
    pub duration: Option<f64>,
    /// Relative tolerance of adaptive integrators.
    pub relative_tolerance: Option<f64>,
    /// Energy-balance tolerance of adaptive integrators (0: off).
    pub energy_tolerance: Option<f64>,
    /// Largest integrator step \[s\].
    pub max_step: Option<f64>,
    /// Recorder sample rate \[Hz\].
    pub sample_rate: Option<f64>,
    /// Per-ball power channels.
    pub power_per_ball: bool,
    /// What the run records (`output.channels`, `balls`, `precision`).
    pub output: OutputSelection,
    /// Azimuth of ball 0 \[rad\].
    pub first_ball_azimuth: f64,
    /// Prescribed ring displacements (x, y, z \[m\], θ_y, θ_z \[rad\]);
    /// quasi-static solves only.
    pub prescribed_displacement: [Option<f64>; 5],
    /// Output directory.
    pub output_directory: Option<String>,
    /// Harris's local power-loss method settings.
    pub power: Power,
    /// Thermal network settings.
    pub thermal: Thermal,
    /// Rating-life settings.
    pub life: Life,
    /// A matched set of the bearing on one shaft (`[arrangement]`).
    pub arrangement: Option<Arrangement>,
    /// Built-in bearings at positions on one rigid shaft (`[shaft]`).
    pub shaft: Option<Shaft>,
    /// Assumed values: (dotted key, reason).
    pub assumptions: Vec<(String, String)>,
}

/// Bearing identity and geometry.
#[derive(Debug, Clone, PartialEq)]
pub struct Bearing {
    /// Preset the geometry came from, if any.
    pub preset: Option<String>,
    /// Designation.
    pub designation: Option<String>,
    /// Validated geometry.
    pub geometry: BearingGeometry,
    /// Bore \[m\].
    pub bore: Option<f64>,
    /// Outside diameter \[m\].
    pub outside_diameter: Option<f64>,
    /// Width \[m\].
    pub width: Option<f64>,
    /// What `[fits]` did to the clearance (None without fits).
    pub fits: Option<FitEffect>,
}

/// Cage data in SI.
#[derive(Debug, Clone, PartialEq)]
pub struct Cage {
    /// Guidance.
    pub guidance: Option<CageGuidance>,
    /// Pocket clearance C_p \[m\].
    pub pocket_clearance: Option<f64>,
    /// Cage bore \[m\].
    pub inner_diameter: Option<f64>,
    /// Cage outside diameter \[m\].
    pub outer_diameter: Option<f64>,
    /// Guide-land width \[m\].
    pub guide_land_width: Option<f64>,
    /// Guide clearance \[m\].
    pub guide_clearance: Option<f64>,
    /// Mass \[kg\].
    pub mass: Option<f64>,
    /// Polar moment of inertia \[kg·m²\].
    pub inertia: Option<f64>,
    /// Pocket contact stiffness \[N/m\].
    pub pocket_stiffness: Option<f64>,
    /// Pocket contact damping \[N·s/m\].
    pub pocket_damping: Option<f64>,
    /// Pocket friction coefficient.
    pub pocket_friction: f64,
    /// Whether the cage whirls.
    pub whirl: bool,
    /// Pocket shape.
    pub pocket_shape: PocketShape,
    /// Pocket law.
    pub pocket_law: PocketLawChoice,
    /// Film force at the pocket wall (gupta_film) \[N\].
    pub pocket_wall_force: f64,
    /// Whether the pocket oil film damps by squeeze.
    pub pocket_squeeze_film: bool,
    /// Least pocket film of the squeeze damping \[m\].
    pub pocket_min_film: f64,
    /// Cavitation condition of the squeeze damping.
    pub pocket_squeeze_cavitation: rolldyn::cage::SqueezeCavitation,
    /// Largest suction of the pocket film (vapour cavitation) \[Pa\].
    pub pocket_squeeze_tension: f64,
    /// Cage material, if given.
    pub material: Option<NamedMaterial>,
    /// Unbalance m_u e \[kg·m\].
    pub unbalance: f64,
}

/// A material with a display name.
#[derive(Debug, Clone, PartialEq)]
pub struct NamedMaterial {
    /// Name for reports.
    pub name: String,
    /// Properties.
    pub material: Material,
}

/// Ball and ring materials.
#[derive(Debug, Clone, PartialEq)]
pub struct Materials {
    /// Ball material.
    pub ball: NamedMaterial,
    /// Ring material.
    pub rings: NamedMaterial,
}

/// Built-in material names and properties.
pub const MATERIALS: [(&str, Material); 2] = [
    ("steel_52100", Material::STEEL_52100),
    ("silicon_nitride", Material::SILICON_NITRIDE),
];

fn text<D>(q: &Option<Quantity<D>>) -> Option<String> {
    q.as_ref().map(|q| q.to_string())
}

/// A checked optional quantity: `Ok(None)` when absent.
fn checked<D: Dimension>(
    key: &str,
    q: &Option<Quantity<D>>,
    rule: impl Fn(f64) -> Result<(), String>,
) -> Result<Option<f64>, Invalid> {
    match q {
        None => Ok(None),
        Some(q) => rule(q.si)
            .map(|_| Some(q.si))
            .map_err(|r| Invalid::new(key, Some(q.to_string()), r)),
    }
}

/// The bearing damping's time τ: at most 1e-3 s (a bearing's published
/// range is (0.25–2.5)·10⁻⁵ s; 1e-3 s would damp a 1 kHz mode
/// supercritically).
fn bearing_damping_time(v: f64) -> Result<(), String> {
    if (0.0..=1e-3).contains(&v) {
        Ok(())
    } else {
        Err("must lie in [0, 1e-3] s (rolling bearings: (0.25–2.5)e-5 s, docs/dynamics.md \"Mounting\")".into())
    }
}

fn positive(v: f64) -> Result<(), String> {
    if v > 0.0 {
        Ok(())
    } else {
        Err("must be positive".into())
    }
}

fn non_negative(v: f64) -> Result<(), String> {
    if v >= 0.0 {
        Ok(())
    } else {
        Err("must not be negative".into())
    }
}

fn positive_number(
    key: &str,
    v: Option<f64>,
    rule: impl Fn(f64) -> bool,
    what: &str,
) -> Result<Option<f64>, Invalid> {
    match v {
        Some(x) if !x.is_finite() => Err(Invalid::new(
            key,
            Some(x.to_string()),
            "must be a finite number",
        )),
        Some(x) if !rule(x) => {
            let text = if x != 0.0 && !(1e-4..1e15).contains(&x.abs()) {
                format!("{x:e}")
            } else {
                x.to_string()
            };
            Err(Invalid::new(key, Some(text), what))
        }
        other => Ok(other),
    }
}

/// Largest shaft speed accepted \[rad/s\]: 10⁶ rpm, far beyond any ball
/// bearing (DN 3·10⁶ mm·rpm is a 3 mm bore at that speed).
pub const MAX_SPEED: f64 = 1e6 * std::f64::consts::TAU / 60.0;
/// Largest load component accepted \[N\] (100 MN).
pub const MAX_FORCE: f64 = 1e8;

/// Checks a speed against [`MAX_SPEED`].
pub fn check_speed(key: &str, v: f64) -> Result<(), Invalid> {
    if v.is_finite() && v.abs() <= MAX_SPEED {
        Ok(())
    } else {
        Err(Invalid::new(
            key,
            Some(format!("{:e} rpm", v * 60.0 / std::f64::consts::TAU)),
            "must lie within ±1 000 000 rpm",
        ))
    }
}

/// Checks a force against [`MAX_FORCE`].
pub fn check_force(key: &str, v: f64) -> Result<(), Invalid> {
    if v.is_finite() && v.abs() <= MAX_FORCE {
        Ok(())
    } else {
        Err(Invalid::new(
            key,
            Some(format!("{v:e} N")),
            "must lie within ±100 MN",
        ))
    }
}

/// The normal force law of `[model]` and its impact-speed floor \[m/s\].
fn normal_law(raw: &RawCase) -> Result<(NormalForceLaw, f64), Invalid> {
    let normal_law = raw
        .model
        .normal_law
        .map_or(NormalForceLaw::MATERIAL, |c| c.0);
    normal_law.validate().map_err(|e| {
        Invalid::new(
            format!("model.normal_law.{}", e.field),
            Some(e.value),
            e.rule,
        )
    })?;
    let impact_speed_floor = checked(
        "model.impact_speed_floor",
        &raw.model.impact_speed_floor,
        positive,
    )?
    .unwrap_or(DEFAULT_IMPACT_SPEED_FLOOR);
    Ok((normal_law, impact_speed_floor))
}

/// The `[shaft]` of a case, refused beside an `[arrangement]` or the
/// case's own `[fits]`.
fn shaft(raw: &RawCase, arrangement: bool) -> Result<Option<shaft::Shaft>, Invalid> {
    let shaft = shaft::shaft(&raw.shaft)?;
    if shaft.is_some() && arrangement {
        return Err(Invalid::new(
            "shaft",
            None,
            "give either [arrangement] (a matched set of the case's bearing) or [shaft] (presets at positions), not both",
        ));
    }
    if shaft.is_some() && raw.fits.is_some() {
        return Err(Invalid::new(
            "fits",
            None,
            "[fits] applies to the case's one bearing; give each shaft bearing its own as [shaft.bearings.fits] (the same keys)",
        ));
    }
    let op = &raw.operating;
    let held = [
        ("fixed_tilt", op.fixed_tilt == Some(true)),
        ("tilt_y", op.tilt_y.is_some()),
        ("tilt_z", op.tilt_z.is_some()),
        ("displacement_x", op.displacement_x.is_some()),
        ("displacement_y", op.displacement_y.is_some()),
        ("displacement_z", op.displacement_z.is_some()),
    ];
    if let Some((key, _)) = held.iter().find(|(_, given)| shaft.is_some() && *given) {
        return Err(Invalid::new(
            format!("operating.{key}"),
            None,
            "a shaft's displacements and tilts follow from its bearings and loads: not with [shaft]",
        ));
    }
    Ok(shaft)
}

impl Case {
    /// Validates a raw case (already merged with its preset and overrides).
    pub fn from_raw(raw: &RawCase) -> Result<Self, Invalid> {
        let operating = operating::operating(&raw.operating)?;
        let (normal_law, impact_speed_floor) = normal_law(raw)?;
        let solver = solver::solver(raw)?;
        let traction_integration = traction::integration(raw.model.traction_integration)?;
        let bearing = bearing(&raw.bearing, raw.fits.as_ref())?;
        let arrangement = arrangement::arrangement(&raw.arrangement, bearing.width)?;
        let shaft = shaft(raw, arrangement.is_some())?;
        let lubricant = raw
            .lubricant
            .as_ref()
            .map(|l| lubricant(l, &bearing.geometry))
            .transpose()?;
        let materials = Materials {
            ball: material("materials.ball", raw.materials.ball.as_ref())?,
            rings: material("materials.rings", raw.materials.rings.as_ref())?,
        };
        let traction = traction(raw.model.traction.as_ref(), lubricant.as_ref(), &materials)?;
        let film_in_approach =
            traction::film_in_approach(raw.model.film_in_approach, &traction, lubricant.as_ref())?;
        let rings = rings::rings(raw)?;
        let rolling_hysteresis = positive_number(
            "model.rolling_hysteresis",
            raw.model.rolling_hysteresis,
            |v| (0.0..1.0).contains(&v),
            "the hysteresis coefficient must lie in [0, 1) (steel: 0.007)",
        )?
        .unwrap_or(0.0);
        let drag = dynamics::drag(&raw.drag)?;
        let seals = dynamics::seals(raw.seals.as_ref())?;
        let lubrication = lubrication::lubrication(
            raw.lubrication.as_ref(),
            &bearing.geometry,
            lubricant.as_ref(),
        )?;
        let sensor = sensor::sensor(
            raw.sensor.as_ref(),
            solver.sample_rate.unwrap_or(DEFAULT_SAMPLE_RATE),
        )?;
        let surface = surface::surface(
            &raw.surface,
            bearing.geometry.ball_count,
            bearing.geometry.ball_diameter,
        )?;
        let mixed_lubrication =
            traction::mixed_lubrication(raw.model.mixed_lubrication.as_ref(), &traction, &surface)?;
        let output = output::selection(&raw.output, bearing.geometry.ball_count)?;
        let thermal = thermal::thermal(&raw.thermal, &materials.ball.name)?;
        let case = Self {
            title: raw.title.clone(),
            bearing,
            cage: cage::cage(&raw.cage)?,
            materials,
            lubricant,
            speed: operating.speed,
            loads: operating.loads,
            load_profile: operating.load_profile,
            drive: operating.drive,
            unbalance: operating.unbalance,
            inner_support: rings.inner_support,
            outer_ring: rings.outer_ring,
            rolling_hysteresis,
            normal_law,
            contact_stiffness: raw.model.contact_stiffness.unwrap_or_default(),
            impact_speed_floor,
            raceway_control: raw.model.raceway_control.unwrap_or_default(),
            traction,
            traction_integration,
            planar: raw.model.planar.unwrap_or(false),
            gravity: raw.model.gravity.unwrap_or(false),
            bearing_damping: checked(
                "model.bearing_damping",
                &raw.model.bearing_damping,
                bearing_damping_time,
            )?,
            film_in_approach,
            mixed_lubrication,
            inner_ring_mass: rings.inner_ring_mass,
            inner_ring_tilt_inertia: rings.inner_ring_tilt_inertia,
            integrator: solver.integrator,
            time_step: solver.time_step,
            start: solver.start,
            drag,
            seals,
            lubrication,
            sensor,
            surface,
            duration: solver.duration,
            relative_tolerance: solver.relative_tolerance,
            energy_tolerance: solver.energy_tolerance,
            max_step: solver.max_step,
            sample_rate: solver.sample_rate,
            power_per_ball: raw.output.power_per_ball.unwrap_or(false),
            output,
            first_ball_azimuth: operating.first_ball_azimuth,
            prescribed_displacement: operating.prescribed_displacement,
            output_directory: raw.output.directory.clone(),
            power: thermal::power(&raw.power)?,
            thermal,
            life: life::life(&raw.life)?,
            arrangement,
            shaft,
            assumptions: raw
                .assumptions
                .iter()
                .map(|(k, v)| (k.clone(), v.clone()))
                .collect(),
        };
        // The pockets' squeeze film needs the oil of every command's case,
        // not only a run's: refused where the file states it.
        case.pocket_squeeze()?;
        Ok(case)
    }
}

impl Case {
    /// Quasi-static solver options of the case (ball 0's azimuth, the
    /// prescribed displacements).
    pub fn solver_options(&self) -> rolldyn::quasistatic::SolverOptions {
        rolldyn::quasistatic::SolverOptions {
            first_ball_azimuth: self.first_ball_azimuth,
            prescribed_displacement: self.prescribed_displacement,
            ..Default::default()
        }
    }
}
