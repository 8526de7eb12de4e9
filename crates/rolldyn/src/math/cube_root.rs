//! The cube root by plain IEEE arithmetic (fdlibm's `cbrt` as revised in
//! FreeBSD's msun, docs/references.md): the contact semi-axes a, b ∝ Q^{1/3}
//! take one per contact and evaluation, and the library's correctly
//! rounded cube root costs about twice as much.
//!
//! Method: an estimate to 5 bits from the exponent field divided by 3, a
//! polynomial in r = t³/x that takes it to 23 bits, rounding to 21 bits
//! (so that t² is exact), and one Newton step t + t (x/t² − t)/(2t + x/t²)
//! to 53 bits. Accuracy: within 0.667 ulp (the method's bound), 1 ulp in
//! the test against the library over 40 decades.

/// (1023 − 1023/3 − 0.03306235651) · 2²⁰: the exponent estimate's bias.
const B1: u32 = 715_094_163;
/// The same for subnormal input scaled by 2⁵⁴.
const B2: u32 = 696_219_795;
/// |1/cbrt(x) − p(x)| < 2⁻²³·⁵ on the reduced range.
const P: [f64; 5] = [
    f64::from_bits(0x3ffe_03e6_0f61_e692),
    f64::from_bits(0xbffe_28e0_92f0_2420),
    f64::from_bits(0x3ff9_f160_4a49_d6c2),
    f64::from_bits(0xbfe8_44cb_bee7_51d9),
    f64::from_bits(0x3fc2_b000_d4e4_edd7),
];

/// x^{1/3} for finite x (odd: cbrt(−x) = −cbrt(x)); NaN and ±∞ return
/// themselves.
pub fn cbrt(x: f64) -> f64 {
    let bits = x.to_bits();
    let sign = ((bits >> 32) as u32) & 0x8000_0000;
    let high = ((bits >> 32) as u32) & 0x7fff_ffff;
    if high >= 0x7ff0_0000 {
        return x + x;
    }
    let t = if high < 0x0010_0000 {
        if x == 0.0 {
            return x;
        }
        // Subnormal: scale by 2⁵⁴ first.
        let scaled = x * f64::from_bits(0x4350_0000_0000_0000);
        let high = ((scaled.to_bits() >> 32) as u32) & 0x7fff_ffff;
        f64::from_bits(u64::from(sign | (high / 3 + B2)) << 32)
    } else {
        f64::from_bits(u64::from(sign | (high / 3 + B1)) << 32)
    };
    // To 23 bits: cbrt(x) = t cbrt(x/t³) ≈ t P(t³/x).
    let r = (t * t) * (t / x);
    let t = t * ((P[0] + r * (P[1] + r * P[2])) + ((r * r) * r) * (P[3] + r * P[4]));
    // Round away from zero to 23 bits, so that t² is exact.
    let t = f64::from_bits((t.to_bits() + 0x8000_0000) & 0xffff_ffff_c000_0000);
    // One Newton step to 53 bits.
    let s = t * t;
    let r = x / s;
    let w = t + t;
    let r = (r - t) / (w + r);
    t + t * r
}

#[cfg(test)]
mod tests {
    use super::cbrt;

    /// Distance in units in the last place.
    fn ulps(a: f64, b: f64) -> u64 {
        a.to_bits().abs_diff(b.to_bits())
    }

    #[test]
    fn within_an_ulp_of_the_library() {
        let mut worst = 0;
        for k in 0..200_000 {
            // 40 decades, 5000 points per decade, irregularly spaced.
            let x = 10f64.powf(-20.0 + k as f64 * 2e-4 + 1.3e-5 * (k as f64).sin());
            for x in [x, -x] {
                worst = worst.max(ulps(cbrt(x), x.cbrt()));
            }
        }
        assert!(worst <= 1, "worst {worst} ulp");
        for x in [1.0, 8.0, 27.0, 1e-300, 1e300] {
            assert!(ulps(cbrt(x), x.cbrt()) <= 1, "{x}");
        }
        assert_eq!(cbrt(0.0).to_bits(), 0.0f64.to_bits());
        assert_eq!(cbrt(-0.0).to_bits(), (-0.0f64).to_bits());
        assert!(ulps(cbrt(5e-310), 5e-310f64.cbrt()) <= 1, "subnormal");
        assert!(cbrt(f64::NAN).is_nan());
        assert_eq!(cbrt(f64::INFINITY), f64::INFINITY);
    }
}
