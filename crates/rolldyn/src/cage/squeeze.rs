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

use super::PocketShape;
use crate::error::{InvalidParameter, require_non_negative, require_positive};
use crate::math::interp::{UniformPchip, UniformPchipRows};
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

/// The spherical pocket's cut-off fraction, in closed form. The opened
/// hemisphere (eccentricity ε_o = e) holds the suction p = K g(u),
/// K = 6ηR²|ḋ|/c³, u = cos θ from its rim (0) to its pole (1),
/// g(u) = ∫₀ᵘ (1 − e v)⁻³ dv = ((1 − e u)⁻² − 1)/(2e) (the axisymmetric
/// Reynolds equation of the module doc); held at T = aK from u_c on,
/// g(u_c) = a, it loses 2πR² ∫_{u_c}^1 (p − T) u du of the whole film's
/// 2πR² ∫₀¹ p u du = πR² K J(e):
/// ```text
/// fraction = (2 ∫_{u_c}^1 g u du − a (1 − u_c²)) / J(e),   u_c = 2a / ((1 + 2ea)(1 + (1 + 2ea)^{−1/2}))
/// ```
/// 0 where the pole's suction K g(1) = K (2 − e)/(2(1 − e)²) is within T.
pub fn sphere_cut_fraction(e: f64, a: f64) -> f64 {
    let gap = 1.0 - e;
    if (2.0 - e) / (2.0 * gap * gap) <= a {
        return 0.0;
    }
    // u_c = (1 − (1 + 2ea)^{−1/2})/e, in the form without its cancellation.
    let lift = 1.0 + 2.0 * e * a;
    let u_c = 2.0 * a / (lift * (1.0 + lift.sqrt().recip()));
    let lost = 2.0 * sphere_moment(e, u_c) - a * (1.0 - u_c * u_c);
    (lost / sphere_film_integral(e)).clamp(0.0, 1.0)
}

/// ∫_{u_c}^1 g(u) u du of [`sphere_cut_fraction`]: with w = 1 − e u,
/// ∫ u (1 − e u)⁻² du = (1/w + ln w)/e², so
/// ((1/w₁ − 1/w_c + ln(w₁/w_c))/e² − (1 − u_c²)/2)/(2e); near e = 0,
/// where that cancels, the series g = Σ_{n≥1} (n + 1)/2 eⁿ⁻¹ uⁿ.
fn sphere_moment(e: f64, u_c: f64) -> f64 {
    if e.abs() < 0.05 {
        // Terms to n = 14: the remainder is below 0.05¹⁴ ≈ 6e-19.
        let mut sum = 0.0;
        for n in (1..=14).rev() {
            let k = n as f64;
            sum = sum * e + 0.5 * (k + 1.0) * (1.0 - u_c.powi(n + 2)) / (k + 2.0);
        }
        sum
    } else {
        let (w1, wc) = (1.0 - e, 1.0 - e * u_c);
        let logs = (e * (u_c - 1.0) / wc).ln_1p();
        ((1.0 / w1 - 1.0 / wc + logs) / (e * e) - 0.5 * (1.0 - u_c * u_c)) / (2.0 * e)
    }
}

/// Nodes of the cut-off table along σ = (1 − ε_o)^¼ ∈ [0, 2^¼] and
/// v = (T/p₀)^¼ ∈ [0, 1].
const CUT_NODES: (usize, usize) = (97, 129);

/// The cut-off fraction over (σ, v) ([`cut_fraction_quadrature`]); in
/// these coordinates it is smooth: near the onset (v → 1) it grows as
/// (1 − v⁴)², at fast rates (v → 0) it tends to 1 as 1 − O(v³), and
/// near the wall (σ → 0) to a limit.
fn cut_table() -> &'static UniformPchipRows {
    static TABLE: OnceLock<UniformPchipRows> = OnceLock::new();
    TABLE.get_or_init(|| {
        let (rows, columns) = CUT_NODES;
        let hs = SQRT_2.sqrt() / (rows - 1) as f64;
        let hv = 1.0 / (columns - 1) as f64;
        let rows = (0..rows)
            .map(|i| {
                // The wall's row as its limit, a hair away from it.
                let sigma = (i as f64 * hs).max(1e-3 * hs);
                let gap = sigma.powi(4);
                let whole = opened_whole(gap);
                let y: Vec<f64> = (0..columns)
                    .map(|j| opened_cut(gap, (j as f64 * hv).powi(4)) / whole)
                    .collect();
                assert!(
                    y.iter().all(|f| f.is_finite()),
                    "the cut-off table's row at σ = {sigma} is not finite"
                );
                UniformPchip::new(0.0, hv, y)
            })
            .collect();
        UniformPchipRows::new(0.0, hs, rows)
    })
}

/// The fraction of the opened film's force lost to the cut-off, by
/// quadrature (the table's source): the opened side at eccentricity ε_o,
/// `onset` = T/p₀ ∈ [0, 1] with p₀ its narrowest strip's suction peak.
/// Each strip (angle φ, u = cos φ, gap h₀ = c(1 − ε_o u), opened at
/// V = |ḋ| u) has the pressure −6ηVR/h(x)², h = h₀(1 + ξ²),
/// x = ξ√(2Rh₀); where its peak p = 6ηVR/h₀² exceeds T it is held at −T
/// for |ξ| < ξ_c, ξ_c² = √(p/T) − 1, which takes from the strip's force
/// per unit length
/// ```text
/// Δ = 2√(2Rh₀) [p (ξ_c/(2(1 + ξ_c²)) + atan(ξ_c)/2) − T ξ_c]
/// ```
/// (0 at ξ_c = 0; as ξ_c → ∞ the strip keeps (8/3) T x_c: −T over the
/// band, a third of that in its tails). The cut is 2R ∫ Δ u dφ over the
/// strips whose peak exceeds T (u > u_c, as p grows with u), by 8-point
/// Gauss–Legendre on intervals that double from the width √(1 − ε_o) of
/// the film's narrowest part; the opened film's whole force is
/// 3√2 π η V R^{5/2} c^{−3/2} I(ε_o) (with |ḋ| for V). In units of R, c
/// and T both depend on ε_o and λ = 6η|ḋ|R/(T c²) = (1 − ε_o)²/onset
/// alone. Clipping each strip is an idealisation, not a solution of the
/// Reynolds equation with a cavity boundary (the Swift–Stieber condition
/// holds a little less suction): an upper bound on the opened side's
/// force as Gümbel's zero is a lower one.
pub fn cut_fraction_quadrature(gap: f64, onset: f64) -> f64 {
    if onset <= 0.0 {
        return 1.0;
    }
    opened_cut(gap, onset) / opened_whole(gap)
}

/// The opened film's whole force per λ in units of R, c and T:
/// (π/√2) I(ε_o), with `gap` = 1 − ε_o.
fn opened_whole(gap: f64) -> f64 {
    PI / SQRT_2 * cylinder_film_quadrature(gap.sqrt()) / gap
}

/// The cut of [`cut_fraction_quadrature`] per λ in units of R, c and T.
/// Written in the gap 1 − ε_o and in 1 − cos φ = 2 sin²(φ/2), which keep
/// their digits at the wall (ε_o → 1).
fn opened_cut(gap: f64, onset: f64) -> f64 {
    if onset >= 1.0 {
        return 0.0;
    }
    if onset <= 0.0 {
        return opened_whole(gap);
    }
    let lambda = gap * gap / onset;
    // The strip's gap h₀/c = 1 − ε_o u = (1 − u) + gap u at 1 − u = x.
    let film = |x: f64| x + gap * (1.0 - x);
    // p(x_c) = 1 at x = 1 − u_c: (gap + (1 − gap) x)² = λ (1 − x), one
    // positive root (the constant term gap² − λ < 0), in the form that
    // keeps its digits.
    let (qa, qb, qc) = (
        (1.0 - gap).powi(2),
        2.0 * gap * (1.0 - gap) + lambda,
        lambda - gap * gap,
    );
    let root = (qb * qb + 4.0 * qa * qc).sqrt();
    let x_c = if qb >= 0.0 {
        (2.0 * qc) / (qb + root)
    } else {
        (root - qb) / (2.0 * qa)
    };
    // φ_c = acos(1 − x_c).
    let phi_c = 2.0 * (0.5 * x_c.clamp(0.0, 1.0)).sqrt().asin();
    let strip = |phi: f64| {
        let x = 2.0 * (0.5 * phi).sin().powi(2);
        let (u, h0) = (1.0 - x, film(x));
        let p = lambda * u / (h0 * h0);
        if p <= 1.0 {
            return 0.0;
        }
        let xi = (p.sqrt() - 1.0).sqrt();
        let cut =
            2.0 * (2.0 * h0).sqrt() * (p * (xi / (2.0 * (1.0 + xi * xi)) + 0.5 * xi.atan()) - xi);
        cut.max(0.0) * u
    };
    let mut width = gap.sqrt().min(phi_c).max(1e-3 * phi_c);
    let (mut start, mut sum) = (0.0, 0.0);
    while start < phi_c {
        let end = (start + width).min(phi_c);
        sum += gauss_legendre_8(&strip, start, end);
        start = end;
        width *= 2.0;
    }
    2.0 * sum / lambda
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

/// 8-point Gauss–Legendre rule on [a, b] (Abramowitz & Stegun, Table 25.4,
/// the digits as printed).
#[allow(clippy::excessive_precision)]
fn gauss_legendre_8(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    const NODES: [(f64, f64); 4] = [
        (0.183_434_642_495_649_8, 0.362_683_783_378_362_0),
        (0.525_532_409_916_329_0, 0.313_706_645_877_887_3),
        (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
        (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
    ];
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    NODES
        .iter()
        .map(|&(x, w)| w * (f(mid - half * x) + f(mid + half * x)))
        .sum::<f64>()
        * half
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
mod tests {
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

    fn squeeze() -> PocketSqueeze {
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

    /// The opened film's force by brute force: each strip's pressure
    /// max(−6ηVR/h², −T) summed over ξ (midpoint, to |ξ| = 400) and φ.
    fn brute_opened(s: &PocketSqueeze, e: f64, c: f64, speed: f64, tension: f64) -> f64 {
        let (r, eta) = (s.ball_radius, s.viscosity);
        let (n_phi, n_xi, top) = (2000, 40_000, 400.0);
        let mut total = 0.0;
        for i in 0..n_phi {
            let phi = (i as f64 + 0.5) * 0.5 * PI / n_phi as f64;
            let u = phi.cos();
            let h0 = c * (1.0 - e * u);
            let p0 = 6.0 * eta * speed * u * r / (h0 * h0);
            // ξ on a grid graded as ξ = top t³, t ∈ (0, 1).
            let mut strip = 0.0;
            for j in 0..n_xi {
                let t = (j as f64 + 0.5) / n_xi as f64;
                let xi = top * t.powi(3);
                let p = (p0 / (1.0 + xi * xi).powi(2)).min(tension);
                strip += p * 3.0 * top * t * t / n_xi as f64;
            }
            total += 2.0 * (2.0 * r * h0).sqrt() * strip * u * 0.5 * PI / n_phi as f64;
        }
        2.0 * r * total
    }

    /// The films of a [`squeeze`] pocket with h_min 1 µm: full, half and
    /// (at `tension`) vapour.
    fn films(tension: f64) -> [PocketSqueeze; 3] {
        let full = PocketSqueeze {
            cavitation: SqueezeCavitation::FullFilm,
            min_film: 1e-6,
            ..squeeze()
        };
        let with = |cavitation| PocketSqueeze {
            cavitation,
            tension,
            ..full
        };
        [
            full,
            with(SqueezeCavitation::HalfSommerfeld),
            with(SqueezeCavitation::Vapour),
        ]
    }

    /// Offsets d/c and rates ḋ \[m/s\] the cut-off is checked at: centred,
    /// off-centre, near the wall both ways, and beyond the wall (the near
    /// film held at the least film, the far one at e = −1).
    const CASES: [(f64, f64); 7] = [
        (0.0, 1e-3),
        (0.5, -0.02),
        (0.99, -0.5),
        (0.99, 0.3),
        (0.3, 2.0),
        (1.2, -0.05),
        (1.2, 5.0),
    ];

    /// The opened film's clipped force by brute force: (squeeze, ε_o, c,
    /// |ḋ|, T).
    type Brute = fn(&PocketSqueeze, f64, f64, f64, f64) -> f64;

    /// The vapour film's force at offsets d and rates ḋ against the
    /// squeezed side's plus `brute`'s opened side, to `tolerance` of the
    /// opened film's whole force; between the two idealisations, and
    /// dissipative. Returns (T, d, ḋ, force, half's, full's) of each.
    fn against_brute_force(
        shape: PocketShape,
        cases: &[(f64, f64)],
        tolerance: f64,
        brute: Brute,
    ) -> Vec<[f64; 6]> {
        let c = 1e-4;
        let mut out = Vec::new();
        for tension in [1e3, 1e5, 1e7] {
            let [full, half, vapour] = films(tension);
            for &(d, rate) in cases {
                let (d, got) = (d * c, vapour.force(shape, d * c, c, rate));
                let squeezed = half.force(shape, d, c, rate);
                let opened_full = full.force(shape, d, c, rate) - squeezed;
                // The opened film's eccentricity, clamped as the model's.
                let toward = (d / c).min(1.0);
                let e = if rate > 0.0 { -toward } else { toward }.min(1.0 - full.min_film / c);
                let want = squeezed + rate.signum() * brute(&full, e, c, rate.abs(), tension);
                assert!(
                    (got - want).abs() <= tolerance * opened_full.abs() + 1e-12 * squeezed.abs(),
                    "T {tension}, d {d}, ḋ {rate}: {got} vs {want} (opened film {opened_full})"
                );
                let (lo, hi) = (squeezed.abs(), full.force(shape, d, c, rate).abs());
                assert!(got.abs() >= lo * (1.0 - 1e-12) && got.abs() <= hi * (1.0 + 1e-12));
                assert!(got * rate >= 0.0);
                out.push([tension, d / c, rate, got.abs(), lo, hi]);
            }
        }
        out
    }

    #[test]
    fn vapour_cut_off_takes_what_the_suction_cannot_hold() {
        let shape = PocketShape::Cylindrical;
        let mut cases = CASES.to_vec();
        cases.push((0.995, -1e-3));
        for [tension, d, rate, got, lo, hi] in
            against_brute_force(shape, &cases, 2e-4, brute_opened)
        {
            if tension == 1e3 && d > 0.9 && rate < -0.01 {
                // A fast rebound from the near wall: most of its suction
                // is cut off.
                assert!(got < lo + 0.05 * (hi - lo), "{got} in [{lo}, {hi}]");
            }
        }
        let c = 1e-4;
        for tension in [1e3, 1e5, 1e7] {
            let [full, _, vapour] = films(tension);
            // Continuous where the cut sets in: the rebound rate at which
            // the narrowest strip's suction reaches T.
            let d = 0.9 * c;
            let h0 = c - d;
            let onset = tension * h0 * h0 / (6.0 * full.viscosity * full.ball_radius);
            let (below, above) = (
                vapour.force(shape, d, c, -onset * (1.0 - 1e-9)),
                vapour.force(shape, d, c, -onset * (1.0 + 1e-6)),
            );
            assert_eq!(below, full.force(shape, d, c, -onset * (1.0 - 1e-9)));
            assert!((above / below - 1.0).abs() < 1e-5, "{below} → {above}");
        }
        // Slow: the suction stays below the tension and the film is whole.
        let [full, _, vapour] = films(DEFAULT_POCKET_TENSION);
        assert_eq!(
            vapour.force(shape, 0.9 * c, c, -1e-5),
            full.force(shape, 0.9 * c, c, -1e-5)
        );
    }

    /// The spherical pocket's opened film by brute force: the suction
    /// min(K g(u), T) on the hemisphere, g by its own midpoint sum, the
    /// force 2πR² ∫ p u du (midpoint, graded towards the pole).
    fn brute_opened_sphere(s: &PocketSqueeze, e: f64, c: f64, speed: f64, tension: f64) -> f64 {
        let r = s.ball_radius;
        let k = 6.0 * s.viscosity * r * r * speed / c.powi(3);
        let n = 400_000;
        let (mut g, mut force, mut u_prev) = (0.0, 0.0, 0.0);
        for i in 0..n {
            // u = 1 − (1 − t)³: cells shrink towards the pole.
            let t = (i as f64 + 1.0) / n as f64;
            let u = 1.0 - (1.0 - t).powi(3);
            let (du, mid) = (u - u_prev, 0.5 * (u + u_prev));
            g += du / (1.0 - e * mid).powi(3);
            force += (k * (g - 0.5 * du / (1.0 - e * mid).powi(3))).min(tension) * mid * du;
            u_prev = u;
        }
        2.0 * PI * r * r * force
    }

    #[test]
    fn sphere_cut_off_takes_what_the_suction_cannot_hold() {
        let mut cases = CASES.to_vec();
        cases.extend([(0.0, 0.3), (0.02, -0.4)]);
        let checked =
            against_brute_force(PocketShape::Spherical, &cases, 1e-5, brute_opened_sphere);
        // The cases reach from no cut to nearly all of the opened film.
        let share = |[_, _, _, got, lo, hi]: [f64; 6]| (hi - got) / (hi - lo);
        assert!(checked.iter().any(|&k| share(k) == 0.0));
        assert!(checked.iter().any(|&k| share(k) > 0.999));
        assert!(checked.iter().any(|&k| (0.1..0.9).contains(&share(k))));
        // The series and the closed form meet at |e| = 0.05.
        for e in [-0.05, 0.05] {
            let a = 0.2;
            let below = sphere_cut_fraction(e * (1.0 - 1e-12), a);
            let above = sphere_cut_fraction(e * (1.0 + 1e-12), a);
            assert!((below - above).abs() < 1e-11, "ε {e}: {below} vs {above}");
        }
        // Continuous at the onset: the pole's suction at T.
        for e in [-0.8, 0.0, 0.6] {
            let onset = (2.0 - e) / (2.0 * (1.0 - e) * (1.0 - e));
            assert_eq!(sphere_cut_fraction(e, onset), 0.0);
            assert!(sphere_cut_fraction(e, onset * (1.0 - 1e-6)) < 1e-8);
        }
    }

    #[test]
    fn cut_table_matches_its_quadrature_between_nodes() {
        for k in 0..4000 {
            // Quasi-random points over the whole (σ, v) square, the wall's
            // rows included.
            let sigma = SQRT_2.sqrt() * ((k as f64 + 0.5) * 0.618_034).fract();
            let v = ((k as f64 + 0.5) * 0.754_878).fract();
            let want = cut_fraction_quadrature(sigma.powi(4), v.powi(4));
            let error = (cut_table().eval(sigma, v) - want).abs();
            // Its worst is where the onset (v → 1) meets the thickest
            // opened film (ε_o → −1, σ → 2^¼): there the narrowest strip's
            // peak is flat in φ and the fraction rises as (1 − v⁴)^1.75
            // instead of (1 − v⁴)²; away from the onset it is a few 1e-6.
            // 2e-4 of the opened film is also what the quadrature is held
            // to against brute force.
            assert!(error <= 2e-4, "σ {sigma}, v {v}: table error {error:e}");
        }
        // Its ends: nothing at the onset, everything at an infinite rate.
        assert_eq!(cut_fraction_quadrature(0.7, 1.0), 0.0);
        assert!((cut_fraction_quadrature(0.7, 1e-12) - 1.0).abs() < 1e-3);
        // At the wall it tends to a limit: the gap's digits are kept.
        let near = cut_fraction_quadrature(1e-16, 0.5);
        assert!(near.is_finite() && near > 0.0 && near < 1.0, "{near}");
        assert!((cut_fraction_quadrature(1e-12, 0.5) - near).abs() < 1e-5);
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
