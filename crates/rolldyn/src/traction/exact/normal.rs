//! The normal contact problem on a grid: the pressure p ≥ 0 that closes
//! the gap where the bodies touch and leaves it open elsewhere, carrying
//! the load Q (Kalker 1990, ch. 5, NORM). Solved by the constrained
//! conjugate-gradient method of I. A. Polonsky and L. M. Keer, "A new
//! numerical method for solving rough contact problems based on the
//! multi-level multi-summation and conjugate gradient techniques", *Wear*
//! 231 (1999) 206–219, with the load prescribed (the rigid approach is
//! the gap's mean over the contact). The displacements are convolutions,
//! computed by FFT ([`Convolution`]).

use super::influence::Influence;
use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

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
    /// Solves to relative tolerance `tolerance` in at most `max_iterations`.
    pub fn solve(&self, tolerance: f64, max_iterations: usize) -> NormalSolution {
        let n = self.along * self.across;
        // u = A p, the normal displacement at every cell.
        let mut displacement = Convolution::new(self.along, self.across, |di, dk| {
            self.influence.normal[self.influence.index(di, dk)]
        });
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
            displacement.apply(&p, &mut u);
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
            displacement.apply(&t, &mut r);
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

/// Linear convolution of an `along` × `across` grid with a kernel over
/// the offsets |di| < along, |dk| < across, by FFT on the grid padded to
/// twice its size (the kernel embedded circularly, so nothing wraps).
pub struct Convolution {
    rows: usize,
    cols: usize,
    along: usize,
    across: usize,
    kernel: Vec<Complex<f64>>,
    buffer: Vec<Complex<f64>>,
    column: Vec<Complex<f64>>,
    row_forward: Arc<dyn Fft<f64>>,
    row_inverse: Arc<dyn Fft<f64>>,
    col_forward: Arc<dyn Fft<f64>>,
    col_inverse: Arc<dyn Fft<f64>>,
}

impl Convolution {
    /// The convolution with `kernel(di, dk)` (field − source offsets).
    pub fn new(along: usize, across: usize, kernel: impl Fn(isize, isize) -> f64) -> Self {
        let (rows, cols) = (2 * along, 2 * across);
        let mut planner = FftPlanner::new();
        let mut out = Self {
            rows,
            cols,
            along,
            across,
            kernel: vec![Complex::default(); rows * cols],
            buffer: vec![Complex::default(); rows * cols],
            column: vec![Complex::default(); rows],
            row_forward: planner.plan_fft_forward(cols),
            row_inverse: planner.plan_fft_inverse(cols),
            col_forward: planner.plan_fft_forward(rows),
            col_inverse: planner.plan_fft_inverse(rows),
        };
        let (ra, rc) = (along as isize, across as isize);
        for di in 1 - ra..ra {
            for dk in 1 - rc..rc {
                let r = di.rem_euclid(rows as isize) as usize;
                let c = dk.rem_euclid(cols as isize) as usize;
                out.kernel[r * cols + c] = Complex::new(kernel(di, dk), 0.0);
            }
        }
        let mut kernel = std::mem::take(&mut out.kernel);
        out.transform(&mut kernel, true);
        out.kernel = kernel;
        out
    }

    /// 2-D transform of `data` (rows × cols) in place.
    fn transform(&mut self, data: &mut [Complex<f64>], forward: bool) {
        let (row_fft, col_fft) = if forward {
            (&self.row_forward, &self.col_forward)
        } else {
            (&self.row_inverse, &self.col_inverse)
        };
        for row in data.chunks_exact_mut(self.cols) {
            row_fft.process(row);
        }
        for c in 0..self.cols {
            for r in 0..self.rows {
                self.column[r] = data[r * self.cols + c];
            }
            col_fft.process(&mut self.column);
            for r in 0..self.rows {
                data[r * self.cols + c] = self.column[r];
            }
        }
    }

    /// out = kernel ∗ values on the grid (row-major, along outer).
    pub fn apply(&mut self, values: &[f64], out: &mut [f64]) {
        let mut buffer = std::mem::take(&mut self.buffer);
        buffer.fill(Complex::default());
        for i in 0..self.along {
            for k in 0..self.across {
                buffer[i * self.cols + k] = Complex::new(values[i * self.across + k], 0.0);
            }
        }
        self.transform(&mut buffer, true);
        for (b, k) in buffer.iter_mut().zip(&self.kernel) {
            *b *= k;
        }
        self.transform(&mut buffer, false);
        let norm = 1.0 / (self.rows * self.cols) as f64;
        for i in 0..self.along {
            for k in 0..self.across {
                out[i * self.across + k] = buffer[i * self.cols + k].re * norm;
            }
        }
        self.buffer = buffer;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The FFT convolution equals the direct sum.
    #[test]
    fn convolution_matches_the_direct_sum() {
        let (na, nc) = (5, 7);
        let kernel = |di: isize, dk: isize| {
            1.0 / (1.0 + (di * di) as f64 + 0.5 * (dk * dk) as f64) + 0.1 * di as f64
        };
        let values: Vec<f64> = (0..na * nc).map(|c| ((c * 37) % 11) as f64 - 4.0).collect();
        let mut got = vec![0.0; na * nc];
        Convolution::new(na, nc, kernel).apply(&values, &mut got);
        for i in 0..na {
            for k in 0..nc {
                let mut want = 0.0;
                for j in 0..na {
                    for l in 0..nc {
                        want += kernel(i as isize - j as isize, k as isize - l as isize)
                            * values[j * nc + l];
                    }
                }
                assert!((got[i * nc + k] - want).abs() < 1e-12 * want.abs().max(1.0));
            }
        }
    }
}
