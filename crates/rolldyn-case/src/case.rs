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

mod arrangement;
mod bearing;
mod dynamics;
mod life;
mod lubricant;
mod output;
mod surface;
mod thermal;
mod traction;
pub use arrangement::{Arrangement, MAX_PRELOAD, MAX_PRELOAD_DISPLACEMENT, Preload, kind_name};
pub use bearing::PARAMETRIZATIONS;
use bearing::bearing;
pub use dynamics::{
    DEFAULT_POCKET_FRICTION, DEFAULT_POCKET_MIN_FILM, GUIDE_MAX_ECCENTRICITY, GUIDE_STOP_STIFFNESS,
    GUPTA_WALL_FORCE, STANDARD_GRAVITY,
};
pub use life::{Life, MAX_VISCOSITY_RATIO};
pub use lubricant::Lubricant;
use lubricant::lubricant;
pub use output::{ChannelGroup, OutputSelection};
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
    /// The lubricant film in the normal approach.
    pub film_in_approach: bool,
    /// Mixed lubrication (`[model.mixed_lubrication]`; None: off).
    pub mixed_lubrication: Option<rolldyn::lubrication::mixed::MixedLubrication>,
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

impl Case {
    /// Validates a raw case (already merged with its preset and overrides).
    pub fn from_raw(raw: &RawCase) -> Result<Self, Invalid> {
        let op = &raw.operating;
        if let Some(s) = &op.speed {
            check_speed("operating.speed", s.si)?;
        }
        for (i, p) in op.speed_profile.iter().flatten().enumerate() {
            check_speed(&format!("operating.speed_profile[{i}].speed"), p.speed.si)?;
        }
        for (key, q) in [
            ("operating.force_x", &op.force_x),
            ("operating.force_y", &op.force_y),
            ("operating.force_z", &op.force_z),
            ("operating.radial_load", &op.radial_load),
        ] {
            if let Some(q) = q {
                check_force(key, q.si)?;
            }
        }
        let speed = match (&op.speed, &op.speed_profile) {
            (Some(_), Some(_)) => {
                return Err(Invalid::new(
                    "operating.speed_profile",
                    None,
                    "give either operating.speed (constant) or operating.speed_profile, not both",
                ));
            }
            (Some(s), None) => Some(SpeedProfile::Constant(s.si)),
            (None, Some(points)) => Some(
                SpeedProfile::piecewise_linear(
                    points.iter().map(|p| (p.time.si, p.speed.si)).collect(),
                )
                .map_err(|(i, e)| {
                    let v = points.get(i).map(|p| p.time.to_string());
                    Invalid::new(format!("operating.speed_profile[{i}].time"), v, e.rule)
                })?,
            ),
            (None, None) => None,
        };
        let force = |q: &Option<Quantity<crate::units::Force>>| q.as_ref().map_or(0.0, |q| q.si);
        let moment = |q: &Option<Quantity<crate::units::Moment>>| q.as_ref().map_or(0.0, |q| q.si);
        let mut loads = Loads {
            force: [force(&op.force_x), force(&op.force_y), force(&op.force_z)],
            moment: [moment(&op.moment_y), moment(&op.moment_z)],
        };
        if let Some(q) = &op.radial_load {
            if op.force_y.is_some() || op.force_z.is_some() {
                return Err(Invalid::new(
                    "operating.radial_load",
                    Some(q.to_string()),
                    "give the radial load either as radial_load (with radial_load_angle) or as force_y/force_z, not both",
                ));
            }
            let angle = op
                .radial_load_angle
                .as_ref()
                .map_or(std::f64::consts::FRAC_PI_2, |a| a.si);
            // Exact zeros along the axes (cos 90° is 6e-17 in floating point).
            let snap = |v: f64| if v.abs() < 1e-12 * q.si.abs() { 0.0 } else { v };
            loads.force[1] = snap(q.si * angle.cos());
            loads.force[2] = snap(q.si * angle.sin());
        } else if let Some(a) = &op.radial_load_angle {
            return Err(Invalid::new(
                "operating.radial_load_angle",
                Some(a.to_string()),
                "needs operating.radial_load",
            ));
        }
        let load_profile = match &op.load_profile {
            None => None,
            Some(points) => {
                if let Some(key) = [
                    ("force_x", &op.force_x),
                    ("force_y", &op.force_y),
                    ("force_z", &op.force_z),
                    ("radial_load", &op.radial_load),
                ]
                .iter()
                .find(|(_, q)| q.is_some())
                .map(|(k, _)| *k)
                .or_else(|| {
                    [("moment_y", &op.moment_y), ("moment_z", &op.moment_z)]
                        .iter()
                        .find(|(_, q)| q.is_some())
                        .map(|(k, _)| *k)
                }) {
                    return Err(Invalid::new(
                        "operating.load_profile",
                        None,
                        format!(
                            "give either constant loads (operating.{key}, ...) or operating.load_profile, not both"
                        ),
                    ));
                }
                let table = points
                    .iter()
                    .map(|p| {
                        (
                            p.time.si,
                            Loads {
                                force: [force(&p.force_x), force(&p.force_y), force(&p.force_z)],
                                moment: [moment(&p.moment_y), moment(&p.moment_z)],
                            },
                        )
                    })
                    .collect();
                Some(LoadProfile::piecewise_linear(table).map_err(|(i, e)| {
                    let v = points.get(i).map(|p| p.time.to_string());
                    Invalid::new(format!("operating.load_profile[{i}].time"), v, e.rule)
                })?)
            }
        };
        // The quasi-static solvers (and a dynamic run's start) see the loads at t = 0.
        let loads = load_profile.as_ref().map_or(loads, |p| p.at(0.0));

        let normal_law = raw.model.normal_law.map_or(NormalForceLaw::Hertz, |c| c.0);
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

        let s = &raw.solver;
        // Practical limits (docs/case-format.md): below them a run cannot
        // finish (steps at round-off) or cannot be stored.
        let at_least = |min: f64, what: &'static str| {
            move |v: f64| {
                if v >= min {
                    Ok(())
                } else {
                    Err(format!("must be at least {what}"))
                }
            }
        };
        let duration = checked("solver.duration", &s.duration, positive)?;
        let max_step = checked("solver.max_step", &s.max_step, at_least(1e-9, "1 ns"))?;
        let relative_tolerance = positive_number(
            "solver.relative_tolerance",
            s.relative_tolerance,
            |x| (1e-12..=0.5).contains(&x),
            "must lie in [1e-12, 0.5] (below 1e-12 the steps stall at round-off)",
        )?;
        let energy_tolerance = positive_number(
            "solver.energy_tolerance",
            s.energy_tolerance,
            |x| x == 0.0 || (1e-9..=0.1).contains(&x),
            "must be 0 (off) or lie in [1e-9, 0.1]",
        )?;
        let sample_rate = checked("output.sample_rate", &raw.output.sample_rate, |v| {
            if v > 0.0 && v <= 1e7 {
                Ok(())
            } else {
                Err("must lie in (0, 10 MHz]".to_string())
            }
        })?;
        let time_step = checked("solver.time_step", &s.time_step, at_least(1e-10, "0.1 ns"))?;
        if let Some(TractionIntegration::Grid { across, along }) = raw.model.traction_integration {
            if across.saturating_mul(along) > 10_000 || across == 0 || along == 0 {
                return Err(Invalid::new(
                    "model.traction_integration",
                    Some(format!("{across} × {along}")),
                    "the grid needs 1 to 10 000 cells (across × along)",
                ));
            }
        }
        let integrator = s.integrator.unwrap_or(IntegratorChoice::Auto);
        if integrator == IntegratorChoice::Rk4 && time_step.is_none() {
            return Err(Invalid::missing(
                "solver.time_step",
                "the rk4 integrator needs a fixed step, e.g. \"0.5 us\"",
            ));
        }
        let bearing = bearing(&raw.bearing)?;
        let arrangement = arrangement::arrangement(&raw.arrangement, bearing.width)?;
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
        if raw.model.film_in_approach == Some(true) {
            if traction.lubricant().is_none() {
                return Err(Invalid::new(
                    "model.film_in_approach",
                    Some("true".into()),
                    "the film needs a film model: model.traction = \"ehl\" with a [lubricant] section",
                ));
            }
            let flow = lubricant.as_ref().is_some_and(|l| {
                l.supply
                    .iter()
                    .any(|s| matches!(s, rolldyn::lubrication::Supply::Flow { .. }))
            });
            if flow {
                return Err(Invalid::new(
                    "model.film_in_approach",
                    Some("true".into()),
                    "the film in the approach needs a flooded supply or lubricant.inlet_distance_ratio, not lubricant.oil_flow (docs/lubrication.md)",
                ));
            }
        }
        let inner_ring_mass = checked("inner_ring.mass", &raw.inner_ring.mass, positive)?;
        let inner_ring_tilt_inertia = checked(
            "inner_ring.tilt_inertia",
            &raw.inner_ring.tilt_inertia,
            positive,
        )?;
        let ir = &raw.inner_ring;
        let zero = |v: Option<f64>| v.unwrap_or(0.0);
        let radial_k = zero(checked(
            "inner_ring.support_radial_stiffness",
            &ir.support_radial_stiffness,
            non_negative,
        )?);
        let radial_c = zero(checked(
            "inner_ring.support_radial_damping",
            &ir.support_radial_damping,
            non_negative,
        )?);
        let inner_support = Support {
            stiffness: [
                zero(checked(
                    "inner_ring.support_axial_stiffness",
                    &ir.support_axial_stiffness,
                    non_negative,
                )?),
                radial_k,
                radial_k,
            ],
            damping: [
                zero(checked(
                    "inner_ring.support_axial_damping",
                    &ir.support_axial_damping,
                    non_negative,
                )?),
                radial_c,
                radial_c,
            ],
        };
        let outer_ring = match &raw.outer_ring {
            None => None,
            Some(o) => {
                let k = checked(
                    "outer_ring.housing_stiffness",
                    &Some(o.housing_stiffness.clone()),
                    non_negative,
                )?
                .unwrap_or(0.0);
                let c = zero(checked(
                    "outer_ring.housing_damping",
                    &o.housing_damping,
                    non_negative,
                )?);
                Some(OuterRing {
                    mass: checked("outer_ring.mass", &Some(o.mass.clone()), positive)?
                        .unwrap_or(0.0),
                    housing: Support {
                        stiffness: [0.0, k, k],
                        damping: [0.0, c, c],
                    },
                })
            }
        };
        let rolling_hysteresis = positive_number(
            "model.rolling_hysteresis",
            raw.model.rolling_hysteresis,
            |v| (0.0..1.0).contains(&v),
            "the hysteresis coefficient must lie in [0, 1) (steel: 0.007)",
        )?
        .unwrap_or(0.0);
        let d = &raw.drag;
        let coefficient = |key: &str, v: Option<f64>| {
            positive_number(
                key,
                v,
                |x| (0.0..=1e4).contains(&x),
                "a drag coefficient must lie in [0, 1e4] (a sphere's C_D is below 1e3 down to Re = 0.03)",
            )
            .map(|v| v.unwrap_or(0.0))
        };
        let drag = DragParameters {
            effective_density: checked(
                "drag.effective_density",
                &d.effective_density,
                non_negative,
            )?
            .unwrap_or(0.0),
            ball_drag_coefficient: coefficient(
                "drag.ball_drag_coefficient",
                d.ball_drag_coefficient,
            )?,
            ball_spin_drag_coefficient: coefficient(
                "drag.ball_spin_drag_coefficient",
                d.ball_spin_drag_coefficient,
            )?,
            cage_viscous: checked("drag.cage_viscous", &d.cage_viscous, non_negative)?
                .unwrap_or(0.0),
            cage_windage: checked("drag.cage_windage", &d.cage_windage, non_negative)?
                .unwrap_or(0.0),
        };

        let surface = surface::surface(
            &raw.surface,
            bearing.geometry.ball_count,
            bearing.geometry.ball_diameter,
        )?;
        let mixed_lubrication =
            traction::mixed_lubrication(raw.model.mixed_lubrication.as_ref(), &traction, &surface)?;
        let materials_ball_name = materials.ball.name.clone();
        let output = output::selection(&raw.output, bearing.geometry.ball_count)?;
        Ok(Self {
            title: raw.title.clone(),
            bearing,
            cage: cage(&raw.cage)?,
            materials,
            lubricant,
            speed,
            loads,
            load_profile,
            inner_support,
            outer_ring,
            rolling_hysteresis,
            normal_law,
            contact_stiffness: raw.model.contact_stiffness.unwrap_or_default(),
            impact_speed_floor,
            raceway_control: raw.model.raceway_control.unwrap_or_default(),
            traction,
            traction_integration: raw.model.traction_integration.unwrap_or_default(),
            planar: raw.model.planar.unwrap_or(false),
            gravity: raw.model.gravity.unwrap_or(false),
            film_in_approach: raw.model.film_in_approach.unwrap_or(false),
            mixed_lubrication,
            inner_ring_mass,
            inner_ring_tilt_inertia,
            integrator,
            time_step,
            start: s.start.unwrap_or(StartChoice::JonesHarris),
            drag,
            surface,
            duration,
            relative_tolerance,
            energy_tolerance,
            max_step,
            sample_rate,
            power_per_ball: raw.output.power_per_ball.unwrap_or(false),
            output,
            first_ball_azimuth: op.first_ball_azimuth.as_ref().map_or(0.0, |a| a.si),
            prescribed_displacement: prescribed(op)?,
            output_directory: raw.output.directory.clone(),
            power: thermal::power(&raw.power)?,
            thermal: thermal::thermal(&raw.thermal, &materials_ball_name)?,
            life: life::life(&raw.life)?,
            arrangement,
            assumptions: raw
                .assumptions
                .iter()
                .map(|(k, v)| (k.clone(), v.clone()))
                .collect(),
        })
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

/// The prescribed displacements of `[operating]`: each instead of its load.
fn prescribed(op: &RawOperating) -> Result<[Option<f64>; 5], Invalid> {
    let fixed = op.fixed_tilt.unwrap_or(false);
    let length = |q: &Option<Quantity<crate::units::Length>>| q.as_ref().map(|q| q.si);
    let angle = |q: &Option<Quantity<crate::units::Angle>>| q.as_ref().map(|q| q.si);
    let out = [
        length(&op.displacement_x),
        length(&op.displacement_y),
        length(&op.displacement_z),
        angle(&op.tilt_y).or(fixed.then_some(0.0)),
        angle(&op.tilt_z).or(fixed.then_some(0.0)),
    ];
    let loads = [
        ("force_x", op.force_x.is_some()),
        ("force_y", op.force_y.is_some() || op.radial_load.is_some()),
        ("force_z", op.force_z.is_some() || op.radial_load.is_some()),
        ("moment_y", op.moment_y.is_some()),
        ("moment_z", op.moment_z.is_some()),
    ];
    let names = [
        "displacement_x",
        "displacement_y",
        "displacement_z",
        "tilt_y",
        "tilt_z",
    ];
    let given = [
        op.displacement_x.is_some(),
        op.displacement_y.is_some(),
        op.displacement_z.is_some(),
        op.tilt_y.is_some(),
        op.tilt_z.is_some(),
    ];
    for k in 0..5 {
        if out[k].is_some() && loads[k].1 {
            let key = if given[k] { names[k] } else { "fixed_tilt" };
            return Err(Invalid::new(
                format!("operating.{key}"),
                None,
                format!(
                    "a ring displacement is either prescribed or follows its load: not with operating.{}",
                    loads[k].0
                ),
            ));
        }
    }
    if out.iter().any(Option::is_some) && op.load_profile.is_some() {
        return Err(Invalid::new(
            "operating.load_profile",
            None,
            "prescribed ring displacements are quasi-static: not with a load table",
        ));
    }
    Ok(out)
}

fn cage(c: &RawCage) -> Result<Cage, Invalid> {
    let cage = Cage {
        guidance: c.guidance,
        pocket_clearance: checked("cage.pocket_clearance", &c.pocket_clearance, positive)?,
        inner_diameter: checked("cage.inner_diameter", &c.inner_diameter, positive)?,
        outer_diameter: checked("cage.outer_diameter", &c.outer_diameter, positive)?,
        guide_land_width: checked("cage.guide_land_width", &c.guide_land_width, positive)?,
        guide_clearance: checked("cage.guide_clearance", &c.guide_clearance, positive)?,
        mass: checked("cage.mass", &c.mass, positive)?,
        inertia: checked("cage.inertia", &c.inertia, positive)?,
        pocket_stiffness: checked("cage.pocket_stiffness", &c.pocket_stiffness, positive)?,
        pocket_damping: checked("cage.pocket_damping", &c.pocket_damping, non_negative)?,
        pocket_friction: positive_number(
            "cage.pocket_friction",
            c.pocket_friction,
            |v| (0.0..=rolldyn::traction::MAX_FRICTION).contains(&v),
            "a friction coefficient must lie in [0, 5]",
        )?
        .unwrap_or(DEFAULT_POCKET_FRICTION),
        whirl: c.whirl.unwrap_or(true),
        pocket_shape: c.pocket_shape.unwrap_or_default(),
        pocket_law: c.pocket_law.unwrap_or(PocketLawChoice::Linear),
        pocket_wall_force: checked("cage.pocket_wall_force", &c.pocket_wall_force, non_negative)?
            .unwrap_or(GUPTA_WALL_FORCE),
        pocket_squeeze_film: c.pocket_squeeze_film.unwrap_or(false),
        pocket_min_film: checked("cage.pocket_min_film", &c.pocket_min_film, positive)?
            .unwrap_or(DEFAULT_POCKET_MIN_FILM),
        pocket_squeeze_cavitation: c.pocket_squeeze_cavitation.unwrap_or_default(),
        material: c
            .material
            .as_ref()
            .map(|m| material("cage.material", Some(m)))
            .transpose()?,
        unbalance: checked("cage.unbalance", &c.unbalance, non_negative)?.unwrap_or(0.0),
    };
    if let (Some(i), Some(o)) = (cage.inner_diameter, cage.outer_diameter) {
        if o <= i {
            return Err(Invalid::new(
                "cage.outer_diameter",
                text(&c.outer_diameter),
                format!(
                    "must exceed cage.inner_diameter ({})",
                    text(&c.inner_diameter).unwrap_or_default()
                ),
            ));
        }
    }
    Ok(cage)
}

fn material(key: &str, choice: Option<&MaterialChoice>) -> Result<NamedMaterial, Invalid> {
    match choice {
        None => Ok(NamedMaterial {
            name: "steel_52100".into(),
            material: Material::STEEL_52100,
        }),
        Some(MaterialChoice::Named(name)) => MATERIALS
            .iter()
            .find(|(n, _)| n == name)
            .map(|(n, m)| NamedMaterial {
                name: n.to_string(),
                material: *m,
            })
            .ok_or_else(|| {
                Invalid::new(
                    key,
                    Some(format!("\"{name}\"")),
                    format!(
                        "unknown material; built-in: {} (or give a table with elastic_modulus, poisson_ratio, density)",
                        MATERIALS.map(|m| m.0).join(", ")
                    ),
                )
            }),
        Some(MaterialChoice::Custom(m)) => {
            checked(&format!("{key}.elastic_modulus"), &Some(m.elastic_modulus.clone()), |v| {
                if (1e6..=1e13).contains(&v) {
                    Ok(())
                } else {
                    Err("must lie in [1 MPa, 10 TPa] (engineering solids)".into())
                }
            })?;
            checked(&format!("{key}.density"), &Some(m.density.clone()), |v| {
                if (1.0..=1e5).contains(&v) {
                    Ok(())
                } else {
                    Err("must lie in [1, 100 000] kg/m^3".into())
                }
            })?;
            positive_number(
                &format!("{key}.poisson_ratio"),
                Some(m.poisson_ratio),
                |v| v > -1.0 && v < 0.5,
                "Poisson's ratio must lie in (-1, 0.5)",
            )?;
            Ok(NamedMaterial {
                name: m.name.clone().unwrap_or_else(|| "custom".into()),
                material: Material {
                    elastic_modulus: m.elastic_modulus.si,
                    poisson_ratio: m.poisson_ratio,
                    density: m.density.si,
                },
            })
        }
    }
}
