//! Life modification factor a_ISO of ISO 281:2007 (§9.3) for radial ball
//! bearings, from the viscosity ratio κ and e_C C_u/P:
//!
//! ```text
//! a_ISO = 0.1 [1 − (2.5671 − c₁/κ^c₂)^0.83 (e_C C_u/P)^(1/3)]^(−9.3)
//!   0.1 ≤ κ < 0.4:  c₁ = 2.2649, c₂ = 0.054381
//!   0.4 ≤ κ < 1:    c₁ = 1.9987, c₂ = 0.19087
//!   1 ≤ κ ≤ 4:      c₁ = 1.9987, c₂ = 0.071739
//! ```
//! κ > 4 is taken as 4; a_ISO is capped at 50 (also where the bracket
//! reaches 0). Below κ = 0.1 the standard gives no factor (None): the
//! three branches are continuous, and at κ = 0.1 the factor is 0.1 for
//! any load.
//!
//! κ = ν/ν₁, the operating kinematic viscosity over the reference
//! viscosity (ISO 281 eq. 41–42, D_pw in mm, n in r/min, ν₁ in mm²/s):
//! ν₁ = 45 000 n^(−0.83) D_pw^(−0.5) for n < 1000 r/min and
//! ν₁ = 4 500 n^(−0.5) D_pw^(−0.5) above.

/// Largest life modification factor (ISO 281 §9.3.1).
pub const MAX_FACTOR: f64 = 50.0;
/// Smallest viscosity ratio the formulas cover.
pub const MIN_VISCOSITY_RATIO: f64 = 0.1;
/// Viscosity ratios above this count as this.
pub const MAX_VISCOSITY_RATIO: f64 = 4.0;

/// Reference kinematic viscosity ν₁ \[m²/s\] for shaft speed n \[r/min\]
/// (> 0) and pitch diameter D_pw \[m\].
pub fn reference_viscosity(speed_rpm: f64, pitch_diameter: f64) -> f64 {
    let n = speed_rpm.abs();
    let d = (pitch_diameter * 1e3).sqrt();
    let mm2_per_s = if n < 1000.0 {
        45_000.0 * n.powf(-0.83) / d
    } else {
        4_500.0 / (n.sqrt() * d)
    };
    mm2_per_s * 1e-6
}

/// a_ISO of a radial ball bearing for viscosity ratio κ and the load ratio
/// e_C C_u/P; None for κ < 0.1 or a non-finite input.
pub fn life_modification_factor(viscosity_ratio: f64, load_ratio: f64) -> Option<f64> {
    if !(viscosity_ratio >= MIN_VISCOSITY_RATIO && load_ratio.is_finite() && load_ratio >= 0.0) {
        return None;
    }
    let kappa = viscosity_ratio.min(MAX_VISCOSITY_RATIO);
    let (c1, c2) = if kappa < 0.4 {
        (2.2649, 0.054381)
    } else if kappa < 1.0 {
        (1.9987, 0.19087)
    } else {
        (1.9987, 0.071739)
    };
    // ≥ 0 for κ ≥ 0.1 (0 within rounding of the constants at κ = 0.1).
    let lubrication = (2.5671 - c1 / kappa.powf(c2)).max(0.0);
    let bracket = 1.0 - lubrication.powf(0.83) * load_ratio.cbrt();
    Some(if bracket <= 0.0 {
        MAX_FACTOR
    } else {
        (0.1 * bracket.powf(-9.3)).min(MAX_FACTOR)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// ν₁ at the two branches, by hand: n = 3000 r/min, D_pw = 39 mm:
    /// 4500/(√3000 √39) = 13.16 mm²/s; n = 500 r/min, D_pw = 100 mm:
    /// 45 000 · 500^−0.83/10 = 25.89 mm²/s. The branches meet within 2.5 % at
    /// 1000 r/min, as the standard's diagram.
    #[test]
    fn reference_viscosity_by_hand() {
        let v = reference_viscosity(3000.0, 39e-3) * 1e6;
        assert!((v - 4500.0 / (3000f64.sqrt() * 39f64.sqrt())).abs() < 1e-9);
        assert!((v - 13.16).abs() < 0.01);
        let v = reference_viscosity(500.0, 0.1) * 1e6;
        assert!((v - 25.89).abs() < 0.01, "{v}");
        let below = reference_viscosity(999.999, 0.05);
        let above = reference_viscosity(1000.0, 0.05);
        assert!((below / above - 1.0).abs() < 0.025, "{below} {above}");
    }

    /// The formula's limits: continuous at κ = 0.4 and 1; 0.1 at κ = 0.1
    /// for any load; 0.1 at e_C C_u/P = 0 for every κ (the bracket is 1);
    /// monotone in κ and in the load ratio; capped at 50; None below 0.1.
    /// A value by hand: κ = 1, e_C C_u/P = 0.1:
    /// 0.1 [1 − 0.5684^0.83 · 0.1^(1/3)]^−9.3 = 2.43.
    #[test]
    fn factor_limits_and_a_value_by_hand() {
        let a = |k: f64, r: f64| life_modification_factor(k, r).unwrap();
        let hand = 0.1 * (1.0 - (2.5671f64 - 1.9987).powf(0.83) * 0.1f64.cbrt()).powf(-9.3);
        assert!((a(1.0, 0.1) - hand).abs() < 1e-12);
        assert!((hand - 2.43).abs() < 0.01, "{hand}");
        for k in [0.4, 1.0] {
            let (lo, hi) = (a(k * (1.0 - 1e-12), 0.2), a(k, 0.2));
            assert!((lo / hi - 1.0).abs() < 1e-3, "κ = {k}: {lo} {hi}");
        }
        assert!((a(0.1, 1.0) - 0.1).abs() < 1e-3);
        assert_eq!(a(2.0, 0.0), 0.1);
        assert_eq!(a(4.0, 5.0), 50.0);
        assert_eq!(a(100.0, 0.3), a(4.0, 0.3));
        assert!(life_modification_factor(0.05, 0.3).is_none());
        assert!(life_modification_factor(f64::NAN, 0.3).is_none());
        let mut last = 0.0;
        for i in 0..=40 {
            let k = 0.1 + 0.1 * i as f64;
            let v = a(k, 0.3);
            assert!(v >= last, "not monotone in κ at {k}");
            last = v;
        }
        let mut last = 0.0;
        for i in 0..=50 {
            let v = a(0.8, 0.02 * i as f64);
            assert!(v >= last, "not monotone in the load ratio");
            last = v;
        }
    }
}
