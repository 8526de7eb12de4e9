//! The bearing section of a case: its geometry from one of the
//! parametrizations of docs/model.md §2 (free contact angle, clearance or raceway
//! diameters), groove radii and the catalogue dimensions.

use super::{Bearing, Invalid, checked, positive, text};
use crate::raw::RawBearing;
use crate::raw::RawFits;
use crate::units::Quantity;
use rolldyn::{BearingGeometry, Clearance, GeometrySpec};

/// The parametrization groups of docs/model.md §2, by their keys.
pub const PARAMETRIZATIONS: [&[&str]; 3] = [
    &["free_contact_angle"],
    &["diametral_clearance"],
    &["inner_raceway_diameter", "outer_raceway_diameter"],
];

fn groove(
    ring: &str,
    curvature: Option<f64>,
    radius: &Option<Quantity<crate::units::Length>>,
    ball_diameter: f64,
) -> Result<(f64, &'static str), Invalid> {
    let (ck, rk) = match ring {
        "inner" => (
            "bearing.inner_groove_curvature",
            "bearing.inner_groove_radius",
        ),
        _ => (
            "bearing.outer_groove_curvature",
            "bearing.outer_groove_radius",
        ),
    };
    match (curvature, radius) {
        (Some(_), Some(r)) => Err(Invalid::new(
            rk,
            Some(r.to_string()),
            format!("give either {ck} or {rk}, not both"),
        )),
        (Some(f), None) => Ok((f, "curvature")),
        (None, Some(r)) => Ok((r.si / ball_diameter, "radius")),
        (None, None) => Err(Invalid::missing(
            ck,
            &format!("give the {ring} groove curvature factor f = r/D (e.g. 0.52) or {rk}"),
        )),
    }
}

/// The clearance parametrization of `[bearing]`: exactly one of the free
/// contact angle, the diametral clearance or both raceway diameters.
fn clearance(b: &RawBearing) -> Result<Clearance, Invalid> {
    let given: Vec<&[&str]> = PARAMETRIZATIONS
        .iter()
        .copied()
        .filter(|keys| keys.iter().any(|k| param_value(b, k).is_some()))
        .collect();
    Ok(match given.as_slice() {
        [] => {
            return Err(Invalid::missing(
                "bearing.free_contact_angle",
                "give one clearance parametrization: free_contact_angle, diametral_clearance, or inner_raceway_diameter + outer_raceway_diameter",
            ));
        }
        [one] => match one[0] {
            "free_contact_angle" => Clearance::FreeContactAngle(
                param_value(b, "free_contact_angle").unwrap_or_default(),
            ),
            "diametral_clearance" => {
                Clearance::Diametral(param_value(b, "diametral_clearance").unwrap_or_default())
            }
            _ => {
                let (Some(inner), Some(outer)) = (
                    b.inner_raceway_diameter.as_ref(),
                    b.outer_raceway_diameter.as_ref(),
                ) else {
                    let missing = if b.inner_raceway_diameter.is_none() {
                        "inner"
                    } else {
                        "outer"
                    };
                    return Err(Invalid::missing(
                        &format!("bearing.{missing}_raceway_diameter"),
                        "parametrization (c) needs both raceway diameters",
                    ));
                };
                if let Some(p) = &b.pitch_diameter {
                    return Err(Invalid::new(
                        "bearing.pitch_diameter",
                        Some(p.to_string()),
                        "with inner/outer_raceway_diameter the pitch diameter is derived, (d_i + d_o)/2; remove it",
                    ));
                }
                Clearance::RacewayDiameters {
                    inner: inner.si,
                    outer: outer.si,
                }
            }
        },
        [first, second, ..] => {
            return Err(Invalid::new(
                format!("bearing.{}", second[0]),
                None,
                format!(
                    "conflicts with bearing.{}: give exactly one clearance parametrization (free_contact_angle, diametral_clearance, or the raceway diameters)",
                    first[0]
                ),
            ));
        }
    })
}

/// A geometry refusal as the case key the user wrote: a groove given by
/// its radius named by it, the value as written.
fn geometry_error(
    b: &RawBearing,
    e: rolldyn::error::InvalidParameter,
    fi_form: &str,
    fo_form: &str,
) -> Invalid {
    let key = match (e.field, fi_form, fo_form) {
        ("inner_groove_curvature", "radius", _) => "inner_groove_radius",
        ("outer_groove_curvature", _, "radius") => "outer_groove_radius",
        (f, _, _) => f,
    };
    let value = match key {
        "ball_diameter" => text(&b.ball_diameter),
        "pitch_diameter" => text(&b.pitch_diameter),
        "inner_groove_radius" => text(&b.inner_groove_radius),
        "outer_groove_radius" => text(&b.outer_groove_radius),
        "free_contact_angle" => text(&b.free_contact_angle),
        "diametral_clearance" => text(&b.diametral_clearance),
        "inner_raceway_diameter" => text(&b.inner_raceway_diameter),
        "outer_raceway_diameter" => text(&b.outer_raceway_diameter),
        "ball_count" => b.ball_count.map(|z| z.to_string()),
        "inner_groove_curvature" => b.inner_groove_curvature.map(|f| f.to_string()),
        "outer_groove_curvature" => b.outer_groove_curvature.map(|f| f.to_string()),
        _ => Some(e.value.clone()),
    };
    Invalid::new(format!("bearing.{key}"), value, e.rule)
}

pub(super) fn bearing(b: &RawBearing, fits: Option<&RawFits>) -> Result<Bearing, Invalid> {
    let d = b.ball_diameter.as_ref().ok_or_else(|| {
        Invalid::missing(
            "bearing.ball_diameter",
            "ball diameter D, e.g. \"6.35 mm\" (or give bearing.preset)",
        )
    })?;
    let z = b
        .ball_count
        .ok_or_else(|| Invalid::missing("bearing.ball_count", "number of balls Z"))?;
    if z < 3 {
        return Err(Invalid::new(
            "bearing.ball_count",
            Some(z.to_string()),
            "a bearing needs at least 3 balls",
        ));
    }
    let (fi, fi_form) = groove(
        "inner",
        b.inner_groove_curvature,
        &b.inner_groove_radius,
        d.si,
    )?;
    let (fo, fo_form) = groove(
        "outer",
        b.outer_groove_curvature,
        &b.outer_groove_radius,
        d.si,
    )?;

    let clearance = clearance(b)?;
    let pitch = match clearance {
        Clearance::RacewayDiameters { .. } => 0.0,
        _ => {
            b.pitch_diameter
                .as_ref()
                .ok_or_else(|| Invalid::missing("bearing.pitch_diameter", "pitch diameter d_m"))?
                .si
        }
    };
    let optional =
        |key: &str, q: &Option<Quantity<crate::units::Length>>| checked(key, q, positive);
    let bore = optional("bearing.bore", &b.bore)?;
    let outside_diameter = optional("bearing.outside_diameter", &b.outside_diameter)?;
    let (clearance, pitch, fit) = match fits {
        Some(fits) => {
            let (c, p, effect) =
                super::fits::mount(fits, clearance, pitch, d.si, bore, outside_diameter)?;
            (c, p, Some(effect))
        }
        None => (clearance, pitch, None),
    };
    let spec = GeometrySpec {
        ball_diameter: d.si,
        ball_count: z as usize,
        pitch_diameter: pitch,
        inner_groove_curvature: fi,
        outer_groove_curvature: fo,
        clearance,
        // A fit that closes the clearance preloads the bearing.
        preload: b.preload.unwrap_or(false)
            || fit
                .as_ref()
                .is_some_and(|f| f.diametral_clearance_mounted_m < 0.0),
    };
    let geometry =
        BearingGeometry::new(&spec).map_err(|e| geometry_error(b, e, fi_form, fo_form))?;
    Ok(Bearing {
        preset: b.preset.clone(),
        designation: b.designation.clone(),
        geometry,
        bore,
        outside_diameter,
        width: optional("bearing.width", &b.width)?,
        fits: fit,
    })
}

fn param_value(b: &RawBearing, key: &str) -> Option<f64> {
    match key {
        "free_contact_angle" => b.free_contact_angle.as_ref().map(|q| q.si),
        "diametral_clearance" => b.diametral_clearance.as_ref().map(|q| q.si),
        "inner_raceway_diameter" => b.inner_raceway_diameter.as_ref().map(|q| q.si),
        "outer_raceway_diameter" => b.outer_raceway_diameter.as_ref().map(|q| q.si),
        _ => None,
    }
}
