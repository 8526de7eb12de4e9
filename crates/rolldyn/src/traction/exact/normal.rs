//! The normal contact problem on a grid: the pressure p ≥ 0 that closes
//! the gap where the bodies touch and leaves it open elsewhere, carrying
//! the load Q (Kalker 1990, ch. 5, NORM). Solved by the constrained
//! conjugate-gradient method of I. A. Polonsky and L. M. Keer, "A new
//! numerical method for solving rough contact problems based on the
//! multi-level multi-summation and conjugate gradient techniques", *Wear*
//! 231 (1999) 206–219, with the load prescribed (the rigid approach is
//! the gap's mean over the contact).

use super::influence::Influence;

/// The grid's geometry for the normal problem.
pub struct NormalProblem<'a> {
    /// Cells along × across.
    pub along: usize,
    pub across: usize,
    /// Cell area \[m²\].
    pub cell_area: f64,
    /// Undeformed gap h₀ at each cell centre (row-major, along outer) \[m\].
    pub gap: &'a [f64],
    /// Normal load Q \[N\].
    pub load: f64,
    /// Influence coefficients.
    pub influence: &'a Influence,
}

/// The solution of the normal problem.
pub struct NormalSolution {
    /// Pressure per cell \[Pa\].
    pub pressure: Vec<f64>,
    /// Iterations taken.
    pub iterations: usize,
    /// Final relative error Σ p |g − ḡ| ΔA / (Q ḡ-scale): the gap's
    /// spread over the loaded cells against the mean surface displacement.
    pub residual: f64,
}

impl NormalProblem<'_> {
    /// u = A p (normal displacement at every cell).
    fn displacement(&self, p: &[f64], u: &mut [f64]) {
        let (na, nc) = (self.along, self.across);
        for i in 0..na {
            for k in 0..nc {
                let mut sum = 0.0;
                for j in 0..na {
                    let row = &p[j * nc..(j + 1) * nc];
                    let di = i as isize - j as isize;
                    for (l, pl) in row.iter().enumerate() {
                        if *pl != 0.0 {
                            sum += self.influence.normal
                                [self.influence.index(di, k as isize - l as isize)]
                                * pl;
                        }
                    }
                }
                u[i * nc + k] = sum;
            }
        }
    }

    /// Solves to relative tolerance `tolerance` in at most `max_iterations`.
    pub fn solve(&self, tolerance: f64, max_iterations: usize) -> NormalSolution {
        let n = self.along * self.across;
        let mut p = vec![self.load / (n as f64 * self.cell_area); n];
        let mut u = vec![0.0; n];
        let mut g = vec![0.0; n];
        let mut t = vec![0.0; n];
        let mut r = vec![0.0; n];
        let (mut g_old, mut delta) = (1.0, 0.0);
        let mut residual = f64::INFINITY;
        let mut iterations = 0;
        while iterations < max_iterations {
            iterations += 1;
            self.displacement(&p, &mut u);
            for c in 0..n {
                g[c] = u[c] + self.gap[c];
            }
            let loaded: Vec<usize> = (0..n).filter(|&c| p[c] > 0.0).collect();
            if loaded.is_empty() {
                break;
            }
            let mean = loaded.iter().map(|&c| g[c]).sum::<f64>() / loaded.len() as f64;
            for v in &mut g {
                *v -= mean;
            }
            let g_norm: f64 = loaded.iter().map(|&c| g[c] * g[c]).sum();
            for c in 0..n {
                t[c] = if p[c] > 0.0 {
                    g[c] + delta * (g_norm / g_old) * t[c]
                } else {
                    0.0
                };
            }
            g_old = g_norm;
            self.displacement(&t, &mut r);
            let r_mean = loaded.iter().map(|&c| r[c]).sum::<f64>() / loaded.len() as f64;
            let (mut num, mut den) = (0.0, 0.0);
            for &c in &loaded {
                num += g[c] * t[c];
                den += (r[c] - r_mean) * t[c];
            }
            let tau = if den > 0.0 { num / den } else { 0.0 };
            let mut changed = false;
            for c in 0..n {
                p[c] = (p[c] - tau * t[c]).max(0.0);
            }
            for c in 0..n {
                if p[c] == 0.0 && g[c] < 0.0 {
                    p[c] -= tau * g[c];
                    changed = true;
                }
            }
            delta = if changed { 0.0 } else { 1.0 };
            let total: f64 = p.iter().sum::<f64>() * self.cell_area;
            if total > 0.0 {
                let s = self.load / total;
                for v in &mut p {
                    *v *= s;
                }
            }
            let scale = mean.abs().max(f64::MIN_POSITIVE);
            residual = loaded.iter().map(|&c| p[c] * g[c].abs()).sum::<f64>() * self.cell_area
                / (self.load * scale);
            if residual < tolerance && !changed {
                break;
            }
        }
        NormalSolution {
            pressure: p,
            iterations,
            residual,
        }
    }
}
