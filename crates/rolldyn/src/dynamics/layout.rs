//! Layout of the dynamic state vector (MODEL §1).

/// Offsets of the parts of the state vector.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StateLayout {
    /// Number of balls.
    pub balls: usize,
    /// Whether each ball carries its spin angle ψ (10th ball state, MODEL
    /// §1): only when the balls have surfaces (waviness, spalls).
    pub ball_spin_angle: bool,
}

impl StateLayout {
    /// Mechanical states per ball (x, r, φ, their rates, ω_x, ω_r, ω_t).
    pub const BALL: usize = 9;
    /// Offset of the spin angle ψ in a ball's block, when present.
    pub const SPIN_ANGLE: usize = 9;
    /// Inner-ring states.
    pub const RING: usize = 10;
    /// Outer-ring states (y_o, z_o and rates).
    pub const OUTER: usize = 4;
    /// Cage states.
    pub const CAGE: usize = 6;
    /// States per ball: 9, or 10 with the spin angle.
    pub fn ball_len(&self) -> usize {
        Self::BALL + usize::from(self.ball_spin_angle)
    }
    /// First state of ball j.
    pub fn ball(&self, j: usize) -> usize {
        self.ball_len() * j
    }
    /// First inner-ring state.
    pub fn ring(&self) -> usize {
        self.ball_len() * self.balls
    }
    /// First outer-ring state.
    pub fn outer(&self) -> usize {
        self.ring() + Self::RING
    }
    /// First cage state.
    pub fn cage(&self) -> usize {
        self.outer() + Self::OUTER
    }
    /// The states that the contacts of ball j touch (read or write): its
    /// own block, both rings and the cage. Nothing else couples the balls,
    /// so the Jacobian is bordered block-diagonal (MODEL §8).
    pub fn ball_coupling(&self, j: usize) -> [std::ops::Range<usize>; 2] {
        [
            self.ball(j)..self.ball(j) + self.ball_len(),
            self.ring()..self.cage() + Self::CAGE,
        ]
    }
    /// The two energy accumulators: drive work and dissipated energy \[J\].
    pub fn work(&self) -> usize {
        self.cage() + Self::CAGE
    }
    /// Total number of states.
    pub fn len(&self) -> usize {
        self.work() + 2
    }
    /// Whether there are no states (never, for a valid bearing).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}
