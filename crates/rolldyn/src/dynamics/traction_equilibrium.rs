//! Traction-consistent quasi-static equilibrium: the "quasi-static
//! tribological model" Zhang et al. 2025 §3.1 starts its dynamics from, with no
//! raceway-control hypothesis.
//!
//! Jones–Harris ([`crate::quasistatic::equilibrium`]) fixes the ball spin by raceway
//! control: the whole gyroscopic moment is carried by the controlling
//! contact. Here the ball angular velocity and orbital speed follow from
//! the force and moment balance of the balls with the case's traction
//! model (any of them: Coulomb, curve, EHL, FASTSIM), exactly as the
//! dynamic model evaluates the contacts:
//!
//! * per ball j, unknowns (x, r, φ̇, ω_x, ω_r, ω_t) with ẋ = ṙ = 0, and
//!   equations: the ball's accelerations of the dynamic model vanish,
//!   m ẍ = F_x = 0, m(r̈ − rφ̇²) = 0, m r φ̈ = F_t = 0, ω̇ = 0 in the
//!   azimuth frame (docs/model.md §1: centrifugal and gyroscopic terms included).
//!   In planar mode the unknowns are (r, φ̇, ω_x).
//! * the inner ring (5 DOF, planar: y, z) and an outer ring on a housing
//!   are in equilibrium with the balls: their accelerations vanish.
//!
//! The ball azimuths stay those of the start (Jones–Harris) state and the
//! cage is centred on them, turning at the mean orbital speed, so the
//! pockets carry nothing; a whirling cage stays at its start position.
//! Each ball is solved by damped Newton with a finite-difference Jacobian
//! (6 × 6), the rings by an outer Newton on their displacements whose
//! Jacobian re-solves the balls (warm-started); both Jacobians are reused
//! (chord steps) while they keep the residual falling fast. The residuals
//! are scaled to forces (moments over D/2) and converge to
//! `relative_tolerance` of the largest contact load.

use super::{BearingModel, StateLayout};
use crate::integrate::{BlockSplit, OdeSystem};
use crate::quasistatic::QuasiStaticError;
use nalgebra::{DMatrix, DVector};

/// Settings of the traction-consistent solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TractionSolveOptions {
    /// Newton iteration limit, per ball and for the rings.
    pub max_iterations: usize,
    /// Converged when every residual force is below this fraction of the
    /// largest contact load.
    pub relative_tolerance: f64,
}

impl Default for TractionSolveOptions {
    fn default() -> Self {
        Self {
            max_iterations: 60,
            relative_tolerance: 1e-8,
        }
    }
}

/// A converged traction-consistent state.
#[derive(Debug, Clone, PartialEq)]
pub struct TractionEquilibrium {
    /// The dynamic model's state vector at equilibrium (velocities of the
    /// rings zero, cage turning at the mean orbital speed).
    pub state: Vec<f64>,
    /// Newton iterations of the ring loop.
    pub ring_iterations: usize,
    /// Newton iterations of all ball solves.
    pub ball_iterations: usize,
    /// Largest residual force relative to the largest contact load.
    pub residual: f64,
}

/// The unknowns of a ball: offsets within its state block.
fn ball_unknowns(planar: bool) -> &'static [usize] {
    if planar {
        &[1, 5, 6]
    } else {
        &[0, 1, 5, 6, 7, 8]
    }
}

struct Solver<'a> {
    model: &'a BearingModel,
    t: f64,
    layout: StateLayout,
    planar: bool,
    /// Ball mass and inertia/(D/2) to turn accelerations into forces.
    mass: f64,
    inertia_over_radius: f64,
    /// Finite-difference steps: position, angular speed.
    step_position: f64,
    step_speed: f64,
    tolerance: f64,
    max_iterations: usize,
    ball_iterations: usize,
    /// Per ball, the LU of its last Jacobian.
    jacobians: Vec<Option<nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>>>,
}

impl Solver<'_> {
    /// Scaled residual of ball j: forces \[N\] (moments over D/2).
    fn ball_residual(&self, y: &[f64], j: usize, out: &mut Vec<f64>) {
        // Room for the spin angle ψ when the balls carry surfaces.
        let mut dy = [0.0; StateLayout::BALL + 1];
        let mut coupling = vec![0.0; self.model.coupling_len()];
        let len = self.layout.ball_len();
        self.model
            .block_rhs(self.t, y, j, &mut dy[..len], &mut coupling);
        let r = y[self.layout.ball(j) + 1];
        out.clear();
        for &k in ball_unknowns(self.planar) {
            // Unknown k pairs with the acceleration of its state: x → ẍ,
            // r → r̈, φ̇ → φ̈ (times r: a force), ω → ω̇.
            let acc = match k {
                0 => dy[3] * self.mass,
                1 => dy[4] * self.mass,
                5 => dy[5] * self.mass * r,
                _ => dy[k] * self.inertia_over_radius,
            };
            out.push(acc);
        }
    }

    fn step_of(&self, k: usize) -> f64 {
        if k <= 1 {
            self.step_position
        } else {
            self.step_speed
        }
    }

    /// The finite-difference Jacobian of ball j's residual `res` at `y`.
    fn ball_jacobian(&self, y: &mut [f64], j: usize, res: &[f64]) -> DMatrix<f64> {
        let b = self.layout.ball(j);
        let unknowns = ball_unknowns(self.planar);
        let n = unknowns.len();
        let mut jac = DMatrix::zeros(n, n);
        let mut trial = Vec::with_capacity(n);
        for (col, &k) in unknowns.iter().enumerate() {
            let h = self.step_of(k);
            let keep = y[b + k];
            y[b + k] = keep + h;
            self.ball_residual(y, j, &mut trial);
            y[b + k] = keep;
            for row in 0..n {
                jac[(row, col)] = (trial[row] - res[row]) / h;
            }
        }
        jac
    }

    /// Solves ball j in place by damped Newton; returns the final scaled
    /// residual norm. The ball's last Jacobian is kept and reused (chord
    /// steps) while the residual falls at least tenfold per step, so the
    /// re-solves of the ring's finite differences cost a few residuals.
    fn solve_ball(&mut self, y: &mut [f64], j: usize, load_scale: f64) -> Result<f64, f64> {
        let b = self.layout.ball(j);
        let unknowns = ball_unknowns(self.planar);
        let mut res = Vec::with_capacity(unknowns.len());
        let mut trial = Vec::with_capacity(unknowns.len());
        self.ball_residual(y, j, &mut res);
        let norm = |v: &[f64]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let mut current = norm(&res);
        let mut fresh = false;
        let mut steps = 0;
        while steps < self.max_iterations {
            if current <= self.tolerance * load_scale {
                return Ok(current);
            }
            if self.jacobians[j].is_none() {
                self.jacobians[j] = Some(self.ball_jacobian(y, j, &res).lu());
                fresh = true;
            }
            let Some(delta) = self.jacobians[j]
                .as_ref()
                .and_then(|lu| lu.solve(&(-DVector::from_column_slice(&res))))
            else {
                return Err(current);
            };
            let start: Vec<f64> = unknowns.iter().map(|&k| y[b + k]).collect();
            let mut lambda = 1.0;
            loop {
                for (i, &k) in unknowns.iter().enumerate() {
                    y[b + k] = start[i] + lambda * delta[i];
                }
                self.ball_residual(y, j, &mut trial);
                let next = norm(&trial);
                let enough = if fresh {
                    next < current
                } else {
                    next < 0.1 * current
                };
                if enough {
                    steps += 1;
                    self.ball_iterations += 1;
                    current = next;
                    std::mem::swap(&mut res, &mut trial);
                    break;
                }
                if !fresh {
                    // A stale Jacobian: undo, refresh it and retry (not a step).
                    for (i, &k) in unknowns.iter().enumerate() {
                        y[b + k] = start[i];
                    }
                    self.jacobians[j] = None;
                    break;
                }
                if lambda < 1e-3 {
                    steps += 1;
                    self.ball_iterations += 1;
                    current = next;
                    std::mem::swap(&mut res, &mut trial);
                    break;
                }
                lambda *= 0.5;
            }
            fresh = false;
        }
        if current <= self.tolerance * load_scale {
            Ok(current)
        } else {
            Err(current)
        }
    }

    /// Solves every ball; returns the largest residual.
    fn solve_balls(&mut self, y: &mut [f64], load_scale: f64) -> Result<f64, f64> {
        let mut worst: f64 = 0.0;
        for j in 0..self.layout.balls {
            worst = worst.max(self.solve_ball(y, j, load_scale)?);
        }
        Ok(worst)
    }

    /// Ring unknowns (state indices) with the acceleration they pair with
    /// and the mass that turns it into a force.
    fn ring_unknowns(&self) -> Vec<(usize, usize, f64)> {
        let p = self.model.parameters();
        let r = self.layout.ring();
        let arm = 0.5 * self.model.geometry().pitch_diameter;
        let mut list = Vec::new();
        let translations: &[usize] = if self.planar { &[1, 2] } else { &[0, 1, 2] };
        for &k in translations {
            list.push((r + k, r + 5 + k, p.inner_ring_mass));
        }
        if !self.planar && !p.inner_ring_tilt_held {
            for k in [3, 4] {
                list.push((r + k, r + 5 + k, p.inner_ring_tilt_inertia / arm));
            }
        }
        if let Some(outer) = &p.outer_ring {
            let o = self.layout.outer();
            for k in [0, 1] {
                list.push((o + k, o + 2 + k, outer.mass));
            }
        }
        list
    }

    /// The first solve of every ball: each starts from its Jones–Harris
    /// state moved by the correction its neighbour needed, with the
    /// neighbour's Jacobian (the balls' states vary smoothly around the
    /// bearing); if that fails, from the Jones–Harris state itself. Err:
    /// a ball's residual.
    fn solve_balls_first(
        &mut self,
        y: &mut [f64],
        start: &[f64],
        load_scale: f64,
    ) -> Result<(), f64> {
        let layout = self.layout;
        let unknowns_ball = ball_unknowns(self.planar);
        for j in 0..layout.balls {
            let b = layout.ball(j);
            if j > 0 {
                let prev = layout.ball(j - 1);
                for &k in unknowns_ball {
                    y[b + k] += y[prev + k] - start[prev + k];
                }
                self.jacobians[j] = self.jacobians[j - 1].clone();
                if self.solve_ball(y, j, load_scale).is_ok() {
                    continue;
                }
                for &k in unknowns_ball {
                    y[b + k] = start[b + k];
                }
                self.jacobians[j] = None;
            }
            self.solve_ball(y, j, load_scale)?;
        }
        Ok(())
    }

    /// The ring residual's Jacobian by finite differences over the ring's
    /// unknowns, every ball re-solved for each column (`res`: the residual
    /// at `y`). Err: a ball's residual.
    fn ring_jacobian(
        &mut self,
        y: &[f64],
        unknowns: &[(usize, usize, f64)],
        res: &[f64],
        load_scale: f64,
    ) -> Result<DMatrix<f64>, f64> {
        let n = unknowns.len();
        let r = self.layout.ring();
        let pitch_diameter = self.model.geometry().pitch_diameter;
        let mut jac = DMatrix::zeros(n, n);
        for (col, &(k, _, _)) in unknowns.iter().enumerate() {
            let tilt = k == r + 3 || k == r + 4;
            let h = if tilt {
                self.step_position / (0.5 * pitch_diameter)
            } else {
                self.step_position
            };
            let mut yp = y.to_vec();
            yp[k] += h;
            self.solve_balls(&mut yp, load_scale)?;
            let rp = self.ring_residual(&yp, unknowns);
            for row in 0..n {
                jac[(row, col)] = (rp[row] - res[row]) / h;
            }
        }
        Ok(jac)
    }

    fn ring_residual(&self, y: &[f64], unknowns: &[(usize, usize, f64)]) -> Vec<f64> {
        let mut dy = vec![0.0; y.len()];
        self.model.rhs(self.t, y, &mut dy);
        unknowns.iter().map(|&(_, acc, m)| dy[acc] * m).collect()
    }
}

/// Rings and balls at rest in their frames; the cage centred on the balls.
fn at_rest_in_their_frames(layout: &StateLayout, y: &mut [f64]) {
    for j in 0..layout.balls {
        let b = layout.ball(j);
        y[b + 3] = 0.0;
        y[b + 4] = 0.0;
    }
    let r = layout.ring();
    y[r + 5..r + 10].fill(0.0);
    let o = layout.outer();
    y[o + 2..o + 4].fill(0.0);
    let c = layout.cage();
    y[c + 2] = y[layout.ball(0) + 2];
    y[c + 3] = 0.0;
    y[c + 4] = 0.0;
}

/// Largest contact load of state `y` (at least 1 N).
fn largest_load(model: &BearingModel, t: f64, y: &[f64]) -> f64 {
    let mut samples = vec![crate::dynamics::ContactSample::default(); model.layout().balls];
    model.contact_samples(t, y, &mut samples);
    samples
        .iter()
        .map(|s| s.inner.load.max(s.outer.load))
        .fold(1.0, f64::max)
}

/// The traction-consistent equilibrium of `model` at time `t` (speed and
/// loads of that instant), starting from `start` (e.g. the Jones–Harris
/// state, [`BearingModel::state_from_equilibrium`]).
pub fn solve_traction_consistent(
    model: &BearingModel,
    start: &[f64],
    t: f64,
    options: &TractionSolveOptions,
) -> Result<TractionEquilibrium, QuasiStaticError> {
    let layout = model.layout();
    let g = model.geometry();
    let mut y = start.to_vec();
    at_rest_in_their_frames(&layout, &mut y);
    let c = layout.cage();
    let omega_i = model.parameters().speed.speed_at(t);
    let mass = model.ball_mass();
    let mut solver = Solver {
        model,
        t,
        layout,
        planar: model.parameters().planar,
        mass,
        // I/(D/2) with I = m D²/10.
        inertia_over_radius: mass * g.ball_diameter / 5.0,
        step_position: 1e-9 * g.ball_diameter,
        step_speed: 1e-8 * (omega_i.abs() * g.pitch_diameter / g.ball_diameter).max(1.0),
        // The ring sums the balls' residual forces: solve each ball tighter.
        tolerance: options.relative_tolerance / layout.balls as f64,
        max_iterations: options.max_iterations,
        ball_iterations: 0,
        jacobians: vec![None; layout.balls],
    };
    let failed = |residual: f64, iterations: usize| QuasiStaticError::NoTractionEquilibrium {
        iterations,
        residual,
        speed_rpm: omega_i * 60.0 / std::f64::consts::TAU,
    };
    let load_scale = largest_load(model, t, &y);
    solver
        .solve_balls_first(&mut y, start, load_scale)
        .map_err(|res| failed(res / load_scale, solver.ball_iterations))?;
    let unknowns = solver.ring_unknowns();
    let norm = |v: &[f64]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let mut res = solver.ring_residual(&y, &unknowns);
    let mut ring_iterations = 0;
    let tolerance = options.relative_tolerance * load_scale;
    // The ring's Jacobian is kept while chord steps cut the residual
    // fourfold (each finite-difference column re-solves all balls).
    let mut ring_lu = None;
    let mut attempts = 0;
    while norm(&res) > tolerance {
        if attempts >= 2 * options.max_iterations {
            return Err(failed(norm(&res) / load_scale, ring_iterations));
        }
        attempts += 1;
        let fresh = ring_lu.is_none();
        if fresh {
            let jac = solver
                .ring_jacobian(&y, &unknowns, &res, load_scale)
                .map_err(|res| failed(res / load_scale, solver.ball_iterations))?;
            ring_lu = Some(jac.lu());
        }
        let Some(delta) = ring_lu
            .as_ref()
            .and_then(|lu| lu.solve(&(-DVector::from_column_slice(&res))))
        else {
            return Err(failed(norm(&res) / load_scale, ring_iterations));
        };
        let base = y.clone();
        let mut lambda = 1.0;
        loop {
            y.copy_from_slice(&base);
            for (i, &(k, _, _)) in unknowns.iter().enumerate() {
                y[k] += lambda * delta[i];
            }
            let solved = solver.solve_balls(&mut y, load_scale);
            let next = solver.ring_residual(&y, &unknowns);
            let enough = if fresh {
                norm(&next) < norm(&res)
            } else {
                norm(&next) < 0.25 * norm(&res)
            };
            if solved.is_ok() && enough {
                ring_iterations += 1;
                res = next;
                break;
            }
            if !fresh {
                // A stale Jacobian: undo and refresh it.
                y.copy_from_slice(&base);
                solver
                    .solve_balls(&mut y, load_scale)
                    .map_err(|res| failed(res / load_scale, solver.ball_iterations))?;
                ring_lu = None;
                break;
            }
            if lambda < 1e-3 {
                return Err(failed(norm(&res) / load_scale, ring_iterations));
            }
            lambda *= 0.5;
        }
    }
    let mean_orbit = (0..layout.balls)
        .map(|j| y[layout.ball(j) + 5])
        .sum::<f64>()
        / layout.balls as f64;
    y[c + 5] = mean_orbit;
    Ok(TractionEquilibrium {
        state: y,
        ring_iterations,
        ball_iterations: solver.ball_iterations,
        residual: norm(&res) / load_scale,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cage::{CageParameters, PocketLaw};
    use crate::contact::HertzModel;
    use crate::dynamics::DynamicsParameters;
    use crate::material::Material;
    use crate::operating::{LoadProfile, Loads, SpeedProfile};
    use crate::quasistatic::{Conditions, QuasiStaticSolver, RacewayControl, SolverOptions};
    use crate::traction::{ModifiedCoulomb, TractionModel};
    use crate::{BearingGeometry, Clearance, GeometrySpec};

    /// An angular-contact bearing (D 7.94 mm, 18 balls, 15°), 10 000 rpm,
    /// F_x 200 N, Coulomb traction μ 0.1 on the 12 × 6 grid.
    #[test]
    fn solution_is_a_fixed_point_of_the_dynamics() {
        let g = BearingGeometry::new(&GeometrySpec {
            ball_diameter: 7.938e-3,
            ball_count: 18,
            pitch_diameter: 54e-3,
            inner_groove_curvature: 0.56,
            outer_groove_curvature: 0.53,
            clearance: Clearance::FreeContactAngle(15f64.to_radians()),
            preload: false,
        })
        .unwrap();
        let steel = Material::STEEL_52100;
        let speed = 10_000.0 * std::f64::consts::TAU / 60.0;
        let loads = Loads {
            force: [200.0, 0.0, 0.0],
            moment: [0.0; 2],
        };
        let friction = ModifiedCoulomb {
            friction: 0.1,
            stick_speed: 0.0,
            full_speed: 1e-3,
        };
        let cage = CageParameters {
            pocket_friction: friction,
            whirl: false,
            ..CageParameters::new(
                0.003,
                2e-6,
                27e-3,
                0.2e-3,
                PocketLaw::Linear {
                    stiffness: 1e7,
                    damping: 20.0,
                },
            )
        };
        let params = DynamicsParameters {
            traction: TractionModel::ModifiedCoulomb(friction),
            speed: SpeedProfile::Constant(speed),
            loads: LoadProfile::Constant(loads),
            ..DynamicsParameters::new(0.5, 1e-4, cage)
        };
        let model = BearingModel::new(&g, &steel, &steel, HertzModel::Exact, params).unwrap();
        let qs = QuasiStaticSolver::new(&g, &steel, &steel, HertzModel::Exact).unwrap();
        let jh = |control| {
            qs.solve(
                &Conditions {
                    loads,
                    inner_speed: speed,
                    control,
                },
                &SolverOptions::default(),
            )
            .unwrap()
        };
        let (outer, inner) = (jh(RacewayControl::Outer), jh(RacewayControl::Inner));
        let start = model.state_from_equilibrium(&outer);
        let solved =
            solve_traction_consistent(&model, &start, 0.0, &TractionSolveOptions::default())
                .unwrap();
        let y = &solved.state;
        let mut dy = vec![0.0; y.len()];
        model.rhs(0.0, y, &mut dy);
        let l = model.layout();
        // Every ball and the ring at rest in their frames: accelerations
        // times mass below 1e-7 of the ~30 N contact loads.
        let m = model.ball_mass();
        for j in 0..l.balls {
            let b = l.ball(j);
            for k in 3..9 {
                assert!(
                    dy[b + k].abs() * m < 3e-6,
                    "ball {j} state {k}: {}",
                    dy[b + k]
                );
            }
        }
        assert!(dy[l.ring() + 5].abs() * 0.5 < 3e-6);
        // Pure axial load: every ball alike; the cage between the two
        // raceway-control hypotheses.
        for j in 1..l.balls {
            assert!((y[l.ball(j) + 5] - y[l.ball(0) + 5]).abs() < 1e-9 * speed);
        }
        let cage = y[l.cage() + 5];
        let (lo, hi) = (
            inner.cage_speed().min(outer.cage_speed()),
            inner.cage_speed().max(outer.cage_speed()),
        );
        assert!(cage > lo && cage < hi, "{cage} outside [{lo}, {hi}]");
    }
}
