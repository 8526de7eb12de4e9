//! How the bearing is lubricated (`[lubrication]`, docs/lubrication.md):
//! the method (oil bath with its level, oil jet, air–oil, grease) and its
//! churning, and the EHL rolling resistance of the lubricated contacts.

use super::{Invalid, checked, non_negative};
use crate::raw::{RawLubrication, RollingResistanceChoice};
use rolldyn::lubrication::churning::{
    ANGULAR_CONTACT_TYPE_CONSTANT, Bath, Churning, DEEP_GROOVE_TYPE_CONSTANT,
};
use rolldyn::lubrication::rolling_resistance::{
    DEFAULT_TEMPERATURE_VISCOSITY, InletHeating, REPLENISHMENT_GREASE, REPLENISHMENT_OIL,
    Replenishment, RollingForceLaw, RollingResistance,
};
use rolldyn::{BearingGeometry, Clearance};

pub use crate::raw::Method;

/// `[lubrication]` in SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lubrication {
    /// The method.
    pub method: Method,
    /// An oil bath's level above the lowest point of the outer ring's
    /// raceway \[m\].
    pub oil_level: Option<f64>,
    /// Whether the lubricated contacts have the EHL rolling resistance.
    pub rolling_resistance: bool,
    /// Its rolling-force fit.
    pub rolling_force_law: RollingForceLaw,
    /// Whether the rolling resistance has Aihara's inlet-heating factor.
    pub inlet_heating: bool,
}

impl Default for Lubrication {
    fn default() -> Self {
        Self {
            method: Method::None,
            oil_level: None,
            rolling_resistance: true,
            rolling_force_law: RollingForceLaw::Houpert,
            inlet_heating: true,
        }
    }
}

/// Checks `[lubrication]` against the bearing and the lubricant.
pub(super) fn lubrication(
    raw: Option<&RawLubrication>,
    geometry: &BearingGeometry,
    lubricant: Option<&super::Lubricant>,
) -> Result<Lubrication, Invalid> {
    let Some(raw) = raw else {
        return Ok(Lubrication::default());
    };
    let method = raw.method.unwrap_or_default();
    let oil_level = checked("lubrication.oil_level", &raw.oil_level, non_negative)?;
    let height = geometry.outer.groove_bottom_diameter;
    match (method, oil_level) {
        (Method::OilBath, None) => {
            return Err(Invalid::missing(
                "lubrication.oil_level",
                "an oil bath needs its level above the lowest point of the outer ring's raceway, e.g. \"5 mm\" (SKF: about the lowest ball's centre); give it with the method (two --set overrides together, or Case.with_values in Python)",
            ));
        }
        (Method::OilBath, Some(h)) if h > height => {
            return Err(Invalid::new(
                "lubrication.oil_level",
                raw.oil_level.as_ref().map(|q| q.to_string()),
                format!(
                    "the oil level lies above the bearing: at most the outer raceway's diameter, {:.4} mm",
                    height * 1e3
                ),
            ));
        }
        (Method::OilBath, _) | (_, None) => {}
        (_, Some(_)) => {
            return Err(Invalid::new(
                "lubrication.oil_level",
                raw.oil_level.as_ref().map(|q| q.to_string()),
                "only an oil bath has a level: set lubrication.method = \"oil_bath\" with it, or remove the level",
            ));
        }
    }
    if method != Method::None && lubricant.is_none() {
        return Err(Invalid::missing(
            "lubricant.viscosity",
            "a lubrication method needs the oil's properties: add a [lubricant] section",
        ));
    }
    if method == Method::Grease && lubricant.is_some_and(|l| l.oil_flow.is_some()) {
        return Err(Invalid::new(
            "lubricant.oil_flow",
            lubricant
                .and_then(|l| l.oil_flow)
                .map(|f| format!("{f} m^3/s")),
            "a greased bearing has no oil supply flow: remove lubricant.oil_flow or choose oil_jet or air_oil",
        ));
    }
    let (rolling_resistance, rolling_force_law) = match raw.rolling_resistance {
        None => (true, RollingForceLaw::Houpert),
        Some(RollingResistanceChoice::None) => (false, RollingForceLaw::Houpert),
        Some(choice) => {
            if lubricant.is_none() {
                return Err(Invalid::missing(
                    "lubricant.viscosity",
                    "the EHL rolling resistance needs the oil's properties: add a [lubricant] section",
                ));
            }
            let law = match choice {
                RollingResistanceChoice::BibouletHoupert => RollingForceLaw::BibouletHoupert,
                _ => RollingForceLaw::Houpert,
            };
            (true, law)
        }
    };
    Ok(Lubrication {
        method,
        oil_level,
        rolling_resistance,
        rolling_force_law,
        inlet_heating: raw.inlet_heating.unwrap_or(true),
    })
}

impl super::Case {
    /// The EHL rolling resistance of the case's lubricated contacts (None
    /// without a `[lubricant]` or with `lubrication.rolling_resistance =
    /// "none"`): the lubricant at its reference temperature; inlet
    /// heating with the Walther law's slope there (else
    /// [`DEFAULT_TEMPERATURE_VISCOSITY`]) and the oil's conductivity (else
    /// [`super::DEFAULT_OIL`]'s); with a lubrication method, SKF's kinematic
    /// replenishment of a flooded supply (needs the bore and outside
    /// diameter).
    pub fn rolling_resistance(&self) -> Result<Option<RollingResistance>, Invalid> {
        let Some(l) = self.lubricant.as_ref() else {
            return Ok(None);
        };
        if !self.lubrication.rolling_resistance {
            return Ok(None);
        }
        let heating = self.lubrication.inlet_heating.then(|| InletHeating {
            temperature_viscosity: match (&l.viscosity_law, l.temperature) {
                (Some(w), Some(t)) => w.temperature_coefficient(t),
                _ => DEFAULT_TEMPERATURE_VISCOSITY,
            },
            conductivity: self.oil_properties().2,
        });
        let constant = match self.lubrication.method {
            Method::None => None,
            Method::OilBath | Method::OilJet => Some(REPLENISHMENT_OIL),
            Method::AirOil | Method::Grease => Some(REPLENISHMENT_GREASE),
        };
        let replenishment = match constant {
            None => None,
            Some(constant) => {
                let (bore, outside_diameter) = self.bore_and_outside_diameter(
                    "the kinematic replenishment of a lubrication method (SKF's φ_rs) needs the bearing's bore and outside diameter",
                )?;
                Some(Replenishment {
                    constant,
                    bore,
                    outside_diameter,
                    type_constant: self.type_constant(),
                    density: self.oil_properties().0,
                })
            }
        };
        Ok(Some(RollingResistance {
            law: self.lubrication.rolling_force_law,
            lubricant: rolldyn::lubrication::Lubricant {
                viscosity: l.viscosity,
                pressure_viscosity: l.pressure_viscosity,
                pressure_model: l.pressure_viscosity_model,
            },
            heating,
            replenishment,
        }))
    }

    /// K_z by the bearing's parametrization: 4.4 (single-row
    /// angular-contact) when given by its free contact angle, else 3.1
    /// (deep-groove).
    fn type_constant(&self) -> f64 {
        match self.bearing.geometry.clearance {
            Clearance::FreeContactAngle(_) => ANGULAR_CONTACT_TYPE_CONSTANT,
            _ => DEEP_GROOVE_TYPE_CONSTANT,
        }
    }

    /// `bearing.bore` and `bearing.outside_diameter` \[m\], or an error
    /// saying `why` they are needed.
    fn bore_and_outside_diameter(&self, why: &str) -> Result<(f64, f64), Invalid> {
        let need = |v: Option<f64>, key: &str| v.ok_or_else(|| Invalid::missing(key, why));
        Ok((
            need(self.bearing.bore, "bearing.bore")?,
            need(self.bearing.outside_diameter, "bearing.outside_diameter")?,
        ))
    }

    /// The churning of an oil bath or jet (None for the other methods).
    /// Needs the bore and outside diameter.
    pub fn churning(&self) -> Result<Option<Churning>, Invalid> {
        let bath = match (self.lubrication.method, self.lubrication.oil_level) {
            (super::lubrication::Method::OilBath, Some(h)) => Bath::Level(h),
            (super::lubrication::Method::OilJet, _) => Bath::Jet,
            _ => return Ok(None),
        };
        let (bore, outside_diameter) = self.bore_and_outside_diameter(
            "the churning of an oil bath or jet (SKF's drag model) needs the bearing's bore and outside diameter",
        )?;
        let (density, _, _) = self.oil_properties();
        Ok(Some(Churning {
            bore,
            outside_diameter,
            ball_diameter: self.bearing.geometry.ball_diameter,
            type_constant: self.type_constant(),
            bath,
            viscosity: self.lubricant.as_ref().map_or(0.0, |l| l.viscosity),
            density,
        }))
    }

    /// The note a lubricated case without a method gets (None otherwise).
    pub fn lubrication_note(&self) -> Option<String> {
        (self.lubricant.is_some() && self.lubrication.method == Method::None).then(|| {
            "the case has a [lubricant] but no lubrication.method: no churning or bath drag is counted (set lubrication.method = \"oil_bath\", \"oil_jet\", \"air_oil\" or \"grease\")".to_string()
        })
    }
}
