//! Hertz point contact of a ball on a raceway (docs/model.md §2.2).
//!
//! # Curvatures
//! With γ = D cos α / d_m the principal relative curvatures of ball and
//! groove are, in the rolling direction x and across it y (Harris &
//! Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed., §6.2):
//! ```text
//! inner: 1/R_x = 2/(D(1 − γ)),  outer: 1/R_x = 2/(D(1 + γ)),   both: 1/R_y = (2 − 1/f)/D
//! Σρ = 1/R_x + 1/R_y,           F(ρ) = (1/R_x − 1/R_y)/Σρ
//! ```
//! which is docs/model.md §2.2's Σρ = (1/D)(4 − 1/f ± 2γ/(1∓γ)).
//!
//! # Exact solve
//! The ellipticity κ = a/b (a across, b along the rolling direction) solves
//! ```text
//! F(ρ) = ((κ² + 1) E(m) − 2 K(m)) / ((κ² − 1) E(m)) = (K − (2 − m) D) / E,   m = 1 − 1/κ²
//! ```
//! (the second form, with D = (K − E)/m, avoids the 0/0 at κ → 1). It is
//! solved by Brent's method in ln κ to machine precision (1e-12 relative at least).
//! Then, with R = 1/Σρ and E' the effective modulus,
//! ```text
//! a = (6κ² E Q R/(π E'))^{1/3},  b = (6 E Q R/(π κ E'))^{1/3},
//! δ = K (9/(2 E R) (Q/(π κ E'))²)^{1/3},   Q = K_c δ^{3/2},
//! K_c = π κ E' √(2 E R/(9 K³)),   p₀ = 3Q/(2π a b)
//! ```
//! (Zhang et al. 2025 eq 4 prints K_c garbled; this is the form of Harris & Kotzalas
//! eqs 6.34–6.43 rewritten with E').
//!
//! # Options
//! * [`HertzModel::HamrockBrewe`]: κ ≈ 1.0339 (R_y/R_x)^0.636,
//!   E ≈ 1.0003 + 0.5968 R_x/R_y, K ≈ 1.5277 + 0.6023 ln(R_y/R_x)
//!   (B. J. Hamrock & D. E. Brewe, "Simplified solution for stresses and
//!   deformations", J. Lubr. Technol. 105 (1983) 171–177). Oracle and option.
//! * [`HertzModel::HertzCircular`]: Shan et al. 2023 eq 12,
//!   K = 4/(3π(h_l + h_r)) √(r_l r_b/(r_l + r_b)) with h = (1 − ν²)/(πE),
//!   i.e. a sphere on a sphere of the raceway's in-plane radius r_l (the
//!   groove-bottom radius). **Correction:** the outer raceway is concave, so
//!   its radius enters with a minus sign, r_l r_b/(r_l − r_b); the paper
//!   prints r_l + r_b for all contacts. For reproducing Shan et al. 2023 only.

use crate::error::InvalidParameter;
use crate::geometry::{Raceway, RingKind};
use crate::math::elliptic;
use crate::math::roots::brent;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Which Hertz contact-stiffness model to use (case file: `model.contact_stiffness`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum HertzModel {
    /// Exact ellipticity solve with complete elliptic integrals (default).
    #[default]
    Exact,
    /// Hamrock–Brewe (1983) closed-form approximations of κ, E, K.
    HamrockBrewe,
    /// Shan et al. 2023 eq 12: circular contact of two spheres (planar papers only).
    HertzCircular,
}

impl HertzModel {
    /// All variants, in the order the docs list them.
    pub const ALL: [HertzModel; 3] = [Self::Exact, Self::HamrockBrewe, Self::HertzCircular];
    /// The case-file name of the model.
    pub fn name(self) -> &'static str {
        match self {
            Self::Exact => "exact",
            Self::HamrockBrewe => "hamrock_brewe",
            Self::HertzCircular => "hertz_circular",
        }
    }
}

/// Relative curvature of a ball–raceway contact.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Curvature {
    /// Effective radius in the rolling direction R_x \[m\].
    pub rolling_radius: f64,
    /// Effective radius across the rolling direction R_y \[m\].
    pub transverse_radius: f64,
}

impl Curvature {
    /// Curvature of a ball of diameter D in the groove of `raceway` at
    /// contact angle α, for pitch diameter d_m.
    pub fn of_raceway(
        raceway: &Raceway,
        ball_diameter: f64,
        pitch_diameter: f64,
        contact_angle: f64,
    ) -> Self {
        let d = ball_diameter;
        let gamma = d * contact_angle.cos() / pitch_diameter;
        let rolling_radius = match raceway.kind {
            RingKind::Inner => d * (1.0 - gamma) / 2.0,
            RingKind::Outer => d * (1.0 + gamma) / 2.0,
        };
        let f = raceway.groove_curvature;
        Self {
            rolling_radius,
            transverse_radius: f * d / (2.0 * f - 1.0),
        }
    }

    /// Equal radii R in both directions (sphere on sphere).
    pub fn circular(effective_radius: f64) -> Self {
        Self {
            rolling_radius: effective_radius,
            transverse_radius: effective_radius,
        }
    }

    /// Curvature sum Σρ = 1/R_x + 1/R_y \[1/m\].
    pub fn sum(&self) -> f64 {
        1.0 / self.rolling_radius + 1.0 / self.transverse_radius
    }

    /// Curvature difference F(ρ) = (1/R_x − 1/R_y)/Σρ \[-\].
    pub fn difference(&self) -> f64 {
        (1.0 / self.rolling_radius - 1.0 / self.transverse_radius) / self.sum()
    }
}

/// Load-independent Hertz constants of one contact: a = a* Q^{1/3},
/// b = b* Q^{1/3}, δ = δ* Q^{2/3}, Q = K_c δ^{3/2}.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct HertzCoefficients {
    /// Ellipticity κ = a/b ≥ 1.
    pub ellipticity: f64,
    /// Complete elliptic integral of the first kind K(m), m = 1 − 1/κ².
    pub elliptic_k: f64,
    /// Complete elliptic integral of the second kind E(m).
    pub elliptic_e: f64,
    /// a* \[m/N^{1/3}\]: semi-major axis (across rolling) per Q^{1/3}.
    pub semi_major_coefficient: f64,
    /// b* \[m/N^{1/3}\]: semi-minor axis (along rolling) per Q^{1/3}.
    pub semi_minor_coefficient: f64,
    /// δ* \[m/N^{2/3}\]: approach per Q^{2/3}.
    pub approach_coefficient: f64,
    /// K_c \[N/m^{1.5}\]: load–deflection constant.
    pub stiffness: f64,
}

/// Hertz results at one load.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct HertzResult {
    /// Normal load Q \[N\].
    pub load: f64,
    /// Semi-major axis a \[m\] (across the rolling direction).
    pub semi_major: f64,
    /// Semi-minor axis b \[m\] (along the rolling direction).
    pub semi_minor: f64,
    /// Elastic approach δ \[m\].
    pub approach: f64,
    /// Maximum (central) pressure p₀ \[Pa\].
    pub max_pressure: f64,
}

impl HertzCoefficients {
    /// Constants from κ, the elliptic integrals, the curvature sum and E'.
    fn from_parts(
        ellipticity: f64,
        k: f64,
        e: f64,
        curvature_sum: f64,
        effective_modulus: f64,
    ) -> Self {
        let r = 1.0 / curvature_sum;
        let ep = effective_modulus;
        let kappa = ellipticity;
        Self {
            ellipticity: kappa,
            elliptic_k: k,
            elliptic_e: e,
            semi_major_coefficient: (6.0 * kappa * kappa * e * r / (PI * ep)).cbrt(),
            semi_minor_coefficient: (6.0 * e * r / (PI * kappa * ep)).cbrt(),
            approach_coefficient: k * (9.0 / (2.0 * e * r) / (PI * kappa * ep).powi(2)).cbrt(),
            stiffness: PI * kappa * ep * (2.0 * e * r / (9.0 * k.powi(3))).sqrt(),
        }
    }

    /// Exact Hertz constants for a curvature and an effective modulus E'.
    pub fn exact(curvature: &Curvature, effective_modulus: f64) -> Result<Self, InvalidParameter> {
        let kappa = solve_ellipticity(curvature.difference())?;
        let c = elliptic::complete(1.0 - 1.0 / (kappa * kappa));
        Ok(Self::from_parts(
            kappa,
            c.k,
            c.e,
            curvature.sum(),
            effective_modulus,
        ))
    }

    /// Hamrock–Brewe (1983) approximate constants.
    pub fn hamrock_brewe(curvature: &Curvature, effective_modulus: f64) -> Self {
        let ratio = curvature.transverse_radius / curvature.rolling_radius;
        Self::from_parts(
            1.0339 * ratio.powf(0.636),
            1.5277 + 0.6023 * ratio.ln(),
            1.0003 + 0.5968 / ratio,
            curvature.sum(),
            effective_modulus,
        )
    }

    /// Circular contact (κ = 1, K = E = π/2) of effective radius R_eff:
    /// K_c = (2/3) E' √R_eff, the sphere-on-sphere Hertz law.
    pub fn circular(effective_radius: f64, effective_modulus: f64) -> Self {
        let curvature = Curvature::circular(effective_radius);
        Self::from_parts(1.0, PI / 2.0, PI / 2.0, curvature.sum(), effective_modulus)
    }

    /// Results at normal load Q ≥ 0.
    pub fn at_load(&self, load: f64) -> HertzResult {
        let q3 = crate::math::cube_root::cbrt(load.max(0.0));
        let semi_major = self.semi_major_coefficient * q3;
        let semi_minor = self.semi_minor_coefficient * q3;
        HertzResult {
            load,
            semi_major,
            semi_minor,
            approach: self.approach_coefficient * q3 * q3,
            max_pressure: if load > 0.0 {
                1.5 * load / (PI * semi_major * semi_minor)
            } else {
                0.0
            },
        }
    }

    /// Elastic load Q = K_c δ^{3/2} (0 for δ ≤ 0).
    #[inline]
    pub fn load(&self, approach: f64) -> f64 {
        if approach > 0.0 {
            self.stiffness * approach * approach.sqrt()
        } else {
            0.0
        }
    }
}

/// Below this parameter m the numerator K − (2 − m)D (which is O(m)) is
/// taken from its Maclaurin series instead of a cancelling difference.
const SERIES_BELOW_M: f64 = 1e-3;

/// The ellipticity equation's right-hand side F(κ) = (K − (2 − m) D)/E.
///
/// For m < 1e-3 the numerator uses its series, from the series of K and E
/// (A&S 17.3.11–12): K − (2 − m)D = (π/2) m (3/8 + 3m/32 + 45m²/1024 +
/// 105m³/4096 + O(m⁴)), keeping F accurate to ~1e-14 relative down to κ → 1.
pub fn ellipticity_equation(kappa: f64) -> f64 {
    let m = 1.0 - 1.0 / (kappa * kappa);
    let c = elliptic::complete(m);
    let numerator = if m < SERIES_BELOW_M {
        PI / 2.0 * m * (3.0 / 8.0 + m * (3.0 / 32.0 + m * (45.0 / 1024.0 + m * 105.0 / 4096.0)))
    } else {
        c.k - (2.0 - m) * c.d
    };
    numerator / c.e
}

/// Largest ellipticity searched; F(ρ) ≥ F(κ_max) ≈ 1 − 1e-7 is rejected.
const MAX_ELLIPTICITY: f64 = 1.0e4;

/// Solves F(κ) = F(ρ) for κ ≥ 1 by Brent's method in ln κ.
/// F(ρ) = 0 gives κ = 1 exactly (circular contact).
pub fn solve_ellipticity(curvature_difference: f64) -> Result<f64, InvalidParameter> {
    let f = curvature_difference;
    if !(0.0..1.0).contains(&f) || !f.is_finite() {
        return Err(InvalidParameter::new(
            "curvature_difference",
            f,
            "must lie in [0, 1) for a ball in a groove (check the groove curvatures)",
        ));
    }
    if f == 0.0 {
        return Ok(1.0);
    }
    let root = brent(
        |u: f64| ellipticity_equation(u.exp()) - f,
        0.0,
        MAX_ELLIPTICITY.ln(),
        // Purely relative tolerance (Brent adds 2ε|x|): ln κ can be ~1e-9.
        f64::MIN_POSITIVE,
    )
    .map_err(|e| {
        InvalidParameter::new(
            "curvature_difference",
            f,
            format!("ellipticity solve failed: {e}"),
        )
    })?;
    Ok(root.exp())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn series_branch_is_continuous() {
        // Both evaluations of the numerator agree at the switch-over point.
        let kappa = (1.0f64 / (1.0 - SERIES_BELOW_M)).sqrt();
        let m = SERIES_BELOW_M;
        let c = elliptic::complete(m);
        let direct = (c.k - (2.0 - m) * c.d) / c.e;
        let series = ellipticity_equation(kappa * (1.0 - 1e-15));
        assert!(
            ((direct - series) / direct).abs() < 1e-11,
            "{direct} vs {series}"
        );
    }

    #[test]
    fn solve_satisfies_equation() {
        // A2: the solve satisfies its defining equation to 1e-10 relative.
        for f in [1e-6, 1e-3, 0.1, 0.5, 0.8, 0.9, 0.95, 0.99, 0.999] {
            let k = solve_ellipticity(f).unwrap();
            let r = ellipticity_equation(k);
            assert!(
                ((r - f) / f).abs() < 1e-10,
                "F = {f}: κ = {k}, residual {}",
                r - f
            );
        }
    }

    #[test]
    fn circular_limit_is_sphere_on_sphere() {
        // A2: equal curvatures → κ = 1 and the sphere-on-sphere formulas
        // a³ = 3 Q R_eff/(4 E*), δ = a²/R_eff, with E* = E'/2.
        let (r_eff, ep, q) = (5e-3, 2.2e11, 100.0);
        let c = Curvature::circular(r_eff);
        assert_eq!(c.difference(), 0.0);
        let h = HertzCoefficients::exact(&c, ep).unwrap();
        assert_eq!(h.ellipticity, 1.0);
        let res = h.at_load(q);
        let a_ref = (3.0 * q * r_eff / (4.0 * ep / 2.0)).cbrt();
        assert!(((res.semi_major - a_ref) / a_ref).abs() < 1e-12);
        assert!(((res.semi_minor - a_ref) / a_ref).abs() < 1e-12);
        let d_ref = a_ref * a_ref / r_eff;
        assert!(((res.approach - d_ref) / d_ref).abs() < 1e-12);
        assert!(((h.load(d_ref) - q) / q).abs() < 1e-12);
        let circ = HertzCoefficients::circular(r_eff, ep);
        assert!(((circ.stiffness - h.stiffness) / h.stiffness).abs() < 1e-14);
        assert!(((circ.stiffness - 2.0 / 3.0 * ep * r_eff.sqrt()) / circ.stiffness).abs() < 1e-14);
    }

    #[test]
    fn load_and_approach_are_inverse() {
        let c = Curvature {
            rolling_radius: 2.8e-3,
            transverse_radius: 40e-3,
        };
        let h = HertzCoefficients::exact(&c, 2.28e11).unwrap();
        let r = h.at_load(350.0);
        assert!(((h.load(r.approach) - 350.0) / 350.0).abs() < 1e-12);
        assert!((r.semi_major / r.semi_minor - h.ellipticity).abs() < 1e-12);
    }

    #[test]
    fn rejects_out_of_range_difference() {
        assert!(solve_ellipticity(1.0).is_err());
        assert!(solve_ellipticity(-0.1).is_err());
        assert!(solve_ellipticity(f64::NAN).is_err());
    }
}
