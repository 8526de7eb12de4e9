//! The dense pieces of the block factorization: LU with partial pivoting
//! of the small blocks and the Schur complement (Golub & Van Loan,
//! *Matrix Computations*, 4th ed., §3.2), in constant-size copies for the
//! common sizes, and the gathers of the kept states.

use super::Singular;

/// Σ aᵢ bᵢ in order.
#[inline(always)]
pub(super) fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(a, b)| a * b).sum()
}

/// Positions of states within a block or within the border, in
/// increasing order. Usually they are consecutive (a free ball's nine
/// states, or its six velocities; the border before its energy
/// accumulators): the gathers are then plain copies, which the compiler
/// vectorizes, instead of indexed loads (the same values either way).
#[derive(Debug, Clone)]
pub(super) struct Active {
    positions: Vec<usize>,
    /// The first position, when they are consecutive.
    run: Option<usize>,
}

impl Active {
    pub(super) fn new(positions: Vec<usize>) -> Self {
        let consecutive = positions.windows(2).all(|w| w[1] == w[0] + 1);
        let run = consecutive.then(|| positions.first().copied().unwrap_or(0));
        Self { positions, run }
    }

    pub(super) fn len(&self) -> usize {
        self.positions.len()
    }

    pub(super) fn iter(&self) -> std::slice::Iter<'_, usize> {
        self.positions.iter()
    }

    /// `to[k] = −from[pₖ]`.
    #[inline(always)]
    pub(super) fn gather_negated(&self, to: &mut [f64], from: &[f64]) {
        if let Some(first) = self.run {
            let from = &from[first..first + to.len()];
            for (t, f) in to.iter_mut().zip(from) {
                *t = -f;
            }
        } else {
            for (t, &p) in to.iter_mut().zip(&self.positions) {
                *t = -from[p];
            }
        }
    }

    /// `to[k] = from[pₖ]`.
    #[inline(always)]
    pub(super) fn gather(&self, to: &mut [f64], from: &[f64]) {
        if let Some(first) = self.run {
            to.copy_from_slice(&from[first..first + to.len()]);
        } else {
            for (t, &p) in to.iter_mut().zip(&self.positions) {
                *t = from[p];
            }
        }
    }

    /// `to[pₖ] = from[k]`.
    #[inline(always)]
    pub(super) fn scatter(&self, from: &[f64], to: &mut [f64]) {
        if let Some(first) = self.run {
            to[first..first + from.len()].copy_from_slice(from);
        } else {
            for (f, &p) in from.iter().zip(&self.positions) {
                to[p] = *f;
            }
        }
    }
}

/// In-place LU with partial pivoting of the row-major n × n matrix `a`.
///
/// The small sizes of the ball blocks and borders (2 to 12 kept states)
/// get their own copies, compiled for a constant n (unrolled, without
/// bounds checks); each runs the same operations in the same order as the
/// general one, so the results are bit-identical.
pub(super) fn lu_factor(a: &mut [f64], n: usize, pivots: &mut [usize]) -> Result<(), Singular> {
    match n {
        2 => lu_factor_n(a, 2, pivots),
        3 => lu_factor_n(a, 3, pivots),
        4 => lu_factor_n(a, 4, pivots),
        5 => lu_factor_n(a, 5, pivots),
        6 => lu_factor_n(a, 6, pivots),
        7 => lu_factor_n(a, 7, pivots),
        8 => lu_factor_n(a, 8, pivots),
        9 => lu_factor_n(a, 9, pivots),
        10 => lu_factor_n(a, 10, pivots),
        11 => lu_factor_n(a, 11, pivots),
        12 => lu_factor_n(a, 12, pivots),
        _ => lu_factor_n(a, n, pivots),
    }
}

/// [`lu_factor`]'s body, inlined into each size.
#[inline(always)]
fn lu_factor_n(a: &mut [f64], n: usize, pivots: &mut [usize]) -> Result<(), Singular> {
    for k in 0..n {
        let (p, max) = (k..n)
            .map(|i| (i, a[i * n + k].abs()))
            .fold((k, -1.0), |best, c| if c.1 > best.1 { c } else { best });
        if max == 0.0 || !max.is_finite() {
            return Err(Singular);
        }
        pivots[k] = p;
        if p != k {
            for c in 0..n {
                a.swap(k * n + c, p * n + c);
            }
        }
        let pivot = a[k * n + k];
        for i in k + 1..n {
            let factor = a[i * n + k] / pivot;
            a[i * n + k] = factor;
            if factor != 0.0 {
                for c in k + 1..n {
                    a[i * n + c] -= factor * a[k * n + c];
                }
            }
        }
    }
    Ok(())
}

/// Solves with an LU from [`lu_factor`]; `x` holds the right-hand side.
/// Small sizes get constant-n copies, as [`lu_factor`].
pub(super) fn lu_solve(lu: &[f64], n: usize, pivots: &[usize], x: &mut [f64]) {
    match n {
        2 => lu_solve_n(lu, 2, pivots, x),
        3 => lu_solve_n(lu, 3, pivots, x),
        4 => lu_solve_n(lu, 4, pivots, x),
        5 => lu_solve_n(lu, 5, pivots, x),
        6 => lu_solve_n(lu, 6, pivots, x),
        7 => lu_solve_n(lu, 7, pivots, x),
        8 => lu_solve_n(lu, 8, pivots, x),
        9 => lu_solve_n(lu, 9, pivots, x),
        10 => lu_solve_n(lu, 10, pivots, x),
        11 => lu_solve_n(lu, 11, pivots, x),
        12 => lu_solve_n(lu, 12, pivots, x),
        _ => lu_solve_n(lu, n, pivots, x),
    }
}

/// [`lu_solve`]'s body, inlined into each size.
#[inline(always)]
fn lu_solve_n(lu: &[f64], n: usize, pivots: &[usize], x: &mut [f64]) {
    for (k, &p) in pivots.iter().enumerate().take(n) {
        x.swap(k, p);
    }
    for i in 1..n {
        let s: f64 = (0..i).map(|c| lu[i * n + c] * x[c]).sum();
        x[i] -= s;
    }
    for i in (0..n).rev() {
        let s: f64 = (i + 1..n).map(|c| lu[i * n + c] * x[c]).sum();
        x[i] = (x[i] - s) / lu[i * n + i];
    }
}

/// Solves for a row-major n × w right-hand side matrix `x` at once.
pub(super) fn lu_solve_rows(lu: &[f64], n: usize, pivots: &[usize], x: &mut [f64], w: usize) {
    for (k, &p) in pivots.iter().enumerate().take(n) {
        if p != k {
            for c in 0..w {
                x.swap(k * w + c, p * w + c);
            }
        }
    }
    for i in 1..n {
        let (done, rest) = x.split_at_mut(i * w);
        let row = &mut rest[..w];
        for c in 0..i {
            let f = lu[i * n + c];
            if f != 0.0 {
                for (r, d) in row.iter_mut().zip(&done[c * w..(c + 1) * w]) {
                    *r -= f * d;
                }
            }
        }
    }
    for i in (0..n).rev() {
        let (head, tail) = x.split_at_mut((i + 1) * w);
        let row = &mut head[i * w..];
        for c in i + 1..n {
            let f = lu[i * n + c];
            if f != 0.0 {
                for (r, d) in row.iter_mut().zip(&tail[(c - i - 1) * w..(c - i) * w]) {
                    *r -= f * d;
                }
            }
        }
        let inv = 1.0 / lu[i * n + i];
        row.iter_mut().for_each(|r| *r *= inv);
    }
}
