//! Steady-rolling tangential solver in traction increments (Vollebregt's
//! SteadyGS, CONTACT; E. A. H. Vollebregt, "A Gauss–Seidel type solver
//! for special convex programs, with application to frictional contact
//! mechanics", *J. Optim. Theory Appl.* 87 (1995) 47–67, and the CONTACT
//! user guide).
//!
//! The steady slip s = w + (A − A⁻) p/Δx equals w + A q/Δx with q the
//! backward difference of the tractions along the flow, q_I = p_I −
//! p_{I−1} (zero inflow at the leading edge; one cell past the trailing
//! edge of each line takes −p of its last cell). In q the operator is the
//! symmetric positive definite compliance A, on which Gauss–Seidel
//! converges, while in p it is not (plain Gauss–Seidel on p diverges).
//!
//! Each line along the flow is swept from the trailing edge to the
//! leading edge. A cell's update δ moves the whole adhering run
//! downstream of it with it (their increments stay), so the increment
//! changes by +δ at the cell and −δ at the first slipping or exterior
//! cell downstream, J*: the cell sees the 2 × 2 coefficient
//! (A(0) − A(J* − I))/Δx, diagonal along a line. It then adheres or
//! slips exactly (its own two-by-two friction problem); tractions pushed over their
//! bound downstream are scaled back onto it.

use super::influence::Influence;
use super::local_solution;
use nalgebra::Vector2;

/// The grid's problem: `along` × `across` cells (index i·across + k, i
/// along the flow from the leading edge), the rigid slip per unit V and
/// the traction bound μ p_n per cell (0 outside the contact).
pub struct SteadyProblem<'a> {
    pub along: usize,
    pub across: usize,
    pub dx: f64,
    pub influence: &'a Influence,
    pub rigid: &'a [Vector2<f64>],
    pub bound: &'a [f64],
}

/// The solved tractions, the steady slip, the adhesion flags.
pub struct SteadySolution {
    pub traction: Vec<Vector2<f64>>,
    pub slip: Vec<Vector2<f64>>,
    pub stick: Vec<bool>,
    pub sweeps: usize,
    pub converged: bool,
}

impl SteadyProblem<'_> {
    /// Solves until a sweep moves no traction by more than `tolerance` of
    /// the largest, in at most `max_sweeps`.
    pub fn solve(&self, tolerance: f64, max_sweeps: usize) -> SteadySolution {
        let (na, nc) = (self.along, self.across);
        let loaded = |i: usize, k: usize| i < na && self.bound[i * nc + k] > 0.0;
        // Tractions and increments on the grid plus one line past the
        // trailing edge (i = na).
        let mut p = vec![Vector2::zeros(); (na + 1) * nc];
        let mut q = vec![Vector2::zeros(); (na + 1) * nc];
        let mut stick = vec![true; na * nc];
        let inf = self.influence;
        let scale = 1.0 / self.dx;
        // s_I = w_I + Σ_J A(I − J) q_J /Δx over the grid.
        let slip_at = |q: &[Vector2<f64>], i: usize, k: usize| {
            let mut s = self.rigid[i * nc + k];
            for j in 0..=na {
                let row = &q[j * nc..(j + 1) * nc];
                let base = inf.index(i as isize - j as isize, k as isize);
                // Offsets k − l for l = 0.. run down from k: the tables'
                // run [base − (nc − 1), base] read backwards.
                let start = base + 1 - nc;
                let (xx, xy, yy) = (
                    &inf.xx[start..=base],
                    &inf.xy[start..=base],
                    &inf.yy[start..=base],
                );
                let (mut sx, mut sy) = (0.0, 0.0);
                for (((ql, a), b), d) in row
                    .iter()
                    .zip(xx.iter().rev())
                    .zip(xy.iter().rev())
                    .zip(yy.iter().rev())
                {
                    sx += a * ql.x + b * ql.y;
                    sy += b * ql.x + d * ql.y;
                }
                s.x += sx * scale;
                s.y += sy * scale;
            }
            s
        };
        let (mut sweeps, mut converged) = (0, false);
        while sweeps < max_sweeps {
            sweeps += 1;
            let mut moved: f64 = 0.0;
            for k in 0..nc {
                for i in (0..na).rev() {
                    let c = i * nc + k;
                    if !loaded(i, k) {
                        continue;
                    }
                    // J*: the first cell downstream that does not adhere.
                    let mut m = i + 1;
                    while loaded(m, k) && stick[m * nc + k] {
                        m += 1;
                    }
                    let coefficient = Vector2::new(
                        (inf.xx[inf.index(0, 0)] - inf.xx[inf.index(i as isize - m as isize, 0)])
                            * scale,
                        (inf.yy[inf.index(0, 0)] - inf.yy[inf.index(i as isize - m as isize, 0)])
                            * scale,
                    );
                    let s = slip_at(&q, i, k);
                    let own = s - coefficient.component_mul(&p[c]);
                    let (new, sticks) = local_solution(&own, &coefficient, self.bound[c]);
                    stick[c] = sticks;
                    let delta = new - p[c];
                    if delta == Vector2::zeros() {
                        continue;
                    }
                    moved = moved.max(delta.norm());
                    // The cell and its adhering run move together, each
                    // held within its bound.
                    p[c] = new;
                    for r in i + 1..m {
                        let cr = r * nc + k;
                        p[cr] += delta;
                        let (size, g) = (p[cr].norm(), self.bound[cr]);
                        if size > g {
                            p[cr] *= g / size;
                        }
                    }
                    // The line's increments from its tractions.
                    for r in i..=na {
                        let before = if r == 0 {
                            Vector2::zeros()
                        } else {
                            p[(r - 1) * nc + k]
                        };
                        q[r * nc + k] = p[r * nc + k] - before;
                    }
                }
            }
            let largest = p.iter().map(|v| v.norm()).fold(0.0, f64::max);
            if moved <= tolerance * largest {
                converged = true;
                break;
            }
        }
        let slip = (0..na * nc)
            .map(|c| {
                if loaded(c / nc, c % nc) {
                    slip_at(&q, c / nc, c % nc)
                } else {
                    Vector2::zeros()
                }
            })
            .collect();
        p.truncate(na * nc);
        SteadySolution {
            traction: p,
            slip,
            stick,
            sweeps,
            converged,
        }
    }
}
