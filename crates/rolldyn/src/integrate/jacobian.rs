//! Finite-difference Jacobians that use the system's structure.
//!
//! A system that splits into blocks coupled only through a border
//! ([`BlockSplit`]) is differentiated **block-wise**: column k of every
//! block is perturbed in one sweep over the blocks (one colour of the
//! column grouping of Curtis, Powell & Reid, *J. Inst. Math. Appl.* 13,
//! 1974), and because each block reports its own contribution to the
//! border derivatives, the border rows Lⱼ = ∂f_B/∂yⱼ are recovered block by
//! block, not summed. A sweep costs one right-hand side, so the blocks cost
//! `block_size` right-hand sides, and each border column one more. States
//! the system marks inert (f does not read them, or they never change)
//! are skipped. Dense systems fall back to one right-hand side per column.
//!
//! Increments: δᵢ = √ε · max(|yᵢ|, sᵢ), sᵢ the system's error scale
//! (Hairer & Wanner, *Solving ODEs II*, §IV.8).

use super::OdeSystem;
use super::linear::{BlockJacobian, BlockLayout};

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
pub trait BlockSplit {
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

    /// Whether column `state` of the Jacobian may be left zero: f does not
    /// depend on the state, or its derivative is identically zero so it
    /// never changes. Default: no state is inert.
    fn inert(&self, _state: usize) -> bool {
        false
    }
}

/// Work space for finite-difference Jacobians.
#[derive(Debug, Clone)]
pub struct JacobianWork {
    y: Vec<f64>,
    scale: Vec<f64>,
    f: Vec<f64>,
    f_perturbed: Vec<f64>,
    couplings: Vec<f64>,
    coupling_sum: Vec<f64>,
    coupling_perturbed: Vec<f64>,
    coupling_trial: Vec<f64>,
}

impl JacobianWork {
    /// Work space for `system`.
    pub fn new(system: &impl OdeSystem) -> Self {
        let n = system.dimension();
        let (blocks, c) = system
            .blocks()
            .map(|s| (s.block_layout().blocks, s.coupling_len()))
            .unwrap_or((0, 0));
        let mut scale = vec![0.0; n];
        system.error_scale(&mut scale);
        Self {
            y: vec![0.0; n],
            scale,
            f: vec![0.0; n],
            f_perturbed: vec![0.0; n],
            couplings: vec![0.0; blocks * c],
            coupling_sum: vec![0.0; c],
            coupling_perturbed: vec![0.0; c],
            coupling_trial: vec![0.0; c],
        }
    }

    fn increment(&self, i: usize) -> f64 {
        let h = f64::EPSILON.sqrt() * self.y[i].abs().max(self.scale[i]);
        // An exactly representable increment: (y + δ) − y = δ.
        (self.y[i] + h) - self.y[i]
    }
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
    let (b, m, start) = (layout.block_size, layout.border, layout.border_start());
    let c = split.coupling_len();
    let mut cost = 1;
    // Base values f_j, c_j, f_B of the split at the unperturbed point (the
    // split may be an approximation of the system's rhs).
    work.coupling_sum.fill(0.0);
    for j in 0..layout.blocks {
        let cj = &mut work.couplings[j * c..(j + 1) * c];
        split.block_rhs(t, &work.y, j, &mut work.f[j * b..(j + 1) * b], cj);
        for (s, v) in work.coupling_sum.iter_mut().zip(cj.iter()) {
            *s += v;
        }
    }
    let (_, f_border) = work.f.split_at_mut(start);
    split.border_rhs(t, &work.y, &work.coupling_sum, f_border);
    // Block columns: one sweep over all blocks per column index k.
    for k in 0..b {
        let mut swept = false;
        for j in 0..layout.blocks {
            let col = j * b + k;
            let diag = &mut jacobian.diag[j * b * b..(j + 1) * b * b];
            let lower = &mut jacobian.lower[j * m * b..(j + 1) * m * b];
            if split.inert(col) {
                (0..b).for_each(|r| diag[r * b + k] = 0.0);
                (0..m).for_each(|r| lower[r * b + k] = 0.0);
                continue;
            }
            swept = true;
            let delta = work.increment(col);
            let saved = work.y[col];
            work.y[col] += delta;
            split.block_rhs(
                t,
                &work.y,
                j,
                &mut work.f_perturbed[..b],
                &mut work.coupling_perturbed,
            );
            work.y[col] = saved;
            for r in 0..b {
                diag[r * b + k] = (work.f_perturbed[r] - work.f[j * b + r]) / delta;
            }
            let cj = &work.couplings[j * c..(j + 1) * c];
            for (trial, ((sum, perturbed), base)) in work.coupling_trial.iter_mut().zip(
                work.coupling_sum
                    .iter()
                    .zip(&work.coupling_perturbed)
                    .zip(cj),
            ) {
                *trial = sum + (perturbed - base);
            }
            split.border_rhs(t, &work.y, &work.coupling_trial, &mut work.f_perturbed[..m]);
            for r in 0..m {
                lower[r * b + k] = (work.f_perturbed[r] - work.f[start + r]) / delta;
            }
        }
        cost += u64::from(swept);
    }
    // Border columns: each a full right-hand side.
    for p in 0..m {
        let col = start + p;
        if split.inert(col) {
            for j in 0..layout.blocks {
                (0..b).for_each(|r| jacobian.upper[j * b * m + r * m + p] = 0.0);
            }
            (0..m).for_each(|r| jacobian.border[r * m + p] = 0.0);
            continue;
        }
        cost += 1;
        let delta = work.increment(col);
        let saved = work.y[col];
        work.y[col] += delta;
        work.coupling_trial.fill(0.0);
        for j in 0..layout.blocks {
            split.block_rhs(
                t,
                &work.y,
                j,
                &mut work.f_perturbed[..b],
                &mut work.coupling_perturbed,
            );
            for r in 0..b {
                jacobian.upper[j * b * m + r * m + p] =
                    (work.f_perturbed[r] - work.f[j * b + r]) / delta;
            }
            for (s, v) in work.coupling_trial.iter_mut().zip(&work.coupling_perturbed) {
                *s += v;
            }
        }
        split.border_rhs(t, &work.y, &work.coupling_trial, &mut work.f_perturbed[..m]);
        work.y[col] = saved;
        for r in 0..m {
            jacobian.border[r * m + p] = (work.f_perturbed[r] - work.f[start + r]) / delta;
        }
    }
    cost
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
}
