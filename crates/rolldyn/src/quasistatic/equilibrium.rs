//! Quasi-static equilibrium of a ball bearing (docs/model.md §7): the static load
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
//! docs/model.md §1), is carried by friction at the contacts:
//! f_k = λ_k (M_g/D) (n_x e_r − n_r e_x), with (λ_i, λ_o) = (0, 2) for outer-
//! and (2, 0) for inner-raceway control (Harris & Kotzalas, *Advanced
//! Concepts of Bearing Technology*, 5th ed., §3.3, eqs 3.49–3.56). The
//! centrifugal force is m r ω_m² with the ball's actual orbit radius r
//! (the usual ½ m d_m ω_m² is its value at r = d_m/2). The rolling equations
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
//! intermediate band where neither raceway controls is not modelled. A
//! fallback reaches inner control from outer control by continuation in
//! the control (`Setup::inner_share`; a numerical path, not a model).
//!
//! **Unloaded balls.** A ball with no contact has no defined position at
//! zero speed; its force equations use the signed extension of the Hertz
//! law (weight 1 at zero speed), which keeps it where its two gaps balance.
//! At speed centrifugal force seats such a ball on the outer raceway and
//! an open inner contact's extension keeps only a weight of
//! [`SPEED_EXTENSION`] = 1e-9: its pull on the ball is at most 1e-9 of the
//! Hertz force at its gap (~3e-7 N for a 10 µm gap on a 7008C), far below
//! the ball's centrifugal load. An open outer contact keeps its full
//! extension: at a solution at speed it is closed (the centrifugal force
//! needs its reaction), and on the way there its pull holds the ball to
//! its raceway, where the centrifugal term's stiffness m ω_m² alone is
//! destabilising and sends Newton inwards. Forces on the ring always use the physical law.
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
use super::ring_contact::{RingContactEval, RingDisplacement, evaluate};
use crate::contact::{ContactTable, HertzModel, HertzResult, RacewayContactModel};
use crate::error::InvalidParameter;
use crate::geometry::{BearingGeometry, RingKind};
use crate::lubrication::approach::FilmLaw;
use crate::material::{Material, effective_modulus};
use crate::math::roots::brent;
use crate::operating::Loads;
use nalgebra::{SMatrix, SVector, Vector3};
use serde::{Deserialize, Serialize};

mod assembly;
mod axial_control;
mod constraints;
mod continuation;
mod newton;
mod race_drive;
mod rebuild;
mod solve;

type Matrix5 = SMatrix<f64, 5, 5>;
type Vector5 = SVector<f64, 5>;
type Row3 = SMatrix<f64, 1, 3>;
type Row5 = SMatrix<f64, 1, 5>;

/// Weight of the signed Hertz extension of an open inner contact in the
/// ball equations at speed.
pub const SPEED_EXTENSION: f64 = 1e-9;

/// A solve whose line search stalls (round-off), or that runs out of
/// iterations converging only linearly (a ball at the edge of the loaded
/// zone), at or below this relative residual, the 1e-8 requirement of
/// VALIDATION B5, is accepted; the residual reached is reported with the
/// solution.
const STAGNATION_ACCEPT: f64 = 1e-8;

/// Relative residual to which a ball free of the inner ring (open inner
/// contact: it loads the ring nowhere, so its state changes neither the
/// ring's equilibrium nor the stiffness) is solved once the ring and the
/// loaded balls are converged. Near rest such a ball is held only by the
/// centrifugal force (~1e-7 N at 1 rpm on a 6206) and its position and
/// speeds are nearly undetermined: Newton converges on it only linearly.
/// 1e-6 of the load scale (forces) and of the reference speeds
/// (kinematics).
const FREE_BALL_TOLERANCE: f64 = 1e-6;

/// Which raceway controls the ball spin (Jones–Harris).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum RacewayControl {
    /// No spin at the outer contact (Zhang et al. 2025 Table 1's choice).
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
    /// Strength σ ∈ [0, 1] of the race drive (`equilibrium::race_drive`)
    /// for balls whose inner contact is open: 1 (default) rolldyn's
    /// kinematics for free balls; 0 Jones–Harris rolling at the nearest
    /// point of the inner groove. Values between are the solver's own
    /// continuation path.
    pub race_drive: f64,
}

impl Default for SolverOptions {
    fn default() -> Self {
        Self {
            max_iterations: 60,
            relative_tolerance: 1e-11,
            first_ball_azimuth: 0.0,
            prescribed_displacement: [None; 5],
            race_drive: 1.0,
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
    /// Largest relative residual at the solution, of the ring and the
    /// balls that load it (a ball free of the inner ring is solved to
    /// 1e-6).
    pub residual: f64,
}

impl Equilibrium {
    /// Cage speed: the mean orbital speed of the balls \[rad/s\].
    pub fn cage_speed(&self) -> f64 {
        self.balls.iter().map(|b| b.orbital_speed).sum::<f64>() / self.balls.len().max(1) as f64
    }
}

/// Quasi-static solver for one bearing and its materials.
///
/// The 7008C of Deng et al. 2022 (Table 1) under a 200 N thrust at 10 000 rpm
/// (Jones–Harris, outer-race control):
/// ```
/// use rolldyn::contact::HertzModel;
/// use rolldyn::geometry::{BearingGeometry, Clearance, GeometrySpec};
/// use rolldyn::material::Material;
/// use rolldyn::operating::Loads;
/// use rolldyn::quasistatic::{Conditions, QuasiStaticSolver, RacewayControl, SolverOptions};
///
/// let geometry = BearingGeometry::new(&GeometrySpec {
///     ball_diameter: 6.35e-3,
///     ball_count: 22,
///     pitch_diameter: 54.0e-3,
///     inner_groove_curvature: 0.5501,
///     outer_groove_curvature: 0.52,
///     clearance: Clearance::FreeContactAngle(17.7f64.to_radians()),
///     preload: false,
/// })?;
/// let steel = Material::STEEL_52100;
/// let solver = QuasiStaticSolver::new(&geometry, &steel, &steel, HertzModel::Exact)?;
/// let conditions = Conditions {
///     loads: Loads { force: [200.0, 0.0, 0.0], moment: [0.0; 2] },
///     inner_speed: 10_000.0 * std::f64::consts::TAU / 60.0,
///     control: RacewayControl::Outer,
/// };
/// let solution = solver.solve(&conditions, &SolverOptions::default())?;
/// // Under pure thrust every ball carries the same share.
/// let first = solution.balls[0].inner.load;
/// assert!(solution.balls.iter().all(|b| (b.inner.load - first).abs() < 1e-6 * first));
/// // Centrifugal force loads the outer contacts more than the inner ones.
/// assert!(solution.balls[0].outer.load > first);
/// // The cage turns at a little under half the shaft speed.
/// let ratio = solution.cage_speed() / conditions.inner_speed;
/// assert!(ratio > 0.4 && ratio < 0.5, "{ratio}");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct QuasiStaticSolver {
    geometry: BearingGeometry,
    inner_table: ContactTable,
    outer_table: ContactTable,
    ball_mass: f64,
    ball_inertia: f64,
    /// The film law of each ball's inner and outer contact, for the film
    /// in the approach (empty: dry Hertz; `films::solve_with_films`).
    films: Vec<[Option<FilmLaw>; 2]>,
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
    /// Per ball ∂residual/∂ω_i.
    speed_derivative: Vec<Vector5>,
    ring: Vector5,
    a: Vec<Matrix5>,
    b: Vec<Matrix5>,
    c: Vec<Matrix5>,
    d: Matrix5,
    largest_load: f64,
    /// Per ball: free of the inner ring (it puts no load on the ring and
    /// the ring's load does not depend on it: C_j = 0).
    free: Vec<bool>,
}

/// Fixed per-solve data of the assembly.
#[derive(Clone, Copy)]
struct Setup<'a> {
    conditions: &'a Conditions,
    options: &'a SolverOptions,
    /// Weight of the signed Hertz extension of an open inner contact in the
    /// ball equations (an open outer contact always has weight 1).
    extension: f64,
    /// Share t of the inner raceway in the control of an inner-controlled
    /// ball: 1 is Jones–Harris inner control, 0 outer control; between,
    /// the homotopy of [`QuasiStaticSolver::start_from_outer_control`]
    /// (friction shares λ_i = 2t, λ_o = 2(1 − t), no-spin condition
    /// t s_i − (1 − t) s_o).
    inner_share: f64,
}

impl<'a> Setup<'a> {
    /// A solve at `conditions`: extension weight 1 at rest and
    /// [`SPEED_EXTENSION`] at speed, controls as stated.
    fn new(conditions: &'a Conditions, options: &'a SolverOptions) -> Self {
        Self {
            conditions,
            options,
            extension: if conditions.inner_speed == 0.0 {
                1.0
            } else {
                SPEED_EXTENSION
            },
            inner_share: 1.0,
        }
    }
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
            films: Vec::new(),
        })
    }

    /// This solver with the film `films[j][k]` in the approach of ball j's
    /// inner (k = 0) and outer contact (docs/model.md §4; `ring_contact`); empty:
    /// dry Hertz.
    pub(crate) fn with_films(&self, films: Vec<[Option<FilmLaw>; 2]>) -> Self {
        Self {
            films,
            ..self.clone()
        }
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
        j: usize,
        y: &Vector5,
        phi: f64,
        ring: &RingDisplacement,
    ) -> (Vector3<f64>, RingContactEval, RingContactEval) {
        let (ex, er) = Self::basis(phi);
        let q = y[0] * ex + y[1] * er;
        let d = self.geometry.ball_diameter;
        let films = self.films.get(j);
        let inner = evaluate(
            &self.geometry.inner,
            &self.inner_table,
            d,
            &q,
            ring,
            true,
            films.and_then(|f| f[0].as_ref()),
        );
        let outer = evaluate(
            &self.geometry.outer,
            &self.outer_table,
            d,
            &q,
            &RingDisplacement::default(),
            true,
            films.and_then(|f| f[1].as_ref()),
        );
        (q, inner, outer)
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
                let (_, inner, outer) = self.contacts(j, y, phi, &ring);
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
            let setup = Setup::new(&conditions, options);
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
                        let (_, inner, outer) =
                            self.contacts(j, y, self.azimuth(j, options), &ring);
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
        let setup = Setup::new(conditions, options);
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
                let (_, inner, outer) = self.contacts(j, y, phi, &ring);
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
        let setup = Setup::new(conditions, options);
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
