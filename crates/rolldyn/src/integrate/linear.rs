//! Bordered block-diagonal matrices and their factorization (Golub & Van
//! Loan, *Matrix Computations*, 4th ed., §3.2 LU with partial pivoting and
//! §4.5.4 block elimination; the Schur-complement solve of arrow-shaped
//! systems).
//!
//! A system whose states split into `blocks` independent blocks of
//! `block_size` states, each coupled only to a common **border** (for a
//! bearing: each ball to the rings and the cage, MODEL §8), has a Jacobian
//!
//! ```text
//!     ⎡ D₀          U₀ ⎤
//! J = ⎢     ⋱       ⋮  ⎥      Dⱼ = ∂fⱼ/∂yⱼ,  Uⱼ = ∂fⱼ/∂y_B,
//!     ⎢        Dₙ   Uₙ ⎥      Lⱼ = ∂f_B/∂yⱼ, A = ∂f_B/∂y_B.
//!     ⎣ L₀  …  Lₙ   A  ⎦
//! ```
//!
//! [`BlockLu`] factors M = σI − J (σ = 1/(hγ) in a Rosenbrock step) block
//! by block: LU of each σI − Dⱼ, Wⱼ = (σI − Dⱼ)⁻¹ Uⱼ, and the Schur
//! complement S = σI − A − Σ Lⱼ Wⱼ of the border. Cost: n·(b³ + b²m + bm²)
//! instead of (nb + m)³ for n blocks of b states and a border of m. A
//! system without blocks (`blocks = 0`) is an ordinary dense LU. Nothing
//! allocates after construction.

use std::fmt;

/// Shape of a bordered block-diagonal matrix: `blocks` diagonal blocks of
/// `block_size` states first, then `border` states.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BlockLayout {
    /// Number of diagonal blocks.
    pub blocks: usize,
    /// States per block.
    pub block_size: usize,
    /// Border states (after the blocks).
    pub border: usize,
}

impl BlockLayout {
    /// A dense matrix of dimension n (no blocks, all border).
    pub fn dense(n: usize) -> Self {
        Self {
            blocks: 0,
            block_size: 0,
            border: n,
        }
    }

    /// Total dimension.
    pub fn dimension(&self) -> usize {
        self.blocks * self.block_size + self.border
    }

    /// First border state.
    pub fn border_start(&self) -> usize {
        self.blocks * self.block_size
    }
}

/// The matrix is singular (a zero pivot) to working precision.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Singular;

impl fmt::Display for Singular {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("singular iteration matrix")
    }
}

/// A Jacobian with bordered block-diagonal structure, stored by blocks
/// (row-major each).
#[derive(Debug, Clone)]
pub struct BlockJacobian {
    layout: BlockLayout,
    /// Dⱼ, `blocks` × b × b.
    pub(crate) diag: Vec<f64>,
    /// Uⱼ, `blocks` × b × m.
    pub(crate) upper: Vec<f64>,
    /// Lⱼ, `blocks` × m × b.
    pub(crate) lower: Vec<f64>,
    /// A, m × m.
    pub(crate) border: Vec<f64>,
}

impl BlockJacobian {
    /// A zero matrix of the given shape.
    pub fn zeros(layout: BlockLayout) -> Self {
        let (n, b, m) = (layout.blocks, layout.block_size, layout.border);
        Self {
            layout,
            diag: vec![0.0; n * b * b],
            upper: vec![0.0; n * b * m],
            lower: vec![0.0; n * m * b],
            border: vec![0.0; m * m],
        }
    }

    /// Its shape.
    pub fn layout(&self) -> BlockLayout {
        self.layout
    }

    /// Entry (row, col) of the full matrix (zero outside the structure).
    pub fn get(&self, row: usize, col: usize) -> f64 {
        let (b, m, s) = (
            self.layout.block_size,
            self.layout.border,
            self.layout.border_start(),
        );
        match (row < s, col < s) {
            (true, true) if row / b == col / b => {
                self.diag[(row / b) * b * b + (row % b) * b + col % b]
            }
            (true, true) => 0.0,
            (true, false) => self.upper[(row / b) * b * m + (row % b) * m + (col - s)],
            (false, true) => self.lower[(col / b) * m * b + (row - s) * b + col % b],
            (false, false) => self.border[(row - s) * m + (col - s)],
        }
    }

    /// y ← J x (for tests and diagnostics).
    pub fn multiply(&self, x: &[f64], y: &mut [f64]) {
        let n = self.layout.dimension();
        for (i, yi) in y.iter_mut().enumerate().take(n) {
            *yi = (0..n).map(|j| self.get(i, j) * x[j]).sum();
        }
    }
}

/// LU factorization of σI − J for a [`BlockJacobian`] J.
#[derive(Debug, Clone)]
pub struct BlockLu {
    layout: BlockLayout,
    /// LU of σI − Dⱼ, `blocks` × b × b, and pivots.
    diag: Vec<f64>,
    diag_pivots: Vec<usize>,
    /// Wⱼ = (σI − Dⱼ)⁻¹ (−Uⱼ), `blocks` × b × m.
    coupled: Vec<f64>,
    /// −Lⱼ, `blocks` × m × b (copied so the Jacobian may change).
    lower: Vec<f64>,
    /// LU of the Schur complement, m × m, and pivots.
    schur: Vec<f64>,
    schur_pivots: Vec<usize>,
}

impl BlockLu {
    /// Work space for matrices of this shape.
    pub fn new(layout: BlockLayout) -> Self {
        let (n, b, m) = (layout.blocks, layout.block_size, layout.border);
        Self {
            layout,
            diag: vec![0.0; n * b * b],
            diag_pivots: vec![0; n * b],
            coupled: vec![0.0; n * b * m],
            lower: vec![0.0; n * m * b],
            schur: vec![0.0; m * m],
            schur_pivots: vec![0; m],
        }
    }

    /// Factors σI − J.
    pub fn factor(&mut self, jacobian: &BlockJacobian, sigma: f64) -> Result<(), Singular> {
        let l = self.layout;
        assert_eq!(
            l, jacobian.layout,
            "factorization and Jacobian shapes differ"
        );
        let (b, m) = (l.block_size, l.border);
        for (s, a) in self.schur.iter_mut().zip(&jacobian.border) {
            *s = -a;
        }
        for i in 0..m {
            self.schur[i * m + i] += sigma;
        }
        for j in 0..l.blocks {
            let d = &mut self.diag[j * b * b..(j + 1) * b * b];
            for (x, a) in d.iter_mut().zip(&jacobian.diag[j * b * b..(j + 1) * b * b]) {
                *x = -a;
            }
            for i in 0..b {
                d[i * b + i] += sigma;
            }
            let piv = &mut self.diag_pivots[j * b..(j + 1) * b];
            lu_factor(d, b, piv)?;
            let w = &mut self.coupled[j * b * m..(j + 1) * b * m];
            for (x, u) in w
                .iter_mut()
                .zip(&jacobian.upper[j * b * m..(j + 1) * b * m])
            {
                *x = -u;
            }
            lu_solve_rows(d, b, piv, w, m);
            let lower = &mut self.lower[j * m * b..(j + 1) * m * b];
            for (x, v) in lower
                .iter_mut()
                .zip(&jacobian.lower[j * m * b..(j + 1) * m * b])
            {
                *x = -v;
            }
            // S −= (−Lⱼ) Wⱼ
            for r in 0..m {
                let srow = &mut self.schur[r * m..(r + 1) * m];
                for k in 0..b {
                    let coefficient = lower[r * b + k];
                    if coefficient != 0.0 {
                        for (s, wk) in srow.iter_mut().zip(&w[k * m..(k + 1) * m]) {
                            *s -= coefficient * wk;
                        }
                    }
                }
            }
        }
        lu_factor(&mut self.schur, m, &mut self.schur_pivots)
    }

    /// Solves (σI − J) x = r in place (`x` holds r on entry).
    pub fn solve(&self, x: &mut [f64]) {
        let l = self.layout;
        let (b, m, s) = (l.block_size, l.border, l.border_start());
        let (blocks, border) = x.split_at_mut(s);
        // zⱼ = (σI − Dⱼ)⁻¹ rⱼ; r_B −= Σ (−Lⱼ) zⱼ.
        for j in 0..l.blocks {
            let z = &mut blocks[j * b..(j + 1) * b];
            lu_solve(
                &self.diag[j * b * b..(j + 1) * b * b],
                b,
                &self.diag_pivots[j * b..(j + 1) * b],
                z,
            );
            let lower = &self.lower[j * m * b..(j + 1) * m * b];
            for (r, xb) in border.iter_mut().enumerate() {
                let row = &lower[r * b..(r + 1) * b];
                *xb -= row.iter().zip(z.iter()).map(|(a, z)| a * z).sum::<f64>();
            }
        }
        lu_solve(&self.schur, m, &self.schur_pivots, border);
        // xⱼ = zⱼ − Wⱼ x_B.
        for j in 0..l.blocks {
            let w = &self.coupled[j * b * m..(j + 1) * b * m];
            for (k, xk) in blocks[j * b..(j + 1) * b].iter_mut().enumerate() {
                *xk -= w[k * m..(k + 1) * m]
                    .iter()
                    .zip(border.iter())
                    .map(|(a, x)| a * x)
                    .sum::<f64>();
            }
        }
    }
}

/// In-place LU with partial pivoting of the row-major n × n matrix `a`.
fn lu_factor(a: &mut [f64], n: usize, pivots: &mut [usize]) -> Result<(), Singular> {
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
fn lu_solve(lu: &[f64], n: usize, pivots: &[usize], x: &mut [f64]) {
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
fn lu_solve_rows(lu: &[f64], n: usize, pivots: &[usize], x: &mut [f64], w: usize) {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A deterministic pseudo-random bordered matrix.
    fn sample(layout: BlockLayout) -> BlockJacobian {
        let mut j = BlockJacobian::zeros(layout);
        let mut state = 12345u64;
        let mut next = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 11) as f64 / (1u64 << 53) as f64) - 0.5
        };
        for v in j
            .diag
            .iter_mut()
            .chain(j.upper.iter_mut())
            .chain(j.lower.iter_mut())
            .chain(j.border.iter_mut())
        {
            *v = next();
        }
        j
    }

    fn residual(layout: BlockLayout, sigma: f64) -> f64 {
        let jac = sample(layout);
        let n = layout.dimension();
        let rhs: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin()).collect();
        let mut lu = BlockLu::new(layout);
        lu.factor(&jac, sigma).unwrap();
        let mut x = rhs.clone();
        lu.solve(&mut x);
        let mut jx = vec![0.0; n];
        jac.multiply(&x, &mut jx);
        (0..n)
            .map(|i| (sigma * x[i] - jx[i] - rhs[i]).abs())
            .fold(0.0, f64::max)
    }

    #[test]
    fn block_solve_matches_the_full_system() {
        // (σI − J) x = r to round-off, for bordered and dense shapes, with σ
        // small enough that pivoting matters.
        for layout in [
            BlockLayout {
                blocks: 5,
                block_size: 4,
                border: 3,
            },
            BlockLayout {
                blocks: 3,
                block_size: 9,
                border: 22,
            },
            BlockLayout::dense(7),
        ] {
            for sigma in [0.01, 1.0, 100.0] {
                let r = residual(layout, sigma);
                assert!(r < 1e-10, "{layout:?} σ {sigma}: residual {r:e}");
            }
        }
    }

    #[test]
    fn singular_matrix_is_reported() {
        let layout = BlockLayout::dense(2);
        let mut jac = BlockJacobian::zeros(layout);
        jac.border.copy_from_slice(&[1.0, 1.0, 1.0, 1.0]);
        // σ = 1: σI − J = [[0, −1], [−1, 0]] is regular (needs a row swap);
        // σ = 2 gives [[1, −1], [−1, 1]], singular.
        let mut lu = BlockLu::new(layout);
        assert!(lu.factor(&jac, 1.0).is_ok());
        assert_eq!(lu.factor(&jac, 2.0), Err(Singular));
    }
}
