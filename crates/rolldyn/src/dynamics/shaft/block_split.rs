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

    /// Evaluates ball `j` of bearing `i` by `f`: on the bearing's own
    /// state (that ball and the border, gathered from `y`) and with the
    /// bearing's slot of `coupling` (the others' slots zeroed).
    fn on_ball<R>(
        &self,
        (i, j): (usize, usize),
        y: &[f64],
        coupling: &mut [f64],
        f: impl FnOnce(&Mounted, &[f64], &mut [f64]) -> R,
    ) -> R {
        let b = &self.bearings[i];
        let mut work = self.take();
        let len = b.model.layout().len();
        self.gather_ball(b, j, y, &mut work.y[..len]);
        coupling.fill(0.0);
        let slot = &mut coupling[i * BallCoupling::LEN..(i + 1) * BallCoupling::LEN];
        let out = f(b, &work.y[..len], slot);
        self.give(work);
        out
    }

    /// A state of the system as a bearing's and the index in that bearing's
    /// own model (its balls, then its border from the outer ring on: the
    /// inner ring's states are the shaft's); None for the shaft's states.
    fn model_state(&self, state: usize) -> Option<(&Mounted, usize)> {
        if state >= self.first_shaft {
            return None;
        }
        self.bearings.iter().find_map(|b| {
            let l = b.model.layout();
            let n = l.balls * self.ball_len;
            if (b.first_ball..b.first_ball + n).contains(&state) {
                Some((b, state - b.first_ball))
            } else if (b.first_border..b.first_border + l.len() - l.outer()).contains(&state) {
                Some((b, state - b.first_border + l.outer()))
            } else {
                None
            }
        })
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
        self.on_ball((i, j), y, coupling, |b, own, slot| {
            b.model.block_rhs(t, own, j, dy_block, slot)
        });
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
        let (own, _) = self.memo_parts();
        self.on_ball((i, j), y, coupling, |b, state, slot| {
            b.model
                .block_rhs_memo(t, state, j, dy_block, slot, &mut memo[..own]);
            memo[own..own + self.ball_len].copy_from_slice(dy_block);
            memo[own + self.ball_len..].copy_from_slice(slot);
        });
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
            Some((_, local)) => self.on_ball((i, j), y, coupling, |b, state, slot| {
                b.model
                    .block_rhs_border_column(t, state, j, local, &memo[..own], dy_block, slot)
            }),
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
        // A ball's rate is a state of the same ball, a border state's one
        // of the same border.
        let (b, local) = self.model_state(state)?;
        let rate = b.model.rate_of(local)?;
        let outer = b.model.layout().outer();
        Some(if local < outer {
            rate + b.first_ball
        } else {
            rate - outer + b.first_border
        })
    }

    fn inert(&self, state: usize) -> bool {
        self.model_state(state)
            .is_some_and(|(b, local)| b.model.inert(local))
    }
}
