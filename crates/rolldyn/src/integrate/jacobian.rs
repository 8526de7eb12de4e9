//! Finite-difference Jacobians that use the system's structure.
//!
//! A system that splits into blocks coupled only through a border
//! ([`BlockSplit`]) is differentiated **block-wise**: column k of every
//! block is perturbed in one sweep over the blocks (one colour of the
//! column grouping of Curtis, Powell & Reid, *J. Inst. Math. Appl.* 13,
//! 1974), and because each block reports its own contribution to the
//! border derivatives, the border rows Lⱼ = ∂f_B/∂yⱼ are recovered block by
//! block, not summed: by the chain rule Lⱼ = (∂f_B/∂C)(∂cⱼ/∂yⱼ), with the
//! border's derivative with respect to the coupling sum C differenced once
//! per Jacobian. A sweep costs one right-hand side, so the blocks cost
//! `block_size` right-hand sides, and each border column one more. States
//! the system marks inert (f does not read them, or they never change)
//! are skipped. Dense systems fall back to one right-hand side per column.
//!
//! Threads: the blocks are shared out in contiguous chunks, a few per
//! thread (so that blocks of unequal cost even out), each chunk
//! differencing all the columns of its blocks in its own copy of the
//! state; every block's numbers are a serial sweep's, and the border
//! columns' couplings are summed in block order, so the Jacobian is the
//! same whatever the threads.
//!
//! A split may also offer a **fast part** ([`BlockSplit::with_fast_part`],
//! [`fast_part_difference`]), whose Jacobian an implicit method refreshes
//! more often than the whole one.
//!
//! Increments: δᵢ = √ε · max(|yᵢ|, sᵢ), sᵢ the system's error scale
//! (Hairer & Wanner, *Solving ODEs II*, §IV.8). The states judged
//! absolutely ([`OdeSystem::absolute_error`]: angles that turn without
//! bound) get δᵢ = √ε · max(1, sᵢ), a fixed fraction of a radian: their
//! size says nothing about the scale on which f varies. With √ε |φ| the
//! increment of a ball's azimuth grew with every turn (0.2 µm along the
//! 7008C's pitch circle after 1 s), and was 1e-14 m for a ball starting
//! at φ = 0; the poorer Jacobian cost the default case's whirl regime
//! 13–18× its steps and drifted its energy balance (docs/performance.md).

use super::OdeSystem;
use super::linear::{BlockJacobian, BlockLayout};
use rayon::prelude::*;

/// A system whose right-hand side splits into blocks, each reading only
/// its own states and the border, and a border part that sees the blocks
/// only through the sum of their couplings:
///
/// f_j = block_j(t, y_j, y_B) and f_B = border(t, y_B, Σ_j c_j(t, y_j, y_B)).
///
/// The Jacobian is taken of this composition. It should equal
/// [`OdeSystem::rhs`]; a cheaper approximation is allowed (a Rosenbrock–W
/// method keeps its order with any Jacobian) but must keep the stiff
/// terms: the bearing's traction at the contact centre instead of over the
/// grid lost the spin-friction stiffness and cut the steps of a whirling
/// 7008C cage from ~20 µs to ~1 µs (docs/performance.md), so the bearing
/// uses its full model.
pub trait BlockSplit: Sync {
    /// The shape: blocks first, then the border.
    fn block_layout(&self) -> BlockLayout;

    /// Length of a block's coupling vector c_j.
    fn coupling_len(&self) -> usize;

    /// Writes f_j into `dy_block` and c_j into `coupling`.
    fn block_rhs(
        &self,
        t: f64,
        y: &[f64],
        block: usize,
        dy_block: &mut [f64],
        coupling: &mut [f64],
    );

    /// Writes f_B for the summed coupling into `dy_border`.
    fn border_rhs(&self, t: f64, y: &[f64], coupling: &[f64], dy_border: &mut [f64]);

    /// Length of a block's memo (0: the split keeps none): what
    /// [`Self::block_rhs_memo`] stores of the unperturbed point for
    /// [`Self::block_rhs_border_column`].
    fn memo_len(&self) -> usize {
        0
    }

    /// [`Self::block_rhs`] at the Jacobian's unperturbed point, also
    /// filling the block's `memo`.
    fn block_rhs_memo(
        &self,
        t: f64,
        y: &[f64],
        block: usize,
        dy_block: &mut [f64],
        coupling: &mut [f64],
        _memo: &mut [f64],
    ) {
        self.block_rhs(t, y, block, dy_block, coupling);
    }

    /// [`Self::block_rhs`] with border state `column` (counted from the
    /// border's first state) perturbed in `y` and the block's `memo` of the
    /// unperturbed point: a split may reuse there what the perturbed state
    /// does not reach. Must give the bits of [`Self::block_rhs`].
    #[allow(clippy::too_many_arguments)]
    fn block_rhs_border_column(
        &self,
        t: f64,
        y: &[f64],
        block: usize,
        _column: usize,
        _memo: &[f64],
        dy_block: &mut [f64],
        coupling: &mut [f64],
    ) {
        self.block_rhs(t, y, block, dy_block, coupling);
    }

    /// Whether the blocks may be evaluated on several threads at once
    /// (worth it when a block costs microseconds). The Jacobian is the
    /// same either way. Default: no.
    fn parallel(&self) -> bool {
        false
    }

    /// Whether column `state` of the Jacobian may be left zero: f does not
    /// depend on the state, or its derivative is identically zero so it
    /// never changes. Default: no state is inert.
    fn inert(&self, _state: usize) -> bool {
        false
    }

    /// The state whose value is the rate of `state`, where f_state(t, y) =
    /// y_v exactly for every (t, y) (a position and its velocity): its row
    /// of the Jacobian is the unit row of v, and the factorization
    /// eliminates it ([`super::linear::BlockLu`]). Default: none.
    fn rate_of(&self, _state: usize) -> Option<usize> {
        None
    }

    /// Whether block j's right-hand side and coupling are zero at and
    /// about y (a bearing's fast part: a ball whose pocket is open), so
    /// that its rows and columns of the Jacobian are zero and are not
    /// differenced. Default: no.
    fn block_is_zero(&self, _t: f64, _y: &[f64], _block: usize) -> bool {
        false
    }

    /// Whether the blocks read border state `border_state` (counted from
    /// the border's first state). A column of a state no block reads has
    /// zero block rows and costs one border evaluation. Default: they all
    /// do.
    fn blocks_read(&self, _border_state: usize) -> bool {
        true
    }

    /// Whether `state` belongs to the fast part's own dynamics (the
    /// bearing's cage): while such states limit the steps, a
    /// Rosenbrock–W method refreshes the fast part's Jacobian
    /// ([`super::rosenbrock::fast_part`]). Default: none.
    fn fast_state(&self, _state: usize) -> bool {
        false
    }

    /// Hands `with` the split's **fast part**, if it has one worth
    /// refreshing between full Jacobians, and returns whether it did: a
    /// part f_F of the right-hand side (same blocks, border and inert
    /// states) whose Jacobian changes within a few steps while costing
    /// little to difference, the rest f − f_F changing slowly at most of
    /// the cost (a bearing: the pockets and the cage's guidance against
    /// the ball–raceway contacts with their traction over the contact
    /// ellipses). A Rosenbrock–W method then uses
    /// J = (J − J_F)(last full Jacobian) + J_F(now) ([`super::rosenbrock`]).
    /// Default: none.
    fn with_fast_part(&self, _with: &mut dyn FnMut(&dyn BlockSplit)) -> bool {
        false
    }
}

/// Chunks of blocks per thread when the blocks are differenced across
/// threads: blocks of unequal cost (a fast part whose open pockets are
/// skipped, [`BlockSplit::block_is_zero`]) even out between the threads.
const CHUNKS_PER_THREAD: usize = 4;

/// Work space for finite-difference Jacobians.
#[derive(Debug, Clone)]
pub struct JacobianWork {
    y: Vec<f64>,
    scale: Vec<f64>,
    /// Whether |yᵢ| enters the increment (false for absolute states).
    sized: Vec<bool>,
    f: Vec<f64>,
    f_perturbed: Vec<f64>,
    couplings: Vec<f64>,
    /// Per block: the split's memo of the unperturbed point.
    memos: Vec<f64>,
    memo_len: usize,
    coupling_sum: Vec<f64>,
    coupling_trial: Vec<f64>,
    /// ∂f_B/∂C transposed (c rows of m): the border's derivative with
    /// respect to the coupling sum.
    border_gradient: Vec<f64>,
    /// Per block: its perturbed coupling for each border column (m × c).
    border_couplings: Vec<f64>,
    /// One copy of y per chunk of blocks ([`CHUNKS_PER_THREAD`] per
    /// thread of the pool the work was made in).
    y_copies: Vec<f64>,
    /// Per block: its right-hand side, a coupling and a border change.
    block_scratch: Vec<f64>,
    block_stride: usize,
}

impl JacobianWork {
    /// Work space for `system`.
    pub fn new(system: &impl OdeSystem) -> Self {
        let n = system.dimension();
        let (layout, c, memo_len) = system
            .blocks()
            .map(|s| (s.block_layout(), s.coupling_len(), s.memo_len()))
            .unwrap_or((BlockLayout::dense(n), 0, 0));
        let blocks = layout.blocks;
        // A block's scratch: its right-hand side (max(b, m)), perturbed
        // coupling (c) and the border's change (m).
        let block_stride = layout.block_size.max(layout.border) + c + layout.border;
        let mut scale = vec![0.0; n];
        system.error_scale(&mut scale);
        let mut absolute = vec![false; n];
        system.absolute_error(&mut absolute);
        for (s, _) in scale.iter_mut().zip(&absolute).filter(|(_, a)| **a) {
            *s = s.max(1.0);
        }
        Self {
            y: vec![0.0; n],
            scale,
            sized: absolute.iter().map(|a| !a).collect(),
            f: vec![0.0; n],
            f_perturbed: vec![0.0; n],
            couplings: vec![0.0; blocks * c],
            memos: vec![0.0; blocks * memo_len],
            memo_len,
            coupling_sum: vec![0.0; c],
            coupling_trial: vec![0.0; c],
            border_gradient: vec![0.0; c * layout.border],
            border_couplings: vec![0.0; blocks * layout.border * c],
            y_copies: vec![
                0.0;
                n * (CHUNKS_PER_THREAD * rayon::current_num_threads())
                    .clamp(1, blocks.max(1))
            ],
            block_scratch: vec![0.0; blocks * block_stride],
            block_stride,
        }
    }

    fn increment(&self, i: usize) -> f64 {
        increment(self.y[i], self.scale[i], self.sized[i])
    }
}

/// Finite-difference increment of a state of value `y` and error scale
/// `scale`, of size √ε max(|y|, scale), or √ε scale if not `sized`;
/// exactly representable: (y + δ) − y = δ.
fn increment(y: f64, scale: f64, sized: bool) -> f64 {
    let magnitude = if sized { y.abs().max(scale) } else { scale };
    let h = f64::EPSILON.sqrt() * magnitude;
    (y + h) - y
}

/// Evaluates ∂f/∂y at (t, y) into `jacobian` by finite differences,
/// block-wise when the system has blocks. `f` is f(t, y). Returns the cost
/// in right-hand-side equivalents.
pub fn finite_difference<S: OdeSystem + ?Sized>(
    system: &S,
    t: f64,
    y: &[f64],
    f: &[f64],
    jacobian: &mut BlockJacobian,
    work: &mut JacobianWork,
) -> u64 {
    work.y.copy_from_slice(y);
    match system.blocks() {
        Some(split) => by_blocks(split, t, jacobian, work),
        None => dense(system, t, f, jacobian, work),
    }
}

/// The Jacobian of the system's fast part ([`BlockSplit::with_fast_part`])
/// at (t, y) into `jacobian`, block-wise; its cost in evaluations of the
/// fast part, or None when the system has no fast part.
pub fn fast_part_difference<S: OdeSystem + ?Sized>(
    system: &S,
    t: f64,
    y: &[f64],
    jacobian: &mut BlockJacobian,
    work: &mut JacobianWork,
) -> Option<u64> {
    let split = system.blocks()?;
    work.y.copy_from_slice(y);
    let mut cost = None;
    split.with_fast_part(&mut |fast| cost = Some(by_blocks(fast, t, jacobian, work)));
    cost
}

fn dense<S: OdeSystem + ?Sized>(
    system: &S,
    t: f64,
    f: &[f64],
    jacobian: &mut BlockJacobian,
    work: &mut JacobianWork,
) -> u64 {
    let n = work.y.len();
    debug_assert_eq!(jacobian.layout(), BlockLayout::dense(n));
    for col in 0..n {
        let delta = work.increment(col);
        let saved = work.y[col];
        work.y[col] += delta;
        system.rhs(t, &work.y, &mut work.f_perturbed);
        work.y[col] = saved;
        for (row, (perturbed, base)) in work.f_perturbed.iter().zip(f).enumerate() {
            jacobian.border[row * n + col] = (perturbed - base) / delta;
        }
    }
    n as u64
}

fn by_blocks(
    split: &dyn BlockSplit,
    t: f64,
    jacobian: &mut BlockJacobian,
    work: &mut JacobianWork,
) -> u64 {
    let layout = split.block_layout();
    debug_assert_eq!(jacobian.layout(), layout);
    let (b, m) = (layout.block_size, layout.border);
    let c = split.coupling_len();
    let parallel = split.parallel();
    let stride = work.block_stride;
    let mut cost = 1;
    base_values(split, t, work);
    coupling_gradient(split, t, work);
    // Every block's columns and border columns, the blocks shared out in
    // contiguous chunks, a few per thread: block j reads only its own states
    // and the border's, so a chunk perturbs its blocks' states, and the
    // border's, in its own copy of y. Each block's numbers are those of a
    // serial sweep whatever the chunks (one hand-over per Jacobian, not
    // one per column).
    let n = layout.dimension();
    let chunks = if parallel { work.y_copies.len() / n } else { 1 };
    let per_chunk = layout.blocks.div_ceil(chunks.max(1)).max(1);
    let cols = Columns {
        split,
        t,
        y: &work.y,
        f: &work.f,
        couplings: &work.couplings,
        memos: &work.memos,
        memo_len: work.memo_len,
        gradient: &work.border_gradient,
        scale: &work.scale,
        sized: &work.sized,
    };
    let run = |ci: usize,
               (diag, lower, upper): (&mut [f64], &mut [f64], &mut [f64]),
               (scratch, perturbed, y): (&mut [f64], &mut [f64], &mut [f64])| {
        y.copy_from_slice(cols.y);
        let first = ci * per_chunk;
        for (local, j) in (first..(first + per_chunk).min(layout.blocks)).enumerate() {
            cols.block(
                j,
                y,
                (
                    &mut diag[local * b * b..][..b * b],
                    &mut lower[local * m * b..][..m * b],
                    &mut upper[local * b * m..][..b * m],
                ),
                &mut scratch[local * stride..][..stride],
                &mut perturbed[local * m * c..][..m * c],
            );
        }
    };
    if chunks > 1 {
        jacobian
            .diag
            .par_chunks_mut(per_chunk * b * b)
            .zip(jacobian.lower.par_chunks_mut(per_chunk * m * b))
            .zip(jacobian.upper.par_chunks_mut(per_chunk * b * m))
            .zip(work.block_scratch.par_chunks_mut(per_chunk * stride))
            .zip(work.border_couplings.par_chunks_mut(per_chunk * m * c))
            .zip(work.y_copies.par_chunks_mut(n))
            .enumerate()
            .for_each(|(ci, (((((d, l), u), s), p), y))| run(ci, (d, l, u), (s, p, y)));
    } else {
        let y = &mut work.y_copies[..n];
        run(
            0,
            (&mut jacobian.diag, &mut jacobian.lower, &mut jacobian.upper),
            (&mut work.block_scratch, &mut work.border_couplings, y),
        );
    }
    for k in 0..b {
        cost += u64::from((0..layout.blocks).any(|j| !split.inert(j * b + k)));
    }
    cost += border_columns(split, t, jacobian, work);
    cost
}

/// [`by_blocks`]' base values f_j, c_j, f_B of the split at the
/// unperturbed point (the split may be an approximation of the system's
/// rhs), and the couplings' sum.
fn base_values(split: &dyn BlockSplit, t: f64, work: &mut JacobianWork) {
    let layout = split.block_layout();
    let (b, start) = (layout.block_size, layout.border_start());
    let c = split.coupling_len();
    let parallel = split.parallel();
    let y = &work.y;
    let memo_len = work.memo_len;
    if memo_len > 0 {
        each_block3(
            parallel,
            (&mut work.f[..start], b),
            (&mut work.couplings, c),
            (&mut work.memos, memo_len),
            |j, f_j, c_j, memo| split.block_rhs_memo(t, y, j, f_j, c_j, memo),
        );
    } else {
        each_block2(
            parallel,
            (&mut work.f[..start], b),
            (&mut work.couplings, c),
            |j, f_j, c_j| split.block_rhs(t, y, j, f_j, c_j),
        );
    }
    work.coupling_sum.fill(0.0);
    for cj in work.couplings.chunks(c) {
        for (s, v) in work.coupling_sum.iter_mut().zip(cj) {
            *s += v;
        }
    }
    let (_, f_border) = work.f.split_at_mut(start);
    split.border_rhs(t, &work.y, &work.coupling_sum, f_border);
}

/// [`by_blocks`]' G = ∂f_B/∂C, one border evaluation per coupling
/// component: the chain rule then gives each block's lower border,
/// ∂f_B/∂y_j = G ∂c_j/∂y_j, from its perturbed coupling, instead of a
/// border evaluation per block and column.
fn coupling_gradient(split: &dyn BlockSplit, t: f64, work: &mut JacobianWork) {
    let layout = split.block_layout();
    let (m, start) = (layout.border, layout.border_start());
    for i in 0..split.coupling_len() {
        let base = work.coupling_sum[i];
        let delta = increment(base, 1.0, true);
        work.coupling_trial.copy_from_slice(&work.coupling_sum);
        work.coupling_trial[i] = base + delta;
        split.border_rhs(t, &work.y, &work.coupling_trial, &mut work.f_perturbed[..m]);
        for r in 0..m {
            work.border_gradient[i * m + r] = (work.f_perturbed[r] - work.f[start + r]) / delta;
        }
    }
}

/// [`by_blocks`]' border rows of the border columns: the blocks' perturbed
/// couplings summed in block order. Returns the border evaluations' cost.
fn border_columns(
    split: &dyn BlockSplit,
    t: f64,
    jacobian: &mut BlockJacobian,
    work: &mut JacobianWork,
) -> u64 {
    let layout = split.block_layout();
    let (m, start) = (layout.border, layout.border_start());
    let c = split.coupling_len();
    let mut cost = 0;
    for p in 0..m {
        let col = start + p;
        if split.inert(col) {
            (0..m).for_each(|r| jacobian.border[r * m + p] = 0.0);
            continue;
        }
        let delta = work.increment(col);
        let saved = work.y[col];
        work.y[col] += delta;
        if split.blocks_read(p) {
            cost += 1;
            work.coupling_trial.fill(0.0);
            for perturbed in work.border_couplings.chunks(m * c) {
                for (s, v) in work
                    .coupling_trial
                    .iter_mut()
                    .zip(&perturbed[p * c..(p + 1) * c])
                {
                    *s += v;
                }
            }
        } else {
            work.coupling_trial.copy_from_slice(&work.coupling_sum);
        }
        split.border_rhs(t, &work.y, &work.coupling_trial, &mut work.f_perturbed[..m]);
        work.y[col] = saved;
        for r in 0..m {
            jacobian.border[r * m + p] = (work.f_perturbed[r] - work.f[start + r]) / delta;
        }
    }
    cost
}

/// What a block's columns read: the split, the unperturbed point and its
/// values, and the border's derivative with respect to the coupling sum.
struct Columns<'a> {
    split: &'a dyn BlockSplit,
    t: f64,
    y: &'a [f64],
    f: &'a [f64],
    couplings: &'a [f64],
    memos: &'a [f64],
    memo_len: usize,
    gradient: &'a [f64],
    scale: &'a [f64],
    sized: &'a [bool],
}

impl Columns<'_> {
    /// Block j's columns (its diagonal block and lower border) and its
    /// rows of the border columns (upper border), with `y` a copy of the
    /// point that is left as it was; the perturbed couplings of the border
    /// columns into `perturbed` (m rows of c).
    fn block(
        &self,
        j: usize,
        y: &mut [f64],
        (diag, lower, upper): (&mut [f64], &mut [f64], &mut [f64]),
        scratch: &mut [f64],
        perturbed: &mut [f64],
    ) {
        let split = self.split;
        let layout = split.block_layout();
        let (b, m, start) = (layout.block_size, layout.border, layout.border_start());
        let c = split.coupling_len();
        let (head, rest) = scratch.split_at_mut(b.max(m));
        let (coupling, change) = rest.split_at_mut(c);
        let (f_j, c_j) = (
            &self.f[j * b..(j + 1) * b],
            &self.couplings[j * c..(j + 1) * c],
        );
        if split.block_is_zero(self.t, y, j) {
            diag.fill(0.0);
            lower.fill(0.0);
            upper.fill(0.0);
            // The border columns see the block's coupling unchanged.
            for p in perturbed.chunks_mut(c) {
                p.copy_from_slice(c_j);
            }
            return;
        }
        for k in 0..b {
            let col = j * b + k;
            if split.inert(col) {
                (0..b).for_each(|r| diag[r * b + k] = 0.0);
                (0..m).for_each(|r| lower[r * b + k] = 0.0);
                continue;
            }
            let delta = increment(y[col], self.scale[col], self.sized[col]);
            let saved = y[col];
            y[col] += delta;
            split.block_rhs(self.t, y, j, &mut head[..b], coupling);
            y[col] = saved;
            for r in 0..b {
                diag[r * b + k] = (head[r] - f_j[r]) / delta;
            }
            // f_B's change: G times the coupling's.
            let change = &mut change[..m];
            change.fill(0.0);
            for (i, (p, base)) in coupling.iter().zip(c_j).enumerate() {
                let dc = p - base;
                if dc != 0.0 {
                    for (v, g) in change.iter_mut().zip(&self.gradient[i * m..(i + 1) * m]) {
                        *v += g * dc;
                    }
                }
            }
            for r in 0..m {
                lower[r * b + k] = change[r] / delta;
            }
        }
        let memo = &self.memos[j * self.memo_len..(j + 1) * self.memo_len];
        for p in 0..m {
            let col = start + p;
            if split.inert(col) || !split.blocks_read(p) {
                (0..b).for_each(|r| upper[r * m + p] = 0.0);
                continue;
            }
            let delta = increment(y[col], self.scale[col], self.sized[col]);
            let saved = y[col];
            y[col] += delta;
            let out = &mut perturbed[p * c..(p + 1) * c];
            split.block_rhs_border_column(self.t, y, j, p, memo, &mut head[..b], out);
            y[col] = saved;
            for r in 0..b {
                upper[r * m + p] = (head[r] - f_j[r]) / delta;
            }
        }
    }
}

/// `per_block(j, a_j, b_j)` for every block j, where a_j and b_j are the
/// j-th chunks of the given lengths; across threads when `parallel`. Each
/// block writes only its own chunks, so the result does not depend on the
/// threads.
fn each_block2<F>(parallel: bool, a: (&mut [f64], usize), b: (&mut [f64], usize), per_block: F)
where
    F: Fn(usize, &mut [f64], &mut [f64]) + Sync,
{
    if parallel {
        a.0.par_chunks_mut(a.1)
            .zip(b.0.par_chunks_mut(b.1))
            .enumerate()
            .for_each(|(j, (x, y))| per_block(j, x, y));
    } else {
        for (j, (x, y)) in a.0.chunks_mut(a.1).zip(b.0.chunks_mut(b.1)).enumerate() {
            per_block(j, x, y);
        }
    }
}

/// [`each_block2`] with three chunked slices.
fn each_block3<F>(
    parallel: bool,
    a: (&mut [f64], usize),
    b: (&mut [f64], usize),
    c: (&mut [f64], usize),
    per_block: F,
) where
    F: Fn(usize, &mut [f64], &mut [f64], &mut [f64]) + Sync,
{
    if parallel {
        a.0.par_chunks_mut(a.1)
            .zip(b.0.par_chunks_mut(b.1))
            .zip(c.0.par_chunks_mut(c.1))
            .enumerate()
            .for_each(|(j, ((x, y), z))| per_block(j, x, y, z));
    } else {
        for (j, ((x, y), z)) in
            a.0.chunks_mut(a.1)
                .zip(b.0.chunks_mut(b.1))
                .zip(c.0.chunks_mut(c.1))
                .enumerate()
        {
            per_block(j, x, y, z);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Three particles on springs to a common mass (the border), with
    /// nonlinear (cubic) springs: a bordered system with known Jacobian.
    struct Chain;
    const K3: f64 = 7.0;
    impl Chain {
        fn spring(d: f64) -> f64 {
            -(d + K3 * d * d * d)
        }
        fn slope(d: f64) -> f64 {
            -(1.0 + 3.0 * K3 * d * d)
        }
    }
    impl OdeSystem for Chain {
        fn dimension(&self) -> usize {
            8
        }
        fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
            let mut c = [0.0];
            let mut sum = [0.0];
            for j in 0..3 {
                self.block_rhs(t, y, j, &mut dy[2 * j..2 * j + 2], &mut c);
                sum[0] += c[0];
            }
            let (_, border) = dy.split_at_mut(6);
            self.border_rhs(t, y, &sum, border);
        }
        fn blocks(&self) -> Option<&dyn BlockSplit> {
            Some(self)
        }
    }
    impl BlockSplit for Chain {
        fn block_layout(&self) -> BlockLayout {
            BlockLayout {
                blocks: 3,
                block_size: 2,
                border: 2,
            }
        }
        fn coupling_len(&self) -> usize {
            1
        }
        fn block_rhs(&self, _t: f64, y: &[f64], j: usize, dy: &mut [f64], c: &mut [f64]) {
            let d = y[2 * j] - y[6];
            dy[0] = y[2 * j + 1];
            dy[1] = Self::spring(d) - 0.1 * y[2 * j + 1];
            c[0] = -Self::spring(d);
        }
        fn border_rhs(&self, _t: f64, y: &[f64], c: &[f64], dy: &mut [f64]) {
            dy[0] = y[7];
            dy[1] = c[0] / 2.0 - y[6];
        }
    }

    #[test]
    fn block_differences_match_the_analytic_jacobian() {
        let sys = Chain;
        let y = [0.1, 0.2, -0.3, 0.0, 0.05, -0.1, 0.02, 0.3];
        let mut f = [0.0; 8];
        sys.rhs(0.0, &y, &mut f);
        let layout = sys.block_layout();
        let mut jac = BlockJacobian::zeros(layout);
        let mut work = JacobianWork::new(&sys);
        let cost = finite_difference(&sys, 0.0, &y, &f, &mut jac, &mut work);
        // 1 base + 2 block colours + 2 border columns.
        assert_eq!(cost, 5);
        let mut exact = [[0.0; 8]; 8];
        let mut sum_slope = 0.0;
        for j in 0..3 {
            let s = Chain::slope(y[2 * j] - y[6]);
            sum_slope += s;
            exact[2 * j][2 * j + 1] = 1.0;
            exact[2 * j + 1][2 * j] = s;
            exact[2 * j + 1][2 * j + 1] = -0.1;
            exact[2 * j + 1][6] = -s;
            exact[7][2 * j] = -s / 2.0;
        }
        exact[6][7] = 1.0;
        exact[7][6] = sum_slope / 2.0 - 1.0;
        for (r, row) in exact.iter().enumerate() {
            for (c, e) in row.iter().enumerate() {
                let got = jac.get(r, c);
                assert!((got - e).abs() < 1e-6, "J[{r}][{c}] = {got}, exact {e}");
            }
        }
    }

    /// A ball on a circle of radius 27 mm whose force varies with its
    /// height R sin φ over 0.1 mm (a contact), with its azimuth φ judged
    /// absolutely at the error scale of 1 µm along the circle.
    struct Orbit;
    const RADIUS: f64 = 0.027;
    const WAVELENGTH: f64 = 1e-4;
    impl OdeSystem for Orbit {
        fn dimension(&self) -> usize {
            1
        }
        fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
            dy[0] = (RADIUS * y[0].sin() / WAVELENGTH).sin();
        }
        fn error_scale(&self, scale: &mut [f64]) {
            scale[0] = 1e-6 / RADIUS;
        }
        fn absolute_error(&self, absolute: &mut [bool]) {
            absolute[0] = true;
        }
    }

    /// The increment of a turning angle is a fixed fraction of a radian:
    /// √ε |φ| after 1000 turns would miss the slope by ~1e-2.
    #[test]
    fn angles_are_differenced_on_the_scale_of_a_radian_after_any_number_of_turns() {
        let k = RADIUS / WAVELENGTH;
        for phi in [0.0, 0.3, 2.0 * std::f64::consts::PI * 1000.0 + 0.3] {
            let y = [phi];
            let mut f = [0.0];
            Orbit.rhs(0.0, &y, &mut f);
            let mut jac = BlockJacobian::zeros(BlockLayout::dense(1));
            let mut work = JacobianWork::new(&Orbit);
            finite_difference(&Orbit, 0.0, &y, &f, &mut jac, &mut work);
            let exact = k * phi.cos() * (k * phi.sin()).cos();
            let error = (jac.get(0, 0) - exact).abs() / k;
            assert!(
                error < 1e-5,
                "φ = {phi}: slope {} vs {exact}",
                jac.get(0, 0)
            );
        }
    }
}
