use super::*;

/// Van der Pol, μ large: the classical stiff test (HW II §IV.1).
struct VanDerPol {
    mu: f64,
}
impl OdeSystem for VanDerPol {
    fn dimension(&self) -> usize {
        2
    }
    fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
        dy[0] = y[1];
        dy[1] = self.mu * ((1.0 - y[0] * y[0]) * y[1]) - y[0];
    }
    fn error_scale(&self, scale: &mut [f64]) {
        scale.fill(1e-3);
    }
}

#[test]
fn order_conditions_up_to_three() {
    // HW II Table IV.7.1 with βᵢⱼ = αᵢⱼ + γᵢⱼ, β'ᵢ = Σⱼ βᵢⱼ; for a
    // W-method the α and γ sums separately (Σ bᵢαᵢ = 1/2, Σ bᵢγ'ᵢ = −γ).
    let t = &ROS34PW2;
    let s = t.b.len();
    let alpha_sum: Vec<f64> = t.alpha.iter().map(|r| r.iter().sum()).collect();
    let gamma_sum: Vec<f64> = t.gamma_below.iter().map(|r| r.iter().sum()).collect();
    let beta = |i: usize, j: usize| t.alpha[i][j] + t.gamma_below[i][j];
    let beta_sum: Vec<f64> = (0..s).map(|i| (0..i).map(|j| beta(i, j)).sum()).collect();
    let g = t.gamma;
    let dot = |w: &[f64], v: &[f64]| w.iter().zip(v).map(|(a, b)| a * b).sum::<f64>();
    for (weights, order) in [(t.b, 3), (t.b_embedded, 2)] {
        assert!((weights.iter().sum::<f64>() - 1.0).abs() < 1e-14);
        assert!((dot(weights, &beta_sum) - (0.5 - g)).abs() < 1e-14);
        assert!((dot(weights, &alpha_sum) - 0.5).abs() < 1e-14);
        assert!((dot(weights, &gamma_sum) + g).abs() < 1e-14);
        if order == 3 {
            let a2: Vec<f64> = alpha_sum.iter().map(|a| a * a).collect();
            assert!((dot(weights, &a2) - 1.0 / 3.0).abs() < 1e-14);
            let nested: f64 = (0..s)
                .map(|i| weights[i] * (0..i).map(|k| beta(i, k) * beta_sum[k]).sum::<f64>())
                .sum();
            assert!((nested - (1.0 / 6.0 - g + g * g)).abs() < 1e-14);
        }
    }
}

/// Numerical damping of an undamped oscillation: x'' = −ω² x stepped
/// N times a period shrinks by |R(iωh)|^N a period, R the stability
/// function R(z) = 1 + z bᵀ (I − z(α + Γ))⁻¹ 1 (HW II §IV.7), computed
/// here from the tableau: 0.9908 at 16 steps a period, 0.9402 at 8 and
/// 0.883 at 6 (the rule of `rolldyn run`'s default step for film
/// pockets; docs/dynamics.md).
#[test]
fn oscillation_damped_per_period_as_the_stability_function_says() {
    use crate::integrate::test_systems::UnitOscillator as Oscillator;
    use nalgebra::Complex;
    let t = &ROS34PW2;
    let stability = |z: Complex<f64>| {
        // (I − z(α + Γ)) k = 1 is lower triangular: forward substitution.
        let mut k = [Complex::new(0.0, 0.0); 4];
        for i in 0..4 {
            let mut rhs = Complex::new(1.0, 0.0);
            for (j, kj) in k.iter().enumerate().take(i) {
                rhs += z * (t.alpha[i][j] + t.gamma_below[i][j]) * kj;
            }
            k[i] = rhs / (Complex::new(1.0, 0.0) - z * t.gamma);
        }
        Complex::new(1.0, 0.0)
            + z * t
                .b
                .iter()
                .zip(&k)
                .map(|(b, k)| k * *b)
                .sum::<Complex<f64>>()
    };
    for (steps, expected) in [(16, 0.9908), (8, 0.9402), (6, 0.8835)] {
        let h = std::f64::consts::TAU / steps as f64;
        let per_period = stability(Complex::new(0.0, h)).norm().powi(steps);
        assert!(
            (per_period - expected).abs() < 1e-4,
            "{steps}: {per_period}"
        );
        let mut r = Rosenbrock::builder(&ROS34PW2)
            .relative_tolerance(0.5)
            .max_step(h)
            .initial_step(Some(h))
            .build(&Oscillator, &[1.0, 0.0])
            .unwrap();
        r.evaluate_jacobian(&Oscillator);
        r.jacobian_age = Some(0);
        let periods = 10;
        for _ in 0..steps * periods {
            r.attempt(&mut Oscillator, h);
            r.finish_step(&mut Oscillator, h);
        }
        let amplitude = r.y()[0].hypot(r.y()[1]);
        let measured = amplitude.powf(1.0 / periods as f64);
        assert!(
            (measured - per_period).abs() < 1e-6,
            "{steps} steps a period: {measured} against {per_period}"
        );
    }
}

/// Fixed steps on a smooth problem, with the exact and with a crude
/// (zero) Jacobian: the global error falls as h³ either way — the W
/// property that lets a step reuse an old Jacobian.
#[test]
fn third_order_with_exact_and_with_wrong_jacobian() {
    struct Rotating;
    impl OdeSystem for Rotating {
        fn dimension(&self) -> usize {
            2
        }
        fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
            dy[0] = -y[1] + 0.1 * t.cos();
            dy[1] = y[0] - 0.2 * y[1] * y[1];
        }
    }
    let reference = {
        let mut r = Rosenbrock::builder(&ROS34PW2)
            .relative_tolerance(1e-12)
            .max_step(1e-3)
            .build(&Rotating, &[1.0, 0.0])
            .unwrap();
        while r.t() < 1.0 {
            r.step(&mut Rotating, 1.0).unwrap();
        }
        r.y().to_vec()
    };
    for zero_jacobian in [false, true] {
        let errors: Vec<f64> = [0.1, 0.05]
            .iter()
            .map(|&h| {
                let mut r = Rosenbrock::builder(&ROS34PW2)
                    .relative_tolerance(0.5)
                    .max_step(h)
                    .initial_step(Some(h))
                    .build(&Rotating, &[1.0, 0.0])
                    .unwrap();
                r.evaluate_jacobian(&Rotating);
                if zero_jacobian {
                    r.jacobian = BlockJacobian::zeros(BlockLayout::dense(2));
                }
                r.jacobian_age = Some(0);
                while r.t() < 1.0 - 1e-12 {
                    // Keep the chosen Jacobian and step: attempt directly.
                    let h = h.min(1.0 - r.t());
                    r.attempt(&mut Rotating, h);
                    r.finish_step(&mut Rotating, h);
                }
                (r.y()[0] - reference[0]).hypot(r.y()[1] - reference[1])
            })
            .collect();
        let ratio = errors[0] / errors[1];
        assert!(
            (6.5..10.0).contains(&ratio),
            "zero Jacobian {zero_jacobian}: errors {errors:?}, ratio {ratio}"
        );
    }
}

#[test]
fn stiff_van_der_pol_in_few_steps() {
    // μ = 1000 to t = 2, on the slow manifold (the first fast
    // transition is near t ≈ 800): an explicit method would be held to
    // h ≲ 2/μ by stability (≥ 1000 steps); the Rosenbrock–W method
    // takes few steps and matches a tight-tolerance run of itself.
    let sys = VanDerPol { mu: 1000.0 };
    let run = |rtol: f64| {
        let mut s = VanDerPol { mu: 1000.0 };
        let mut r = Rosenbrock::builder(&ROS34PW2)
            .relative_tolerance(rtol)
            .max_step(1.0)
            .build(&sys, &[2.0, 0.0])
            .unwrap();
        while r.t() < 2.0 {
            r.step(&mut s, 2.0).unwrap();
        }
        (r.y().to_vec(), r.stats())
    };
    let (tight, _) = run(1e-10);
    let (y, stats) = run(1e-5);
    assert!((y[0] - tight[0]).abs() < 1e-5 * 2.0, "{y:?} vs {tight:?}");
    assert!(stats.steps < 200, "{stats:?}");
    assert!(stats.jacobian_evaluations >= 1);
    assert!(stats.factorizations >= stats.jacobian_evaluations);
}

/// The energy control's scaled error shrinks with the step as the
/// states' error does, h^q (q = 3 for ROS34PW2): the estimate (the
/// embedded solution's local error, h³) over an allowance per unit step
/// (h) goes as h², and raised to q/(q − 1) it gives the PI controller the
/// exponent it assumes. A pendulum, θ'' = −sin θ, at 1 rad amplitude.
#[test]
fn scaled_energy_error_goes_as_the_states_error() {
    use crate::integrate::energy_control::EnergyBalance;
    struct Pendulum;
    impl OdeSystem for Pendulum {
        fn dimension(&self) -> usize {
            2
        }
        fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
            dy[0] = y[1];
            dy[1] = -y[0].sin();
        }
        fn energy_balance(&self, _t: f64, y: &[f64]) -> Option<EnergyBalance> {
            Some(EnergyBalance {
                work: 0.0,
                dissipated: 0.0,
                mechanical: 0.5 * y[1] * y[1] + 1.0 - y[0].cos(),
            })
        }
    }
    let y0 = [0.3, 0.9];
    let scaled = |h: f64| {
        let mut r = Rosenbrock::builder(&ROS34PW2)
            .relative_tolerance(0.5)
            .max_step(1.0)
            .initial_step(Some(h))
            .energy_tolerance(Some(1e-3))
            // ε h P₀ ≥ 6e-12 J: far above the energies' rounding (2e-16 J),
            // so that the allowance goes as h.
            .build(&Pendulum, &y0)
            .unwrap();
        r.evaluate_jacobian(&Pendulum);
        r.attempt(&mut Pendulum, h)
    };
    for h in [0.05, 0.025, 0.0125] {
        let ratio = scaled(h) / scaled(0.5 * h);
        let exponent = ratio.log2();
        assert!(
            (exponent - 3.0).abs() < 0.3,
            "h = {h}: err(h)/err(h/2) = 2^{exponent:.3}"
        );
    }
}
