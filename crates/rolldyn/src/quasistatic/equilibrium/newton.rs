//! Damped Newton iteration of the quasi-static equations (docs/model.md §7): the
//! bordered ball/ring system solved by the Schur complement on the ring,
//! a backtracking line search on the scaled residual, and the convergence
//! rules (tolerance, and acceptance at the requirement when round-off or
//! a near-unloaded ball stops the quadratic convergence).

use super::{
    Assembly, FREE_BALL_TOLERANCE, Matrix5, QuasiStaticError, QuasiStaticSolver, STAGNATION_ACCEPT,
    Setup, State, Vector5,
};
use crate::geometry::RingKind;

impl QuasiStaticSolver {
    /// The converged result; with prescribed displacements the stiffness
    /// comes from the unconstrained equations.
    fn converged(
        &self,
        state: State,
        s: Matrix5,
        iterations: usize,
        residual: f64,
        controls: &[RingKind],
        setup: Setup<'_>,
    ) -> (State, Matrix5, usize, f64) {
        let s = if Self::constrained(setup) {
            self.full_schur(&state, controls, setup)
        } else {
            s
        };
        (state, s, iterations, residual)
    }

    /// Largest relative residuals (forces over `scale`, kinematics over
    /// the reference speeds) of the ring and the balls that load it, and
    /// of the balls free of the inner ring.
    pub(super) fn residual_norm(&self, asm: &Assembly, scale: f64, omega_ref: f64) -> (f64, f64) {
        let v_ref = omega_ref * self.lever();
        let mut loaded = self.scaled_ring(&asm.ring).amax() / scale;
        let mut free: f64 = 0.0;
        for (r, &is_free) in asm.ball.iter().zip(&asm.free) {
            let worst = (r[0].abs() / scale)
                .max(r[1].abs() / scale)
                .max(r[2].abs() / v_ref)
                .max(r[3].abs() / v_ref)
                .max(r[4].abs() / omega_ref);
            if is_free {
                free = free.max(worst);
            } else {
                loaded = loaded.max(worst);
            }
        }
        (loaded, free)
    }

    pub(super) fn merit(&self, asm: &Assembly, scale: f64, omega_ref: f64) -> f64 {
        let v_ref = omega_ref * self.lever();
        let mut sum = (self.scaled_ring(&asm.ring) / scale).norm_squared();
        for r in &asm.ball {
            sum += (r[0] / scale).powi(2)
                + (r[1] / scale).powi(2)
                + (r[2] / v_ref).powi(2)
                + (r[3] / v_ref).powi(2)
                + (r[4] / omega_ref).powi(2);
        }
        sum
    }

    /// Newton step by the Schur complement; also returns S.
    pub(super) fn newton_step(asm: &Assembly) -> Option<(Vec<Vector5>, Vector5, Matrix5)> {
        let mut s = asm.d;
        let mut rhs = -asm.ring;
        let mut inv = Vec::with_capacity(asm.a.len());
        for j in 0..asm.a.len() {
            let a_inv = asm.a[j].try_inverse()?;
            let ca = asm.c[j] * a_inv;
            s -= ca * asm.b[j];
            rhs += ca * asm.ball[j];
            inv.push(a_inv);
        }
        let du = s.lu().solve(&rhs)?;
        let dy = (0..asm.a.len())
            .map(|j| -inv[j] * (asm.ball[j] + asm.b[j] * du))
            .collect();
        Some((dy, du, s))
    }

    /// Newton from `state` at fixed controls. Returns the state, S, the
    /// iterations and the residual.
    pub(super) fn newton(
        &self,
        state: State,
        controls: &[RingKind],
        setup: Setup<'_>,
    ) -> Result<(State, Matrix5, usize, f64), QuasiStaticError> {
        let mut state = Self::with_prescribed(state, setup);
        let l = self.lever();
        let applied = self
            .scaled_ring(&Self::applied(&setup.conditions.loads))
            .amax();
        let omega_ref = setup.conditions.inner_speed.abs().max(1.0);
        let max_translation = 0.05 * self.geometry.ball_diameter;
        // Ball spin reaches ~(d_m/D) ω_i; the cap only stops absurd steps.
        let max_speed_step =
            2.0 * omega_ref * self.geometry.pitch_diameter / self.geometry.ball_diameter;
        let mut asm = self.constrained_assembly(&state, controls, setup);
        let scale = applied.max(asm.largest_load).max(f64::MIN_POSITIVE);
        let fail = |iterations, residual| QuasiStaticError::NoConvergence {
            iterations,
            residual,
            speed_rpm: setup.conditions.inner_speed * 60.0 / std::f64::consts::TAU,
        };
        for iteration in 0..=setup.options.max_iterations {
            let scale_now = applied.max(asm.largest_load).max(f64::MIN_POSITIVE);
            let (residual, free) = self.residual_norm(&asm, scale_now, omega_ref);
            if !residual.is_finite() || !free.is_finite() {
                return Err(fail(iteration, residual.max(free)));
            }
            let step = Self::newton_step(&asm);
            let tolerance = setup.options.relative_tolerance;
            if residual <= tolerance && free <= FREE_BALL_TOLERANCE.max(tolerance) {
                let s = step.map(|(_, _, s)| s).unwrap_or_else(Matrix5::zeros);
                return Ok(self.converged(state, s, iteration, residual, controls, setup));
            }
            if iteration == setup.options.max_iterations {
                // Out of iterations while still descending: a ball at the
                // edge of the loaded zone (δ → 0, where δ^{3/2} has no
                // second derivative) slows Newton to linear convergence.
                // Accepted at the requirement, as a stall is.
                if residual <= STAGNATION_ACCEPT && free <= FREE_BALL_TOLERANCE {
                    let s = step.map(|(_, _, s)| s).unwrap_or_else(Matrix5::zeros);
                    return Ok(self.converged(state, s, iteration, residual, controls, setup));
                }
                return Err(fail(iteration, residual.max(free)));
            }
            let Some((dy, du, _)) = step else {
                return Err(QuasiStaticError::Unsupported {
                    reason: "the contact stiffness is singular: no ball is loaded in the direction of the load".into(),
                });
            };
            let mut largest_translation = du
                .fixed_rows::<3>(0)
                .amax()
                .max(du.fixed_rows::<2>(3).amax() * l);
            let mut largest_speed: f64 = 0.0;
            for v in &dy {
                largest_translation = largest_translation.max(v[0].abs()).max(v[1].abs());
                largest_speed = largest_speed.max(v.fixed_rows::<3>(2).amax());
            }
            let mut lambda = (max_translation / largest_translation.max(f64::MIN_POSITIVE))
                .min(max_speed_step / largest_speed.max(f64::MIN_POSITIVE))
                .min(1.0);
            let merit0 = self.merit(&asm, scale, omega_ref);
            let mut accepted = None;
            for _ in 0..40 {
                let trial = State {
                    balls: state
                        .balls
                        .iter()
                        .zip(&dy)
                        .map(|(b, d)| b + lambda * d)
                        .collect(),
                    ring: state.ring + lambda * du,
                };
                let trial_asm = self.constrained_assembly(&trial, controls, setup);
                let m = self.merit(&trial_asm, scale, omega_ref);
                if m.is_finite() && m <= (1.0 - 1e-4 * lambda) * merit0 {
                    accepted = Some((trial, trial_asm));
                    break;
                }
                lambda *= 0.5;
            }
            let Some((trial, trial_asm)) = accepted else {
                // No descent left: round-off. Accept if already well inside
                // the requirement (1e-8 of the load, VALIDATION B5).
                if residual <= STAGNATION_ACCEPT && free <= FREE_BALL_TOLERANCE {
                    let s = Self::newton_step(&asm)
                        .map(|(_, _, s)| s)
                        .unwrap_or_else(Matrix5::zeros);
                    return Ok(self.converged(state, s, iteration, residual, controls, setup));
                }
                return Err(fail(iteration, residual.max(free)));
            };
            state = trial;
            asm = trial_asm;
        }
        Err(fail(setup.options.max_iterations, f64::NAN))
    }
}
