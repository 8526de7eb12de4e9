//! eˣ by plain IEEE arithmetic, for loops that the compiler vectorizes.
//!
//! The C library's `exp` is a call the compiler cannot vectorize, and its
//! last bit may differ between library versions and processors. [`exp`]
//! uses only additions, multiplications, one division, a minimum, a
//! maximum and bit operations, each correctly rounded or exact, so the
//! same input gives the same bits on every machine, in scalar code and in
//! SIMD lanes alike (the companion of [`super::logarithm`]).
//!
//! Method (fdlibm's `exp`, docs/references.md, written without branches):
//! x = n ln 2 + r with n the nearest integer to x/ln 2 and |r| ≲ ½ ln 2,
//! r carried as hi − lo with ln 2 split so that n · ln2_hi is exact;
//! eʳ = 1 + 2r/(2 − R(r)) − … in fdlibm's rational form with its degree-5
//! Remez polynomial in r² (error below 2⁻⁵⁹), and eˣ = 2ⁿ eʳ with 2ⁿ
//! applied as two factors 2^⌊n/2⌉ · 2^(n − ⌊n/2⌉), each a normal number,
//! so that results in the subnormal range are rounded once and results
//! beyond the largest finite number overflow to +∞.
//! Accuracy: within 1 ulp of the exact value (fdlibm's bound), within
//! 2 ulp of the C library's over the whole range (test; 1.0 measured
//! against glibc 2.36).

use super::logarithm::{LN2_HI, LN2_LO};

/// 1.5 · 2⁵²: adding it rounds a number of magnitude below 2⁵¹ to the
/// nearest integer m and leaves m in the low mantissa bits.
const ROUNDING_SHIFT: f64 = 6_755_399_441_055_744.0;
/// fdlibm's Remez coefficients of R(r) = r²(P1 + r²(P2 + …)), by their
/// bits (1.666…e-1, −2.777…e-3, 6.613…e-5, −1.653…e-6, 4.138…e-8).
const P: [f64; 5] = [
    f64::from_bits(0x3fc5_5555_5555_553e),
    f64::from_bits(0xbf66_c16c_16be_bd93),
    f64::from_bits(0x3f11_566a_af25_de2c),
    f64::from_bits(0xbebb_bd41_c5d2_6bf1),
    f64::from_bits(0x3e66_3769_72be_a4d0),
];
/// Below e^−746 every result rounds to 0, above e^710 to +∞: clamping
/// there keeps n and its halves in range.
const SMALLEST: f64 = -746.0;
const LARGEST: f64 = 710.0;

/// x rounded to the nearest integer (ties to even), |x| < 2⁵¹.
#[inline(always)]
fn round_to_integer(x: f64) -> f64 {
    (x + ROUNDING_SHIFT) - ROUNDING_SHIFT
}

/// 2ᵏ for an integer k in [−1022, 1023], from its bits: k + 1023 is the
/// biased exponent, taken from the low mantissa bits of k + 1023 + 1.5·2⁵².
#[inline(always)]
fn power_of_two(k: f64) -> f64 {
    f64::from_bits((k + (ROUNDING_SHIFT + 1023.0)).to_bits() << 52)
}

/// eˣ, without branches: +∞ above ~709.78, 0 below ~−745.13, NaN for NaN.
#[inline(always)]
pub fn exp(x: f64) -> f64 {
    let x = x.clamp(SMALLEST, LARGEST);
    let n = round_to_integer(x * std::f64::consts::LOG2_E);
    let hi = x - n * LN2_HI;
    let lo = n * LN2_LO;
    let r = hi - lo;
    let t = r * r;
    let c = r - t * (P[0] + t * (P[1] + t * (P[2] + t * (P[3] + t * P[4]))));
    let y = 1.0 - ((lo - (r * c) / (2.0 - c)) - hi);
    let half = round_to_integer(0.5 * n);
    y * power_of_two(half) * power_of_two(n - half)
}

#[cfg(test)]
mod tests {
    use super::super::logarithm::tests::ulps;
    use super::*;

    #[test]
    fn exp_is_within_two_ulp_of_the_library() {
        let mut worst: f64 = 0.0;
        // x over the range of normal results, 2·10⁵ points, and near the
        // reduction's half-way points n ± ½ ln 2.
        for k in -200_000..=200_000 {
            let x = k as f64 * 3.54e-3 + 1e-7 * (k % 13) as f64;
            if x > -708.0 && x < 709.7 {
                worst = worst.max(ulps(exp(x), x.exp()));
            }
        }
        for n in -1000..=1000 {
            for d in [-0.5, 0.5] {
                let x = (n as f64 + d) * std::f64::consts::LN_2;
                let x = x + 1e-15 * x.abs();
                if x > -708.0 && x < 709.7 {
                    worst = worst.max(ulps(exp(x), x.exp()));
                }
            }
        }
        assert!(worst <= 2.0, "worst {worst} ulp");
    }

    #[test]
    fn exact_values_limits_and_subnormals() {
        assert_eq!(exp(0.0), 1.0);
        assert_eq!(exp(-0.0), 1.0);
        assert!(ulps(exp(1.0), std::f64::consts::E) <= 1.0);
        // Monotone across the points where n steps (x = (n + ½) ln 2).
        for n in [-700, -3, 0, 5, 600] {
            let mid = (n as f64 + 0.5) * std::f64::consts::LN_2;
            let mut x = mid - 64.0 * f64::EPSILON * mid.abs().max(1.0);
            let mut previous = exp(x);
            for _ in 0..128 {
                x = x.next_up();
                assert!(exp(x) >= previous, "not monotone at {x}");
                previous = exp(x);
            }
        }
        assert_eq!(exp(710.0), f64::INFINITY);
        assert_eq!(exp(f64::INFINITY), f64::INFINITY);
        assert_eq!(exp(-746.0), 0.0);
        assert_eq!(exp(f64::NEG_INFINITY), 0.0);
        assert!(exp(f64::NAN).is_nan());
        assert_eq!(exp(709.78), 709.78f64.exp());
        // Subnormal results: rounded once, as the library's.
        for x in [-708.5, -720.0, -730.25, -740.0, -744.5, -745.1] {
            let (fast, std) = (exp(x), x.exp());
            assert!(
                (fast - std).abs() <= 2.0 * f64::from_bits(1),
                "x = {x}: {fast:e} vs {std:e}"
            );
        }
    }
}
