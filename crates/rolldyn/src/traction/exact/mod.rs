//! Kalker's exact theory of steady rolling contact, by boundary elements
//! (J. J. Kalker, *Three-Dimensional Elastic Bodies in Rolling Contact*,
//! Kluwer 1990, ch. 5; E. A. H. Vollebregt, "Numerical modeling of
//! measured railway creep versus creep-force curves with CONTACT",
//! *Wear* 314 (2014) 87–95, and the CONTACT user guide, for the
//! algorithms). It is the reference the simplified theory, FASTSIM
//! ([`super::fastsim`]), is checked against (docs/validation.md).
//!
//! # Model
//! Two quasi-identical elastic half-spaces (combined G and ν as in
//! [`super::fastsim::combined_elastic_constants`]) touch over an ellipse
//! with semi-axes a_r along the rolling direction x̂ and b_r across it.
//! Material flows through the contact along +x̂ at speed V. The surface
//! is cut into `cells_along` × `cells_across` rectangles over
//! [−1.05 a_r, 1.05 a_r] × [−1.05 b_r, 1.05 b_r]; the tractions are
//! constant on each ([`influence`]).
//!
//! 1. **Normal problem** ([`normal`]): the pressure that closes the
//!    Hertz gap h₀ = A x² + B y² (the curvatures that give these
//!    semi-axes under this load, Johnson 1985 eqs 3.59–3.61) where it is
//!    positive, for the load Q. It reproduces the Hertz pressure (test).
//! 2. **Tangential problem**, steady state: the slip of ball material
//!    relative to ring material at a cell centre x_I is
//!    ```text
//!    s_I = w(x_I) + V (u_I − u(x_I − Δx)) / Δx
//!    ```
//!    (Kalker's backward difference of the material derivative V ∂u/∂x,
//!    with u = A p the relative elastic displacement from the tractions
//!    p on the ball, and w the rigid slip). Each cell either adheres
//!    (s_I = 0, |p_I| ≤ μ p_n) or slips (p_I = −μ p_n s_I/|s_I|). Solved
//!    by Gauss–Seidel sweeps from the leading edge, each cell's own
//!    two-by-two problem solved exactly (Vollebregt's SteadyGS), until
//!    no traction moves by more than `tolerance` · μ p₀.
//!
//! The rigid slip is that of FASTSIM's engine frame: on a flat contact
//! w = V(ξ − φ y, η + φ x); on a conforming groove the cells also carry
//! the differential (Heathcote) slip of the deformed surface at depth
//! d(y), w_x = s·x̂ − Ω_n y − d Ω·ŷ, w_y = s·ŷ + Ω_n x + d Ω·x̂ (the
//! half-space elastic field is kept; the curvature enters the kinematics
//! only, as in FASTSIM).
//!
//! # Accuracy and cost
//! The backward difference and the constant-traction cells make the
//! forces converge at first order in the cell size (docs/validation.md
//! gives the grid study); 40 × 40 cells reproduce Kalker's creep
//! coefficients to about 2 %. Each evaluation solves dense convolutions
//! directly: O(N²) per sweep for N cells, about 0.2–1 s for 40 × 40. It
//! is a reference for checks, not a law for the time loop.

pub mod influence;
pub mod normal;

use super::fastsim::MapCell;
use super::{ContactPatch, Creep, TractionResult};
use crate::error::{InvalidParameter, require_positive};
use crate::math::elliptic;
use influence::Influence;
use nalgebra::{Vector2, Vector3};
use normal::NormalProblem;
use std::f64::consts::PI;

/// Size of the potential contact area against the Hertz ellipse's
/// bounding box.
const MARGIN: f64 = 1.05;

/// Transient steps remembered by the Anderson acceleration.
const ANDERSON_DEPTH: usize = 6;

/// Default cells along and across the rolling direction.
pub const DEFAULT_CELLS: usize = 32;

/// Largest accepted number of cells per direction (the dense
/// convolutions cost O(cells⁴)).
pub const MAX_CELLS: usize = 200;

/// The exact steady-rolling solver's parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExactRolling {
    /// Friction coefficient μ.
    pub friction: f64,
    /// Combined shear modulus G \[Pa\].
    pub shear_modulus: f64,
    /// Combined Poisson ratio ν.
    pub poisson_ratio: f64,
    /// Cells along the rolling direction.
    pub cells_along: usize,
    /// Cells across it.
    pub cells_across: usize,
    /// Convergence: largest traction change in a sweep over μ p₀.
    pub tolerance: f64,
    /// Most transient steps.
    pub max_steps: usize,
    /// Most Gauss–Seidel sweeps, over all steps.
    pub max_sweeps: usize,
}

/// A solved contact: resultants, the map, and how the solver went.
#[derive(Debug, Clone)]
pub struct ExactSolution {
    /// Resultants on the ball, in the frame of the patch (as FASTSIM's).
    pub result: TractionResult,
    /// Every cell of the numerical contact area.
    pub cells: Vec<MapCell>,
    /// Frictional power −Σ p·s V ΔA dissipated in the slip area \[W\]
    /// (in steady state it equals the rigid-slip power `result.dissipation`
    /// up to the discretisation).
    pub frictional_power: f64,
    /// Normal-problem iterations taken.
    pub normal_iterations: usize,
    /// Transient steps and Gauss–Seidel sweeps (over all steps) taken.
    pub steps: usize,
    pub sweeps: usize,
    /// Whether the tangential sweeps met the tolerance.
    pub converged: bool,
}

impl ExactRolling {
    /// The solver with the default grid and tolerance.
    pub fn new(friction: f64, shear_modulus: f64, poisson_ratio: f64) -> Self {
        Self {
            friction,
            shear_modulus,
            poisson_ratio,
            cells_along: DEFAULT_CELLS,
            cells_across: DEFAULT_CELLS,
            tolerance: 1e-5,
            max_steps: 2000,
            max_sweeps: 100_000,
        }
    }

    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        super::require_friction("friction", self.friction)?;
        require_positive("shear_modulus", self.shear_modulus)?;
        super::kalker::check_poisson_ratio(self.poisson_ratio)?;
        for (field, n) in [
            ("cells_along", self.cells_along),
            ("cells_across", self.cells_across),
        ] {
            if !(4..=MAX_CELLS).contains(&n) {
                return Err(InvalidParameter::new(
                    field,
                    n as f64,
                    format!("must be between 4 and {MAX_CELLS}"),
                ));
            }
        }
        Ok(())
    }

    /// Solves the contact `patch` (its semi-minor axis lies along the
    /// rolling direction, as in a ball bearing) for the sliding velocity
    /// `slip` of ball material relative to ring material at P, the
    /// relative angular velocity `spin` = ω_b − ω_ring and the signed
    /// rolling velocity `rolling` (u·e_roll, the flow direction) \[m/s\].
    pub fn solve(
        &self,
        patch: &ContactPatch,
        slip: &Vector3<f64>,
        spin: &Vector3<f64>,
        rolling: f64,
    ) -> ExactSolution {
        let (na, nc) = (self.cells_along.max(4), self.cells_across.max(4));
        let (along, across) = (patch.semi_minor, patch.semi_major);
        let dx = 2.0 * MARGIN * along / na as f64;
        let dy = 2.0 * MARGIN * across / nc as f64;
        let cell_area = dx * dy;
        let x_of = |i: usize| -MARGIN * along + (i as f64 + 0.5) * dx;
        let y_of = |k: usize| -MARGIN * across + (k as f64 + 0.5) * dy;
        let influence = Influence::new(na, nc, dx, dy, self.shear_modulus, self.poisson_ratio);

        // 1. Normal problem on the Hertz gap of these semi-axes.
        let effective_modulus = self.shear_modulus / (1.0 - self.poisson_ratio);
        let (curv_x, curv_y) = hertz_curvatures(along, across, patch.load, effective_modulus);
        let gap: Vec<f64> = (0..na * nc)
            .map(|c| curv_x * x_of(c / nc).powi(2) + curv_y * y_of(c % nc).powi(2))
            .collect();
        let normal = NormalProblem {
            along: na,
            across: nc,
            cell_area,
            gap: &gap,
            load: patch.load,
            influence: &influence,
        }
        .solve(1e-10, 2000);
        let pressure = normal.pressure;
        let bound: Vec<f64> = pressure.iter().map(|p| self.friction * p).collect();

        // 2. Rigid slip per cell, per unit V (creepage units), in the
        // frame whose x̂ is the flow direction.
        let direction = if rolling >= 0.0 { 1.0 } else { -1.0 };
        let n = patch.normal;
        let ex = direction * patch.rolling_direction;
        let ey = n.cross(&ex);
        let speed = rolling.abs().max(f64::MIN_POSITIVE);
        let (s_x, s_y) = (slip.dot(&ex), slip.dot(&ey));
        let (w_n, w_x, w_y) = (spin.dot(&n), spin.dot(&ex), spin.dot(&ey));
        let depth = |y: f64| {
            let r = patch.deformed_radius;
            if r.is_finite() {
                r - (r * r - y * y).max(0.0).sqrt()
            } else {
                0.0
            }
        };
        let rigid = |c: usize| {
            let (x, y) = (x_of(c / nc), y_of(c % nc));
            let d = depth(y);
            Vector2::new(s_x - w_n * y - d * w_y, s_y + w_n * x + d * w_x) / speed
        };
        let w: Vec<Vector2<f64>> = (0..na * nc).map(rigid).collect();

        // The compliance A/Δx at the cell centres (`here`) and at the
        // points one cell upstream (`upstream`), as tables over offsets.
        let (ri, rk) = (na as isize - 1, nc as isize - 1);
        let width = (2 * nc - 1) as isize;
        let table = |k: &[f64], shift: isize| -> Vec<f64> {
            let mut out = Vec::with_capacity(((2 * ri + 1) * width) as usize);
            for di in -ri..=ri {
                for dk in -rk..=rk {
                    out.push(k[influence.index(di - shift, dk)] / dx);
                }
            }
            out
        };
        let here = [
            table(&influence.xx, 0),
            table(&influence.xy, 0),
            table(&influence.yy, 0),
        ];
        let upstream = [
            table(&influence.xx, 1),
            table(&influence.xy, 1),
            table(&influence.yy, 1),
        ];
        let at = |di: isize, dk: isize| ((di + ri) * width + dk + rk) as usize;
        let diagonal = Vector2::new(here[0][at(0, 0)], here[2][at(0, 0)]);
        let loaded: Vec<usize> = (0..na * nc).filter(|&c| pressure[c] > 0.0).collect();
        // The loaded cells of each row along x: a contiguous run across
        // (the contact is convex), empty outside it.
        let spans: Vec<(usize, usize)> = (0..na)
            .map(|i| {
                let row: Vec<usize> = (0..nc).filter(|&k| pressure[i * nc + k] > 0.0).collect();
                match (row.first(), row.last()) {
                    (Some(&first), Some(&last)) => (first, last + 1),
                    _ => (0, 0),
                }
            })
            .collect();
        // Adds Σ T(I − c) v over the loaded cells I to `out` (x and y
        // parts), for a table triple T: one contiguous run of the tables
        // per row. Only the loaded cells' slip is used.
        let scatter = |t: &[Vec<f64>; 3], c: usize, v: Vector2<f64>, out: &mut [Vec<f64>; 2]| {
            let (i_c, k_c) = ((c / nc) as isize, (c % nc) as isize);
            for (i_f, &(k0, k1)) in spans.iter().enumerate() {
                if k0 == k1 {
                    continue;
                }
                let base = at(i_f as isize - i_c, k0 as isize - k_c);
                let n = k1 - k0;
                let row = i_f * nc + k0..i_f * nc + k1;
                let (xx, xy, yy) = (
                    &t[0][base..base + n],
                    &t[1][base..base + n],
                    &t[2][base..base + n],
                );
                let [ox, oy] = out;
                for (((ox, oy), (a, b)), d) in ox[row.clone()]
                    .iter_mut()
                    .zip(&mut oy[row])
                    .zip(xx.iter().zip(xy))
                    .zip(yy)
                {
                    *ox += a * v.x + b * v.y;
                    *oy += b * v.x + d * v.y;
                }
            }
        };

        // 3. Pseudo-transient iteration: each outer step is one step of
        // transient rolling by Δx (Kalker 1990, ch. 5), whose fixed point
        // is the steady state above: the upstream displacement A⁻p comes
        // from the previous traction field, and the cells solve the
        // remaining static problem (a symmetric positive definite
        // compliance) by Gauss–Seidel sweeps with each cell's friction
        // law solved exactly (Vollebregt's ConvexGS), to a fraction of the
        // last step's change (inexact inner solves; the fixed point is
        // the same).
        // The field as a flat vector over the loaded cells (x, y pairs).
        let m = loaded.len();
        let mut iterate = vec![0.0; 2 * m];
        let mut p = vec![Vector2::zeros(); na * nc];
        let mut slip = [vec![0.0; na * nc], vec![0.0; na * nc]];
        let mut shifted = [vec![0.0; na * nc], vec![0.0; na * nc]];
        let mut stick = vec![false; na * nc];
        let (mut sweeps, mut steps, mut converged) = (0, 0, false);
        let mut anderson = Anderson::new(ANDERSON_DEPTH);
        while steps < self.max_steps {
            steps += 1;
            // T(x): the transient step from the field x. Its upstream
            // displacement A⁻x/Δx is frozen; the static problem starts
            // from x.
            for part in &mut shifted {
                part.fill(0.0);
            }
            let mut here_now = [vec![0.0; na * nc], vec![0.0; na * nc]];
            for (j, &c) in loaded.iter().enumerate() {
                p[c] = Vector2::new(iterate[2 * j], iterate[2 * j + 1]);
                if p[c] != Vector2::zeros() {
                    scatter(&upstream, c, p[c], &mut shifted);
                    scatter(&here, c, p[c], &mut here_now);
                }
            }
            for c in 0..na * nc {
                slip[0][c] = w[c].x + here_now[0][c] - shifted[0][c];
                slip[1][c] = w[c].y + here_now[1][c] - shifted[1][c];
            }
            loop {
                sweeps += 1;
                let (mut moved, mut largest): (f64, f64) = (0.0, 0.0);
                for &c in &loaded {
                    let s_c = Vector2::new(slip[0][c], slip[1][c]);
                    let own = s_c - diagonal.component_mul(&p[c]);
                    let (new, sticks) = local_solution(&own, &diagonal, bound[c]);
                    stick[c] = sticks;
                    largest = largest.max(new.norm());
                    let change = new - p[c];
                    if change == Vector2::zeros() {
                        continue;
                    }
                    moved = moved.max(change.norm());
                    p[c] = new;
                    scatter(&here, c, change, &mut slip);
                }
                if moved <= 0.1 * self.tolerance * largest || sweeps >= self.max_sweeps {
                    break;
                }
            }
            // Residual T(x) − x against the tolerance, relative to the
            // field's largest traction.
            let mapped: Vec<f64> = loaded.iter().flat_map(|&c| [p[c].x, p[c].y]).collect();
            let (mut change, mut largest): (f64, f64) = (0.0, 0.0);
            for j in 0..m {
                let d =
                    (mapped[2 * j] - iterate[2 * j]).hypot(mapped[2 * j + 1] - iterate[2 * j + 1]);
                change = change.max(d);
                largest = largest.max(mapped[2 * j].hypot(mapped[2 * j + 1]));
            }
            if change <= self.tolerance * largest || sweeps >= self.max_sweeps {
                converged = change <= self.tolerance * largest;
                break;
            }
            anderson.next(&mut iterate, &mapped);
        }
        // The steady slip of the solved field, s = w + (A − A⁻) p/Δx.
        let mut upstream_now = [vec![0.0; na * nc], vec![0.0; na * nc]];
        for &c in &loaded {
            scatter(&upstream, c, p[c], &mut upstream_now);
        }
        let s: Vec<Vector2<f64>> = (0..na * nc)
            .map(|c| {
                Vector2::new(
                    slip[0][c] + shifted[0][c] - upstream_now[0][c],
                    slip[1][c] + shifted[1][c] - upstream_now[1][c],
                )
            })
            .collect();

        // 4. Resultants and the map.
        let (mut fx, mut fy, mut mn, mut mx, mut my) = (0.0, 0.0, 0.0, 0.0, 0.0);
        let (mut power, mut friction_power, mut stuck) = (0.0, 0.0, 0);
        let mut cells = Vec::with_capacity(loaded.len());
        for &c in &loaded {
            let (x, y) = (x_of(c / nc), y_of(c % nc));
            let f = p[c] * cell_area;
            fx += f.x;
            fy += f.y;
            mn += x * f.y - y * f.x;
            let d = depth(y);
            mx += d * f.y;
            my -= d * f.x;
            power -= f.dot(&w[c]) * speed;
            friction_power -= f.dot(&s[c]) * speed;
            stuck += usize::from(stick[c]);
            cells.push(MapCell {
                x,
                y,
                traction: p[c],
                bound: bound[c],
                stick: stick[c],
            });
        }
        let result = TractionResult {
            force: fx * ex + fy * ey,
            moment: Vector3::zeros(),
            couple: mx * ex + my * ey + mn * n,
            dissipation: power,
            creep: Some(Creep {
                longitudinal: s_x / speed,
                lateral: s_y / speed,
                spin: w_n / speed,
                stick_fraction: if loaded.is_empty() {
                    0.0
                } else {
                    stuck as f64 / loaded.len() as f64
                },
            }),
        };
        ExactSolution {
            result,
            cells,
            frictional_power: friction_power,
            normal_iterations: normal.iterations,
            steps,
            sweeps,
            converged,
        }
    }
}

/// Anderson acceleration of a fixed-point iteration x ← T(x) (D. G.
/// Anderson, *J. ACM* 12 (1965) 547; H. F. Walker and P. Ni, *SIAM J.
/// Numer. Anal.* 49 (2011) 1715, "Type II", undamped): the next iterate
/// combines the last `depth` images so that the combination of their
/// residuals T(x) − x is least in the 2-norm.
struct Anderson {
    depth: usize,
    /// Differences of successive iterates and of successive residuals.
    iterates: Vec<Vec<f64>>,
    residuals: Vec<Vec<f64>>,
    last: Option<(Vec<f64>, Vec<f64>)>,
}

impl Anderson {
    fn new(depth: usize) -> Self {
        Self {
            depth,
            iterates: Vec::new(),
            residuals: Vec::new(),
            last: None,
        }
    }

    /// Replaces `x` by the next iterate, given its image `mapped` = T(x).
    fn next(&mut self, x: &mut [f64], mapped: &[f64]) {
        let residual: Vec<f64> = mapped.iter().zip(x.iter()).map(|(t, x)| t - x).collect();
        if let Some((last_x, last_r)) = self.last.take() {
            self.iterates
                .push(x.iter().zip(&last_x).map(|(a, b)| a - b).collect());
            self.residuals
                .push(residual.iter().zip(&last_r).map(|(a, b)| a - b).collect());
            if self.iterates.len() > self.depth {
                self.iterates.remove(0);
                self.residuals.remove(0);
            }
        }
        self.last = Some((x.to_vec(), residual.clone()));
        let k = self.residuals.len();
        // γ = argmin |r − ΔR γ| by the normal equations (k ≤ depth),
        // with a relative ridge against near-dependent columns.
        let mut gram = nalgebra::DMatrix::<f64>::zeros(k, k);
        let mut rhs = nalgebra::DVector::<f64>::zeros(k);
        for a in 0..k {
            rhs[a] = dot(&self.residuals[a], &residual);
            for b in 0..=a {
                let v = dot(&self.residuals[a], &self.residuals[b]);
                gram[(a, b)] = v;
                gram[(b, a)] = v;
            }
        }
        let ridge = 1e-12 * (0..k).map(|a| gram[(a, a)]).fold(0.0, f64::max);
        for a in 0..k {
            gram[(a, a)] += ridge;
        }
        let gamma = if k > 0 {
            gram.cholesky().map(|c| c.solve(&rhs))
        } else {
            None
        };
        for (i, xi) in x.iter_mut().enumerate() {
            let mut v = *xi + residual[i];
            if let Some(g) = &gamma {
                for a in 0..k {
                    v -= g[a] * (self.iterates[a][i] + self.residuals[a][i]);
                }
            }
            *xi = v;
        }
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// One cell's own problem: with the slip `own` that the other cells'
/// tractions and the rigid slip give it, and its diagonal rolling
/// coefficients `d` (s = own + d ∘ p), the traction that adheres (s = 0)
/// within the bound `g`, or else slips at the bound against the slip:
/// p = −t s with s = own/(1 + t d) and t|s| = g (t found by a safeguarded
/// Newton iteration on the increasing function t²|s(t)|² − g²).
fn local_solution(own: &Vector2<f64>, d: &Vector2<f64>, g: f64) -> (Vector2<f64>, bool) {
    let adhere = Vector2::new(-own.x / d.x, -own.y / d.y);
    if adhere.norm() <= g {
        return (adhere, true);
    }
    if g == 0.0 {
        return (Vector2::zeros(), false);
    }
    let value = |t: f64| {
        let sx = own.x / (1.0 + t * d.x);
        let sy = own.y / (1.0 + t * d.y);
        let f = t * t * (sx * sx + sy * sy) - g * g;
        // d/dt of t² s_c² = 2 t s_c² / (1 + t d_c).
        let df = 2.0 * t * (sx * sx / (1.0 + t * d.x) + sy * sy / (1.0 + t * d.y));
        (f, df)
    };
    // Bracket: t|s(t)| ≤ t|own| gives f(g/|own|) ≤ 0; grow the upper end.
    let mut lo = g / own.norm();
    let mut hi = 2.0 * lo;
    while value(hi).0 < 0.0 {
        lo = hi;
        hi *= 2.0;
    }
    let mut t = lo;
    for _ in 0..100 {
        let (f, df) = value(t);
        if f.abs() <= 1e-14 * g * g {
            break;
        }
        if f < 0.0 {
            lo = t;
        } else {
            hi = t;
        }
        let next = t - f / df;
        t = if next > lo && next < hi {
            next
        } else {
            0.5 * (lo + hi)
        };
        if hi - lo <= 1e-15 * hi {
            break;
        }
    }
    let s = Vector2::new(own.x / (1.0 + t * d.x), own.y / (1.0 + t * d.y));
    let p = -t * s;
    // Exactly on the bound (the iteration leaves a relative 1e-14).
    (p * (g / p.norm()), false)
}

/// The curvature coefficients (A, B) of the gap h₀ = A x² + B y² whose
/// Hertz contact under load Q with effective modulus E* (1/E* = Σ (1 −
/// ν_i²)/E_i) has semi-axis `along` in x and `across` in y (Johnson 1985,
/// eqs 3.59–3.61: with a ≥ b the semi-axes and e² = 1 − b²/a²,
/// A_a = p₀ b (K − E)/(E* a² e²), A_b = p₀ b ((a²/b²) E − K)/(E* a² e²)).
pub fn hertz_curvatures(along: f64, across: f64, load: f64, effective_modulus: f64) -> (f64, f64) {
    let (major, minor) = (along.max(across), along.min(across));
    let p0 = 1.5 * load / (PI * along * across);
    let m = 1.0 - (minor / major).powi(2);
    let c = elliptic::complete(m);
    let scale = p0 * minor / (effective_modulus * major * major);
    // (K − E)/m = D; ((a²/b²) E − K)/m = (E/(1 − m) − K)/m.
    let on_major = scale * c.d;
    let on_minor = if m > 1e-6 {
        scale * (c.e / (1.0 - m) - c.k) / m
    } else {
        scale * PI / 4.0
    };
    if along >= across {
        (on_major, on_minor)
    } else {
        (on_minor, on_major)
    }
}

#[cfg(test)]
mod tests;
