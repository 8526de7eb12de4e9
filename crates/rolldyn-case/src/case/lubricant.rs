//! The case's lubricant (`[lubricant]`, docs/model.md §4): properties in SI and
//! the oil supply of each ring (fully flooded, an inlet distance ratio, or
//! an oil flow), Zhang et al. 2020 eqs 26–30.

use super::{Invalid, checked, non_negative, positive};
use crate::raw::RawLubricant;
use rolldyn::BearingGeometry;
use rolldyn::lubrication::Supply;
use rolldyn::thermal::Walther;

/// Lubricant in SI.
#[derive(Debug, Clone, PartialEq)]
pub struct Lubricant {
    /// Name.
    pub name: Option<String>,
    /// η₀ \[Pa·s\].
    pub viscosity: f64,
    /// α_p \[1/Pa\].
    pub pressure_viscosity: f64,
    /// Density \[kg/m³\].
    pub density: Option<f64>,
    /// Thermal conductivity \[W/(m·K)\].
    pub thermal_conductivity: Option<f64>,
    /// Specific heat \[J/(kg·K)\].
    pub specific_heat: Option<f64>,
    /// Reference temperature \[K\].
    pub temperature: Option<f64>,
    /// Pressure–viscosity law.
    pub pressure_viscosity_model: rolldyn::lubrication::PressureViscosity,
    /// Oil supply of the inner and outer raceway contacts (starvation).
    pub supply: [Supply; 2],
    /// Oil supply flow \[m³/s\], if given.
    pub oil_flow: Option<f64>,
    /// Viscosity–temperature law through (`temperature`, `viscosity`) and
    /// (`second_temperature`, `second_viscosity`), if both are given.
    pub viscosity_law: Option<Walther>,
}

pub(super) fn lubricant(
    l: &RawLubricant,
    geometry: &BearingGeometry,
) -> Result<Lubricant, Invalid> {
    let mut out = base(l, geometry)?;
    out.oil_flow = checked("lubricant.oil_flow", &l.oil_flow, positive)?;
    let second = (
        checked("lubricant.second_viscosity", &l.second_viscosity, positive)?,
        checked(
            "lubricant.second_temperature",
            &l.second_temperature,
            positive,
        )?,
    );
    out.viscosity_law = match second {
        (None, None) => None,
        (Some(eta2), Some(t2)) => {
            let t1 = out.temperature.ok_or_else(|| {
                Invalid::missing(
                    "lubricant.temperature",
                    "the viscosity–temperature law needs the temperature at which lubricant.viscosity holds",
                )
            })?;
            let density = out.density.unwrap_or(super::thermal::DEFAULT_OIL.0);
            Some(
                Walther::through((t1, out.viscosity), (t2, eta2), density).map_err(|e| {
                    Invalid::new(
                        "lubricant.second_viscosity",
                        l.second_viscosity.as_ref().map(|q| q.to_string()),
                        e.rule,
                    )
                })?,
            )
        }
        (Some(_), None) => {
            return Err(Invalid::missing(
                "lubricant.second_temperature",
                "lubricant.second_viscosity needs the temperature at which it holds",
            ));
        }
        (None, Some(_)) => {
            return Err(Invalid::missing(
                "lubricant.second_viscosity",
                "lubricant.second_temperature needs the viscosity at that temperature",
            ));
        }
    };
    Ok(out)
}

fn base(l: &RawLubricant, geometry: &BearingGeometry) -> Result<Lubricant, Invalid> {
    Ok(Lubricant {
        name: l.name.clone(),
        viscosity: checked("lubricant.viscosity", &Some(l.viscosity.clone()), positive)?
            .unwrap_or_default(),
        pressure_viscosity: checked(
            "lubricant.pressure_viscosity",
            &Some(l.pressure_viscosity.clone()),
            non_negative,
        )?
        .unwrap_or_default(),
        density: checked("lubricant.density", &l.density, positive)?,
        thermal_conductivity: checked(
            "lubricant.thermal_conductivity",
            &l.thermal_conductivity,
            positive,
        )?,
        specific_heat: checked("lubricant.specific_heat", &l.specific_heat, positive)?,
        temperature: checked("lubricant.temperature", &l.temperature, |t| {
            if t > 0.0 {
                Ok(())
            } else {
                Err("must be above absolute zero".into())
            }
        })?,
        pressure_viscosity_model: l.pressure_viscosity_model.unwrap_or_default(),
        supply: supply(l, geometry)?,
        oil_flow: None,
        viscosity_law: None,
    })
}

/// The supply per ring: `inlet_distance_ratio` (both rings) or its
/// `_inner`/`_outer` forms, or `oil_flow` (with the density for ν = η/ρ;
/// the inlet film on each ring's raceway radius, thrown by the inner ring's
/// speed as Zhang et al. 2020 eq 27 has it); fully flooded without any.
fn supply(l: &RawLubricant, geometry: &BearingGeometry) -> Result<[Supply; 2], Invalid> {
    let ratio = |key: &str, v: Option<f64>| -> Result<Option<Supply>, Invalid> {
        v.map(|r| {
            let s = Supply::InletDistance(r);
            s.validate()
                .map(|_| s)
                .map_err(|e| Invalid::new(format!("lubricant.{key}"), Some(r.to_string()), e.rule))
        })
        .transpose()
    };
    let both = ratio("inlet_distance_ratio", l.inlet_distance_ratio)?;
    let inner = ratio("inlet_distance_ratio_inner", l.inlet_distance_ratio_inner)?;
    let outer = ratio("inlet_distance_ratio_outer", l.inlet_distance_ratio_outer)?;
    if both.is_some() && (inner.is_some() || outer.is_some()) {
        return Err(Invalid::new(
            "lubricant.inlet_distance_ratio",
            None,
            "give inlet_distance_ratio (both rings) or the _inner/_outer forms, not both",
        ));
    }
    if let Some(flow) = &l.oil_flow {
        if both.or(inner).or(outer).is_some() {
            return Err(Invalid::new(
                "lubricant.oil_flow",
                Some(flow.to_string()),
                "give either oil_flow or an inlet distance ratio, not both",
            ));
        }
        checked("lubricant.oil_flow", &Some(flow.clone()), positive)?;
        let density = l.density.as_ref().map(|d| d.si).ok_or_else(|| {
            Invalid::missing(
                "lubricant.density",
                "the oil density (kinematic viscosity ν = η/ρ of the oil-flow supply)",
            )
        })?;
        let nu = l.viscosity.si / density;
        let at = |radius: f64| Supply::Flow {
            flow: flow.si,
            kinematic_viscosity: nu,
            radius,
        };
        return Ok([
            at(0.5 * geometry.inner.groove_bottom_diameter),
            at(0.5 * geometry.outer.groove_bottom_diameter),
        ]);
    }
    Ok([
        both.or(inner).unwrap_or_default(),
        both.or(outer).unwrap_or_default(),
    ])
}
