//! Explicit Runge–Kutta integration with fixed or adaptive steps and dense
//! output (Hairer, Nørsett & Wanner, *Solving Ordinary Differential
//! Equations I*, 2nd ed., §II.4 step-size control, §II.6 dense output).

use super::checkpoint::{Checkpoint, CheckpointError, StateReader, StateWriter};
use super::energy_control::EnergyControl;
use super::point::StepPoint;
use super::step_control::{IntegrationError, IntegrationStats, PiControl, StepMethod, take_step};
use super::tableau::Tableau;
use super::{Integrator, OdeSystem, Tolerances};

/// How the step size is chosen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StepControl {
    /// Constant step h \[s\] (the last step shortened to land on the end).
    Fixed {
        /// Step \[s\], > 0.
        step: f64,
    },
    /// Error-controlled step (needs a tableau with an error estimate).
    Adaptive {
        /// Relative tolerance (absolute tolerances come from the system).
        relative_tolerance: f64,
        /// Largest step \[s\].
        max_step: f64,
        /// First step \[s\]; `None`: Hairer's starting-step estimate.
        initial_step: Option<f64>,
    },
}

/// An explicit Runge–Kutta integrator with its work space.
#[derive(Debug, Clone)]
pub struct ExplicitRk {
    tableau: &'static Tableau,
    control: StepControl,
    /// The current point, the last accepted step, the controller, the
    /// energy control and the counters.
    point: StepPoint,
    k: Vec<Vec<f64>>,
    stage: Vec<f64>,
    y_new: Vec<f64>,
    tolerances: Tolerances,
    /// Dense-output weights of the last accepted step (DOPRI5).
    dense: Vec<f64>,
}

impl ExplicitRk {
    /// The builder of an integrator with this tableau ([`super::Builder`]:
    /// defaults, changed by name).
    pub fn builder(tableau: &'static Tableau) -> super::Builder<Tableau> {
        super::Builder::new(tableau)
    }

    /// Sets up an integration of `system` from (t0, y0).
    pub(crate) fn start(
        tableau: &'static Tableau,
        control: StepControl,
        system: &impl OdeSystem,
        t0: f64,
        y0: &[f64],
    ) -> Result<Self, IntegrationError> {
        match control {
            StepControl::Fixed { step } if !(step > 0.0 && step.is_finite()) => {
                return Err(IntegrationError::Setting(format!(
                    "fixed step {step} must be positive"
                )));
            }
            StepControl::Adaptive {
                relative_tolerance,
                max_step,
                ..
            } => {
                if tableau.error.is_empty() {
                    return Err(IntegrationError::Setting(format!(
                        "{} has no error estimate; use a fixed step",
                        tableau.name
                    )));
                }
                StepPoint::check_adaptive(relative_tolerance, max_step)?;
            }
            _ => {}
        }
        let tolerances = match control {
            StepControl::Adaptive {
                relative_tolerance, ..
            } => Tolerances::new(system, relative_tolerance),
            _ => Tolerances::new(system, 1.0),
        };
        let point = StepPoint::start(system, t0, y0)?;
        let n = y0.len();
        let mut me = Self {
            tableau,
            control,
            point,
            k: vec![vec![0.0; n]; tableau.c.len()],
            stage: vec![0.0; n],
            y_new: vec![0.0; n],
            tolerances,
            dense: vec![0.0; n],
        };
        me.point.h = match control {
            StepControl::Fixed { step } => step,
            StepControl::Adaptive {
                initial_step: Some(h),
                max_step,
                ..
            } => h.min(max_step),
            StepControl::Adaptive { max_step, .. } => me.starting_step(system).min(max_step),
        };
        Ok(me)
    }

    /// Hairer's starting-step estimate (Solving ODEs I, §II.4).
    fn starting_step(&mut self, system: &impl OdeSystem) -> f64 {
        // Weighted RMS norm of a vector, scaled at the current state.
        let norm = |v: &mut dyn Iterator<Item = f64>| {
            let (mut sum, mut n) = (0.0, 0.0);
            for (i, x) in v.enumerate() {
                sum += (x / (self.tolerances.scale(i, self.point.y[i].abs()))).powi(2);
                n += 1.0;
            }
            (sum / n).sqrt()
        };
        let d0 = norm(&mut self.point.y.iter().copied());
        let d1 = norm(&mut self.point.f.iter().copied());
        let h0 = if d0 < 1e-5 || d1 < 1e-5 {
            1e-6
        } else {
            0.01 * d0 / d1
        };
        for i in 0..self.point.y.len() {
            self.stage[i] = self.point.y[i] + h0 * self.point.f[i];
        }
        system.rhs(self.point.t + h0, &self.stage, &mut self.y_new);
        self.point.stats.rhs_evaluations += 1;
        let d2 = norm(&mut self.y_new.iter().zip(&self.point.f).map(|(a, b)| a - b)) / h0;
        let order = self.tableau.order as f64;
        let h1 = if d1.max(d2) <= 1e-15 {
            (h0 * 1e-3).max(1e-6)
        } else {
            (0.01 / d1.max(d2)).powf(1.0 / order)
        };
        (100.0 * h0).min(h1)
    }

    /// Also controls the error of the system's energy balance to
    /// `tolerance` per unit of energy turned over in a step
    /// ([`super::energy_control`]); adaptive steps only, no effect for a
    /// system that keeps no balance. Call before the first step.
    pub(crate) fn with_energy_control(mut self, system: &impl OdeSystem, tolerance: f64) -> Self {
        if matches!(self.control, StepControl::Adaptive { .. }) && !self.tableau.error.is_empty() {
            self.point
                .control_energy(system, tolerance, self.tableau.order);
        }
        self
    }

    /// Step size the next step will try.
    pub fn step_size(&self) -> f64 {
        self.point.h
    }

    /// Continues from (t, y) with a first step h, as after a hand-over from
    /// another integrator: f evaluated afresh, the controller's memory
    /// cleared, the energy control continued from `energy`.
    pub(crate) fn restart(
        &mut self,
        system: &impl OdeSystem,
        t: f64,
        y: &[f64],
        h: f64,
        energy: Option<&EnergyControl>,
    ) {
        let h = match self.control {
            StepControl::Adaptive { max_step, .. } => h.min(max_step),
            StepControl::Fixed { step } => step,
        };
        self.point.restart(system, t, y, h, energy);
    }

    /// The energy-balance control, if any.
    pub(crate) fn energy_control(&self) -> Option<&EnergyControl> {
        self.point.energy.as_ref()
    }

    /// Computes the stages and the candidate y_new for step h; returns the
    /// scaled error norm (0 for methods without an estimate).
    fn try_step(&mut self, system: &mut impl OdeSystem, h: f64, rtol: Option<f64>) -> f64 {
        let tab = self.tableau;
        let n = self.point.y.len();
        let last = tab.c.len() - 1;
        // An FSAL method's last stage is the candidate y₁ (its row of a is
        // b, so the same sums give the same bits): it serves the step's
        // acceptance, and the energy control's balance there comes with it.
        let balance = rtol.is_some() && self.point.energy.is_some();
        let mut end = None;
        self.point.states_error = f64::INFINITY;
        self.k[0].copy_from_slice(&self.point.f);
        for s in 1..tab.c.len() {
            let row = tab.a[s];
            for i in 0..n {
                let mut acc = 0.0;
                for (j, a) in row.iter().enumerate() {
                    acc += a * self.k[j][i];
                }
                self.stage[i] = self.point.y[i] + h * acc;
            }
            let t_stage = self.point.t + tab.c[s] * h;
            if tab.fsal && s == last {
                end = system.rhs_at_end(t_stage, &self.stage, &mut self.k[s], balance);
            } else {
                system.rhs(t_stage, &self.stage, &mut self.k[s]);
            }
            self.point.stats.rhs_evaluations += 1;
        }
        for i in 0..n {
            let mut acc = 0.0;
            for (j, b) in tab.b.iter().enumerate() {
                acc += b * self.k[j][i];
            }
            self.y_new[i] = self.point.y[i] + h * acc;
        }
        if rtol.is_none() || tab.error.is_empty() {
            return if self.y_new.iter().all(|v| v.is_finite()) {
                0.0
            } else {
                f64::INFINITY
            };
        }
        let mut sum = 0.0;
        for i in 0..n {
            let mut e = 0.0;
            for (j, w) in tab.error.iter().enumerate() {
                e += w * self.k[j][i];
            }
            let scale = self
                .tolerances
                .scale(i, self.point.y[i].abs().max(self.y_new[i].abs()));
            sum += (h * e / scale).powi(2);
        }
        let err = (sum / n as f64).sqrt();
        self.point.states_error = err;
        if !err.is_finite() {
            return f64::INFINITY;
        }
        match &mut self.point.energy {
            // Only a step the states pass needs the energy's verdict.
            Some(energy) if err <= 1.0 => {
                if !tab.fsal {
                    end = system.energy_balance(self.point.t + h, &self.y_new);
                }
                let (k, weights) = (&self.k, tab.error);
                let error =
                    |i: usize| h * weights.iter().zip(k).map(|(w, k)| w * k[i]).sum::<f64>();
                let candidate = (&self.y_new[..], end);
                err.max(energy.scaled_error(
                    system,
                    self.point.t,
                    &self.point.y,
                    h,
                    candidate,
                    error,
                ))
            }
            _ => err,
        }
    }

    /// The scaled error of each component in the last attempt of step h
    /// (the terms of the error norm; the state itself where not finite).
    fn error_terms(&self, h: f64) -> impl Iterator<Item = f64> + '_ {
        (0..self.point.y.len()).map(move |i| {
            let e: f64 = self
                .tableau
                .error
                .iter()
                .enumerate()
                .map(|(j, w)| w * self.k[j][i])
                .sum();
            let scale = self
                .tolerances
                .scale(i, self.point.y[i].abs().max(self.y_new[i].abs()));
            if self.y_new[i].is_finite() {
                (h * e / scale).abs()
            } else {
                f64::INFINITY
            }
        })
    }

    fn finish_step(&mut self, system: &mut impl OdeSystem, h: f64) {
        let n = self.point.y.len();
        let tab = self.tableau;
        // Dense-output weights (DOPRI5): h Σ d_i k_i.
        if !tab.dense.is_empty() {
            for i in 0..n {
                let mut acc = 0.0;
                for (j, d) in tab.dense.iter().enumerate() {
                    acc += d * self.k[j][i];
                }
                self.dense[i] = h * acc;
            }
        }
        self.point.advance(h, &self.y_new);
        if tab.fsal {
            let last = tab.c.len() - 1;
            self.point.f.copy_from_slice(&self.k[last]);
        } else {
            system.rhs(self.point.t, &self.point.y, &mut self.point.f);
            self.point.stats.rhs_evaluations += 1;
        }
        self.point.accepted();
        if system.accept_step(self.point.t, &self.point.y) {
            system.rhs(self.point.t, &self.point.y, &mut self.point.f);
            self.point.stats.rhs_evaluations += 1;
        }
    }
}

impl StepMethod for ExplicitRk {
    fn point(&self) -> (f64, &[f64]) {
        (self.point.t, &self.point.y)
    }

    fn max_step(&self) -> f64 {
        match self.control {
            StepControl::Adaptive { max_step, .. } => max_step,
            StepControl::Fixed { .. } => f64::INFINITY,
        }
    }

    fn error_order(&self) -> Option<f64> {
        match self.control {
            StepControl::Adaptive { .. } => Some(self.tableau.order as f64),
            StepControl::Fixed { .. } => None,
        }
    }

    fn step_size(&mut self) -> (&mut f64, &mut PiControl) {
        (&mut self.point.h, &mut self.point.control)
    }

    fn attempt<S: OdeSystem>(&mut self, system: &mut S, h: f64) -> f64 {
        let rtol = match self.control {
            StepControl::Adaptive {
                relative_tolerance, ..
            } => Some(relative_tolerance),
            StepControl::Fixed { .. } => None,
        };
        self.try_step(system, h, rtol)
    }

    fn finish<S: OdeSystem>(&mut self, system: &mut S, h: f64) {
        self.finish_step(system, h);
    }

    fn reject(&mut self) {
        self.point.stats.rejected_steps += 1;
    }

    fn states_error(&self) -> f64 {
        self.point.states_error
    }

    /// A fixed step fails only on a non-finite state: the first one.
    fn too_small<S: OdeSystem>(
        &self,
        system: &S,
        step: f64,
        tried: f64,
        err: f64,
    ) -> IntegrationError {
        if let StepControl::Fixed { .. } = self.control {
            let first = self.y_new.iter().position(|v| !v.is_finite()).unwrap_or(0);
            return IntegrationError::NonFinite {
                t: self.point.t,
                state: system.state_name(first),
            };
        }
        PiControl::too_small(
            self.point.t,
            step,
            err,
            system,
            self.error_terms(tried),
            &self.point.y,
            &self.point.f,
            &self.tolerances,
        )
    }
}

impl Checkpoint for ExplicitRk {
    fn save(&self, out: &mut StateWriter) {
        out.tag(self.tableau.name);
        self.point.save(out);
        out.f64s(&self.dense);
        out.f64(self.point.control.err_prev);
        self.point.save_energy(out);
        self.point.stats.save(out);
    }

    fn restore(&mut self, input: &mut StateReader) -> Result<(), CheckpointError> {
        input.tag(self.tableau.name)?;
        self.point.restore(input)?;
        input.f64s_into("dense", &mut self.dense)?;
        self.point.control.err_prev = input.f64()?;
        self.point.restore_energy(input)?;
        self.point.stats.restore(input)
    }
}

impl Integrator for ExplicitRk {
    /// Current time.
    fn t(&self) -> f64 {
        self.point.t
    }

    /// Current state.
    fn y(&self) -> &[f64] {
        &self.point.y
    }

    /// Takes one accepted step, not beyond `t_limit` (`step_control::take_step`).
    /// Calls the system's `accept_step` hook once, after acceptance.
    fn step<S: OdeSystem>(&mut self, system: &mut S, t_limit: f64) -> Result<(), IntegrationError> {
        take_step(self, system, t_limit)
    }

    /// Dense output: the state at time `t` within the last accepted step
    /// (clamped to it), written into `out`. DOPRI5 uses its 4th-order
    /// continuous extension; other methods a cubic Hermite interpolant.
    fn interpolate(&self, t: f64, out: &mut [f64]) {
        if self.point.h_prev == 0.0 {
            out.copy_from_slice(&self.point.y);
            return;
        }
        let h = self.point.h_prev;
        let theta = ((t - self.point.t_prev) / h).clamp(0.0, 1.0);
        let t1 = 1.0 - theta;
        if !self.tableau.dense.is_empty() {
            for (i, o) in out.iter_mut().enumerate() {
                let r2 = self.point.y[i] - self.point.y_prev[i];
                let r3 = h * self.point.f_prev[i] - r2;
                let r4 = r2 - h * self.point.f[i] - r3;
                *o = self.point.y_prev[i]
                    + theta * (r2 + t1 * (r3 + theta * (r4 + t1 * self.dense[i])));
            }
        } else {
            hermite(
                self.point.t_prev,
                h,
                &self.point.y_prev,
                &self.point.f_prev,
                &self.point.y,
                &self.point.f,
                t,
                out,
            );
        }
    }

    /// Counters so far.
    fn stats(&self) -> IntegrationStats {
        self.point.stats
    }
}

/// Cubic Hermite interpolation at t in the step [t0, t0 + h] from the
/// values and derivatives at its ends (clamped to the step).
#[allow(clippy::too_many_arguments)]
pub(crate) fn hermite(
    t0: f64,
    h: f64,
    y0: &[f64],
    f0: &[f64],
    y1: &[f64],
    f1: &[f64],
    t: f64,
    out: &mut [f64],
) {
    if h == 0.0 {
        out.copy_from_slice(y1);
        return;
    }
    let theta = ((t - t0) / h).clamp(0.0, 1.0);
    let (t2, t3) = (theta * theta, theta * theta * theta);
    let h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
    let h10 = t3 - 2.0 * t2 + theta;
    let h01 = -2.0 * t3 + 3.0 * t2;
    let h11 = t3 - t2;
    for (i, o) in out.iter_mut().enumerate() {
        *o = h00 * y0[i] + h10 * h * f0[i] + h01 * y1[i] + h11 * h * f1[i];
    }
}

#[cfg(test)]
mod tests;
