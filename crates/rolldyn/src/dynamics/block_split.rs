//! The dynamic model's bordered block structure for the implicit
//! integrators (docs/model.md §8): one block per ball, the rings, cage and
//! energy accumulators in the border. The balls couple only through the
//! border, so the Jacobian is differenced block by block and a border
//! column re-evaluates only the contact its state reaches.

use super::ball_equations::{BallContact, ContactShare, Shares};
use super::coupling::BallCoupling;
use super::model::BearingModel;
use crate::integrate::BlockSplit;
use crate::integrate::linear::BlockLayout;

impl BlockSplit for BearingModel {
    fn block_layout(&self) -> BlockLayout {
        BlockLayout {
            blocks: self.elements.layout.balls,
            block_size: self.elements.layout.ball_len(),
            border: self.elements.layout.len() - self.elements.layout.ring(),
        }
    }

    fn coupling_len(&self) -> usize {
        BallCoupling::LEN
    }

    fn parallel(&self) -> bool {
        self.ball_pass.is_parallel()
    }

    fn block_rhs(
        &self,
        t: f64,
        y: &[f64],
        block: usize,
        dy_block: &mut [f64],
        coupling: &mut [f64],
    ) {
        self.block_rhs_from(t, y, block, dy_block, coupling, Shares::Evaluate(None));
    }

    fn border_rhs(&self, t: f64, y: &[f64], coupling: &[f64], dy_border: &mut [f64]) {
        let (inner, _) = self.elements.ring_motion(t, y);
        self.border_rhs_with(t, y, &inner, &BallCoupling::read(coupling), dy_border, None);
    }

    fn memo_len(&self) -> usize {
        ContactShare::MEMO_LEN
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
        let shares = Shares::Evaluate(Some(memo));
        self.block_rhs_from(t, y, block, dy_block, coupling, shares);
    }

    /// Only the contact the border state touches is evaluated again
    /// (`dynamics::ball_equations`).
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
        let shares = Shares::Reuse {
            memo,
            contact: BallContact::touched_by(&self.elements.layout, column),
        };
        self.block_rhs_from(t, y, block, dy_block, coupling, shares);
    }

    /// Frozen states (planar motion, a locked cage whirl, a fixed outer
    /// ring) never change, and nothing reads the energy accumulators.
    fn inert(&self, state: usize) -> bool {
        let l = self.elements.layout;
        let p = &self.elements.params;
        if state < l.ring() {
            let k = state % l.ball_len();
            return p.planar && matches!(k, 0 | 3 | 7 | 8);
        }
        if state < l.outer() {
            return p.planar && matches!(state - l.ring(), 0 | 3 | 4 | 5 | 8 | 9);
        }
        if state < l.slide() {
            return p.outer_ring.is_none();
        }
        if state < l.cage() {
            return false;
        }
        if state < l.work() {
            return !p.cage.whirl && matches!(state - l.cage(), 0 | 1 | 3 | 4);
        }
        true
    }
}
