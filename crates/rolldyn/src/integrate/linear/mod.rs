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

mod dense;

use dense::{Active, dot, lu_factor, lu_solve, lu_solve_rows};

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
///
/// **Positions** are eliminated too: a state q whose rate is another
/// state v (f_q = y_v, a position and its velocity) has the row e_v in J,
/// so σ x_q − x_v = r_q gives x_q = (r_q + x_v)/σ, and the other rows
/// read Σ_q J_iq x_q = Σ_q J_iq (r_q + x_v)/σ: the column J_iq/σ joins v's
/// column and J_iq r_q/σ the right-hand side. The factorization then works
/// on the velocities alone (the option M1, M2 for y′ᵢ = y_{i+M2}, i ≤ M1,
/// of Hairer & Wanner's RADAU5 and RODAS codes, Hairer & Wanner II): a
/// free ball keeps 6 of its 9 states, the 7008C's border 8 of 16, and a
/// factorization costs about half. The pairs must hold exactly, for every
/// state (checked in debug builds). The positions are recovered before
/// the inert states, whose rows may read them.
#[derive(Debug, Clone)]
pub struct BlockLu {
    layout: BlockLayout,
    /// The active states (not inert): positions within a block, and
    /// within the border.
    block_active: Active,
    border_active: Active,
    /// The inert ones.
    block_inert: Vec<usize>,
    border_inert: Vec<usize>,
    /// Of the active states, those the factorization keeps: all but the
    /// eliminated positions.
    block_kept: Active,
    border_kept: Active,
    /// The eliminated positions: (position q, position of its velocity v,
    /// index of v among the kept states), within a block and the border.
    block_paired: Vec<(usize, usize, usize)>,
    border_paired: Vec<(usize, usize, usize)>,
    sigma: f64,
    /// LU of the kept part of σI − Dⱼ (positions folded in), `blocks` ×
    /// b' × b', and pivots.
    diag: Vec<f64>,
    diag_pivots: Vec<usize>,
    /// Wⱼ = (σI − Dⱼ)⁻¹ (−Uⱼ) on the kept states, `blocks` × b' × m'.
    coupled: Vec<f64>,
    /// −Lⱼ on the kept states, positions folded in, `blocks` × m' × b'.
    lower: Vec<f64>,
    /// LU of the Schur complement, m' × m', and pivots.
    schur: Vec<f64>,
    schur_pivots: Vec<usize>,
    /// Per block: J on its kept states' rows and the eliminated positions'
    /// columns, b' × (e_b + e_B): its own positions', then the border's.
    block_fold: Vec<f64>,
    /// Per block: Lⱼ on the kept border rows and the block's eliminated
    /// positions, m' × e_b.
    lower_fold: Vec<f64>,
    /// A on the kept border rows and the border's eliminated positions,
    /// m' × e_B.
    border_fold: Vec<f64>,
    /// Rows of J of the inert block states on the active states: per block
    /// and inert state, its active block entries, then its active border
    /// entries.
    inert_block_rows: Vec<f64>,
    /// Rows of J of the inert border states: per inert state, each block's
    /// active entries, then the active border entries.
    inert_border_rows: Vec<f64>,
    /// Whether each inert row above (blocks' first, block by block, then
    /// the border's) is zero on the active states: such a state's solution
    /// is rᵢ/σ, without the dot product. Most are (a planar model's frozen
    /// states, angles no force depends on, accumulators of unused powers).
    inert_row_is_zero: Vec<bool>,
    /// Per block: whether its coupling to the kept border (Uⱼ, so Wⱼ) has
    /// a nonzero entry, and per block and kept border state whether that
    /// row of Lⱼ has one. A ball out of contact with the rings is
    /// decoupled from the border (both zero); a loaded one couples to a
    /// few border states. The solve skips the zero products (their sums
    /// are ±0, so the results are unchanged).
    coupled_nonzero: Vec<bool>,
    lower_row_nonzero: Vec<bool>,
    /// A block's and the border's kept part of the vector being solved.
    block_work: Vec<f64>,
    border_work: Vec<f64>,
    /// The active border states' solution, for the inert rows.
    border_active_work: Vec<f64>,
    /// The eliminated positions' right-hand sides over σ: a block's, the
    /// border's.
    block_scaled: Vec<f64>,
    border_scaled: Vec<f64>,
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
        Self::with_structure(layout, inert, |_| None)
    }

    /// Work space for matrices of this shape, with the Jacobian's inert
    /// states and its positions: `rate_of(q) = Some(v)` where f_q = y_v
    /// exactly ([`crate::integrate::BlockSplit::rate_of`]). A block's
    /// position is eliminated when its pair holds in every block, within
    /// the block; the border's within the border; neither when v is inert
    /// or itself a position.
    pub fn with_structure(
        layout: BlockLayout,
        inert: impl Fn(usize) -> bool,
        rate_of: impl Fn(usize) -> Option<usize>,
    ) -> Self {
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
        // A block position's velocity, the same in every block.
        let block_rate = |k: usize| -> Option<usize> {
            let v = rate_of(k).filter(|&v| v < b)?;
            (0..n)
                .all(|j| rate_of(j * b + k) == Some(j * b + v))
                .then_some(v)
        };
        let border_rate = |r: usize| rate_of(s + r)?.checked_sub(s).filter(|&v| v < m);
        let pairs = |active: &[usize], rate: &dyn Fn(usize) -> Option<usize>| {
            active
                .iter()
                .filter_map(|&q| {
                    let v = rate(q)?;
                    (v != q && active.contains(&v) && rate(v).is_none()).then_some((q, v))
                })
                .collect::<Vec<_>>()
        };
        let (block_pairs, border_pairs) = (
            if n > 0 {
                pairs(&block_active, &block_rate)
            } else {
                Vec::new()
            },
            pairs(&border_active, &border_rate),
        );
        let kept = |active: &[usize], pairs: &[(usize, usize)]| -> Vec<usize> {
            active
                .iter()
                .copied()
                .filter(|k| !pairs.iter().any(|(q, _)| q == k))
                .collect()
        };
        let (block_kept, border_kept) = (
            kept(&block_active, &block_pairs),
            kept(&border_active, &border_pairs),
        );
        let indexed = |pairs: Vec<(usize, usize)>, kept: &[usize]| -> Vec<(usize, usize, usize)> {
            pairs
                .into_iter()
                .map(|(q, v)| (q, v, kept.iter().position(|&k| k == v).unwrap_or(0)))
                .collect()
        };
        let (block_paired, border_paired) = (
            indexed(block_pairs, &block_kept),
            indexed(border_pairs, &border_kept),
        );
        let (ba, ma) = (block_active.len(), border_active.len());
        let (bk, mk) = (block_kept.len(), border_kept.len());
        let (be, me) = (block_paired.len(), border_paired.len());
        Self {
            layout,
            sigma: 0.0,
            diag: vec![0.0; n * bk * bk],
            diag_pivots: vec![0; n * bk],
            coupled: vec![0.0; n * bk * mk],
            lower: vec![0.0; n * mk * bk],
            schur: vec![0.0; mk * mk],
            schur_pivots: vec![0; mk],
            block_fold: vec![0.0; n * bk * (be + me)],
            lower_fold: vec![0.0; n * mk * be],
            border_fold: vec![0.0; mk * me],
            inert_block_rows: vec![0.0; n * block_inert.len() * (ba + ma)],
            inert_border_rows: vec![0.0; border_inert.len() * (n * ba + ma)],
            inert_row_is_zero: vec![false; n * block_inert.len() + border_inert.len()],
            coupled_nonzero: vec![true; n],
            lower_row_nonzero: vec![true; n * mk],
            block_work: vec![0.0; bk],
            border_work: vec![0.0; mk],
            border_active_work: vec![0.0; ma],
            block_scaled: vec![0.0; be],
            border_scaled: vec![0.0; me],
            schur_parts: vec![0.0; n * mk * mk],
            parallel: false,
            block_active: Active::new(block_active),
            border_active: Active::new(border_active),
            block_kept: Active::new(block_kept),
            border_kept: Active::new(border_kept),
            block_paired,
            border_paired,
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

    /// States per block, and of the border, that the factorization keeps
    /// (neither inert nor an eliminated position).
    pub fn kept_states(&self) -> (usize, usize) {
        (self.block_kept.len(), self.border_kept.len())
    }

    /// Factors σI − J (constant-size copies for the common kept block
    /// sizes, as [`Self::solve`]; bit-identical).
    pub fn factor(&mut self, jacobian: &BlockJacobian, sigma: f64) -> Result<(), Singular> {
        self.gather(jacobian);
        self.refactor(jacobian, sigma)
    }

    /// Factors σI − J for a new σ, where J is the Jacobian of the last
    /// [`Self::factor`]: the parts of the factorization that do not depend
    /// on σ (the inert states' rows, the positions' columns, which
    /// couplings are zero) are reused. The same result as [`Self::factor`],
    /// bit for bit; a W-method refactors at every new step size between
    /// Jacobians.
    pub fn refactor(&mut self, jacobian: &BlockJacobian, sigma: f64) -> Result<(), Singular> {
        assert_eq!(
            self.layout, jacobian.layout,
            "factorization and Jacobian shapes differ"
        );
        match self.block_kept.len() {
            3 => self.refactor_sized(jacobian, sigma, 3),
            5 => self.refactor_sized(jacobian, sigma, 5),
            6 => self.refactor_sized(jacobian, sigma, 6),
            9 => self.refactor_sized(jacobian, sigma, 9),
            bk => self.refactor_sized(jacobian, sigma, bk),
        }
    }

    /// Whether every eliminated position's row of J is the unit row of its
    /// velocity.
    fn pairs_hold(&self, jacobian: &BlockJacobian) -> bool {
        let l = self.layout;
        let (b, m) = (l.block_size, l.border);
        let unit = |row: &[f64], v: usize| {
            row.iter()
                .enumerate()
                .all(|(c, &x)| x == if c == v { 1.0 } else { 0.0 })
        };
        let zero = |row: &[f64]| row.iter().all(|&x| x == 0.0);
        let blocks = (0..l.blocks).all(|j| {
            self.block_paired.iter().all(|&(q, v, _)| {
                unit(&jacobian.diag[j * b * b + q * b..][..b], v)
                    && zero(&jacobian.upper[j * b * m + q * m..][..m])
            })
        });
        let border = self.border_paired.iter().all(|&(q, v, _)| {
            unit(&jacobian.border[q * m..][..m], v)
                && (0..l.blocks).all(|j| zero(&jacobian.lower[j * m * b + q * b..][..b]))
        });
        blocks && border
    }

    /// The σ-independent parts of the factorization of J: the rows of the
    /// inert states on the active ones, the eliminated positions' columns
    /// on the kept rows, and which couplings are zero.
    fn gather(&mut self, jacobian: &BlockJacobian) {
        let l = self.layout;
        assert_eq!(
            l, jacobian.layout,
            "factorization and Jacobian shapes differ"
        );
        debug_assert!(
            self.pairs_hold(jacobian),
            "a position's row of the Jacobian is not its velocity's unit row"
        );
        let (b, m) = (l.block_size, l.border);
        let (ba, ma) = (self.block_active.len(), self.border_active.len());
        let (bk, mk) = (self.block_kept.len(), self.border_kept.len());
        let (be, me) = (self.block_paired.len(), self.border_paired.len());
        let bf = be + me;
        let (bi, border_row_len) = (self.block_inert.len(), l.blocks * ba + ma);
        let row_len = ba + ma;
        for (q, &r) in self.border_inert.iter().enumerate() {
            let row = &mut self.inert_border_rows[q * border_row_len..][..border_row_len];
            for j in 0..l.blocks {
                self.block_active.gather(
                    &mut row[j * ba..(j + 1) * ba],
                    &jacobian.lower[j * m * b + r * b..][..b],
                );
            }
            self.border_active
                .gather(&mut row[l.blocks * ba..], &jacobian.border[r * m..][..m]);
            self.inert_row_is_zero[l.blocks * bi + q] = row.iter().all(|&v| v == 0.0);
        }
        for (i, &r) in self.border_kept.iter().enumerate() {
            for (e, &(q, _, _)) in self.border_paired.iter().enumerate() {
                self.border_fold[i * me + e] = jacobian.border[r * m + q];
            }
        }
        for j in 0..l.blocks {
            let (jd, ju, jl) = (
                &jacobian.diag[j * b * b..(j + 1) * b * b],
                &jacobian.upper[j * b * m..(j + 1) * b * m],
                &jacobian.lower[j * m * b..(j + 1) * m * b],
            );
            for (q, &r) in self.block_inert.iter().enumerate() {
                let row = &mut self.inert_block_rows[(j * bi + q) * row_len..][..row_len];
                self.block_active.gather(&mut row[..ba], &jd[r * b..][..b]);
                self.border_active.gather(&mut row[ba..], &ju[r * m..][..m]);
                self.inert_row_is_zero[j * bi + q] = row.iter().all(|&v| v == 0.0);
            }
            let fold = &mut self.block_fold[j * bk * bf..(j + 1) * bk * bf];
            for (i, &r) in self.block_kept.iter().enumerate() {
                let row = &mut fold[i * bf..(i + 1) * bf];
                for (e, &(q, _, _)) in self.block_paired.iter().enumerate() {
                    row[e] = jd[r * b + q];
                }
                for (e, &(q, _, _)) in self.border_paired.iter().enumerate() {
                    row[be + e] = ju[r * m + q];
                }
            }
            self.coupled_nonzero[j] = self.block_kept.iter().enumerate().any(|(i, &r)| {
                self.border_kept.iter().any(|&c| ju[r * m + c] != 0.0)
                    || fold[i * bf + be..(i + 1) * bf].iter().any(|&v| v != 0.0)
            });
            let lower_fold = &mut self.lower_fold[j * mk * be..(j + 1) * mk * be];
            for (i, &r) in self.border_kept.iter().enumerate() {
                let row = &mut lower_fold[i * be..(i + 1) * be];
                for (e, &(q, _, _)) in self.block_paired.iter().enumerate() {
                    row[e] = jl[r * b + q];
                }
                self.lower_row_nonzero[j * mk + i] = row.iter().any(|&v| v != 0.0)
                    || self.block_kept.iter().any(|&c| jl[r * b + c] != 0.0);
            }
        }
    }

    /// [`Self::refactor`]'s body for `bk` kept block states. Each block's
    /// LU, Wⱼ and share (−Lⱼ) Wⱼ of the Schur complement, across threads
    /// when [`Self::set_parallel`]; the shares are then subtracted in block
    /// order, so the factors do not depend on the threads.
    #[inline(always)]
    fn refactor_sized(
        &mut self,
        jacobian: &BlockJacobian,
        sigma: f64,
        bk: usize,
    ) -> Result<(), Singular> {
        let l = self.layout;
        let (b, m) = (l.block_size, l.border);
        let mk = self.border_kept.len();
        let (be, me) = (self.block_paired.len(), self.border_paired.len());
        let bf = be + me;
        let inverse = 1.0 / sigma;
        self.sigma = sigma;
        for (i, &r) in self.border_kept.iter().enumerate() {
            let row = &mut self.schur[i * mk..(i + 1) * mk];
            self.border_kept
                .gather_negated(row, &jacobian.border[r * m..(r + 1) * m]);
            row[i] += sigma;
            for (e, &(_, _, k)) in self.border_paired.iter().enumerate() {
                row[k] -= self.border_fold[i * me + e] * inverse;
            }
        }
        let (block_kept, border_kept) = (&self.block_kept, &self.border_kept);
        let (block_paired, border_paired) = (&self.block_paired, &self.border_paired);
        let (block_fold, lower_fold) = (&self.block_fold, &self.lower_fold);
        let (coupled_nonzero, lower_row_nonzero) = (&self.coupled_nonzero, &self.lower_row_nonzero);
        let factor_block =
            |j: usize,
             (d, piv): (&mut [f64], &mut [usize]),
             (w, lower, part): (&mut [f64], &mut [f64], &mut [f64])| {
                let (jd, ju, jl) = (
                    &jacobian.diag[j * b * b..(j + 1) * b * b],
                    &jacobian.upper[j * b * m..(j + 1) * b * m],
                    &jacobian.lower[j * m * b..(j + 1) * m * b],
                );
                let fold = &block_fold[j * bk * bf..(j + 1) * bk * bf];
                for (i, &r) in block_kept.iter().enumerate() {
                    let row = &mut d[i * bk..(i + 1) * bk];
                    block_kept.gather_negated(row, &jd[r * b..(r + 1) * b]);
                    row[i] += sigma;
                    for (e, &(_, _, k)) in block_paired.iter().enumerate() {
                        row[k] -= fold[i * bf + e] * inverse;
                    }
                }
                lu_factor(d, bk, piv)?;
                // −Lⱼ with the block's positions folded in: the solve's and
                // the Schur complement's.
                let lf = &lower_fold[j * mk * be..(j + 1) * mk * be];
                for (i, &r) in border_kept.iter().enumerate() {
                    let row = &mut lower[i * bk..(i + 1) * bk];
                    block_kept.gather_negated(row, &jl[r * b..(r + 1) * b]);
                    for (e, &(_, _, k)) in block_paired.iter().enumerate() {
                        row[k] -= lf[i * be + e] * inverse;
                    }
                }
                // A block decoupled from the border (Uⱼ = 0) has Wⱼ = 0 and no
                // share in the Schur complement; the solve skips it.
                if !coupled_nonzero[j] {
                    return Ok(());
                }
                for (i, &r) in block_kept.iter().enumerate() {
                    let row = &mut w[i * mk..(i + 1) * mk];
                    border_kept.gather_negated(row, &ju[r * m..(r + 1) * m]);
                    for (e, &(_, _, k)) in border_paired.iter().enumerate() {
                        row[k] -= fold[i * bf + be + e] * inverse;
                    }
                }
                lu_solve_rows(d, bk, piv, w, mk);
                // Its share (−Lⱼ) Wⱼ of the Schur complement.
                for r in (0..mk).filter(|&r| lower_row_nonzero[j * mk + r]) {
                    let prow = &mut part[r * mk..(r + 1) * mk];
                    prow.fill(0.0);
                    for (k, &coefficient) in lower[r * bk..(r + 1) * bk].iter().enumerate() {
                        if coefficient != 0.0 {
                            for (p, wk) in prow.iter_mut().zip(&w[k * mk..(k + 1) * mk]) {
                                *p += coefficient * wk;
                            }
                        }
                    }
                }
                Ok(())
            };
        if self.parallel && bk > 0 && mk > 0 && l.blocks > 1 {
            self.diag
                .par_chunks_mut(bk * bk)
                .zip(self.diag_pivots.par_chunks_mut(bk))
                .zip(self.coupled.par_chunks_mut(bk * mk))
                .zip(self.lower.par_chunks_mut(mk * bk))
                .zip(self.schur_parts.par_chunks_mut(mk * mk))
                .enumerate()
                .try_for_each(|(j, ((((d, piv), w), lower), part))| {
                    factor_block(j, (d, piv), (w, lower, part))
                })?;
        } else {
            for j in 0..l.blocks {
                factor_block(
                    j,
                    (
                        &mut self.diag[j * bk * bk..(j + 1) * bk * bk],
                        &mut self.diag_pivots[j * bk..(j + 1) * bk],
                    ),
                    (
                        &mut self.coupled[j * bk * mk..(j + 1) * bk * mk],
                        &mut self.lower[j * mk * bk..(j + 1) * mk * bk],
                        &mut self.schur_parts[j * mk * mk..(j + 1) * mk * mk],
                    ),
                )?;
            }
        }
        self.subtract_schur_shares();
        lu_factor(&mut self.schur, mk, &mut self.schur_pivots)
    }

    /// S −= Σⱼ (−Lⱼ) Wⱼ, the blocks in order (the rows where Lⱼ has an
    /// entry), so the Schur complement does not depend on the threads.
    #[inline(always)]
    fn subtract_schur_shares(&mut self) {
        let mk = self.border_kept.len();
        for j in (0..self.layout.blocks).filter(|&j| self.coupled_nonzero[j]) {
            let part = &self.schur_parts[j * mk * mk..(j + 1) * mk * mk];
            for r in (0..mk).filter(|&r| self.lower_row_nonzero[j * mk + r]) {
                let schur_row = &mut self.schur[r * mk..(r + 1) * mk];
                for (s, p) in schur_row.iter_mut().zip(&part[r * mk..(r + 1) * mk]) {
                    *s -= p;
                }
            }
        }
    }

    /// Solves (σI − J) x = r in place (`x` holds r on entry). The common
    /// sizes of the kept ball blocks (3: planar, 6: a free ball, and 5 and
    /// 9 without positions) get their own constant-size copies, as the
    /// small dense LU; bit-identical.
    pub fn solve(&mut self, x: &mut [f64]) {
        match self.block_kept.len() {
            3 => self.solve_sized(x, 3),
            5 => self.solve_sized(x, 5),
            6 => self.solve_sized(x, 6),
            9 => self.solve_sized(x, 9),
            bk => self.solve_sized(x, bk),
        }
    }

    /// [`Self::solve`]'s body for `bk` kept block states.
    #[inline(always)]
    fn solve_sized(&mut self, x: &mut [f64], bk: usize) {
        let l = self.layout;
        let (b, s) = (l.block_size, l.border_start());
        let (ba, mk) = (self.block_active.len(), self.border_kept.len());
        let (be, me) = (self.block_paired.len(), self.border_paired.len());
        let bf = be + me;
        let inverse = 1.0 / self.sigma;
        let (blocks, border) = x.split_at_mut(s);
        // The border's kept right-hand side, its positions' folded in.
        for (t, &(q, _, _)) in self.border_scaled.iter_mut().zip(&self.border_paired) {
            *t = border[q] * inverse;
        }
        let xb = &mut self.border_work;
        self.border_kept.gather(xb, border);
        if me > 0 {
            for (i, v) in xb.iter_mut().enumerate() {
                *v += dot(&self.border_fold[i * me..(i + 1) * me], &self.border_scaled);
            }
        }
        // zⱼ = (σI − Dⱼ)⁻¹ rⱼ (kept in x); r_B −= Σ (−Lⱼ) zⱼ.
        for j in 0..l.blocks {
            let block = &mut blocks[j * b..(j + 1) * b];
            for (t, &(q, _, _)) in self.block_scaled.iter_mut().zip(&self.block_paired) {
                *t = block[q] * inverse;
            }
            let z = &mut self.block_work;
            self.block_kept.gather(z, block);
            if bf > 0 {
                let fold = &self.block_fold[j * bk * bf..(j + 1) * bk * bf];
                for (i, v) in z.iter_mut().enumerate() {
                    let row = &fold[i * bf..(i + 1) * bf];
                    *v +=
                        dot(&row[..be], &self.block_scaled) + dot(&row[be..], &self.border_scaled);
                }
            }
            if be > 0 {
                let fold = &self.lower_fold[j * mk * be..(j + 1) * mk * be];
                for (i, v) in xb.iter_mut().enumerate() {
                    *v += dot(&fold[i * be..(i + 1) * be], &self.block_scaled);
                }
            }
            lu_solve(
                &self.diag[j * bk * bk..(j + 1) * bk * bk],
                bk,
                &self.diag_pivots[j * bk..(j + 1) * bk],
                z,
            );
            self.block_kept.scatter(z, block);
            let lower = &self.lower[j * mk * bk..(j + 1) * mk * bk];
            let nonzero = &self.lower_row_nonzero[j * mk..(j + 1) * mk];
            for ((r, v), _) in xb
                .iter_mut()
                .enumerate()
                .zip(nonzero)
                .filter(|(_, nz)| **nz)
            {
                *v -= dot(&lower[r * bk..(r + 1) * bk], z);
            }
        }
        lu_solve(&self.schur, mk, &self.schur_pivots, xb);
        self.border_kept.scatter(xb, border);
        for &(q, v, _) in &self.border_paired {
            border[q] = (border[q] + border[v]) / self.sigma;
        }
        let xa = &mut self.border_active_work;
        self.border_active.gather(xa, border);
        // xⱼ = zⱼ − Wⱼ x_B; then the block's positions and inert states.
        let row_len = ba + xa.len();
        for j in 0..l.blocks {
            let w = &self.coupled[j * bk * mk..(j + 1) * bk * mk];
            let block = &mut blocks[j * b..(j + 1) * b];
            for (i, &k) in self
                .block_kept
                .iter()
                .enumerate()
                .filter(|_| self.coupled_nonzero[j])
            {
                block[k] -= dot(&w[i * mk..(i + 1) * mk], xb);
            }
            for &(q, v, _) in &self.block_paired {
                block[q] = (block[q] + block[v]) / self.sigma;
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
                    .zip(self.block_active.iter())
                    .map(|(a, &c)| a * block[c])
                    .sum::<f64>()
                    + dot(&row[ba..], xa);
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
            let row = &self.inert_border_rows[q * (l.blocks * ba + xa.len())..]
                [..l.blocks * ba + xa.len()];
            let mut coupled = 0.0;
            for j in 0..l.blocks {
                let block = &blocks[j * b..(j + 1) * b];
                coupled += row[j * ba..(j + 1) * ba]
                    .iter()
                    .zip(self.block_active.iter())
                    .map(|(a, &c)| a * block[c])
                    .sum::<f64>();
            }
            coupled += dot(&row[l.blocks * ba..], xa);
            border[r] = (border[r] + coupled) / self.sigma;
        }
    }
}

#[cfg(test)]
mod tests;
