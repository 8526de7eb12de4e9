//! `[power]` and `[thermal]` in SI (Lei et al. 2023; docs/model.md §10), and the inputs
//! of Harris's local method, the bearing's thermal network and the coupled
//! iteration built from the whole case. Defaults are documented in
//! docs/thermal.md and reported by `rolldyn thermal`.

use super::{Case, Invalid, checked, positive};
use crate::raw::{RawPower, RawThermal};
use crate::units::{Dimension, Quantity};
use rolldyn::power::LocalMethodInputs;
use rolldyn::power::harris::LubricatedContacts;
use rolldyn::quasistatic::films::FilmInputs;
use rolldyn::thermal::ThermalInputs;
use rolldyn::thermal::bearing::Solid;
use rolldyn::thermal::coupled::Expansion;
use rolldyn::traction::TractionModel;

/// `[power]` in SI.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Power {
    /// Sliding friction f_s, if given.
    pub sliding_friction: Option<f64>,
}

/// `[thermal]` in SI; None where the default depends on other sections.
#[derive(Debug, Clone, PartialEq)]
pub struct Thermal {
    /// Ambient temperature \[K\].
    pub ambient_temperature: f64,
    /// Oil inlet temperature \[K\], if given.
    pub oil_inlet_temperature: Option<f64>,
    /// Oil flow \[m³/s\], if given.
    pub oil_flow: Option<f64>,
    /// Housing outside diameter \[m\], if given.
    pub housing_diameter: Option<f64>,
    /// Housing width \[m\], if given.
    pub housing_width: Option<f64>,
    /// Shaft length in air each side \[m\], if given.
    pub shaft_length: Option<f64>,
    /// Housing–air convection \[W/(m²K)\].
    pub housing_convection: f64,
    /// Shaft–air convection \[W/(m²K)\].
    pub shaft_convection: f64,
    /// Balls and rings to oil \[W/(m²K)\], if given.
    pub oil_convection: Option<f64>,
    /// Ring and shaft.
    pub ring: Solid,
    /// Balls.
    pub ball: Solid,
    /// Housing.
    pub housing: Solid,
    /// Expansion coefficients and reference temperature.
    pub expansion: Expansion,
    /// Shaft and housing expansion coefficients of a set's axial growth
    /// \[1/K\] (docs/systems.md).
    pub shaft_housing_expansion: [f64; 2],
    /// Coupled to `rolldyn run`: the update interval \[s\] (None: not coupled).
    pub run_coupling: Option<f64>,
    /// A coupled run starts with every part at the ambient temperature
    /// (`thermal.run_start = "ambient"`) instead of the steady state.
    pub run_from_ambient: bool,
}

/// Default update interval of the run coupling \[s\].
pub const DEFAULT_UPDATE_INTERVAL: f64 = 1e-3;

/// Silicon nitride: k = 30 W/(m·K), c = 690 J/(kg·K), α = 3.2e-6 1/K
/// (typical hot-pressed Si₃N₄ bearing grade, ASTM F2094 class data).
const SILICON_NITRIDE: (f64, f64, f64) = (30.0, 690.0, 3.2e-6);
/// AISI 52100: α = 11.9e-6 1/K (ASM handbook, 20–100 °C).
const STEEL_EXPANSION: f64 = 11.9e-6;
/// Default convection of housing and shaft to still air \[W/(m²K)\]
/// (natural convection, Incropera & DeWitt Table 1.1: 2–25).
pub const DEFAULT_AIR_CONVECTION: f64 = 15.0;

pub(super) fn power(p: &RawPower) -> Result<Power, Invalid> {
    if let Some(f) = p.sliding_friction {
        if !(f.is_finite() && (0.0..=1.0).contains(&f)) {
            return Err(Invalid::new(
                "power.sliding_friction",
                Some(f.to_string()),
                "must lie in [0, 1]",
            ));
        }
    }
    Ok(Power {
        sliding_friction: p.sliding_friction,
    })
}

/// A positive quantity, or `default` when absent.
fn positive_or<D: Dimension>(
    key: &str,
    q: &Option<Quantity<D>>,
    default: f64,
) -> Result<f64, Invalid> {
    Ok(checked(key, q, positive)?.unwrap_or(default))
}

/// The rings', balls' and housing's thermal properties (steel, or
/// silicon nitride balls), changed by the keys that give them, and the
/// balls' default expansion coefficient.
struct Solids {
    ring: Solid,
    ball: Solid,
    housing: Solid,
    ball_expansion: f64,
}

fn solids(t: &RawThermal, ceramic: bool) -> Result<Solids, Invalid> {
    let steel = Solid::STEEL;
    let ring = Solid {
        conductivity: positive_or(
            "thermal.ring_conductivity",
            &t.ring_conductivity,
            steel.conductivity,
        )?,
        specific_heat: positive_or(
            "thermal.ring_specific_heat",
            &t.ring_specific_heat,
            steel.specific_heat,
        )?,
        density: steel.density,
    };
    let (k_b, c_b, a_b) = if ceramic {
        SILICON_NITRIDE
    } else {
        (steel.conductivity, steel.specific_heat, STEEL_EXPANSION)
    };
    let ball = Solid {
        conductivity: positive_or("thermal.ball_conductivity", &t.ball_conductivity, k_b)?,
        specific_heat: positive_or("thermal.ball_specific_heat", &t.ball_specific_heat, c_b)?,
        density: if ceramic { 3200.0 } else { steel.density },
    };
    let housing = Solid {
        conductivity: positive_or(
            "thermal.housing_conductivity",
            &t.housing_conductivity,
            steel.conductivity,
        )?,
        ..steel
    };
    Ok(Solids {
        ring,
        ball,
        housing,
        ball_expansion: a_b,
    })
}

pub(super) fn thermal(t: &RawThermal, ball_material: &str) -> Result<Thermal, Invalid> {
    if t.run_start.is_some() && !t.run_coupling.unwrap_or(false) {
        return Err(Invalid::new(
            "thermal.run_start",
            None,
            "is used only with thermal.run_coupling = true",
        ));
    }
    if t.update_interval.is_some() && !t.run_coupling.unwrap_or(false) {
        return Err(Invalid::new(
            "thermal.update_interval",
            t.update_interval.as_ref().map(|q| q.to_string()),
            "is used only with thermal.run_coupling = true",
        ));
    }
    let temperature = |key: &str, q| {
        checked(key, q, |v| {
            if v > 0.0 {
                Ok(())
            } else {
                Err("must be above absolute zero".into())
            }
        })
    };
    let Solids {
        ring,
        ball,
        housing,
        ball_expansion,
    } = solids(t, ball_material == "silicon_nitride")?;
    let ambient =
        temperature("thermal.ambient_temperature", &t.ambient_temperature)?.unwrap_or(293.15);
    let ring_expansion = checked(
        "thermal.ring_expansion",
        &t.ring_expansion,
        super::non_negative,
    )?
    .unwrap_or(STEEL_EXPANSION);
    Ok(Thermal {
        ambient_temperature: ambient,
        oil_inlet_temperature: temperature(
            "thermal.oil_inlet_temperature",
            &t.oil_inlet_temperature,
        )?,
        oil_flow: checked("thermal.oil_flow", &t.oil_flow, super::non_negative)?,
        housing_diameter: checked("thermal.housing_diameter", &t.housing_diameter, positive)?,
        housing_width: checked("thermal.housing_width", &t.housing_width, positive)?,
        shaft_length: checked("thermal.shaft_length", &t.shaft_length, super::non_negative)?,
        housing_convection: positive_or(
            "thermal.housing_convection",
            &t.housing_convection,
            DEFAULT_AIR_CONVECTION,
        )?,
        shaft_convection: checked(
            "thermal.shaft_convection",
            &t.shaft_convection,
            super::non_negative,
        )?
        .unwrap_or(DEFAULT_AIR_CONVECTION),
        oil_convection: checked("thermal.oil_convection", &t.oil_convection, positive)?,
        ring,
        ball,
        housing,
        run_coupling: if t.run_coupling.unwrap_or(false) {
            Some(
                checked("thermal.update_interval", &t.update_interval, positive)?
                    .unwrap_or(DEFAULT_UPDATE_INTERVAL),
            )
        } else {
            None
        },
        run_from_ambient: matches!(t.run_start, Some(crate::raw::RawThermalStart::Ambient)),
        shaft_housing_expansion: [
            checked(
                "thermal.shaft_expansion",
                &t.shaft_expansion,
                super::non_negative,
            )?
            .unwrap_or(ring_expansion),
            checked(
                "thermal.housing_expansion",
                &t.housing_expansion,
                super::non_negative,
            )?
            .unwrap_or(ring_expansion),
        ],
        expansion: Expansion {
            ring: ring_expansion,
            ball: checked(
                "thermal.ball_expansion",
                &t.ball_expansion,
                super::non_negative,
            )?
            .unwrap_or(ball_expansion),
            reference_temperature: temperature(
                "thermal.reference_temperature",
                &t.reference_temperature,
            )?
            .unwrap_or(293.15),
        },
    })
}

/// Typical mineral-oil properties used when `[lubricant]` lacks them
/// (density 870 kg/m³, c_p 1900 J/(kg·K), k 0.13 W/(m·K); e.g. ISO VG 32
/// turbine oil data sheets).
pub const DEFAULT_OIL: (f64, f64, f64) = (870.0, 1900.0, 0.13);
/// Kinematic viscosity of the oil without a `[lubricant]` \[m²/s\]: ISO VG 32
/// at 40 °C.
pub const DEFAULT_OIL_VISCOSITY: f64 = 32e-6;

impl Case {
    /// Sliding friction f_s of the local method: `power.sliding_friction`,
    /// else the traction model's full-sliding value.
    pub fn sliding_friction(&self) -> Result<f64, Invalid> {
        if let Some(f) = self.power.sliding_friction {
            return Ok(f);
        }
        match &self.traction {
            TractionModel::ModifiedCoulomb(c) => Ok(c.friction),
            TractionModel::Ehl(e) => Ok(e.limiting_shear_coefficient),
            TractionModel::TractionCurve(c) => Ok(c.d),
            TractionModel::Fastsim(f) => Ok(f.friction),
            TractionModel::ExactTable(t) => Ok(t.friction),
            TractionModel::None => Err(Invalid::missing(
                "power.sliding_friction",
                "the local power-loss method needs the sliding friction coefficient (the case has no traction model to take it from)",
            )),
        }
    }

    /// Inputs of Harris's local method from the case.
    pub fn local_method_inputs(&self) -> Result<LocalMethodInputs, Invalid> {
        let g = &self.bearing.geometry;
        Ok(LocalMethodInputs {
            sliding_friction: self.sliding_friction()?,
            hysteresis: self.rolling_hysteresis,
            pocket_friction: self.cage.pocket_friction,
            cage_weight: if self.gravity {
                self.cage.mass.unwrap_or(0.0) * super::STANDARD_GRAVITY
            } else {
                0.0
            },
            pocket_radius: g.pitch_diameter / 2.0,
            guide: self.guide_land_of(false)?,
            drag: self.drag,
            seals: self.seals,
            rolling_resistance: self.rolling_resistance()?.map(|model| LubricatedContacts {
                model,
                films: FilmInputs {
                    lubricant: model.lubricant,
                    supply: self
                        .lubricant
                        .as_ref()
                        .map_or(Default::default(), |l| l.supply),
                    roughness: [0.0; 2],
                    effective_modulus: rolldyn::material::effective_modulus(
                        &self.materials.ball.material,
                        &self.materials.rings.material,
                    ),
                },
            }),
            churning: self.churning()?,
        })
    }

    /// Oil density, specific heat and conductivity: the lubricant's, else
    /// [`DEFAULT_OIL`].
    pub fn oil_properties(&self) -> (f64, f64, f64) {
        let l = self.lubricant.as_ref();
        (
            l.and_then(|l| l.density).unwrap_or(DEFAULT_OIL.0),
            l.and_then(|l| l.specific_heat).unwrap_or(DEFAULT_OIL.1),
            l.and_then(|l| l.thermal_conductivity)
                .unwrap_or(DEFAULT_OIL.2),
        )
    }

    /// Inputs of the bearing's thermal network from the case (bore,
    /// outside diameter and width required).
    pub fn thermal_inputs(&self) -> Result<ThermalInputs, Invalid> {
        let b = &self.bearing;
        let need = |v: Option<f64>, key: &str| {
            v.ok_or_else(|| {
                Invalid::missing(
                    key,
                    "the thermal network needs the bearing's bore, outside diameter and width",
                )
            })
        };
        let (bore, outside, width) = (
            need(b.bore, "bearing.bore")?,
            need(b.outside_diameter, "bearing.outside_diameter")?,
            need(b.width, "bearing.width")?,
        );
        let t = &self.thermal;
        let (density, specific_heat, conductivity) = self.oil_properties();
        let lubricant = self.lubricant.as_ref();
        Ok(ThermalInputs {
            bore,
            outside_diameter: outside,
            width,
            ball_diameter: b.geometry.ball_diameter,
            pitch_diameter: b.geometry.pitch_diameter,
            ball_count: b.geometry.ball_count,
            ball: t.ball,
            ring: t.ring,
            housing: t.housing,
            housing_diameter: t.housing_diameter.unwrap_or(1.6 * outside),
            housing_width: t.housing_width.unwrap_or(2.0 * width),
            shaft_length: t.shaft_length.unwrap_or(width),
            ambient_temperature: t.ambient_temperature,
            oil_inlet_temperature: t
                .oil_inlet_temperature
                .or(lubricant.and_then(|l| l.temperature))
                .unwrap_or(t.ambient_temperature),
            oil_flow: t
                .oil_flow
                .or(lubricant.and_then(|l| l.oil_flow))
                .unwrap_or(0.0),
            oil_density: density,
            oil_specific_heat: specific_heat,
            oil_conductivity: conductivity,
            oil_kinematic_viscosity: lubricant
                .map_or(DEFAULT_OIL_VISCOSITY, |l| l.viscosity / density),
            housing_convection: t.housing_convection,
            shaft_convection: t.shaft_convection,
            oil_convection: t.oil_convection,
        })
    }
}
