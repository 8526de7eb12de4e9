//! The solve strategy (MODEL §7): the static solution from the built-in
//! start, the continuation in speed, and the fallbacks in order (axial
//! load to speed first, outer-control start for inner and Harris control,
//! the axial-displacement search, and last the solve without the race
//! drive continued in its strength); warm starts from a previous
//! solution.

use super::continuation::Path;
use super::{
    Conditions, Equilibrium, Matrix5, QuasiStaticError, QuasiStaticSolver, RacewayControl, State,
    Vector5,
};
use crate::geometry::RingKind;
use crate::quasistatic::SolverOptions;
use crate::quasistatic::ring_contact::RingDisplacement;

impl QuasiStaticSolver {
    /// Solves the quasi-static equilibrium from the built-in start: the
    /// static solution, then continuation in speed; where that fails, with
    /// the axial displacement found from its reaction (`axial_control`).
    ///
    /// With no applied load and no contact closed (clearance, at rest) the
    /// ring can sit anywhere inside the clearance: the centred position is
    /// returned with every ball unloaded and zero stiffness.
    ///
    /// With the race drive on, at speed, where the free solve fails, the
    /// free solve without the drive (Jones–Harris kinematics for free
    /// balls) continued in the drive's strength
    /// ([`SolverOptions::race_drive`]) comes before the axial-displacement
    /// search; where everything fails (other than by a refusal,
    /// [`QuasiStaticError::AxialLoadTooSmall`]), the whole solve without
    /// the drive, continued likewise; a refusal found without the drive is
    /// returned as it is.
    pub fn solve(
        &self,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Result<Equilibrium, QuasiStaticError> {
        if !(0.0..=1.0).contains(&options.race_drive) {
            return Err(QuasiStaticError::Unsupported {
                reason: format!(
                    "race_drive = {} is outside [0, 1] (1: rolldyn's free-ball kinematics, 0: Jones–Harris)",
                    options.race_drive
                ),
            });
        }
        self.solve_with_drive(conditions, options).or_else(|e| {
            if matches!(e, QuasiStaticError::AxialLoadTooSmall { .. }) {
                return Err(e);
            }
            match self.via_jones_harris_kinematics(conditions, options, |without| {
                self.solve_with_drive(conditions, without)
            }) {
                Some(Err(refusal @ QuasiStaticError::AxialLoadTooSmall { .. })) => Err(refusal),
                Some(Ok(eq)) => Ok(eq),
                _ => Err(e),
            }
        })
    }

    /// `solve` without the race drive (σ = 0: Jones–Harris kinematics for
    /// free balls), then continued in σ to the options' σ. None where the
    /// drive plays no part (σ = 0, or at rest, where the kinematics do
    /// not enter); the error of `solve`, or of the continuation, otherwise.
    fn via_jones_harris_kinematics(
        &self,
        conditions: &Conditions,
        options: &SolverOptions,
        solve: impl Fn(&SolverOptions) -> Result<Equilibrium, QuasiStaticError>,
    ) -> Option<Result<Equilibrium, QuasiStaticError>> {
        if options.race_drive == 0.0 || conditions.inner_speed == 0.0 {
            return None;
        }
        let without = SolverOptions {
            race_drive: 0.0,
            ..*options
        };
        Some(solve(&without).and_then(|start| {
            let path = self.continue_in_drive(Self::state_of(&start), conditions, options)?;
            Ok(self.continued(&start, path, conditions, options))
        }))
    }

    /// The solution at the end of a continuation `path` from `start`.
    fn continued(
        &self,
        start: &Equilibrium,
        (state, schur, iterations, residual, controls): Path,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Equilibrium {
        self.solution(
            &state,
            &schur,
            start.iterations + iterations,
            residual,
            &controls,
            conditions,
            options,
        )
    }

    /// [`Self::solve`] at the options' race drive.
    fn solve_with_drive(
        &self,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Result<Equilibrium, QuasiStaticError> {
        self.solve_free(conditions, options)
            .or_else(|e| self.start_from_outer_control(conditions, options).ok_or(e))
            .or_else(|e| {
                // Before the costly axial-displacement search: the free
                // solve without the race drive, continued in its strength.
                self.via_jones_harris_kinematics(conditions, options, |without| {
                    self.solve_free(conditions, without)
                })
                .and_then(Result::ok)
                .ok_or(e)
            })
            .or_else(|e| {
                if options.prescribed_displacement[0].is_some() {
                    return Err(e);
                }
                // At speed: from the solution at rest (its axial displacement
                // held while the speed rises); else from the built-in start.
                let at_rest = Conditions {
                    inner_speed: 0.0,
                    ..*conditions
                };
                let rest = (conditions.inner_speed != 0.0)
                    .then(|| self.solve(&at_rest, options).ok())
                    .flatten();
                self.solve_by_axial_displacement(conditions, options, rest.as_ref())
                    .map_err(|fallback| match fallback {
                        QuasiStaticError::AxialLoadTooSmall { .. } => fallback,
                        _ => e,
                    })
            })
    }

    /// Inner or Harris control where the continuation failed: from the
    /// outer-control solution at the same speed and loads (the ring
    /// displacement and ball positions differ little between controls),
    /// by continuation in the control.
    pub(super) fn start_from_outer_control(
        &self,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Option<Equilibrium> {
        if conditions.control == RacewayControl::Outer || conditions.inner_speed == 0.0 {
            return None;
        }
        let outer = Conditions {
            control: RacewayControl::Outer,
            ..*conditions
        };
        let start = self.solve_free(&outer, options).ok()?;
        let path = self
            .continue_in_control(Self::state_of(&start), conditions, options)
            .ok()?;
        Some(self.continued(&start, path, conditions, options))
    }

    /// [`Self::solve`] without the axial-displacement fallback: static
    /// solution, then continuation in speed (or axial load first).
    pub(super) fn solve_free(
        &self,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Result<Equilibrium, QuasiStaticError> {
        let loads = conditions.loads;
        let at_rest = Conditions {
            inner_speed: 0.0,
            ..*conditions
        };
        let start = self.initial_state(&loads, options, false);
        if Self::applied(&loads).amax() == 0.0
            && !self.any_contact(&start, options)
            && conditions.inner_speed == 0.0
        {
            let controls = vec![RingKind::Outer; self.geometry.ball_count];
            return Ok(self.solution(
                &start,
                &Matrix5::zeros(),
                0,
                0.0,
                &controls,
                &at_rest,
                options,
            ));
        }
        let static_solution = self
            .solve_at(start, &at_rest, options)
            .or_else(|_| {
                self.solve_at(self.initial_state(&loads, options, true), &at_rest, options)
            })
            .or_else(|_| self.continue_in_load(&at_rest, options))?;
        let path = self
            .continue_in_speed(static_solution, conditions, options)
            .or_else(|e| {
                self.axial_then_load_at_speed(conditions, options)
                    .map_err(|_| e)
            })?;
        let (state, s, iterations, residual, controls) = path;
        Ok(self.solution(
            &state, &s, iterations, residual, &controls, conditions, options,
        ))
    }

    fn any_contact(&self, state: &State, options: &SolverOptions) -> bool {
        let ring = RingDisplacement::from_array(state.ring.into());
        state.balls.iter().enumerate().any(|(j, y)| {
            let (_, inner, outer) = self.contacts(y, self.azimuth(j, options), &ring);
            inner.in_contact() || outer.in_contact()
        })
    }

    /// Solves starting from a previous solution (warm start for sweeps);
    /// falls back to the built-in start.
    pub fn solve_from(
        &self,
        previous: &Equilibrium,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Result<Equilibrium, QuasiStaticError> {
        let mut guess = Self::state_of(previous);
        if previous.inner_speed != 0.0 {
            let ratio = conditions.inner_speed / previous.inner_speed;
            for b in &mut guess.balls {
                b[2] *= ratio;
                b[3] *= ratio;
                b[4] *= ratio;
            }
        }
        if previous.inner_speed == 0.0 && conditions.inner_speed != 0.0 {
            return self.solve(conditions, options);
        }
        match self.solve_at(guess, conditions, options) {
            Ok((st, s, it, res, controls)) => {
                Ok(self.solution(&st, &s, it, res, &controls, conditions, options))
            }
            Err(_) => self.solve(conditions, options),
        }
    }

    /// The unknowns of a solution.
    pub(super) fn state_of(solution: &Equilibrium) -> State {
        State {
            balls: solution
                .balls
                .iter()
                .map(|b| {
                    Vector5::new(
                        b.axial_position,
                        b.radial_position,
                        b.orbital_speed,
                        b.spin_axial,
                        b.spin_radial,
                    )
                })
                .collect(),
            ring: Vector5::from(solution.displacement),
        }
    }
}
