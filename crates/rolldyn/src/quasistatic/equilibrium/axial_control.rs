//! Axial-displacement control: the first fallback of a quasi-static solve
//! where the free solve fails, and of a sweep's warm start (the
//! stress grids of docs/quasistatic.md). The caller runs it without the race drive and continues
//! its solution in the drive's strength (`solve.rs`).
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
//! [`MARCH_AFTER_MINIMUM`] doubling steps past its minimum, the minimum is
//! refined (`refine_minimum`); where it stays short of zero the search
//! stops with [`QuasiStaticError::AxialLoadTooSmall`], giving the least
//! axial load F_x + min R_x (at a held x the equilibrium does not depend
//! on F_x, so this is a property of the branch, checked in the tests: at
//! 1.05 times it the point converges).

use super::{
    Conditions, Equilibrium, Matrix5, QuasiStaticError, QuasiStaticSolver, STAGNATION_ACCEPT,
};
use crate::quasistatic::SolverOptions;

/// Where the axial-displacement search takes its first solution from.
#[derive(Clone, Copy)]
pub(super) enum AxialStart<'a> {
    /// The solution at rest: its axial displacement held while the speed
    /// rises (else the equivalent pure axial load's, taken to speed and
    /// then to the loads).
    Rest(&'a Equilibrium),
    /// A solution at a nearby operating point (a sweep's neighbour): its
    /// axial displacement held, one solve from its state.
    Neighbour(&'a Equilibrium),
    /// The built-in start (at rest).
    BuiltIn,
}

/// Largest number of solves of the root search.
const MAX_SOLVES: usize = 60;

/// Doubling steps past a minimum of |R| without a sign change after which
/// the minimum is taken as the end of the loaded-flank branch.
const MARCH_AFTER_MINIMUM: usize = 4;

impl QuasiStaticSolver {
    /// The solution with the axial displacement found from its reaction,
    /// from `start` (every solve at a held x after the first is
    /// warm-started from the last).
    pub(super) fn solve_by_axial_displacement(
        &self,
        conditions: &Conditions,
        options: &SolverOptions,
        start: AxialStart<'_>,
    ) -> Result<Equilibrium, QuasiStaticError> {
        let scale = self
            .scaled_ring(&Self::applied(&conditions.loads))
            .amax()
            .max(f64::MIN_POSITIVE);
        let target = options.relative_tolerance.max(1e-12) * scale;
        let max_step = 0.05 * self.geometry.ball_diameter;
        let held_at = |x: f64| held_at(options, x);
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
        let mut first_iterations = 0;
        let (mut x, (mut eq, mut r)) = match self.axial_start(start, conditions, options)? {
            Some((x, eq, it)) => {
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
        // Smallest |R| seen (x, R), the march steps since |R| last fell,
        // and every solution before a bracket (for the minimum's
        // refinement).
        let mut smallest = (x, r);
        let mut growing = 0;
        let mut samples = vec![(x, r, eq.clone())];
        for _ in 0..MAX_SOLVES {
            if r.abs() <= target {
                return Ok(finish(eq, r / scale, iterations + first_iterations));
            }
            let next = match (bracket, last_step) {
                (Some(((a, ra), (b, rb))), _) => (a * rb - b * ra) / (rb - ra),
                // |R| grew: past a minimum of R (another branch of
                // equilibria lies further on); march on, doubling.
                (None, Some(step)) if !improving => x + (2.0 * step).clamp(-max_step, max_step),
                (None, _) => x - (r / axial_stiffness(&eq)).clamp(-max_step, max_step),
            };
            let (eq_next, r_next) = match solve(next, Some(&eq)) {
                Ok(v) => v,
                // A failed solve between a good x and the step: halve it.
                Err(_) if bracket.is_none() => solve(0.5 * (x + next), Some(&eq))?,
                Err(e) => return Err(e),
            };
            let mut x_next = eq_next.displacement[0];
            let (mut eq_next, mut r_next) = (eq_next, r_next);
            improving = r_next.abs() < r.abs();
            if bracket.is_none() && r_next.signum() == r.signum() {
                samples.push((x_next, r_next, eq_next.clone()));
            }
            if r_next.abs() < smallest.1.abs() {
                smallest = (x_next, r_next);
                growing = 0;
            } else if bracket.is_none() && r_next.signum() == r.signum() {
                growing += 1;
                // |R| grew over a march of doubling steps (16 times the
                // step that found the minimum) without changing sign: the
                // reaction has a minimum short of zero. Beyond it the
                // balls move to the groove's other flank (a branch a
                // one-shouldered ring does not have): no equilibrium,
                // unless the minimum, refined, crosses zero.
                if growing >= MARCH_AFTER_MINIMUM {
                    match refine_minimum(&mut samples, max_step, target, &mut solve) {
                        Minimum::Least(least) => {
                            return Err(QuasiStaticError::AxialLoadTooSmall {
                                axial_load: conditions.loads.force[0],
                                least_axial_load: conditions.loads.force[0] + least,
                                speed_rpm: conditions.inner_speed * 60.0 / std::f64::consts::TAU,
                            });
                        }
                        Minimum::Crossing((xa, ra), at_b) => {
                            // Continue the root search in [a, b] from b.
                            (x, r) = (xa, ra);
                            (x_next, r_next, eq_next) = *at_b;
                        }
                    }
                }
            }
            last_step = Some(x_next - x);
            bracket = next_bracket(bracket, &mut last_side, (x, r), (x_next, r_next));
            (x, eq, r) = (x_next, eq_next, r_next);
        }
        if r.abs() <= STAGNATION_ACCEPT * scale {
            return Ok(finish(eq, r / scale, iterations + first_iterations));
        }
        Err(QuasiStaticError::NoConvergence {
            iterations: iterations + first_iterations,
            residual: r.abs() / scale,
            speed_rpm: conditions.inner_speed * 60.0 / std::f64::consts::TAU,
        })
    }

    /// The first solution of the root search from a sweep's neighbour or
    /// the solution at rest, with its axial displacement and iterations;
    /// None for the built-in start.
    fn axial_start(
        &self,
        start: AxialStart<'_>,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Result<Option<(f64, Equilibrium, usize)>, QuasiStaticError> {
        let held_at = |x: f64| held_at(options, x);
        Ok(Some(match start {
            AxialStart::Neighbour(near) => {
                let x = near.displacement[0];
                let held = held_at(x);
                let guess = Self::at_speed_of(near, conditions);
                let (state, schur, it, residual, controls) =
                    self.solve_at(guess, conditions, &held)?;
                let eq = self.solution(&state, &schur, it, residual, &controls, conditions, &held);
                (x, eq, it)
            }
            AxialStart::Rest(rest) => {
                let controls = rest.balls.iter().map(|b| b.control).collect();
                let from = (Self::state_of(rest), Matrix5::zeros(), 0, 0.0, controls);
                let (x, (state, schur, it, residual, controls)) = self
                    .continue_in_speed_via_outer_control(
                        from,
                        conditions,
                        &held_at(rest.displacement[0]),
                    )
                    .map(|path| (rest.displacement[0], path))
                    .or_else(|e| {
                        self.axial_then_load_at_speed_held(conditions, options)
                            .map_err(|_| e)
                    })?;
                let eq = self.solution(
                    &state,
                    &schur,
                    it,
                    residual,
                    &controls,
                    conditions,
                    &held_at(x),
                );
                (x, eq, it)
            }
            AxialStart::BuiltIn => return Ok(None),
        }))
    }
}

/// The root search's solution: its axial reaction taken as zero, its
/// residual at least the reaction's relative to the loads' scale.
fn finish(mut eq: Equilibrium, relative_reaction: f64, iterations: usize) -> Equilibrium {
    eq.reaction[0] = 0.0;
    eq.residual = eq.residual.max(relative_reaction.abs());
    eq.iterations = iterations;
    eq
}

/// `options` with the axial displacement held at `x`.
fn held_at(options: &SolverOptions, x: f64) -> SolverOptions {
    let mut held = *options;
    held.prescribed_displacement[0] = Some(x);
    held
}

/// The axial stiffness of a Newton step on the reaction: the conventional
/// one where positive, else the magnitude of K_xx.
fn axial_stiffness(eq: &Equilibrium) -> f64 {
    eq.conventional_stiffness()
        .map(|k| k[0])
        .filter(|k| k.is_finite() && *k > 0.0)
        .unwrap_or(eq.stiffness[0][0].abs().max(f64::MIN_POSITIVE))
}

/// The root search's bracket after the step from `(x, r)` to `next`: a
/// first bracket once the reaction changes sign, then Illinois (the
/// retained end's value halved when the same end is kept twice;
/// `last_side` remembers which).
fn next_bracket(
    bracket: Option<((f64, f64), (f64, f64))>,
    last_side: &mut i8,
    (x, r): (f64, f64),
    (x_next, r_next): (f64, f64),
) -> Option<((f64, f64), (f64, f64))> {
    match bracket {
        None if r.signum() != r_next.signum() => Some(((x, r), (x_next, r_next))),
        None => None,
        Some(((a, ra), (b, rb))) => {
            if r_next.signum() == ra.signum() {
                let rb = if *last_side == 1 { 0.5 * rb } else { rb };
                *last_side = 1;
                Some(((x_next, r_next), (b, rb)))
            } else {
                let ra = if *last_side == -1 { 0.5 * ra } else { ra };
                *last_side = -1;
                Some(((a, ra), (x_next, r_next)))
            }
        }
    }
}

/// A refined minimum of the axial reaction.
enum Minimum {
    /// The reaction's least value (signed) on the branch: no root.
    Least(f64),
    /// Two points (x, R) whose reactions differ in sign, a root between,
    /// with the solution at the second (or the second is a root).
    Crossing((f64, f64), Box<(f64, f64, Equilibrium)>),
}

/// The next point of the successive parabolic interpolation through
/// (a, f_a), (b, f_b), (c, f_c), a < b < c with f_b the least: the
/// parabola's vertex, or a golden-section step into the wider side when
/// the vertex lies outside (a, c) or within 1e-3 of the width from b; None
/// when the value the parabola predicts at its vertex is within 1e-4 of
/// f_b (converged).
fn parabolic_step((a, b, c): (f64, f64, f64), (fa, fb, fc): (f64, f64, f64)) -> Option<f64> {
    const GOLDEN: f64 = 0.381_966_011_250_105_1;
    let p = (b - a) * (b - a) * (fb - fc) - (b - c) * (b - c) * (fb - fa);
    let q = (b - a) * (fb - fc) - (b - c) * (fb - fa);
    let vertex = if q != 0.0 { b - 0.5 * p / q } else { f64::NAN };
    let curvature = 2.0 * ((fc - fb) / (c - b) - (fb - fa) / (b - a)) / (c - a);
    let predicted = fb - 0.5 * curvature * (vertex - b).powi(2);
    if vertex.is_finite() && (fb - predicted).abs() <= 1e-4 * fb.abs() {
        return None;
    }
    let width = c - a;
    Some(
        if vertex.is_finite() && vertex > a && vertex < c && (vertex - b).abs() > 1e-3 * width {
            vertex
        } else if c - b > b - a {
            b + GOLDEN * (c - b)
        } else {
            b - GOLDEN * (b - a)
        },
    )
}

/// Solves of the minimum's refinement.
const MAX_REFINE: usize = 16;

/// Refines the minimum of |R(x)| among `samples` (solutions (x, R) whose
/// reactions have one sign): secant descent from the smallest sample until
/// it is bracketed by close neighbours (the march that found the minimum
/// may have jumped between branches of held-x equilibria, so far samples
/// say little), then successive parabolic interpolation, safeguarded by
/// golden-section steps. Steps are at most `max_step`. Stops at a sign
/// change, or a reaction within `tolerance` of zero (a root lies between,
/// or is reached: the caller's root search goes on from there), when the
/// parabola through the bracket predicts less than 1e-4 of the least |R|
/// to gain, or after [`MAX_REFINE`] solves; a failed solve ends the
/// refinement with the least value found.
fn refine_minimum(
    samples: &mut Vec<(f64, f64, Equilibrium)>,
    max_step: f64,
    tolerance: f64,
    solve: &mut impl FnMut(f64, Option<&Equilibrium>) -> Result<(Equilibrium, f64), QuasiStaticError>,
) -> Minimum {
    samples.sort_by(|a, b| a.0.total_cmp(&b.0));
    let sign = samples[0].1.signum();
    let value = |r: f64| sign * r;
    let best = |samples: &[(f64, f64, Equilibrium)]| {
        (0..samples.len())
            .min_by(|&i, &j| value(samples[i].1).total_cmp(&value(samples[j].1)))
            .unwrap_or(0)
    };
    let mut solves = 0;
    // A new solution at x from the nearest sample; a sign change ends the
    // refinement.
    let mut probe = |samples: &mut Vec<(f64, f64, Equilibrium)>,
                     x: f64,
                     solves: &mut usize|
     -> Result<Option<Minimum>, ()> {
        *solves += 1;
        let near = (0..samples.len())
            .min_by(|&i, &j| {
                (samples[i].0 - x)
                    .abs()
                    .total_cmp(&(samples[j].0 - x).abs())
            })
            .unwrap_or(0);
        let (eq, r) = solve(x, Some(&samples[near].2)).map_err(|_| ())?;
        let x = eq.displacement[0];
        if value(r) <= tolerance {
            let (xa, ra) = (samples[near].0, samples[near].1);
            return Ok(Some(Minimum::Crossing((xa, ra), Box::new((x, r, eq)))));
        }
        let at = samples.partition_point(|s| s.0 < x);
        samples.insert(at, (x, r, eq));
        Ok(None)
    };
    // Descent: secant steps on the slope from the smallest sample to its
    // nearest neighbour, away from it, each short of halfway to the next
    // sample on that side (samples may lie on another branch), until the
    // smallest sample has a neighbour on each side within four times the
    // nearer one's distance.
    while solves < MAX_REFINE {
        let i = best(samples);
        let n = samples.len();
        let (b, fb) = (samples[i].0, value(samples[i].1));
        let below = (i > 0).then(|| i - 1);
        let above = (i + 1 < n).then_some(i + 1);
        let near = match (below, above) {
            (Some(l), Some(u)) if b - samples[l].0 <= samples[u].0 - b => l,
            (Some(_), Some(u)) => u,
            (Some(l), None) => l,
            (None, Some(u)) => u,
            (None, None) => match probe(samples, b + 1e-3 * max_step, &mut solves) {
                Ok(Some(crossing)) => return crossing,
                Ok(None) => continue,
                Err(()) => return Minimum::Least(samples[i].1),
            },
        };
        let (xn, fn_) = (samples[near].0, value(samples[near].1));
        let far = if near + 1 == i { above } else { below };
        let gap = (xn - b).abs();
        if far.is_some_and(|k| (samples[k].0 - b).abs() <= 4.0 * gap) {
            break;
        }
        let slope = (fn_ - fb) / (xn - b);
        let mut step = (-fb / slope).clamp(-max_step, max_step);
        if !step.is_finite() || step * (xn - b) > 0.0 {
            step = (b - xn).signum() * gap;
        }
        if let Some(k) = far {
            let room = 0.5 * (samples[k].0 - b);
            if step.abs() > room.abs() {
                step = room;
            }
        }
        match probe(samples, b + step, &mut solves) {
            Ok(Some(crossing)) => return crossing,
            Ok(None) => {}
            Err(()) => return Minimum::Least(samples[best(samples)].1),
        }
    }
    while solves < MAX_REFINE {
        let i = best(samples);
        if i == 0 || i + 1 >= samples.len() {
            break;
        }
        let (a, b, c) = (samples[i - 1].0, samples[i].0, samples[i + 1].0);
        let values = (
            value(samples[i - 1].1),
            value(samples[i].1),
            value(samples[i + 1].1),
        );
        let Some(x) = parabolic_step((a, b, c), values) else {
            break;
        };
        match probe(samples, x, &mut solves) {
            Ok(Some(crossing)) => return crossing,
            Ok(None) => {}
            Err(()) => break,
        }
    }
    Minimum::Least(samples[best(samples)].1)
}
