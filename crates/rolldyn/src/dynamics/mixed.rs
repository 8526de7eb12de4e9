//! Mixed lubrication in the dynamic model (docs/model.md §3, model 5): each
//! ball–raceway contact's asperity share φ from its film parameter
//! Λ = h_min/σ (Greenwood–Tripp load sharing, `lubrication::mixed`), which
//! weights boundary friction against the fluid's traction law
//! (`traction::mixed`).
//!
//! h_min is the contact's steady Hamrock–Dowson minimum film at its load,
//! starved by the ring's supply (docs/model.md §4), also with the film in the
//! approach (whose fixed point carries the central film only).

use super::elements::Elements;
use super::motion::RingMotion;
use crate::contact::hertz::{HertzCoefficients, HertzResult};
use crate::lubrication::ContactFilm;

impl Elements {
    /// Asperity share φ of a contact with `ring` at load Q \[N\] (0 without
    /// mixed lubrication or load): Λ = h_min/σ of the steady film (`steady`
    /// when the caller has it, else computed at contact angle α and
    /// entrainment speed u), against the mean Hertz pressure Q/(πab).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn asperity_share(
        &self,
        ring: &RingMotion,
        hertz: &HertzCoefficients,
        contact_angle: f64,
        entrainment_speed: f64,
        load: f64,
        ellipse: &HertzResult,
        steady: Option<&ContactFilm>,
    ) -> f64 {
        let Some(mixed) = &self.params.mixed_lubrication else {
            return 0.0;
        };
        if load <= 0.0 {
            return 0.0;
        }
        let minimum = match steady {
            Some(film) => film.minimum,
            None => self
                .steady_film(
                    ring,
                    hertz,
                    contact_angle,
                    entrainment_speed,
                    load,
                    ellipse.semi_minor,
                )
                .map_or(0.0, |film| film.minimum),
        };
        let sigma = self.params.surface.composite_roughness(ring.raceway.kind);
        let mean_pressure = load / (std::f64::consts::PI * ellipse.semi_major * ellipse.semi_minor);
        mixed.asperity_share(minimum / sigma, mean_pressure, self.effective_modulus)
    }
}
