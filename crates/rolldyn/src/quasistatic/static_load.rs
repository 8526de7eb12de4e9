//! Static load distribution (MODEL §7.1): the inner-ring displacement
//! (x, y, z, θ_y, θ_z) and every ball's contacts under combined loads
//! (F_x, F_y, F_z, M_y, M_z) at zero speed, with clearance or preload.
//!
//! # Equations
//! Unknowns: each ball's centre in its azimuth plane (axial x_j, radial
//! r_j; the azimuth φ_j is held by the cage) and the inner-ring
//! displacement u. The outer ring is fixed. Each ball contact comes from the
//! exact torus geometry ([`super::ring_contact`]); the residuals are
//! ```text
//! ball j (e_x, e_r components):  F_ij + F_oj = 0
//! inner ring (F_x, F_y, F_z, M_y, M_z):  Σ_j [−F_ij ; (q_j − t) × (−F_ij)] + applied = 0
//! ```
//! The tangential components of the contact forces (second order in the
//! ring tilt) go to the cage and are not part of the ball equations. This
//! is the textbook two-force-member ball (Harris & Kotzalas, *Essential
//! Concepts*, ch. 7) written with exact geometry instead of small-angle
//! formulas.
//!
//! # Solution
//! Newton's method with the analytic Jacobian. The Jacobian is bordered
//! block-diagonal: a 2 × 2 block per ball, coupled only to the ring. It is
//! solved by eliminating the balls and solving the 5 × 5 Schur complement
//! S = D − Σ C_j A_j⁻¹ B_j, in O(Z). Steps are limited (0.05 D of
//! translation per iteration) and globalised by Armijo backtracking on the
//! squared residual. The start needs no user guess: the ring is pushed along
//! the direction of the applied load until the contact forces balance its
//! magnitude (a 1-D Brent search, balls in equilibrium at every trial), and
//! Newton starts from there.
//!
//! A ball that carries no load has no defined position at zero speed; its
//! equations use the signed extension of the Hertz law, which keeps it
//! where its two gaps balance. The forces on the ring use the physical law.
//!
//! # Stiffness
//! At the solution, the linearised equations give du/dF = −S⁻¹ (implicit
//! function theorem), so the bearing stiffness matrix is K = −S: the
//! Schur complement of the analytic Jacobian, with no re-solve. Units of
//! the entries: N/m, N/rad, N·m/m, N·m/rad in the order (x, y, z, θ_y, θ_z).

use super::ring_contact::{Matrix3x5, RingContactEval, RingDisplacement, evaluate};
use crate::contact::{ContactTable, HertzModel, HertzResult, RacewayContactModel};
use crate::error::InvalidParameter;
use crate::geometry::{BearingGeometry, RingKind};
use crate::material::{Material, effective_modulus};
use crate::math::roots::brent;
use crate::operating::Loads;
use nalgebra::{Matrix2, Matrix3, SMatrix, SVector, Vector2, Vector3};
use serde::Serialize;

type Matrix2x5 = SMatrix<f64, 2, 5>;
type Matrix5x2 = SMatrix<f64, 5, 2>;
type Matrix5 = SMatrix<f64, 5, 5>;
type Vector5 = SVector<f64, 5>;

/// Solver settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StaticOptions {
    /// Newton iteration limit.
    pub max_iterations: usize,
    /// Convergence: every residual (forces, and moments divided by d_m/2)
    /// below this fraction of the load scale.
    pub relative_tolerance: f64,
    /// Azimuth of ball 0 \[rad\] (0: on the +y axis; e_r = cos φ e_y + sin φ e_z).
    pub first_ball_azimuth: f64,
}

impl Default for StaticOptions {
    fn default() -> Self {
        Self {
            max_iterations: 100,
            relative_tolerance: 1e-11,
            first_ball_azimuth: 0.0,
        }
    }
}

/// Why a static solve failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StaticSolveError {
    /// Newton did not reach the tolerance.
    #[error(
        "no static equilibrium found after {iterations} Newton iterations (largest residual {residual:.3e} N); the load may exceed what the bearing can carry"
    )]
    NoConvergence {
        /// Iterations done.
        iterations: usize,
        /// Largest residual at the end \[N\].
        residual: f64,
    },
    /// The ring is not held: no contact can carry the load direction.
    #[error("the bearing cannot carry this load: {reason}")]
    Unsupported {
        /// What is missing.
        reason: String,
    },
}

/// One contact of the solution.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ContactLoad {
    /// Normal load Q \[N\].
    pub load: f64,
    /// Contact angle α \[rad\].
    pub contact_angle: f64,
    /// Penetration (elastic approach) δ \[m\]; negative: gap.
    pub penetration: f64,
    /// Hertz results at Q (semi-axes, p₀).
    pub hertz: HertzResult,
}

/// One ball of the solution.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BallLoad {
    /// Azimuth φ_j \[rad\].
    pub azimuth: f64,
    /// Axial position of the ball centre x_j \[m\].
    pub axial_position: f64,
    /// Radial position of the ball centre r_j \[m\].
    pub radial_position: f64,
    /// Inner-raceway contact.
    pub inner: ContactLoad,
    /// Outer-raceway contact.
    pub outer: ContactLoad,
}

/// A converged static solution.
#[derive(Debug, Clone, PartialEq)]
pub struct StaticSolution {
    /// Inner-ring displacement (x, y, z \[m\], θ_y, θ_z \[rad\]).
    pub displacement: [f64; 5],
    /// Per ball, including balls that carry no load.
    pub balls: Vec<BallLoad>,
    /// Bearing stiffness matrix K = −∂(contact forces on the ring)/∂u, rows
    /// and columns (x, y, z, θ_y, θ_z).
    pub stiffness: [[f64; 5]; 5],
    /// Newton iterations used.
    pub iterations: usize,
    /// Largest residual at the solution \[N\] (moments divided by d_m/2).
    pub residual: f64,
}

/// Static load-distribution solver for one bearing.
#[derive(Debug, Clone)]
pub struct StaticSolver {
    geometry: BearingGeometry,
    inner_table: ContactTable,
    outer_table: ContactTable,
}

/// Ball positions (x_j, r_j) and ring displacement u.
#[derive(Debug, Clone, PartialEq)]
struct State {
    balls: Vec<Vector2<f64>>,
    ring: Vector5,
}

/// Residuals and Jacobian blocks at one state.
struct Assembly {
    ball_residual: Vec<Vector2<f64>>,
    ring_residual: Vector5,
    a: Vec<Matrix2<f64>>,
    b: Vec<Matrix2x5>,
    c: Vec<Matrix5x2>,
    d: Matrix5,
    /// Largest contact load \[N\] (sets the round-off level of the residuals).
    largest_load: f64,
}

fn cross_matrix(v: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -v.z, v.y, v.z, 0.0, -v.x, -v.y, v.x, 0.0)
}

impl StaticSolver {
    /// Builds the contact tables for a bearing and its materials.
    pub fn new(
        geometry: &BearingGeometry,
        ball: &Material,
        rings: &Material,
        model: HertzModel,
    ) -> Result<Self, InvalidParameter> {
        let ep = effective_modulus(ball, rings);
        Ok(Self {
            geometry: geometry.clone(),
            inner_table: ContactTable::new(RacewayContactModel::new(
                geometry,
                RingKind::Inner,
                ep,
                model,
            ))?,
            outer_table: ContactTable::new(RacewayContactModel::new(
                geometry,
                RingKind::Outer,
                ep,
                model,
            ))?,
        })
    }

    /// The bearing geometry.
    pub fn geometry(&self) -> &BearingGeometry {
        &self.geometry
    }

    /// The contact table of one ring.
    pub fn table(&self, ring: RingKind) -> &ContactTable {
        match ring {
            RingKind::Inner => &self.inner_table,
            RingKind::Outer => &self.outer_table,
        }
    }

    fn lever(&self) -> f64 {
        self.geometry.pitch_diameter / 2.0
    }

    fn azimuth(&self, j: usize, options: &StaticOptions) -> f64 {
        options.first_ball_azimuth
            + std::f64::consts::TAU * j as f64 / self.geometry.ball_count as f64
    }

    /// The load vector (F_x, F_y, F_z, M_y, M_z).
    fn applied(loads: &Loads) -> Vector5 {
        Vector5::new(
            loads.force[0],
            loads.force[1],
            loads.force[2],
            loads.moment[0],
            loads.moment[1],
        )
    }

    /// Residual weights: forces as they are, moments divided by d_m/2.
    fn scaled(&self, ring: &Vector5) -> Vector5 {
        let l = self.lever();
        Vector5::new(ring[0], ring[1], ring[2], ring[3] / l, ring[4] / l)
    }

    fn ball_basis(phi: f64) -> (Vector3<f64>, Vector3<f64>) {
        (Vector3::x(), Vector3::new(0.0, phi.cos(), phi.sin()))
    }

    fn ball_contacts(
        &self,
        position: &Vector2<f64>,
        phi: f64,
        ring: &RingDisplacement,
    ) -> (Vector3<f64>, RingContactEval, RingContactEval) {
        let (ex, er) = Self::ball_basis(phi);
        let q = position[0] * ex + position[1] * er;
        let d = self.geometry.ball_diameter;
        let inner = evaluate(&self.geometry.inner, &self.inner_table, d, &q, ring, true);
        let outer = evaluate(
            &self.geometry.outer,
            &self.outer_table,
            d,
            &q,
            &RingDisplacement::default(),
            true,
        );
        (q, inner, outer)
    }

    fn assemble(&self, state: &State, loads: &Loads, options: &StaticOptions) -> Assembly {
        let z = self.geometry.ball_count;
        let ring = RingDisplacement::from_array(state.ring.into());
        let mut asm = Assembly {
            ball_residual: Vec::with_capacity(z),
            ring_residual: Self::applied(loads),
            a: Vec::with_capacity(z),
            b: Vec::with_capacity(z),
            c: Vec::with_capacity(z),
            d: Matrix5::zeros(),
            largest_load: 0.0,
        };
        for (j, position) in state.balls.iter().enumerate() {
            let phi = self.azimuth(j, options);
            let (ex, er) = Self::ball_basis(phi);
            let e = SMatrix::<f64, 3, 2>::from_columns(&[ex, er]);
            let (q, inner, outer) = self.ball_contacts(position, phi, &ring);
            asm.largest_load = asm.largest_load.max(inner.load).max(outer.load);
            asm.ball_residual
                .push(e.transpose() * (inner.force + outer.force));
            asm.a
                .push(e.transpose() * (inner.dforce_dball + outer.dforce_dball) * e);
            asm.b.push(e.transpose() * inner.dforce_dring);

            // Force of the ball on the ring: physical (clipped) law only.
            let (f, df_dq, df_du) = if inner.in_contact() {
                (-inner.force, -inner.dforce_dball, -inner.dforce_dring)
            } else {
                (Vector3::zeros(), Matrix3::zeros(), Matrix3x5::zeros())
            };
            let arm = q - ring.translation;
            let moment = arm.cross(&f);
            let arm_x = cross_matrix(&arm);
            let f_x = cross_matrix(&f);
            let dm_dq = arm_x * df_dq - f_x;
            let mut dm_du = arm_x * df_du;
            for k in 0..3 {
                let col = dm_du.column(k) + f_x.column(k);
                dm_du.set_column(k, &col);
            }
            asm.ring_residual += Vector5::new(f.x, f.y, f.z, moment.y, moment.z);
            let mut c = Matrix5x2::zeros();
            let mut d = Matrix5::zeros();
            let dfq = df_dq * e;
            let dmq = dm_dq * e;
            for col in 0..2 {
                c[(0, col)] = dfq[(0, col)];
                c[(1, col)] = dfq[(1, col)];
                c[(2, col)] = dfq[(2, col)];
                c[(3, col)] = dmq[(1, col)];
                c[(4, col)] = dmq[(2, col)];
            }
            for col in 0..5 {
                d[(0, col)] = df_du[(0, col)];
                d[(1, col)] = df_du[(1, col)];
                d[(2, col)] = df_du[(2, col)];
                d[(3, col)] = dm_du[(1, col)];
                d[(4, col)] = dm_du[(2, col)];
            }
            asm.c.push(c);
            asm.d += d;
        }
        asm
    }

    /// Largest scaled residual of an assembly \[N\].
    fn residual_norm(&self, asm: &Assembly) -> f64 {
        let balls = asm
            .ball_residual
            .iter()
            .map(|r| r.amax())
            .fold(0.0, f64::max);
        balls.max(self.scaled(&asm.ring_residual).amax())
    }

    fn merit(&self, asm: &Assembly) -> f64 {
        asm.ball_residual
            .iter()
            .map(|r| r.norm_squared())
            .sum::<f64>()
            + self.scaled(&asm.ring_residual).norm_squared()
    }

    /// Schur complement S = D − Σ C_j A_j⁻¹ B_j and the Newton step.
    fn newton_step(asm: &Assembly) -> Option<(Vec<Vector2<f64>>, Vector5, Matrix5)> {
        let mut s = asm.d;
        let mut rhs = -asm.ring_residual;
        let mut inv = Vec::with_capacity(asm.a.len());
        for j in 0..asm.a.len() {
            let a_inv = asm.a[j].try_inverse()?;
            s -= asm.c[j] * a_inv * asm.b[j];
            rhs += asm.c[j] * a_inv * asm.ball_residual[j];
            inv.push(a_inv);
        }
        let du = s.lu().solve(&rhs)?;
        let db = (0..asm.a.len())
            .map(|j| -inv[j] * (asm.ball_residual[j] + asm.b[j] * du))
            .collect();
        Some((db, du, s))
    }

    /// Places every ball in equilibrium for a fixed ring displacement.
    fn equilibrate_balls(&self, state: &mut State, options: &StaticOptions) {
        let ring = RingDisplacement::from_array(state.ring.into());
        let max_step = 0.05 * self.geometry.ball_diameter;
        for (j, position) in state.balls.iter_mut().enumerate() {
            let phi = self.azimuth(j, options);
            let (ex, er) = Self::ball_basis(phi);
            let e = SMatrix::<f64, 3, 2>::from_columns(&[ex, er]);
            for _ in 0..50 {
                let (_, inner, outer) = self.ball_contacts(position, phi, &ring);
                let r = e.transpose() * (inner.force + outer.force);
                let scale = inner.force.norm().max(outer.force.norm()).max(1e-12);
                if r.amax() <= 1e-13 * scale {
                    break;
                }
                let a = e.transpose() * (inner.dforce_dball + outer.dforce_dball) * e;
                let Some(step) = a.lu().solve(&(-r)) else {
                    break;
                };
                let factor = (max_step / step.amax().max(f64::MIN_POSITIVE)).min(1.0);
                *position += factor * step;
            }
        }
    }

    /// Initial state: balls at the pitch circle, ring pushed along the load
    /// direction until the contact forces match the load magnitude.
    fn initial_state(&self, loads: &Loads, options: &StaticOptions) -> State {
        let z = self.geometry.ball_count;
        let mut state = State {
            balls: vec![Vector2::new(0.0, self.geometry.pitch_diameter / 2.0); z],
            ring: Vector5::zeros(),
        };
        self.equilibrate_balls(&mut state, options);
        let applied = self.scaled(&Self::applied(loads));
        let magnitude = applied.norm();
        if magnitude == 0.0 {
            return state;
        }
        let direction = applied / magnitude;
        let l = self.lever();
        let ring_at = |s: f64| {
            Vector5::new(
                s * direction[0],
                s * direction[1],
                s * direction[2],
                s * direction[3] / l,
                s * direction[4] / l,
            )
        };
        let balls0 = state.balls.clone();
        // f(s): load-direction component of the residual; positive while
        // the contacts carry less than the load.
        let mut f = |s: f64| {
            let mut trial = State {
                balls: balls0.clone(),
                ring: ring_at(s),
            };
            self.equilibrate_balls(&mut trial, options);
            let asm = self.assemble(&trial, loads, options);
            direction.dot(&self.scaled(&asm.ring_residual))
        };
        let limit = self.geometry.ball_diameter;
        let mut hi = 1e-7 * self.geometry.ball_diameter;
        while hi < limit && f(hi) > 0.0 {
            hi *= 2.0;
        }
        let s = if hi >= limit {
            limit
        } else {
            brent(&mut f, 0.0, hi, 1e-12 * limit).unwrap_or(hi)
        };
        state.ring = ring_at(s);
        self.equilibrate_balls(&mut state, options);
        state
    }

    /// Solves the static load distribution for `loads` from the built-in start.
    ///
    /// With no applied load and no contact closed (a bearing with clearance
    /// at rest), the ring can sit anywhere inside the clearance; the
    /// centred position is returned, every ball unloaded, stiffness zero.
    pub fn solve(
        &self,
        loads: &Loads,
        options: &StaticOptions,
    ) -> Result<StaticSolution, StaticSolveError> {
        let start = self.initial_state(loads, options);
        if Self::applied(loads).amax() == 0.0 {
            let ring = RingDisplacement::from_array(start.ring.into());
            let any_contact = start.balls.iter().enumerate().any(|(j, p)| {
                let (_, inner, outer) = self.ball_contacts(p, self.azimuth(j, options), &ring);
                inner.in_contact() || outer.in_contact()
            });
            if !any_contact {
                return Ok(self.solution(&start, &Matrix5::zeros(), 0, 0.0, options));
            }
        }
        self.newton(start, loads, options)
    }

    /// Solves starting from a previous solution (warm start for sweeps).
    pub fn solve_from(
        &self,
        previous: &StaticSolution,
        loads: &Loads,
        options: &StaticOptions,
    ) -> Result<StaticSolution, StaticSolveError> {
        let start = State {
            balls: previous
                .balls
                .iter()
                .map(|b| Vector2::new(b.axial_position, b.radial_position))
                .collect(),
            ring: Vector5::from(previous.displacement),
        };
        self.newton(start, loads, options)
            .or_else(|_| self.solve(loads, options))
    }

    fn newton(
        &self,
        mut state: State,
        loads: &Loads,
        options: &StaticOptions,
    ) -> Result<StaticSolution, StaticSolveError> {
        let l = self.lever();
        let applied = self.scaled(&Self::applied(loads)).amax();
        let max_translation = 0.05 * self.geometry.ball_diameter;
        let mut asm = self.assemble(&state, loads, options);
        for iteration in 0..=options.max_iterations {
            let residual = self.residual_norm(&asm);
            if !residual.is_finite() {
                break;
            }
            let step = Self::newton_step(&asm);
            // Relative to the applied load or, for a preloaded bearing at
            // rest, to the internal contact loads.
            let scale = applied.max(asm.largest_load);
            let tolerance = options.relative_tolerance * if scale > 0.0 { scale } else { 1.0 };
            if residual <= tolerance {
                let stiffness = step.map(|(_, _, s)| -s).unwrap_or_else(Matrix5::zeros);
                return Ok(self.solution(&state, &stiffness, iteration, residual, options));
            }
            if iteration == options.max_iterations {
                return Err(StaticSolveError::NoConvergence {
                    iterations: iteration,
                    residual,
                });
            }
            let Some((db, du, _)) = step else {
                return Err(StaticSolveError::Unsupported {
                    reason: "the contact stiffness is singular: no ball is loaded in the direction of the load (is the load zero inside the clearance?)".into(),
                });
            };
            let largest = du
                .fixed_rows::<3>(0)
                .amax()
                .max(du.fixed_rows::<2>(3).amax() * l)
                .max(db.iter().map(|v| v.amax()).fold(0.0, f64::max));
            let mut lambda = (max_translation / largest.max(f64::MIN_POSITIVE)).min(1.0);
            let merit0 = self.merit(&asm);
            let mut accepted = None;
            for _ in 0..40 {
                let trial = State {
                    balls: state
                        .balls
                        .iter()
                        .zip(&db)
                        .map(|(b, d)| b + lambda * d)
                        .collect(),
                    ring: state.ring + lambda * du,
                };
                let trial_asm = self.assemble(&trial, loads, options);
                let m = self.merit(&trial_asm);
                if m.is_finite() && m <= (1.0 - 1e-4 * lambda) * merit0 {
                    accepted = Some((trial, trial_asm));
                    break;
                }
                lambda *= 0.5;
            }
            let Some((trial, trial_asm)) = accepted else {
                return Err(StaticSolveError::NoConvergence {
                    iterations: iteration,
                    residual,
                });
            };
            state = trial;
            asm = trial_asm;
        }
        Err(StaticSolveError::NoConvergence {
            iterations: options.max_iterations,
            residual: self.residual_norm(&asm),
        })
    }

    fn solution(
        &self,
        state: &State,
        stiffness: &Matrix5,
        iterations: usize,
        residual: f64,
        options: &StaticOptions,
    ) -> StaticSolution {
        let ring = RingDisplacement::from_array(state.ring.into());
        let contact = |eval: &RingContactEval, table: &ContactTable| ContactLoad {
            load: eval.load,
            contact_angle: eval.contact_angle,
            penetration: eval.penetration,
            hertz: table.at(eval.contact_angle).at_load(eval.load),
        };
        let balls = state
            .balls
            .iter()
            .enumerate()
            .map(|(j, position)| {
                let phi = self.azimuth(j, options);
                let (_, inner, outer) = self.ball_contacts(position, phi, &ring);
                BallLoad {
                    azimuth: phi,
                    axial_position: position[0],
                    radial_position: position[1],
                    inner: contact(&inner, &self.inner_table),
                    outer: contact(&outer, &self.outer_table),
                }
            })
            .collect();
        let mut k = [[0.0; 5]; 5];
        for (i, row) in k.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                *v = stiffness[(i, j)];
            }
        }
        StaticSolution {
            displacement: state.ring.into(),
            balls,
            stiffness: k,
            iterations,
            residual,
        }
    }
}
