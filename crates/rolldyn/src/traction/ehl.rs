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

use super::{BATCH, Cells, ContactConditions, TractionLaw};
use crate::error::{InvalidParameter, require_positive};
use crate::lubrication::Lubricant;
use crate::math::logarithm::asinh_non_negative;

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
    /// The viscosity η(p) (Barus or Roelands).
    #[inline]
    fn pressure_term(&self, pressure: f64) -> f64 {
        self.lubricant.viscosity_at(pressure)
    }

    /// The viscosities in one loop ([`Lubricant::viscosities_at`]).
    #[inline(always)]
    fn pressure_terms(&self, values: &mut [f64]) {
        self.lubricant.viscosities_at(values);
    }

    /// g = min(τ₀ asinh(η |v| / (h τ₀)), Λ_L p) / |v|, η the cell's term.
    #[inline]
    fn stress_ratio(
        &self,
        pressure: f64,
        viscosity: f64,
        speed: f64,
        conditions: &ContactConditions,
    ) -> f64 {
        let film = conditions.film;
        if speed == 0.0 || pressure <= 0.0 || film <= 0.0 {
            return 0.0;
        }
        let tau0 = self.eyring_stress;
        let x = viscosity * speed * (1.0 / (film * tau0));
        let eyring = tau0 * asinh_non_negative(x);
        eyring.min(self.limiting_shear_coefficient * pressure) * (1.0 / speed)
    }

    /// The cells stage by stage: Eyring arguments of all cells first, then
    /// their asinh, then the ratios; per cell the same arithmetic as
    /// [`Self::stress_ratio`] (bit-identical). asinh is plain arithmetic
    /// (`math::logarithm`), so each stage is a loop the compiler
    /// vectorizes.
    #[inline(always)]
    fn stress_ratios(
        &self,
        pressures: &Cells,
        viscosities: &Cells,
        speeds: &Cells,
        conditions: &ContactConditions,
        ratios: &mut Cells,
    ) {
        let film = conditions.film;
        if film <= 0.0 {
            *ratios = [0.0; BATCH];
            return;
        }
        let tau0 = self.eyring_stress;
        let per_film_stress = 1.0 / (film * tau0);
        let mut eyring = [0.0; BATCH];
        for k in 0..BATCH {
            eyring[k] = viscosities[k] * speeds[k] * per_film_stress;
        }
        for e in &mut eyring {
            *e = tau0 * asinh_non_negative(*e);
        }
        for k in 0..BATCH {
            let (pressure, speed) = (pressures[k], speeds[k]);
            ratios[k] = if speed == 0.0 || pressure <= 0.0 {
                0.0
            } else {
                eyring[k].min(self.limiting_shear_coefficient * pressure) * (1.0 / speed)
            };
        }
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use nalgebra::Vector3;

    /// The default case's EHL rheology (also the traction module's batch test).
    pub(crate) fn law() -> EhlRheology {
        crate::testing::ehl_7008c()
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
