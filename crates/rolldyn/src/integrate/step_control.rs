//! What both adaptive integrators share: their counters, why an
//! integration stops, the PI step-size controller (Gustafsson;
//! Hairer, Nørsett & Wanner, *Solving ODEs I*, §II.4) and the loop that
//! attempts, accepts and rejects a step (`take_step`); each method
//! supplies only its attempt (`StepMethod`).

use super::{OdeSystem, Tolerances};

/// Counters of an integration.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize)]
pub struct IntegrationStats {
    /// Accepted steps.
    pub steps: u64,
    /// Rejected steps.
    pub rejected_steps: u64,
    /// Right-hand-side evaluations by the stages (and dense output).
    pub rhs_evaluations: u64,
    /// Jacobian evaluations (implicit methods).
    pub jacobian_evaluations: u64,
    /// Cost of the Jacobians in right-hand-side equivalents (one per
    /// colour of the column grouping).
    pub jacobian_rhs_evaluations: u64,
    /// LU factorizations of the iteration matrix (implicit methods).
    pub factorizations: u64,
    /// Evaluations of the Jacobian's fast part, between full Jacobians and
    /// with them while it is refreshing (implicit methods, systems with a
    /// fast part: `rosenbrock::fast_part`).
    pub fast_part_jacobians: u64,
}

/// Why integration stopped early.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum IntegrationError {
    /// The error control asked for a step below the resolution of t.
    #[error(
        "step size {step:.3e} s at t = {t:.6e} s fell below the smallest step the time resolution allows (largest error in {state})"
    )]
    StepTooSmall {
        /// Time reached \[s\].
        t: f64,
        /// Step asked for \[s\].
        step: f64,
        /// The state component with the largest error in the last attempt
        /// ([`OdeSystem::state_name`]).
        state: String,
    },
    /// The state or its derivative became NaN or infinite.
    #[error("the solution became non-finite at t = {t:.6e} s (first in {state})")]
    NonFinite {
        /// Time reached \[s\].
        t: f64,
        /// The first state component that is not finite (or whose
        /// derivative is not).
        state: String,
    },
    /// Bad settings.
    #[error("invalid integrator setting: {0}")]
    Setting(String),
    /// The state left the range the models hold for (the run's observer
    /// stopped it).
    #[error("the run left the models' range at t = {t:.6e} s: {reason}")]
    Limit {
        /// Time reached \[s\].
        t: f64,
        /// What passed which limit.
        reason: String,
    },
}

/// Weight β of the previous error in the PI step-size controller
/// (Gustafsson; Hairer, Nørsett & Wanner, *Solving ODEs I*, §II.4, and
/// their DOPRI5 code, which allows β ≤ 0.1 and uses 0.04). The larger
/// value damps the step-size oscillation at the stability boundary, where
/// the bearing's stiff traction keeps explicit methods.
const PI_BETA: f64 = 0.08;

/// Step-size control shared by the adaptive integrators: landing on the
/// end without a sliver step, the PI update after an accepted step and the
/// cut after a rejected one (error norms scaled so that 1 is the tolerance,
/// `order` the exponent q of err ∝ h^q).
#[derive(Debug, Clone, Copy)]
pub(crate) struct PiControl {
    /// Error norm of the last accepted step.
    pub(crate) err_prev: f64,
}

impl PiControl {
    pub(crate) fn new() -> Self {
        Self { err_prev: 1e-4 }
    }

    /// The step to try: `natural`, or the rest of the way to the limit if
    /// that is shorter or only slightly longer.
    pub(crate) fn landing(natural: f64, remaining: f64) -> f64 {
        if natural >= remaining || (remaining - natural) < 0.01 * natural {
            remaining
        } else {
            natural
        }
    }

    /// Next step after an accepted one of error `err` (natural size
    /// `natural`): h · 0.9 err^{−(1/q − 0.75β)} err_prev^{β}, no growth
    /// right after a rejection.
    pub(crate) fn accepted(&mut self, natural: f64, err: f64, order: f64, rejected: bool) -> f64 {
        let err = err.max(1e-10);
        let factor = 0.9 * err.powf(-(1.0 / order - 0.75 * PI_BETA)) * self.err_prev.powf(PI_BETA);
        self.err_prev = err.max(1e-4);
        natural * factor.clamp(0.2, if rejected { 1.0 } else { 5.0 })
    }

    /// Next step after a rejected step h of error `err` (∞: not finite).
    pub(crate) fn rejected(h: f64, err: f64, order: f64) -> f64 {
        let factor = if err.is_finite() {
            (0.9 * err.powf(-1.0 / order)).clamp(0.2, 1.0)
        } else {
            0.2
        };
        h * factor
    }

    /// The error for a step that fell below `min_step`, naming a state
    /// component: the one with the largest scaled error term of the last
    /// attempt (`error_terms`) when that error is finite; otherwise (the
    /// attempt overflowed, and a linear solve spreads NaN over every
    /// component) the one changing fastest relative to its tolerance at
    /// the last accepted point, |f_k| / (atol_k + rtol |y_k|).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn too_small(
        t: f64,
        step: f64,
        err: f64,
        system: &impl OdeSystem,
        error_terms: impl Iterator<Item = f64>,
        y: &[f64],
        f: &[f64],
        tolerances: &Tolerances,
    ) -> IntegrationError {
        let largest = |terms: &mut dyn Iterator<Item = f64>| {
            terms
                .enumerate()
                .filter(|(_, c)| c.is_finite())
                .fold(
                    (0, f64::NEG_INFINITY),
                    |w, (i, c)| if c > w.1 { (i, c) } else { w },
                )
                .0
        };
        if err.is_finite() {
            let state = system.state_name(largest(&mut { error_terms }));
            IntegrationError::StepTooSmall { t, step, state }
        } else {
            let mut rates = (0..y.len()).map(|k| f[k].abs() / tolerances.scale(k, y[k].abs()));
            let state = system.state_name(largest(&mut rates));
            IntegrationError::NonFinite { t, state }
        }
    }
}

/// An integrator's side of the step loop ([`take_step`]): its point, its
/// step size and controller, and its attempt.
pub(crate) trait StepMethod {
    /// The current time and state.
    fn point(&self) -> (f64, &[f64]);
    /// Largest step its settings allow \[s\].
    fn max_step(&self) -> f64;
    /// Exponent q of err ∝ h^q; None: a fixed step without error control.
    fn error_order(&self) -> Option<f64>;
    /// The step size to try next and the PI controller's state.
    fn step_size(&mut self) -> (&mut f64, &mut PiControl);
    /// Prepares an attempt (an implicit method refreshes its Jacobian).
    fn prepare<S: OdeSystem>(&mut self, _system: &S) {}
    /// Attempts step h from the current point; the scaled error norm (≤ 1
    /// accepts; ∞ when not finite). The system is `&mut` for
    /// [`OdeSystem::rhs_at_end`] at the candidate end.
    fn attempt<S: OdeSystem>(&mut self, system: &mut S, h: f64) -> f64;
    /// Moves to the attempted step's end and calls the system's
    /// `accept_step`.
    fn finish<S: OdeSystem>(&mut self, system: &mut S, h: f64);
    /// Counts a rejection (an implicit method may also age its Jacobian).
    fn reject(&mut self);
    /// The states' own scaled error norm of the last attempt, without the
    /// energy balance's verdict (∞ when its stages were not finite).
    fn states_error(&self) -> f64;
    /// The error when the step falls below the smallest (new size `step`,
    /// after an attempt `tried` of error `err`): names the state.
    fn too_small<S: OdeSystem>(
        &self,
        system: &S,
        step: f64,
        tried: f64,
        err: f64,
    ) -> IntegrationError;
}

/// One accepted step of `method`, not beyond `t_limit`: the step limited
/// by the settings and the system ([`OdeSystem::step_limit`]), landing on
/// `t_limit` without a sliver, cut after each rejection by the PI
/// controller until accepted or below the time resolution. A fixed-step
/// method fails on a non-finite attempt.
///
/// A step that the states pass and only the energy balance rejects is
/// taken when the next try would fall below the time resolution: where
/// the right-hand side jumps (a ball's path over a spall has a kink, so a
/// damped contact's force jumps), a step across the jump leaves ΔP h in
/// the balance, which the allowance of a tight energy tolerance
/// ([`super::energy_control::EVENT_SHARE`]) may only pass at steps the
/// clock cannot resolve. Such a step, a few times 16 ε t long, leaves
/// ΔP × 1e-16 t or so: nothing the balance can show.
pub(crate) fn take_step<M: StepMethod, S: OdeSystem>(
    method: &mut M,
    system: &mut S,
    t_limit: f64,
) -> Result<(), IntegrationError> {
    let (t, y) = method.point();
    let remaining = t_limit - t;
    if remaining <= 0.0 {
        return Ok(());
    }
    let min_step = 16.0 * f64::EPSILON * t.abs().max(remaining);
    let max_step = method.max_step().min(system.step_limit(t, y));
    let order = method.error_order();
    let mut rejected = false;
    loop {
        method.prepare(system);
        let natural = (*method.step_size().0).min(max_step);
        let h = PiControl::landing(natural, remaining);
        let err = method.attempt(system, h);
        // Passed, or only the energy rejects it and the next try would
        // fall below the time resolution (above).
        let accept = err <= 1.0
            || (method.states_error() <= 1.0
                && order.is_some_and(|q| PiControl::rejected(h, err, q) < min_step));
        if accept {
            if let Some(q) = order {
                let (step, control) = method.step_size();
                *step = control.accepted(natural, err.min(1.0), q, rejected);
            }
            method.finish(system, h);
            return Ok(());
        }
        let Some(q) = order else {
            return Err(method.too_small(system, h, h, err));
        };
        let next = PiControl::rejected(h, err, q);
        method.reject();
        rejected = true;
        *method.step_size().0 = next;
        if next < min_step {
            return Err(method.too_small(system, next, h, err));
        }
    }
}
