//! `[shaft]` in SI: built-in or catalogue bearings at positions on one
//! rigid shaft and the loads on it, checked with the key of the offending
//! entry.

use super::{Invalid, checked};
use crate::catalogue::{CatalogueBearing, CatalogueError};
use crate::presets::Preset;
use crate::raw::{RawAxial, RawOrientation, RawShaft, RawShaftBearing, RawShaftLoad};
use rolldyn::operating::Loads;
use rolldyn::quasistatic::system::Orientation;
use std::borrow::Cow;

/// Friction coefficient of a floating bearing's outer ring in its housing
/// bore when the case gives none: steel on steel or cast iron, oiled
/// (0.1–0.2; an assumption, stated in docs/systems.md).
pub const DEFAULT_HOUSING_FRICTION: f64 = 0.1;

/// Largest distance of a bearing or a load from the reference point \[m\].
pub const MAX_SHAFT_POSITION: f64 = 10.0;

/// Largest preload offset of a shaft bearing \[m\].
pub const MAX_PRELOAD_OFFSET: f64 = 1e-3;

/// Where a shaft bearing's geometry and settings come from.
#[derive(Debug, Clone, PartialEq)]
pub enum BearingSource {
    /// A built-in bearing (`rolldyn presets`).
    Preset(&'static Preset),
    /// A catalogue bearing (docs/catalogue.md), its clearance group given.
    Catalogue(CatalogueBearing),
    /// A bearing given inline: its case text (its `[bearing]` table and
    /// any `materials`, `cage`, `lubricant`, `model` and `inner_ring`
    /// tables) and its
    /// name in messages.
    Inline {
        /// `shaft.bearings[i]`, or its designation.
        name: String,
        /// A case of those tables alone.
        text: String,
    },
}

impl BearingSource {
    /// The case text the bearing is solved with: a preset or catalogue
    /// bearing without its own mounting (the shaft mounts it).
    pub fn case_text(&self) -> Result<Cow<'static, str>, String> {
        let bare = crate::presets::without_mounting;
        match self {
            Self::Preset(p) => Ok(Cow::Owned(p.without_mounting())),
            Self::Catalogue(b) => b
                .case_text()
                .map(|t| Cow::Owned(bare(&t)))
                .map_err(|e| e.to_string()),
            Self::Inline { text, .. } => Ok(Cow::Owned(text.clone())),
        }
    }

    /// Its name in messages: the preset's name or the designation.
    pub fn name(&self) -> &str {
        match self {
            Self::Preset(p) => p.name,
            Self::Catalogue(b) => &b.designation,
            Self::Inline { name, .. } => name,
        }
    }

    /// The case key that named it.
    pub fn key(&self) -> &'static str {
        match self {
            Self::Preset(_) => "preset",
            Self::Catalogue(_) => "catalogue",
            Self::Inline { .. } => "bearing",
        }
    }
}

/// One bearing of the shaft.
#[derive(Debug, Clone, PartialEq)]
pub struct ShaftBearing {
    /// Its geometry and settings: a preset or a catalogue bearing.
    pub source: BearingSource,
    /// Axial position of its pitch plane \[m\].
    pub position: f64,
    /// Which thrust it carries.
    pub orientation: Orientation,
    /// Its outer ring slides in the housing (no thrust).
    pub floating: bool,
    /// Friction coefficient of a floating bearing's outer ring in its
    /// bore (a run's sliding ring; 0 for a located bearing).
    pub housing_friction: f64,
    /// Axial offset of its inner ring towards its loaded side at zero
    /// shaft displacement \[m\] (its preload displacement).
    pub preload_offset: f64,
    /// Its `[shaft.bearings.fits]` as a `[fits]` table, added to its case
    /// text (None: no fits).
    pub fits: Option<String>,
}

impl ShaftBearing {
    /// The case text the bearing is solved with: its source's, with its
    /// fits.
    pub fn case_text(&self) -> Result<Cow<'static, str>, String> {
        let text = self.source.case_text()?;
        Ok(match &self.fits {
            None => text,
            Some(fits) => Cow::Owned(format!("{text}\n{fits}")),
        })
    }
}

/// `[shaft]`, checked.
#[derive(Debug, Clone, PartialEq)]
pub struct Shaft {
    /// The bearings, in the case's order.
    pub bearings: Vec<ShaftBearing>,
    /// The `[[shaft.loads]]` as one load about the reference point x = 0
    /// (a force F at x = a adds the moments M_y = −a F_z, M_z = a F_y).
    pub loads: Loads,
    /// The `[[shaft.loads]]` each at its position (x \[m\], load there).
    pub point_loads: Vec<(f64, Loads)>,
    /// The loads' fluctuations with the shaft's angle (gear meshes; in
    /// runs).
    pub harmonic_loads: Vec<rolldyn::dynamics::shaft::HarmonicLoad>,
    /// The elastic shaft's section (None: rigid).
    pub section: Option<rolldyn::quasistatic::elastic_shaft::ShaftSection>,
}

fn position(key: String, q: &crate::units::Quantity<crate::units::Length>) -> Result<f64, Invalid> {
    checked(&key, &Some(q.clone()), |v| {
        if v.abs() <= MAX_SHAFT_POSITION {
            Ok(())
        } else {
            Err(format!(
                "must lie within ±{MAX_SHAFT_POSITION} m of the reference point"
            ))
        }
    })
    .map(|v| v.unwrap_or(0.0))
}

/// Young's modulus of an elastic shaft without `shaft.elastic_modulus`
/// \[Pa\]: steel.
pub const DEFAULT_SHAFT_MODULUS: f64 = 206e9;

pub(super) fn shaft(raw: &Option<RawShaft>) -> Result<Option<Shaft>, Invalid> {
    let Some(raw) = raw else { return Ok(None) };
    if raw.bearings.is_empty() {
        return Err(Invalid::new(
            "shaft.bearings",
            None,
            "[shaft] needs at least one [[shaft.bearings]] entry with its preset and position",
        ));
    }
    let mut bearings = Vec::with_capacity(raw.bearings.len());
    for (i, b) in raw.bearings.iter().enumerate() {
        bearings.push(shaft_bearing(i, b, &bearings)?);
    }
    if bearings.iter().all(|b| b.floating) {
        return Err(Invalid::new(
            "shaft.bearings",
            None,
            "every bearing floats: at least one must locate the shaft axially (axial = \"located\")",
        ));
    }
    let (loads, point_loads, harmonic_loads) = shaft_loads(&raw.loads)?;
    let section = shaft_section(raw)?;
    Ok(Some(Shaft {
        bearings,
        loads,
        point_loads,
        harmonic_loads,
        section,
    }))
}

/// One `[[shaft.bearings]]` entry, checked (`placed`: the bearings
/// before it, whose pitch planes it must not share).
fn shaft_bearing(
    i: usize,
    b: &RawShaftBearing,
    placed: &[ShaftBearing],
) -> Result<ShaftBearing, Invalid> {
    let key = |name: &str| format!("shaft.bearings[{i}].{name}");
    if let (Some(group), None) = (&b.clearance_group, &b.catalogue) {
        return Err(Invalid::new(
            key("clearance_group"),
            Some(group.clone()),
            "a clearance group applies to a catalogue bearing (catalogue = \"6206\"; inline: bearing.catalogue with bearing.clearance_group)",
        ));
    }
    // The tables that complete an inline bearing.
    let with_inline = [
        ("materials", b.materials.is_some()),
        ("cage", b.cage.is_some()),
        ("lubricant", b.lubricant.is_some()),
        ("model", b.model.is_some()),
        ("inner_ring", b.inner_ring.is_some()),
    ];
    if let (None, Some((table, _))) = (&b.bearing, with_inline.iter().find(|(_, given)| *given)) {
        return Err(Invalid::new(
            key(table),
            None,
            "applies to an inline bearing ([shaft.bearings.bearing]); a preset or catalogue bearing brings its own",
        ));
    }
    let source = bearing_source(i, b)?;
    let at = position(key("position"), &b.position)?;
    if let Some(j) = placed
        .iter()
        .position(|o: &ShaftBearing| (o.position - at).abs() < 1e-6)
    {
        return Err(Invalid::new(
            key("position"),
            Some(b.position.to_string()),
            format!("bearing {j} sits there already (pitch planes at least 1 µm apart)"),
        ));
    }
    let floating = b.axial == Some(RawAxial::Floating);
    let housing_friction = match b.housing_friction {
        None => {
            if floating {
                DEFAULT_HOUSING_FRICTION
            } else {
                0.0
            }
        }
        Some(_) if !floating => {
            return Err(Invalid::new(
                key("housing_friction"),
                b.housing_friction.map(|v| v.to_string()),
                "only a floating bearing's outer ring slides in its bore (axial = \"floating\")",
            ));
        }
        Some(v) if !(v.is_finite() && (0.0..=1.0).contains(&v)) => {
            return Err(Invalid::new(
                key("housing_friction"),
                Some(v.to_string()),
                "must lie in [0, 1]",
            ));
        }
        Some(v) => v,
    };
    let preload_offset = checked(&key("preload_offset"), &b.preload_offset, |v| {
        if floating && v != 0.0 {
            Err("a floating bearing takes no preload (its outer ring slides)".into())
        } else if (0.0..=MAX_PRELOAD_OFFSET).contains(&v) {
            Ok(())
        } else {
            Err(format!(
                "must lie in [0, {} mm] (towards the bearing's loaded side)",
                MAX_PRELOAD_OFFSET * 1e3
            ))
        }
    })?
    .unwrap_or(0.0);
    Ok(ShaftBearing {
        source,
        position: at,
        orientation: match b.orientation {
            None | Some(RawOrientation::Forward) => Orientation::Forward,
            Some(RawOrientation::Reversed) => Orientation::Reversed,
        },
        floating,
        housing_friction,
        preload_offset,
        fits: b
            .fits
            .as_ref()
            .map(|fits| {
                #[derive(serde::Serialize)]
                struct Fits<'a> {
                    fits: &'a crate::raw::RawFits,
                }
                toml::to_string(&Fits { fits })
                    .map_err(|e| Invalid::new(key("fits"), None, e.to_string()))
            })
            .transpose()?,
    })
}

/// Where entry `i`'s bearing comes from: a preset, a catalogue bearing or
/// an inline table (with the tables that complete it, as TOML text).
fn bearing_source(i: usize, b: &RawShaftBearing) -> Result<BearingSource, Invalid> {
    let key = |name: &str| format!("shaft.bearings[{i}].{name}");
    Ok(match (&b.preset, &b.catalogue, &b.bearing) {
        (Some(name), None, None) => {
            BearingSource::Preset(crate::presets::find(name).ok_or_else(|| {
                Invalid::new(
                    key("preset"),
                    Some(name.clone()),
                    format!(
                        "unknown bearing; built-in bearings: {}",
                        crate::presets::names()
                    ),
                )
            })?)
        }
        (None, Some(designation), None) => BearingSource::Catalogue(
            CatalogueBearing::lookup(designation, b.clearance_group.as_deref()).map_err(|e| {
                match &e {
                    CatalogueError::Designation { designation, .. } => {
                        Invalid::new(key("catalogue"), Some(designation.clone()), e.to_string())
                    }
                    CatalogueError::Clearance { group, .. } => {
                        Invalid::new(key("clearance_group"), Some(group.clone()), e.to_string())
                    }
                }
            })?,
        ),
        (None, None, Some(bearing)) => {
            #[derive(serde::Serialize)]
            struct Inline<'a> {
                bearing: &'a crate::raw::RawBearing,
                #[serde(skip_serializing_if = "Option::is_none")]
                materials: &'a Option<crate::raw::RawMaterials>,
                #[serde(skip_serializing_if = "Option::is_none")]
                cage: &'a Option<crate::raw::RawCage>,
                #[serde(skip_serializing_if = "Option::is_none")]
                lubricant: &'a Option<crate::raw::RawLubricant>,
                #[serde(skip_serializing_if = "Option::is_none")]
                model: &'a Option<crate::raw::RawModel>,
                #[serde(skip_serializing_if = "Option::is_none")]
                inner_ring: &'a Option<crate::raw::RawInnerRing>,
            }
            let text = toml::to_string(&Inline {
                bearing,
                materials: &b.materials,
                cage: &b.cage,
                lubricant: &b.lubricant,
                model: &b.model,
                inner_ring: &b.inner_ring,
            })
            .map_err(|e| Invalid::new(key("bearing"), None, e.to_string()))?;
            BearingSource::Inline {
                name: bearing
                    .designation
                    .clone()
                    .unwrap_or_else(|| format!("shaft.bearings[{i}]")),
                text,
            }
        }
        _ => {
            return Err(Invalid::new(
                key("preset"),
                None,
                "name the bearing once: by preset (rolldyn presets), catalogue (rolldyn catalogue) or an inline [shaft.bearings.bearing] table",
            ));
        }
    })
}

/// The `[[shaft.loads]]`: their sum about the reference point, each
/// with its position, and their gear-mesh fluctuations.
type ShaftLoads = (
    Loads,
    Vec<(f64, Loads)>,
    Vec<rolldyn::dynamics::shaft::HarmonicLoad>,
);

fn shaft_loads(raw: &[RawShaftLoad]) -> Result<ShaftLoads, Invalid> {
    let mut loads = Loads::default();
    let mut point_loads = Vec::with_capacity(raw.len());
    let mut harmonic_loads = Vec::new();
    for (i, l) in raw.iter().enumerate() {
        let key = |name: &str| format!("shaft.loads[{i}].{name}");
        let a = position(key("position"), &l.position)?;
        let force = |name: &str, q: &Option<crate::units::Quantity<crate::units::Force>>| {
            checked(&key(name), q, |_| Ok(())).map(|v| v.unwrap_or(0.0))
        };
        let (fx, fy, fz) = (
            force("force_x", &l.force_x)?,
            force("force_y", &l.force_y)?,
            force("force_z", &l.force_z)?,
        );
        let moment = |name: &str, q: &Option<crate::units::Quantity<crate::units::Moment>>| {
            checked(&key(name), q, |_| Ok(())).map(|v| v.unwrap_or(0.0))
        };
        let (my, mz) = (
            moment("moment_y", &l.moment_y)?,
            moment("moment_z", &l.moment_z)?,
        );
        loads.force[0] += fx;
        loads.force[1] += fy;
        loads.force[2] += fz;
        loads.moment[0] += my - a * fz;
        loads.moment[1] += mz + a * fy;
        point_loads.push((
            a,
            Loads {
                force: [fx, fy, fz],
                moment: [my, mz],
            },
        ));
        if let Some(h) = harmonic_load(i, l, a, [fx, fy, fz])? {
            harmonic_loads.push(h);
        }
    }
    Ok((loads, point_loads, harmonic_loads))
}

/// The gear-mesh fluctuation of load `i` at position `a` with forces
/// `force`, if it has one.
fn harmonic_load(
    i: usize,
    l: &RawShaftLoad,
    a: f64,
    [fx, fy, fz]: [f64; 3],
) -> Result<Option<rolldyn::dynamics::shaft::HarmonicLoad>, Invalid> {
    let key = |name: &str| format!("shaft.loads[{i}].{name}");
    match (l.mesh_order, l.mesh_fluctuation) {
        (None, None) => Ok(None),
        (Some(order), Some(fluctuation)) => {
            if !(order.is_finite() && order > 0.0) {
                return Err(Invalid::new(
                    key("mesh_order"),
                    Some(order.to_string()),
                    "must be positive (the gear's tooth count)",
                ));
            }
            if !(0.0..=1.0).contains(&fluctuation) {
                return Err(Invalid::new(
                    key("mesh_fluctuation"),
                    Some(fluctuation.to_string()),
                    "must lie in [0, 1] (a fraction of the force)",
                ));
            }
            Ok(Some(rolldyn::dynamics::shaft::HarmonicLoad {
                position: a,
                amplitude: [fx, fy, fz].map(|f| fluctuation * f),
                order,
                phase: 0.0,
            }))
        }
        (Some(_), None) => Err(Invalid::new(
            key("mesh_fluctuation"),
            None,
            "missing: a mesh_order needs the fluctuation's amplitude as a fraction of the force",
        )),
        (None, Some(_)) => Err(Invalid::new(
            key("mesh_order"),
            None,
            "missing: a mesh_fluctuation needs the gear's tooth count",
        )),
    }
}

/// The elastic shaft's section (`shaft.diameter`), or None for a rigid
/// shaft.
fn shaft_section(
    raw: &RawShaft,
) -> Result<Option<rolldyn::quasistatic::elastic_shaft::ShaftSection>, Invalid> {
    Ok(
        match checked("shaft.diameter", &raw.diameter, super::positive)? {
            None => {
                for (key, given) in [
                    ("shaft.bore", raw.bore.is_some()),
                    ("shaft.elastic_modulus", raw.elastic_modulus.is_some()),
                ] {
                    if given {
                        return Err(Invalid::new(
                            key,
                            None,
                            "describes an elastic shaft: give shaft.diameter too (without it the shaft is rigid)",
                        ));
                    }
                }
                None
            }
            Some(diameter) => {
                let bore = checked("shaft.bore", &raw.bore, |v| {
                    if (0.0..diameter).contains(&v) {
                        Ok(())
                    } else {
                        Err(format!("must lie in [0, shaft.diameter = {diameter} m)"))
                    }
                })?
                .unwrap_or(0.0);
                let elastic_modulus = checked(
                    "shaft.elastic_modulus",
                    &raw.elastic_modulus,
                    super::positive,
                )?
                .unwrap_or(DEFAULT_SHAFT_MODULUS);
                Some(rolldyn::quasistatic::elastic_shaft::ShaftSection {
                    diameter,
                    bore,
                    elastic_modulus,
                })
            }
        },
    )
}
