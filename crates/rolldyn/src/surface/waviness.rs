//! Waviness: a Fourier series in the angle around a ring or a ball
//! (Deng et al. 2022 eq 1, docs/model.md §6), given term by term or drawn from an amplitude
//! law with random phases (deterministic for a seed).

use crate::error::{InvalidParameter, require_non_negative, require_positive};
use crate::math::random::SplitMix64;
use std::f64::consts::TAU;

/// One waviness harmonic: q cos(l θ + η).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WavinessTerm {
    /// Order l (waves per circumference), ≥ 1.
    pub order: u32,
    /// Amplitude q \[m\].
    pub amplitude: f64,
    /// Phase η \[rad\].
    pub phase: f64,
}

/// Random waviness: orders `min_order..=max_order`, amplitude
/// q_l = q₀ (l_min / l)^p (p: `exponent`), phases uniform on [0, 2π) from
/// a seeded generator, so the same seed gives the same surface on every
/// machine and thread count.
///
/// The power law is a modelling choice (amplitudes that fall with order, as
/// measured waviness spectra do); rolldyn does not claim a universal law.
/// Give measured orders as explicit terms when they are known.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RandomWaviness {
    /// Lowest order l_min (≥ 1).
    pub min_order: u32,
    /// Highest order l_max (≥ l_min).
    pub max_order: u32,
    /// Amplitude q₀ at the lowest order \[m\].
    pub amplitude: f64,
    /// Exponent p of the amplitude decay (0: all orders equal).
    pub exponent: f64,
    /// Seed of the phase generator.
    pub seed: u64,
}

/// Highest waviness order accepted: beyond this the wavelength on any real
/// raceway is shorter than the Hertz contact and the point-contact
/// evaluation (docs/model.md §6) is meaningless.
pub const MAX_ORDER: u32 = 10_000;

impl RandomWaviness {
    /// Checks the law.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        if self.min_order == 0 {
            return Err(InvalidParameter::new(
                "min_order",
                self.min_order,
                "waviness orders start at 1",
            ));
        }
        if self.max_order < self.min_order || self.max_order > MAX_ORDER {
            return Err(InvalidParameter::new(
                "max_order",
                self.max_order,
                format!("must lie in [min_order = {}, {MAX_ORDER}]", self.min_order),
            ));
        }
        require_non_negative("amplitude", self.amplitude)?;
        if !(0.0..=10.0).contains(&self.exponent) {
            return Err(InvalidParameter::new(
                "exponent",
                self.exponent,
                "must lie in [0, 10] (amplitudes do not grow with the order)",
            ));
        }
        Ok(())
    }

    /// The terms, with `stream` mixed into the seed (one stream per ball, so
    /// balls get different phases from one seed).
    pub fn terms(&self, stream: u64) -> Vec<WavinessTerm> {
        let mut rng = SplitMix64::new(self.seed ^ stream.wrapping_mul(0xA076_1D64_78BD_642F));
        (self.min_order..=self.max_order)
            .map(|order| WavinessTerm {
                order,
                amplitude: self.amplitude
                    * (f64::from(self.min_order) / f64::from(order)).powf(self.exponent),
                phase: TAU * rng.unit(),
            })
            .collect()
    }
}

/// A waviness profile w(θ) = Σ q_l cos(l θ + η_l).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Waviness {
    /// The harmonics.
    pub terms: Vec<WavinessTerm>,
}

impl Waviness {
    /// Checks every term (order 1 … [`MAX_ORDER`], amplitude ≥ 0, phase finite).
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        for term in &self.terms {
            if term.order == 0 || term.order > MAX_ORDER {
                return Err(InvalidParameter::new(
                    "order",
                    term.order,
                    format!("must lie in [1, {MAX_ORDER}]"),
                ));
            }
            require_non_negative("amplitude", term.amplitude)?;
            if !term.phase.is_finite() {
                return Err(InvalidParameter::new("phase", term.phase, "must be finite"));
            }
        }
        Ok(())
    }

    /// Whether there are no terms.
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }

    /// Height w(θ) \[m\] and slope dw/dθ \[m/rad\].
    pub fn at(&self, angle: f64) -> (f64, f64) {
        let (mut w, mut slope) = (0.0, 0.0);
        for term in &self.terms {
            let l = f64::from(term.order);
            let (s, c) = (l * angle + term.phase).sin_cos();
            w += term.amplitude * c;
            slope -= term.amplitude * l * s;
        }
        (w, slope)
    }

    /// Highest order present (0 when empty).
    pub fn max_order(&self) -> u32 {
        self.terms.iter().map(|t| t.order).max().unwrap_or(0)
    }
}

/// Checks that a length is positive (helper for the surface parameters).
pub(super) fn positive(field: &'static str, value: f64) -> Result<(), InvalidParameter> {
    require_positive(field, value)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn height_and_slope_of_one_term() {
        let w = Waviness {
            terms: vec![WavinessTerm {
                order: 3,
                amplitude: 2e-7,
                phase: 0.4,
            }],
        };
        let theta = 1.1;
        let (h, s) = w.at(theta);
        assert!((h - 2e-7 * (3.0 * theta + 0.4).cos()).abs() < 1e-22);
        // Slope against a central difference.
        let d = 1e-6;
        let fd = (w.at(theta + d).0 - w.at(theta - d).0) / (2.0 * d);
        assert!((s - fd).abs() < 1e-9 * 6e-7, "{s} vs {fd}");
    }

    #[test]
    fn random_waviness_is_deterministic_and_follows_the_law() {
        let law = RandomWaviness {
            min_order: 2,
            max_order: 8,
            amplitude: 1e-7,
            exponent: 1.0,
            seed: 42,
        };
        law.validate().unwrap();
        let a = law.terms(0);
        assert_eq!(a, law.terms(0));
        assert_ne!(a, law.terms(1), "each stream has its own phases");
        assert_eq!(a.len(), 7);
        assert!((a[2].amplitude - 1e-7 * 2.0 / 4.0).abs() < 1e-22);
        assert!(a.iter().all(|t| (0.0..TAU).contains(&t.phase)));
        // The phases are spread over the circle, not stuck.
        let mean_cos: f64 = law.terms(3).iter().map(|t| t.phase.cos()).sum::<f64>() / 7.0;
        assert!(mean_cos.abs() < 0.9);
    }

    #[test]
    fn bad_laws_are_refused() {
        let mut law = RandomWaviness {
            min_order: 0,
            max_order: 8,
            amplitude: 1e-7,
            exponent: 1.0,
            seed: 1,
        };
        assert_eq!(law.validate().unwrap_err().field, "min_order");
        law.min_order = 9;
        assert_eq!(law.validate().unwrap_err().field, "max_order");
        let w = Waviness {
            terms: vec![WavinessTerm {
                order: 2,
                amplitude: -1.0,
                phase: 0.0,
            }],
        };
        assert_eq!(w.validate().unwrap_err().field, "amplitude");
    }
}
