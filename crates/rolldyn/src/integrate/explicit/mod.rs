//! Explicit Runge–Kutta integration with fixed or adaptive steps and dense
//! output (Hairer, Nørsett & Wanner, *Solving Ordinary Differential
//! Equations I*, 2nd ed., §II.4 step-size control, §II.6 dense output).

use super::checkpoint::{
    Checkpoint, CheckpointError, StateReader, StateWriter, restore_step, save_step,
};
use super::energy_control::EnergyControl;
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
    t: f64,
    y: Vec<f64>,
    /// f(t, y) at the current point (k_1 of the next step).
    f: Vec<f64>,
    h: f64,
    k: Vec<Vec<f64>>,
    stage: Vec<f64>,
    y_new: Vec<f64>,
    tolerances: Tolerances,
    // Last accepted step, for dense output.
    t_prev: f64,
    h_prev: f64,
    y_prev: Vec<f64>,
    f_prev: Vec<f64>,
    dense: Vec<f64>,
    stats: IntegrationStats,
    control_state: PiControl,
    /// Error control of the energy balance, if asked for.
    energy: Option<EnergyControl>,
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
        let n = system.dimension();
        if y0.len() != n {
            return Err(IntegrationError::Setting(format!(
                "initial state has {} values, the system {n}",
                y0.len()
            )));
        }
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
                if !(relative_tolerance > 0.0 && relative_tolerance < 1.0) {
                    return Err(IntegrationError::Setting(format!(
                        "relative tolerance {relative_tolerance} must lie in (0, 1)"
                    )));
                }
                if max_step.is_nan() || max_step <= 0.0 {
                    return Err(IntegrationError::Setting(format!(
                        "max step {max_step} must be positive"
                    )));
                }
            }
            _ => {}
        }
        let tolerances = match control {
            StepControl::Adaptive {
                relative_tolerance, ..
            } => Tolerances::new(system, relative_tolerance),
            _ => Tolerances::new(system, 1.0),
        };
        let mut f = vec![0.0; n];
        system.rhs(t0, y0, &mut f);
        let mut me = Self {
            tableau,
            control,
            t: t0,
            y: y0.to_vec(),
            f,
            h: 0.0,
            k: vec![vec![0.0; n]; tableau.c.len()],
            stage: vec![0.0; n],
            y_new: vec![0.0; n],
            tolerances,
            t_prev: t0,
            h_prev: 0.0,
            y_prev: y0.to_vec(),
            f_prev: vec![0.0; n],
            dense: vec![0.0; n],
            stats: IntegrationStats {
                rhs_evaluations: 1,
                ..Default::default()
            },
            control_state: PiControl::new(),
            energy: None,
        };
        if me.f.iter().any(|v| !v.is_finite()) {
            let first = me.f.iter().position(|v| !v.is_finite()).unwrap_or(0);
            return Err(IntegrationError::NonFinite {
                t: t0,
                state: system.state_name(first),
            });
        }
        me.h = match control {
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
                sum += (x / (self.tolerances.scale(i, self.y[i].abs()))).powi(2);
                n += 1.0;
            }
            (sum / n).sqrt()
        };
        let d0 = norm(&mut self.y.iter().copied());
        let d1 = norm(&mut self.f.iter().copied());
        let h0 = if d0 < 1e-5 || d1 < 1e-5 {
            1e-6
        } else {
            0.01 * d0 / d1
        };
        for i in 0..self.y.len() {
            self.stage[i] = self.y[i] + h0 * self.f[i];
        }
        system.rhs(self.t + h0, &self.stage, &mut self.y_new);
        self.stats.rhs_evaluations += 1;
        let d2 = norm(&mut self.y_new.iter().zip(&self.f).map(|(a, b)| a - b)) / h0;
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
            self.energy = EnergyControl::new(
                system,
                tolerance,
                f64::from(self.tableau.order),
                self.t,
                &self.y,
            );
        }
        self
    }

    /// Step size the next step will try.
    pub fn step_size(&self) -> f64 {
        self.h
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
        self.t = t;
        self.y.copy_from_slice(y);
        system.rhs(t, y, &mut self.f);
        self.stats.rhs_evaluations += 1;
        self.t_prev = t;
        self.h_prev = 0.0;
        self.control_state = PiControl::new();
        self.h = match self.control {
            StepControl::Adaptive { max_step, .. } => h.min(max_step),
            StepControl::Fixed { step } => step,
        };
        if let (Some(mine), Some(from)) = (&mut self.energy, energy) {
            mine.continue_from(from);
        }
    }

    /// The energy-balance control, if any.
    pub(crate) fn energy_control(&self) -> Option<&EnergyControl> {
        self.energy.as_ref()
    }

    /// Computes the stages and the candidate y_new for step h; returns the
    /// scaled error norm (0 for methods without an estimate).
    fn try_step(&mut self, system: &mut impl OdeSystem, h: f64, rtol: Option<f64>) -> f64 {
        let tab = self.tableau;
        let n = self.y.len();
        let last = tab.c.len() - 1;
        // An FSAL method's last stage is the candidate y₁ (its row of a is
        // b, so the same sums give the same bits): it serves the step's
        // acceptance, and the energy control's balance there comes with it.
        let balance = rtol.is_some() && self.energy.is_some();
        let mut end = None;
        self.k[0].copy_from_slice(&self.f);
        for s in 1..tab.c.len() {
            let row = tab.a[s];
            for i in 0..n {
                let mut acc = 0.0;
                for (j, a) in row.iter().enumerate() {
                    acc += a * self.k[j][i];
                }
                self.stage[i] = self.y[i] + h * acc;
            }
            let t_stage = self.t + tab.c[s] * h;
            if tab.fsal && s == last {
                end = system.rhs_at_end(t_stage, &self.stage, &mut self.k[s], balance);
            } else {
                system.rhs(t_stage, &self.stage, &mut self.k[s]);
            }
            self.stats.rhs_evaluations += 1;
        }
        for i in 0..n {
            let mut acc = 0.0;
            for (j, b) in tab.b.iter().enumerate() {
                acc += b * self.k[j][i];
            }
            self.y_new[i] = self.y[i] + h * acc;
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
                .scale(i, self.y[i].abs().max(self.y_new[i].abs()));
            sum += (h * e / scale).powi(2);
        }
        let err = (sum / n as f64).sqrt();
        if !err.is_finite() {
            return f64::INFINITY;
        }
        match &mut self.energy {
            // Only a step the states pass needs the energy's verdict.
            Some(energy) if err <= 1.0 => {
                if !tab.fsal {
                    end = system.energy_balance(self.t + h, &self.y_new);
                }
                let (k, weights) = (&self.k, tab.error);
                let error =
                    |i: usize| h * weights.iter().zip(k).map(|(w, k)| w * k[i]).sum::<f64>();
                let candidate = (&self.y_new[..], end);
                err.max(energy.scaled_error(system, self.t, &self.y, h, candidate, error))
            }
            _ => err,
        }
    }

    /// The scaled error of each component in the last attempt of step h
    /// (the terms of the error norm; the state itself where not finite).
    fn error_terms(&self, h: f64) -> impl Iterator<Item = f64> + '_ {
        (0..self.y.len()).map(move |i| {
            let e: f64 = self
                .tableau
                .error
                .iter()
                .enumerate()
                .map(|(j, w)| w * self.k[j][i])
                .sum();
            let scale = self
                .tolerances
                .scale(i, self.y[i].abs().max(self.y_new[i].abs()));
            if self.y_new[i].is_finite() {
                (h * e / scale).abs()
            } else {
                f64::INFINITY
            }
        })
    }

    fn finish_step(&mut self, system: &mut impl OdeSystem, h: f64) {
        let n = self.y.len();
        let tab = self.tableau;
        self.t_prev = self.t;
        self.h_prev = h;
        self.y_prev.copy_from_slice(&self.y);
        self.f_prev.copy_from_slice(&self.f);
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
        self.t += h;
        self.y.copy_from_slice(&self.y_new);
        if tab.fsal {
            let last = tab.c.len() - 1;
            self.f.copy_from_slice(&self.k[last]);
        } else {
            system.rhs(self.t, &self.y, &mut self.f);
            self.stats.rhs_evaluations += 1;
        }
        self.stats.steps += 1;
        if let Some(energy) = &mut self.energy {
            energy.accepted();
        }
        if system.accept_step(self.t, &self.y) {
            system.rhs(self.t, &self.y, &mut self.f);
            self.stats.rhs_evaluations += 1;
        }
    }
}

impl StepMethod for ExplicitRk {
    fn point(&self) -> (f64, &[f64]) {
        (self.t, &self.y)
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
        (&mut self.h, &mut self.control_state)
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
        self.stats.rejected_steps += 1;
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
                t: self.t,
                state: system.state_name(first),
            };
        }
        PiControl::too_small(
            self.t,
            step,
            err,
            system,
            self.error_terms(tried),
            &self.y,
            &self.f,
            &self.tolerances,
        )
    }
}

impl Checkpoint for ExplicitRk {
    fn save(&self, out: &mut StateWriter) {
        out.tag(self.tableau.name);
        save_step(
            out,
            [self.t, self.h, self.t_prev, self.h_prev],
            [&self.y, &self.f, &self.y_prev, &self.f_prev],
        );
        out.f64s(&self.dense);
        out.f64(self.control_state.err_prev);
        if let Some(energy) = &self.energy {
            energy.save(out);
        }
        self.stats.save(out);
    }

    fn restore(&mut self, input: &mut StateReader) -> Result<(), CheckpointError> {
        input.tag(self.tableau.name)?;
        restore_step(
            input,
            [&mut self.t, &mut self.h, &mut self.t_prev, &mut self.h_prev],
            [&mut self.y, &mut self.f, &mut self.y_prev, &mut self.f_prev],
        )?;
        input.f64s_into("dense", &mut self.dense)?;
        self.control_state.err_prev = input.f64()?;
        if let Some(energy) = &mut self.energy {
            energy.restore(input)?;
        }
        self.stats.restore(input)
    }
}

impl Integrator for ExplicitRk {
    /// Current time.
    fn t(&self) -> f64 {
        self.t
    }

    /// Current state.
    fn y(&self) -> &[f64] {
        &self.y
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
        if self.h_prev == 0.0 {
            out.copy_from_slice(&self.y);
            return;
        }
        let h = self.h_prev;
        let theta = ((t - self.t_prev) / h).clamp(0.0, 1.0);
        let t1 = 1.0 - theta;
        if !self.tableau.dense.is_empty() {
            for (i, o) in out.iter_mut().enumerate() {
                let r2 = self.y[i] - self.y_prev[i];
                let r3 = h * self.f_prev[i] - r2;
                let r4 = r2 - h * self.f[i] - r3;
                *o = self.y_prev[i] + theta * (r2 + t1 * (r3 + theta * (r4 + t1 * self.dense[i])));
            }
        } else {
            hermite(
                self.t_prev,
                h,
                &self.y_prev,
                &self.f_prev,
                &self.y,
                &self.f,
                t,
                out,
            );
        }
    }

    /// Counters so far.
    fn stats(&self) -> IntegrationStats {
        self.stats
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
