//! EHL traction rheology (Deng et al. 2022 eqs 13–15; docs/model.md §3, model 3):
//! ```text
//! τ = −min( τ₀ asinh( η(p) |v| / (h τ₀) ),  Λ_L p ) v/|v|,     η(p) = η₀ exp(α_p p)   (Barus)
//! ```
//! Eyring's shear-thinning with a limiting shear stress Λ_L p (K. L.
//! Johnson & J. L. Tevaarwerk, Proc. R. Soc. A 356 (1977) 215; Deng et al. 2022).
//! At small slip the law is Newtonian, τ ≈ η v/h; at large slip it
//! saturates at Λ_L p. The film h is the Hamrock–Dowson central film of the
//! contact (docs/model.md §4). The stress is continuous in the slip (asinh is odd
//! and smooth), so no regularisation is needed.

use super::{BATCH, ContactConditions, TractionLaw};
use crate::error::{InvalidParameter, require_positive};
use crate::lubrication::Lubricant;
use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

/// Parameters of the EHL traction rheology.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EhlRheology {
    /// Eyring stress τ₀ \[Pa\] (typically 2–10 MPa for mineral oils).
    pub eyring_stress: f64,
    /// Limiting shear-stress coefficient Λ_L \[-\] (typically 0.05–0.1).
    pub limiting_shear_coefficient: f64,
    /// The lubricant (η₀, α_p).
    pub lubricant: Lubricant,
}

impl EhlRheology {
    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        require_positive("eyring_stress", self.eyring_stress)?;
        require_positive(
            "limiting_shear_coefficient",
            self.limiting_shear_coefficient,
        )?;
        self.lubricant.validate()
    }
}

impl TractionLaw for EhlRheology {
    #[inline]
    fn shear_stress(
        &self,
        pressure: f64,
        slip: &Vector3<f64>,
        conditions: &ContactConditions,
    ) -> Vector3<f64> {
        let film = conditions.film;
        let speed = slip.norm();
        if speed == 0.0 || pressure <= 0.0 || film <= 0.0 {
            return Vector3::zeros();
        }
        let tau0 = self.eyring_stress;
        let eta = self.lubricant.viscosity_at(pressure);
        let x = eta * speed * (1.0 / (film * tau0));
        let eyring = tau0 * asinh_non_negative(x);
        let tau = eyring.min(self.limiting_shear_coefficient * pressure);
        -(tau * (1.0 / speed)) * slip
    }

    /// The cells stage by stage: slip speeds, viscosities and Eyring
    /// arguments of all cells first, then the stresses; per cell the same
    /// arithmetic as [`Self::shear_stress`] (bit-identical), but the
    /// square roots, exponentials and divisions of different cells no
    /// longer wait for each other.
    #[inline]
    fn shear_stresses(
        &self,
        pressures: &[f64],
        slips: &[Vector3<f64>],
        conditions: &ContactConditions,
        stresses: &mut [Vector3<f64>],
    ) {
        let n = pressures.len().min(BATCH);
        let film = conditions.film;
        let tau0 = self.eyring_stress;
        let per_film_stress = 1.0 / (film * tau0);
        let mut speed = [0.0; BATCH];
        let mut x = [0.0; BATCH];
        for k in 0..n {
            speed[k] = slips[k].norm();
        }
        for k in 0..n {
            let eta = self.lubricant.viscosity_at(pressures[k]);
            x[k] = eta * speed[k] * per_film_stress;
        }
        for k in 0..n {
            let pressure = pressures[k];
            stresses[k] = if speed[k] == 0.0 || pressure <= 0.0 || film <= 0.0 {
                Vector3::zeros()
            } else {
                let eyring = tau0 * asinh_non_negative(x[k]);
                let tau = eyring.min(self.limiting_shear_coefficient * pressure);
                -(tau * (1.0 / speed[k])) * slips[k]
            };
        }
    }
}

/// asinh(x) for x ≥ 0 without `hypot` (the standard library's asinh
/// spends most of its time there; the traction grid calls it per cell):
/// ln(x + √(x² + 1)) from x = 0.5 on (no cancellation there), the
/// cancellation-free log1p(x + x²/(1 + √(1 + x²))) below, and ln(2x)
/// above 1e8 (no overflow of x²; relative error below 1e-16).
#[inline]
fn asinh_non_negative(x: f64) -> f64 {
    if x > 1e8 {
        (2.0 * x).ln()
    } else if x >= 0.5 {
        (x + (x * x + 1.0).sqrt()).ln()
    } else {
        let x2 = x * x;
        (x + x2 / (1.0 + (1.0 + x2).sqrt())).ln_1p()
    }
}

#[cfg(test)]
pub(super) mod tests {
    #[test]
    fn fast_asinh_matches_the_standard_library() {
        for k in -300..=100 {
            let x = 1.3f64.powi(k);
            let (fast, std) = (super::asinh_non_negative(x), x.asinh());
            assert!(
                (fast - std).abs() <= 4.0 * f64::EPSILON * std,
                "x = {x}: {fast} vs {std}"
            );
        }
        assert_eq!(super::asinh_non_negative(0.0), 0.0);
    }

    use super::*;

    /// The default case's EHL rheology (also the traction module's batch test).
    pub(crate) fn law() -> EhlRheology {
        EhlRheology {
            eyring_stress: 5e6,
            limiting_shear_coefficient: 0.08,
            lubricant: Lubricant {
                viscosity: 0.0467,
                pressure_viscosity: 2.2e-8,
                pressure_model: Default::default(),
            },
        }
    }

    #[test]
    fn newtonian_at_small_slip_and_limited_at_large() {
        let l = law();
        let (p, h) = (0.2e9, 0.5e-6);
        let eta = l.lubricant.viscosity_at(p);
        let v = 1e-9;
        let h = ContactConditions {
            film: h,
            entrainment_speed: 1.0,
            ..Default::default()
        };
        let tau = l.shear_stress(p, &Vector3::new(v, 0.0, 0.0), &h);
        assert!(
            ((-tau.x) / (eta * v / h.film) - 1.0).abs() < 1e-6,
            "Newtonian limit"
        );
        let big = l.shear_stress(1.5e9, &Vector3::new(0.0, 5.0, 0.0), &h);
        assert!((big.y + 0.08 * 1.5e9).abs() < 1e-3, "limiting shear");
        // Monotone in the slip.
        let mut prev = 0.0;
        for k in 0..40 {
            let s = 1e-6 * 1.5f64.powi(k);
            let t = -l.shear_stress(p, &Vector3::new(s, 0.0, 0.0), &h).x;
            assert!(t >= prev);
            prev = t;
        }
    }
}
