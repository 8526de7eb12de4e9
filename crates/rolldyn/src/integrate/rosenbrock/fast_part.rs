//! The fast part's Jacobian, refreshed at every step while that pays.
//!
//! A W-method keeps its order with any matrix, so the Jacobian may be
//! assembled from parts of different ages. A system whose split has a
//! fast part f_F ([`BlockSplit::with_fast_part`]) gets
//!
//! J = (J − J_F)(t_J, y_J) + J_F(t_n, y_n),
//!
//! the slow rest from the last full Jacobian and the fast part at the
//! current point. On the default 7008C case (a whirling cage whose pocket
//! and land contacts open and close within a few steps) the steps then
//! take twice as long as with the full Jacobian alone, nearly what a new
//! full Jacobian at every step gives, for the cost of differencing the
//! pockets and the cage only (docs/performance.md).
//!
//! Where the steps are set by something else (a cage riding on its balls,
//! the balls' vibrations, the energy estimate) the refresh only costs. So
//! it runs while the fast part's own states limit the steps: over windows
//! of [`WINDOW_ATTEMPTS`] attempted steps the method counts the attempts
//! whose largest weighted error is in a fast state
//! ([`BlockSplit::fast_state`]; the bearing's cage), and refreshes during
//! the next window when their share reaches [`START_SHARE`], or, once
//! refreshing, stays above [`STOP_SHARE`] (a refresh lowers that share
//! itself). Measured: the default case's cage leads 27 % of the attempts
//! without the refresh and 18 % with it (steps halved); the 30 × 62
//! angular-contact bearing's inner-ring-guided cage 4 % and 2 % (no gain,
//! its steps follow the balls; refreshing always cost it 39 %). The
//! thresholds lie between. Counting attempts, not wall time, keeps runs
//! deterministic.
//!
//! [`BlockSplit::fast_state`]: crate::integrate::BlockSplit::fast_state
//! [`BlockSplit::with_fast_part`]: crate::integrate::BlockSplit::with_fast_part

use crate::integrate::OdeSystem;
use crate::integrate::checkpoint::{CheckpointError, StateReader, StateWriter};
use crate::integrate::jacobian::{JacobianWork, fast_part_difference};
use crate::integrate::linear::BlockJacobian;

/// Attempted steps over which the fast states' share is counted.
pub const WINDOW_ATTEMPTS: u32 = 200;

/// Share of a window's attempts led by a fast state from which the
/// refresh starts.
pub const START_SHARE: f64 = 0.10;

/// Share below which a running refresh stops.
pub const STOP_SHARE: f64 = 0.05;

/// The refresh, its matrices and its policy.
#[derive(Debug, Clone)]
pub(super) struct FastRefresh {
    /// J − J_F at the last full Jacobian.
    slow: BlockJacobian,
    /// J_F at the last refresh.
    fast: BlockJacobian,
    /// Accepted steps since J_F was differenced.
    age: u32,
    /// Whether J_F is refreshed at every step.
    refreshing: bool,
    /// Attempts in the current window, and those a fast state led.
    attempts: u32,
    led: u32,
}

impl FastRefresh {
    /// For a system whose split has a fast part; None otherwise.
    pub(super) fn of(system: &impl OdeSystem, like: &BlockJacobian) -> Option<Self> {
        let split = system.blocks()?;
        if !split.with_fast_part(&mut |_| {}) {
            return None;
        }
        Some(Self {
            slow: like.clone(),
            fast: like.clone(),
            age: 0,
            refreshing: false,
            attempts: 0,
            led: 0,
        })
    }

    /// Whether J_F is refreshed at every step now.
    pub(super) fn refreshing(&self) -> bool {
        self.refreshing
    }

    /// After a full Jacobian `full` at (t, y): while refreshing, J_F there
    /// and the slow rest J − J_F. Returns whether it differenced J_F.
    pub(super) fn split(
        &mut self,
        system: &impl OdeSystem,
        (t, y): (f64, &[f64]),
        full: &BlockJacobian,
        work: &mut JacobianWork,
    ) -> bool {
        if !self.refreshing {
            return false;
        }
        fast_part_difference(system, t, y, &mut self.fast, work);
        combine(&mut self.slow, full, &self.fast, -1.0);
        self.age = 0;
        true
    }

    /// At the start of a step: while refreshing and J_F is older than the
    /// current point, J_F at (t, y) and `jacobian` = slow + J_F. Returns
    /// whether it did.
    pub(super) fn refresh(
        &mut self,
        system: &impl OdeSystem,
        (t, y): (f64, &[f64]),
        jacobian: &mut BlockJacobian,
        work: &mut JacobianWork,
    ) -> bool {
        if !self.refreshing || self.age == 0 {
            return false;
        }
        fast_part_difference(system, t, y, &mut self.fast, work);
        combine(jacobian, &self.slow, &self.fast, 1.0);
        self.age = 0;
        true
    }

    /// After an accepted step: J_F ages.
    pub(super) fn accepted(&mut self) {
        self.age += 1;
    }

    /// After an attempted step whose largest weighted error was in a fast
    /// state (`led`) or not. Returns true when the refresh starts (the
    /// caller then evaluates a full Jacobian, which the slow rest is taken
    /// from).
    pub(super) fn attempted(&mut self, led: bool) -> bool {
        self.attempts += 1;
        self.led += u32::from(led);
        if self.attempts < WINDOW_ATTEMPTS {
            return false;
        }
        let share = f64::from(self.led) / f64::from(self.attempts);
        (self.attempts, self.led) = (0, 0);
        let was = self.refreshing;
        self.refreshing = share >= if was { STOP_SHARE } else { START_SHARE };
        self.refreshing && !was
    }

    /// A hand-over from another method: a new window, no refresh.
    pub(super) fn restart(&mut self) {
        (self.attempts, self.led) = (0, 0);
        self.refreshing = false;
    }

    pub(super) fn save(&self, out: &mut StateWriter) {
        out.tag("fast part");
        for part in [&self.slow, &self.fast] {
            for values in [&part.diag, &part.upper, &part.lower, &part.border] {
                out.f64s(values);
            }
        }
        for v in [
            u64::from(self.age),
            u64::from(self.refreshing),
            u64::from(self.attempts),
            u64::from(self.led),
        ] {
            out.u64(v);
        }
    }

    pub(super) fn restore(&mut self, input: &mut StateReader) -> Result<(), CheckpointError> {
        input.tag("fast part")?;
        for part in [&mut self.slow, &mut self.fast] {
            input.f64s_into("fast part diagonal blocks", &mut part.diag)?;
            input.f64s_into("fast part upper border", &mut part.upper)?;
            input.f64s_into("fast part lower border", &mut part.lower)?;
            input.f64s_into("fast part corner", &mut part.border)?;
        }
        let small = |v: u64, what: &str| {
            u32::try_from(v)
                .map_err(|_| CheckpointError::Mismatch(format!("{what} {v} out of range")))
        };
        self.age = small(input.u64()?, "fast part age")?;
        self.refreshing = input.u64()? != 0;
        self.attempts = small(input.u64()?, "fast part window attempts")?;
        self.led = small(input.u64()?, "fast part window lead count")?;
        Ok(())
    }
}

/// out = a + sign · b, part by part.
fn combine(out: &mut BlockJacobian, a: &BlockJacobian, b: &BlockJacobian, sign: f64) {
    for (o, (x, z)) in [
        (&mut out.diag, (&a.diag, &b.diag)),
        (&mut out.upper, (&a.upper, &b.upper)),
        (&mut out.lower, (&a.lower, &b.lower)),
        (&mut out.border, (&a.border, &b.border)),
    ] {
        for (o, (x, z)) in o.iter_mut().zip(x.iter().zip(z.iter())) {
            *o = x + sign * z;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrate::linear::BlockLayout;

    fn refresh() -> FastRefresh {
        let like = BlockJacobian::zeros(BlockLayout::dense(2));
        FastRefresh {
            slow: like.clone(),
            fast: like,
            age: 0,
            refreshing: false,
            attempts: 0,
            led: 0,
        }
    }

    /// One window in which `led` of the attempts were led by a fast state;
    /// whether the refresh started at its end.
    fn window(r: &mut FastRefresh, led: u32) -> bool {
        let mut started = false;
        for k in 0..WINDOW_ATTEMPTS {
            started |= r.attempted(k < led);
        }
        started
    }

    #[test]
    fn starts_at_the_start_share_and_stops_below_the_stop_share() {
        let mut r = refresh();
        let share = |s: f64| (s * f64::from(WINDOW_ATTEMPTS)).round() as u32;
        assert!(!window(&mut r, share(START_SHARE) - 1));
        assert!(!r.refreshing);
        assert!(window(&mut r, share(START_SHARE)), "starts");
        assert!(r.refreshing);
        // Between the shares it keeps going (the refresh lowers the share).
        assert!(!window(&mut r, share(STOP_SHARE)));
        assert!(r.refreshing);
        assert!(!window(&mut r, share(STOP_SHARE) - 1));
        assert!(!r.refreshing, "stops");
        // A hand-over from the explicit method: a new window, no refresh.
        r.attempted(true);
        r.restart();
        assert!(!r.refreshing && r.attempts == 0 && r.led == 0);
    }

    #[test]
    fn refreshes_only_a_jacobian_older_than_the_point() {
        let mut r = refresh();
        r.refreshing = true;
        r.age = 0;
        struct NoSplit;
        impl OdeSystem for NoSplit {
            fn dimension(&self) -> usize {
                2
            }
            fn rhs(&self, _t: f64, _y: &[f64], dy: &mut [f64]) {
                dy.fill(0.0);
            }
        }
        let mut work = JacobianWork::new(&NoSplit);
        let mut j = BlockJacobian::zeros(BlockLayout::dense(2));
        assert!(!r.refresh(&NoSplit, (0.0, &[0.0, 0.0]), &mut j, &mut work));
        r.accepted();
        assert!(r.refresh(&NoSplit, (0.0, &[0.0, 0.0]), &mut j, &mut work));
        assert_eq!(r.age, 0);
    }
}
