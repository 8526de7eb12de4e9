//! Time integration of ODE systems y' = f(t, y). Knows nothing of bearings
//! (CODE.md: the bearing model implements [`OdeSystem`], the integrator
//! advances it, observers receive samples).
//!
//! * [`OdeSystem`]: in-place right-hand side, per-state error scales, and a hook called after every **accepted** step (where the
//!   bearing model updates its contact-episode memory, MODEL §2.3).
//! * [`ExplicitRk`]: explicit Runge–Kutta methods from tableaus given as
//!   data ([`tableau`]): classical RK4 with a fixed step, and Dormand–Prince
//!   5(4) with error control and 4th-order dense output. All work vectors
//!   are allocated once; a step allocates nothing.
//! * [`IntegrationStats`]: steps, rejected steps, RHS evaluations.
//! * [`run`]: to an end time with samples at a fixed rate (dense output),
//!   a stop flag and progress callbacks.

pub mod driver;
pub mod explicit;
pub mod tableau;

pub use driver::{RunEnd, RunReport, run};
pub use explicit::{ExplicitRk, IntegrationError, IntegrationStats, StepControl};

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

    /// Called once after every accepted step with the new state (never
    /// inside Runge–Kutta stages). Returns true when this changed the
    /// right-hand side (e.g. a contact episode was recorded), so that the
    /// integrator re-evaluates f at the new point. Default: nothing.
    fn accept_step(&mut self, _t: f64, _y: &[f64]) -> bool {
        false
    }
}
