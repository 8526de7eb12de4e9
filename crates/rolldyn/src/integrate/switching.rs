//! Automatic choice between a stiff and an explicit method, by their
//! measured cost.
//!
//! A bearing run changes character as it goes. Between defect impacts
//! the stiff Rosenbrock–W method (ROS34PW2) takes steps hundreds of times
//! longer than DOPRI5's stability limit, set by the traction slopes. After
//! a ball strikes a spall edge, the contact and ring vibrations it excites
//! ring on (an undamped Hertz contact has nothing to damp them) and the
//! L-stable method must resolve them finely to keep the energy balance,
//! while DOPRI5, held by the same traction slopes to steps of a fraction
//! of a microsecond, resolves them anyway and damps nothing. Measured on
//! the 6205 preset with a deep outer-race spall: before the first impact
//! ROS34PW2 took 290 steps in 5 ms against DOPRI5's 18 881; from 10 to
//! 20 ms 137 000 against 39 000 (docs/dynamics.md).
//!
//! The switch follows the stiffness-switching idea of LSODA (Petzold
//! 1983, *SIAM J. Sci. Stat. Comput.* 4: 136–148): run one method, know
//! what the other would cost, change when the other is cheaper. LSODA
//! predicts the other method's step from error constants; here the cost
//! of each method is measured over windows of [`WINDOW_STEPS`] accepted
//! steps (the second half of each, after the step size has settled from
//! a hand-over), in right-hand-side evaluations per simulated second (a
//! Jacobian column group and a factorization count as one evaluation each:
//! on the 6205 preset a factorization costs 1.6, with EHL traction less).
//! Counting evaluations, not wall time, keeps the run deterministic.
//!
//! * The run starts with the stiff method. When its cost rises above
//!   [`REGIME_CHANGE`] times the lowest it has had (an impact, ringing),
//!   the explicit method gets a trial window, and keeps the run when it
//!   costs less by the margin [`HYSTERESIS`]; later the stiff method hands
//!   over whenever such a rise puts its cost above the explicit cost last
//!   measured (the explicit step is bounded by stability, so its cost
//!   varies little along a run).
//! * The explicit method tries the stiff one again after a number of
//!   windows that doubles after every trial the stiff method loses (up to
//!   [`MAX_WAIT_WINDOWS`]) and returns to one when it wins: the stiff
//!   cost changes with the motion (ringing dies out, a ball leaves the
//!   load zone) and can only be known by trying.
//! * An explicit step that fails (stiffness beyond its reach) hands the
//!   run back to the stiff method for good.
//!
//! A hand-over restarts the receiving method at the current point with the
//! current step: its first-stage derivative evaluated afresh, a new
//! Jacobian for the stiff method, the energy-balance control's bookkeeping
//! carried over.

use super::checkpoint::{CheckpointError, StateReader, StateWriter};
use super::{
    Checkpoint, ExplicitRk, IntegrationError, IntegrationStats, Integrator, OdeSystem, Rosenbrock,
};

/// Accepted steps over which a method's cost is measured.
pub const WINDOW_STEPS: u32 = 100;

/// The stiff method hands over when it costs more than this multiple of
/// the explicit method's last measured cost (and the explicit method
/// keeps a trial only when it costs less than the stiff one divided by
/// it): a margin against switching back and forth on noise.
pub const HYSTERESIS: f64 = 1.25;

/// The stiff method's cost per simulated second, relative to the lowest
/// it has had in the run, above which the explicit method is considered:
/// an impact, the ringing after it, a ball entering a spall. Below it the
/// stiff method runs on, and a smooth run never pays for a trial (the
/// explicit method's own traces, vibrations at the tolerance in lightly
/// damped modes, then cost the stiff method more when it takes over
/// again: measured on the default case, 3 µs steps for a millisecond
/// instead of 100 µs).
pub const REGIME_CHANGE: f64 = 4.0;

/// Longest wait, in windows, between trials of the stiff method while the
/// explicit one runs.
pub const MAX_WAIT_WINDOWS: u32 = 64;

/// Which method is active.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Active {
    Stiff,
    Explicit,
}

/// What the switch remembers between windows.
#[derive(Debug, Clone, Copy)]
struct Policy {
    active: Active,
    /// The method for the next step.
    next: Active,
    /// Start of the measured half of the current window: time and total
    /// cost so far.
    window_t: f64,
    window_cost: f64,
    window_steps: u32,
    /// The current window is a trial of the active method.
    trial: bool,
    /// Last measured cost per simulated second \[1/s\] of each method,
    /// and the stiff method's lowest.
    stiff_rate: Option<f64>,
    lowest_stiff_rate: f64,
    explicit_rate: Option<f64>,
    /// Windows until the explicit method tries the stiff one again, and
    /// the current wait after lost trials.
    wait: u32,
    backoff: u32,
    /// Hand-overs so far.
    switches: u64,
}

/// ROS34PW2 and DOPRI5 (or any stiff and explicit pair), switched by cost.
#[derive(Debug, Clone)]
pub struct Switching {
    stiff: Rosenbrock,
    explicit: ExplicitRk,
    policy: Policy,
}

/// Cost of a method's work so far in right-hand-side evaluations.
fn cost(stats: IntegrationStats) -> f64 {
    (stats.rhs_evaluations + stats.jacobian_rhs_evaluations + stats.factorizations) as f64
}

impl Switching {
    /// The pair, both set up at the same initial point (with the same
    /// energy control, if any); the stiff method starts.
    pub fn new(stiff: Rosenbrock, explicit: ExplicitRk) -> Self {
        let window_t = stiff.t();
        Self {
            policy: Policy {
                active: Active::Stiff,
                next: Active::Stiff,
                window_t,
                window_cost: 0.0,
                window_steps: 0,
                trial: false,
                stiff_rate: None,
                lowest_stiff_rate: f64::INFINITY,
                explicit_rate: None,
                wait: 0,
                backoff: 1,
                switches: 0,
            },
            stiff,
            explicit,
        }
    }

    /// Hand-overs between the methods so far.
    pub fn switches(&self) -> u64 {
        self.policy.switches
    }

    /// Whether the explicit method is the active one.
    pub fn explicit_active(&self) -> bool {
        self.policy.active == Active::Explicit
    }

    /// Accepted steps of (stiff, explicit) method so far.
    pub fn steps_by_method(&self) -> (u64, u64) {
        (self.stiff.stats().steps, self.explicit.stats().steps)
    }

    fn total_cost(&self) -> f64 {
        cost(self.stiff.stats()) + cost(self.explicit.stats())
    }

    /// Counts an accepted step; when it closes a window, measures the
    /// active method's cost and chooses the method for the next step.
    fn after_step(&mut self) {
        self.policy.window_steps += 1;
        if self.policy.window_steps == WINDOW_STEPS / 2 {
            // The first half settles the step size after a hand-over; the
            // cost is measured over the second.
            self.policy.window_t = self.t();
            self.policy.window_cost = self.total_cost();
        }
        if self.policy.window_steps < WINDOW_STEPS {
            return;
        }
        let (t, total) = (self.t(), self.total_cost());
        let p = &mut self.policy;
        let rate = (total - p.window_cost) / (t - p.window_t).max(f64::MIN_POSITIVE);
        let was_trial = std::mem::replace(&mut p.trial, false);
        p.next = match p.active {
            Active::Stiff => {
                p.stiff_rate = Some(rate);
                let lowest = p.lowest_stiff_rate.min(rate);
                p.lowest_stiff_rate = lowest;
                // Only a regime change can make the explicit method cheaper.
                let changed = rate > REGIME_CHANGE * lowest;
                match p.explicit_rate {
                    // The explicit cost is not known yet: try it.
                    None if changed => {
                        p.trial = true;
                        Active::Explicit
                    }
                    Some(explicit) if (changed || was_trial) && rate > HYSTERESIS * explicit => {
                        if was_trial {
                            // The stiff method lost its trial.
                            p.backoff = (2 * p.backoff).min(MAX_WAIT_WINDOWS);
                        }
                        Active::Explicit
                    }
                    _ => {
                        if was_trial {
                            p.backoff = 1;
                        }
                        Active::Stiff
                    }
                }
            }
            Active::Explicit => {
                p.explicit_rate = Some(rate);
                let stiff = p.stiff_rate.unwrap_or(f64::INFINITY);
                if was_trial && HYSTERESIS * rate > stiff {
                    // The explicit method lost its trial.
                    Active::Stiff
                } else if p.wait == 0 {
                    p.trial = true;
                    Active::Stiff
                } else {
                    p.wait -= 1;
                    Active::Explicit
                }
            }
        };
        if p.next == Active::Explicit && p.active == Active::Stiff {
            p.wait = p.backoff;
        }
        p.window_t = t;
        p.window_cost = total;
        p.window_steps = 0;
    }

    /// Makes the chosen method the active one at the current point.
    fn hand_over(&mut self, system: &impl OdeSystem) {
        let next = self.policy.next;
        if next == self.policy.active {
            return;
        }
        match next {
            Active::Explicit => {
                let (t, h) = (self.stiff.t(), self.stiff.step_size());
                let energy = self.stiff.energy_control();
                self.explicit.restart(system, t, self.stiff.y(), h, energy);
            }
            Active::Stiff => {
                let (t, h) = (self.explicit.t(), self.explicit.step_size());
                let energy = self.explicit.energy_control();
                self.stiff.restart(system, t, self.explicit.y(), h, energy);
            }
        }
        self.policy.active = next;
        self.policy.switches += 1;
    }
}

impl Integrator for Switching {
    fn t(&self) -> f64 {
        match self.policy.active {
            Active::Stiff => self.stiff.t(),
            Active::Explicit => self.explicit.t(),
        }
    }

    fn y(&self) -> &[f64] {
        match self.policy.active {
            Active::Stiff => self.stiff.y(),
            Active::Explicit => self.explicit.y(),
        }
    }

    /// One accepted step of the active method; a window that closes with
    /// it may hand over to the other method for the next step.
    fn step<S: OdeSystem>(&mut self, system: &mut S, t_limit: f64) -> Result<(), IntegrationError> {
        if self.t() >= t_limit {
            return Ok(());
        }
        // The hand-over chosen after the last step happens now, so that
        // the last step's dense output stayed with the method that took it.
        self.hand_over(system);
        match self.policy.active {
            Active::Stiff => self.stiff.step(system, t_limit)?,
            Active::Explicit => {
                if self.explicit.step(system, t_limit).is_err() {
                    // Stiffness beyond the explicit method's reach (its
                    // step fell below the time resolution, or its stages
                    // overflowed): the stiff method takes over from the
                    // last accepted point and keeps the run for good.
                    let p = &mut self.policy;
                    p.explicit_rate = Some(f64::INFINITY);
                    (p.next, p.trial, p.window_steps) = (Active::Stiff, false, 0);
                    self.hand_over(system);
                    self.policy.window_t = self.t();
                    self.policy.window_cost = self.total_cost();
                    self.stiff.step(system, t_limit)?;
                }
            }
        }
        self.after_step();
        Ok(())
    }

    fn interpolate(&self, t: f64, out: &mut [f64]) {
        match self.policy.active {
            Active::Stiff => self.stiff.interpolate(t, out),
            Active::Explicit => self.explicit.interpolate(t, out),
        }
    }

    fn stats(&self) -> IntegrationStats {
        let (a, b) = (self.stiff.stats(), self.explicit.stats());
        IntegrationStats {
            steps: a.steps + b.steps,
            rejected_steps: a.rejected_steps + b.rejected_steps,
            rhs_evaluations: a.rhs_evaluations + b.rhs_evaluations,
            jacobian_evaluations: a.jacobian_evaluations + b.jacobian_evaluations,
            jacobian_rhs_evaluations: a.jacobian_rhs_evaluations + b.jacobian_rhs_evaluations,
            factorizations: a.factorizations + b.factorizations,
            fast_part_jacobians: a.fast_part_jacobians + b.fast_part_jacobians,
        }
    }
}

impl Checkpoint for Switching {
    fn save(&self, out: &mut StateWriter) {
        let p = &self.policy;
        out.tag("switching");
        let code = |a: Active| u64::from(a == Active::Explicit);
        for v in [
            code(p.active),
            code(p.next),
            u64::from(p.window_steps),
            u64::from(p.trial),
            u64::from(p.wait),
            u64::from(p.backoff),
            p.switches,
        ] {
            out.u64(v);
        }
        out.f64(p.window_t);
        out.f64(p.window_cost);
        out.opt_f64(p.stiff_rate);
        out.f64(p.lowest_stiff_rate);
        out.opt_f64(p.explicit_rate);
        self.stiff.save(out);
        self.explicit.save(out);
    }

    fn restore(&mut self, input: &mut StateReader) -> Result<(), CheckpointError> {
        input.tag("switching")?;
        let active = |v: u64| {
            if v == 1 {
                Active::Explicit
            } else {
                Active::Stiff
            }
        };
        let small = |v: u64, what: &str| {
            u32::try_from(v).map_err(|_| {
                CheckpointError::Mismatch(format!("switching {what} {v} out of range"))
            })
        };
        let p = &mut self.policy;
        p.active = active(input.u64()?);
        p.next = active(input.u64()?);
        p.window_steps = small(input.u64()?, "window")?;
        p.trial = input.u64()? == 1;
        p.wait = small(input.u64()?, "wait")?;
        p.backoff = small(input.u64()?, "backoff")?;
        p.switches = input.u64()?;
        p.window_t = input.f64()?;
        p.window_cost = input.f64()?;
        p.stiff_rate = input.opt_f64()?;
        p.lowest_stiff_rate = input.f64()?;
        p.explicit_rate = input.opt_f64()?;
        self.stiff.restore(input)?;
        self.explicit.restore(input)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrate::tableau::DOPRI5;
    use crate::integrate::{ROS34PW2, StepControl};

    /// A stiff relaxation z' = −k (z − sin t) beside an undamped oscillator
    /// x'' = −ω² x + F(t) that a short pulse F at t = 50 ms sets ringing:
    /// smooth and stiff before the pulse (the stiff method's long steps
    /// win), a resolved vibration after it (the explicit method, bounded
    /// by k, wins), as a bearing before and after a spall impact.
    struct Struck;
    impl Struck {
        const K: f64 = 1e5;
        const OMEGA: f64 = 1e4;
        fn pulse(t: f64) -> f64 {
            1e4 * (-((t - 0.05) / 1e-4).powi(2)).exp()
        }
    }
    impl OdeSystem for Struck {
        fn dimension(&self) -> usize {
            3
        }
        fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
            dy[0] = -Self::K * (y[0] - t.sin());
            dy[1] = y[2];
            dy[2] = -Self::OMEGA * Self::OMEGA * y[1] + Self::pulse(t);
        }
        fn error_scale(&self, scale: &mut [f64]) {
            scale.copy_from_slice(&[1.0, 1e-4, 1.0]);
        }
    }

    const RTOL: f64 = 1e-5;
    const END: f64 = 0.1;

    fn stiff() -> Rosenbrock {
        Rosenbrock::builder(&ROS34PW2)
            .relative_tolerance(RTOL)
            .max_step(1e-3)
            .build(&Struck, &[0.0; 3])
            .unwrap()
    }

    fn explicit(rtol: f64) -> ExplicitRk {
        let control = StepControl::Adaptive {
            relative_tolerance: rtol,
            max_step: 1e-3,
            initial_step: None,
        };
        ExplicitRk::builder(&DOPRI5)
            .control(control)
            .build(&Struck, &[0.0; 3])
            .unwrap()
    }

    fn run_to(integrator: &mut impl Integrator, end: f64) {
        while integrator.t() < end {
            integrator.step(&mut Struck, end).unwrap();
        }
    }

    #[test]
    fn each_method_runs_where_it_is_cheaper() {
        let mut auto = Switching::new(stiff(), explicit(RTOL));
        run_to(&mut auto, END);
        let (mut ros, mut dopri) = (stiff(), explicit(RTOL));
        run_to(&mut ros, END);
        run_to(&mut dopri, END);
        let mut reference = explicit(1e-10);
        run_to(&mut reference, END);
        // Before the pulse the stiff method runs alone; after it the
        // explicit one takes over.
        let (stiff_steps, explicit_steps) = auto.steps_by_method();
        assert!(auto.switches() >= 1 && stiff_steps > 0 && explicit_steps > 0);
        assert!(
            auto.explicit_active(),
            "the ringing ends with the stiff method"
        );
        // Cheaper than either alone (the trials included).
        let c = |s: IntegrationStats| cost(s);
        let (c_auto, c_ros, c_dopri) = (c(auto.stats()), c(ros.stats()), c(dopri.stats()));
        assert!(
            c_auto < 0.8 * c_ros.min(c_dopri),
            "auto {c_auto}, ros34pw2 {c_ros}, dopri5 {c_dopri}"
        );
        // And as accurate as its tolerance asks: the oscillator's
        // amplitude ≈ 1e-4 after the pulse.
        for (k, scale) in [(0, 1.0), (1, 1e-4), (2, 1.0)] {
            let err = (auto.y()[k] - reference.y()[k]).abs() / scale;
            assert!(err < 100.0 * RTOL, "state {k}: error {err:e}");
        }
    }

    /// `Struck` with a relaxation far too stiff for any explicit step.
    struct Rigid;
    impl OdeSystem for Rigid {
        fn dimension(&self) -> usize {
            4
        }
        fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
            Struck.rhs(t, &y[..3], &mut dy[..3]);
            dy[3] = -1e19 * (y[3] - t.sin());
        }
        fn error_scale(&self, scale: &mut [f64]) {
            scale.copy_from_slice(&[1.0, 1e-4, 1.0, 1.0]);
        }
    }

    #[test]
    fn an_explicit_method_out_of_its_depth_hands_back_for_good() {
        let stiff = Rosenbrock::builder(&ROS34PW2)
            .relative_tolerance(RTOL)
            .max_step(1e-3)
            .build(&Rigid, &[0.0; 4])
            .unwrap();
        let control = StepControl::Adaptive {
            relative_tolerance: RTOL,
            max_step: 1e-3,
            initial_step: None,
        };
        let explicit = ExplicitRk::builder(&DOPRI5)
            .control(control)
            .build(&Rigid, &[0.0; 4])
            .unwrap();
        let mut auto = Switching::new(stiff, explicit);
        while auto.t() < END {
            auto.step(&mut Rigid, END).unwrap();
        }
        // It tried the explicit method after the pulse, which failed.
        assert!(auto.switches() >= 2, "{} switches", auto.switches());
        assert!(!auto.explicit_active());
        assert_eq!(auto.steps_by_method().1, 0);
        assert!((auto.y()[3] - END.sin()).abs() < 1e-6);
    }

    #[test]
    fn a_smooth_run_never_leaves_the_stiff_method() {
        let mut auto = Switching::new(stiff(), explicit(RTOL));
        run_to(&mut auto, 0.045);
        assert_eq!(auto.switches(), 0);
        assert_eq!(auto.steps_by_method().1, 0);
    }

    #[test]
    fn a_restored_run_continues_bit_identically() {
        let mut whole = Switching::new(stiff(), explicit(RTOL));
        run_to(&mut whole, 0.06);
        let mut out = StateWriter::new();
        whole.save(&mut out);
        let bytes = out.into_bytes();
        run_to(&mut whole, END);
        let mut resumed = Switching::new(stiff(), explicit(RTOL));
        resumed.restore(&mut StateReader::new(&bytes)).unwrap();
        run_to(&mut resumed, END);
        assert_eq!(whole.y(), resumed.y());
        assert_eq!(whole.stats(), resumed.stats());
        assert_eq!(whole.switches(), resumed.switches());
    }
}
