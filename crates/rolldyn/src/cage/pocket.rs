//! Ball–pocket contact (docs/model.md §5): pocket shapes and normal force laws.
//!
//! The ball centre's offset d from the pocket centre is measured
//! perpendicular to the pocket axis (cylindrical pocket, axis along the
//! cage radius) or in all directions (spherical pocket). With the
//! per-side clearance c = C_p/2 and δ = d − c:
//! ```text
//! linear      F = k δ + c_d δ̇                      δ > 0        (Zhang et al. 2025 eq 6)
//! hertz       F = K_bc δ^{3/2} + c_d δ̇             δ > 0        (Deng et al. 2022 eq 29)
//! gupta_film  F = (F_w/c) d                         d ≤ c        (Deng et al. 2022 eqs 26–28)
//!             F = F_w + K_bc δ^{3/2} + c_d δ̇        d > c
//! ```
//! F is clamped at ≥ 0 (no adhesion). In Deng et al. 2022 the film term is
//! K'_c δ_bc with K'_c = 11/C_p, C_p Deng et al. 2022's per-side clearance: a force
//! of F_w = 11 N when the ball reaches the pocket wall, an empirical
//! hydrodynamic term (Gupta). rolldyn keeps F_w as a parameter (default
//! 11 N in the case file) and treats the film term as elastic (it is a
//! function of position only), so it stores energy ½ (F_w/c) d².
//!
//! K_bc is the Hertz constant of the ball in the concave pocket: ball
//! radius R_b = D/2, pocket radius R_p = (D + C_p)/2. Deng et al. 2022 eq 29 gives
//! it by the Hamrock–Brewe approximation with R_ξ = R_b R_p/(R_p − R_b)
//! across a cylindrical pocket's axis and R_η = R_b along it;
//! [`hertz_pocket_stiffness`] uses the exact Hertz solution of
//! [`crate::contact::HertzCoefficients`] with the same radii (spherical
//! pocket: R_ξ in both directions).

use crate::contact::{Curvature, HertzCoefficients};
use crate::error::{InvalidParameter, require_non_negative, require_positive};
use serde::{Deserialize, Serialize};

/// Shape of the cage pockets.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum PocketShape {
    /// Cylinder with its axis along the cage radius: no radial guidance
    /// of the cage by the balls.
    #[default]
    Cylindrical,
    /// Sphere: the balls also hold the cage radially (ball-guided cages).
    Spherical,
}

/// Ball–pocket normal force law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PocketLaw {
    /// k δ + c_d δ̇ beyond the clearance (Zhang et al. 2025 eq 6).
    Linear {
        /// Stiffness k \[N/m\].
        stiffness: f64,
        /// Damping c_d \[N·s/m\].
        damping: f64,
    },
    /// K_bc δ^{3/2} + c_d δ̇ beyond the clearance (Deng et al. 2022 eq 29).
    Hertz {
        /// Hertz constant K_bc \[N/m^{3/2}\].
        stiffness: f64,
        /// Damping c_d \[N·s/m\].
        damping: f64,
    },
    /// Film force inside the clearance, Hertz beyond (Deng et al. 2022 eqs 26–28).
    GuptaFilm {
        /// Film force at the pocket wall F_w \[N\] (Deng et al. 2022: 11 N).
        wall_force: f64,
        /// Hertz constant K_bc \[N/m^{3/2}\].
        stiffness: f64,
        /// Damping c_d beyond the clearance \[N·s/m\].
        damping: f64,
    },
}

/// Normal force of one pocket contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PocketForce {
    /// Total normal force F ≥ 0 \[N\].
    pub total: f64,
    /// Its elastic (position-only) part \[N\]; F − elastic is damping.
    pub elastic: f64,
}

impl PocketLaw {
    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        let (stiffness, damping) = match *self {
            Self::Linear { stiffness, damping } | Self::Hertz { stiffness, damping } => {
                (stiffness, damping)
            }
            Self::GuptaFilm {
                wall_force,
                stiffness,
                damping,
            } => {
                require_non_negative("pocket_wall_force", wall_force)?;
                (stiffness, damping)
            }
        };
        require_positive("pocket_stiffness", stiffness)?;
        require_non_negative("pocket_damping", damping)
    }

    /// Whether the law acts at offset d for per-side clearance c (the film
    /// law acts everywhere off-centre, the others only beyond c).
    #[inline]
    pub fn acts(&self, offset: f64, half_clearance: f64) -> bool {
        match self {
            Self::GuptaFilm { .. } => offset > 0.0,
            _ => offset > half_clearance,
        }
    }

    /// Normal force at offset d, per-side clearance c and rate ḋ.
    #[inline]
    pub fn force(&self, offset: f64, half_clearance: f64, rate: f64) -> PocketForce {
        let delta = offset - half_clearance;
        let (elastic, damping) = match *self {
            Self::Linear { stiffness, damping } => (stiffness * delta.max(0.0), damping),
            Self::Hertz { stiffness, damping } => (hertz(stiffness, delta), damping),
            Self::GuptaFilm {
                wall_force,
                stiffness,
                damping,
            } => {
                if delta <= 0.0 {
                    return PocketForce {
                        total: wall_force * offset / half_clearance,
                        elastic: wall_force * offset / half_clearance,
                    };
                }
                (wall_force + hertz(stiffness, delta), damping)
            }
        };
        if delta <= 0.0 {
            return PocketForce {
                total: 0.0,
                elastic: 0.0,
            };
        }
        PocketForce {
            total: (elastic + damping * rate).max(0.0),
            elastic,
        }
    }

    /// Elastic energy at offset d (the integral of the elastic force) \[J\].
    pub fn energy(&self, offset: f64, half_clearance: f64) -> f64 {
        let delta = (offset - half_clearance).max(0.0);
        match *self {
            Self::Linear { stiffness, .. } => 0.5 * stiffness * delta * delta,
            Self::Hertz { stiffness, .. } => 0.4 * stiffness * delta * delta * delta.sqrt(),
            Self::GuptaFilm {
                wall_force,
                stiffness,
                ..
            } => {
                let inside = offset.min(half_clearance);
                0.5 * wall_force * inside * inside / half_clearance
                    + wall_force * delta
                    + 0.4 * stiffness * delta * delta * delta.sqrt()
            }
        }
    }
}

#[inline]
fn hertz(stiffness: f64, delta: f64) -> f64 {
    if delta > 0.0 {
        stiffness * delta * delta.sqrt()
    } else {
        0.0
    }
}

/// Hertz constant K_bc \[N/m^{3/2}\] of a ball of diameter D in a pocket
/// of diameter D + C_p, for the effective modulus E' of ball and cage
/// materials (exact Hertz; Deng et al. 2022 eq 29 uses Hamrock–Brewe).
pub fn hertz_pocket_stiffness(
    shape: PocketShape,
    ball_diameter: f64,
    pocket_clearance: f64,
    effective_modulus: f64,
) -> Result<f64, InvalidParameter> {
    let rb = 0.5 * ball_diameter;
    let rp = 0.5 * (ball_diameter + pocket_clearance);
    let conformal = rb * rp / (rp - rb);
    let curvature = match shape {
        // Across the axis: ball in the concave cylinder; along it: ball alone.
        PocketShape::Cylindrical => Curvature {
            rolling_radius: rb,
            transverse_radius: conformal,
        },
        PocketShape::Spherical => Curvature::circular(conformal),
    };
    Ok(HertzCoefficients::exact(&curvature, effective_modulus)?.stiffness)
}

#[cfg(test)]
mod tests {
    use super::*;

    const C: f64 = 0.1e-3;

    fn laws() -> [PocketLaw; 3] {
        [
            PocketLaw::Linear {
                stiffness: 1e7,
                damping: 0.0,
            },
            PocketLaw::Hertz {
                stiffness: 1e9,
                damping: 0.0,
            },
            PocketLaw::GuptaFilm {
                wall_force: 11.0,
                stiffness: 1e9,
                damping: 0.0,
            },
        ]
    }

    #[test]
    fn energy_is_the_integral_of_the_elastic_force() {
        // dE/dd = F_elastic, checked by central differences on both sides
        // of the clearance.
        for law in laws() {
            for d in [0.3 * C, 0.9 * C, 1.2 * C, 2.0 * C] {
                let h = 1e-10;
                let de = (law.energy(d + h, C) - law.energy(d - h, C)) / (2.0 * h);
                let f = law.force(d, C, 0.0).elastic;
                assert!(
                    (de - f).abs() <= 1e-6 * f.abs().max(1e-3),
                    "{law:?} at {d}: dE/dd {de} vs F {f}"
                );
            }
        }
    }

    #[test]
    fn gupta_film_is_continuous_at_the_wall_and_matches_seed001() {
        let law = laws()[2];
        let inside = law.force(C * (1.0 - 1e-12), C, 0.0).total;
        let outside = law.force(C * (1.0 + 1e-12), C, 0.0).total;
        assert!((inside - 11.0).abs() < 1e-6 && (outside - 11.0).abs() < 1e-6);
        // Inside: K'_c d with K'_c = 11 N / c (Deng et al. 2022 eq 28).
        assert!((law.force(0.5 * C, C, 0.0).total - 5.5).abs() < 1e-12);
    }

    #[test]
    fn damping_cannot_pull() {
        let law = PocketLaw::Linear {
            stiffness: 1e7,
            damping: 1e3,
        };
        assert_eq!(law.force(1.01 * C, C, -10.0).total, 0.0);
        assert!(!law.acts(0.99 * C, C) && law.acts(1.01 * C, C));
    }

    #[test]
    fn hertz_pocket_stiffness_matches_seed001_eq29() {
        // Deng et al. 2022 eq 29 (Hamrock–Brewe) for a cylindrical pocket of the
        // 7008C (D = 7.938 mm, C_p = 0.175 mm), steel on steel.
        let (d, cp, ep): (f64, f64, f64) = (7.938e-3, 0.175e-3, 206e9 / (1.0 - 0.3f64.powi(2)));
        let rb = d / 2.0;
        let rp = (d + cp) / 2.0;
        let r_xi = rb * rp / (rp - rb);
        let r_eta = rb;
        let ratio = r_xi / r_eta;
        let k1 = 1.0339 * ratio.powf(0.636);
        let gamma = 1.5277 + 0.6023 * ratio.ln();
        let eps1 = 1.0003 + 0.5968 / ratio;
        let r1 = r_xi * r_eta / (r_xi + r_eta);
        let seed = std::f64::consts::PI * k1 * ep * (r1 * eps1 / (4.5 * gamma.powi(3))).sqrt();
        let exact = hertz_pocket_stiffness(PocketShape::Cylindrical, d, cp, ep).unwrap();
        // Hamrock–Brewe's accuracy at R_ξ/R_η ≈ 47 (docs/contact.md: ≤ 2.7 %).
        assert!((exact / seed - 1.0).abs() < 0.03, "{exact} vs {seed}");
        let sphere = hertz_pocket_stiffness(PocketShape::Spherical, d, cp, ep).unwrap();
        assert!(sphere > exact, "a conforming sphere is stiffer");
    }
}
