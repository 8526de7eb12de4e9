//! One shape for setting up every integrator: a builder with defaults,
//! changed by name, built on a system and its initial state.
//!
//! ```
//! use rolldyn::integrate::tableau::DOPRI5;
//! use rolldyn::integrate::{ExplicitRk, ROS34PW2, Rosenbrock};
//! # use rolldyn::integrate::OdeSystem;
//! # struct Decay;
//! # impl OdeSystem for Decay {
//! #     fn dimension(&self) -> usize { 1 }
//! #     fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) { dy[0] = -y[0]; }
//! # }
//! let stiff = Rosenbrock::builder(&ROS34PW2)
//!     .relative_tolerance(1e-6)
//!     .max_step(0.1)
//!     .build(&Decay, &[1.0])?;
//! let explicit = ExplicitRk::builder(&DOPRI5).fixed_step(1e-3).build(&Decay, &[1.0])?;
//! # Ok::<(), rolldyn::integrate::IntegrationError>(())
//! ```

use super::tableau::Tableau;
use super::{ExplicitRk, IntegrationError, OdeSystem, Rosenbrock, RosenbrockTableau, StepControl};

/// The settings of an integrator of tableau type `T`, with defaults:
/// adaptive steps at a relative tolerance of 10⁻⁶, no largest step, the
/// starting step estimated, from t = 0, no energy control.
#[derive(Debug, Clone, Copy)]
pub struct Builder<T: 'static> {
    tableau: &'static T,
    relative_tolerance: f64,
    max_step: f64,
    initial_step: Option<f64>,
    fixed_step: Option<f64>,
    start_time: f64,
    energy_tolerance: Option<f64>,
}

impl<T> Builder<T> {
    /// The defaults for `tableau`.
    pub fn new(tableau: &'static T) -> Self {
        Self {
            tableau,
            relative_tolerance: 1e-6,
            max_step: f64::INFINITY,
            initial_step: None,
            fixed_step: None,
            start_time: 0.0,
            energy_tolerance: None,
        }
    }

    /// Relative tolerance of the error control (absolute tolerances come
    /// from the system).
    pub fn relative_tolerance(mut self, relative_tolerance: f64) -> Self {
        self.relative_tolerance = relative_tolerance;
        self
    }

    /// Largest step \[s\].
    pub fn max_step(mut self, max_step: f64) -> Self {
        self.max_step = max_step;
        self
    }

    /// First step \[s\]; `None`: estimated from the initial derivative.
    pub fn initial_step(mut self, initial_step: Option<f64>) -> Self {
        self.initial_step = initial_step;
        self
    }

    /// A constant step \[s\] instead of the error control (explicit
    /// methods only).
    pub fn fixed_step(mut self, step: f64) -> Self {
        self.fixed_step = Some(step);
        self
    }

    /// The step control as one value (the case layer's form).
    pub fn control(self, control: StepControl) -> Self {
        match control {
            StepControl::Fixed { step } => self.fixed_step(step),
            StepControl::Adaptive {
                relative_tolerance,
                max_step,
                initial_step,
            } => Self {
                fixed_step: None,
                ..self
                    .relative_tolerance(relative_tolerance)
                    .max_step(max_step)
                    .initial_step(initial_step)
            },
        }
    }

    /// Time of the initial state \[s\].
    pub fn start_time(mut self, t0: f64) -> Self {
        self.start_time = t0;
        self
    }

    /// Also controls the error of the system's energy balance to this
    /// tolerance per unit of energy turned over in a step
    /// ([`super::energy_control`]); None: not.
    pub fn energy_tolerance(mut self, tolerance: Option<f64>) -> Self {
        self.energy_tolerance = tolerance;
        self
    }

    fn step_control(&self) -> StepControl {
        match self.fixed_step {
            Some(step) => StepControl::Fixed { step },
            None => StepControl::Adaptive {
                relative_tolerance: self.relative_tolerance,
                max_step: self.max_step,
                initial_step: self.initial_step,
            },
        }
    }
}

impl Builder<Tableau> {
    /// The explicit Runge–Kutta integrator of `system` from `y0`.
    pub fn build(
        self,
        system: &impl OdeSystem,
        y0: &[f64],
    ) -> Result<ExplicitRk, IntegrationError> {
        let rk = ExplicitRk::start(
            self.tableau,
            self.step_control(),
            system,
            self.start_time,
            y0,
        )?;
        Ok(match self.energy_tolerance {
            Some(tolerance) => rk.with_energy_control(system, tolerance),
            None => rk,
        })
    }
}

impl Builder<RosenbrockTableau> {
    /// The Rosenbrock–W integrator of `system` from `y0` (error-controlled
    /// steps only: a fixed step is refused).
    pub fn build(
        self,
        system: &impl OdeSystem,
        y0: &[f64],
    ) -> Result<Rosenbrock, IntegrationError> {
        if let Some(step) = self.fixed_step {
            return Err(IntegrationError::Setting(format!(
                "a fixed step ({step} s) is for the explicit methods; a Rosenbrock method controls its step"
            )));
        }
        let r = Rosenbrock::start(
            self.tableau,
            self.relative_tolerance,
            self.max_step,
            self.initial_step,
            system,
            self.start_time,
            y0,
        )?;
        Ok(match self.energy_tolerance {
            Some(tolerance) => r.with_energy_control(system, tolerance),
            None => r,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrate::tableau::DOPRI5;
    use crate::integrate::test_systems::Decay;
    use crate::integrate::{Integrator, ROS34PW2};

    #[test]
    fn builders_set_what_they_name() {
        let rk = ExplicitRk::builder(&DOPRI5)
            .relative_tolerance(1e-8)
            .max_step(0.01)
            .start_time(2.0)
            .build(&Decay, &[1.0])
            .unwrap();
        assert_eq!(rk.t(), 2.0);
        assert!(rk.step_size() <= 0.01);
        let fixed = ExplicitRk::builder(&DOPRI5)
            .fixed_step(1e-3)
            .build(&Decay, &[1.0])
            .unwrap();
        assert_eq!(fixed.step_size(), 1e-3);
        let stiff = Rosenbrock::builder(&ROS34PW2)
            .max_step(0.05)
            .initial_step(Some(0.02))
            .build(&Decay, &[1.0])
            .unwrap();
        assert_eq!(stiff.step_size(), 0.02);
        let refused = Rosenbrock::builder(&ROS34PW2)
            .fixed_step(1e-3)
            .build(&Decay, &[1.0]);
        assert!(matches!(refused, Err(IntegrationError::Setting(_))));
        let bad = Rosenbrock::builder(&ROS34PW2)
            .relative_tolerance(2.0)
            .build(&Decay, &[1.0]);
        assert!(matches!(bad, Err(IntegrationError::Setting(_))));
    }
}
