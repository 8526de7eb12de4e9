//! What both one-step integrators (explicit Runge–Kutta and Rosenbrock)
//! carry from one step to the next: the current point and f there, the
//! last accepted step for dense output, the step size to try with the PI
//! controller's memory, the energy-balance control and the counters
//! (`step_control` holds the loop that uses them).

use super::OdeSystem;
use super::checkpoint::{CheckpointError, StateReader, StateWriter, restore_step, save_step};
use super::energy_control::EnergyControl;
use super::step_control::{IntegrationError, IntegrationStats, PiControl};

/// The state of an integration between steps.
#[derive(Debug, Clone)]
pub(crate) struct StepPoint {
    /// Current time.
    pub t: f64,
    /// Current state.
    pub y: Vec<f64>,
    /// f(t, y) at the current point (the first stage of the next step).
    pub f: Vec<f64>,
    /// Step size the next step will try.
    pub h: f64,
    /// Start of the last accepted step.
    pub t_prev: f64,
    /// Its size (0: none yet).
    pub h_prev: f64,
    /// The state at its start.
    pub y_prev: Vec<f64>,
    /// f at its start.
    pub f_prev: Vec<f64>,
    /// Counters so far.
    pub stats: IntegrationStats,
    /// The step-size controller's memory.
    pub control: PiControl,
    /// Error control of the energy balance, if asked for.
    pub energy: Option<EnergyControl>,
    /// The states' scaled error norm of the last attempt (∞ before the
    /// first, or when its stages were not finite), apart from the energy's.
    pub states_error: f64,
}

impl StepPoint {
    /// Starts at (t0, y0): checks the state's length against the system,
    /// evaluates f there and refuses a non-finite one. The step size is
    /// left at 0 for the integrator to choose.
    pub fn start(system: &impl OdeSystem, t0: f64, y0: &[f64]) -> Result<Self, IntegrationError> {
        let n = system.dimension();
        if y0.len() != n {
            return Err(IntegrationError::Setting(format!(
                "initial state has {} values, the system {n}",
                y0.len()
            )));
        }
        let mut f = vec![0.0; n];
        system.rhs(t0, y0, &mut f);
        if let Some(first) = f.iter().position(|v| !v.is_finite()) {
            return Err(IntegrationError::NonFinite {
                t: t0,
                state: system.state_name(first),
            });
        }
        Ok(Self {
            t: t0,
            y: y0.to_vec(),
            f,
            h: 0.0,
            t_prev: t0,
            h_prev: 0.0,
            y_prev: y0.to_vec(),
            f_prev: vec![0.0; n],
            stats: IntegrationStats {
                rhs_evaluations: 1,
                ..Default::default()
            },
            control: PiControl::new(),
            energy: None,
            states_error: f64::INFINITY,
        })
    }

    /// Checks an adaptive method's relative tolerance and largest step.
    pub fn check_adaptive(relative_tolerance: f64, max_step: f64) -> Result<(), IntegrationError> {
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
        Ok(())
    }

    /// Starts the energy-balance control at the current point
    /// ([`super::energy_control`]) for a method of order `order`.
    pub fn control_energy(&mut self, system: &impl OdeSystem, tolerance: f64, order: u32) {
        self.energy = EnergyControl::new(system, tolerance, f64::from(order), self.t, &self.y);
    }

    /// The accepted step h moves the point to y_new: the current point
    /// becomes the last step's start (f at the new point is the caller's).
    pub fn advance(&mut self, h: f64, y_new: &[f64]) {
        self.t_prev = self.t;
        self.h_prev = h;
        self.y_prev.copy_from_slice(&self.y);
        self.f_prev.copy_from_slice(&self.f);
        self.t += h;
        self.y.copy_from_slice(y_new);
    }

    /// After an accepted step, with its f in place: counts it and tells
    /// the energy control.
    pub fn accepted(&mut self) {
        self.stats.steps += 1;
        if let Some(energy) = &mut self.energy {
            energy.accepted();
        }
    }

    /// Continues from (t, y) with a first step h, as after a hand-over from
    /// another integrator: f evaluated afresh, the controller's memory
    /// cleared, the energy control continued from `energy`.
    pub fn restart(
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
        self.control = PiControl::new();
        self.h = h;
        if let (Some(mine), Some(from)) = (&mut self.energy, energy) {
            mine.continue_from(from);
        }
    }

    /// Writes the times and vectors of the point and the last step.
    pub fn save(&self, out: &mut StateWriter) {
        save_step(
            out,
            [self.t, self.h, self.t_prev, self.h_prev],
            [&self.y, &self.f, &self.y_prev, &self.f_prev],
        );
    }

    /// Reads what [`StepPoint::save`] wrote.
    pub fn restore(&mut self, input: &mut StateReader) -> Result<(), CheckpointError> {
        restore_step(
            input,
            [&mut self.t, &mut self.h, &mut self.t_prev, &mut self.h_prev],
            [&mut self.y, &mut self.f, &mut self.y_prev, &mut self.f_prev],
        )
    }

    /// Writes the energy control's state, if any.
    pub fn save_energy(&self, out: &mut StateWriter) {
        if let Some(energy) = &self.energy {
            energy.save(out);
        }
    }

    /// Reads what [`StepPoint::save_energy`] wrote.
    pub fn restore_energy(&mut self, input: &mut StateReader) -> Result<(), CheckpointError> {
        if let Some(energy) = &mut self.energy {
            energy.restore(input)?;
        }
        Ok(())
    }
}
