//! Axial-displacement control: the last fallback of a quasi-static solve
//! (issue 16's stress grid).
//!
//! A light axial load on an angular-contact bearing under a heavy radial
//! load (7218B: F_x ≤ 100 N with F_z ≥ 10 kN) leaves the ring close to a
//! mechanism: few balls carry, and an axial translation combined with a
//! tilt about the loaded zone is resisted only by the balls at its edge,
//! whose δ^{3/2} law has no second derivative at δ = 0. Newton's steps
//! along that soft mode overshoot by millimetres and the line search
//! stalls (the merit rises for any step the linear model predicts).
//!
//! Prescribing the axial displacement x removes the soft mode (the tilt
//! alone moves the loaded balls axially, which is stiff), so each solve at
//! fixed x converges; x is then found from its reaction, the axial load
//! the constraint must add, R_x(x) = 0, by a safeguarded secant:
//! Newton steps on the conventional axial stiffness 1/C_xx (dR_x/dx with
//! the other loads held) until the root is bracketed, then the Illinois
//! variant of regula falsi.
//!
//! Along the loaded-flank branch R_x falls with x towards the unloaded
//! side; with the tilt free it can reach a minimum short of zero (7218B,
//! F_x = 10 N, F_z = 50 kN: R_x ≥ 16.7 N), beyond which R_x rises again as
//! the balls turn over to the groove's other flank (the torus has no
//! shoulder; docs/geometry.md). When |R_x| keeps growing for
//! [`MARCH_AFTER_MINIMUM`] doubling steps past its minimum, the search
//! stops with [`QuasiStaticError::AxialLoadTooSmall`], giving the least
//! axial load F_x + min R_x.

use super::{
    Conditions, Equilibrium, Matrix5, QuasiStaticError, QuasiStaticSolver, STAGNATION_ACCEPT,
};
use crate::quasistatic::SolverOptions;

/// Largest number of solves of the root search.
const MAX_SOLVES: usize = 60;

/// Doubling steps past a minimum of |R| without a sign change after which
/// the minimum is taken as the end of the loaded-flank branch.
const MARCH_AFTER_MINIMUM: usize = 4;

impl QuasiStaticSolver {
    /// The solution with the axial displacement found from its reaction.
    /// At speed, `rest` is the solution at rest: the first solve holds its
    /// axial displacement and continues it in speed (every solve at a
    /// held x is then warm-started from the last); without it the first
    /// guess is the built-in start's.
    pub(super) fn solve_by_axial_displacement(
        &self,
        conditions: &Conditions,
        options: &SolverOptions,
        rest: Option<&Equilibrium>,
    ) -> Result<Equilibrium, QuasiStaticError> {
        let scale = self
            .scaled_ring(&Self::applied(&conditions.loads))
            .amax()
            .max(f64::MIN_POSITIVE);
        let target = options.relative_tolerance.max(1e-12) * scale;
        let max_step = 0.05 * self.geometry.ball_diameter;
        let held_at = |x: f64| {
            let mut held = *options;
            held.prescribed_displacement[0] = Some(x);
            held
        };
        let mut iterations = 0;
        // Each solve starts from the last solution (one Newton pass at the
        // conditions' speed), else from the built-in start.
        let mut solve = |x: f64, previous: Option<&Equilibrium>| {
            let held = held_at(x);
            match previous {
                Some(p) => self.solve_from(p, conditions, &held),
                None => self
                    .solve_free(conditions, &held)
                    .or_else(|e| self.start_from_outer_control(conditions, &held).ok_or(e)),
            }
            .map(|eq| {
                iterations += eq.iterations;
                let r = eq.reaction[0];
                (eq, r)
            })
        };
        let finish = |mut eq: Equilibrium, r: f64, iterations: usize| {
            eq.reaction[0] = 0.0;
            eq.residual = eq.residual.max(r.abs() / scale);
            eq.iterations = iterations;
            eq
        };
        let mut first_iterations = 0;
        let (mut x, (mut eq, mut r)) = match rest {
            Some(rest) => {
                let x = rest.displacement[0];
                let held = held_at(x);
                let controls = rest.balls.iter().map(|b| b.control).collect();
                let from = (Self::state_of(rest), Matrix5::zeros(), 0, 0.0, controls);
                let (state, schur, it, residual, controls) =
                    self.continue_in_speed_via_outer_control(from, conditions, &held)?;
                let eq = self.solution(&state, &schur, it, residual, &controls, conditions, &held);
                first_iterations = it;
                let r = eq.reaction[0];
                (x, (eq, r))
            }
            None => {
                let x = self.initial_state(&conditions.loads, options, false).ring[0];
                (x, solve(x, None)?)
            }
        };
        // Bracket [(x, R)] once the reaction changes sign.
        let mut bracket: Option<((f64, f64), (f64, f64))> = None;
        let mut last_side = 0i8;
        // The last step while searching, and whether it reduced |R|.
        let mut last_step: Option<f64> = None;
        let mut improving = true;
        // Smallest |R| seen (x, R) and the march steps since |R| last fell.
        let mut smallest = (x, r);
        let mut growing = 0;
        for _ in 0..MAX_SOLVES {
            if r.abs() <= target {
                return Ok(finish(eq, r, iterations + first_iterations));
            }
            let next = match (bracket, last_step) {
                (Some(((a, ra), (b, rb))), _) => (a * rb - b * ra) / (rb - ra),
                // |R| grew: past a minimum of R (another branch of
                // equilibria lies further on); march on, doubling.
                (None, Some(step)) if !improving => x + (2.0 * step).clamp(-max_step, max_step),
                (None, _) => {
                    let k = eq
                        .conventional_stiffness()
                        .map(|k| k[0])
                        .filter(|k| k.is_finite() && *k > 0.0)
                        .unwrap_or(eq.stiffness[0][0].abs().max(f64::MIN_POSITIVE));
                    x - (r / k).clamp(-max_step, max_step)
                }
            };
            let (eq_next, r_next) = match solve(next, Some(&eq)) {
                Ok(v) => v,
                // A failed solve between a good x and the step: halve it.
                Err(_) if bracket.is_none() => solve(0.5 * (x + next), Some(&eq))?,
                Err(e) => return Err(e),
            };
            let x_next = eq_next.displacement[0];
            improving = r_next.abs() < r.abs();
            if r_next.abs() < smallest.1.abs() {
                smallest = (x_next, r_next);
                growing = 0;
            } else if bracket.is_none() && r_next.signum() == r.signum() {
                growing += 1;
                // |R| grew over a march of doubling steps (16 times the
                // step that found the minimum) without changing sign: the
                // reaction has a minimum short of zero. Beyond it the
                // balls move to the groove's other flank (a branch a
                // one-shouldered ring does not have): no equilibrium.
                if growing >= MARCH_AFTER_MINIMUM {
                    return Err(QuasiStaticError::AxialLoadTooSmall {
                        axial_load: conditions.loads.force[0],
                        least_axial_load: conditions.loads.force[0] + smallest.1,
                        speed_rpm: conditions.inner_speed * 60.0 / std::f64::consts::TAU,
                    });
                }
            }
            last_step = Some(x_next - x);
            bracket = match bracket {
                None if r.signum() != r_next.signum() => Some(((x, r), (x_next, r_next))),
                None => None,
                Some(((a, ra), (b, rb))) => {
                    // Illinois: halve the retained end's value when the
                    // same end is kept twice.
                    if r_next.signum() == ra.signum() {
                        let rb = if last_side == 1 { 0.5 * rb } else { rb };
                        last_side = 1;
                        Some(((x_next, r_next), (b, rb)))
                    } else {
                        let ra = if last_side == -1 { 0.5 * ra } else { ra };
                        last_side = -1;
                        Some(((a, ra), (x_next, r_next)))
                    }
                }
            };
            (x, eq, r) = (x_next, eq_next, r_next);
        }
        if r.abs() <= STAGNATION_ACCEPT * scale {
            return Ok(finish(eq, r, iterations + first_iterations));
        }
        Err(QuasiStaticError::NoConvergence {
            iterations: iterations + first_iterations,
            residual: r.abs() / scale,
            speed_rpm: conditions.inner_speed * 60.0 / std::f64::consts::TAU,
        })
    }
}
