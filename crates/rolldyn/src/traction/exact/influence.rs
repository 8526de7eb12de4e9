//! Influence coefficients of an elastic half-space for tractions that are
//! constant over rectangular cells (Boussinesq and Cerruti; K. L. Johnson,
//! *Contact Mechanics*, 1985, §3.2 and §3.5; J. J. Kalker, *Three-Dimensional
//! Elastic Bodies in Rolling Contact*, 1990, ch. 5).
//!
//! A point force on the surface of a half-space with shear modulus G_i and
//! Poisson ratio ν_i displaces the surface at distance ρ = √(x² + y²) by
//! ```text
//! normal P:      u_z = P (1 − ν_i) / (2π G_i ρ)
//! tangential Q_x: u_x = Q_x / (2π G_i) [(1 − ν_i)/ρ + ν_i x²/ρ³],
//!                 u_y = Q_x / (2π G_i) ν_i x y/ρ³
//! ```
//! (plus a normal displacement ∝ (1 − 2ν_i) that two bodies of equal
//! (1 − 2ν)/G cancel: Kalker's *quasi-identity*, assumed here as in his
//! creep coefficients). Two bodies pressed by ±P and sheared by ±Q add
//! their displacements; with Kalker's combined constants 1/G = ½(1/G₁ +
//! 1/G₂), ν/G = ½(ν₁/G₁ + ν₂/G₂) the relative displacement is
//! ```text
//! u_z = (1 − ν) P / (π G ρ),
//! u_x = [(1 − ν)/ρ + ν x²/ρ³] Q_x/(π G) + ν x y/ρ³ Q_y/(π G)   (u_y alike)
//! ```
//! Integrated over a cell, with primitives whose mixed derivative is the
//! kernel (∂²/∂x∂y), evaluated at the four corners:
//! ```text
//! 1/ρ:    x ln(y + ρ) + y ln(x + ρ)
//! x²/ρ³:  y ln(x + ρ)
//! y²/ρ³:  x ln(y + ρ)
//! xy/ρ³:  −ρ
//! ```
//! On a uniform grid the coefficients depend on the offset between cells
//! only, so one table per kernel serves the whole grid (a convolution).

use std::f64::consts::PI;

/// y ln(x + ρ), ρ = √(x² + y²), continuous where x + ρ → 0 (x < 0, y → 0):
/// there x + ρ = y²/(ρ − x) is taken without cancellation, and the
/// product tends to 0.
fn y_log_x_plus_rho(x: f64, y: f64) -> f64 {
    if y == 0.0 {
        return 0.0;
    }
    let rho = x.hypot(y);
    let sum = if x >= 0.0 { x + rho } else { y * y / (rho - x) };
    y * sum.ln()
}

/// ∫∫ f over [x₀, x₁] × [y₀, y₁] from a primitive F with ∂²F/∂x∂y = f.
fn corners(f: impl Fn(f64, f64) -> f64, x: (f64, f64), y: (f64, f64)) -> f64 {
    f(x.1, y.1) - f(x.0, y.1) - f(x.1, y.0) + f(x.0, y.0)
}

/// The four surface kernels integrated over one cell.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct CellIntegrals {
    /// ∫∫ 1/ρ \[m\].
    pub inverse: f64,
    /// ∫∫ x²/ρ³ \[m\].
    pub xx: f64,
    /// ∫∫ y²/ρ³ \[m\].
    pub yy: f64,
    /// ∫∫ xy/ρ³ \[m\].
    pub xy: f64,
}

/// The kernels integrated over the cell of size `dx` × `dy` centred at
/// (`x`, `y`) relative to the field point.
pub fn cell_integrals(x: f64, y: f64, dx: f64, dy: f64) -> CellIntegrals {
    let xs = (x - 0.5 * dx, x + 0.5 * dx);
    let ys = (y - 0.5 * dy, y + 0.5 * dy);
    let xx = corners(y_log_x_plus_rho, xs, ys);
    let yy = corners(|a, b| y_log_x_plus_rho(b, a), xs, ys);
    CellIntegrals {
        inverse: xx + yy,
        xx,
        yy,
        xy: corners(|a, b| -a.hypot(b), xs, ys),
    }
}

/// Influence coefficients of a uniform grid of `along` × `across` cells of
/// size `dx` × `dy`: the relative surface displacement at a cell centre
/// per unit traction on a cell at offset (i, k) \[m/Pa\], for offsets
/// −`along` ≤ i ≤ `along`, |k| < `across` (the rolling derivative needs
/// the extra offset upstream).
#[derive(Debug, Clone)]
pub struct Influence {
    along: usize,
    across: usize,
    /// Normal: u_z per p_z.
    pub normal: Vec<f64>,
    /// Tangential: u_x per p_x.
    pub xx: Vec<f64>,
    /// u_x per p_y (= u_y per p_x).
    pub xy: Vec<f64>,
    /// u_y per p_y.
    pub yy: Vec<f64>,
}

impl Influence {
    /// The coefficients for combined shear modulus G \[Pa\] and Poisson
    /// ratio ν (quasi-identical bodies).
    pub fn new(
        along: usize,
        across: usize,
        dx: f64,
        dy: f64,
        shear_modulus: f64,
        poisson_ratio: f64,
    ) -> Self {
        let (nx, ny) = (2 * along + 1, 2 * across - 1);
        let n = nx * ny;
        let scale = 1.0 / (PI * shear_modulus);
        let nu = poisson_ratio;
        let mut out = Self {
            along,
            across,
            normal: vec![0.0; n],
            xx: vec![0.0; n],
            xy: vec![0.0; n],
            yy: vec![0.0; n],
        };
        for a in 0..nx {
            for b in 0..ny {
                let i = a as f64 - along as f64;
                let k = b as f64 - (across as f64 - 1.0);
                // Traction on the cell at offset (i, k) from the field
                // point, i.e. the source at (i dx, k dy) relative to it;
                // the kernels are even, so the sign of the offset is free.
                let c = cell_integrals(i * dx, k * dy, dx, dy);
                let at = a * ny + b;
                out.normal[at] = scale * (1.0 - nu) * c.inverse;
                out.xx[at] = scale * ((1.0 - nu) * c.inverse + nu * c.xx);
                out.yy[at] = scale * ((1.0 - nu) * c.inverse + nu * c.yy);
                out.xy[at] = scale * nu * c.xy;
            }
        }
        out
    }

    /// Index into the tables of the offset (field − source) (`di`, `dk`) in
    /// cells.
    #[inline(always)]
    pub fn index(&self, di: isize, dk: isize) -> usize {
        let a = (di + self.along as isize) as usize;
        let b = (dk + self.across as isize - 1) as usize;
        a * (2 * self.across - 1) + b
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Midpoint-rule integral of a kernel over a cell far from the field
    /// point, where it is smooth.
    fn brute(f: impl Fn(f64, f64) -> f64, x: f64, y: f64, dx: f64, dy: f64) -> f64 {
        let n = 400;
        let mut sum = 0.0;
        for i in 0..n {
            for j in 0..n {
                let px = x - 0.5 * dx + (i as f64 + 0.5) * dx / n as f64;
                let py = y - 0.5 * dy + (j as f64 + 0.5) * dy / n as f64;
                sum += f(px, py);
            }
        }
        sum * dx * dy / (n * n) as f64
    }

    #[test]
    fn cell_integrals_match_quadrature() {
        for &(x, y) in &[
            (3.0, 0.5),
            (-2.0, 1.5),
            (0.7, -4.0),
            (-3.0, -2.0),
            (-3.0, 0.0),
        ] {
            let (dx, dy) = (1.0, 0.6);
            let c = cell_integrals(x, y, dx, dy);
            let r = |a: f64, b: f64| a.hypot(b);
            let want = [
                brute(|a, b| 1.0 / r(a, b), x, y, dx, dy),
                brute(|a, b| a * a / r(a, b).powi(3), x, y, dx, dy),
                brute(|a, b| b * b / r(a, b).powi(3), x, y, dx, dy),
                brute(|a, b| a * b / r(a, b).powi(3), x, y, dx, dy),
            ];
            for (got, want) in [c.inverse, c.xx, c.yy, c.xy].iter().zip(want) {
                assert!(
                    (got - want).abs() < 1e-5 * want.abs().max(1e-3),
                    "{x},{y}: {got} vs {want}"
                );
            }
        }
    }

    /// The self-coefficient of a square cell: ∫∫ 1/ρ over a square of side
    /// 2s about its centre is 8 s ln(1 + √2) (Love 1929).
    #[test]
    fn self_coefficient_of_a_square() {
        let c = cell_integrals(0.0, 0.0, 2.0, 2.0);
        let want = 8.0 * (1.0 + 2f64.sqrt()).ln();
        assert!((c.inverse - want).abs() < 1e-13);
        // By symmetry the two quadratic kernels share it, and xy vanishes.
        assert!((c.xx - c.yy).abs() < 1e-13);
        assert!(c.xy.abs() < 1e-13);
    }
}
