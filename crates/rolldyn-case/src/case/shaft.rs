//! `[shaft]` in SI: built-in bearings at positions on one rigid shaft and
//! the loads on it, checked with the key of the offending entry.

use super::{Invalid, checked};
use crate::raw::{RawAxial, RawOrientation, RawShaft};
use rolldyn::operating::Loads;
use rolldyn::quasistatic::system::Orientation;

/// Largest distance of a bearing or a load from the reference point \[m\].
pub const MAX_SHAFT_POSITION: f64 = 10.0;

/// One bearing of the shaft.
#[derive(Debug, Clone, PartialEq)]
pub struct ShaftBearing {
    /// The preset's name, as `rolldyn presets` lists it.
    pub preset: &'static str,
    /// Axial position of its pitch plane \[m\].
    pub position: f64,
    /// Which thrust it carries.
    pub orientation: Orientation,
    /// Its outer ring slides in the housing (no thrust).
    pub floating: bool,
}

/// `[shaft]`, checked.
#[derive(Debug, Clone, PartialEq)]
pub struct Shaft {
    /// The bearings, in the case's order.
    pub bearings: Vec<ShaftBearing>,
    /// The `[[shaft.loads]]` as one load about the reference point x = 0
    /// (a force F at x = a adds the moments M_y = −a F_z, M_z = a F_y).
    pub loads: Loads,
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
        let key = |name: &str| format!("shaft.bearings[{i}].{name}");
        let preset = crate::presets::find(&b.preset).ok_or_else(|| {
            Invalid::new(
                key("preset"),
                Some(b.preset.clone()),
                format!(
                    "unknown bearing; built-in bearings: {}",
                    crate::presets::names()
                ),
            )
        })?;
        let at = position(key("position"), &b.position)?;
        if let Some(j) = bearings
            .iter()
            .position(|o: &ShaftBearing| (o.position - at).abs() < 1e-6)
        {
            return Err(Invalid::new(
                key("position"),
                Some(b.position.to_string()),
                format!("bearing {j} sits there already (pitch planes at least 1 µm apart)"),
            ));
        }
        bearings.push(ShaftBearing {
            preset: preset.name,
            position: at,
            orientation: match b.orientation {
                None | Some(RawOrientation::Forward) => Orientation::Forward,
                Some(RawOrientation::Reversed) => Orientation::Reversed,
            },
            floating: b.axial == Some(RawAxial::Floating),
        });
    }
    if bearings.iter().all(|b| b.floating) {
        return Err(Invalid::new(
            "shaft.bearings",
            None,
            "every bearing floats: at least one must locate the shaft axially (axial = \"located\")",
        ));
    }
    let mut loads = Loads::default();
    for (i, l) in raw.loads.iter().enumerate() {
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
        loads.force[0] += fx;
        loads.force[1] += fy;
        loads.force[2] += fz;
        loads.moment[0] -= a * fz;
        loads.moment[1] += a * fy;
    }
    Ok(Some(Shaft { bearings, loads }))
}
