//! Quasi-static equilibrium of a ball bearing (MODEL §7): the static load
//! distribution at zero speed and the Jones–Harris high-speed model, one
//! set of equations.
//!
//! # Unknowns
//! Per ball j (azimuth φ_j fixed by the cage): the centre in its azimuth
//! plane (x_j, r_j), the orbital speed ω_m and the ball's absolute angular
//! velocity (ω_x, ω_r) in the azimuth frame (yaw ω_t = 0, as in Jones–Harris).
//! For the inner ring: u = (x, y, z, θ_y, θ_z). The outer ring is fixed and
//! the inner ring turns at ω_i.
//!
//! # Equations (per ball, then the inner ring)
//! ```text
//! forces (e_x, e_r):   F_i + F_o + f_i + f_o + m r ω_m² e_r = 0
//! rolling, contact k:  ω_m r + (D/2)(ω_x n_r − ω_r n_x) − Ω_k (r + (D/2) n_r) = 0     (k = i, o)
//! raceway control c:   (ω_x − Ω_c) n_x + ω_r n_r = 0                                (no spin at c)
//! inner ring:          Σ_j −(F_ij + f_ij), moments about the ring centre, + applied = 0
//! ```
//! F_k = −Q_k n_k are the normal forces of the exact torus contacts
//! ([`super::ring_contact`]), n_x, n_r the normal's axial and radial
//! components, Ω_i = ω_i, Ω_o = 0. The gyroscopic moment the ball needs,
//! M_g = J ω_m ω_r about e_t (J = m D²/10, from dH/dt = ω_m e_x × J ω_b,
//! MODEL §1), is carried by friction at the contacts:
//! f_k = λ_k (M_g/D) (n_x e_r − n_r e_x), with (λ_i, λ_o) = (0, 2) for outer-
//! and (2, 0) for inner-raceway control (Harris & Kotzalas, *Advanced
//! Concepts of Bearing Technology*, 5th ed., §3.3, eqs 3.49–3.56). The
//! centrifugal force is m r ω_m² with the ball's actual orbit radius r
//! (MODEL's ½ m d_m ω_m² is its value at r = d_m/2). The rolling equations
//! use the nominal ring axes: ring displacements change surface speeds by a
//! relative ~displacement/d_m, which Jones–Harris also neglects.
//!
//! At zero speed the kinematic equations give zero speeds and the force
//! equations are the textbook two-force-member ball with exact geometry.
//!
//! **Raceway control.** `outer`, `inner`, or `harris`: per ball, the raceway
//! with the larger spin-resisting moment, ∝ Q a E(m) (Harris & Kotzalas,
//! *Advanced Concepts*, §3.4), controls. The criterion is re-evaluated after
//! each converged solve until no ball changes (at most 5 passes); the
//! intermediate band where neither raceway controls is not modelled.
//!
//! **Unloaded balls.** A ball with no contact has no defined position at
//! zero speed; its force equations use the signed extension of the Hertz
//! law (weight 1 at zero speed), which keeps it where its two gaps balance.
//! At speed centrifugal force seats such a ball on the outer raceway and
//! the extension keeps only a weight of [`SPEED_EXTENSION`] = 1e-9: the
//! pull of an open inner contact on its ball is at most 1e-9 of the Hertz
//! force at its gap (~3e-7 N for a 10 µm gap on a 7008C), far below the
//! ball's centrifugal load. Forces on the ring always use the physical law.
//!
//! # Solution
//! Newton's method with the analytic Jacobian, bordered block-diagonal (a
//! 5 × 5 block per ball coupled only to the ring), solved by eliminating
//! the balls and solving the 5 × 5 Schur complement S = D − Σ C_j A_j⁻¹ B_j
//! (O(Z) work). Steps are limited to 0.05 D of translation and globalised
//! by Armijo backtracking on the scaled squared residual. The start needs no
//! user guess: the ring is first pushed along the load direction by a
//! Hertz-based estimate of its displacement. If Newton fails from there, a
//! 1-D Brent search along the load direction (balls in equilibrium at each
//! trial) finds where the contacts carry the load, and Newton restarts.
//! Speed is reached by continuation from the static solution, with the
//! speed step halved on failure.
//!
//! # Stiffness
//! At the solution du/dF = −S⁻¹ (implicit-function theorem), so the bearing
//! stiffness matrix is K = −S, with no re-solve. Rows and columns are
//! (x, y, z, θ_y, θ_z); units N/m, N/rad, N·m/m, N·m/rad.

pub use super::error::QuasiStaticError;
use super::ring_contact::{Matrix3x5, RingContactEval, RingDisplacement, evaluate};
use crate::contact::{ContactTable, HertzModel, HertzResult, RacewayContactModel};
use crate::error::InvalidParameter;
use crate::geometry::{BearingGeometry, RingKind};
use crate::material::{Material, effective_modulus};
use crate::math::roots::brent;
use crate::operating::Loads;
use nalgebra::{Matrix3, SMatrix, SVector, Vector3};
use serde::{Deserialize, Serialize};

mod axial_control;
mod constraints;
mod continuation;
mod newton;
mod rebuild;
mod solve;

type Matrix5 = SMatrix<f64, 5, 5>;
type Vector5 = SVector<f64, 5>;
type Row3 = SMatrix<f64, 1, 3>;
type Row5 = SMatrix<f64, 1, 5>;

/// Weight of the signed Hertz extension in the ball equations at speed.
pub const SPEED_EXTENSION: f64 = 1e-9;

/// A solve whose line search stalls (round-off), or that runs out of
/// iterations converging only linearly (a ball at the edge of the loaded
/// zone), at or below this relative residual, the 1e-8 requirement of
/// VALIDATION B5, is accepted; the residual reached is reported with the
/// solution.
const STAGNATION_ACCEPT: f64 = 1e-8;

/// Which raceway controls the ball spin (Jones–Harris).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum RacewayControl {
    /// No spin at the outer contact (seed 002 Table 1's choice).
    #[default]
    Outer,
    /// No spin at the inner contact.
    Inner,
    /// Per ball, the raceway with the larger Q a E(m) controls.
    Harris,
}

/// Operating point of a quasi-static solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Conditions {
    /// Loads on the inner ring.
    pub loads: Loads,
    /// Inner-ring speed ω_i \[rad/s\] (0: static load distribution).
    pub inner_speed: f64,
    /// Raceway control hypothesis.
    pub control: RacewayControl,
}

/// Solver settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverOptions {
    /// Newton iteration limit per solve.
    pub max_iterations: usize,
    /// Convergence: force residuals below this fraction of the load scale
    /// (moments divided by d_m/2), kinematic residuals below it relative to
    /// ω_i d_m/2.
    pub relative_tolerance: f64,
    /// Azimuth of ball 0 \[rad\] (0: +y axis; e_r = cos φ e_y + sin φ e_z).
    pub first_ball_azimuth: f64,
    /// Ring displacements held at a value (x, y, z \[m\], θ_y, θ_z \[rad\]):
    /// a fixed tilt or misalignment; None: free, its load given.
    pub prescribed_displacement: [Option<f64>; 5],
}

impl Default for SolverOptions {
    fn default() -> Self {
        Self {
            max_iterations: 60,
            relative_tolerance: 1e-11,
            first_ball_azimuth: 0.0,
            prescribed_displacement: [None; 5],
        }
    }
}

/// One contact of the solution.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ContactSolution {
    /// Normal load Q \[N\].
    pub load: f64,
    /// Contact angle α \[rad\].
    pub contact_angle: f64,
    /// Penetration (elastic approach) δ \[m\]; negative: gap.
    pub penetration: f64,
    /// Spin-to-roll ratio ω_s/ω_roll of the ball relative to the ring.
    pub spin_to_roll: f64,
    /// Hertz results at Q (semi-axes, p₀).
    pub hertz: HertzResult,
}

/// One ball of the solution.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BallSolution {
    /// Azimuth φ_j \[rad\].
    pub azimuth: f64,
    /// Axial position of the ball centre \[m\].
    pub axial_position: f64,
    /// Radial position of the ball centre \[m\].
    pub radial_position: f64,
    /// Orbital speed ω_m \[rad/s\].
    pub orbital_speed: f64,
    /// Ball angular velocity, axial component ω_x (absolute) \[rad/s\].
    pub spin_axial: f64,
    /// Ball angular velocity, radial component ω_r \[rad/s\].
    pub spin_radial: f64,
    /// Ball spin speed relative to the cage ω_R = |ω_b − ω_m e_x| \[rad/s\].
    pub spin_speed: f64,
    /// Attitude angle β of the spin axis relative to the cage, from the
    /// bearing axis, positive as in Harris & Kotzalas (the ball spins
    /// backwards about the axis relative to the cage) \[rad\]. Under outer
    /// control tan β = sin α_o/(cos α_o + D/(2r)), Harris's eq. 3.39 with
    /// the ball's actual orbit radius r for d_m/2.
    pub attitude: f64,
    /// The raceway that controls this ball.
    pub control: RingKind,
    /// Inner-raceway contact.
    pub inner: ContactSolution,
    /// Outer-raceway contact.
    pub outer: ContactSolution,
}

/// A converged quasi-static solution.
#[derive(Debug, Clone, PartialEq)]
pub struct Equilibrium {
    /// Inner-ring speed \[rad/s\].
    pub inner_speed: f64,
    /// Inner-ring displacement (x, y, z \[m\], θ_y, θ_z \[rad\]).
    pub displacement: [f64; 5],
    /// Per ball, including balls that carry no load.
    pub balls: Vec<BallSolution>,
    /// Bearing stiffness matrix K = −∂(contact forces on the ring)/∂u.
    pub stiffness: [[f64; 5]; 5],
    /// Loads the prescribed displacements need (F_x, F_y, F_z \[N\], M_y,
    /// M_z \[N·m\]; zero where the displacement is free).
    pub reaction: [f64; 5],
    /// Newton iterations used (all passes and continuation steps).
    pub iterations: usize,
    /// Largest relative residual at the solution.
    pub residual: f64,
}

impl Equilibrium {
    /// Cage speed: the mean orbital speed of the balls \[rad/s\].
    pub fn cage_speed(&self) -> f64 {
        self.balls.iter().map(|b| b.orbital_speed).sum::<f64>() / self.balls.len().max(1) as f64
    }
}

/// Quasi-static solver for one bearing and its materials.
#[derive(Debug, Clone)]
pub struct QuasiStaticSolver {
    geometry: BearingGeometry,
    inner_table: ContactTable,
    outer_table: ContactTable,
    ball_mass: f64,
    ball_inertia: f64,
}

/// Unknowns: per ball (x, r, ω_m, ω_x, ω_r), ring u.
#[derive(Debug, Clone, PartialEq)]
struct State {
    balls: Vec<Vector5>,
    ring: Vector5,
}

/// Residuals and Jacobian blocks.
struct Assembly {
    ball: Vec<Vector5>,
    ring: Vector5,
    a: Vec<Matrix5>,
    b: Vec<Matrix5>,
    c: Vec<Matrix5>,
    d: Matrix5,
    largest_load: f64,
}

/// Fixed per-solve data of the assembly.
#[derive(Clone, Copy)]
struct Setup<'a> {
    conditions: &'a Conditions,
    options: &'a SolverOptions,
    /// Weight of the signed Hertz extension in the ball equations.
    extension: f64,
}

fn cross_matrix(v: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -v.z, v.y, v.z, 0.0, -v.x, -v.y, v.x, 0.0)
}

/// The force of a contact on the ball, with the extension weighted.
fn weighted(eval: &RingContactEval, extension: f64) -> (Vector3<f64>, Matrix3<f64>, Matrix3x5) {
    let w = if eval.in_contact() { 1.0 } else { extension };
    (w * eval.force, w * eval.dforce_dball, w * eval.dforce_dring)
}

impl QuasiStaticSolver {
    /// Builds the contact tables for a bearing and its materials.
    pub fn new(
        geometry: &BearingGeometry,
        ball: &Material,
        rings: &Material,
        model: HertzModel,
    ) -> Result<Self, InvalidParameter> {
        let ep = effective_modulus(ball, rings);
        let ball_mass = geometry.ball_mass(ball.density);
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
            ball_mass,
            ball_inertia: ball_mass * geometry.ball_diameter.powi(2) / 10.0,
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

    fn azimuth(&self, j: usize, options: &SolverOptions) -> f64 {
        options.first_ball_azimuth
            + std::f64::consts::TAU * j as f64 / self.geometry.ball_count as f64
    }

    fn applied(loads: &Loads) -> Vector5 {
        Vector5::new(
            loads.force[0],
            loads.force[1],
            loads.force[2],
            loads.moment[0],
            loads.moment[1],
        )
    }

    /// Forces as they are, moments divided by d_m/2.
    fn scaled_ring(&self, ring: &Vector5) -> Vector5 {
        let l = self.lever();
        Vector5::new(ring[0], ring[1], ring[2], ring[3] / l, ring[4] / l)
    }

    fn basis(phi: f64) -> (Vector3<f64>, Vector3<f64>) {
        (Vector3::x(), Vector3::new(0.0, phi.cos(), phi.sin()))
    }

    fn contacts(
        &self,
        y: &Vector5,
        phi: f64,
        ring: &RingDisplacement,
    ) -> (Vector3<f64>, RingContactEval, RingContactEval) {
        let (ex, er) = Self::basis(phi);
        let q = y[0] * ex + y[1] * er;
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

    /// (λ_i, λ_o) and the controlling ring of ball j.
    fn control_of(control: RingKind) -> (f64, f64) {
        match control {
            RingKind::Outer => (0.0, 2.0),
            RingKind::Inner => (2.0, 0.0),
        }
    }

    fn assemble(&self, state: &State, controls: &[RingKind], setup: Setup<'_>) -> Assembly {
        let z = self.geometry.ball_count;
        let d = self.geometry.ball_diameter;
        let half = 0.5 * d;
        let (m, inertia) = (self.ball_mass, self.ball_inertia);
        let omega_i = setup.conditions.inner_speed;
        let ring = RingDisplacement::from_array(state.ring.into());
        let mut asm = Assembly {
            ball: Vec::with_capacity(z),
            ring: Self::applied(&setup.conditions.loads),
            a: Vec::with_capacity(z),
            b: Vec::with_capacity(z),
            c: Vec::with_capacity(z),
            d: Matrix5::zeros(),
            largest_load: 0.0,
        };
        for (j, y) in state.balls.iter().enumerate() {
            let phi = self.azimuth(j, setup.options);
            let (ex, er) = Self::basis(phi);
            let e = SMatrix::<f64, 3, 2>::from_columns(&[ex, er]);
            let (q, inner, outer) = self.contacts(y, phi, &ring);
            asm.largest_load = asm.largest_load.max(inner.load).max(outer.load);
            let (r, wm, wx, wr) = (y[1], y[2], y[3], y[4]);
            let (lambda_i, lambda_o) = Self::control_of(controls[j]);

            // Normal components and their gradients.
            let nx = |c: &RingContactEval| c.normal.dot(&ex);
            let nr = |c: &RingContactEval| c.normal.dot(&er);
            let grad_q = |c: &RingContactEval, axis: &Vector3<f64>| -> Row3 {
                axis.transpose() * c.dnormal_dball
            };
            let grad_u = |c: &RingContactEval, axis: &Vector3<f64>| -> Row5 {
                axis.transpose() * c.dnormal_dring
            };

            // Gyroscopic friction f_k = c_k t_k, t_k = n_x e_r − n_r e_x.
            let mg = inertia * wm * wr;
            let tangent = |c: &RingContactEval| nx(c) * er - nr(c) * ex;
            let dtangent_dq = |c: &RingContactEval| er * grad_q(c, &ex) - ex * grad_q(c, &er);
            let dtangent_du = |c: &RingContactEval| er * grad_u(c, &ex) - ex * grad_u(c, &er);
            let (ci, co) = (lambda_i * mg / d, lambda_o * mg / d);
            let (fi, fo) = (ci * tangent(&inner), co * tangent(&outer));

            let (force_i, dfi_dq, dfi_du) = weighted(&inner, setup.extension);
            let (force_o, dfo_dq, _) = weighted(&outer, setup.extension);

            let mut res = Vector5::zeros();
            let force = e.transpose() * (force_i + force_o + fi + fo);
            res[0] = force[0];
            res[1] = force[1] + m * r * wm * wm;
            let rolling = |c: &RingContactEval, omega: f64| {
                wm * r + half * (wx * nr(c) - wr * nx(c)) - omega * (r + half * nr(c))
            };
            res[2] = rolling(&inner, omega_i);
            res[3] = rolling(&outer, 0.0);
            let (cc, omega_c) = match controls[j] {
                RingKind::Inner => (&inner, omega_i),
                RingKind::Outer => (&outer, 0.0),
            };
            res[4] = (wx - omega_c) * nx(cc) + wr * nr(cc);
            asm.ball.push(res);

            // A: ball rows × (x, r, ω_m, ω_x, ω_r).
            let mut a = Matrix5::zeros();
            let df_dq = dfi_dq + dfo_dq + ci * dtangent_dq(&inner) + co * dtangent_dq(&outer);
            let f_pos = e.transpose() * df_dq * e;
            let dforce_dwm = e.transpose()
                * (lambda_i * inertia * wr / d * tangent(&inner)
                    + lambda_o * inertia * wr / d * tangent(&outer));
            let dforce_dwr = e.transpose()
                * (lambda_i * inertia * wm / d * tangent(&inner)
                    + lambda_o * inertia * wm / d * tangent(&outer));
            for row in 0..2 {
                a[(row, 0)] = f_pos[(row, 0)];
                a[(row, 1)] = f_pos[(row, 1)];
                a[(row, 2)] = dforce_dwm[row];
                a[(row, 4)] = dforce_dwr[row];
            }
            a[(1, 1)] += m * wm * wm;
            a[(1, 2)] += 2.0 * m * r * wm;
            let rolling_dq = |c: &RingContactEval, omega: f64| -> Row3 {
                half * (wx - omega) * grad_q(c, &er) - half * wr * grad_q(c, &ex)
            };
            for (row, c, omega) in [(2, &inner, omega_i), (3, &outer, 0.0)] {
                let g = rolling_dq(c, omega) * e;
                a[(row, 0)] = g[0];
                a[(row, 1)] = g[1] + wm - omega;
                a[(row, 2)] = r;
                a[(row, 3)] = half * nr(c);
                a[(row, 4)] = -half * nx(c);
            }
            let spin_dq: Row3 = (wx - omega_c) * grad_q(cc, &ex) + wr * grad_q(cc, &er);
            let g = spin_dq * e;
            a[(4, 0)] = g[0];
            a[(4, 1)] = g[1];
            a[(4, 3)] = nx(cc);
            a[(4, 4)] = nr(cc);
            asm.a.push(a);

            // B: ball rows × ring u (only the inner contact depends on u).
            let mut b = Matrix5::zeros();
            let fu = e.transpose() * (dfi_du + ci * dtangent_du(&inner));
            b.fixed_view_mut::<2, 5>(0, 0).copy_from(&fu);
            let roll_u: Row5 =
                half * (wx - omega_i) * grad_u(&inner, &er) - half * wr * grad_u(&inner, &ex);
            b.set_row(2, &roll_u);
            if controls[j] == RingKind::Inner {
                let spin_u: Row5 = (wx - omega_i) * grad_u(&inner, &ex) + wr * grad_u(&inner, &er);
                b.set_row(4, &spin_u);
            }
            asm.b.push(b);

            // Ring: force and moment of this ball on the inner ring
            // (physical normal law plus the inner friction force).
            let (fn_phys, dfn_dq, dfn_du) = if inner.in_contact() {
                (inner.force, inner.dforce_dball, inner.dforce_dring)
            } else {
                (Vector3::zeros(), Matrix3::zeros(), Matrix3x5::zeros())
            };
            let f_ring = -(fn_phys + fi);
            let df_ring_dq = -(dfn_dq + ci * dtangent_dq(&inner));
            let df_ring_du = -(dfn_du + ci * dtangent_du(&inner));
            let df_ring_dwm = -(lambda_i * inertia * wr / d) * tangent(&inner);
            let df_ring_dwr = -(lambda_i * inertia * wm / d) * tangent(&inner);
            let arm = q - ring.translation;
            let arm_x = cross_matrix(&arm);
            let f_x = cross_matrix(&f_ring);
            let n_x = cross_matrix(&inner.normal);
            let fi_x = cross_matrix(&fi);
            // Friction acts at P = q + (D/2) n: extra couple −(D/2) n × f_i.
            let moment = arm.cross(&f_ring) - half * inner.normal.cross(&fi);
            let dm_dq = arm_x * df_ring_dq
                - f_x
                - half * (n_x * (ci * dtangent_dq(&inner)) - fi_x * inner.dnormal_dball);
            let mut dm_du = arm_x * df_ring_du
                - half * (n_x * (ci * dtangent_du(&inner)) - fi_x * inner.dnormal_dring);
            for k in 0..3 {
                let col = dm_du.column(k) + f_x.column(k);
                dm_du.set_column(k, &col);
            }
            let dm_dwm =
                arm_x * df_ring_dwm - half * n_x * (lambda_i * inertia * wr / d * tangent(&inner));
            let dm_dwr =
                arm_x * df_ring_dwr - half * n_x * (lambda_i * inertia * wm / d * tangent(&inner));
            asm.ring += Vector5::new(f_ring.x, f_ring.y, f_ring.z, moment.y, moment.z);

            let mut c = Matrix5::zeros();
            let fq = df_ring_dq * e;
            let mq = dm_dq * e;
            for col in 0..2 {
                for row in 0..3 {
                    c[(row, col)] = fq[(row, col)];
                }
                c[(3, col)] = mq[(1, col)];
                c[(4, col)] = mq[(2, col)];
            }
            for row in 0..3 {
                c[(row, 2)] = df_ring_dwm[row];
                c[(row, 4)] = df_ring_dwr[row];
            }
            c[(3, 2)] = dm_dwm.y;
            c[(4, 2)] = dm_dwm.z;
            c[(3, 4)] = dm_dwr.y;
            c[(4, 4)] = dm_dwr.z;
            asm.c.push(c);
            let mut dd = Matrix5::zeros();
            for col in 0..5 {
                for row in 0..3 {
                    dd[(row, col)] = df_ring_du[(row, col)];
                }
                dd[(3, col)] = dm_du[(1, col)];
                dd[(4, col)] = dm_du[(2, col)];
            }
            asm.d += dd;
        }
        asm
    }

    /// Places every ball in force equilibrium for a fixed ring (zero speed).
    fn equilibrate_balls(&self, state: &mut State, options: &SolverOptions) {
        let ring = RingDisplacement::from_array(state.ring.into());
        let max_step = 0.05 * self.geometry.ball_diameter;
        for (j, y) in state.balls.iter_mut().enumerate() {
            let phi = self.azimuth(j, options);
            let (ex, er) = Self::basis(phi);
            let e = SMatrix::<f64, 3, 2>::from_columns(&[ex, er]);
            for _ in 0..50 {
                let (_, inner, outer) = self.contacts(y, phi, &ring);
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
                y[0] += factor * step[0];
                y[1] += factor * step[1];
            }
        }
    }

    /// Ring displacement along the load direction u(s).
    fn along_load(&self, direction: &Vector5, s: f64) -> Vector5 {
        let l = self.lever();
        Vector5::new(
            s * direction[0],
            s * direction[1],
            s * direction[2],
            s * direction[3] / l,
            s * direction[4] / l,
        )
    }

    /// Zero-speed start: balls at the pitch circle, ring displaced along the
    /// load by a Hertz estimate, or (`search`) by a Brent search for the
    /// displacement at which the contacts carry the load.
    fn initial_state(&self, loads: &Loads, options: &SolverOptions, search: bool) -> State {
        let g = &self.geometry;
        let mut state = State {
            balls: vec![Vector5::new(0.0, g.pitch_diameter / 2.0, 0.0, 0.0, 0.0); g.ball_count],
            ring: Vector5::zeros(),
        };
        let applied = self.scaled_ring(&Self::applied(loads));
        let magnitude = applied.norm();
        if magnitude == 0.0 {
            self.equilibrate_balls(&mut state, options);
            return state;
        }
        let direction = applied / magnitude;
        let gap = g.diametral_clearance.max(0.0) / 2.0;
        let s = if search {
            let balls0 = state.balls.clone();
            let controls = vec![RingKind::Outer; g.ball_count];
            let conditions = Conditions {
                loads: *loads,
                inner_speed: 0.0,
                control: RacewayControl::Outer,
            };
            let setup = Setup {
                conditions: &conditions,
                options,
                extension: 1.0,
            };
            let mut f = |s: f64| {
                let mut trial = State {
                    balls: balls0.clone(),
                    ring: self.along_load(&direction, s),
                };
                self.equilibrate_balls(&mut trial, options);
                direction.dot(&self.scaled_ring(&self.assemble(&trial, &controls, setup).ring))
            };
            let limit = g.ball_diameter;
            let mut hi = gap.max(1e-7 * limit);
            while hi < limit && f(hi) > 0.0 {
                hi *= 2.0;
            }
            if hi >= limit {
                limit
            } else {
                brent(&mut f, 0.0, hi, 1e-12 * limit).unwrap_or(hi)
            }
        } else {
            // Hertz estimate: a quarter of the balls share the load.
            let k = self
                .inner_table
                .stiffness(g.nominal_contact_angle())
                .min(self.outer_table.stiffness(g.nominal_contact_angle()));
            let per_ball = magnitude / (0.25 * g.ball_count as f64);
            gap + 2.0 * (per_ball / k).powf(2.0 / 3.0)
        };
        state.ring = self.along_load(&direction, s);
        if search {
            self.equilibrate_balls(&mut state, options);
        }
        state
    }

    fn controls_for(
        &self,
        control: RacewayControl,
        state: Option<&State>,
        options: &SolverOptions,
    ) -> Vec<RingKind> {
        let z = self.geometry.ball_count;
        match (control, state) {
            (RacewayControl::Inner, _) => vec![RingKind::Inner; z],
            (RacewayControl::Outer, _) | (RacewayControl::Harris, None) => vec![RingKind::Outer; z],
            (RacewayControl::Harris, Some(state)) => {
                let ring = RingDisplacement::from_array(state.ring.into());
                state
                    .balls
                    .iter()
                    .enumerate()
                    .map(|(j, y)| {
                        let (_, inner, outer) = self.contacts(y, self.azimuth(j, options), &ring);
                        let moment = |c: &RingContactEval, table: &ContactTable| {
                            let h = table.at(c.contact_angle);
                            c.load * h.at_load(c.load).semi_major * h.elliptic_e
                        };
                        if moment(&outer, &self.outer_table) >= moment(&inner, &self.inner_table) {
                            RingKind::Outer
                        } else {
                            RingKind::Inner
                        }
                    })
                    .collect()
            }
        }
    }

    /// Solves at fixed speed from `state`, iterating the Harris criterion.
    fn solve_at(
        &self,
        state: State,
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Result<(State, Matrix5, usize, f64, Vec<RingKind>), QuasiStaticError> {
        let extension = if conditions.inner_speed == 0.0 {
            1.0
        } else {
            SPEED_EXTENSION
        };
        let setup = Setup {
            conditions,
            options,
            extension,
        };
        let mut controls = self.controls_for(conditions.control, Some(&state), options);
        let (mut state, mut s, mut iterations, mut residual) =
            self.newton(state, &controls, setup)?;
        for _ in 0..5 {
            if conditions.control != RacewayControl::Harris {
                break;
            }
            let next = self.controls_for(conditions.control, Some(&state), options);
            if next == controls {
                break;
            }
            controls = next;
            let (st, ss, it, res) = self.newton(state, &controls, setup)?;
            state = st;
            s = ss;
            iterations += it;
            residual = res;
        }
        Ok((state, s, iterations, residual, controls))
    }

    #[allow(clippy::too_many_arguments)]
    fn solution(
        &self,
        state: &State,
        schur: &Matrix5,
        iterations: usize,
        residual: f64,
        controls: &[RingKind],
        conditions: &Conditions,
        options: &SolverOptions,
    ) -> Equilibrium {
        let ring = RingDisplacement::from_array(state.ring.into());
        let omega_i = conditions.inner_speed;
        let balls = state
            .balls
            .iter()
            .enumerate()
            .map(|(j, y)| {
                let phi = self.azimuth(j, options);
                let (ex, er) = Self::basis(phi);
                let (_, inner, outer) = self.contacts(y, phi, &ring);
                let omega_b = y[3] * ex + y[4] * er;
                let contact = |eval: &RingContactEval, table: &ContactTable, ring_speed: f64| {
                    let relative = omega_b - ring_speed * ex;
                    let spin = relative.dot(&eval.normal);
                    let roll = (relative - spin * eval.normal).norm();
                    ContactSolution {
                        load: eval.load,
                        contact_angle: eval.contact_angle,
                        penetration: eval.penetration,
                        spin_to_roll: if roll > 0.0 { spin / roll } else { 0.0 },
                        hertz: table.at(eval.contact_angle).at_load(eval.load),
                    }
                };
                let (rel_x, rel_r) = (y[3] - y[2], y[4]);
                BallSolution {
                    azimuth: phi,
                    axial_position: y[0],
                    radial_position: y[1],
                    orbital_speed: y[2],
                    spin_axial: y[3],
                    spin_radial: y[4],
                    spin_speed: rel_x.hypot(rel_r),
                    attitude: if rel_x == 0.0 && rel_r == 0.0 {
                        0.0
                    } else {
                        rel_r.atan2(-rel_x)
                    },
                    control: controls[j],
                    inner: contact(&inner, &self.inner_table, omega_i),
                    outer: contact(&outer, &self.outer_table, 0.0),
                }
            })
            .collect();
        let k = -schur;
        let setup = Setup {
            conditions,
            options,
            extension: if omega_i == 0.0 { 1.0 } else { SPEED_EXTENSION },
        };
        Equilibrium {
            inner_speed: omega_i,
            displacement: state.ring.into(),
            balls,
            stiffness: std::array::from_fn(|i| std::array::from_fn(|j| k[(i, j)])),
            reaction: self.reaction(state, controls, setup),
            iterations,
            residual,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{Clearance, GeometrySpec};

    /// The assembled Jacobian blocks equal central differences of the
    /// residual, at speed, with friction on the inner ring (inner control).
    #[test]
    fn jacobian_matches_finite_differences() {
        let g = BearingGeometry::new(&GeometrySpec {
            ball_diameter: 6.35e-3,
            ball_count: 5,
            pitch_diameter: 54e-3,
            inner_groove_curvature: 0.55,
            outer_groove_curvature: 0.52,
            clearance: Clearance::FreeContactAngle(17.7f64.to_radians()),
            preload: false,
        })
        .unwrap();
        let solver = QuasiStaticSolver::new(
            &g,
            &Material::STEEL_52100,
            &Material::STEEL_52100,
            HertzModel::Exact,
        )
        .unwrap();
        let conditions = Conditions {
            loads: Loads {
                force: [300.0, 50.0, -80.0],
                moment: [1.0, -0.5],
            },
            inner_speed: 1000.0,
            control: RacewayControl::Inner,
        };
        let options = SolverOptions::default();
        let setup = Setup {
            conditions: &conditions,
            options: &options,
            extension: 1e-6,
        };
        let state = State {
            balls: (0..5)
                .map(|j| {
                    Vector5::new(
                        -3e-6 + 1e-7 * j as f64,
                        27.002e-3,
                        440.0 + j as f64,
                        180.0,
                        -2400.0,
                    )
                })
                .collect(),
            ring: Vector5::new(1.2e-5, 1e-6, -2e-6, 1e-4, -5e-5),
        };
        let controls = vec![RingKind::Inner; 5];
        let asm = solver.assemble(&state, &controls, setup);
        let steps = [1e-9, 1e-9, 1e-3, 1e-3, 1e-3];
        for j in 0..5 {
            for (k, &step) in steps.iter().enumerate() {
                let (mut plus, mut minus) = (state.clone(), state.clone());
                plus.balls[j][k] += step;
                minus.balls[j][k] -= step;
                let (ap, am) = (
                    solver.assemble(&plus, &controls, setup),
                    solver.assemble(&minus, &controls, setup),
                );
                let fd_ball = (ap.ball[j] - am.ball[j]) / (2.0 * step);
                let fd_ring = (ap.ring - am.ring) / (2.0 * step);
                let (a, c) = (asm.a[j].column(k), asm.c[j].column(k));
                assert!(
                    (fd_ball - a).norm() <= 1e-4 * fd_ball.norm().max(1e-3),
                    "A[{j}] col {k}: {fd_ball:?} vs {a:?}"
                );
                assert!(
                    (fd_ring - c).norm() <= 1e-4 * fd_ring.norm().max(1e-3),
                    "C[{j}] col {k}: {fd_ring:?} vs {c:?}"
                );
            }
        }
        let ring_steps = [1e-9, 1e-9, 1e-9, 1e-8, 1e-8];
        for (k, &step) in ring_steps.iter().enumerate() {
            let (mut plus, mut minus) = (state.clone(), state.clone());
            plus.ring[k] += step;
            minus.ring[k] -= step;
            let (ap, am) = (
                solver.assemble(&plus, &controls, setup),
                solver.assemble(&minus, &controls, setup),
            );
            let fd_ring = (ap.ring - am.ring) / (2.0 * step);
            assert!(
                (fd_ring - asm.d.column(k)).norm() <= 1e-4 * fd_ring.norm().max(1e-3),
                "D col {k}: {fd_ring:?} vs {:?}",
                asm.d.column(k)
            );
            for j in 0..5 {
                let fd_ball = (ap.ball[j] - am.ball[j]) / (2.0 * step);
                let b = asm.b[j].column(k);
                assert!(
                    (fd_ball - b).norm() <= 1e-4 * fd_ball.norm().max(1e-3),
                    "B[{j}] col {k}: {fd_ball:?} vs {:?}",
                    b.transpose()
                );
            }
        }
    }
}
