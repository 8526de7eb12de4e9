//! The block structure of bearings on a shaft for the implicit
//! integrators: every bearing's balls are the blocks, each bearing's outer
//! ring, cage and accumulators and the shaft the border. A border column
//! of one bearing re-evaluates that bearing's balls only (the others come
//! from the unperturbed point's memo); a shaft column moves every inner
//! ring and re-evaluates every ball.

use super::{Mounted, SHAFT_LEN, ShaftDynamics};
use crate::dynamics::coupling::BallCoupling;
use crate::integrate::BlockSplit;
use crate::integrate::linear::BlockLayout;

impl ShaftDynamics {
    /// Ball `j` of bearing `b` and the bearing's border into `out` (the
    /// other balls' slots are not read by one ball's equations).
    fn gather_ball(&self, b: &Mounted, j: usize, y: &[f64], out: &mut [f64]) {
        let at = j * self.ball_len;
        out[at..at + self.ball_len]
            .copy_from_slice(&y[b.first_ball + at..b.first_ball + at + self.ball_len]);
        self.gather_border(b, y, out);
    }
}

impl BlockSplit for ShaftDynamics {
    fn block_layout(&self) -> BlockLayout {
        BlockLayout {
            blocks: self.bearings.iter().map(|b| b.model.layout().balls).sum(),
            block_size: self.ball_len,
            border: self.dimension - self.bearings[0].first_border,
        }
    }

    fn coupling_len(&self) -> usize {
        BallCoupling::LEN * self.bearings.len()
    }

    fn parallel(&self) -> bool {
        self.bearings[0].model.parallel()
    }

    fn block_rhs(
        &self,
        t: f64,
        y: &[f64],
        block: usize,
        dy_block: &mut [f64],
        coupling: &mut [f64],
    ) {
        let (i, j) = self.block_owner(block);
        let b = &self.bearings[i];
        let mut work = self.take();
        let len = b.model.layout().len();
        self.gather_ball(b, j, y, &mut work.y[..len]);
        coupling.fill(0.0);
        let slot = &mut coupling[i * BallCoupling::LEN..(i + 1) * BallCoupling::LEN];
        b.model.block_rhs(t, &work.y[..len], j, dy_block, slot);
        self.give(work);
    }

    fn border_rhs(&self, t: f64, y: &[f64], coupling: &[f64], dy_border: &mut [f64]) {
        let mut work = self.take();
        let (mut shaft_load, mut axial_moment) = ([0.0; 5], 0.0);
        let start = self.bearings[0].first_border;
        for (i, b) in self.bearings.iter().enumerate() {
            let l = b.model.layout();
            let (r, len) = (l.ring(), l.len());
            self.gather_border(b, y, &mut work.y[..len]);
            let slot = &coupling[i * BallCoupling::LEN..(i + 1) * BallCoupling::LEN];
            b.model
                .border_rhs(t, &work.y[..len], slot, &mut work.dy[r..len]);
            axial_moment += self.collect_border(b, &work.dy[..len], dy_border, &mut shaft_load);
        }
        self.give(work);
        let s = self.first_shaft;
        self.shaft_rhs(
            t,
            &y[s..],
            &shaft_load,
            axial_moment,
            &mut dy_border[s - start..],
        );
    }

    fn memo_len(&self) -> usize {
        self.memo_parts().1
    }

    fn block_rhs_memo(
        &self,
        t: f64,
        y: &[f64],
        block: usize,
        dy_block: &mut [f64],
        coupling: &mut [f64],
        memo: &mut [f64],
    ) {
        let (i, j) = self.block_owner(block);
        let b = &self.bearings[i];
        let (own, _) = self.memo_parts();
        let mut work = self.take();
        let len = b.model.layout().len();
        self.gather_ball(b, j, y, &mut work.y[..len]);
        coupling.fill(0.0);
        let slot = &mut coupling[i * BallCoupling::LEN..(i + 1) * BallCoupling::LEN];
        b.model
            .block_rhs_memo(t, &work.y[..len], j, dy_block, slot, &mut memo[..own]);
        self.give(work);
        memo[own..own + self.ball_len].copy_from_slice(dy_block);
        memo[own + self.ball_len..].copy_from_slice(slot);
    }

    /// A border state of another bearing leaves the block as it was (its
    /// memo); one of its own bearing reuses what the bearing's memo
    /// allows; a shaft state moves the ring and evaluates the ball again.
    fn block_rhs_border_column(
        &self,
        t: f64,
        y: &[f64],
        block: usize,
        column: usize,
        memo: &[f64],
        dy_block: &mut [f64],
        coupling: &mut [f64],
    ) {
        let (i, j) = self.block_owner(block);
        let (own, _) = self.memo_parts();
        match self.border_owner(column) {
            Some((k, _)) if k != i => {
                coupling.fill(0.0);
                dy_block.copy_from_slice(&memo[own..own + self.ball_len]);
                coupling[i * BallCoupling::LEN..(i + 1) * BallCoupling::LEN]
                    .copy_from_slice(&memo[own + self.ball_len..]);
            }
            Some((_, local)) => {
                let b = &self.bearings[i];
                let mut work = self.take();
                let len = b.model.layout().len();
                self.gather_ball(b, j, y, &mut work.y[..len]);
                coupling.fill(0.0);
                let slot = &mut coupling[i * BallCoupling::LEN..(i + 1) * BallCoupling::LEN];
                b.model.block_rhs_border_column(
                    t,
                    &work.y[..len],
                    j,
                    local,
                    &memo[..own],
                    dy_block,
                    slot,
                );
                self.give(work);
            }
            None => self.block_rhs(t, y, block, dy_block, coupling),
        }
    }

    /// The shaft's translations and tilts, its rotation angle under a
    /// torque drive, and each bearing's own positions
    /// ([`BlockSplit::rate_of`] of its model).
    fn rate_of(&self, state: usize) -> Option<usize> {
        if state >= self.first_shaft {
            return match state - self.first_shaft {
                0..5 => Some(state + 5),
                SHAFT_LEN if self.drive.is_some() => Some(state + 1),
                _ => None,
            };
        }
        for b in &self.bearings {
            let l = b.model.layout();
            let n = l.balls * self.ball_len;
            if (b.first_ball..b.first_ball + n).contains(&state) {
                return Some(b.model.rate_of(state - b.first_ball)? + b.first_ball);
            }
            if (b.first_border..b.first_border + l.len() - l.outer()).contains(&state) {
                let v = b.model.rate_of(state - b.first_border + l.outer())?;
                return Some(v - l.outer() + b.first_border);
            }
        }
        None
    }

    fn inert(&self, state: usize) -> bool {
        if state >= self.first_shaft {
            return false;
        }
        for b in &self.bearings {
            let l = b.model.layout();
            let n = l.balls * self.ball_len;
            if (b.first_ball..b.first_ball + n).contains(&state) {
                return b.model.inert(state - b.first_ball);
            }
            if (b.first_border..b.first_border + l.len() - l.outer()).contains(&state) {
                return b.model.inert(state - b.first_border + l.outer());
            }
        }
        false
    }
}
