//! Bordered block-diagonal matrices and their factorization (Golub & Van
//! Loan, *Matrix Computations*, 4th ed., §3.2 LU with partial pivoting and
//! §4.5.4 block elimination; the Schur-complement solve of arrow-shaped
//! systems).
//!
//! A system whose states split into `blocks` independent blocks of
//! `block_size` states, each coupled only to a common **border** (for a
//! bearing: each ball to the rings and the cage, docs/model.md §8), has a Jacobian
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

use rayon::prelude::*;

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
///
/// States marked **inert** have a zero column in J (nothing reads them, or
/// they never change): row k of σI − J then reads σ x_k − Σ_c J_kc x_c = r_k
/// with c over the other states only, and no other row contains x_k. The
/// factorization leaves them out (a planar 6304 keeps 5 of 9 ball states
/// and 6 of 22 border states) and the solve recovers them afterwards,
/// x_k = (r_k + Σ_c J_kc x_c)/σ. A block state is left out when it is inert
/// in every block.
#[derive(Debug, Clone)]
pub struct BlockLu {
    layout: BlockLayout,
    /// The active states: positions within a block, and within the border.
    block_active: Vec<usize>,
    border_active: Vec<usize>,
    /// The inert ones.
    block_inert: Vec<usize>,
    border_inert: Vec<usize>,
    sigma: f64,
    /// LU of σI − Dⱼ on the active states, `blocks` × b' × b', and pivots.
    diag: Vec<f64>,
    diag_pivots: Vec<usize>,
    /// Wⱼ = (σI − Dⱼ)⁻¹ (−Uⱼ), `blocks` × b' × m'.
    coupled: Vec<f64>,
    /// −Lⱼ, `blocks` × m' × b' (copied so the Jacobian may change).
    lower: Vec<f64>,
    /// LU of the Schur complement, m' × m', and pivots.
    schur: Vec<f64>,
    schur_pivots: Vec<usize>,
    /// Rows of J of the inert block states on the active states: per block
    /// and inert state, b' entries of Dⱼ then m' of Uⱼ.
    inert_block_rows: Vec<f64>,
    /// Rows of J of the inert border states: per inert state, b' entries of
    /// each Lⱼ, then m' of A.
    inert_border_rows: Vec<f64>,
    /// Whether each inert row above (blocks' first, block by block, then
    /// the border's) is zero on the active states: such a state's solution
    /// is rᵢ/σ, without the dot product. Most are (a planar model's frozen
    /// states, angles no force depends on, accumulators of unused powers).
    inert_row_is_zero: Vec<bool>,
    /// Per block: whether Uⱼ (so Wⱼ) has a nonzero entry, and per block and
    /// active border state whether that row of Lⱼ has one. A ball out of
    /// contact with the rings is decoupled from the border (both zero);
    /// a loaded one couples to a few border states. The solve skips the
    /// zero products (their sums are ±0, so the results are unchanged).
    coupled_nonzero: Vec<bool>,
    lower_row_nonzero: Vec<bool>,
    /// A block's and the border's active part of the vector being solved.
    block_work: Vec<f64>,
    border_work: Vec<f64>,
    /// Per block, its share (−Lⱼ) Wⱼ of the Schur complement, m' × m'.
    schur_parts: Vec<f64>,
    /// Whether the factorization runs its blocks across threads.
    parallel: bool,
}

impl BlockLu {
    /// Work space for matrices of this shape, every state active.
    pub fn new(layout: BlockLayout) -> Self {
        Self::with_inert(layout, |_| false)
    }

    /// Work space for matrices of this shape whose columns are zero for
    /// the states `inert` marks (the Jacobian's inert states).
    pub fn with_inert(layout: BlockLayout, inert: impl Fn(usize) -> bool) -> Self {
        let (n, b, m, s) = (
            layout.blocks,
            layout.block_size,
            layout.border,
            layout.border_start(),
        );
        let (block_inert, block_active): (Vec<usize>, Vec<usize>) =
            (0..b).partition(|&k| n > 0 && (0..n).all(|j| inert(j * b + k)));
        let (border_inert, border_active): (Vec<usize>, Vec<usize>) =
            (0..m).partition(|&r| inert(s + r));
        let (ba, ma) = (block_active.len(), border_active.len());
        Self {
            layout,
            sigma: 0.0,
            diag: vec![0.0; n * ba * ba],
            diag_pivots: vec![0; n * ba],
            coupled: vec![0.0; n * ba * ma],
            lower: vec![0.0; n * ma * ba],
            schur: vec![0.0; ma * ma],
            schur_pivots: vec![0; ma],
            inert_block_rows: vec![0.0; n * block_inert.len() * (ba + ma)],
            inert_border_rows: vec![0.0; border_inert.len() * (n * ba + ma)],
            inert_row_is_zero: vec![false; n * block_inert.len() + border_inert.len()],
            coupled_nonzero: vec![true; n],
            lower_row_nonzero: vec![true; n * border_active.len()],
            block_work: vec![0.0; ba],
            border_work: vec![0.0; ma],
            schur_parts: vec![0.0; n * ma * ma],
            parallel: false,
            block_active,
            border_active,
            block_inert,
            border_inert,
        }
    }

    /// Runs the factorization's blocks across the threads of the current
    /// rayon pool (the same factors, bit for bit; the solve stays serial:
    /// at 5–10 µs it is too short to share).
    pub fn set_parallel(&mut self, parallel: bool) {
        self.parallel = parallel;
    }

    /// Factors σI − J (constant-size copies for the common active block
    /// sizes, as [`Self::solve`]; bit-identical).
    pub fn factor(&mut self, jacobian: &BlockJacobian, sigma: f64) -> Result<(), Singular> {
        self.gather(jacobian);
        self.refactor(jacobian, sigma)
    }

    /// Factors σI − J for a new σ, where J is the Jacobian of the last
    /// [`Self::factor`]: the parts of the factorization that do not depend
    /// on σ (the inert states' rows, −Lⱼ, which couplings are zero) are
    /// reused. The same result as [`Self::factor`], bit for bit; a
    /// W-method refactors at every new step size between Jacobians.
    pub fn refactor(&mut self, jacobian: &BlockJacobian, sigma: f64) -> Result<(), Singular> {
        assert_eq!(
            self.layout, jacobian.layout,
            "factorization and Jacobian shapes differ"
        );
        match self.block_active.len() {
            5 => self.refactor_sized(jacobian, sigma, 5),
            9 => self.refactor_sized(jacobian, sigma, 9),
            ba => self.refactor_sized(jacobian, sigma, ba),
        }
    }

    /// The σ-independent parts of the factorization of J: the rows of the
    /// inert states on the active ones, −Lⱼ on the active states, and
    /// which of them, and which Uⱼ, are zero.
    fn gather(&mut self, jacobian: &BlockJacobian) {
        let l = self.layout;
        assert_eq!(
            l, jacobian.layout,
            "factorization and Jacobian shapes differ"
        );
        let (b, m) = (l.block_size, l.border);
        let (ba, ma) = (self.block_active.len(), self.border_active.len());
        let (bi, border_row_len) = (self.block_inert.len(), l.blocks * ba + ma);
        let row_len = ba + ma;
        for (q, &r) in self.border_inert.iter().enumerate() {
            let row = &mut self.inert_border_rows[q * border_row_len..][..border_row_len];
            for j in 0..l.blocks {
                for (k, &c) in self.block_active.iter().enumerate() {
                    row[j * ba + k] = jacobian.lower[j * m * b + r * b + c];
                }
            }
            for (k, &c) in self.border_active.iter().enumerate() {
                row[l.blocks * ba + k] = jacobian.border[r * m + c];
            }
            self.inert_row_is_zero[l.blocks * bi + q] = row.iter().all(|&v| v == 0.0);
        }
        for j in 0..l.blocks {
            let (jd, ju, jl) = (
                &jacobian.diag[j * b * b..(j + 1) * b * b],
                &jacobian.upper[j * b * m..(j + 1) * b * m],
                &jacobian.lower[j * m * b..(j + 1) * m * b],
            );
            for (q, &r) in self.block_inert.iter().enumerate() {
                let row = &mut self.inert_block_rows[(j * bi + q) * row_len..][..row_len];
                for (k, &c) in self.block_active.iter().enumerate() {
                    row[k] = jd[r * b + c];
                }
                for (k, &c) in self.border_active.iter().enumerate() {
                    row[ba + k] = ju[r * m + c];
                }
                self.inert_row_is_zero[j * bi + q] = row.iter().all(|&v| v == 0.0);
            }
            self.coupled_nonzero[j] = self
                .block_active
                .iter()
                .any(|&r| self.border_active.iter().any(|&c| ju[r * m + c] != 0.0));
            let lower = &mut self.lower[j * ma * ba..(j + 1) * ma * ba];
            for (i, &r) in self.border_active.iter().enumerate() {
                for (k, &c) in self.block_active.iter().enumerate() {
                    lower[i * ba + k] = -jl[r * b + c];
                }
                self.lower_row_nonzero[j * ma + i] =
                    lower[i * ba..(i + 1) * ba].iter().any(|&v| v != 0.0);
            }
        }
    }

    /// [`Self::refactor`]'s body for `ba` active block states. Each block's
    /// LU, Wⱼ and share (−Lⱼ) Wⱼ of the Schur complement, across threads
    /// when [`Self::set_parallel`]; the shares are then subtracted in block
    /// order, so the factors do not depend on the threads.
    #[inline(always)]
    fn refactor_sized(
        &mut self,
        jacobian: &BlockJacobian,
        sigma: f64,
        ba: usize,
    ) -> Result<(), Singular> {
        let l = self.layout;
        let (b, m) = (l.block_size, l.border);
        let ma = self.border_active.len();
        self.sigma = sigma;
        for (i, &r) in self.border_active.iter().enumerate() {
            for (k, &c) in self.border_active.iter().enumerate() {
                self.schur[i * ma + k] = -jacobian.border[r * m + c];
            }
            self.schur[i * ma + i] += sigma;
        }
        let (block_active, border_active) = (&self.block_active, &self.border_active);
        let (coupled_nonzero, lower_row_nonzero) = (&self.coupled_nonzero, &self.lower_row_nonzero);
        let lower = &self.lower;
        let factor_block =
            |j: usize, d: &mut [f64], piv: &mut [usize], w: &mut [f64], part: &mut [f64]| {
                let (jd, ju) = (
                    &jacobian.diag[j * b * b..(j + 1) * b * b],
                    &jacobian.upper[j * b * m..(j + 1) * b * m],
                );
                for (i, &r) in block_active.iter().enumerate() {
                    for (k, &c) in block_active.iter().enumerate() {
                        d[i * ba + k] = -jd[r * b + c];
                    }
                    d[i * ba + i] += sigma;
                }
                lu_factor(d, ba, piv)?;
                // A block decoupled from the border (Uⱼ = 0) has Wⱼ = 0 and no
                // share in the Schur complement; the solve skips it.
                if !coupled_nonzero[j] {
                    return Ok(());
                }
                for (i, &r) in block_active.iter().enumerate() {
                    for (k, &c) in border_active.iter().enumerate() {
                        w[i * ma + k] = -ju[r * m + c];
                    }
                }
                lu_solve_rows(d, ba, piv, w, ma);
                // Its share (−Lⱼ) Wⱼ of the Schur complement.
                for r in (0..ma).filter(|&r| lower_row_nonzero[j * ma + r]) {
                    let prow = &mut part[r * ma..(r + 1) * ma];
                    prow.fill(0.0);
                    let lower = &lower[(j * ma + r) * ba..(j * ma + r + 1) * ba];
                    for (k, &coefficient) in lower.iter().enumerate() {
                        if coefficient != 0.0 {
                            for (p, wk) in prow.iter_mut().zip(&w[k * ma..(k + 1) * ma]) {
                                *p += coefficient * wk;
                            }
                        }
                    }
                }
                Ok(())
            };
        if self.parallel && ba > 0 && ma > 0 && l.blocks > 1 {
            self.diag
                .par_chunks_mut(ba * ba)
                .zip(self.diag_pivots.par_chunks_mut(ba))
                .zip(self.coupled.par_chunks_mut(ba * ma))
                .zip(self.schur_parts.par_chunks_mut(ma * ma))
                .enumerate()
                .try_for_each(|(j, (((d, piv), w), part))| factor_block(j, d, piv, w, part))?;
        } else {
            for j in 0..l.blocks {
                factor_block(
                    j,
                    &mut self.diag[j * ba * ba..(j + 1) * ba * ba],
                    &mut self.diag_pivots[j * ba..(j + 1) * ba],
                    &mut self.coupled[j * ba * ma..(j + 1) * ba * ma],
                    &mut self.schur_parts[j * ma * ma..(j + 1) * ma * ma],
                )?;
            }
        }
        // S −= Σⱼ (−Lⱼ) Wⱼ, the blocks in order (the rows where Lⱼ has
        // an entry).
        for j in (0..l.blocks).filter(|&j| coupled_nonzero[j]) {
            let part = &self.schur_parts[j * ma * ma..(j + 1) * ma * ma];
            for r in (0..ma).filter(|&r| lower_row_nonzero[j * ma + r]) {
                let schur_row = &mut self.schur[r * ma..(r + 1) * ma];
                for (s, p) in schur_row.iter_mut().zip(&part[r * ma..(r + 1) * ma]) {
                    *s -= p;
                }
            }
        }
        lu_factor(&mut self.schur, ma, &mut self.schur_pivots)
    }

    /// Solves (σI − J) x = r in place (`x` holds r on entry). The common
    /// sizes of the active ball blocks (5: planar, 9: a free ball) get
    /// their own constant-size copies, as the small dense LU; bit-identical.
    pub fn solve(&mut self, x: &mut [f64]) {
        match self.block_active.len() {
            5 => self.solve_sized(x, 5),
            9 => self.solve_sized(x, 9),
            ba => self.solve_sized(x, ba),
        }
    }

    /// [`Self::solve`]'s body for `ba` active block states.
    #[inline(always)]
    fn solve_sized(&mut self, x: &mut [f64], ba: usize) {
        let l = self.layout;
        let (b, s) = (l.block_size, l.border_start());
        let ma = self.border_active.len();
        let (blocks, border) = x.split_at_mut(s);
        let xb = &mut self.border_work;
        for (v, &r) in xb.iter_mut().zip(&self.border_active) {
            *v = border[r];
        }
        // zⱼ = (σI − Dⱼ)⁻¹ rⱼ (kept in x); r_B −= Σ (−Lⱼ) zⱼ.
        for j in 0..l.blocks {
            let block = &mut blocks[j * b..(j + 1) * b];
            let z = &mut self.block_work;
            for (v, &k) in z.iter_mut().zip(&self.block_active) {
                *v = block[k];
            }
            lu_solve(
                &self.diag[j * ba * ba..(j + 1) * ba * ba],
                ba,
                &self.diag_pivots[j * ba..(j + 1) * ba],
                z,
            );
            for (v, &k) in z.iter().zip(&self.block_active) {
                block[k] = *v;
            }
            let lower = &self.lower[j * ma * ba..(j + 1) * ma * ba];
            let nonzero = &self.lower_row_nonzero[j * ma..(j + 1) * ma];
            for ((r, v), _) in xb
                .iter_mut()
                .enumerate()
                .zip(nonzero)
                .filter(|(_, nz)| **nz)
            {
                let row = &lower[r * ba..(r + 1) * ba];
                *v -= row.iter().zip(z.iter()).map(|(a, z)| a * z).sum::<f64>();
            }
        }
        lu_solve(&self.schur, ma, &self.schur_pivots, xb);
        for (v, &r) in xb.iter().zip(&self.border_active) {
            border[r] = *v;
        }
        // xⱼ = zⱼ − Wⱼ x_B; then the inert states of the block.
        let row_len = ba + ma;
        for j in 0..l.blocks {
            let w = &self.coupled[j * ba * ma..(j + 1) * ba * ma];
            let block = &mut blocks[j * b..(j + 1) * b];
            for (i, &k) in self
                .block_active
                .iter()
                .enumerate()
                .filter(|_| self.coupled_nonzero[j])
            {
                block[k] -= w[i * ma..(i + 1) * ma]
                    .iter()
                    .zip(xb.iter())
                    .map(|(a, x)| a * x)
                    .sum::<f64>();
            }
            for (q, &k) in self.block_inert.iter().enumerate() {
                let index = j * self.block_inert.len() + q;
                if self.inert_row_is_zero[index] {
                    block[k] = (block[k] + 0.0) / self.sigma;
                    continue;
                }
                let row = &self.inert_block_rows[index * row_len..][..row_len];
                let coupled: f64 = row[..ba]
                    .iter()
                    .zip(&self.block_active)
                    .map(|(a, &c)| a * block[c])
                    .sum::<f64>()
                    + row[ba..]
                        .iter()
                        .zip(xb.iter())
                        .map(|(a, x)| a * x)
                        .sum::<f64>();
                block[k] = (block[k] + coupled) / self.sigma;
            }
        }
        // The inert border states.
        let first_border_row = l.blocks * self.block_inert.len();
        for (q, &r) in self.border_inert.iter().enumerate() {
            if self.inert_row_is_zero[first_border_row + q] {
                border[r] = (border[r] + 0.0) / self.sigma;
                continue;
            }
            let row = &self.inert_border_rows[q * (l.blocks * ba + ma)..][..l.blocks * ba + ma];
            let mut coupled = 0.0;
            for j in 0..l.blocks {
                let block = &blocks[j * b..(j + 1) * b];
                coupled += row[j * ba..(j + 1) * ba]
                    .iter()
                    .zip(&self.block_active)
                    .map(|(a, &c)| a * block[c])
                    .sum::<f64>();
            }
            coupled += row[l.blocks * ba..]
                .iter()
                .zip(xb.iter())
                .map(|(a, x)| a * x)
                .sum::<f64>();
            border[r] = (border[r] + coupled) / self.sigma;
        }
    }
}

/// In-place LU with partial pivoting of the row-major n × n matrix `a`.
///
/// The small sizes of the ball blocks and borders (4 to 12 active states)
/// get their own copies, compiled for a constant n (unrolled, without
/// bounds checks); each runs the same operations in the same order as the
/// general one, so the results are bit-identical.
fn lu_factor(a: &mut [f64], n: usize, pivots: &mut [usize]) -> Result<(), Singular> {
    match n {
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
fn lu_solve(lu: &[f64], n: usize, pivots: &[usize], x: &mut [f64]) {
    match n {
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
mod tests;
