//! The dynamic model's bordered block structure for the implicit
//! integrators (docs/model.md §8): one block per ball, the rings, cage and
//! energy accumulators in the border. The balls couple only through the
//! border, so the Jacobian is differenced block by block and a border
//! column re-evaluates only the contact its state reaches.
//!
//! The split's fast part ([`BlockSplit::with_fast_part`]) is the pockets'
//! terms in the balls' equations and the border's equations (the cage
//! with its guidance, the rings) with the pockets' coupling: the balls'
//! raceway contacts, gravity, drag and frame terms are the slow rest. Its
//! Jacobian changes fastest (a whirling cage's pocket and land contacts
//! open and close within a few steps) and costs least to difference (no
//! traction over the contact ellipses, no ring motion, and a ball whose
//! pocket is open adds nothing: [`BlockSplit::block_is_zero`]), so the
//! Rosenbrock–W method refreshes it at every step while it pays
//! (`integrate::rosenbrock`, docs/dynamics.md "Integration"). Offered
//! when the raceway contacts integrate traction over a grid (otherwise
//! they cost about what the rest does).

use super::ball_equations::{BallContact, ContactShare, Part, Shares};
use super::coupling::BallCoupling;
use super::model::BearingModel;
use crate::integrate::BlockSplit;
use crate::integrate::linear::BlockLayout;

/// The model's split restricted to `part`'s contacts.
struct PartOf<'a> {
    model: &'a BearingModel,
    part: Part,
}

impl BlockSplit for BearingModel {
    fn block_layout(&self) -> BlockLayout {
        self.whole().block_layout()
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
        self.whole().block_rhs(t, y, block, dy_block, coupling);
    }

    fn border_rhs(&self, t: f64, y: &[f64], coupling: &[f64], dy_border: &mut [f64]) {
        self.whole().border_rhs(t, y, coupling, dy_border);
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
        self.whole()
            .block_rhs_memo(t, y, block, dy_block, coupling, memo);
    }

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
        self.whole()
            .block_rhs_border_column(t, y, block, column, memo, dy_block, coupling);
    }

    fn inert(&self, state: usize) -> bool {
        self.whole().inert(state)
    }

    /// The positions and their velocities (docs/model.md §1): a ball's
    /// x, r, φ; the inner ring's translations and tilts, its rotation
    /// angle under a torque drive; the outer ring's position in a
    /// compliant housing, its axial position when it slides; the cage's
    /// centre and angle. Not where a frozen state's rate is held at zero
    /// (planar motion, a cage without whirl, no housing).
    fn rate_of(&self, state: usize) -> Option<usize> {
        let l = self.elements.layout;
        let p = &self.elements.params;
        if state < l.ring() {
            let k = state % l.ball_len();
            return match k {
                0 if p.planar => None,
                0..=2 => Some(state + 3),
                _ => None,
            };
        }
        if state < l.spin() {
            return match state - l.ring() {
                k if p.inner_ring_state_frozen(k) => None,
                k @ 0..=4 => Some(l.ring() + k + 5),
                _ => None,
            };
        }
        if state < l.outer() {
            return (state == l.spin()).then_some(state + 1);
        }
        if state < l.slide() {
            return (p.outer_ring.is_some() && state < l.outer() + 2).then_some(state + 2);
        }
        if state < l.cage() {
            return (state == l.slide()).then_some(state + 1);
        }
        match state.checked_sub(l.cage())? {
            2 => Some(state + 3),
            0 | 1 if p.cage.whirl => Some(state + 3),
            _ => None,
        }
    }

    /// The cage's states.
    fn fast_state(&self, state: usize) -> bool {
        let layout = &self.elements.layout;
        (layout.cage()..layout.work()).contains(&state)
    }

    fn with_fast_part(&self, with: &mut dyn FnMut(&dyn BlockSplit)) -> bool {
        if !self.ball_pass.expensive_contacts() {
            return false;
        }
        with(&PartOf {
            model: self,
            part: Part::Fast,
        });
        true
    }
}

impl BearingModel {
    /// The split with all the contacts.
    fn whole(&self) -> PartOf<'_> {
        PartOf {
            model: self,
            part: Part::Whole,
        }
    }
}

impl BlockSplit for PartOf<'_> {
    fn block_layout(&self) -> BlockLayout {
        let layout = &self.model.elements.layout;
        BlockLayout {
            blocks: layout.balls,
            block_size: layout.ball_len(),
            border: layout.len() - layout.ring(),
        }
    }

    fn coupling_len(&self) -> usize {
        BallCoupling::LEN
    }

    fn parallel(&self) -> bool {
        self.model.ball_pass.is_parallel()
    }

    /// The fast part of a ball whose pocket is open.
    fn block_is_zero(&self, _t: f64, y: &[f64], block: usize) -> bool {
        self.part == Part::Fast && self.model.pocket_open(block, y)
    }

    /// Without the raceway contacts the balls do not read the rings.
    fn blocks_read(&self, border_state: usize) -> bool {
        let layout = &self.model.elements.layout;
        self.part == Part::Whole || layout.ring() + border_state >= layout.cage()
    }

    fn block_rhs(
        &self,
        t: f64,
        y: &[f64],
        block: usize,
        dy_block: &mut [f64],
        coupling: &mut [f64],
    ) {
        let shares = Shares::Evaluate(None);
        self.model
            .block_rhs_from(t, y, block, dy_block, coupling, shares, self.part);
    }

    fn border_rhs(&self, t: f64, y: &[f64], coupling: &[f64], dy_border: &mut [f64]) {
        let (inner, _) = self.model.elements.ring_motion(t, y);
        let coupling = BallCoupling::read(coupling);
        self.model
            .border_rhs_with(t, y, &inner, &coupling, dy_border, None);
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
        self.model
            .block_rhs_from(t, y, block, dy_block, coupling, shares, self.part);
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
            contact: BallContact::touched_by(&self.model.elements.layout, column),
        };
        self.model
            .block_rhs_from(t, y, block, dy_block, coupling, shares, self.part);
    }

    /// Frozen states (planar motion, a locked cage whirl, a fixed outer
    /// ring) never change, and nothing reads the energy accumulators.
    fn inert(&self, state: usize) -> bool {
        let l = self.model.elements.layout;
        let p = &self.model.elements.params;
        if state < l.ring() {
            let k = state % l.ball_len();
            return p.planar && matches!(k, 0 | 3 | 7 | 8);
        }
        if state < l.outer() {
            return p.inner_ring_state_frozen(state - l.ring());
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
