//! Time integration of ODE systems y' = f(t, y). Knows nothing of bearings
//! (the bearing model implements [`OdeSystem`], the integrator
//! advances it, observers receive samples).
//!
//! * [`OdeSystem`]: in-place right-hand side, per-state error scales, and a hook called after every **accepted** step (where the
//!   bearing model updates its contact-episode memory, docs/model.md §2.3).
//! * [`ExplicitRk`]: explicit Runge–Kutta methods from tableaus given as
//!   data ([`tableau`]): classical RK4 with a fixed step, and Dormand–Prince
//!   5(4) with error control and 4th-order dense output. All work vectors
//!   are allocated once; a step allocates nothing.
//! * [`Rosenbrock`]: linearly implicit Rosenbrock–W methods for stiff
//!   systems (ROS34PW2), with error control, dense output, and a Jacobian
//!   that is evaluated rarely ([`jacobian`]: finite differences grouped
//!   by the system's block structure) and factored by blocks ([`linear`]).
//! * [`Switching`]: ROS34PW2 and DOPRI5 in one run, each where it is
//!   cheaper by measured cost (the stiffness switch of LSODA).
//! * [`Builder`]: one shape for setting up every integrator
//!   (`Rosenbrock::builder(&ROS34PW2).relative_tolerance(1e-3).max_step(h).build(&model, &y0)`;
//!   `ExplicitRk::builder(&DOPRI5)` likewise, or `.fixed_step(h)`).
//! * [`Integrator`]: what the driver needs from an integrator; [`Solver`]
//!   is the choice among them.
//! * [`IntegrationStats`]: steps, rejected steps, RHS evaluations,
//!   Jacobian evaluations and factorizations.
//! * [`run`]: to an end time with samples at a fixed rate (dense output),
//!   a stop flag and progress callbacks; [`run_from`] continues a run
//!   restored from a [`checkpoint`] on the same sample grid.
//! * [`Checkpoint`]: the complete state of an integrator or system as
//!   bytes, so that an interrupted run continues bit-identically.

pub mod builder;
pub mod checkpoint;
pub mod driver;
pub mod energy_control;
pub mod explicit;
pub mod jacobian;
pub mod linear;
mod point;
pub mod rosenbrock;
pub mod step_control;
pub mod switching;
pub mod tableau;
#[cfg(test)]
pub(crate) mod test_systems;

pub use builder::Builder;
pub use checkpoint::{Checkpoint, CheckpointError, StateReader, StateWriter};
pub use driver::{RunEnd, RunReport, Sampling, run, run_from};
pub use energy_control::{DEFAULT_ENERGY_TOLERANCE, EnergyBalance};
pub use explicit::{ExplicitRk, StepControl};
pub use jacobian::BlockSplit;
pub use rosenbrock::{ROS34PW2, Rosenbrock, RosenbrockTableau};
pub use step_control::{IntegrationError, IntegrationStats};
pub use switching::Switching;

/// A system of first-order ODEs y' = f(t, y).
pub trait OdeSystem {
    /// Number of states.
    fn dimension(&self) -> usize;

    /// Writes f(t, y) into `dydt` (same length as `y`). Must not allocate.
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]);

    /// Characteristic magnitude of each state, written into `scale`: the
    /// size below which its error is judged absolutely. The absolute
    /// tolerance is `relative tolerance × scale`, so one relative tolerance
    /// controls every state consistently. Default: 1 for every state.
    fn error_scale(&self, scale: &mut [f64]) {
        scale.fill(1.0);
    }

    /// Marks the states whose error is judged against their scale alone,
    /// without the relative part rtol × |y|: angles that grow without
    /// bound (an orbital angle after n turns would otherwise be allowed
    /// an error of rtol × 2πn). Default: none.
    fn absolute_error(&self, _absolute: &mut [bool]) {}

    /// A name for state component `index`, for messages (an integration
    /// failure names the component with the largest error). Default
    /// `y[index]`.
    fn state_name(&self, index: usize) -> String {
        format!("y[{index}]")
    }

    /// Largest step the system allows from (t, y): features that an error
    /// estimate cannot see coming (a surface defect ahead of a contact).
    /// Asked once before each step. Default: no limit.
    fn step_limit(&self, _t: f64, _y: &[f64]) -> f64 {
        f64::INFINITY
    }

    /// Called once after every accepted step with the new state (never
    /// inside Runge–Kutta stages). Returns true when this changed the
    /// right-hand side (e.g. a contact episode was recorded), so that the
    /// integrator re-evaluates f at the new point. Default: nothing.
    fn accept_step(&mut self, _t: f64, _y: &[f64]) -> bool {
        false
    }

    /// The system's energy balance at (t, y), if it keeps one: work done on
    /// it and energy dissipated since the start (accumulated as states) and
    /// its mechanical energy. Integrators given an energy tolerance control
    /// the error of W − D − E as well as the states' ([`energy_control`]).
    /// Must not allocate. Default: none.
    fn energy_balance(&self, _t: f64, _y: &[f64]) -> Option<EnergyBalance> {
        None
    }

    /// [`Self::rhs`] at a step's candidate end (t, y), the point
    /// `accept_step` receives if the step is accepted, and with `balance`
    /// [`Self::energy_balance`] there (else None): a system may share the
    /// work of the two (the contacts' geometry) and keep what its
    /// `accept_step` needs at this point. The right-hand side is the one
    /// before acceptance; an `accept_step` that returns true has it
    /// evaluated again. Must not allocate. Default: the two apart.
    fn rhs_at_end(
        &mut self,
        t: f64,
        y: &[f64],
        dydt: &mut [f64],
        balance: bool,
    ) -> Option<EnergyBalance> {
        self.rhs(t, y, dydt);
        if balance {
            self.energy_balance(t, y)
        } else {
            None
        }
    }

    /// The block structure of the right-hand side, if it has one: implicit
    /// methods then differentiate and factor by blocks. Default: none
    /// (a dense Jacobian).
    fn blocks(&self) -> Option<&dyn BlockSplit> {
        None
    }
}

/// Error tolerances per state (Hairer, Nørsett & Wanner I §II.4): a
/// state's error is measured against atol_k + rtol_k |y_k|, with atol_k =
/// rtol × its [`OdeSystem::error_scale`] and rtol_k = rtol, or 0 for the
/// states of [`OdeSystem::absolute_error`].
#[derive(Debug, Clone)]
pub(crate) struct Tolerances {
    absolute: Vec<f64>,
    relative: Vec<f64>,
}

impl Tolerances {
    pub(crate) fn new(system: &impl OdeSystem, rtol: f64) -> Self {
        let n = system.dimension();
        let mut absolute = vec![0.0; n];
        system.error_scale(&mut absolute);
        absolute.iter_mut().for_each(|a| *a *= rtol);
        let mut flags = vec![false; n];
        system.absolute_error(&mut flags);
        let relative = flags.iter().map(|&a| if a { 0.0 } else { rtol }).collect();
        Self { absolute, relative }
    }

    /// The error scale of state k whose magnitude is `magnitude`.
    #[inline]
    pub(crate) fn scale(&self, k: usize, magnitude: f64) -> f64 {
        self.absolute[k] + self.relative[k] * magnitude
    }
}

/// What the driver needs from an integrator.
pub trait Integrator {
    /// Current time.
    fn t(&self) -> f64;
    /// Current state.
    fn y(&self) -> &[f64];
    /// Takes one accepted step, not beyond `t_limit`.
    fn step<S: OdeSystem>(&mut self, system: &mut S, t_limit: f64) -> Result<(), IntegrationError>;
    /// The state at `t` within the last accepted step.
    fn interpolate(&self, t: f64, out: &mut [f64]);
    /// Counters so far.
    fn stats(&self) -> IntegrationStats;
}

/// An integrator chosen at run time (e.g. from a case file).
#[derive(Debug, Clone)]
pub enum Solver {
    /// Explicit Runge–Kutta.
    Explicit(Box<ExplicitRk>),
    /// Linearly implicit Rosenbrock–W.
    Rosenbrock(Box<Rosenbrock>),
    /// Both, switched by their measured cost ([`switching`]).
    Switching(Box<Switching>),
}

impl Checkpoint for Solver {
    fn save(&self, out: &mut StateWriter) {
        match self {
            Self::Explicit(i) => i.save(out),
            Self::Rosenbrock(i) => i.save(out),
            Self::Switching(i) => i.save(out),
        }
    }
    fn restore(&mut self, input: &mut StateReader) -> Result<(), CheckpointError> {
        match self {
            Self::Explicit(i) => i.restore(input),
            Self::Rosenbrock(i) => i.restore(input),
            Self::Switching(i) => i.restore(input),
        }
    }
}

impl Integrator for Solver {
    fn t(&self) -> f64 {
        match self {
            Self::Explicit(i) => i.t(),
            Self::Rosenbrock(i) => i.t(),
            Self::Switching(i) => i.t(),
        }
    }
    fn y(&self) -> &[f64] {
        match self {
            Self::Explicit(i) => i.y(),
            Self::Rosenbrock(i) => i.y(),
            Self::Switching(i) => i.y(),
        }
    }
    fn step<S: OdeSystem>(&mut self, system: &mut S, t_limit: f64) -> Result<(), IntegrationError> {
        match self {
            Self::Explicit(i) => i.step(system, t_limit),
            Self::Rosenbrock(i) => i.step(system, t_limit),
            Self::Switching(i) => i.step(system, t_limit),
        }
    }
    fn interpolate(&self, t: f64, out: &mut [f64]) {
        match self {
            Self::Explicit(i) => i.interpolate(t, out),
            Self::Rosenbrock(i) => i.interpolate(t, out),
            Self::Switching(i) => i.interpolate(t, out),
        }
    }
    fn stats(&self) -> IntegrationStats {
        match self {
            Self::Explicit(i) => i.stats(),
            Self::Rosenbrock(i) => i.stats(),
            Self::Switching(i) => i.stats(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An angle turning at 100 rad/s beside a position: the angle is
    /// judged absolutely.
    struct Turning;
    impl OdeSystem for Turning {
        fn dimension(&self) -> usize {
            2
        }
        fn rhs(&self, _t: f64, _y: &[f64], dy: &mut [f64]) {
            dy.copy_from_slice(&[1.0, 100.0]);
        }
        fn error_scale(&self, scale: &mut [f64]) {
            scale.copy_from_slice(&[1e-6, 1e-4]);
        }
        fn absolute_error(&self, absolute: &mut [bool]) {
            absolute[1] = true;
        }
    }

    #[test]
    fn absolute_states_have_no_relative_part() {
        let tol = Tolerances::new(&Turning, 1e-2);
        // Position: atol + rtol |y|.
        assert!((tol.scale(0, 3.0) - (1e-8 + 3e-2)).abs() < 1e-15);
        // Angle after many turns: atol only.
        assert_eq!(tol.scale(1, 1000.0), tol.scale(1, 0.0));
        assert!((tol.scale(1, 1000.0) - 1e-6).abs() < 1e-18);
    }
}
