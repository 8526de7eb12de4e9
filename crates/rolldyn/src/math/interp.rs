//! Monotone piecewise-cubic Hermite interpolation on a uniform grid
//! (F. N. Fritsch & R. E. Carlson, "Monotone piecewise cubic
//! interpolation", SIAM J. Numer. Anal. 17 (1980) 238–246; the derivative
//! rule is the weighted harmonic mean of Fritsch & Butland 1984, as in
//! SciPy's `PchipInterpolator`). Monotone data stay monotone, with no
//! overshoot, and smooth data are reproduced to O(h⁴) away from extrema.
//!
//! Evaluation is allocation-free and O(1) (uniform grid: the cell index is
//! computed, not searched), which is what the time loop needs.

/// A monotone cubic interpolant of samples y_i at x_i = x0 + i h.
#[derive(Debug, Clone, PartialEq)]
pub struct UniformPchip {
    x0: f64,
    h: f64,
    y: Vec<f64>,
    slope: Vec<f64>,
}

impl UniformPchip {
    /// Builds the interpolant. Needs at least two samples and h > 0.
    pub fn new(x0: f64, h: f64, y: Vec<f64>) -> Self {
        let n = y.len();
        assert!(
            n >= 2 && h > 0.0,
            "UniformPchip needs ≥ 2 samples and h > 0"
        );
        let delta: Vec<f64> = y.windows(2).map(|w| (w[1] - w[0]) / h).collect();
        let mut slope = vec![0.0; n];
        for i in 1..n - 1 {
            let (d0, d1) = (delta[i - 1], delta[i]);
            slope[i] = if d0 * d1 <= 0.0 {
                0.0
            } else {
                // Equal spacing: weights 3h, 3h → harmonic mean 2/(1/d0 + 1/d1).
                2.0 / (1.0 / d0 + 1.0 / d1)
            };
        }
        slope[0] = end_slope(delta[0], delta.get(1).copied().unwrap_or(delta[0]));
        slope[n - 1] = end_slope(
            delta[n - 2],
            if n >= 3 { delta[n - 3] } else { delta[n - 2] },
        );
        Self { x0, h, y, slope }
    }

    /// Interpolated value and its derivative d/dx at x; outside the grid
    /// the value is clamped to the ends and the derivative is zero.
    #[inline]
    pub fn eval_with_derivative(&self, x: f64) -> (f64, f64) {
        let last = self.y.len() - 1;
        let raw = (x - self.x0) / self.h;
        let s = raw.clamp(0.0, last as f64);
        let i = (s as usize).min(last - 1);
        let t = s - i as f64;
        let (y0, y1) = (self.y[i], self.y[i + 1]);
        let (m0, m1) = (self.slope[i] * self.h, self.slope[i + 1] * self.h);
        let t2 = t * t;
        let t3 = t2 * t;
        let value = (2.0 * t3 - 3.0 * t2 + 1.0) * y0
            + (t3 - 2.0 * t2 + t) * m0
            + (-2.0 * t3 + 3.0 * t2) * y1
            + (t3 - t2) * m1;
        let dvalue_dt = (6.0 * t2 - 6.0 * t) * (y0 - y1)
            + (3.0 * t2 - 4.0 * t + 1.0) * m0
            + (3.0 * t2 - 2.0 * t) * m1;
        let inside = (0.0..=last as f64).contains(&raw);
        (value, if inside { dvalue_dt / self.h } else { 0.0 })
    }

    /// Interpolated value at x; x outside the grid is clamped to its ends.
    #[inline]
    pub fn eval(&self, x: f64) -> f64 {
        self.eval_in(&self.locate(x))
    }

    /// The cell of x (clamped to the grid) and its Hermite basis, which
    /// every interpolant on the same grid (same x0, h and length) shares:
    /// locate once, then [`Self::eval_in`] each of them.
    #[inline]
    pub fn locate(&self, x: f64) -> GridCell {
        let last = self.y.len() - 1;
        let s = ((x - self.x0) / self.h).clamp(0.0, last as f64);
        let index = (s as usize).min(last - 1);
        GridCell::at(index, s - index as f64)
    }

    /// The value in a cell from [`Self::locate`] of an interpolant on the
    /// same grid; the same arithmetic as [`Self::eval`].
    #[inline]
    pub fn eval_in(&self, cell: &GridCell) -> f64 {
        let i = cell.index;
        let (y0, y1) = (self.y[i], self.y[i + 1]);
        let (m0, m1) = (self.slope[i] * self.h, self.slope[i + 1] * self.h);
        cell.combine(y0, m0, y1, m1)
    }

    /// Node i's value y_i and slope times the spacing, m_i h (what
    /// [`GridCell::combine`] takes).
    pub fn node(&self, i: usize) -> (f64, f64) {
        (self.y[i], self.slope[i] * self.h)
    }
}

/// A point's cell on a uniform grid and its cubic Hermite basis
/// (h₀₀, h₁₀, h₀₁, h₁₁ at the cell's local coordinate).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridCell {
    index: usize,
    basis: [f64; 4],
}

impl GridCell {
    /// Cell `index` at local coordinate t ∈ [0, 1].
    #[inline]
    fn at(index: usize, t: f64) -> Self {
        let t2 = t * t;
        let t3 = t2 * t;
        GridCell {
            index,
            basis: [
                2.0 * t3 - 3.0 * t2 + 1.0,
                t3 - 2.0 * t2 + t,
                -2.0 * t3 + 3.0 * t2,
                t3 - t2,
            ],
        }
    }

    /// The cell's left node.
    #[inline]
    pub fn index(&self) -> usize {
        self.index
    }

    /// The cubic through the cell's left and right nodes (values y₀, y₁,
    /// slopes times the spacing m₀, m₁) at the located point.
    #[inline]
    pub fn combine(&self, y0: f64, m0: f64, y1: f64, m1: f64) -> f64 {
        let [b0, b1, b2, b3] = self.basis;
        b0 * y0 + b1 * m0 + b2 * y1 + b3 * m1
    }
}

/// A C¹ interpolant of samples z_ij at (x0 + i h, y_j), on rows that share
/// one uniform y grid: along y each row is a [`UniformPchip`] (monotone),
/// across the rows a cubic Hermite whose node slopes are the central
/// differences of the rows' values at y (Catmull–Rom; one-sided at the
/// ends). O(1) and allocation-free; outside the grid the point is clamped
/// to it.
#[derive(Debug, Clone, PartialEq)]
pub struct UniformPchipRows {
    x0: f64,
    h: f64,
    rows: Vec<UniformPchip>,
}

impl UniformPchipRows {
    /// Rows at x0 + i h, each over the same y grid. Needs two rows, h > 0.
    pub fn new(x0: f64, h: f64, rows: Vec<UniformPchip>) -> Self {
        assert!(
            rows.len() >= 2 && h > 0.0,
            "UniformPchipRows needs ≥ 2 rows and h > 0"
        );
        let grid = |r: &UniformPchip| (r.x0, r.h, r.y.len());
        assert!(
            rows.iter().all(|r| grid(r) == grid(&rows[0])),
            "UniformPchipRows needs rows on one y grid"
        );
        Self { x0, h, rows }
    }

    /// Interpolated value at (x, y).
    #[inline]
    pub fn eval(&self, x: f64, y: f64) -> f64 {
        let last = self.rows.len() - 1;
        let along = self.rows[0].locate(y);
        let at = |i: usize| self.rows[i].eval_in(&along);
        let s = ((x - self.x0) / self.h).clamp(0.0, last as f64);
        let i = (s as usize).min(last - 1);
        let (z0, z1) = (at(i), at(i + 1));
        let before = if i > 0 { at(i - 1) } else { 2.0 * z0 - z1 };
        let after = if i + 1 < last {
            at(i + 2)
        } else {
            2.0 * z1 - z0
        };
        GridCell::at(i, s - i as f64).combine(z0, 0.5 * (z1 - before), z1, 0.5 * (after - z0))
    }
}

/// One-sided three-point end slope with the PCHIP shape safeguards.
fn end_slope(d0: f64, d1: f64) -> f64 {
    let s = (3.0 * d0 - d1) / 2.0;
    if s.signum() != d0.signum() {
        0.0
    } else if d0.signum() != d1.signum() && s.abs() > 3.0 * d0.abs() {
        3.0 * d0
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproduces_nodes_and_is_monotone() {
        let y: Vec<f64> = (0..11).map(|i| (i as f64 * 0.1).powi(3)).collect();
        let p = UniformPchip::new(0.0, 0.1, y.clone());
        for (i, yi) in y.iter().enumerate() {
            assert!((p.eval(i as f64 * 0.1) - yi).abs() < 1e-15);
        }
        let mut prev = p.eval(0.0);
        for k in 1..=1000 {
            let v = p.eval(k as f64 * 1e-3);
            assert!(v >= prev - 1e-15);
            prev = v;
        }
    }

    #[test]
    fn derivative_matches_finite_difference() {
        let p = UniformPchip::new(
            0.0,
            0.05,
            (0..=40).map(|i| (i as f64 * 0.05).sin() + 2.0).collect(),
        );
        for x in [0.013, 0.5, 0.77, 1.234, 1.9] {
            let (v, d) = p.eval_with_derivative(x);
            assert_eq!(v, p.eval(x));
            let h = 1e-7;
            let fd = (p.eval(x + h) - p.eval(x - h)) / (2.0 * h);
            assert!((d - fd).abs() < 1e-6, "x = {x}: {d} vs {fd}");
        }
    }

    #[test]
    fn rows_reproduce_nodes_and_converge_on_smooth_data() {
        let f = |x: f64, y: f64| (2.0 * x).sin() * (0.5 + y).exp();
        let table = |n: usize| {
            let h = 1.0 / n as f64;
            let rows = (0..=n)
                .map(|i| {
                    let y = (0..=n).map(|j| f(i as f64 * h, j as f64 * h)).collect();
                    UniformPchip::new(0.0, h, y)
                })
                .collect();
            UniformPchipRows::new(0.0, h, rows)
        };
        let t = table(16);
        assert!((t.eval(0.25, 0.5) - f(0.25, 0.5)).abs() < 1e-15);
        let err = |n: usize| {
            let t = table(n);
            (0..997)
                .map(|k| {
                    let (x, y) = (0.2 + 0.6 * k as f64 / 997.0, (k as f64 * 0.618).fract());
                    (t.eval(x, y) - f(x, y)).abs()
                })
                .fold(0.0, f64::max)
        };
        // Catmull–Rom across the rows is O(h³).
        let ratio = err(32) / err(64);
        assert!(ratio > 6.0, "ratio {ratio}");
        // C¹ across a row: the one-sided slopes agree at x = 0.5.
        let t = table(8);
        let d = 1e-6;
        let left = (t.eval(0.5, 0.3) - t.eval(0.5 - d, 0.3)) / d;
        let right = (t.eval(0.5 + d, 0.3) - t.eval(0.5, 0.3)) / d;
        assert!((left - right).abs() < 1e-4, "{left} vs {right}");
    }

    #[test]
    fn converges_at_fourth_order_on_smooth_data() {
        let err = |n: usize| {
            let h = 1.0 / n as f64;
            let p = UniformPchip::new(0.0, h, (0..=n).map(|i| (i as f64 * h).exp()).collect());
            (0..997)
                .map(|k| {
                    let x = 0.2 + 0.6 * k as f64 / 997.0;
                    (p.eval(x) - x.exp()).abs()
                })
                .fold(0.0, f64::max)
        };
        let ratio = err(50) / err(100);
        // Interior error of PCHIP on smooth monotone data is O(h^3)..O(h^4).
        assert!(ratio > 7.0, "ratio {ratio}");
    }
}
