//! The vapour cut-off of the pocket film's opened side (docs/dynamics.md,
//! "Pocket squeeze film"): the fraction of the opened film's force its
//! suction loses where it is held at the tension T. For a cylindrical
//! pocket each strip's pressure is clipped in closed form and the strips
//! summed by quadrature, tabulated once per process over the opened
//! side's eccentricity and T/p₀; for a spherical pocket the clipped cap
//! integrates in closed form. The suction cannot fall below the oil's
//! vapour pressure in a film opened within microseconds (Sun & Brewe
//! 1992).

use super::{cylinder_film_quadrature, sphere_film_integral};
use crate::math::interp::{UniformPchip, UniformPchipRows};
use std::f64::consts::{PI, SQRT_2};
use std::sync::OnceLock;

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
pub(super) fn cut_table() -> &'static UniformPchipRows {
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

#[cfg(test)]
mod tests {
    use super::super::tests::squeeze;
    use super::super::{DEFAULT_POCKET_TENSION, PocketSqueeze, SqueezeCavitation};
    use super::*;
    use crate::cage::PocketShape;

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
}
