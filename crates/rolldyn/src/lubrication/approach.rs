//! The lubricant film in the normal approach (docs/model.md §4, option): a
//! contact's central film as a function of its load, its integral, and
//! the light-load floor.
//!
//! The option puts the central film into the elastic compression,
//! δ_el = δ + h_c(Q), Q = K_c δ_el^{3/2}, a fixed point in Q. At fixed
//! entrainment speed u and geometry the film is a function of the load
//! alone,
//!
//! ```text
//! h(q) = H q^a S(q),   a = −0.067                    (Hamrock–Dowson h_c)
//! S(q) = min(1, ((L − 1)/(L*(q) − 1))^0.25) = min(1, C q^c)     (starved)
//! L*(q) − 1 = 3.06 (R_x h_fl/b²)^0.56,  b = β q^{1/3}
//!   ⇒  c = −0.14 (a − 2/3) = 0.10271
//! ```
//! (Zhang et al. 2020 eqs 16–30 as in [`super::hamrock_dowson`] and
//! [`super::starvation`]; H is the flooded film at 1 N, β the Hertz
//! semi-axis coefficient). [`FilmLaw`] holds H, C and the floor and gives
//! h(q), dh/dq and ∫₀^q h. The contact then stores
//! V = (2/5) K_c δ_el^{5/2} − Q h + ∫₀^Q h dq, whose δ-derivative is Q:
//! the film is a nonlinear spring in series with Hertz (its compliance
//! dh/dQ is Zhang et al. 2020's 1/K_oil). H, C and the floor change with u and the
//! contact angle: that change of V at fixed Q, ∂/∂t ∫₀^Q h dq, is the work
//! the film does on the contact. It is drawn from the entrainment, and the
//! energy balance counts it (`dynamics::film`).
//!
//! **Light loads.** h ∝ q^−0.067 grows without bound as q → 0, so a
//! contact could never open. Below the floor Q_f = W_f E' R_x²
//! ([`FLOOR_LOAD_PARAMETER`] W_f = 1e-7) the film is held at h(Q_f): a
//! contact carries load through its film until its gap exceeds h(Q_f).
//! Hamrock & Dowson fitted their formulas over one decade of W about 1e-6
//! (Part III, J. Lubr. Technol. 99 (1977) 264–276), so the floor is below
//! the loads the formula was made for. It also keeps the fixed point
//! unique: a starved film grows with load (exponent a + c = +0.036), and
//! the elastic approach must outgrow it, 1.5 (a + c) h/δ_el < 1, i.e.
//! δ_el > 0.054 h. At the floor that is δ_el ≈ 0.1 µm against 0.054 h ≈
//! 0.03 µm (Zhang et al. 2020's bearing, h ≈ 0.5 µm) and 0.07 µm (7008C at
//! 10 000 rpm, h ≈ 1.3 µm). Newton's slope is bounded below (0.1) as a
//! guard.
//!
//! Supplies: flooded and an inlet distance ratio L (Zhang et al. 2020's input). The
//! oil-flow supply makes L a function of b and h_c that is not a power of
//! the load; the film in the approach refuses it.

use super::starvation::Supply;
use super::{Lubricant, hamrock_dowson};
use crate::error::InvalidParameter;

/// Dimensionless load W = Q/(E' R_x²) below which a contact's film is
/// held at its value there (light-load floor).
pub const FLOOR_LOAD_PARAMETER: f64 = 1e-7;

/// Load exponent of the flooded central film (Hamrock–Dowson h_c ∝ W^−0.067).
pub const FLOODED_EXPONENT: f64 = -0.067;

/// Load exponent of the starvation factor at a fixed inlet distance ratio,
/// S ∝ q^c: c = −0.25 · 0.56 (a − 2/3).
pub const STARVATION_EXPONENT: f64 = -0.25 * 0.56 * (FLOODED_EXPONENT - 2.0 / 3.0);

/// Speed exponent of the flooded film (Hamrock–Dowson h_c ∝ U^0.67).
pub const SPEED_EXPONENT: f64 = 0.67;

/// Exponent of the flooded film in the starvation factor, S ∝ H^−0.14
/// (S = ((L − 1)/(L* − 1))^0.25, L* − 1 ∝ (R_x H/β²)^0.56).
pub const STARVATION_FILM_EXPONENT: f64 = 0.25 * 0.56;

/// What a contact's film depends on besides its load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmGeometry {
    /// Entrainment speed u \[m/s\].
    pub entrainment_speed: f64,
    /// Rolling-direction radius R_x \[m\].
    pub rolling_radius: f64,
    /// Effective modulus E' \[Pa\].
    pub effective_modulus: f64,
    /// Ellipticity κ = a/b.
    pub ellipticity: f64,
    /// Hertz semi-axis coefficient β along the rolling direction,
    /// b = β Q^{1/3} \[m/N^{1/3}\].
    pub semi_minor_coefficient: f64,
}

/// A contact's central film as a function of its load (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmLaw {
    /// Flooded film at 1 N, H \[m\].
    flooded: f64,
    /// Starvation coefficient C (S = min(1, C q^c)); ∞ when flooded.
    starvation: f64,
    /// Floor load Q_f \[N\].
    floor: f64,
    /// Load q* from which the film is flooded (0: always flooded).
    knee: f64,
}

impl FilmLaw {
    /// The law of a contact with `geometry`, lubricated by `lubricant`
    /// through `supply`. The oil-flow supply is refused.
    pub fn new(
        lubricant: &Lubricant,
        supply: &Supply,
        geometry: &FilmGeometry,
    ) -> Result<Self, InvalidParameter> {
        let g = geometry;
        let flooded = hamrock_dowson(
            lubricant,
            g.entrainment_speed,
            1.0,
            g.rolling_radius,
            g.effective_modulus,
            g.ellipticity,
        )
        .central;
        let starvation = match *supply {
            Supply::Flooded => f64::INFINITY,
            Supply::InletDistance(l) => {
                // L*(q) − 1 = 3.06 (R_x H/β²)^0.56 q^{0.56(a − 2/3)}.
                let scale = 3.06
                    * (g.rolling_radius * flooded / g.semi_minor_coefficient.powi(2)).powf(0.56);
                if scale > 0.0 {
                    ((l - 1.0).max(0.0) / scale).powf(0.25)
                } else {
                    f64::INFINITY
                }
            }
            Supply::Flow { flow, .. } => {
                return Err(InvalidParameter::new(
                    "oil_flow",
                    flow,
                    "the film in the normal approach needs a flooded supply or an inlet distance ratio",
                ));
            }
        };
        Ok(Self {
            flooded,
            starvation,
            floor: FLOOR_LOAD_PARAMETER * g.effective_modulus * g.rolling_radius.powi(2),
            knee: if starvation.is_finite() && starvation > 0.0 {
                starvation.powf(-1.0 / STARVATION_EXPONENT)
            } else if starvation.is_finite() {
                f64::INFINITY
            } else {
                0.0
            },
        })
    }

    /// Floor load Q_f \[N\].
    pub fn floor(&self) -> f64 {
        self.floor
    }

    /// The same law with every film times `factor` (a continuation path
    /// from the dry contact, factor 0, to this law, factor 1).
    pub fn scaled(&self, factor: f64) -> Self {
        Self {
            flooded: factor * self.flooded,
            ..*self
        }
    }

    /// Load q* above which the film is flooded (0 when always flooded).
    fn flooded_from(&self) -> f64 {
        self.knee
    }

    /// Central film h(q) \[m\] at load q \[N\].
    pub fn film(&self, load: f64) -> f64 {
        self.film_and_exponent(load).0
    }

    /// h(q) and its local load exponent d ln h/d ln q (0 below the floor).
    fn film_and_exponent(&self, load: f64) -> (f64, f64) {
        let q = load.max(self.floor);
        let (h, exponent) = if q >= self.knee {
            (self.flooded * q.powf(FLOODED_EXPONENT), FLOODED_EXPONENT)
        } else {
            let e = FLOODED_EXPONENT + STARVATION_EXPONENT;
            (self.flooded * self.starvation * q.powf(e), e)
        };
        (h, if load > self.floor { exponent } else { 0.0 })
    }

    /// Compliance of the film dh/dq \[m/N\] (minus 1/K_oil of the central
    /// film): 0 below the floor.
    pub fn slope(&self, load: f64) -> f64 {
        let (h, exponent) = self.film_and_exponent(load);
        if exponent == 0.0 {
            0.0
        } else {
            exponent * h / load
        }
    }

    /// ∫₀^q h dq' \[N·m\].
    pub fn integral(&self, load: f64) -> f64 {
        let (flooded, starved) = self.integral_parts(load);
        flooded + starved
    }

    /// ∂(∫₀^q h dq')/∂ ln u at fixed q \[N·m\]: h ∝ U^0.67 where flooded,
    /// and S ∝ H^−0.14 (L* − 1 ∝ H^0.56) where starved, so the starved part
    /// goes as u^{0.67 · 0.86}. The knee between the parts moves with u,
    /// but h is continuous there, so it adds nothing.
    pub fn integral_speed_derivative(&self, load: f64) -> f64 {
        let (flooded, starved) = self.integral_parts(load);
        SPEED_EXPONENT * (flooded + (1.0 - STARVATION_FILM_EXPONENT) * starved)
    }

    /// ∫₀^q h dq' split into its flooded and starved parts \[N·m\].
    fn integral_parts(&self, load: f64) -> (f64, f64) {
        let q = load.max(0.0);
        let knee = self.flooded_from();
        let floor_flooded = self.floor >= knee;
        let split = |part: f64, flooded: bool| if flooded { (part, 0.0) } else { (0.0, part) };
        if q <= self.floor {
            return split(q * self.film(self.floor), floor_flooded);
        }
        let knee = knee.clamp(self.floor, q);
        // ∫ k x^e dx from x0 to x1.
        let power = |k: f64, e: f64, x0: f64, x1: f64| {
            k * (x1.powf(e + 1.0) - x0.powf(e + 1.0)) / (e + 1.0)
        };
        let (mut flooded, mut starved) = split(self.floor * self.film(self.floor), floor_flooded);
        if knee > self.floor {
            starved += power(
                self.flooded * self.starvation,
                FLOODED_EXPONENT + STARVATION_EXPONENT,
                self.floor,
                knee,
            );
        }
        if q > knee {
            flooded += power(self.flooded, FLOODED_EXPONENT, knee, q);
        }
        (flooded, starved)
    }
}

/// The fixed point of a contact with its film in the approach.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElasticApproach {
    /// Elastic approach δ_el = δ + h(Q) \[m\].
    pub approach: f64,
    /// Elastic load Q = K_c δ_el^{3/2} \[N\].
    pub load: f64,
    /// Central film h(Q) \[m\].
    pub film: f64,
    /// dQ/dδ over K_H = 3Q/(2δ_el): 1/(1 − K_H dh/dQ), the film in series.
    pub series_factor: f64,
}

impl FilmLaw {
    /// The fixed point δ_el = δ + h(K_c δ_el^{3/2}) of a contact with Hertz
    /// constant K_c \[N/m^{3/2}\] and geometric overlap δ \[m\] (negative:
    /// gap); None when open, δ + h(0) ≤ 0.
    ///
    /// Newton on g(x) = x − δ − h(K x^{3/2}), g' = 1 − h'(Q) 3Q/(2x), from
    /// the film at the geometric load: g' ≥ 1 for a flooded film and close
    /// to 1 for a starved one (module doc); converged to rounding.
    pub fn elastic_approach(&self, stiffness: f64, overlap: f64) -> Option<ElasticApproach> {
        if overlap + self.film(0.0) <= 0.0 {
            return None;
        }
        let load_at = |x: f64| stiffness * x * x.sqrt();
        let mut x = overlap + self.film(load_at(overlap.max(0.0)));
        let mut slope = 1.0;
        for _ in 0..30 {
            let load = load_at(x);
            let (h, exponent) = self.film_and_exponent(load);
            let g = x - overlap - h;
            // h' 3Q/(2x) = 1.5 (d ln h/d ln Q) h/x.
            slope = (1.0 - 1.5 * exponent * h / x).max(0.1);
            let next = x - g / slope;
            let next = if next > 0.0 { next } else { 0.5 * x };
            let done = (next - x).abs() <= 1e-15 * x;
            x = next;
            if done {
                break;
            }
        }
        let load = load_at(x);
        Some(ElasticApproach {
            approach: x,
            load,
            film: self.film(load),
            series_factor: 1.0 / slope,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lubrication::film::{FilmConditions, contact_film, test_oil as oil};

    const GEOMETRY: FilmGeometry = FilmGeometry {
        entrainment_speed: 10.0,
        rolling_radius: 2.8e-3,
        effective_modulus: 2.29e11,
        ellipticity: 5.1,
        semi_minor_coefficient: 2.5e-5,
    };

    fn reference(supply: &Supply, load: f64) -> f64 {
        contact_film(
            &oil(),
            supply,
            0.0,
            &FilmConditions {
                entrainment_speed: GEOMETRY.entrainment_speed,
                load,
                rolling_radius: GEOMETRY.rolling_radius,
                effective_modulus: GEOMETRY.effective_modulus,
                ellipticity: GEOMETRY.ellipticity,
                semi_minor: GEOMETRY.semi_minor_coefficient * load.cbrt(),
                ring_speed: 1000.0,
            },
        )
        .central
    }

    /// Flooded, starved at Zhang et al. 2020's extremes, and flooded by a far inlet.
    const SUPPLIES: [Supply; 4] = [
        Supply::Flooded,
        Supply::InletDistance(1.1),
        Supply::InletDistance(1.9),
        Supply::InletDistance(20.0),
    ];

    #[test]
    fn the_law_is_the_starved_hamrock_dowson_film_above_the_floor() {
        for supply in SUPPLIES {
            let law = FilmLaw::new(&oil(), &supply, &GEOMETRY).unwrap();
            assert!((law.floor() - 1e-7 * 2.29e11 * 2.8e-3f64.powi(2)).abs() < 1e-15);
            for q in [0.2, 1.0, 5.0, 30.0, 300.0, 3000.0] {
                let (h, expected) = (law.film(q), reference(&supply, q));
                assert!(
                    (h / expected - 1.0).abs() < 1e-12,
                    "{supply:?} {q}: {h} {expected}"
                );
            }
            // Held below the floor.
            assert_eq!(law.film(0.0), law.film(law.floor()));
            let half = law.scaled(0.5);
            assert!((half.film(7.0) - 0.5 * law.film(7.0)).abs() < 1e-15 * law.film(7.0));
            assert!(
                (half.integral(7.0) - 0.5 * law.integral(7.0)).abs() < 1e-15 * law.integral(7.0)
            );
            assert_eq!(law.film(0.5 * law.floor()), law.film(law.floor()));
        }
    }

    #[test]
    fn slope_and_integral_are_the_derivative_and_antiderivative_of_the_film() {
        for supply in SUPPLIES {
            let law = FilmLaw::new(&oil(), &supply, &GEOMETRY).unwrap();
            let knee = law.flooded_from();
            for q in [0.3, 2.0, 40.0, 900.0] {
                if (q / knee - 1.0).abs() < 1e-3 {
                    continue;
                }
                let d = 1e-6 * q;
                let slope = (law.film(q + d) - law.film(q - d)) / (2.0 * d);
                assert!((law.slope(q) / slope - 1.0).abs() < 1e-8, "{q}");
                let rate = (law.integral(q + d) - law.integral(q - d)) / (2.0 * d);
                assert!((rate / law.film(q) - 1.0).abs() < 1e-8, "{q}");
            }
            // Simpson on a fine log grid from the floor.
            let q: f64 = 500.0;
            let n = 20_000;
            let (x0, x1) = (law.floor().ln(), q.ln());
            let hstep = (x1 - x0) / n as f64;
            let f = |x: f64| law.film(x.exp()) * x.exp();
            let mut sum = f(x0) + f(x1);
            for k in 1..n {
                sum += f(x0 + k as f64 * hstep) * if k % 2 == 1 { 4.0 } else { 2.0 };
            }
            let expected = law.floor() * law.film(law.floor()) + sum * hstep / 3.0;
            assert!(
                (law.integral(q) / expected - 1.0).abs() < 1e-9,
                "{supply:?}: {} {expected}",
                law.integral(q)
            );
        }
    }

    #[test]
    fn the_speed_derivative_of_the_integral_is_the_laws() {
        for supply in SUPPLIES {
            let at = |u: f64| {
                FilmLaw::new(
                    &oil(),
                    &supply,
                    &FilmGeometry {
                        entrainment_speed: u,
                        ..GEOMETRY
                    },
                )
                .unwrap()
            };
            let u = GEOMETRY.entrainment_speed;
            let du = 1e-5 * u;
            for q in [0.05, 0.3, 5.0, 60.0, 900.0] {
                let fd = (at(u + du).integral(q) - at(u - du).integral(q)) / (2.0 * du / u);
                let exact = at(u).integral_speed_derivative(q);
                assert!(
                    (exact / fd - 1.0).abs() < 1e-7,
                    "{supply:?} {q}: {exact} {fd}"
                );
            }
        }
    }

    #[test]
    fn the_film_in_the_approach_refuses_an_oil_flow_supply() {
        let flow = Supply::Flow {
            flow: 1e-8,
            kinematic_viscosity: 3e-5,
            radius: 0.02,
        };
        let e = FilmLaw::new(&oil(), &flow, &GEOMETRY).unwrap_err();
        assert!(e.to_string().contains("inlet distance"), "{e}");
        // No entrainment: no film.
        let still = FilmGeometry {
            entrainment_speed: 0.0,
            ..GEOMETRY
        };
        let law = FilmLaw::new(&oil(), &Supply::InletDistance(1.5), &still).unwrap();
        assert_eq!(law.film(10.0), 0.0);
        assert_eq!(law.integral(10.0), 0.0);
    }
}
