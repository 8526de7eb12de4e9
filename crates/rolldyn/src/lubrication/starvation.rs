//! Starved EHL films (docs/model.md §4; Zhang et al. 2020 eqs 26–30 after Hamrock & Dowson
//! 1977, "Isothermal elastohydrodynamic lubrication of point contacts,
//! Part IV: starvation results", ASME J. Lubr. Technol. 99, 15–23).
//!
//! The inlet meniscus sits at X_b from the contact centre, L = X_b/b (b:
//! the Hertz semi-axis along the rolling direction). The film is fully
//! flooded from the critical inlet distance
//!
//! ```text
//! L* = 1 + 3.06 [(R_x/b)² H_c]^0.56,   H_c = h_c/R_x            (Zhang et al. 2020 eq 29)
//! ```
//! on; below it the film shrinks as
//!
//! ```text
//! h_s = h ((L − 1)/(L* − 1))^0.25                                (Zhang et al. 2020 eq 30)
//! ```
//! vanishing as the meniscus reaches the contact edge (L → 1). rolldyn
//! applies the central film's boundary and factor to the minimum film too:
//! one meniscus starves both; Hamrock & Dowson fit a separate boundary for
//! h_min, which is not used (the two differ by a few per cent in L*).
//!
//! The inlet distance may instead follow from an oil supply flow Q_v: the
//! inlet film a centrifugal thin film leaves on the ring,
//! h_b = (3 ν Q_v / (2π ω² r²))^{1/3} (Zhang et al. 2020 eq 27 prints the exponent
//! 2/3, which is dimensionally wrong; docs/model.md §4), and
//! X_b = b + ((h_b/h_c − 1)/1.21)^{2/3} (R_x h_c)^{2/3} b^{−1/3} (Zhang et al. 2020
//! eq 26; no meniscus lift, L = 1, when h_b ≤ h_c).

use crate::error::{InvalidParameter, require_positive};

/// How the inlet of a ring's contacts is supplied.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Supply {
    /// Fully flooded (no starvation).
    #[default]
    Flooded,
    /// Inlet distance ratio L = X_b/b, > 1.
    InletDistance(f64),
    /// Oil supply flow: Q_v \[m³/s\], kinematic viscosity ν \[m²/s\] and the
    /// ring's raceway radius r \[m\] (the ring speed comes from the run).
    Flow {
        /// Supply flow Q_v \[m³/s\].
        flow: f64,
        /// Kinematic viscosity ν \[m²/s\].
        kinematic_viscosity: f64,
        /// Raceway radius r \[m\].
        radius: f64,
    },
}

impl Supply {
    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        match *self {
            Self::Flooded => Ok(()),
            Self::InletDistance(l) => {
                if l.is_finite() && l > 1.0 {
                    Ok(())
                } else {
                    Err(InvalidParameter::new(
                        "inlet_distance_ratio",
                        l,
                        "must be finite and > 1 (the meniscus lies outside the contact)",
                    ))
                }
            }
            Self::Flow {
                flow,
                kinematic_viscosity,
                radius,
            } => {
                require_positive("oil_flow", flow)?;
                require_positive("kinematic_viscosity", kinematic_viscosity)?;
                require_positive("raceway_radius", radius)
            }
        }
    }

    /// The inlet distance ratio L for a contact of semi-axis b, rolling
    /// radius R_x and flooded central film h_c, with the ring turning at ω
    /// \[rad/s\] (∞ when flooded).
    pub fn inlet_distance_ratio(
        &self,
        semi_minor: f64,
        rolling_radius: f64,
        central_film: f64,
        ring_speed: f64,
    ) -> f64 {
        match *self {
            Self::Flooded => f64::INFINITY,
            Self::InletDistance(l) => l,
            Self::Flow {
                flow,
                kinematic_viscosity,
                radius,
            } => {
                let w2r2 = (ring_speed * radius).powi(2);
                if w2r2 <= 0.0 || central_film <= 0.0 {
                    return f64::INFINITY;
                }
                let inlet_film =
                    (3.0 * kinematic_viscosity * flow / (2.0 * std::f64::consts::PI * w2r2)).cbrt();
                let lift = ((inlet_film / central_film - 1.0).max(0.0) / 1.21).powf(2.0 / 3.0);
                let x_b = semi_minor
                    + lift
                        * (rolling_radius * central_film).powf(2.0 / 3.0)
                        * semi_minor.powf(-1.0 / 3.0);
                x_b / semi_minor
            }
        }
    }
}

/// Critical inlet distance ratio L* (Zhang et al. 2020 eq 29) for flooded central
/// film h_c, rolling radius R_x and semi-axis b.
pub fn critical_inlet_ratio(central_film: f64, rolling_radius: f64, semi_minor: f64) -> f64 {
    let hc = central_film / rolling_radius;
    1.0 + 3.06 * ((rolling_radius / semi_minor).powi(2) * hc).powf(0.56)
}

/// Film reduction factor ((L − 1)/(L* − 1))^0.25 in [0, 1] (Zhang et al. 2020 eq 30);
/// 1 at and above L*.
pub fn starvation_factor(inlet_ratio: f64, critical_ratio: f64) -> f64 {
    if inlet_ratio >= critical_ratio {
        1.0
    } else if inlet_ratio <= 1.0 {
        0.0
    } else {
        ((inlet_ratio - 1.0) / (critical_ratio - 1.0)).powf(0.25)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn critical_ratio_and_factor_limits() {
        // 7008C inner contact, ~0.3 µm film, b ≈ 0.1 mm, R_x ≈ 2.8 mm.
        let (hc, rx, b) = (0.3e-6, 2.8e-3, 0.1e-3);
        let l_star = critical_inlet_ratio(hc, rx, b);
        let expected = 1.0 + 3.06 * ((rx / b).powi(2) * hc / rx).powf(0.56);
        assert!((l_star - expected).abs() < 1e-15 * expected);
        assert!(l_star > 1.0);
        // Flooded at and above L*, exactly.
        assert_eq!(starvation_factor(l_star, l_star), 1.0);
        assert_eq!(starvation_factor(1e9, l_star), 1.0);
        assert_eq!(
            Supply::Flooded.inlet_distance_ratio(b, rx, hc, 1.0),
            f64::INFINITY
        );
        // L → 1: no film; monotone in between with the 1/4 power.
        assert_eq!(starvation_factor(1.0, l_star), 0.0);
        let near = starvation_factor(1.0 + 1e-8, l_star);
        assert!(near > 0.0 && near < 0.02, "{near}");
        let half = 1.0 + 0.5 * (l_star - 1.0);
        assert!((starvation_factor(half, l_star) - 0.5f64.powf(0.25)).abs() < 1e-15);
        let mut last = 0.0;
        for k in 1..=100 {
            let f = starvation_factor(1.0 + k as f64 * 0.01 * (l_star - 1.0), l_star);
            assert!(f >= last);
            last = f;
        }
    }

    #[test]
    fn supply_flow_sets_the_inlet_distance() {
        let (hc, rx, b) = (0.3e-6, 2.8e-3, 0.1e-3);
        let supply = |flow: f64| Supply::Flow {
            flow,
            kinematic_viscosity: 50e-6,
            radius: 0.024,
        };
        let omega = 1000.0;
        // More oil: a thicker inlet layer, the meniscus further out.
        let l1 = supply(1e-9).inlet_distance_ratio(b, rx, hc, omega);
        let l2 = supply(1e-7).inlet_distance_ratio(b, rx, hc, omega);
        assert!(l2 > l1 && l1 >= 1.0, "{l1} {l2}");
        // h_b from the corrected eq 27 (exponent 1/3) and X_b from eq 26.
        let h_b =
            (3.0 * 50e-6 * 1e-7 / (2.0 * std::f64::consts::PI * (omega * 0.024f64).powi(2))).cbrt();
        let x_b =
            b + ((h_b / hc - 1.0) / 1.21).powf(2.0 / 3.0) * (rx * hc).powf(2.0 / 3.0) / b.cbrt();
        assert!((l2 - x_b / b).abs() < 1e-12 * l2);
        // Too little oil to lift the meniscus: L = 1 (no film).
        assert_eq!(supply(1e-30).inlet_distance_ratio(b, rx, hc, omega), 1.0);
        assert!(Supply::InletDistance(1.0).validate().is_err());
        assert!(supply(0.0).validate().is_err());
        assert!(Supply::InletDistance(1.5).validate().is_ok());
    }
}
