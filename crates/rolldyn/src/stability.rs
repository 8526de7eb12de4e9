//! Linear stability of a running state: is a steady run a state the
//! bearing returns to, or one it whirls away from?
//!
//! The model's equations ẏ = f(t, y) are linearized about states of a run,
//! A = ∂f/∂y by central differences of the right-hand side, and the
//! eigenvalues λ = σ ± iω of A are its small motions' growth rates σ and
//! angular frequencies ω: σ > 0 grows as e^{σt}, ζ = −σ/|λ| is the
//! damping ratio (Meirovitch, *Fundamentals of Vibrations*, 2001); the
//! logarithmic decrement of rotordynamics is δ = −2πσ/ω ≈ 2πζ (Genta,
//! *Dynamics of Rotating Systems*, 2005).
//!
//! A bearing's equations are periodic in time (the balls turn), so a
//! Jacobian frozen at one instant does not decide stability in general;
//! the exact answer is Floquet's, from the flow map over a period. A
//! Jacobian **averaged** over states sampled along a period is the
//! first-order averaging approximation of the periodic system (Nayfeh &
//! Mook, *Nonlinear Oscillations*, 1979, the method of averaging), good when the coefficients
//! vary little over a period against their mean (a ring running under a
//! centred load, whose contacts all carry alike) and the period is short
//! against the mode's (on the free 7218B ring at 10 000 rpm the ball pass
//! is 1.28 kHz against a 680 Hz mode, and a Floquet analysis agrees to
//! 4 %). Where the contacts load
//! and unload along the period, and above all where balls strike their
//! pockets, the run is not smooth and neither the averaged Jacobian nor a
//! differenced flow map describes it: docs/dynamics.md ("Dry traction at
//! speed") shows both missing on the mounted 7218B.
//!
//! Increments: each state is perturbed by 1e-4 of its error scale
//! ([`OdeSystem::error_scale`]), the size the integrator judges it at, so
//! positions in metres and speeds in radians per second get commensurate
//! steps; the result is insensitive to it over 1e-6…1e-1 on the bearing
//! models.
use crate::integrate::OdeSystem;
use nalgebra::{Complex, DMatrix, DVector};

/// Relative size of a state's perturbation against its error scale.
const PERTURBATION: f64 = 1e-4;

/// One eigenvalue of a linearized run and its shape.
#[derive(Debug, Clone)]
pub struct Eigenmode {
    /// Growth rate σ, the eigenvalue's real part \[1/s\]; positive grows.
    pub growth_rate: f64,
    /// Frequency ω/2π of the oscillation, the imaginary part \[Hz\]; zero
    /// for a real eigenvalue.
    pub frequency: f64,
    /// Damping ratio ζ = −σ/|λ| (negative where the mode grows).
    pub damping_ratio: f64,
    /// The eigenvector, normalized to unit Euclidean length over the states
    /// divided by their error scales (so a component's modulus compares
    /// across units).
    pub shape: Vec<Complex<f64>>,
}

/// The Jacobian ∂f/∂y of `system` at (t, y) by central differences.
pub fn jacobian(system: &impl OdeSystem, t: f64, y: &[f64]) -> DMatrix<f64> {
    let n = y.len();
    let mut scale = vec![1.0; n];
    system.error_scale(&mut scale);
    let mut jac = DMatrix::zeros(n, n);
    let (mut plus, mut minus) = (vec![0.0; n], vec![0.0; n]);
    let mut shifted = y.to_vec();
    for k in 0..n {
        let h = PERTURBATION * scale[k].max(f64::MIN_POSITIVE.sqrt());
        shifted[k] = y[k] + h;
        let up = shifted[k];
        system.rhs(t, &shifted, &mut plus);
        shifted[k] = y[k] - h;
        // The step actually taken (a large angle rounds its increment).
        let step = up - shifted[k];
        system.rhs(t, &shifted, &mut minus);
        shifted[k] = y[k];
        for i in 0..n {
            jac[(i, k)] = (plus[i] - minus[i]) / step;
        }
    }
    jac
}

/// The mean of the Jacobians at `states` (time, state): the averaged
/// system of a periodic run when the states sample one period evenly.
///
/// # Panics
/// If `states` is empty or the states differ in length (a caller's bug).
pub fn averaged_jacobian(system: &impl OdeSystem, states: &[(f64, Vec<f64>)]) -> DMatrix<f64> {
    assert!(!states.is_empty(), "no states to average over");
    let mut sum = jacobian(system, states[0].0, &states[0].1);
    for (t, y) in &states[1..] {
        sum += jacobian(system, *t, y);
    }
    sum / states.len() as f64
}

/// The eigenmodes of a linearized system `jac`, least stable first; of a
/// complex pair only the one with positive frequency. `scale` is each
/// state's error scale, used to normalize the shapes.
pub fn eigenmodes(jac: &DMatrix<f64>, scale: &[f64]) -> Vec<Eigenmode> {
    // The eigenvalues of D⁻¹ J D, D = diag(scale): the same, from a
    // matrix whose entries no longer span the states' units.
    let floor = f64::MIN_POSITIVE.sqrt();
    let balanced = DMatrix::from_fn(jac.nrows(), jac.ncols(), |r, c| {
        jac[(r, c)] * scale[c].max(floor) / scale[r].max(floor)
    });
    let mut modes: Vec<Eigenmode> = balanced
        .complex_eigenvalues()
        .iter()
        .filter(|lambda| lambda.im >= 0.0)
        .map(|&lambda| Eigenmode {
            growth_rate: lambda.re,
            frequency: lambda.im / std::f64::consts::TAU,
            damping_ratio: if lambda.norm() > 0.0 {
                -lambda.re / lambda.norm()
            } else {
                0.0
            },
            shape: mode_shape(jac, lambda, scale),
        })
        .collect();
    modes.sort_by(|a, b| b.growth_rate.total_cmp(&a.growth_rate));
    modes
}

/// Where a mode's growth rate comes from: σ split over the Jacobian's
/// columns. With v the mode's (right) eigenvector and w its left one
/// (wᴴJ = λwᴴ), λ = wᴴJv / wᴴv exactly, a sum over the entries J_rc; entry
/// c of the result is Re(Σ_r w̄_r J_rc v_c / wᴴv), the share of state c's
/// influence \[1/s\] (positive raises σ), and the entries sum to σ. For a
/// part of the Jacobian (a force's terms) in `part`, the same weights give
/// that part's first-order share of σ (the eigenvalue's sensitivity,
/// Golub & Van Loan 2013). `jac` is the matrix the mode is of, `scale` as
/// for [`eigenmodes`]. Zeros where the left eigenvector is orthogonal to
/// the mode (a defective eigenvalue).
pub fn growth_split(
    jac: &DMatrix<f64>,
    part: &DMatrix<f64>,
    mode: &Eigenmode,
    scale: &[f64],
) -> Vec<f64> {
    let floor = f64::MIN_POSITIVE.sqrt();
    let n = jac.nrows();
    let v: Vec<Complex<f64>> = mode
        .shape
        .iter()
        .zip(scale)
        .map(|(c, s)| c * s.max(floor))
        .collect();
    let lambda = Complex::new(mode.growth_rate, mode.frequency * std::f64::consts::TAU);
    // The left eigenvector: Jᵀ w = λ̄ w.
    let w = inverse_iteration(&jac.transpose(), lambda.conj());
    let denominator: Complex<f64> = (0..n).map(|r| w[r].conj() * v[r]).sum();
    if denominator.norm() == 0.0 || !denominator.norm().is_finite() {
        return vec![0.0; n];
    }
    (0..n)
        .map(|c| {
            let column: Complex<f64> = (0..n).map(|r| w[r].conj() * part[(r, c)]).sum();
            (column * v[c] / denominator).re
        })
        .collect()
}

/// The eigenvector of `jac` for its eigenvalue `lambda`, unit length, by
/// inverse iteration (Golub & Van Loan 2013).
fn inverse_iteration(jac: &DMatrix<f64>, lambda: Complex<f64>) -> DVector<Complex<f64>> {
    let n = jac.nrows();
    // A shift a hair off the eigenvalue keeps the matrix invertible.
    let shift = lambda + Complex::new(1e-9 * lambda.norm().max(1.0), 0.0);
    let shifted =
        jac.map(|v| Complex::new(v, 0.0)) - DMatrix::<Complex<f64>>::identity(n, n) * shift;
    let lu = shifted.lu();
    let mut v = DVector::from_element(n, Complex::new(1.0, 0.0));
    for _ in 0..4 {
        match lu.solve(&v) {
            Some(next) => v = next,
            None => break,
        }
        let norm = v.norm();
        if norm > 0.0 && norm.is_finite() {
            v /= Complex::new(norm, 0.0);
        }
    }
    v
}

/// The eigenvector of `jac` for `lambda`, normalized over the scaled
/// states.
fn mode_shape(jac: &DMatrix<f64>, lambda: Complex<f64>, scale: &[f64]) -> Vec<Complex<f64>> {
    let v = inverse_iteration(jac, lambda);
    let mut shape: Vec<Complex<f64>> = v
        .iter()
        .zip(scale)
        .map(|(c, s)| c / s.max(f64::MIN_POSITIVE.sqrt()))
        .collect();
    let norm = shape.iter().map(|c| c.norm_sqr()).sum::<f64>().sqrt();
    if norm > 0.0 && norm.is_finite() {
        shape.iter_mut().for_each(|c| *c /= norm);
    }
    shape
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An isotropic rotor on its bearing with cross-coupled stiffness q
    /// (Genta 2005; the destabilizing force of seals and of the
    /// Alford effect): m ÿ + c ẏ + k y + q z = 0, m z̈ + c ż + k z − q y = 0.
    struct CrossCoupledRotor {
        mass: f64,
        damping: f64,
        stiffness: f64,
        cross: f64,
    }

    impl OdeSystem for CrossCoupledRotor {
        fn dimension(&self) -> usize {
            4
        }
        fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
            let (m, c, k, q) = (self.mass, self.damping, self.stiffness, self.cross);
            dy[0] = y[2];
            dy[1] = y[3];
            dy[2] = (-c * y[2] - k * y[0] - q * y[1]) / m;
            dy[3] = (-c * y[3] - k * y[1] + q * y[0]) / m;
        }
        fn error_scale(&self, scale: &mut [f64]) {
            scale.copy_from_slice(&[1e-6, 1e-6, 1e-3, 1e-3]);
        }
    }

    /// Its characteristic equation factors into m λ² + c λ + k ∓ i q = 0:
    /// the forward whirl loses stability where q > c ω_n, ω_n = √(k/m).
    fn exact_roots(r: &CrossCoupledRotor) -> Vec<Complex<f64>> {
        let (m, c, k, q) = (r.mass, r.damping, r.stiffness, r.cross);
        let mut roots = Vec::new();
        for sign in [1.0, -1.0] {
            let disc = Complex::new(c * c - 4.0 * m * k, 4.0 * m * q * sign).sqrt();
            roots.push((-c + disc) / (2.0 * m));
            roots.push((-c - disc) / (2.0 * m));
        }
        roots
    }

    #[test]
    fn the_eigenvalues_of_a_cross_coupled_rotor_are_its_characteristic_roots() {
        let base = CrossCoupledRotor {
            mass: 2.0,
            damping: 40.0,
            stiffness: 8e6,
            cross: 0.0,
        };
        let omega_n = (base.stiffness / base.mass).sqrt();
        // Below, at twice and at the threshold q = c ω_n.
        for ratio in [0.5, 1.0, 2.0] {
            let rotor = CrossCoupledRotor {
                cross: ratio * base.damping * omega_n,
                ..base
            };
            let jac = jacobian(&rotor, 0.0, &[0.0; 4]);
            let modes = eigenmodes(&jac, &[1e-6, 1e-6, 1e-3, 1e-3]);
            let mut exact: Vec<Complex<f64>> = exact_roots(&rotor)
                .into_iter()
                .filter(|r| r.im >= 0.0)
                .collect();
            exact.sort_by(|a, b| b.re.total_cmp(&a.re));
            assert_eq!(modes.len(), 2);
            for (mode, root) in modes.iter().zip(&exact) {
                let scale = root.norm();
                assert!(
                    (mode.growth_rate - root.re).abs() < 1e-6 * scale,
                    "{ratio}: σ {} against {}",
                    mode.growth_rate,
                    root.re
                );
                assert!((mode.frequency * std::f64::consts::TAU - root.im).abs() < 1e-6 * scale);
            }
            // The least stable root's sign follows q against c ω_n.
            let least = modes[0].growth_rate;
            match ratio {
                r if r < 1.0 => assert!(least < 0.0),
                r if r > 1.0 => assert!(least > 0.0),
                _ => assert!(least.abs() < 1e-6 * omega_n),
            }
            // The growing or least damped mode whirls forward: z lags y
            // by a quarter period (z/y = −i for e^{iωt}).
            let shape = &modes[0].shape;
            let ratio_zy = shape[1] / shape[0];
            assert!(
                (ratio_zy - Complex::new(0.0, -1.0)).norm() < 1e-6,
                "z/y = {ratio_zy}"
            );
        }
    }

    #[test]
    fn a_modes_growth_split_sums_to_its_growth_rate_and_names_the_cross_stiffness() {
        let rotor = CrossCoupledRotor {
            mass: 2.0,
            damping: 40.0,
            stiffness: 8e6,
            cross: 2.0 * 40.0 * 2000.0,
        };
        let scale = [1e-6, 1e-6, 1e-3, 1e-3];
        let jac = jacobian(&rotor, 0.0, &[0.0; 4]);
        let mode = &eigenmodes(&jac, &scale)[0];
        let split = growth_split(&jac, &jac, mode, &scale);
        let sum: f64 = split.iter().sum();
        assert!((sum - mode.growth_rate).abs() < 1e-6 * mode.growth_rate.abs().max(1.0));
        // The damping's part: c ∂λ/∂c = −cλ/(2mλ + c) from the
        // characteristic equation, which takes about c/2m off σ.
        let part = |entries: &[(usize, usize)]| {
            let mut p = DMatrix::zeros(4, 4);
            for &(r, c) in entries {
                p[(r, c)] = jac[(r, c)];
            }
            growth_split(&jac, &p, mode, &scale).iter().sum::<f64>()
        };
        let lambda = Complex::new(mode.growth_rate, mode.frequency * std::f64::consts::TAU);
        let (m, c) = (rotor.mass, rotor.damping);
        let damping = part(&[(2, 2), (3, 3)]);
        let exact = (-c * lambda / (2.0 * m * lambda + c)).re;
        assert!(
            (damping - exact).abs() < 1e-6 * c / m,
            "{damping} against {exact}"
        );
        // The cross stiffness feeds the forward whirl more than the
        // damping drains it: the mode grows.
        let cross = part(&[(2, 1), (3, 0)]);
        assert!(
            cross > -damping && mode.growth_rate > 0.0,
            "{cross}, {damping}"
        );
    }

    /// A spring whose stiffness varies over a period, k (1 + ε cos t).
    struct PumpedSpring;

    impl OdeSystem for PumpedSpring {
        fn dimension(&self) -> usize {
            2
        }
        fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
            dy[0] = y[1];
            dy[1] = -100.0 * (1.0 + 0.5 * t.cos()) * y[0];
        }
    }

    #[test]
    fn an_averaged_jacobian_is_the_mean_stiffness_over_the_period() {
        let period = std::f64::consts::TAU;
        let states: Vec<(f64, Vec<f64>)> = (0..8)
            .map(|i| (period * i as f64 / 8.0, vec![0.0, 0.0]))
            .collect();
        let mean = averaged_jacobian(&PumpedSpring, &states);
        assert!((mean[(1, 0)] + 100.0).abs() < 1e-6, "{}", mean[(1, 0)]);
        assert!((mean[(0, 1)] - 1.0).abs() < 1e-9);
        // The frozen Jacobian at t = 0 is the stiffest instant.
        let frozen = jacobian(&PumpedSpring, 0.0, &[0.0, 0.0]);
        assert!((frozen[(1, 0)] + 150.0).abs() < 1e-6);
    }
}
