//! Continuation paths of the quasi-static solve (docs/model.md §7): in speed from
//! the static solution (Euler predictor on the solution's speed tangent,
//! step doubled after easy solves and halved on failure), in load from an
//! equivalent pure axial load, and the fallback that takes the axial load
//! to speed first and then blends to the target loads at speed; in the
//! raceway control (from outer control) and in the race drive's strength
//! (from Jones–Harris kinematics); the first guesses at speed (free balls
//! seated by the centrifugal force, speeds from the kinematic equations).

use super::{Conditions, Matrix5, QuasiStaticError, QuasiStaticSolver, Setup, State, Vector5};
use crate::geometry::RingKind;
use crate::operating::Loads;
use crate::quasistatic::ring_contact::RingDisplacement;
use crate::quasistatic::{RacewayControl, SolverOptions};

/// Continuation in a homotopy parameter p from 0, where `from` is a
/// solution, to 1: `solve(p, guess)` solves at p. First p = 1 in one step;
/// where that fails, steps of p halved on failure and doubled after easy
/// solves (≤ 8 iterations), down to 1e-3.
fn continue_in_parameter(
    from: State,
    mut solve: impl FnMut(f64, State) -> Result<Path, QuasiStaticError>,
) -> Result<Path, QuasiStaticError> {
    let mut failure = match solve(1.0, from.clone()) {
        Ok(path) => return Ok(path),
        Err(e) => e,
    };
    let (mut state, mut iterations) = (from, 0);
    let (mut p, mut step) = (0.0f64, 0.5f64);
    while step >= 1e-3 {
        let next = (p + step).min(1.0);
        match solve(next, state.clone()) {
            Ok((st, s, it, res, controls)) => {
                iterations += it;
                if next == 1.0 {
                    return Ok((st, s, iterations, res, controls));
                }
                (state, p) = (st, next);
                if it <= 8 {
                    step *= 2.0;
                }
                continue;
            }
            Err(e) => failure = e,
        }
        step *= 0.5;
    }
    Err(failure)
}

/// A converged point of a path: state, Schur complement, iterations,
/// residual, raceway controls.
pub(super) type Path = (State, Matrix5, usize, f64, Vec<RingKind>);

impl QuasiStaticSolver {
    /// Static fallback: from a pure axial load of the same magnitude (all
    /// balls loaded, an easy solve) to the target loads along
    /// F(λ) = (1 − λ) F_axial + λ F_target, halving λ's step on failure.
    pub(super) fn continue_in_load(
        &self,
        at_rest: &Conditions,
        options: &SolverOptions,
    ) -> Result<Path, QuasiStaticError> {
        let axial = self.equivalent_axial(&at_rest.loads);
        let current = self.solve_at(
            self.initial_state(&axial, options, false),
            &Conditions {
                loads: axial,
                ..*at_rest
            },
            options,
        )?;
        self.blend_loads(current, &axial, at_rest, options)
    }

    /// A pure axial load of the target's magnitude (forces, moments over
    /// d_m/2): every ball loaded, an easy solve.
    fn equivalent_axial(&self, target: &Loads) -> Loads {
        let magnitude = self.scaled_ring(&Self::applied(target)).norm();
        Loads {
            force: [magnitude, 0.0, 0.0],
            moment: [0.0, 0.0],
        }
    }

    /// Continuation in load at the conditions' speed from the solution
    /// `current` under `axial` to the target loads along
    /// F(λ) = (1 − λ) F_axial + λ F_target, halving λ's step on failure.
    fn blend_loads(
        &self,
        mut current: Path,
        axial: &Loads,
        at: &Conditions,
        options: &SolverOptions,
    ) -> Result<Path, QuasiStaticError> {
        let target = at.loads;
        let blend = |lambda: f64| Loads {
            force: std::array::from_fn(|i| {
                (1.0 - lambda) * axial.force[i] + lambda * target.force[i]
            }),
            moment: std::array::from_fn(|i| lambda * target.moment[i]),
        };
        let (mut lambda, mut step) = (0.0f64, 1.0f64);
        while lambda < 1.0 {
            let next = (lambda + step).min(1.0);
            let conditions = Conditions {
                loads: blend(next),
                ..*at
            };
            match self.solve_at(current.0.clone(), &conditions, options) {
                Ok(solution) => {
                    let easy = solution.2 <= 8;
                    current.2 += solution.2;
                    current = (solution.0, solution.1, current.2, solution.3, solution.4);
                    lambda = next;
                    if easy {
                        step *= 2.0;
                    }
                }
                Err(e) => {
                    step *= 0.5;
                    if step < 1e-4 {
                        return Err(e);
                    }
                }
            }
        }
        Ok(current)
    }

    /// Continuation from the converged static solution `from` to the target
    /// speed, doubling the speed step on success and halving it on failure.
    pub(super) fn continue_in_speed(
        &self,
        from: Path,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Result<Path, QuasiStaticError> {
        let target = conditions.inner_speed;
        let (mut state, mut s, mut iterations, mut residual, mut controls) = from;
        let mut current = 0.0f64;
        let mut step = target;
        let min_step = if options.race_drive > 0.0 { 1e-2 } else { 1e-4 } * target.abs();
        while current != target {
            let next = if (target - current).abs() <= step.abs() {
                target
            } else {
                current + step
            };
            let trial_conditions = Conditions {
                inner_speed: next,
                ..*conditions
            };
            let guess = if current == 0.0 {
                let seated = self.seat_free_balls(&state, next, options);
                self.with_kinematic_speeds(&seated, &controls, &trial_conditions, options)
            } else {
                let at_current = Conditions {
                    inner_speed: current,
                    ..*conditions
                };
                let setup = Setup::new(&at_current, options);
                match self.speed_tangent(&state, &controls, setup) {
                    Some(t) => State {
                        balls: state
                            .balls
                            .iter()
                            .zip(&t.balls)
                            .map(|(y, d)| y + (next - current) * d)
                            .collect(),
                        ring: state.ring + (next - current) * t.ring,
                    },
                    None => {
                        self.with_kinematic_speeds(&state, &controls, &trial_conditions, options)
                    }
                }
            };
            match self.solve_at(guess, &trial_conditions, options) {
                Ok((st, ss, it, res, ctl)) => {
                    state = st;
                    s = ss;
                    iterations += it;
                    residual = res;
                    controls = ctl;
                    current = next;
                    // Grow the step only after an easy solve.
                    if it <= 8 {
                        step *= 2.0;
                    }
                }
                Err(e) => {
                    step *= 0.5;
                    if step.abs() < min_step {
                        return Err(e);
                    }
                }
            }
        }
        Ok((state, s, iterations, residual, controls))
    }

    /// Fallback when the speed continuation from the static solution fails
    /// (light axial with heavy radial load: the unloaded balls' seating at a
    /// few rpm is ill-conditioned): the equivalent pure axial load taken to
    /// speed first (every ball loaded), then a continuation in load at speed.
    pub(super) fn axial_then_load_at_speed(
        &self,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Result<Path, QuasiStaticError> {
        let (at_speed, axial) = self.equivalent_axial_at_speed(conditions, options)?;
        self.blend_loads(at_speed, &axial, conditions, options)
    }

    /// [`Self::axial_then_load_at_speed`] with the axial displacement held
    /// where the equivalent pure axial load puts it (the first point of
    /// the axial-displacement search where the solution at rest cannot be
    /// taken to speed): the held axial displacement returned with the
    /// path.
    pub(super) fn axial_then_load_at_speed_held(
        &self,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Result<(f64, Path), QuasiStaticError> {
        let (at_speed, axial) = self.equivalent_axial_at_speed(conditions, options)?;
        let x = at_speed.0.ring[0];
        let mut held = *options;
        held.prescribed_displacement[0] = Some(x);
        Ok((x, self.blend_loads(at_speed, &axial, conditions, &held)?))
    }

    /// The solution under the equivalent pure axial load (every ball
    /// loaded) taken to the conditions' speed, and that load.
    fn equivalent_axial_at_speed(
        &self,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Result<(Path, Loads), QuasiStaticError> {
        let axial = self.equivalent_axial(&conditions.loads);
        let at_rest = Conditions {
            loads: axial,
            inner_speed: 0.0,
            ..*conditions
        };
        let rest = self.solve_at(
            self.initial_state(&axial, options, false),
            &at_rest,
            options,
        )?;
        let at_speed = self.continue_in_speed(
            rest,
            &Conditions {
                loads: axial,
                ..*conditions
            },
            options,
        )?;
        Ok((at_speed, axial))
    }

    /// [`Self::continue_in_speed`]; where that fails under inner or Harris
    /// control, the continuation in speed under outer control, then in
    /// the control ([`Self::continue_in_control`]).
    pub(super) fn continue_in_speed_via_outer_control(
        &self,
        from: Path,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Result<Path, QuasiStaticError> {
        let direct = self.continue_in_speed(from.clone(), conditions, options);
        let Err(failure) = direct else {
            return direct;
        };
        if conditions.control == RacewayControl::Outer {
            return Err(failure);
        }
        let outer = Conditions {
            control: RacewayControl::Outer,
            ..*conditions
        };
        let (state, ..) = self
            .continue_in_speed(
                (
                    from.0,
                    from.1,
                    from.2,
                    from.3,
                    vec![RingKind::Outer; from.4.len()],
                ),
                &outer,
                options,
            )
            .map_err(|_| failure.clone())?;
        self.continue_in_control(state, conditions, options)
            .map_err(|_| failure)
    }

    /// Continuation in the raceway control from `from`, a solution under
    /// outer control at the conditions' speed and loads, to the
    /// conditions' control, along the share t of the inner raceway in the
    /// inner-controlled balls' control ([`Setup::inner_share`], 0 → 1).
    /// The balls' controls are the conditions' at `from`; under Harris
    /// control they are re-evaluated at t = 1.
    pub(super) fn continue_in_control(
        &self,
        from: State,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Result<Path, QuasiStaticError> {
        let controls = self.controls_for(conditions.control, Some(&from), options);
        continue_in_parameter(from, |share, state| {
            if share == 1.0 {
                return self.solve_at(state, conditions, options);
            }
            let setup = Setup {
                inner_share: share,
                ..Setup::new(conditions, options)
            };
            self.newton(state, &controls, setup)
                .map(|(st, s, it, res)| (st, s, it, res, controls.clone()))
        })
    }

    /// Continuation in the race drive's strength σ
    /// ([`SolverOptions::race_drive`]) from `from`, a solution with σ = 0,
    /// to the options' σ.
    pub(super) fn continue_in_drive(
        &self,
        from: State,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Result<Path, QuasiStaticError> {
        continue_in_parameter(from, |fraction, state| {
            let partial = SolverOptions {
                race_drive: fraction * options.race_drive,
                ..*options
            };
            self.solve_at(state, conditions, &partial)
        })
    }

    /// Tangent of the solution path with respect to the inner-ring speed,
    /// dy/dω_i = −J⁻¹ ∂R/∂ω_i, from the same bordered solve as a Newton
    /// step (Euler predictor of the speed continuation).
    fn speed_tangent(
        &self,
        state: &State,
        controls: &[RingKind],
        setup: Setup<'_>,
    ) -> Option<State> {
        let mut asm = self.assemble(state, controls, setup);
        asm.ball = std::mem::take(&mut asm.speed_derivative);
        asm.ring = Vector5::zeros();
        let (dy, du, _) = Self::newton_step(&asm)?;
        Some(State {
            balls: dy,
            ring: du,
        })
    }

    /// First guess at speed for balls that carry at rest less inner load
    /// than the centrifugal force at speed (none, or the barely touching
    /// balls at the edge of the loaded zone, which the centrifugal force
    /// lifts off the inner race): it seats them at the bottom of the
    /// outer groove, compressed by δ_o = (m r ω_m²/K_o)^{2/3} with the
    /// pure-rolling ω_m.
    fn seat_free_balls(&self, state: &State, omega_i: f64, options: &SolverOptions) -> State {
        let g = &self.geometry;
        let ring = RingDisplacement::from_array(state.ring.into());
        let k_o = self.outer_table.stiffness(0.0);
        let r = g.pitch_diameter / 2.0;
        let omega_m = 0.5 * omega_i * (1.0 - g.ball_diameter / g.pitch_diameter);
        let centrifugal = self.ball_mass * r * omega_m * omega_m;
        let mut out = state.clone();
        for (j, y) in out.balls.iter_mut().enumerate() {
            let (_, inner, _) = self.contacts(j, y, self.azimuth(j, options), &ring);
            if inner.in_contact() && inner.load >= centrifugal {
                continue;
            }
            let approach = (centrifugal / k_o).powf(2.0 / 3.0);
            y[0] = g.outer.groove_centre_axial;
            y[1] = g.outer.groove_centre_radius + g.outer.groove_radius - 0.5 * g.ball_diameter
                + approach;
        }
        out
    }

    /// `state` with every ball's speeds (ω_m, ω_x, ω_r) replaced by the
    /// solution of its kinematic equations (rolling at both contacts, no
    /// spin at the controlling one, with the race drive) at the speed of
    /// `conditions` for the current positions: these equations are linear
    /// in the speeds.
    fn with_kinematic_speeds(
        &self,
        state: &State,
        controls: &[RingKind],
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> State {
        let ring = RingDisplacement::from_array(state.ring.into());
        let setup = Setup::new(conditions, options);
        let mut out = state.clone();
        for (j, y) in out.balls.iter_mut().enumerate() {
            // The kinematic rows are linear in the speeds: one Newton step
            // on their 3 × 3 block solves them.
            let terms = self.ball_terms(j, y, &ring, controls[j], setup);
            let block = terms.a.fixed_view::<3, 3>(2, 2).into_owned();
            let residual = terms.residual.fixed_rows::<3>(2).into_owned();
            if let Some(step) = block.lu().solve(&residual) {
                let speeds = y.fixed_rows::<3>(2) - step;
                y.fixed_rows_mut::<3>(2).copy_from(&speeds);
            }
        }
        out
    }
}
