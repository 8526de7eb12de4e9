//! The solve strategy (docs/model.md §7): the static solution from the built-in
//! start, the continuation in speed, and the fallbacks in order
//! (outer-control start for inner and Harris control, the
//! axial-displacement search, the axial load taken to speed first, and
//! last the solve without the race drive continued in its strength); warm
//! starts from a previous solution.

use super::axial_control::AxialStart;
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
    /// static solution, then continuation in speed; where that fails, the
    /// fallbacks of `solve_with_drive` in order, the first of them the
    /// axial-displacement search (`axial_control`), which either converges
    /// or refuses the point with its least axial load
    /// ([`QuasiStaticError::AxialLoadTooSmall`]); a refusal is the answer.
    ///
    /// With no applied load and no contact closed (clearance, at rest) the
    /// ring can sit anywhere inside the clearance: the centred position is
    /// returned with every ball unloaded and zero stiffness.
    ///
    /// With the race drive on, at speed, where everything fails other than
    /// by a refusal, the whole solve without the drive (Jones–Harris
    /// kinematics for free balls), continued in the drive's strength
    /// ([`SolverOptions::race_drive`]); a refusal found without the drive
    /// is returned as it is.
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
        let unloaded = conditions.loads.force.iter().all(|f| *f == 0.0)
            && conditions.loads.moment.iter().all(|m| *m == 0.0);
        self.solve_with_drive(conditions, options)
            .or_else(|e| {
                if matches!(e, QuasiStaticError::AxialLoadTooSmall { .. }) {
                    return Err(e);
                }
                match self.via_jones_harris_kinematics(conditions, options, |without| {
                    self.solve_with_drive(conditions, without)
                }) {
                    Some(Err(refusal @ QuasiStaticError::AxialLoadTooSmall { .. })) => {
                        Err(refusal)
                    }
                    Some(Ok(eq)) => Ok(eq),
                    _ => Err(e),
                }
            })
            .map_err(|e| {
                // Without any load the ring's position is not determined
                // (at speed the balls leave the inner raceway): say so
                // rather than how Newton failed.
                if unloaded {
                    QuasiStaticError::Unsupported {
                        reason: "no load is applied (all forces and moments are zero), so the inner ring's position is not determined; give a load (an angular-contact bearing runs under an axial load or preload)".into(),
                    }
                } else {
                    e
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

    /// [`Self::solve`] at the options' race drive: the free solve (static
    /// solution continued in speed), the outer-control start, the
    /// axial-displacement search, the axial load taken to speed first, and
    /// the free solve without the drive continued in its strength, in this
    /// order; a refusal ([`QuasiStaticError::AxialLoadTooSmall`]) ends the
    /// chain.
    fn solve_with_drive(
        &self,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Result<Equilibrium, QuasiStaticError> {
        let unless_refused = |result: Result<Equilibrium, QuasiStaticError>,
                              next: &dyn Fn() -> Option<Equilibrium>| {
            match result {
                Err(e) if !matches!(e, QuasiStaticError::AxialLoadTooSmall { .. }) => {
                    next().ok_or(e)
                }
                done => done,
            }
        };
        let free = self
            .solve_static_then_speed(conditions, options)
            .map(|path| self.solution_of_path(path, conditions, options));
        let result = unless_refused(free, &|| self.start_from_outer_control(conditions, options));
        let result = match result {
            Err(e) if !matches!(e, QuasiStaticError::AxialLoadTooSmall { .. }) => self
                .solve_by_axial_displacement_without_drive(conditions, options, None)
                .map_err(|fallback| match fallback {
                    QuasiStaticError::AxialLoadTooSmall { .. } => fallback,
                    _ => e,
                }),
            done => done,
        };
        let result = unless_refused(result, &|| {
            self.axial_then_load_at_speed(conditions, options)
                .ok()
                .map(|path| self.solution_of_path(path, conditions, options))
        });
        unless_refused(result, &|| {
            self.via_jones_harris_kinematics(conditions, options, |without| {
                self.solve_free(conditions, without)
            })
            .and_then(Result::ok)
        })
    }

    /// The axial-displacement search (`axial_control`) without the race
    /// drive, its result continued in the drive's strength at the axial
    /// displacement found. The drive acts on balls whose inner contact is
    /// open, which carry no load to the inner ring: the search's reaction,
    /// and a refusal's least axial load, do not depend on it.
    ///
    /// Without a `neighbour` (a solution at a nearby operating point to
    /// start from), at speed, from the solution at rest; else from the
    /// built-in start.
    fn solve_by_axial_displacement_without_drive(
        &self,
        conditions: &Conditions,
        options: &SolverOptions,
        neighbour: Option<&Equilibrium>,
    ) -> Result<Equilibrium, QuasiStaticError> {
        if options.prescribed_displacement[0].is_some() {
            return Err(QuasiStaticError::Unsupported {
                reason: "the axial displacement is prescribed".into(),
            });
        }
        let without = SolverOptions {
            race_drive: 0.0,
            ..*options
        };
        let at_rest = Conditions {
            inner_speed: 0.0,
            ..*conditions
        };
        let rest = (neighbour.is_none() && conditions.inner_speed != 0.0)
            .then(|| self.solve(&at_rest, options).ok())
            .flatten();
        let start = match (neighbour, &rest) {
            (Some(near), _) => AxialStart::Neighbour(near),
            (None, Some(rest)) => AxialStart::Rest(rest),
            (None, None) => AxialStart::BuiltIn,
        };
        let found = self.solve_by_axial_displacement(conditions, &without, start)?;
        if options.race_drive == 0.0 || conditions.inner_speed == 0.0 {
            return Ok(found);
        }
        let mut held = *options;
        held.prescribed_displacement[0] = Some(found.displacement[0]);
        let path = self.continue_in_drive(Self::state_of(&found), conditions, &held)?;
        let mut eq = self.continued(&found, path, conditions, &held);
        eq.residual = eq.residual.max(found.residual);
        eq.reaction[0] = 0.0;
        Ok(eq)
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
        let path = self
            .solve_static_then_speed(conditions, options)
            .or_else(|e| {
                self.axial_then_load_at_speed(conditions, options)
                    .map_err(|_| e)
            })?;
        Ok(self.solution_of_path(path, conditions, options))
    }

    /// The static solution from the built-in start (or by continuation in
    /// load), continued in speed.
    ///
    /// With no applied load and no contact closed (clearance, at rest) the
    /// ring can sit anywhere inside the clearance: the centred position is
    /// returned with every ball unloaded and zero stiffness.
    fn solve_static_then_speed(
        &self,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Result<Path, QuasiStaticError> {
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
            return Ok((start, Matrix5::zeros(), 0, 0.0, controls));
        }
        let static_solution = self
            .solve_at(start, &at_rest, options)
            .or_else(|_| {
                self.solve_at(self.initial_state(&loads, options, true), &at_rest, options)
            })
            .or_else(|_| self.continue_in_load(&at_rest, options))?;
        self.continue_in_speed(static_solution, conditions, options)
    }

    /// The solution at a converged point of a path.
    fn solution_of_path(
        &self,
        (state, schur, iterations, residual, controls): Path,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Equilibrium {
        self.solution(
            &state, &schur, iterations, residual, &controls, conditions, options,
        )
    }

    fn any_contact(&self, state: &State, options: &SolverOptions) -> bool {
        let ring = RingDisplacement::from_array(state.ring.into());
        state.balls.iter().enumerate().any(|(j, y)| {
            let (_, inner, outer) = self.contacts(j, y, self.azimuth(j, options), &ring);
            inner.in_contact() || outer.in_contact()
        })
    }

    /// Solves starting from a previous solution (warm start for sweeps);
    /// where one Newton solve from it fails, the axial-displacement search
    /// from it (a refusal found so is the answer: along the previous
    /// solution's branch the load needs more axial load); else the
    /// built-in start.
    pub fn solve_from(
        &self,
        previous: &Equilibrium,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Result<Equilibrium, QuasiStaticError> {
        if previous.inner_speed == 0.0 && conditions.inner_speed != 0.0 {
            return self.solve(conditions, options);
        }
        let guess = Self::at_speed_of(previous, conditions);
        match self.solve_at(guess, conditions, options) {
            Ok(path) => Ok(self.solution_of_path(path, conditions, options)),
            Err(_) => self
                .solve_by_axial_displacement_without_drive(conditions, options, Some(previous))
                .or_else(|e| match e {
                    QuasiStaticError::AxialLoadTooSmall { .. } => Err(e),
                    _ => self.solve(conditions, options),
                }),
        }
    }

    /// The unknowns of `solution` with its speeds scaled to the speed of
    /// `conditions` (a first guess there).
    pub(super) fn at_speed_of(solution: &Equilibrium, conditions: &Conditions) -> State {
        let mut guess = Self::state_of(solution);
        if solution.inner_speed != 0.0 {
            let ratio = conditions.inner_speed / solution.inner_speed;
            for b in &mut guess.balls {
                b[2] *= ratio;
                b[3] *= ratio;
                b[4] *= ratio;
            }
        }
        guess
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
