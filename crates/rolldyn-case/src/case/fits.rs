//! `[fits]` in SI: the change of the raceway diameters an interference fit
//! makes, and the bearing's clearance after mounting.
//!
//! Thick-walled cylinders of one material (Lamé; Harris & Kotzalas 2006,
//! interference fitting): an inner ring of bore d and raceway diameter d_i
//! pressed with effective diametral interference I_s on a shaft of bore
//! d_s grows at its raceway by
//!
//! ```text
//! Δ_i = I_s (d/d_i) (1 − (d_s/d)²) / (1 − (d_s/d_i)²)
//! ```
//!
//! and an outer ring of outside diameter D and raceway diameter d_o
//! pressed with I_h into a housing of outside diameter D_h shrinks by
//!
//! ```text
//! Δ_o = I_h (d_o/D) (1 − (D/D_h)²) / (1 − (d_o/D_h)²)
//! ```
//!
//! (a solid shaft and a large housing: Δ_i = I_s d/d_i, Δ_o = I_h d_o/D).
//! The diametral clearance falls by Δ_i + Δ_o, and the pitch diameter moves
//! by (Δ_i − Δ_o)/2. Shaft and housing are taken of the rings' modulus;
//! the interference is the effective one (the measured one less the
//! surfaces' smoothing).

use super::tolerances::{ClassFit, housing_fit, shaft_fit};
use super::{Invalid, checked, non_negative, positive};
use crate::raw::RawFits;
use rolldyn::geometry::Clearance;

/// What the fits do to the bearing.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct FitEffect {
    /// The shaft's tolerance class and its interference range, when given
    /// by class.
    pub shaft_fit: Option<ClassFit>,
    /// The housing's, likewise.
    pub housing_fit: Option<ClassFit>,
    /// Growth of the inner raceway diameter \[m\].
    pub inner_raceway_expansion_m: f64,
    /// Shrinkage of the outer raceway diameter \[m\].
    pub outer_raceway_contraction_m: f64,
    /// Diametral clearance before mounting \[m\].
    pub diametral_clearance_unmounted_m: f64,
    /// Diametral clearance mounted (negative: a preload) \[m\].
    pub diametral_clearance_mounted_m: f64,
}

/// The inner raceway's expansion \[m\] under a shaft interference
/// `shaft` \[m\] (bore d, raceway diameter `inner`, hollow shaft of bore
/// d_s from `fits.shaft_bore`): Lamé's thick-walled cylinders of one
/// material (module doc), Δ_i = I (d/d_i)(1 − (d_s/d)²)/(1 − (d_s/d_i)²).
fn inner_raceway_expansion(
    fits: &RawFits,
    shaft: f64,
    bore: Option<f64>,
    inner: f64,
) -> Result<f64, Invalid> {
    Ok(if shaft > 0.0 {
        let d = bore.ok_or_else(|| {
            Invalid::missing(
                "bearing.bore",
                "the inner ring's bore, for fits.shaft_interference",
            )
        })?;
        let ds = checked("fits.shaft_bore", &fits.shaft_bore, non_negative)?.unwrap_or(0.0);
        if ds >= d {
            return Err(Invalid::new(
                "fits.shaft_bore",
                fits.shaft_bore.as_ref().map(|q| q.to_string()),
                "must be smaller than the bearing's bore",
            ));
        }
        shaft * (d / inner) * (1.0 - (ds / d).powi(2)) / (1.0 - (ds / inner).powi(2))
    } else {
        0.0
    })
}

/// The outer raceway's contraction \[m\] under a housing interference
/// `housing` \[m\] (outside diameter D, raceway diameter `outer`, housing
/// of outside diameter D_h from `fits.housing_outside_diameter`, else
/// rigid), the same way: Δ_o = I (d_o/D)(1 − (D/D_h)²)/(1 − (d_o/D_h)²).
fn outer_raceway_contraction(
    fits: &RawFits,
    housing: f64,
    outside: Option<f64>,
    outer: f64,
) -> Result<f64, Invalid> {
    Ok(if housing > 0.0 {
        let big = outside.ok_or_else(|| {
            Invalid::missing(
                "bearing.outside_diameter",
                "the outer ring's outside diameter, for fits.housing_interference",
            )
        })?;
        let factor = match checked(
            "fits.housing_outside_diameter",
            &fits.housing_outside_diameter,
            positive,
        )? {
            None => 1.0,
            Some(dh) if dh > big => (1.0 - (big / dh).powi(2)) / (1.0 - (outer / dh).powi(2)),
            Some(_) => {
                return Err(Invalid::new(
                    "fits.housing_outside_diameter",
                    fits.housing_outside_diameter
                        .as_ref()
                        .map(|q| q.to_string()),
                    "must be larger than the bearing's outside diameter",
                ));
            }
        };
        housing * (outer / big) * factor
    } else {
        0.0
    })
}

/// The mounted clearance parametrization and pitch diameter for `clearance`
/// and `pitch` of a bearing with ball diameter `ball`, bore `bore` and
/// outside diameter `outside`, under `fits`.
pub(super) fn mount(
    fits: &RawFits,
    clearance: Clearance,
    pitch: f64,
    ball: f64,
    bore: Option<f64>,
    outside: Option<f64>,
) -> Result<(Clearance, f64, FitEffect), Invalid> {
    let (inner, outer) = match clearance {
        Clearance::Diametral(p) => (pitch - ball - 0.5 * p, pitch + ball + 0.5 * p),
        Clearance::RacewayDiameters { inner, outer } => (inner, outer),
        Clearance::FreeContactAngle(_) => {
            return Err(Invalid::new(
                "fits",
                None,
                "fits need the bearing's diametral_clearance or its raceway diameters (a free contact angle fixes the clearance's shape, not its size)",
            ));
        }
    };
    let by_class = |key: &str,
                    class: &Option<String>,
                    given: bool,
                    size: Option<f64>,
                    size_key: &str,
                    of: fn(&str, f64) -> Result<ClassFit, String>|
     -> Result<Option<ClassFit>, Invalid> {
        let Some(class) = class else { return Ok(None) };
        if given {
            return Err(Invalid::new(
                key,
                Some(class.clone()),
                "give the interference or the tolerance class, not both",
            ));
        }
        let size =
            size.ok_or_else(|| Invalid::missing(size_key, "the ring's diameter, for its fit"))?;
        of(class, size)
            .map(Some)
            .map_err(|rule| Invalid::new(key, Some(class.clone()), rule))
    };
    let shaft_class = by_class(
        "fits.shaft_tolerance",
        &fits.shaft_tolerance,
        fits.shaft_interference.is_some(),
        bore,
        "bearing.bore",
        shaft_fit,
    )?;
    let housing_class = by_class(
        "fits.housing_tolerance",
        &fits.housing_tolerance,
        fits.housing_interference.is_some(),
        outside,
        "bearing.outside_diameter",
        housing_fit,
    )?;
    let shaft = match &shaft_class {
        Some(f) => f.interference_used_m,
        None => checked(
            "fits.shaft_interference",
            &fits.shaft_interference,
            non_negative,
        )?
        .unwrap_or(0.0),
    };
    let housing = match &housing_class {
        Some(f) => f.interference_used_m,
        None => checked(
            "fits.housing_interference",
            &fits.housing_interference,
            non_negative,
        )?
        .unwrap_or(0.0),
    };
    let expansion = inner_raceway_expansion(fits, shaft, bore, inner)?;
    let contraction = outer_raceway_contraction(fits, housing, outside, outer)?;
    let unmounted = outer - inner - 2.0 * ball;
    let mounted = unmounted - expansion - contraction;
    let effect = FitEffect {
        shaft_fit: shaft_class,
        housing_fit: housing_class,
        inner_raceway_expansion_m: expansion,
        outer_raceway_contraction_m: contraction,
        diametral_clearance_unmounted_m: unmounted,
        diametral_clearance_mounted_m: mounted,
    };
    let clearance = match clearance {
        Clearance::RacewayDiameters { .. } => Clearance::RacewayDiameters {
            inner: inner + expansion,
            outer: outer - contraction,
        },
        _ => Clearance::Diametral(mounted),
    };
    Ok((clearance, pitch + 0.5 * (expansion - contraction), effect))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::units::Quantity;

    fn length(text: &str) -> Option<Quantity<crate::units::Length>> {
        Some(serde_json::from_value(serde_json::json!(text)).unwrap())
    }

    /// 6206: d 30, D 62, d_m 46, D_w 9.525 mm, P_d 13 µm.
    const BALL: f64 = 9.525e-3;

    fn mounted(fits: &RawFits) -> Result<(Clearance, f64, FitEffect), Invalid> {
        mount(
            fits,
            Clearance::Diametral(13e-6),
            46e-3,
            BALL,
            Some(30e-3),
            Some(62e-3),
        )
    }

    #[test]
    fn a_solid_shaft_and_a_large_housing_take_the_diameter_ratios() {
        let fits = RawFits {
            shaft_interference: length("15 um"),
            housing_interference: length("5 um"),
            ..RawFits::default()
        };
        let (clearance, pitch, f) = mounted(&fits).unwrap();
        let (inner, outer) = (46e-3 - BALL - 6.5e-6, 46e-3 + BALL + 6.5e-6);
        assert!((f.inner_raceway_expansion_m - 15e-6 * 30e-3 / inner).abs() < 1e-15);
        assert!((f.outer_raceway_contraction_m - 5e-6 * outer / 62e-3).abs() < 1e-15);
        let left = 13e-6 - f.inner_raceway_expansion_m - f.outer_raceway_contraction_m;
        assert!((f.diametral_clearance_mounted_m - left).abs() < 1e-15);
        assert_eq!(
            clearance,
            Clearance::Diametral(f.diametral_clearance_mounted_m)
        );
        let shift = 0.5 * (f.inner_raceway_expansion_m - f.outer_raceway_contraction_m);
        assert!((pitch - 46e-3 - shift).abs() < 1e-15);
    }

    /// A thin hollow shaft gives way (less growth); a thin housing too
    /// (less shrinkage); as the hollow and the housing wall thicken, both
    /// tend to the solid limits.
    /// A fit by tolerance class is the explicit fit of its probable
    /// interference; with both on one side, the case names the key.
    #[test]
    fn class_fits_are_their_probable_interference() {
        let by_class = mounted(&RawFits {
            shaft_tolerance: Some("m5".into()),
            housing_tolerance: Some("K7".into()),
            ..RawFits::default()
        })
        .unwrap()
        .2;
        let shaft = by_class.shaft_fit.as_ref().unwrap().interference_used_m;
        let housing = by_class.housing_fit.as_ref().unwrap().interference_used_m;
        let explicit = mounted(&RawFits {
            shaft_interference: length(&format!("{} um", shaft * 1e6)),
            housing_interference: length(&format!("{} um", housing * 1e6)),
            ..RawFits::default()
        })
        .unwrap()
        .2;
        assert!(
            (by_class.diametral_clearance_mounted_m - explicit.diametral_clearance_mounted_m).abs()
                < 1e-15
        );
        let both = mounted(&RawFits {
            shaft_tolerance: Some("m5".into()),
            shaft_interference: length("5 um"),
            ..RawFits::default()
        })
        .unwrap_err();
        assert_eq!(both.key, "fits.shaft_tolerance");
        let bad = mounted(&RawFits {
            housing_tolerance: Some("X7".into()),
            ..RawFits::default()
        })
        .unwrap_err();
        assert!(bad.rule.contains("housing class"), "{}", bad.rule);
    }

    #[test]
    fn hollow_shafts_and_thin_housings_give_way() {
        let solid = mounted(&RawFits {
            shaft_interference: length("15 um"),
            housing_interference: length("5 um"),
            ..RawFits::default()
        })
        .unwrap()
        .2;
        let thin = mounted(&RawFits {
            shaft_interference: length("15 um"),
            shaft_bore: length("25 mm"),
            housing_interference: length("5 um"),
            housing_outside_diameter: length("70 mm"),
            ..RawFits::default()
        })
        .unwrap()
        .2;
        let thick = mounted(&RawFits {
            shaft_interference: length("15 um"),
            shaft_bore: length("1 mm"),
            housing_interference: length("5 um"),
            housing_outside_diameter: length("10 m"),
            ..RawFits::default()
        })
        .unwrap()
        .2;
        assert!(thin.inner_raceway_expansion_m < 0.6 * solid.inner_raceway_expansion_m);
        assert!(thin.outer_raceway_contraction_m < 0.6 * solid.outer_raceway_contraction_m);
        for (a, b) in [
            (
                thick.inner_raceway_expansion_m,
                solid.inner_raceway_expansion_m,
            ),
            (
                thick.outer_raceway_contraction_m,
                solid.outer_raceway_contraction_m,
            ),
        ] {
            assert!((a / b - 1.0).abs() < 2e-3, "{a} vs {b}");
        }
    }

    #[test]
    fn fits_need_the_ring_dimensions_and_a_clearance() {
        let fits = RawFits {
            shaft_interference: length("15 um"),
            ..RawFits::default()
        };
        let err = |r: Result<(Clearance, f64, FitEffect), Invalid>| r.unwrap_err().key;
        assert_eq!(
            err(mount(
                &fits,
                Clearance::Diametral(1e-5),
                46e-3,
                BALL,
                None,
                Some(62e-3)
            )),
            "bearing.bore"
        );
        assert_eq!(
            err(mount(
                &fits,
                Clearance::FreeContactAngle(0.3),
                46e-3,
                BALL,
                Some(30e-3),
                None
            )),
            "fits"
        );
        let bored = RawFits {
            shaft_bore: length("30 mm"),
            ..fits.clone()
        };
        assert_eq!(err(mounted(&bored)), "fits.shaft_bore");
        let negative = RawFits {
            housing_interference: length("-1 um"),
            ..RawFits::default()
        };
        assert_eq!(err(mounted(&negative)), "fits.housing_interference");
    }
}
