//! Lubricant films (docs/model.md §4): Hamrock–Dowson central and minimum film
//! thickness of an elliptical EHL contact, and the pressure dependence of
//! viscosity.
//!
//! ```text
//! U = η₀ u/(E' R_x),  W = Q/(E' R_x²),  G = α_p E',  κ = a/b
//! h_c   = R_x · 2.69 U^0.67 G^0.53 W^−0.067 (1 − 0.61 e^{−0.73 κ})
//! h_min = R_x · 3.63 U^0.68 G^0.49 W^−0.073 (1 − e^{−0.68 κ})
//! ```
//! (B. J. Hamrock & D. Dowson, *Ball Bearing Lubrication*, Wiley 1981,
//! eqs 7.26, 7.23; Zhang et al. 2020 eqs 16–25.) **Correction:** Zhang et al. 2020 eq 19
//! prints W = Q/(E R_x); the dimensionless load has R_x². u is the
//! entrainment speed of docs/model.md §3 (mean surface speed relative to the
//! contact), not Zhang et al. 2020 eq 14's shaft-speed approximation. E' here is the
//! effective modulus of docs/model.md §2.2 (E' = 2/[(1−ν₁²)/E₁ + (1−ν₂²)/E₂]), the
//! one Hamrock & Dowson use.
//!
//! [`drag`]: drag of the air–oil mixture on the balls and the cage.
//! [`rolling_resistance`]: the EHL (Poiseuille) rolling resistance of a
//! contact. [`churning`]: the churning loss of an oil bath or jet.
//! [`approach`]: the film in the normal approach, a state relaxing to
//! its steady value. [`starvation`]: starved films from the inlet distance or the oil supply
//! (Zhang et al. 2020 eqs 26–30). [`film`]: a contact's whole film state (flooded
//! and starved films, Λ = h_min/σ, K_oil). [`film_stiffness`]: the oil film's normal
//! stiffness K_oil = Q/(0.073 h_min) (Zhang et al. 2020 eq 37).

use crate::error::InvalidParameter;
use serde::{Deserialize, Serialize};

pub mod approach;
pub mod churning;
pub mod drag;
pub mod film;
pub mod mixed;
pub mod rolling_resistance;
pub mod starvation;
pub use film::{ContactFilm, FilmConditions, contact_film};
pub use starvation::{Supply, critical_inlet_ratio, starvation_factor};

/// Pressure dependence of the viscosity.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum PressureViscosity {
    /// Barus: η = η₀ exp(α_p p).
    #[default]
    Barus,
    /// Roelands: η = η₀ exp[(ln η₀ + 9.67)((1 + p/p_r)^z − 1)],
    /// p_r = 1.96e8 Pa, z = α_p / (5.1e-9 (ln η₀ + 9.67)) (η₀ in Pa·s;
    /// Hamrock, *Fundamentals of Fluid Film Lubrication*, eqs 4.11–4.14),
    /// so that both laws have the same initial slope α_p.
    Roelands,
}

/// Lubricant properties the film and traction models need.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Lubricant {
    /// Dynamic viscosity η₀ at atmospheric pressure \[Pa·s\], > 0.
    pub viscosity: f64,
    /// Pressure–viscosity coefficient α_p \[1/Pa\], ≥ 0.
    pub pressure_viscosity: f64,
    /// Pressure–viscosity law.
    #[serde(default)]
    pub pressure_model: PressureViscosity,
}

/// Roelands' reference pressure p_r \[Pa\].
pub const ROELANDS_PRESSURE: f64 = 1.96e8;

impl Lubricant {
    /// Checks the properties.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        if !(self.viscosity.is_finite() && self.viscosity > 0.0) {
            return Err(InvalidParameter::new(
                "viscosity",
                self.viscosity,
                "must be positive",
            ));
        }
        if !(self.pressure_viscosity.is_finite() && self.pressure_viscosity >= 0.0) {
            return Err(InvalidParameter::new(
                "pressure_viscosity",
                self.pressure_viscosity,
                "must not be negative",
            ));
        }
        Ok(())
    }

    /// Viscosity η(p) \[Pa·s\] by the chosen pressure–viscosity law
    /// (Barus's exponential by [`crate::math::exponential::exp`]).
    #[inline]
    pub fn viscosity_at(&self, pressure: f64) -> f64 {
        match self.pressure_model {
            PressureViscosity::Barus => self.barus_viscosity(pressure),
            PressureViscosity::Roelands => {
                let ln_ratio = self.viscosity.ln() + 9.67;
                let z = self.pressure_viscosity / (5.1e-9 * ln_ratio);
                self.viscosity
                    * (ln_ratio * ((1.0 + pressure / ROELANDS_PRESSURE).powf(z) - 1.0)).exp()
            }
        }
    }

    /// [`Self::viscosity_at`] of each of `values` (pressures \[Pa\] on
    /// entry, viscosities \[Pa·s\] on return): the same arithmetic per
    /// value, Barus's in a loop the compiler vectorizes.
    #[inline(always)]
    pub fn viscosities_at(&self, values: &mut [f64]) {
        match self.pressure_model {
            PressureViscosity::Barus => {
                for value in values {
                    *value = self.barus_viscosity(*value);
                }
            }
            PressureViscosity::Roelands => {
                for value in values {
                    *value = self.viscosity_at(*value);
                }
            }
        }
    }

    /// η₀ exp(α p).
    #[inline(always)]
    fn barus_viscosity(&self, pressure: f64) -> f64 {
        self.viscosity * crate::math::exponential::exp(self.pressure_viscosity * pressure)
    }
}

/// Film thicknesses of one contact \[m\].
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Film {
    /// Central film thickness h_c.
    pub central: f64,
    /// Minimum film thickness h_min.
    pub minimum: f64,
}

/// Hamrock–Dowson film for entrainment speed u \[m/s\], load Q \[N\],
/// rolling-direction radius R_x \[m\], effective modulus E' \[Pa\] and
/// ellipticity κ. Zero when u or Q is zero.
pub fn hamrock_dowson(
    lubricant: &Lubricant,
    entrainment_speed: f64,
    load: f64,
    rolling_radius: f64,
    effective_modulus: f64,
    ellipticity: f64,
) -> Film {
    let u = entrainment_speed.abs();
    if u <= 0.0 || load <= 0.0 {
        return Film::default();
    }
    let rx = rolling_radius;
    let speed = lubricant.viscosity * u / (effective_modulus * rx);
    let weight = load / (effective_modulus * rx * rx);
    let material = lubricant.pressure_viscosity * effective_modulus;
    // The powers as exponentials of the three logarithms (3 ln + 2 exp
    // instead of 6 pow: the films are evaluated at every contact of every
    // right-hand side; the same values to ~1e-15).
    let (ln_u, ln_g, ln_w) = (speed.ln(), material.ln(), weight.ln());
    Film {
        central: rx
            * 2.69
            * (0.67 * ln_u + 0.53 * ln_g - 0.067 * ln_w).exp()
            * (1.0 - 0.61 * (-0.73 * ellipticity).exp()),
        minimum: rx
            * 3.63
            * (0.68 * ln_u + 0.49 * ln_g - 0.073 * ln_w).exp()
            * (1.0 - (-0.68 * ellipticity).exp()),
    }
}

/// Oil-film normal stiffness K_oil = dQ/dh_min = Q/(0.073 h_min) \[N/m\]
/// (Zhang et al. 2020 eq 37 written out: h_min ∝ Q^−0.073 in the Hamrock–Dowson
/// formula; docs/model.md §4). Infinite without a film (the contact is then
/// Hertz alone).
pub fn film_stiffness(load: f64, minimum_film: f64) -> f64 {
    if minimum_film > 0.0 {
        load / (0.073 * minimum_film)
    } else {
        f64::INFINITY
    }
}

/// Series stiffness of the Hertz contact (K_c = dQ/dδ) and the film:
/// 1/K = 1/K_c + 1/K_oil \[N/m\].
pub fn series_stiffness(contact: f64, film: f64) -> f64 {
    1.0 / (1.0 / contact + 1.0 / film)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn film_stiffness_is_the_derivative_of_the_film_law() {
        let oil = Lubricant {
            viscosity: 0.0467,
            pressure_viscosity: 2.2e-8,
            pressure_model: PressureViscosity::Barus,
        };
        let (u, rx, ep, kappa) = (10.0, 2.8e-3, 2.29e11, 5.1);
        let q = 50.0;
        let film = hamrock_dowson(&oil, u, q, rx, ep, kappa);
        // dQ/dh_min by central differences of h_min(Q) (κ held, as in eq 37).
        let dq = 1e-4 * q;
        let dh = hamrock_dowson(&oil, u, q + dq, rx, ep, kappa).minimum
            - hamrock_dowson(&oil, u, q - dq, rx, ep, kappa).minimum;
        // h_min falls with load: the stiffness is the magnitude.
        let fd = (2.0 * dq / dh).abs();
        let k = film_stiffness(q, film.minimum);
        assert!((k / fd - 1.0).abs() < 1e-6, "{k} vs {fd}");
        assert_eq!(film_stiffness(q, 0.0), f64::INFINITY);
        assert_eq!(series_stiffness(2e8, f64::INFINITY), 2e8);
        assert!((series_stiffness(2e8, 2e8) - 1e8).abs() < 1e-6);
    }

    #[test]
    fn scaling_laws() {
        let oil = Lubricant {
            viscosity: 0.0467,
            pressure_viscosity: 2.2e-8,
            pressure_model: PressureViscosity::Barus,
        };
        let base = hamrock_dowson(&oil, 10.0, 50.0, 2.8e-3, 2.29e11, 5.1);
        let fast = hamrock_dowson(&oil, 20.0, 50.0, 2.8e-3, 2.29e11, 5.1);
        let heavy = hamrock_dowson(&oil, 10.0, 100.0, 2.8e-3, 2.29e11, 5.1);
        assert!(((fast.central / base.central) - 2f64.powf(0.67)).abs() < 1e-12);
        assert!(((heavy.central / base.central) - 2f64.powf(-0.067)).abs() < 1e-12);
        assert!(((fast.minimum / base.minimum) - 2f64.powf(0.68)).abs() < 1e-12);
        // 7008C-like contact, 46.7 mPa·s oil at ~10 m/s: a film of order 0.1–1 µm.
        assert!(base.central > 1e-7 && base.central < 2e-6, "{base:?}");
        assert!(base.minimum < base.central);
        assert_eq!(
            hamrock_dowson(&oil, 0.0, 50.0, 2.8e-3, 2.29e11, 5.1),
            Film::default()
        );
    }

    #[test]
    fn roelands_has_the_barus_slope_and_grows_slower() {
        let barus = Lubricant {
            viscosity: 0.0467,
            pressure_viscosity: 2.2e-8,
            pressure_model: PressureViscosity::Barus,
        };
        let roelands = Lubricant {
            pressure_model: PressureViscosity::Roelands,
            ..barus
        };
        // d ln η/dp at p = 0 is α_p for both (Hamrock eq 4.14 defines z so).
        let h = 1e3;
        let slope = (roelands.viscosity_at(h) / roelands.viscosity).ln() / h;
        assert!((slope / 2.2e-8 - 1.0).abs() < 1e-3, "{slope}");
        // At 1 GPa Roelands is far below the exponential Barus law.
        assert!(roelands.viscosity_at(1e9) < 0.1 * barus.viscosity_at(1e9));
        assert_eq!(roelands.viscosity_at(0.0), roelands.viscosity);
    }
}
