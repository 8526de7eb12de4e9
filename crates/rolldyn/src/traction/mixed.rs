//! Mixed-lubrication traction (docs/model.md §3, model 5): the fluid's stress law
//! and boundary friction on the asperities, weighted by the asperities'
//! share φ of the contact's load (`lubrication::mixed`, Greenwood–Tripp
//! load sharing after Johnson, Greenwood & Poon 1972):
//! ```text
//! τ = (1 − φ) τ_fluid(p, v, h) + φ τ_b(p, v),   τ_b = −c_d(|v|) μ_b p v/|v|
//! ```
//! The share is one number per contact, so the same φ weights every cell of
//! the ellipse. φ = 0 gives the fluid law's stresses exactly, φ = 1 the
//! modified Coulomb law's. Both parts oppose the slip, so the blend
//! dissipates and the energy balance (B2) needs nothing more.

use super::{BATCH, Cells, ContactConditions, ModifiedCoulomb, TractionLaw};
use crate::error::{InvalidParameter, require_positive};
use crate::lubrication;

use serde::{Deserialize, Serialize};

/// Mixed lubrication of the ball–raceway contacts (case file:
/// `[model.mixed_lubrication]`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MixedLubrication {
    /// Boundary friction of the asperity contacts: μ_b and the slip
    /// regularisation of the modified Coulomb law.
    pub boundary: ModifiedCoulomb,
    /// Roughness parameter σβη \[-\].
    pub sigma_beta_eta: f64,
    /// Ratio of the composite roughness to the summit radius σ/β \[-\].
    pub sigma_over_beta: f64,
}

impl MixedLubrication {
    /// Checks the parameters; the error names the field.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        self.boundary.validate()?;
        require_positive("sigma_beta_eta", self.sigma_beta_eta)?;
        require_positive("sigma_over_beta", self.sigma_over_beta)?;
        if self.sigma_over_beta > 1.0 {
            return Err(InvalidParameter::new(
                "sigma_over_beta",
                self.sigma_over_beta,
                "summits much sharper than their height spread (σ/β > 1) are outside Greenwood and Tripp's small-slope model; typical values are 1e-4 to 1e-2",
            ));
        }
        Ok(())
    }

    /// K = (16√2 π/15) (σβη)² √(σ/β).
    pub fn asperity_constant(&self) -> f64 {
        lubrication::mixed::asperity_constant(self.sigma_beta_eta, self.sigma_over_beta)
    }

    /// Asperity pressure p_a = K E* F_{5/2}(Λ) \[Pa\] at film parameter Λ,
    /// with docs/model.md §2.2's effective modulus E' = 2E* \[Pa\].
    pub fn asperity_pressure(&self, film_parameter: f64, effective_modulus: f64) -> f64 {
        lubrication::mixed::asperity_pressure(
            self.asperity_constant(),
            film_parameter,
            effective_modulus,
        )
    }

    /// The asperities' share φ = min(1, p_a/p̄) of a contact's load, at
    /// film parameter Λ and mean Hertz pressure p̄ = Q/(πab) \[Pa\]; 0 for an
    /// unloaded contact.
    pub fn asperity_share(
        &self,
        film_parameter: f64,
        mean_pressure: f64,
        effective_modulus: f64,
    ) -> f64 {
        lubrication::mixed::asperity_share(
            self.asperity_constant(),
            film_parameter,
            mean_pressure,
            effective_modulus,
        )
    }
}

/// A fluid stress law blended with boundary friction at one contact.
pub struct Blended<'a, L: TractionLaw> {
    /// The fluid's law (the EHL rheology).
    pub fluid: &'a L,
    /// Boundary friction of the asperity contacts.
    pub boundary: &'a ModifiedCoulomb,
    /// Asperity share φ of the contact's load, in [0, 1].
    pub share: f64,
}

impl<L: TractionLaw> TractionLaw for Blended<'_, L> {
    /// The fluid's term (the boundary friction needs none).
    #[inline]
    fn pressure_term(&self, pressure: f64) -> f64 {
        self.fluid.pressure_term(pressure)
    }

    /// The fluid's terms.
    #[inline(always)]
    fn pressure_terms(&self, values: &mut [f64]) {
        self.fluid.pressure_terms(values);
    }

    /// (1 − φ) g_fluid + φ g_boundary.
    #[inline]
    fn stress_ratio(
        &self,
        pressure: f64,
        term: f64,
        speed: f64,
        conditions: &ContactConditions,
    ) -> f64 {
        (1.0 - self.share) * self.fluid.stress_ratio(pressure, term, speed, conditions)
            + self.share * self.boundary.stress_ratio(pressure, 0.0, speed, conditions)
    }

    /// The fluid's cells in its own batches, then the boundary's.
    #[inline(always)]
    fn stress_ratios(
        &self,
        pressures: &Cells,
        terms: &Cells,
        speeds: &Cells,
        conditions: &ContactConditions,
        ratios: &mut Cells,
    ) {
        self.fluid
            .stress_ratios(pressures, terms, speeds, conditions, ratios);
        for k in 0..BATCH {
            ratios[k] = (1.0 - self.share) * ratios[k]
                + self.share
                    * self
                        .boundary
                        .stress_ratio(pressures[k], 0.0, speeds[k], conditions);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    #[test]
    fn the_blend_ends_at_its_two_laws() {
        let fluid = super::super::ehl::tests::law();
        let boundary = ModifiedCoulomb {
            friction: 0.1,
            stick_speed: 0.0,
            full_speed: 1e-3,
        };
        let c = ContactConditions {
            film: 2e-7,
            entrainment_speed: 10.0,
            rolling_velocity: 10.0,
        };
        let (p, v) = (1.2e9, Vector3::new(0.3, -0.1, 0.0));
        let at = |share: f64| {
            Blended {
                fluid: &fluid,
                boundary: &boundary,
                share,
            }
            .shear_stress(p, &v, &c)
        };
        assert_eq!(at(0.0), fluid.shear_stress(p, &v, &c));
        assert_eq!(at(1.0), boundary.shear_stress(p, &v, &c));
        // Linear in the share, and every blend opposes the slip.
        let (f, b) = (at(0.0), at(1.0));
        for share in [0.1, 0.5, 0.9] {
            assert!((at(share) - ((1.0 - share) * f + share * b)).norm() < 1e-9 * b.norm());
            assert!(at(share).dot(&v) < 0.0);
        }
        // Batches are cell by cell.
        let law = Blended {
            fluid: &fluid,
            boundary: &boundary,
            share: 0.3,
        };
        let cells = [0.0, 5e8, 1.2e9, 2e9, 1e9, 0.0, 3e9, 1e8];
        let pressures: [f64; BATCH] = std::array::from_fn(|k| cells[k % 8]);
        let speeds: [f64; BATCH] =
            std::array::from_fn(|k| [0.3, 3e-5, 0.0, 0.3, 1e-9, 0.0, 2.0, 1e3][(k + k / 8) % 8]);
        let terms = pressures.map(|p| law.pressure_term(p));
        let mut out = [0.0; BATCH];
        law.stress_ratios(&pressures, &terms, &speeds, &c, &mut out);
        for k in 0..BATCH {
            let single = law.stress_ratio(pressures[k], terms[k], speeds[k], &c);
            assert_eq!(out[k].to_bits(), single.to_bits(), "cell {k}");
        }
    }

    fn mixed() -> MixedLubrication {
        MixedLubrication {
            boundary: ModifiedCoulomb {
                friction: 0.1,
                stick_speed: 0.0,
                full_speed: 1e-3,
            },
            sigma_beta_eta: 0.04,
            sigma_over_beta: 1e-3,
        }
    }

    #[test]
    fn bad_parameters_are_refused() {
        let mut m = mixed();
        m.sigma_beta_eta = 0.0;
        assert_eq!(m.validate().unwrap_err().field, "sigma_beta_eta");
        let mut m = mixed();
        m.sigma_over_beta = 2.0;
        assert_eq!(m.validate().unwrap_err().field, "sigma_over_beta");
        let mut m = mixed();
        m.boundary.friction = -1.0;
        assert_eq!(m.validate().unwrap_err().field, "friction");
    }
}
