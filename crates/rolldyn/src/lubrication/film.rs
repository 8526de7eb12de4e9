//! The film state of one contact: flooded Hamrock–Dowson films, their
//! starvation (Zhang et al. 2020 eqs 26–30), the film parameter Λ = h_min/σ and the
//! oil-film stiffness (docs/model.md §4).

use super::starvation::{Supply, critical_inlet_ratio, starvation_factor};
use super::{Lubricant, film_stiffness, hamrock_dowson};

/// Geometry and kinematics of a lubricated contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmConditions {
    /// Entrainment speed u \[m/s\].
    pub entrainment_speed: f64,
    /// Normal load Q \[N\].
    pub load: f64,
    /// Rolling-direction radius R_x \[m\].
    pub rolling_radius: f64,
    /// Effective modulus E' \[Pa\].
    pub effective_modulus: f64,
    /// Ellipticity κ = a/b.
    pub ellipticity: f64,
    /// Hertz semi-axis along the rolling direction b \[m\].
    pub semi_minor: f64,
    /// Speed of the ring that carries the supply film \[rad/s\] (oil-flow supply).
    pub ring_speed: f64,
}

/// Film state of one contact.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactFilm {
    /// Fully flooded central film h_c \[m\].
    pub flooded_central: f64,
    /// Fully flooded minimum film h_min \[m\].
    pub flooded_minimum: f64,
    /// Inlet distance ratio L (∞ when flooded).
    pub inlet_ratio: f64,
    /// Critical inlet distance ratio L*.
    pub critical_ratio: f64,
    /// Film reduction factor in [0, 1] (1: flooded).
    pub starvation_factor: f64,
    /// Central film h_c (starved) \[m\].
    pub central: f64,
    /// Minimum film h_min (starved) \[m\].
    pub minimum: f64,
    /// Film parameter Λ = h_min/σ (None without a roughness).
    pub lambda: Option<f64>,
    /// Oil-film stiffness K_oil = Q/(0.073 h_min) \[N/m\] (∞ without a film).
    pub stiffness: f64,
}

/// The film of a contact under `conditions`, starved by `supply`, with
/// composite roughness σ = √(R_q,ball² + R_q,race²) \[m\] (0: no Λ).
pub fn contact_film(
    lubricant: &Lubricant,
    supply: &Supply,
    composite_roughness: f64,
    c: &FilmConditions,
) -> ContactFilm {
    let flooded = hamrock_dowson(
        lubricant,
        c.entrainment_speed,
        c.load,
        c.rolling_radius,
        c.effective_modulus,
        c.ellipticity,
    );
    if flooded.central <= 0.0 || c.semi_minor <= 0.0 {
        return ContactFilm {
            inlet_ratio: f64::INFINITY,
            critical_ratio: f64::INFINITY,
            starvation_factor: 1.0,
            stiffness: f64::INFINITY,
            lambda: (composite_roughness > 0.0).then_some(0.0),
            ..ContactFilm::default()
        };
    }
    let inlet_ratio = supply.inlet_distance_ratio(
        c.semi_minor,
        c.rolling_radius,
        flooded.central,
        c.ring_speed,
    );
    let critical_ratio = critical_inlet_ratio(flooded.central, c.rolling_radius, c.semi_minor);
    let factor = starvation_factor(inlet_ratio, critical_ratio);
    let minimum = factor * flooded.minimum;
    ContactFilm {
        flooded_central: flooded.central,
        flooded_minimum: flooded.minimum,
        inlet_ratio,
        critical_ratio,
        starvation_factor: factor,
        central: factor * flooded.central,
        minimum,
        lambda: (composite_roughness > 0.0).then(|| minimum / composite_roughness),
        stiffness: film_stiffness(c.load, minimum),
    }
}

/// A mineral oil for the module tests (η₀ 46.7 mPa·s, α_p 2.2e-8 1/Pa).
#[cfg(test)]
pub(crate) fn test_oil() -> Lubricant {
    Lubricant {
        viscosity: 0.0467,
        pressure_viscosity: 2.2e-8,
        pressure_model: super::PressureViscosity::Barus,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn oil() -> Lubricant {
        test_oil()
    }

    fn conditions() -> FilmConditions {
        FilmConditions {
            entrainment_speed: 10.0,
            load: 50.0,
            rolling_radius: 2.8e-3,
            effective_modulus: 2.29e11,
            ellipticity: 5.1,
            semi_minor: 0.1e-3,
            ring_speed: 1000.0,
        }
    }

    #[test]
    fn flooded_supply_gives_the_hamrock_dowson_film_exactly() {
        let c = conditions();
        let f = contact_film(&oil(), &Supply::Flooded, 0.1e-6, &c);
        let hd = hamrock_dowson(&oil(), 10.0, 50.0, 2.8e-3, 2.29e11, 5.1);
        assert_eq!(f.central, hd.central);
        assert_eq!(f.minimum, hd.minimum);
        assert_eq!(f.starvation_factor, 1.0);
        assert_eq!(f.lambda, Some(hd.minimum / 0.1e-6));
        // A very large inlet distance is flooded too, exactly.
        let far = contact_film(&oil(), &Supply::InletDistance(1e6), 0.0, &c);
        assert_eq!(far.central, hd.central);
        assert_eq!(far.lambda, None);
    }

    #[test]
    fn starvation_thins_the_film_and_stiffens_it() {
        let c = conditions();
        let flooded = contact_film(&oil(), &Supply::Flooded, 0.0, &c);
        let mut last = 0.0;
        for l in [1.01, 1.1, 1.3, 1.5, 1.7, 1.9] {
            let f = contact_film(&oil(), &Supply::InletDistance(l), 0.0, &c);
            assert!(f.central >= last && f.central <= flooded.central);
            assert!(f.stiffness >= flooded.stiffness);
            last = f.central;
        }
        let near = contact_film(&oil(), &Supply::InletDistance(1.0 + 1e-9), 0.0, &c);
        assert!(near.central < 0.01 * flooded.central);
        // No speed: no film, no stiffness limit.
        let still = contact_film(
            &oil(),
            &Supply::InletDistance(1.5),
            0.0,
            &FilmConditions {
                entrainment_speed: 0.0,
                ..c
            },
        );
        assert_eq!(still.central, 0.0);
        assert_eq!(still.stiffness, f64::INFINITY);
    }
}
