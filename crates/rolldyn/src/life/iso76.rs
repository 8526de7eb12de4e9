//! Basic static radial load rating C_0r by ISO 76:2006 and the fatigue load
//! limit C_u of ISO 281:2007 (§B.3.2.2, simplified for ball bearings).
//!
//! ISO 76 defines C_0r of a radial ball bearing as the static radial load
//! that gives a calculated contact pressure of 4 200 MPa at the centre of
//! the most heavily loaded ball–raceway contact, with the most loaded ball
//! carrying Q_max = 5 F_r/(i Z cos α) (Stribeck), for steel of
//! E = 2.07·10⁵ N/mm² and ν = 0.3. Here the Hertz contact of each raceway
//! is solved exactly (`contact::hertz`) with the bearing's own groove
//! radii, so C_0r = i Z cos α Q_4200/5 with Q_4200 the smaller of the inner
//! and outer loads that reach 4 200 MPa. ISO 76's f_0 table was computed
//! the same way for the standard's groove radii (r_i = 0.52 D_w,
//! r_e = 0.53 D_w for deep-groove bearings); the test checks catalogue
//! values of such bearings.
//!
//! C_u = C_0r/22 for D_pw ≤ 100 mm and C_0r/22 · (100/D_pw)^0.5 above
//! (ISO 281:2007 eq. B.8–B.9: a fatigue stress limit of 1 500 MPa).

use crate::contact::hertz::{Curvature, HertzCoefficients};
use crate::error::InvalidParameter;
use crate::geometry::{BearingGeometry, RingKind};
use crate::material::{Material, effective_modulus};
use std::f64::consts::PI;

/// ISO 76's reference contact pressure of radial ball bearings \[Pa\].
pub const STATIC_RATING_PRESSURE: f64 = 4.2e9;

/// Stribeck's factor of ISO 76: Q_max = 5 F_r/(i Z cos α).
pub const STRIBECK_FACTOR: f64 = 5.0;

/// The steel ISO 76 assumes: E = 207 GPa, ν = 0.3 (the density is unused).
pub const STANDARD_STEEL: Material = Material {
    elastic_modulus: 207e9,
    poisson_ratio: 0.3,
    density: 7850.0,
};

/// Basic static radial load rating C_0r \[N\] of a single-row radial ball
/// bearing at its nominal contact angle.
pub fn static_load_rating(geometry: &BearingGeometry) -> Result<f64, InvalidParameter> {
    let alpha = geometry.nominal_contact_angle();
    let modulus = effective_modulus(&STANDARD_STEEL, &STANDARD_STEEL);
    let mut limit = f64::INFINITY;
    for ring in [RingKind::Inner, RingKind::Outer] {
        let curvature = Curvature::of_raceway(
            geometry.raceway(ring),
            geometry.ball_diameter,
            geometry.pitch_diameter,
            alpha,
        );
        let h = HertzCoefficients::exact(&curvature, modulus)?;
        // p₀ = 3Q/(2π a b) with a = a* Q^{1/3}, b = b* Q^{1/3}.
        let load = (STATIC_RATING_PRESSURE
            * 2.0
            * PI
            * h.semi_major_coefficient
            * h.semi_minor_coefficient
            / 3.0)
            .powi(3);
        limit = limit.min(load);
    }
    Ok(geometry.ball_count as f64 * alpha.cos() * limit / STRIBECK_FACTOR)
}

/// Fatigue load limit C_u \[N\] of a ball bearing of static rating C_0r
/// \[N\] and pitch diameter D_pw \[m\] (ISO 281 eq. B.8–B.9).
pub fn fatigue_load_limit(static_rating: f64, pitch_diameter: f64) -> f64 {
    let d_mm = pitch_diameter * 1e3;
    let base = static_rating / 22.0;
    if d_mm <= 100.0 {
        base
    } else {
        base * (100.0 / d_mm).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{Clearance, GeometrySpec};

    const IN: f64 = 0.0254;

    fn deep_groove(d: f64, dm: f64, z: usize) -> BearingGeometry {
        BearingGeometry::new(&GeometrySpec {
            ball_diameter: d,
            ball_count: z,
            pitch_diameter: dm,
            inner_groove_curvature: 0.52,
            outer_groove_curvature: 0.53,
            clearance: Clearance::Diametral(10e-6),
            preload: false,
        })
        .unwrap()
    }

    /// C_0r of catalogue deep-groove bearings from their ball sets with
    /// ISO 76's groove radii, against the values NSK lists (CAT. E1102,
    /// computed by ISO 76): 6205 7.85 kN, 6203 4.75 kN, 6206 11.3 kN,
    /// 6304 7.90 kN. Found 7.87, 4.76, 11.26, 7.89 kN (≤ 0.4 %); 1 % (the
    /// catalogue rounds f_0 and C_0r to three figures).
    #[test]
    fn static_rating_matches_catalogue_values() {
        for (name, d, dm, z, catalogue) in [
            ("6205", 0.3126 * IN, 1.537 * IN, 9, 7_850.0),
            ("6203", 0.2656 * IN, 1.122 * IN, 8, 4_750.0),
            ("6206", 9.525e-3, 46e-3, 9, 11_300.0),
            ("6304", 9.52e-3, 36e-3, 7, 7_900.0),
        ] {
            let c0 = static_load_rating(&deep_groove(d, dm, z)).unwrap();
            assert!(
                (c0 / catalogue - 1.0).abs() < 0.01,
                "{name}: {c0} N vs {catalogue} N"
            );
        }
    }

    #[test]
    fn fatigue_load_limit_branches() {
        assert_eq!(fatigue_load_limit(22_000.0, 0.05), 1000.0);
        assert!((fatigue_load_limit(22_000.0, 0.4) - 500.0).abs() < 1e-9);
    }
}
