//! Complete elliptic integrals of the first and second kind, K(m) and E(m),
//! in the *parameter* convention m = k² (Abramowitz & Stegun 17.3).
//!
//! Computed from Carlson's symmetric integrals by the duplication theorem
//! (B. C. Carlson, "Numerical computation of real or complex elliptic
//! integrals", Numerical Algorithms 10 (1995) 13–26, algorithms for R_F and
//! R_D):
//!
//! ```text
//! K(m) = R_F(0, 1−m, 1)
//! D(m) = (K − E)/m = R_D(0, 1−m, 1)/3      (no cancellation as m → 0)
//! E(m) = K(m) − m D(m)
//! ```
//!
//! Accuracy: the truncation tolerance below bounds the relative error of the
//! series by ~1e-18, so results are good to a few ulp (A1 checks 1e-12).

/// Relative tolerance of Carlson's duplication loop. The remaining series
/// error is below `ERRTOL^6 / 4` ≈ 1e-19 (Carlson 1995, eq. 2.2).
const ERRTOL: f64 = 7.0e-4;

/// Carlson's symmetric integral of the first kind R_F(x, y, z) for
/// non-negative arguments with at most one zero.
pub fn carlson_rf(x: f64, y: f64, z: f64) -> f64 {
    let (mut x, mut y, mut z) = (x, y, z);
    loop {
        let mu = (x + y + z) / 3.0;
        let dx = (mu - x) / mu;
        let dy = (mu - y) / mu;
        let dz = (mu - z) / mu;
        if dx.abs().max(dy.abs()).max(dz.abs()) < ERRTOL {
            let e2 = dx * dy - dz * dz;
            let e3 = dx * dy * dz;
            return (1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0)
                / mu.sqrt();
        }
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lambda = sx * (sy + sz) + sy * sz;
        x = 0.25 * (x + lambda);
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
    }
}

/// Carlson's symmetric integral of the second kind R_D(x, y, z) for x, y ≥ 0
/// (not both zero) and z > 0.
pub fn carlson_rd(x: f64, y: f64, z: f64) -> f64 {
    let (mut x, mut y, mut z) = (x, y, z);
    let mut sum = 0.0;
    let mut factor = 1.0;
    loop {
        let mu = (x + y + 3.0 * z) / 5.0;
        let dx = (mu - x) / mu;
        let dy = (mu - y) / mu;
        let dz = (mu - z) / mu;
        if dx.abs().max(dy.abs()).max(dz.abs()) < ERRTOL {
            let ea = dx * dy;
            let eb = dz * dz;
            let ec = ea - eb;
            let ed = ea - 6.0 * eb;
            let ef = ed + ec + ec;
            let s1 = ed * (-3.0 / 14.0 + 9.0 / 88.0 * ed - 9.0 / 52.0 * dz * ef);
            let s2 = dz * (ef / 6.0 + dz * (-9.0 / 22.0 * ec + 3.0 / 26.0 * dz * ea));
            return 3.0 * sum + factor * (1.0 + s1 + s2) / (mu * mu.sqrt());
        }
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lambda = sx * (sy + sz) + sy * sz;
        sum += factor / (sz * (z + lambda));
        factor *= 0.25;
        x = 0.25 * (x + lambda);
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
    }
}

/// The complete elliptic integrals at parameter m ∈ [0, 1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CompleteElliptic {
    /// K(m), first kind.
    pub k: f64,
    /// E(m), second kind.
    pub e: f64,
    /// D(m) = (K − E)/m, computed without cancellation (π/4 at m = 0).
    pub d: f64,
}

/// K(m), E(m) and D(m) for 0 ≤ m < 1. Callers guarantee the range (the Hertz
/// solver only passes m = 1 − 1/κ² with finite κ ≥ 1).
pub fn complete(m: f64) -> CompleteElliptic {
    let y = 1.0 - m;
    let k = carlson_rf(0.0, y, 1.0);
    let d = carlson_rd(0.0, y, 1.0) / 3.0;
    CompleteElliptic { k, e: k - m * d, d }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn rel(a: f64, b: f64) -> f64 {
        ((a - b) / b).abs()
    }

    #[test]
    fn known_values_at_half() {
        // A1 (docs/validation.md): reference values from A&S Table 17.1 / mpmath.
        let c = complete(0.5);
        assert!(
            rel(c.k, 1.854_074_677_301_371_9) < 1e-12,
            "K(0.5) = {}",
            c.k
        );
        assert!(
            rel(c.e, 1.350_643_881_047_675_5) < 1e-12,
            "E(0.5) = {}",
            c.e
        );
    }

    #[test]
    fn limit_m_to_zero_is_half_pi() {
        for m in [0.0, 1e-300, 1e-16] {
            let c = complete(m);
            assert!(rel(c.k, PI / 2.0) < 1e-12);
            assert!(rel(c.e, PI / 2.0) < 1e-12);
            assert!(rel(c.d, PI / 4.0) < 1e-12);
        }
    }

    #[test]
    fn legendre_relation_holds() {
        // E K' + E' K − K K' = π/2 (A&S 17.3.13), with primes at 1 − m.
        for m in [0.01, 0.1, 0.3, 0.5, 0.7, 0.95, 0.999] {
            let a = complete(m);
            let b = complete(1.0 - m);
            let lhs = a.e * b.k + b.e * a.k - a.k * b.k;
            assert!(rel(lhs, PI / 2.0) < 1e-13, "m = {m}: {lhs}");
        }
    }

    #[test]
    fn d_matches_difference_where_stable() {
        let m = 0.6;
        let c = complete(m);
        assert!(rel(c.d, (c.k - c.e) / m) < 1e-14);
    }
}
