//! ln(1 + u) and asinh by plain IEEE arithmetic, for loops that the
//! compiler vectorizes.
//!
//! The C library's `log` and `log1p` are calls the compiler cannot
//! vectorize, and their last bit may differ between library versions and
//! processors. These use only additions, multiplications, one division,
//! a square root and bit operations, each correctly rounded or exact, so
//! the same input gives the same bits on every machine, in scalar code and
//! in SIMD lanes alike, and a loop over cells compiles to vector
//! instructions.
//!
//! Method (fdlibm's `log1p`, docs/references.md, written without
//! branches): 1 + u = 2^e m with m in [√½, √2), the rounding error of
//! 1 + u carried as a correction c/(1 + u), and
//! ln m = 2 atanh f = 2f (1 + f²/3 + f⁴/5 + …), f = (m − 1)/(m + 1),
//! |f| ≤ 0.1716, summed to the f²¹/21 term (truncation below 2⁻⁵⁵ of the
//! sum) by Estrin's scheme (Estrin 1960).
//! Accuracy: within 2 ulp of the exact value over [0, 1e300] (test).

/// ln 2 split so that e · `LN2_HI` is exact for |e| < 2¹¹ (fdlibm's;
/// also `math::exponential`'s).
pub(super) const LN2_HI: f64 = f64::from_bits(0x3fe6_2e42_fee0_0000);
/// ln 2 − `LN2_HI`.
pub(super) const LN2_LO: f64 = f64::from_bits(0x3dea_39ef_3579_3c76);
/// Bits of √½ (rounded), the lower end of the reduced mantissa's range.
const SQRT_HALF_BITS: u64 = 0x3fe6_a09e_667f_3bcd;
/// Bits of 1.0.
const ONE_BITS: u64 = 0x3ff0_0000_0000_0000;
/// The mantissa field of an f64.
const MANTISSA: u64 = 0x000f_ffff_ffff_ffff;
/// 2⁵²: f64::from_bits(bits of 2⁵² | n) − 2⁵² = n for n < 2⁵².
const TWO_52_BITS: u64 = 0x4330_0000_0000_0000;

/// 1/3, 1/5, …, 1/21: the atanh series' coefficients.
const ATANH_SERIES: [f64; 10] = [
    1.0 / 3.0,
    1.0 / 5.0,
    1.0 / 7.0,
    1.0 / 9.0,
    1.0 / 11.0,
    1.0 / 13.0,
    1.0 / 15.0,
    1.0 / 17.0,
    1.0 / 19.0,
    1.0 / 21.0,
];

/// ln(1 + u) for u ≥ 0 (finite), without branches.
#[inline(always)]
pub fn ln_1p(u: f64) -> f64 {
    let sum = 1.0 + u;
    // The rounding error of 1 + u, exact (Fast2Sum with the larger first).
    let error = if u < 1.0 {
        u - (sum - 1.0)
    } else {
        1.0 - (sum - u)
    };
    // sum = 2^e m, m in [√½, √2): shifting the bits by 1 − √½ moves the
    // exponent's boundary to √½.
    let shifted = sum.to_bits().wrapping_add(ONE_BITS - SQRT_HALF_BITS);
    let exponent =
        f64::from_bits(TWO_52_BITS | (shifted >> 52)) - (4_503_599_627_370_496.0 + 1023.0);
    let m = f64::from_bits((shifted & MANTISSA).wrapping_add(SQRT_HALF_BITS));
    let f = (m - 1.0) / (m + 1.0);
    let s = f * f;
    // (atanh f − f)/f³ = 1/3 + s/5 + … + s⁹/21 + …, by Estrin's scheme
    // (pairs, then powers s², s⁴, s⁸: a chain of 5 steps instead of 9).
    let c = &ATANH_SERIES;
    let (s2, pair) = (s * s, |k: usize| c[k] + c[k + 1] * s);
    let s4 = s2 * s2;
    let low = pair(0) + pair(2) * s2;
    let high = pair(4) + pair(6) * s2;
    let series = (low + high * s4) + pair(8) * (s4 * s4);
    let two_f = 2.0 * f;
    let ln_m = two_f + two_f * s * series;
    exponent * LN2_HI + (ln_m + (exponent * LN2_LO + error / sum))
}

/// asinh(x) for x ≥ 0 (finite), without branches: ln(1 + u) with
/// u = x + x²/(1 + √(1 + x²)) (no cancellation), and u = 2x − 1 above
/// x = 1e8 (relative error of asinh x = ln 2x there below 1e-16; no
/// overflow of x²).
#[inline(always)]
pub fn asinh_non_negative(x: f64) -> f64 {
    let x2 = x * x;
    let u = if x > 1e8 {
        2.0 * x - 1.0
    } else {
        x + x2 / (1.0 + (1.0 + x2).sqrt())
    };
    ln_1p(u)
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// Distance in units in the last place (of normal numbers; also
    /// `math::exponential`'s tests).
    pub(in crate::math) fn ulps(a: f64, b: f64) -> f64 {
        (a - b).abs() / (b.abs() * f64::EPSILON).max(f64::MIN_POSITIVE)
    }

    #[test]
    fn ln_1p_is_within_two_ulp_of_the_library() {
        let mut worst: f64 = 0.0;
        for k in -3000..=3000 {
            // u from 1e-300 to 1e300, and around the range boundaries.
            let u = 10f64.powf(k as f64 * 0.1) * (1.0 + 1e-3 * (k % 7) as f64);
            worst = worst.max(ulps(ln_1p(u), u.ln_1p()));
        }
        for u in [
            0.0,
            1.0,
            2.0f64.sqrt() - 1.0,
            0.5f64.sqrt() - 1.0 + 1.0,
            1e-8,
            3.0,
        ] {
            worst = worst.max(ulps(ln_1p(u), u.ln_1p()));
        }
        assert_eq!(ln_1p(0.0), 0.0);
        assert!(worst <= 2.0, "worst {worst} ulp");
    }

    #[test]
    fn asinh_is_within_four_ulp_of_the_library() {
        for k in -300..=100 {
            let x = 1.3f64.powi(k);
            let (fast, std) = (asinh_non_negative(x), x.asinh());
            assert!(ulps(fast, std) <= 4.0, "x = {x}: {fast} vs {std}");
        }
        assert_eq!(asinh_non_negative(0.0), 0.0);
        assert!(asinh_non_negative(1e200).is_finite());
    }
}
