//! Bearing sets on a rigid shaft (docs/systems.md): several bearings,
//! each with its full quasi-static (Jones–Harris) solution, sharing the
//! shaft's five rigid-body displacements; matched pairs with a preload
//! set by a force or by an axial displacement of the rings; the lift-off
//! load of an opposed pair; the set's stiffness at the shaft reference
//! point.
//!
//! # Equations
//! The shaft displacement u = (x, y, z, θ_y, θ_z) is taken at the shaft
//! reference point x = 0. Bearing i sits at axial position x_i, facing
//! the +x thrust (as built: the inner ring's +x load loads the balls,
//! docs/model.md §2) or mirrored. Its inner ring then moves by
//!
//! ```text
//! u_i = M_i P_i u + s_i e_x,   P_i u = (x, y + x_i θ_z, z − x_i θ_y, θ_y, θ_z)
//! ```
//!
//! (rigid shaft, small rotations; M_i = diag(−1, 1, 1, −1, −1) for a
//! mirrored bearing, the reflection x → −x acting on forces and, as
//! pseudovectors, on tilts and moments; else the identity), with s_i the
//! axial offset that sets the preload. Each bearing's equilibrium with its
//! ring held at u_i ([`SolverOptions::prescribed_displacement`]) gives the
//! load R_i the shaft applies to the ring and the stiffness K_i = ∂R_i/∂u_i
//! ([`Equilibrium::reaction`], [`Equilibrium::stiffness`]). The shaft is
//! in equilibrium when
//!
//! ```text
//! Σ_i P_iᵀ M_i R_i(u_i) = F,   K_set = Σ_i P_iᵀ M_i K_i M_i P_i
//! ```
//!
//! with F = (F_x, F_y, F_z, M_y, M_z) the external load on the shaft about
//! the reference point: Newton's method on u with the Jacobian K_set and a
//! backtracking line search.
//!
//! # Preload and lift-off
//! A preload force F_p sets the axial offset s (the same on each bearing of
//! a pair) at which, with no external load, each bearing carries F_p
//! axially; a preload displacement sets s directly. At speed the
//! centrifugal forces change the contact angles, and with a displacement
//! preload the preload itself: it is reported at every operating point.
//! The lift-off load of an opposed pair is the external axial load that
//! unloads the opposed bearing (its axial load reaches zero). For two equal
//! bearings with Hertz contacts and unchanged contact angles it is
//! 2^{3/2} F_p ≈ 2.83 F_p (Harris & Kotzalas 2006; the validation tests).

use super::{Equilibrium, QuasiStaticError, QuasiStaticSolver, RacewayControl, SolverOptions};
use crate::operating::Loads;
use nalgebra::{SMatrix, SVector};

pub(crate) type Matrix5 = SMatrix<f64, 5, 5>;
type Vector5 = SVector<f64, 5>;

mod preload;

/// Newton iteration limit of the shaft equilibrium.
const MAX_ITERATIONS: usize = 60;
/// Relative residual of the shaft equilibrium (forces over the load
/// scale, moments over the load scale times the set's axial span).
const TOLERANCE: f64 = 1e-10;

/// Which thrust direction a bearing carries.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Orientation {
    /// As built: a +x load on the inner ring loads the balls.
    Forward,
    /// Mirrored: carries −x thrust.
    Reversed,
}

/// Why a set has no equilibrium.
#[derive(Debug, Clone, thiserror::Error)]
pub enum SystemError {
    /// One bearing's quasi-static solve failed.
    #[error("bearing {index}: {source}")]
    Bearing {
        /// Bearing index (0-based, in the set's order).
        index: usize,
        /// The failure.
        source: QuasiStaticError,
    },
    /// The shaft equilibrium did not converge.
    #[error(
        "no shaft equilibrium: Newton stopped after {iterations} iterations with a relative residual of {residual:.3e}; a set without preload may have no stiffness against the load (add a preload or a load that closes the contacts)"
    )]
    NoConvergence {
        /// Iterations done.
        iterations: usize,
        /// Largest relative residual at the end.
        residual: f64,
    },
    /// The preload cannot be reached.
    #[error("preload: {reason}")]
    Preload {
        /// Why.
        reason: String,
    },
}

/// One bearing of a set.
#[derive(Debug, Clone)]
pub struct MountedBearing {
    /// Its quasi-static solver (contact tables).
    pub solver: QuasiStaticSolver,
    /// Axial position x_i of its pitch plane on the shaft \[m\].
    pub position: f64,
    /// Which thrust it carries.
    pub orientation: Orientation,
    /// Axial offset s_i of its inner ring towards its loaded side at zero
    /// shaft displacement \[m\] (the preload displacement).
    pub axial_offset: f64,
    /// A floating bearing: its outer ring slides in the housing, so the
    /// shaft's axial motion does not reach it and it carries no thrust; its
    /// inner ring finds the axial place where its balls carry none
    /// (held in the other four).
    pub floating: bool,
}

impl MountedBearing {
    /// M_i P_i as a matrix (shaft displacement → ring displacement).
    fn transform(&self) -> Matrix5 {
        let mut p = Matrix5::identity();
        p[(1, 4)] = self.position;
        p[(2, 3)] = -self.position;
        if self.floating {
            // The shaft's axial motion does not reach it, nor its thrust
            // the shaft.
            p[(0, 0)] = 0.0;
        }
        if self.orientation == Orientation::Reversed {
            for k in [0, 3, 4] {
                p.row_mut(k).neg_mut();
            }
        }
        p
    }

    /// The ring displacement u_i for shaft displacement `u`.
    pub fn ring_displacement(&self, u: &[f64; 5]) -> [f64; 5] {
        let mut local = self.transform() * Vector5::from(*u);
        local[0] += self.axial_offset;
        local.into()
    }

    /// The bearing's load on the shaft about the reference point (the
    /// shaft's share P_iᵀ M_i R_i of its equilibrium) for ring reaction
    /// `reaction`.
    pub fn shaft_load(&self, reaction: &[f64; 5]) -> [f64; 5] {
        (self.transform().transpose() * Vector5::from(*reaction)).into()
    }

    /// The axial load the bearing carries \[N\], ≥ 0 on its loaded side.
    pub fn axial_load(equilibrium: &Equilibrium) -> f64 {
        equilibrium.reaction[0]
    }

    /// Whether shaft displacement `u` moves this bearing's inner ring back
    /// from its loaded side, to at most its preload offset: where its
    /// balls can leave the inner raceway.
    fn unloaded_by(&self, u: &[f64; 5]) -> bool {
        !self.floating && self.ring_displacement(u)[0] <= self.axial_offset
    }

    /// Whether shaft displacement `u` leaves this bearing's balls free of
    /// both raceways at rest for certain: its inner ring held back along
    /// the axis (x ≤ 0, where the balls at most touch), by less than half
    /// its axial play (short of the opposite shoulders, whether x = 0 is
    /// the middle of the play or its end), no radial or tilt displacement,
    /// no interference. A solve there would only fail, slowly.
    fn open_at_rest(&self, u: &[f64; 5], inner_speed: f64) -> bool {
        let ring = self.ring_displacement(u);
        let geometry = self.solver.geometry();
        !self.floating
            && inner_speed == 0.0
            && geometry.diametral_clearance >= 0.0
            && ring[0] <= 0.0
            && ring[0] > -0.5 * geometry.axial_play()
            && ring[1..].iter().all(|&v| v == 0.0)
    }

    /// The bearing at shaft displacement `u`: its equilibrium with its ring
    /// held there (from `near`, a nearby state, when given), its load on
    /// the shaft about the reference point P_iᵀ M_i R_i and its stiffness
    /// there P_iᵀ M_i K_i M_i P_i (a floating bearing's free axial motion
    /// condensed out); None when it is open at rest or unloaded (lifted
    /// off).
    pub(crate) fn contribution(
        &self,
        u: &[f64; 5],
        conditions: &SystemConditions,
        options: &SolverOptions,
        near: Option<&Equilibrium>,
    ) -> Result<Option<(Equilibrium, [f64; 5], Matrix5)>, QuasiStaticError> {
        if self.open_at_rest(u, conditions.inner_speed) {
            return Ok(None);
        }
        let eq = match self.solve(u, conditions.inner_speed, conditions.control, options, near) {
            Ok(eq) => eq,
            Err(_) if self.unloaded_by(u) => return Ok(None),
            Err(e) => return Err(e),
        };
        let t = self.transform();
        let share = self.shaft_load(&eq.reaction);
        let mut k = Matrix5::from(eq.stiffness).transpose();
        if self.floating && k[(0, 0)] != 0.0 {
            // Its axial motion is free (no thrust): condense it out.
            k -= k.column(0) * k.row(0) / k[(0, 0)];
        }
        Ok(Some((eq, share, t.transpose() * k * t)))
    }

    /// The bearing's equilibrium with its ring held at its displacement
    /// for shaft displacement `u`. Where the direct solve fails (at speed
    /// the solver's path from the static solution cannot reach a ring
    /// that is open at rest but closed by the balls' centrifugal
    /// displacement), by continuation in the ring displacement from the
    /// preload state, warm-started, with the step halved on failure. With
    /// `warm` (its equilibrium at a nearby shaft displacement: the previous
    /// Newton iterate, bisection point or sweep point) from there first.
    fn solve(
        &self,
        u: &[f64; 5],
        inner_speed: f64,
        control: RacewayControl,
        options: &SolverOptions,
        warm: Option<&Equilibrium>,
    ) -> Result<Equilibrium, QuasiStaticError> {
        let conditions = super::Conditions {
            loads: Loads::default(),
            inner_speed,
            control,
        };
        // A floating bearing's inner ring finds its own axial place (no
        // thrust); the others are held in all five.
        let held = |ring: [f64; 5]| SolverOptions {
            prescribed_displacement: std::array::from_fn(|k| {
                (k > 0 || !self.floating).then_some(ring[k])
            }),
            ..*options
        };
        let target = self.ring_displacement(u);
        // `solve_from` falls back to the cold solve itself.
        let direct = match warm {
            Some(previous) => self.solver.solve_from(previous, &conditions, &held(target)),
            None => self.solver.solve(&conditions, &held(target)),
        };
        // At rest there is no centrifugal path to follow: the direct
        // solve's answer stands.
        if direct.is_ok() || self.axial_offset == 0.0 || inner_speed == 0.0 {
            return direct;
        }
        let start = [self.axial_offset, 0.0, 0.0, 0.0, 0.0];
        let Ok(mut previous) = self.solver.solve(&conditions, &held(start)) else {
            return direct;
        };
        let (mut done, mut step) = (0.0, 0.25);
        while done < 1.0 {
            let next = f64::min(done + step, 1.0);
            let ring = std::array::from_fn(|k| start[k] + next * (target[k] - start[k]));
            match self.solver.solve_from(&previous, &conditions, &held(ring)) {
                Ok(eq) => {
                    (previous, done) = (eq, next);
                    step = f64::min(2.0 * step, 0.25);
                }
                Err(e) if step < 1.0 / 512.0 => return Err(e),
                Err(_) => step *= 0.5,
            }
        }
        Ok(previous)
    }
}

/// A set's operating point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SystemConditions {
    /// External load on the shaft about its reference point.
    pub loads: Loads,
    /// Shaft (inner-ring) speed \[rad/s\].
    pub inner_speed: f64,
    /// Raceway control of every bearing.
    pub control: RacewayControl,
}

/// The set's equilibrium.
#[derive(Debug, Clone, PartialEq)]
pub struct SystemEquilibrium {
    /// Shaft displacement at the reference point (x, y, z \[m\], θ_y, θ_z
    /// \[rad\]).
    pub displacement: [f64; 5],
    /// Each bearing's equilibrium, its ring held at its displacement;
    /// [`Equilibrium::reaction`] is the load on its inner ring in its own
    /// frame. None: the bearing is unloaded by the external load beyond
    /// lift-off (its inner ring has moved back past its preload offset and
    /// its balls have no equilibrium on the inner raceway): it carries
    /// nothing and adds no stiffness.
    pub bearings: Vec<Option<Equilibrium>>,
    /// Each bearing's load on the shaft about the reference point.
    pub shaft_loads: Vec<[f64; 5]>,
    /// The set's stiffness at the reference point, K_set.
    pub stiffness: [[f64; 5]; 5],
    /// Newton iterations on the shaft.
    pub iterations: usize,
}

/// Every bearing's state at one shaft displacement.
struct Evaluation {
    bearings: Vec<Option<Equilibrium>>,
    shares: Vec<[f64; 5]>,
    /// Σ P_iᵀ M_i R_i − F.
    residual: Vector5,
    /// K_set.
    stiffness: Matrix5,
}

/// Bearings on one rigid shaft.
#[derive(Debug, Clone)]
pub struct ShaftSystem {
    /// The bearings.
    pub bearings: Vec<MountedBearing>,
}

/// How a matched set of bearings is mounted.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SetKind {
    /// One bearing.
    Single,
    /// A pair with its pressure cones' apexes outward ("O", DB): the
    /// +x-thrust bearing on the −x side. High moment stiffness.
    BackToBack,
    /// A pair with the apexes inward ("X", DF): the +x-thrust bearing on
    /// the +x side.
    FaceToFace,
    /// A pair sharing the +x thrust (DT); takes no preload by itself.
    Tandem,
    /// Three bearings: a tandem pair for the +x thrust on the −x side and
    /// one opposed on the +x side, apexes outward (TBT): the +x thrust
    /// shared by two bearings, the −x by one.
    TandemBackToBack,
    /// Three bearings: a tandem pair for the +x thrust on the +x side and
    /// one opposed on the −x side, apexes inward (TFT).
    TandemFaceToFace,
}

impl SetKind {
    /// Whether the set has bearings facing both ways (and so a preload and
    /// a lift-off load).
    pub fn opposed(self) -> bool {
        matches!(
            self,
            Self::BackToBack | Self::FaceToFace | Self::TandemBackToBack | Self::TandemFaceToFace
        )
    }
}

impl ShaftSystem {
    /// A matched set of `solver`'s bearing, neighbouring pitch planes
    /// `spacing` \[m\] apart and symmetric about the shaft reference point
    /// (a triple's middle bearing on it), no axial offset.
    pub fn matched(solver: &QuasiStaticSolver, kind: SetKind, spacing: f64) -> Self {
        let mount = |position, orientation| MountedBearing {
            solver: solver.clone(),
            position,
            orientation,
            axial_offset: 0.0,
            floating: false,
        };
        let half = 0.5 * spacing;
        use Orientation::{Forward, Reversed};
        let bearings = match kind {
            SetKind::Single => vec![mount(0.0, Forward)],
            SetKind::BackToBack => vec![mount(-half, Forward), mount(half, Reversed)],
            SetKind::FaceToFace => vec![mount(half, Forward), mount(-half, Reversed)],
            SetKind::Tandem => vec![mount(-half, Forward), mount(half, Forward)],
            SetKind::TandemBackToBack => vec![
                mount(-spacing, Forward),
                mount(0.0, Forward),
                mount(spacing, Reversed),
            ],
            SetKind::TandemFaceToFace => vec![
                mount(-spacing, Reversed),
                mount(0.0, Forward),
                mount(spacing, Forward),
            ],
        };
        Self { bearings }
    }

    /// Scale of the moments: the set's axial span, at least the largest
    /// pitch radius.
    fn lever(&self) -> f64 {
        let (lo, hi) = self
            .bearings
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), b| {
                (lo.min(b.position), hi.max(b.position))
            });
        let radius = self
            .bearings
            .iter()
            .map(|b| b.solver.geometry().pitch_diameter / 2.0)
            .fold(0.0, f64::max);
        (hi - lo).max(radius)
    }

    /// Every bearing's equilibrium at shaft displacement `u`, with the
    /// residual Σ P_iᵀ M_i R_i − F and the set's stiffness.
    fn evaluate(
        &self,
        u: &[f64; 5],
        conditions: &SystemConditions,
        options: &SolverOptions,
        warm: Option<&[Option<Equilibrium>]>,
    ) -> Result<Evaluation, SystemError> {
        let mut bearings: Vec<Option<Equilibrium>> = Vec::with_capacity(self.bearings.len());
        let mut shares = Vec::with_capacity(self.bearings.len());
        let applied = Vector5::new(
            conditions.loads.force[0],
            conditions.loads.force[1],
            conditions.loads.force[2],
            conditions.loads.moment[0],
            conditions.loads.moment[1],
        );
        let mut residual = -applied;
        let mut stiffness = Matrix5::zeros();
        for (index, b) in self.bearings.iter().enumerate() {
            // From its own state nearby, else from an identical bearing
            // already solved at the same ring displacement (a matched
            // set's mirror-image bearings at the start).
            let ring = b.ring_displacement(u);
            let twin = || {
                self.bearings[..index]
                    .iter()
                    .zip(&bearings)
                    .find(|(other, _)| {
                        other.ring_displacement(u) == ring
                            && other.solver.geometry() == b.solver.geometry()
                    })
                    .and_then(|(_, eq)| eq.as_ref())
            };
            let near = warm
                .and_then(|w| w.get(index))
                .and_then(Option::as_ref)
                .or_else(twin);
            match b
                .contribution(u, conditions, options, near)
                .map_err(|source| SystemError::Bearing { index, source })?
            {
                Some((eq, share, k)) => {
                    residual += Vector5::from(share);
                    stiffness += k;
                    shares.push(share);
                    bearings.push(Some(eq));
                }
                None => {
                    shares.push([0.0; 5]);
                    bearings.push(None);
                }
            }
        }
        Ok(Evaluation {
            bearings,
            shares,
            residual,
            stiffness,
        })
    }

    /// Largest relative residual: forces over `scale`, moments over
    /// `scale` times the lever.
    fn relative(&self, residual: &Vector5, scale: f64) -> f64 {
        let lever = self.lever();
        (0..5)
            .map(|k| residual[k].abs() / if k < 3 { scale } else { scale * lever })
            .fold(0.0, f64::max)
    }

    /// The shaft equilibrium under `conditions`, from zero displacement;
    /// where the set has no stiffness there (no preload, contacts just
    /// touching), from the displacement of bearing 0 under an equal share
    /// of the load.
    pub fn solve(
        &self,
        conditions: &SystemConditions,
        options: &SolverOptions,
    ) -> Result<SystemEquilibrium, SystemError> {
        match self.solve_from([0.0; 5], conditions, options) {
            Err(SystemError::NoConvergence { iterations: 1, .. })
            | Err(SystemError::Bearing { .. }) => {
                let start = self.start_from_share(conditions, options)?;
                self.solve_from(start, conditions, options)
            }
            other => other,
        }
    }

    /// The shaft displacement at which bearing 0 alone, its ring free,
    /// carries 1/n of the external load.
    fn start_from_share(
        &self,
        conditions: &SystemConditions,
        options: &SolverOptions,
    ) -> Result<[f64; 5], SystemError> {
        let first = &self.bearings[0];
        let n = self.bearings.len() as f64;
        let l = conditions.loads;
        // The share in the bearing's own frame (M is its own inverse).
        let local = first
            .transform()
            .transpose()
            .try_inverse()
            .map_or([0.0; 5], |inv| {
                (inv * Vector5::new(l.force[0], l.force[1], l.force[2], l.moment[0], l.moment[1])
                    / n)
                    .into()
            });
        let eq = first
            .solver
            .solve(
                &super::Conditions {
                    loads: Loads {
                        force: [local[0], local[1], local[2]],
                        moment: [local[3], local[4]],
                    },
                    inner_speed: conditions.inner_speed,
                    control: conditions.control,
                },
                options,
            )
            .map_err(|source| SystemError::Bearing { index: 0, source })?;
        let mut ring = Vector5::from(eq.displacement);
        ring[0] -= first.axial_offset;
        Ok(first
            .transform()
            .try_inverse()
            .map_or([0.0; 5], |inv| (inv * ring).into()))
    }

    /// The equilibrium of a general shaft system (bearings at different
    /// positions, none preloaded: a `[shaft]`): from the displacement the
    /// rigid shaft's statics suggest ([`Self::start_from_statics`]), else
    /// as [`Self::solve`].
    pub fn solve_general(
        &self,
        conditions: &SystemConditions,
        options: &SolverOptions,
    ) -> Result<SystemEquilibrium, SystemError> {
        match self
            .start_from_statics(conditions, options)
            .and_then(|start| self.solve_from(start, conditions, options))
        {
            Ok(eq) => Ok(eq),
            Err(_) => self.solve(conditions, options),
        }
    }

    /// A start for a statically spread system: the external load shared
    /// among the bearings by the rigid shaft's statics (forces only, the
    /// least-norm shares that balance forces and moments; the axial load
    /// on the bearings that carry its direction), each bearing solved
    /// under its share with its ring free, and the shaft displacement that
    /// fits their ring displacements best (least squares).
    pub fn start_from_statics(
        &self,
        conditions: &SystemConditions,
        options: &SolverOptions,
    ) -> Result<[f64; 5], SystemError> {
        let n = self.bearings.len();
        let l = conditions.loads;
        // Radial shares: Σ R = F, Σ x R = M (y: M_z; z: −M_y), least norm.
        let shares = |force: f64, moment: f64| -> Vec<f64> {
            let (s0, s1, s2) = self.bearings.iter().fold((0.0, 0.0, 0.0), |(a, b, c), m| {
                (a + 1.0, b + m.position, c + m.position * m.position)
            });
            let det = s0 * s2 - s1 * s1;
            if n == 1 || det.abs() < 1e-18 {
                return vec![force / n as f64; n];
            }
            // R_i = λ + μ x_i with [s0 s1; s1 s2] (λ, μ) = (F, M).
            let lambda = (force * s2 - moment * s1) / det;
            let mu = (s0 * moment - s1 * force) / det;
            self.bearings
                .iter()
                .map(|m| lambda + mu * m.position)
                .collect()
        };
        let ry = shares(l.force[1], l.moment[1]);
        let rz = shares(l.force[2], -l.moment[0]);
        let carriers: Vec<bool> = self
            .bearings
            .iter()
            .map(|m| {
                !m.floating
                    && match m.orientation {
                        Orientation::Forward => l.force[0] >= 0.0,
                        Orientation::Reversed => l.force[0] <= 0.0,
                    }
            })
            .collect();
        let count = carriers.iter().filter(|c| **c).count().max(1) as f64;
        let mut normal = Matrix5::zeros();
        let mut right = Vector5::zeros();
        for (i, b) in self.bearings.iter().enumerate() {
            let axial = if carriers[i] { l.force[0] / count } else { 0.0 };
            // The share on the shaft is −(the load on the ring) by the
            // bearing's reaction; in its own frame M_i flips x.
            let sign = if b.orientation == Orientation::Reversed {
                -1.0
            } else {
                1.0
            };
            let local = super::Conditions {
                loads: Loads {
                    force: [sign * axial, ry[i], rz[i]],
                    moment: [0.0, 0.0],
                },
                inner_speed: conditions.inner_speed,
                control: conditions.control,
            };
            let Ok(eq) = b.solver.solve(&local, options) else {
                continue;
            };
            let mut ring = Vector5::from(eq.displacement);
            ring[0] -= b.axial_offset;
            let t = b.transform();
            normal += t.transpose() * t;
            right += t.transpose() * ring;
        }
        let u = normal
            .lu()
            .solve(&right)
            .ok_or(SystemError::NoConvergence {
                iterations: 0,
                residual: f64::INFINITY,
            })?;
        Ok(u.into())
    }

    /// The shaft equilibrium under `conditions`, from displacement `start`.
    pub fn solve_from(
        &self,
        start: [f64; 5],
        conditions: &SystemConditions,
        options: &SolverOptions,
    ) -> Result<SystemEquilibrium, SystemError> {
        self.newton(start, None, conditions, options)
    }

    /// The shaft equilibrium under `conditions`, from a nearby one (a
    /// neighbouring sweep point, bisection point or preload offset): its
    /// displacement and its bearings' states as the first guesses. The
    /// same equilibrium as [`Self::solve`] to the solvers' tolerances.
    pub fn solve_near(
        &self,
        near: &SystemEquilibrium,
        conditions: &SystemConditions,
        options: &SolverOptions,
    ) -> Result<SystemEquilibrium, SystemError> {
        self.solve_predicted(near.displacement, near, conditions, options)
            .or_else(|_| self.solve(conditions, options))
    }

    /// Newton from the displacement `start` (e.g. extrapolated from the
    /// last two sweep points), each bearing from its state in `near`; no
    /// fallback (the caller's: [`Self::solve`] for a set,
    /// [`Self::solve_general`] for a shaft).
    pub fn solve_predicted(
        &self,
        start: [f64; 5],
        near: &SystemEquilibrium,
        conditions: &SystemConditions,
        options: &SolverOptions,
    ) -> Result<SystemEquilibrium, SystemError> {
        self.newton(start, Some(&near.bearings), conditions, options)
    }

    /// Newton on the shaft displacement from `start`, each bearing solved
    /// from its state at the previous iterate (or from `warm`).
    fn newton(
        &self,
        start: [f64; 5],
        warm: Option<&[Option<Equilibrium>]>,
        conditions: &SystemConditions,
        options: &SolverOptions,
    ) -> Result<SystemEquilibrium, SystemError> {
        let mut u = start;
        let mut state = self.evaluate(&u, conditions, options, warm)?;
        // Load scale: the external load, or what the bearings carry.
        let carried = state
            .shares
            .iter()
            .map(|s| s[..3].iter().map(|f| f.abs()).fold(0.0, f64::max))
            .fold(0.0, f64::max);
        let external = conditions
            .loads
            .force
            .iter()
            .map(|f| f.abs())
            .fold(0.0, f64::max);
        let scale = external.max(carried).max(1.0);
        let mut error = self.relative(&state.residual, scale);
        let mut iterations = 0;
        while error > TOLERANCE {
            if iterations == MAX_ITERATIONS {
                return Err(SystemError::NoConvergence {
                    iterations,
                    residual: error,
                });
            }
            iterations += 1;
            let Some(step) = state.stiffness.lu().solve(&state.residual) else {
                return Err(SystemError::NoConvergence {
                    iterations,
                    residual: error,
                });
            };
            // Backtracking: halve the step until the residual falls.
            let mut factor = 1.0;
            loop {
                let trial: [f64; 5] = std::array::from_fn(|k| u[k] - factor * step[k]);
                match self.evaluate(&trial, conditions, options, Some(&state.bearings)) {
                    Ok(next) => {
                        let e = self.relative(&next.residual, scale);
                        if e < error || factor < 1e-3 {
                            (u, state, error) = (trial, next, e);
                            break;
                        }
                    }
                    Err(e) if factor < 1e-3 => return Err(e),
                    Err(_) => {}
                }
                factor *= 0.5;
            }
        }
        let stiffness = state.stiffness;
        Ok(SystemEquilibrium {
            displacement: u,
            bearings: state.bearings,
            shaft_loads: state.shares,
            stiffness: std::array::from_fn(|i| std::array::from_fn(|j| stiffness[(i, j)])),
            iterations,
        })
    }
}
