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
//!    in the traction increments along the flow, on which the operator
//!    is the symmetric compliance ([`steady`], Vollebregt's SteadyGS),
//!    until a sweep moves no traction by more than `tolerance` of the
//!    largest.
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
//! forces converge at first order in the cell size or faster (order ≈ 1.6
//! for the lateral force of spin), plus a non-monotone part from the
//! staircase edge; 32 × 32 cells reproduce Kalker's creep coefficients to
//! 1–2 % (tests), and the lateral force of a spinning ball-bearing contact
//! to −5.6 %. [`ExactRolling::solve_extrapolated`] (the default of
//! `rolldyn traction --method exact`) solves three grids and extrapolates
//! to zero cell size: 0.2 % on that force ([`extrapolate`]; the
//! convergence table is in docs/dynamics.md). Each evaluation convolves
//! the normal problem by FFT and sweeps the tangential one in 15–50 sweeps
//! of O(N²) for N cells: about 0.03 s at 32 × 32, 0.3 s at 64 × 64.
//! It is a reference for checks, not a law for the time loop.

pub mod extrapolate;
pub mod influence;
pub mod normal;
pub mod steady;

pub use extrapolate::{EXTRAPOLATION_GRIDS, Extrapolated, FlowFrame, Resultants};

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

/// Default cells along and across the rolling direction.
pub const DEFAULT_CELLS: usize = 32;

/// Largest accepted number of cells per direction: the tangential sweeps
/// cost O(cells⁴) each (release build, one contact: 64 cells 1 s, 96
/// cells 5 s, 128 about 16 s; 200 took over 90 s).
pub const MAX_CELLS: usize = 128;

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
    /// Convergence: largest traction change in a sweep over the largest
    /// traction.
    pub tolerance: f64,
    /// Most Gauss–Seidel sweeps.
    pub max_sweeps: usize,
}

/// A solved contact: resultants, the map, and how the solver went.
#[derive(Debug, Clone)]
pub struct ExactSolution {
    /// Resultants on the ball, in the frame of the patch (as FASTSIM's).
    pub result: TractionResult,
    /// The same resultants as numbers in the flow frame.
    pub resultants: Resultants,
    /// The flow frame of the solve.
    pub frame: FlowFrame,
    /// Every cell of the numerical contact area.
    pub cells: Vec<MapCell>,
    /// Frictional power −Σ p·s V ΔA dissipated in the slip area \[W\]
    /// (in steady state it equals the rigid-slip power `result.dissipation`
    /// up to the discretisation).
    pub frictional_power: f64,
    /// Normal-problem iterations taken.
    pub normal_iterations: usize,
    /// Gauss–Seidel sweeps of the tangential problem.
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
            max_sweeps: 1000,
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
        if patch.load <= 0.0 {
            return ExactSolution {
                result: TractionResult::default(),
                resultants: Resultants::default(),
                frame: FlowFrame {
                    ex: patch.rolling_direction,
                    ey: patch.normal.cross(&patch.rolling_direction),
                    n: patch.normal,
                },
                cells: Vec::new(),
                frictional_power: 0.0,
                normal_iterations: 0,
                sweeps: 0,
                converged: true,
            };
        }
        let contact = self.prepare(patch.semi_minor, patch.semi_major, patch.load);
        let cell_area = contact.cell_area();
        let (x_of, y_of) = (|c: usize| contact.x(c), |c: usize| contact.y(c));
        let bound = &contact.bound;

        // 1. The grid and the normal problem; 2. rigid slip per cell, per
        // unit V (creepage units), in the frame whose x̂ is the flow
        // direction.
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
            let (x, y) = (x_of(c), y_of(c));
            let d = depth(y);
            Vector2::new(s_x - w_n * y - d * w_y, s_y + w_n * x + d * w_x) / speed
        };
        let w: Vec<Vector2<f64>> = (0..contact.cells()).map(rigid).collect();

        // 3. The tangential problem (SteadyGS in traction increments).
        let loaded: Vec<usize> = (0..contact.cells()).filter(|&c| bound[c] > 0.0).collect();
        let tangential = contact.tangential(&w, self.tolerance, self.max_sweeps);
        let (p, s, stick) = (&tangential.traction, &tangential.slip, &tangential.stick);

        // 4. Resultants and the map.
        let mut sums = Resultants::default();
        let mut stuck = 0;
        let mut cells = Vec::with_capacity(loaded.len());
        for &c in &loaded {
            let (x, y) = (x_of(c), y_of(c));
            let f = p[c] * cell_area;
            sums.force_along += f.x;
            sums.force_across += f.y;
            sums.spin_moment += x * f.y - y * f.x;
            let d = depth(y);
            sums.couple_along += d * f.y;
            sums.couple_across -= d * f.x;
            sums.power -= f.dot(&w[c]) * speed;
            sums.frictional_power -= f.dot(&s[c]) * speed;
            stuck += usize::from(stick[c]);
            cells.push(MapCell {
                x,
                y,
                traction: p[c],
                bound: bound[c],
                stick: stick[c],
            });
        }
        let frame = FlowFrame { ex, ey, n };
        let creep = Creep {
            longitudinal: s_x / speed,
            lateral: s_y / speed,
            spin: w_n / speed,
            stick_fraction: if loaded.is_empty() {
                0.0
            } else {
                stuck as f64 / loaded.len() as f64
            },
        };
        let result = frame.result(&sums, creep);
        ExactSolution {
            result,
            resultants: sums,
            frame,
            cells,
            frictional_power: sums.frictional_power,
            normal_iterations: contact.normal_iterations,
            sweeps: tangential.sweeps,
            converged: tangential.converged,
        }
    }
}

impl ExactRolling {
    /// The grid, influence coefficients and normal problem of an ellipse
    /// with semi-axes `along` and `across` the rolling direction \[m\]
    /// under load `load` \[N\]: everything of a solve that does not
    /// depend on the creepages (a table of many creepages on one contact
    /// prepares it once).
    pub fn prepare(&self, along: f64, across: f64, load: f64) -> PreparedContact {
        let (na, nc) = (self.cells_along.max(4), self.cells_across.max(4));
        let dx = 2.0 * MARGIN * along / na as f64;
        let dy = 2.0 * MARGIN * across / nc as f64;
        let influence = Influence::new(na, nc, dx, dy, self.shear_modulus, self.poisson_ratio);
        let mut contact = PreparedContact {
            along: na,
            across: nc,
            dx,
            dy,
            half_along: along,
            half_across: across,
            influence,
            bound: Vec::new(),
            normal_iterations: 0,
        };
        // The normal problem on the Hertz gap of these semi-axes.
        let effective_modulus = self.shear_modulus / (1.0 - self.poisson_ratio);
        let (curv_x, curv_y) = hertz_curvatures(along, across, load, effective_modulus);
        let gap: Vec<f64> = (0..na * nc)
            .map(|c| curv_x * contact.x(c).powi(2) + curv_y * contact.y(c).powi(2))
            .collect();
        let normal = NormalProblem {
            along: na,
            across: nc,
            cell_area: dx * dy,
            gap: &gap,
            load,
            influence: &contact.influence,
        }
        .solve(1e-10, 2000);
        contact.bound = normal.pressure.iter().map(|p| self.friction * p).collect();
        contact.normal_iterations = normal.iterations;
        contact
    }
}

/// A contact's grid with its influence coefficients and the traction
/// bound μ p_n of its solved normal problem ([`ExactRolling::prepare`]).
/// Cells are numbered i·across + k, i along the flow from the leading edge.
#[derive(Debug, Clone)]
pub struct PreparedContact {
    /// Cells along the flow.
    pub along: usize,
    /// Cells across it.
    pub across: usize,
    /// Cell length along the flow \[m\].
    pub dx: f64,
    /// Cell width across it \[m\].
    pub dy: f64,
    /// Hertz semi-axis along the flow \[m\].
    pub half_along: f64,
    /// Hertz semi-axis across it \[m\].
    pub half_across: f64,
    influence: Influence,
    /// Traction bound μ p_n per cell \[Pa\] (0 outside the contact).
    pub bound: Vec<f64>,
    /// Iterations the normal problem took.
    pub normal_iterations: usize,
}

impl PreparedContact {
    /// Number of cells.
    pub fn cells(&self) -> usize {
        self.along * self.across
    }

    /// Area of one cell \[m²\].
    pub fn cell_area(&self) -> f64 {
        self.dx * self.dy
    }

    /// Centre of cell `c` along the flow, from the contact centre \[m\].
    pub fn x(&self, c: usize) -> f64 {
        -MARGIN * self.half_along + ((c / self.across) as f64 + 0.5) * self.dx
    }

    /// Centre of cell `c` across the flow \[m\].
    pub fn y(&self, c: usize) -> f64 {
        -MARGIN * self.half_across + ((c % self.across) as f64 + 0.5) * self.dy
    }

    /// The steady tangential problem for the rigid slip per unit rolling
    /// speed `rigid` (one value per cell, creepage units).
    pub fn tangential(
        &self,
        rigid: &[Vector2<f64>],
        tolerance: f64,
        max_sweeps: usize,
    ) -> steady::SteadySolution {
        steady::SteadyProblem {
            along: self.along,
            across: self.across,
            dx: self.dx,
            influence: &self.influence,
            rigid,
            bound: &self.bound,
        }
        .solve(tolerance, max_sweeps)
    }
}

/// One cell's own problem: with the slip `own` that the other cells'
/// tractions and the rigid slip give it, and its diagonal rolling
/// coefficients `d` (s = own + d ∘ p), the traction that adheres (s = 0)
/// within the bound `g`, or else slips at the bound against the slip:
/// p = −t s with s = own/(1 + t d) and t|s| = g (t found by a safeguarded
/// Newton iteration on the increasing function t²|s(t)|² − g²).
pub(super) fn local_solution(own: &Vector2<f64>, d: &Vector2<f64>, g: f64) -> (Vector2<f64>, bool) {
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
