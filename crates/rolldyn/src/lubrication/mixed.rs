//! Mixed lubrication: the share of a contact's load that the asperities
//! carry, as a function of the film parameter Λ = h_min/σ (docs/model.md §3,
//! model 5).
//!
//! **Asperity pressure** of two nominally flat rough surfaces with Gaussian
//! summit heights (J. A. Greenwood & J. H. Tripp, "The contact of two
//! nominally flat rough surfaces", *Proc. Instn Mech. Engrs* 185 (1970–71)
//! 625–633):
//! ```text
//! p_a(λ) = K E* F_{5/2}(λ),   K = (16√2 π/15) (σβη)² √(σ/β),   λ = h/σ
//! F_n(λ) = (1/√(2π)) ∫_λ^∞ (s − λ)^n e^{−s²/2} ds
//! ```
//! σ is the composite RMS roughness √(R_q,ball² + R_q,race²), η the summit
//! density of each surface and β their tip radius (given as the
//! dimensionless σβη ≈ 0.03–0.07 and σ/β ≈ 1e-4–1e-2), h the separation of
//! the mean planes. E* is the Hertz modulus of the summit pairs,
//! 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂, i.e. E'/2 with docs/model.md §2.2's E'.
//! The constant follows from summing Hertz contacts of summit pairs of
//! radius β over their lateral offsets (docs/lubrication.md gives the
//! steps).
//!
//! **Load sharing** after K. L. Johnson, J. A. Greenwood & S. Y. Poon ("A
//! simple theory of asperity contact in elastohydrodynamic lubrication",
//! *Wear* 19 (1972) 91–108): the film is set in the inlet, as for smooth
//! surfaces, and the asperities carry p_a at that separation. Here the
//! separation is the minimum film, λ = Λ = h_min/σ (the conservative
//! choice: the central film would give less asperity load), and the
//! asperities' share of the contact's load is
//! ```text
//! φ(Λ) = min(1, p_a(Λ)/p̄),   p̄ = Q/(π a b)
//! ```
//! **Limits.** Λ → ∞: φ = 0 exactly (taken as 0 from Λ = [`SMOOTH_ABOVE`],
//! where F_{5/2} < 4e-11). Λ → 0: φ → min(1, 0.6166 K E*/p̄): the summits
//! at coinciding mean planes carry a pressure of order K E*, some 10–100
//! MPa, so a contact at bearing pressures (~1 GPa) keeps most of its load
//! on the film even at Λ = 0. The full boundary regime (φ = 1) needs the
//! separation to fall below the smooth film, which this uncoupled sharing
//! does not model. φ falls monotonically with Λ.

use crate::math::interp::UniformPchip;
use std::sync::LazyLock;

/// Film parameter from which the surfaces are taken as separated (φ = 0).
pub const SMOOTH_ABOVE: f64 = 6.0;

/// Table step of ln F_{5/2} in λ.
const TABLE_STEP: f64 = 1.0 / 32.0;

/// ln F_{5/2}(λ) on [0, [`SMOOTH_ABOVE`]], by Simpson's rule on
/// u = s − λ ∈ [0, 14] (the integrand is below e^{−98} beyond).
static LN_F52: LazyLock<UniformPchip> = LazyLock::new(|| {
    let nodes = (SMOOTH_ABOVE / TABLE_STEP).round() as usize;
    let values = (0..=nodes)
        .map(|i| greenwood_tripp_integral(2.5, i as f64 * TABLE_STEP).ln())
        .collect();
    UniformPchip::new(0.0, TABLE_STEP, values)
});

/// F_n(λ) for λ ≥ 0 by composite Simpson's rule (the table's source and
/// the tests' reference).
fn greenwood_tripp_integral(n: f64, lambda: f64) -> f64 {
    const INTERVALS: usize = 7000;
    const UPPER: f64 = 14.0;
    let h = UPPER / INTERVALS as f64;
    let f = |u: f64| u.powf(n) * (-0.5 * (u + lambda) * (u + lambda)).exp();
    let mut sum = f(0.0) + f(UPPER);
    for k in 1..INTERVALS {
        sum += if k % 2 == 1 { 4.0 } else { 2.0 } * f(k as f64 * h);
    }
    sum * h / 3.0 / (2.0 * std::f64::consts::PI).sqrt()
}

/// Greenwood and Tripp's F_{5/2}(λ) for λ ≥ 0 (0 from [`SMOOTH_ABOVE`]):
/// a monotone cubic in ln F, relative error below 1e-6.
pub fn f_five_halves(lambda: f64) -> f64 {
    if lambda >= SMOOTH_ABOVE {
        0.0
    } else {
        LN_F52.eval(lambda.max(0.0)).exp()
    }
}

/// Greenwood and Tripp's constant K = (16√2 π/15) (σβη)² √(σ/β) from the
/// roughness parameter σβη and the ratio σ/β \[-\].
pub fn asperity_constant(sigma_beta_eta: f64, sigma_over_beta: f64) -> f64 {
    16.0 * std::f64::consts::SQRT_2 * std::f64::consts::PI / 15.0
        * sigma_beta_eta.powi(2)
        * sigma_over_beta.sqrt()
}

/// Asperity pressure p_a = K E* F_{5/2}(Λ) \[Pa\] at film parameter Λ for
/// the constant K ([`asperity_constant`]), with docs/model.md §2.2's
/// effective modulus E' = 2E* \[Pa\].
pub fn asperity_pressure(constant: f64, film_parameter: f64, effective_modulus: f64) -> f64 {
    constant * 0.5 * effective_modulus * f_five_halves(film_parameter)
}

/// The asperities' share φ = min(1, p_a/p̄) of a contact's load for the
/// constant K, at film parameter Λ and mean Hertz pressure p̄ = Q/(πab)
/// \[Pa\]; 0 for an unloaded contact.
pub fn asperity_share(
    constant: f64,
    film_parameter: f64,
    mean_pressure: f64,
    effective_modulus: f64,
) -> f64 {
    if mean_pressure <= 0.0 {
        return 0.0;
    }
    (asperity_pressure(constant, film_parameter, effective_modulus) / mean_pressure).min(1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// F_n(0) = 2^{(n−1)/2} Γ((n+1)/2)/√(2π) (Γ(7/4), Γ(5/4), Γ(9/4) to
    /// 16 digits).
    const F52_AT_0: f64 = 1.681_792_830_507_429 * 0.919_062_526_848_883 / 2.506_628_274_631_000_5;
    const F32_AT_0: f64 = 1.189_207_115_002_721 * 0.906_402_477_055_477 / 2.506_628_274_631_000_5;
    const F72_AT_0: f64 = 2.378_414_230_005_442 * 1.133_003_096_319_346 / 2.506_628_274_631_000_5;

    #[test]
    fn the_table_meets_the_closed_forms_at_zero() {
        assert!((f_five_halves(0.0) / F52_AT_0 - 1.0).abs() < 1e-8);
        // dF_{5/2}/dλ = −(5/2) F_{3/2}: a central difference of the table.
        let e = 1e-4;
        let slope = (f_five_halves(0.5 + e) - f_five_halves(0.5 - e)) / (2.0 * e);
        let reference = -2.5 * greenwood_tripp_integral(1.5, 0.5);
        // (The monotone cubic's slopes are O(h²) accurate: 1e-5 here.)
        assert!(
            (slope / reference - 1.0).abs() < 1e-4,
            "{slope} vs {reference}"
        );
        assert!((greenwood_tripp_integral(1.5, 0.0) / F32_AT_0 - 1.0).abs() < 1e-8);
    }

    #[test]
    fn the_table_integrates_to_f_seven_halves() {
        // ∫₀^∞ F_{5/2}(λ) dλ = F_{7/2}(0)/(7/2): the whole table at once
        // (Simpson over [0, 6]; the tail beyond is below 1e-11).
        let n = 6000;
        let h = SMOOTH_ABOVE / n as f64;
        let mut sum = f_five_halves(0.0);
        for k in 1..n {
            sum += if k % 2 == 1 { 4.0 } else { 2.0 } * f_five_halves(k as f64 * h);
        }
        let integral = sum * h / 3.0;
        assert!(
            (integral / (F72_AT_0 / 3.5) - 1.0).abs() < 1e-7,
            "{integral}"
        );
    }

    #[test]
    fn the_table_follows_the_asymptote_and_ends_at_zero() {
        // F_n(λ) ~ φ(λ) Γ(n+1)/λ^{n+1} [1 − (n+1)(n+2)/(2λ²) + (n+1)…(n+4)/(8λ⁴)]:
        // at λ = 5.9 the first term left out is 1.8 %.
        let l: f64 = 5.9;
        let phi = (-0.5 * l * l).exp() / (2.0 * std::f64::consts::PI).sqrt();
        let gamma = 3.323_350_970_447_843; // Γ(7/2)
        let series = 1.0 - 3.5 * 4.5 / (2.0 * l * l) + 3.5 * 4.5 * 5.5 * 6.5 / (8.0 * l.powi(4));
        let asymptote = phi * gamma / l.powf(3.5) * series;
        assert!((f_five_halves(l) / asymptote - 1.0).abs() < 0.025);
        assert_eq!(f_five_halves(SMOOTH_ABOVE), 0.0);
        assert_eq!(f_five_halves(1e9), 0.0);
        // Between nodes the table meets the integral.
        for l in [0.013, 0.77, 2.345, 4.9] {
            let r = f_five_halves(l) / greenwood_tripp_integral(2.5, l);
            assert!((r - 1.0).abs() < 1e-6, "λ = {l}: {r}");
        }
    }

    #[test]
    fn the_share_falls_with_the_film_parameter_from_its_zero_film_limit() {
        let e = 2.3e11;
        // K = 4.7393 × 0.0016 × √1e-3.
        let k = 16.0 * 2f64.sqrt() * std::f64::consts::PI / 15.0 * 0.0016 * 1e-3f64.sqrt();
        assert!((asperity_constant(0.04, 1e-3) / k - 1.0).abs() < 1e-14);
        let p = 1e9;
        let at_zero = asperity_share(k, 0.0, p, e);
        assert!((at_zero / (k * 0.5 * e * F52_AT_0 / p) - 1.0).abs() < 1e-8);
        // At bearing pressures the zero-film share stays small (~1.7 %).
        assert!(at_zero > 0.01 && at_zero < 0.03, "{at_zero}");
        // At a low pressure the summits carry the whole load: φ = 1.
        assert_eq!(asperity_share(k, 0.0, 1e6, e), 1.0);
        let mut last = at_zero;
        for i in 1..=700 {
            let share = asperity_share(k, i as f64 * 0.01, p, e);
            assert!(share <= last, "Λ = {}", i as f64 * 0.01);
            last = share;
        }
        assert_eq!(asperity_share(k, SMOOTH_ABOVE, p, e), 0.0);
        assert_eq!(asperity_share(k, 1.0, 0.0, e), 0.0);
    }
}
