//! Squeeze-film damping of a ball in its lubricated pocket (a rolldyn
//! extension of docs/model.md §5; none of the source papers has it).
//!
//! Deng et al. 2022's `gupta_film` law (eqs 26–28) gives the pocket oil film a
//! stiffness but no damping, so a cage on its pocket films has an
//! undamped mode (the 3.6–3.8 kHz rattle of docs/validation.md). An oil
//! film between approaching surfaces resists the approach: this module
//! adds that squeeze-film force, from the isoviscous Reynolds equation for
//! rigid surfaces. The film being squeezed carries pressure; the one being
//! opened holds suction down to the oil's vapour pressure
//! (`SqueezeCavitation::Vapour`, the default, [`PocketSqueeze::force`]),
//! none (half-Sommerfeld, Gümbel: it cavitates at ambient pressure) or any
//! (full Sommerfeld).
//!
//! Ball radius R, per-side clearance c, ball-centre offset d = ε c
//! towards the wall, approach rate ḋ. The gap at angle φ from the
//! direction of offset is h = c (1 − ε cos φ), so the wall there is
//! approached at ḋ cos φ.
//!
//! **Cylindrical pocket** (axis along the cage radius). Along the pocket
//! axis the wall is straight and the ball's surface recedes as z²/(2R):
//! at each φ the film is that of a cylinder of radius R approaching a
//! plane, whose load per unit length is 3√2 π η V R^{3/2} / h^{3/2}
//! (short-bearing approximation; Hamrock, Schmid & Jacobson,
//! *Fundamentals of Fluid Film Lubrication*, 2nd ed., ch. 10, rigid
//! cylinder in normal approach). Summed over the approached half of the
//! pocket (R dφ, component cos φ):
//! ```text
//! F = 3√2 π η R^{5/2} c^{−3/2} ḋ I(ε),   I(ε) = ∫_{−π/2}^{π/2} cos²φ (1 − ε cos φ)^{−3/2} dφ
//! ```
//! The band that carries the film is √(2Rh) wide against a circumferential
//! length scale R√(2h/c), a ratio √(c/R) (0.15 for the 7008C), so the
//! short-bearing approximation holds to O(c/R). The pocket must be longer
//! than the band (√(2Rc) ≈ 0.8 mm for the 7008C).
//!
//! **Spherical pocket.** On the sphere h = c (1 − ε cos θ); the
//! axisymmetric Reynolds equation integrates in closed form over the
//! approached hemisphere (regular at the pole, p = 0 at its rim):
//! ```text
//! F = 6π η R⁴ c^{−3} ḋ J(ε),   J(ε) = ∫₀¹ (1 − u²)/(1 − ε u)³ du = Σ_k (k+2)/(k+3) ε^k
//!                                    = 1/(1 − ε) + (ln(1 − ε) + ε + ε²/2)/ε³
//! ```
//! Both tend to the sphere–plane result 6π η R_eq² ḋ/h (R_eq = R²/c,
//! h = c(1 − ε)) for the spherical pocket, and to 12π η R^{5/2} ḋ /
//! (c^{3/2}(1 − ε)) for the cylindrical one, as the ball nears the wall.
//!
//! Moving away from the near wall (ḋ < 0) squeezes the far one: the same
//! formulas with ε → −ε. Without cavitation (`SqueezeCavitation::FullFilm`,
//! the full-Sommerfeld condition: the film holds tension) both sides carry
//! pressure, and since the cylindrical film is solved angle by angle and
//! the spherical one has the same pressure gradient on both hemispheres,
//! the damping is the sum of the two sides' (full sphere at ε = 0:
//! 8π η R⁴/c³). It is smooth in ḋ; the half-Sommerfeld damping changes
//! at ḋ = 0 from one side's film to the other's. The vapour cut-off takes
//! from the full film what the opened side's suction cannot hold (its
//! pressure clipped at the tension T: strip by strip in a cylindrical
//! pocket, over a cap around the pole in a spherical one; Sun & Brewe 1992
//! for why the vapour pressure, not ambient, bounds a film opened within
//! microseconds; docs/dynamics.md, "Pocket squeeze film"). The film on the approached side is held at
//! h ≥ h_min (`min_film`, e.g. the composite roughness), i.e. ε ≤ 1 −
//! h_min/c; beyond the wall (d > c, the solid contact of the normal law)
//! the squeeze damping stays at its h_min value. The force is purely
//! dissipative: it stores no energy, and its power F ḋ ≥ 0 is dissipated.
//!
//! I(ε) is an incomplete elliptic integral: it is tabulated once per
//! process, as (1 − ε) I(ε), which is bounded (2√2 at the wall), against
//! (1 − ε)^¼, in which it is smooth, and interpolated (monotone cubic) in
//! the time loop.

mod cut_off;

pub use cut_off::{cut_fraction_quadrature, sphere_cut_fraction};

use super::PocketShape;
use crate::error::{InvalidParameter, require_non_negative, require_positive};
use crate::math::interp::UniformPchip;
use cut_off::cut_table;
use serde::{Deserialize, Serialize};
use std::f64::consts::{PI, SQRT_2};
use std::sync::OnceLock;

/// Which side of the pocket film carries pressure.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum SqueezeCavitation {
    /// Half-Sommerfeld (Gümbel): only the squeezed side; the opened side
    /// cavitates at ambient pressure.
    HalfSommerfeld,
    /// Full-Sommerfeld: both sides, the opened one in tension.
    FullFilm,
    /// Both sides, the opened one in tension down to the oil's vapour
    /// pressure: its suction is cut off at [`PocketSqueeze::tension`].
    /// A cavity fills with vapour quickly, while
    /// dissolved air is far too slow to come out of solution (Sun & Brewe
    /// 1992), so a film opened within microseconds cavitates near the
    /// vapour pressure, not at ambient.
    #[default]
    Vapour,
}

/// Default [`PocketSqueeze::tension`] \[Pa\]: a bath at standard
/// atmospheric pressure, whose oil cavitates at its vapour pressure
/// (below 1 Pa for mineral oils at bearing temperatures: taken as 0).
pub const DEFAULT_POCKET_TENSION: f64 = 101_325.0;

/// Squeeze-film damping of the pocket oil film.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PocketSqueeze {
    /// Oil viscosity η \[Pa·s\] (the lubricant's η₀; the thermal coupling
    /// updates it with the guide land's).
    pub viscosity: f64,
    /// Ball radius R \[m\].
    pub ball_radius: f64,
    /// Least film h_min on the approached side \[m\].
    pub min_film: f64,
    /// Which side of the film carries pressure.
    pub cavitation: SqueezeCavitation,
    /// Largest suction the opened film holds, ambient less vapour
    /// pressure \[Pa\] ([`SqueezeCavitation::Vapour`] only).
    pub tension: f64,
}

impl PocketSqueeze {
    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        require_non_negative("pocket_squeeze_viscosity", self.viscosity)?;
        require_positive("ball_radius", self.ball_radius)?;
        require_positive("pocket_min_film", self.min_film)?;
        require_positive("pocket_squeeze_tension", self.tension)
    }

    /// Builds the tables this film reads now (once per process; a model
    /// with the squeeze film calls it when it is made, so the time loop
    /// only reads them): a cylindrical pocket's film integral, and with
    /// the vapour cut-off its table (a spherical pocket's are closed forms).
    pub fn build_tables(&self, shape: PocketShape) {
        if shape == PocketShape::Cylindrical {
            cylinder_table();
            if self.cavitation == SqueezeCavitation::Vapour {
                cut_table();
            }
        }
    }

    /// Squeeze-film force on the ball \[N\] at offset d from the pocket
    /// centre, per-side clearance c and approach rate ḋ (towards the wall
    /// the ball is offset to): positive pushes the ball back towards the
    /// pocket centre. Its sign is that of ḋ, so F ḋ ≥ 0.
    #[inline]
    pub fn force(&self, shape: PocketShape, offset: f64, half_clearance: f64, rate: f64) -> f64 {
        match self.cavitation {
            SqueezeCavitation::Vapour => {
                let c = half_clearance;
                let squeezed = self.side_damping(shape, offset, c, rate) * rate;
                let opened = self.side_damping(shape, offset, c, -rate) * rate;
                squeezed + opened * (1.0 - self.cut_fraction(shape, offset, c, rate))
            }
            _ => self.damping(shape, offset, half_clearance, rate) * rate,
        }
    }

    /// Damping coefficient F/ḋ \[N·s/m\] for an approach rate of the sign
    /// of `rate` (for [`SqueezeCavitation::Vapour`], the full film's: the
    /// cut-off makes its force nonlinear in ḋ, [`Self::force`]).
    #[inline]
    pub fn damping(&self, shape: PocketShape, offset: f64, half_clearance: f64, rate: f64) -> f64 {
        match self.cavitation {
            SqueezeCavitation::HalfSommerfeld => {
                self.side_damping(shape, offset, half_clearance, rate)
            }
            SqueezeCavitation::FullFilm | SqueezeCavitation::Vapour => {
                self.side_damping(shape, offset, half_clearance, 1.0)
                    + self.side_damping(shape, offset, half_clearance, -1.0)
            }
        }
    }

    /// The fraction of the opened film's force that its suction's cut-off
    /// at the tension T takes (0 below the onset): from the table of
    /// [`cut_fraction_quadrature`] (cylindrical pockets), in closed form
    /// ([`sphere_cut_fraction`], spherical ones).
    #[inline]
    fn cut_fraction(&self, shape: PocketShape, offset: f64, c: f64, rate: f64) -> f64 {
        if rate == 0.0 {
            return 0.0;
        }
        let most = 1.0 - self.min_film / c;
        let toward = (offset / c).min(1.0);
        // The opened side: the far wall while approaching the near one.
        let e = if rate > 0.0 { -toward } else { toward }.min(most);
        let gap = 1.0 - e;
        let r = self.ball_radius;
        match shape {
            PocketShape::Cylindrical => {
                // The narrowest strip's suction peak 6η|ḋ|R/(c(1 − ε_o))².
                let peak = 6.0 * self.viscosity * rate.abs() * r / (c * gap).powi(2);
                if peak <= self.tension {
                    return 0.0;
                }
                let onset = self.tension / peak;
                cut_table()
                    .eval(gap.sqrt().sqrt(), onset.sqrt().sqrt())
                    .clamp(0.0, 1.0)
            }
            PocketShape::Spherical => {
                // The suction's scale 6ηR²|ḋ|/c³.
                let scale = 6.0 * self.viscosity * r * r * rate.abs() / c.powi(3);
                sphere_cut_fraction(e, self.tension / scale)
            }
        }
    }

    /// The damping of one side's film: the side approached at a rate of
    /// the sign of `rate` (the near wall for ḋ ≥ 0).
    #[inline]
    fn side_damping(&self, shape: PocketShape, offset: f64, half_clearance: f64, rate: f64) -> f64 {
        let c = half_clearance;
        let r = self.ball_radius;
        let most = 1.0 - self.min_film / c;
        let toward = (offset / c).min(1.0);
        let eccentricity = if rate >= 0.0 { toward } else { -toward }.min(most);
        match shape {
            PocketShape::Cylindrical => {
                // I(ε) = f(√(1−ε))/(1−ε), the film on the approached side c(1−ε).
                let film = c * (1.0 - eccentricity);
                3.0 * SQRT_2
                    * PI
                    * self.viscosity
                    * r
                    * r
                    * (r / c).sqrt()
                    * cylinder_film_integral((1.0 - eccentricity).sqrt())
                    / film
            }
            PocketShape::Spherical => {
                6.0 * PI * self.viscosity * (r * r / c).powi(2) / c
                    * sphere_film_integral(eccentricity)
            }
        }
    }
}

/// (1 − ε) I(ε) of the cylindrical pocket at x = √(1 − ε), x ∈ [0, √2]
/// (clamped), from the table. The table's abscissa is √x: near the wall
/// the function goes as 2√2 + O(x² ln x), which is C³ in √x and not in x.
#[inline]
pub fn cylinder_film_integral(x: f64) -> f64 {
    cylinder_table().eval(x.sqrt())
}

/// J(ε) of the spherical pocket, ε ∈ [−1, 1): the power series (k+2)/(k+3)
/// εᵏ near 0, where the closed form cancels, the closed form elsewhere.
#[inline]
pub fn sphere_film_integral(eccentricity: f64) -> f64 {
    let e = eccentricity;
    if e.abs() < 0.05 {
        // Terms to k = 12: the remainder is below 0.05¹³ ≈ 1e-17.
        let mut sum = 0.0;
        for k in (0..=12).rev() {
            sum = sum * e + (k as f64 + 2.0) / (k as f64 + 3.0);
        }
        sum
    } else {
        1.0 / (1.0 - e) + ((-e).ln_1p() + e + 0.5 * e * e) / (e * e * e)
    }
}

/// Nodes of the cylindrical table on √x ∈ [0, 2^¼].
const TABLE_NODES: usize = 1025;

fn cylinder_table() -> &'static UniformPchip {
    static TABLE: OnceLock<UniformPchip> = OnceLock::new();
    TABLE.get_or_init(|| {
        let h = SQRT_2.sqrt() / (TABLE_NODES - 1) as f64;
        let y = (0..TABLE_NODES)
            .map(|i| cylinder_film_quadrature((i as f64 * h).powi(2)))
            .collect();
        UniformPchip::new(0.0, h, y)
    })
}

/// (1 − ε) I(ε) at x = √(1 − ε) by quadrature (the table's source).
/// For ε > 0 the peak of the integrand at φ = 0, of width √(1 − ε), is
/// spread out by t = tan(φ/2) = a tan ϑ, a = √((1 − ε)/(1 + ε)):
/// (1 − ε) I = 4/√(1 + ε) ∫₀^{atan(1/a)} cos²φ √(1 + t²) cos ϑ dϑ.
pub fn cylinder_film_quadrature(x: f64) -> f64 {
    let e = 1.0 - x * x;
    if x <= 0.0 {
        return 2.0 * SQRT_2;
    }
    if e > 0.0 {
        let a = x / (2.0 - x * x).sqrt();
        let integrand = |theta: f64| {
            let t = a * theta.tan();
            let cos_phi = (1.0 - t * t) / (1.0 + t * t);
            cos_phi * cos_phi * (1.0 + t * t).sqrt() * theta.cos()
        };
        4.0 / (1.0 + e).sqrt() * simpson(integrand, 0.0, (1.0 / a).atan())
    } else {
        let integrand = |phi: f64| {
            let c = phi.cos();
            c * c / (1.0 - e * c).powf(1.5)
        };
        (1.0 - e) * 2.0 * simpson(integrand, 0.0, 0.5 * PI)
    }
}

/// Composite Simpson rule, 2000 intervals (smooth integrands: error
/// below 1e-12).
fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    const N: usize = 2000;
    let h = (b - a) / N as f64;
    let inner: f64 = (1..N)
        .map(|i| f(a + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 })
        .sum();
    (f(a) + f(b) + inner) * h / 3.0
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// Brute-force I(ε) by the midpoint rule on φ, 2·10⁵ cells.
    fn brute_cylinder(e: f64) -> f64 {
        let n = 200_000;
        let h = PI / n as f64;
        (0..n)
            .map(|i| {
                let c = (-0.5 * PI + (i as f64 + 0.5) * h).cos();
                c * c / (1.0 - e * c).powf(1.5)
            })
            .sum::<f64>()
            * h
    }

    #[test]
    fn cylinder_integral_known_values() {
        // ε = 0: ∫ cos² over a half turn = π/2.
        assert!((cylinder_film_quadrature(1.0) - 0.5 * PI).abs() < 1e-12);
        for e in [-1.0, -0.5, 0.3, 0.9, 0.99, 0.999] {
            let x = (1.0f64 - e).sqrt();
            let want = (1.0 - e) * brute_cylinder(e);
            let got = cylinder_film_quadrature(x);
            assert!((got - want).abs() < 1e-7 * want, "ε {e}: {got} vs {want}");
        }
        // The wall limit 2√2 is approached continuously.
        let near = cylinder_film_quadrature(1e-4);
        assert!((near - 2.0 * SQRT_2).abs() < 1e-3, "{near}");
    }

    #[test]
    fn cylinder_table_matches_quadrature_between_nodes() {
        let mut worst: f64 = 0.0;
        for i in 0..997 {
            let x = SQRT_2 * (i as f64 + 0.37) / 997.0;
            let want = cylinder_film_quadrature(x);
            worst = worst.max((cylinder_film_integral(x) - want).abs() / want);
        }
        assert!(worst < 1e-7, "worst relative table error {worst:e}");
    }

    #[test]
    fn sphere_integral_series_and_closed_form_agree() {
        assert!((sphere_film_integral(0.0) - 2.0 / 3.0).abs() < 1e-15);
        // Direct quadrature of ∫₀¹ (1 − u²)/(1 − εu)³ du.
        for e in [-1.0, -0.3, -0.049, 0.049, 0.051, 0.5, 0.9, 0.99] {
            let want = if e < 0.95 {
                simpson(|u| (1.0 - u * u) / (1.0 - e * u).powi(3), 0.0, 1.0)
            } else {
                // Simpson misses the peak at u = 1; the series, 2·10⁴ terms.
                (0..20_000)
                    .map(|k| (k as f64 + 2.0) / (k as f64 + 3.0) * e.powi(k))
                    .sum()
            };
            let got = sphere_film_integral(e);
            assert!((got - want).abs() < 1e-9 * want, "ε {e}: {got} vs {want}");
        }
    }

    pub(in crate::cage::squeeze) fn squeeze() -> PocketSqueeze {
        PocketSqueeze {
            viscosity: 0.02,
            ball_radius: 4e-3,
            min_film: 1e-8,
            cavitation: SqueezeCavitation::HalfSommerfeld,
            tension: DEFAULT_POCKET_TENSION,
        }
    }

    #[test]
    fn near_the_wall_both_tend_to_their_plane_limits() {
        let s = squeeze();
        let c = 1e-4;
        let d = c - 1e-7;
        let h = c - d;
        let r = s.ball_radius;
        // Sphere in a sphere → sphere–plane with R_eq = R²/c.
        let sphere = s.damping(PocketShape::Spherical, d, c, 1.0);
        let plane = 6.0 * PI * s.viscosity * (r * r / c).powi(2) / h;
        assert!((sphere / plane - 1.0).abs() < 0.02, "{}", sphere / plane);
        // Cylindrical pocket → 12π η R^{5/2} /(c^{3/2}(1 − ε)).
        let cylinder = s.damping(PocketShape::Cylindrical, d, c, 1.0);
        let limit = 12.0 * PI * s.viscosity * r.powf(2.5) / (c.powf(1.5) * (h / c));
        assert!(
            (cylinder / limit - 1.0).abs() < 0.02,
            "{}",
            cylinder / limit
        );
    }

    #[test]
    fn force_opposes_the_motion_and_is_held_at_the_least_film() {
        let s = squeeze();
        let c = 1e-4;
        for shape in [PocketShape::Cylindrical, PocketShape::Spherical] {
            for d in [0.0, 0.3 * c, 0.9 * c, 1.2 * c] {
                assert!(s.force(shape, d, c, 1e-3) > 0.0);
                assert!(s.force(shape, d, c, -1e-3) < 0.0);
                // Approaching the near wall is damped more than the far one.
                if d > 0.0 {
                    assert!(s.damping(shape, d, c, 1.0) > s.damping(shape, d, c, -1.0));
                }
            }
            // At and beyond the wall: the h_min value.
            let at_floor = s.damping(shape, c - s.min_film, c, 1.0);
            assert_eq!(s.damping(shape, c, c, 1.0), at_floor);
            assert_eq!(s.damping(shape, 1.5 * c, c, 1.0), at_floor);
            // Centred, the two directions are the same film.
            assert_eq!(
                s.damping(shape, 0.0, c, 1.0),
                s.damping(shape, 0.0, c, -1.0)
            );
        }
    }

    #[test]
    fn full_film_sums_both_sides_and_is_smooth_in_the_rate() {
        let half = squeeze();
        let full = PocketSqueeze {
            cavitation: SqueezeCavitation::FullFilm,
            ..half
        };
        let (c, r, eta) = (1e-4, half.ball_radius, half.viscosity);
        // Centred: the full sphere 8π η R⁴/c³ (Reynolds on the whole
        // sphere) and the full circle 3√2 π η R^{5/2} c^{−3/2} · π.
        let sphere = full.damping(PocketShape::Spherical, 0.0, c, 1.0);
        let want = 8.0 * PI * eta * r.powi(4) / c.powi(3);
        assert!((sphere / want - 1.0).abs() < 1e-14, "{}", sphere / want);
        let cylinder = full.damping(PocketShape::Cylindrical, 0.0, c, 1.0);
        let want = 3.0 * SQRT_2 * PI * eta * r.powf(2.5) / c.powf(1.5) * PI;
        assert!((cylinder / want - 1.0).abs() < 1e-7, "{}", cylinder / want);
        for shape in [PocketShape::Cylindrical, PocketShape::Spherical] {
            for d in [0.0, 0.4 * c, 0.95 * c] {
                let both = half.damping(shape, d, c, 1.0) + half.damping(shape, d, c, -1.0);
                assert_eq!(full.damping(shape, d, c, 1.0), both);
                assert_eq!(full.damping(shape, d, c, -1.0), both);
            }
        }
    }

    #[test]
    fn damping_is_proportional_to_viscosity() {
        let s = squeeze();
        let double = PocketSqueeze {
            viscosity: 2.0 * s.viscosity,
            ..s
        };
        let shape = PocketShape::Cylindrical;
        let ratio = double.damping(shape, 5e-5, 1e-4, 1.0) / s.damping(shape, 5e-5, 1e-4, 1.0);
        assert!((ratio - 2.0).abs() < 1e-14);
    }
}
