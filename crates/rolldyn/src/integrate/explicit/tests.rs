use super::*;
use crate::integrate::tableau::{DOPRI5, RK4};

/// y₀' = −y₀ (tame), y₁' = y₁² from y₁(0) = 1 (blows up at t = 1),
/// with named components.
struct NamedBlowUp;

impl OdeSystem for NamedBlowUp {
    fn dimension(&self) -> usize {
        2
    }
    fn rhs(&self, _t: f64, y: &[f64], dydt: &mut [f64]) {
        dydt[0] = -y[0];
        dydt[1] = y[1] * y[1];
    }
    fn state_name(&self, index: usize) -> String {
        ["tame", "exploding"][index].into()
    }
}

/// A failing integration names the component that fails, with both
/// integrators (exit 3 with the time, the state and a hint).
#[test]
fn failure_names_the_state_component() {
    let adaptive = StepControl::Adaptive {
        relative_tolerance: 1e-6,
        max_step: 0.1,
        initial_step: None,
    };
    let mut explicit = ExplicitRk::builder(&DOPRI5)
        .control(adaptive)
        .build(&NamedBlowUp, &[1.0, 1.0])
        .unwrap();
    let mut stiff = crate::integrate::Rosenbrock::builder(&crate::integrate::ROS34PW2)
        .relative_tolerance(1e-6)
        .max_step(0.1)
        .build(&NamedBlowUp, &[1.0, 1.0])
        .unwrap();
    let mut failures = Vec::new();
    for _ in 0..100_000 {
        if let Err(e) = explicit.step(&mut NamedBlowUp, 2.0) {
            failures.push(e);
            break;
        }
    }
    for _ in 0..100_000 {
        if let Err(e) = stiff.step(&mut NamedBlowUp, 2.0) {
            failures.push(e);
            break;
        }
    }
    assert_eq!(failures.len(), 2);
    for e in failures {
        let (t, state) = match &e {
            IntegrationError::StepTooSmall { t, state, .. }
            | IntegrationError::NonFinite { t, state } => (*t, state.clone()),
            other => panic!("{other}"),
        };
        assert_eq!(state, "exploding", "{e}");
        assert!((t - 1.0).abs() < 1e-2, "{e}");
        assert!(e.to_string().contains("exploding"));
    }
}

/// Harmonic oscillator x'' = −x.
struct Oscillator {
    accepted: u64,
}

impl OdeSystem for Oscillator {
    fn dimension(&self) -> usize {
        2
    }
    fn rhs(&self, _t: f64, y: &[f64], dydt: &mut [f64]) {
        dydt[0] = y[1];
        dydt[1] = -y[0];
    }
    fn error_scale(&self, scale: &mut [f64]) {
        scale.fill(1e-3);
    }
    fn accept_step(&mut self, _t: f64, _y: &[f64]) -> bool {
        self.accepted += 1;
        false
    }
}

fn run(
    tab: &'static crate::integrate::tableau::Tableau,
    control: StepControl,
    t_end: f64,
) -> (f64, IntegrationStats, u64) {
    let mut sys = Oscillator { accepted: 0 };
    let mut rk = ExplicitRk::builder(tab)
        .control(control)
        .build(&sys, &[1.0, 0.0])
        .unwrap();
    while rk.t() < t_end {
        rk.step(&mut sys, t_end).unwrap();
    }
    assert_eq!(rk.t(), t_end);
    let err = (rk.y()[0] - t_end.cos())
        .abs()
        .max((rk.y()[1] + t_end.sin()).abs());
    (err, rk.stats(), sys.accepted)
}

#[test]
fn rk4_converges_at_fourth_order() {
    let (e1, s1, accepted) = run(&RK4, StepControl::Fixed { step: 0.1 }, 10.0);
    let (e2, _, _) = run(&RK4, StepControl::Fixed { step: 0.05 }, 10.0);
    let ratio = e1 / e2;
    assert!((14.0..18.0).contains(&ratio), "ratio {ratio}");
    assert_eq!(s1.steps, 100);
    assert_eq!(accepted, s1.steps, "hook once per accepted step");
    assert_eq!(s1.rhs_evaluations, 1 + 4 * 100);
}

#[test]
fn dopri5_meets_its_tolerance_and_scales() {
    let control = |rtol| StepControl::Adaptive {
        relative_tolerance: rtol,
        max_step: 1.0,
        initial_step: None,
    };
    let (e1, s1, _) = run(&DOPRI5, control(1e-6), 20.0);
    let (e2, s2, _) = run(&DOPRI5, control(1e-9), 20.0);
    assert!(e1 < 1e-4 && e2 < 1e-7, "{e1} {e2}");
    assert!(e2 < e1 / 100.0);
    assert!(s2.steps > s1.steps);
    // FSAL: 6 new evaluations per attempted step after the first.
    let attempts = s1.steps + s1.rejected_steps;
    assert!(s1.rhs_evaluations <= 2 + 6 * attempts, "{s1:?}");
}

#[test]
fn dense_output_is_fourth_order() {
    let err = |rtol: f64| {
        let mut sys = Oscillator { accepted: 0 };
        let mut rk = ExplicitRk::builder(&DOPRI5)
            .control(StepControl::Fixed { step: rtol })
            .build(&sys, &[1.0, 0.0])
            .unwrap();
        let mut worst = 0.0f64;
        let mut out = [0.0; 2];
        while rk.t() < 5.0 {
            let t0 = rk.t();
            rk.step(&mut sys, 5.0).unwrap();
            for k in 1..4 {
                let t = t0 + (rk.t() - t0) * k as f64 / 4.0;
                rk.interpolate(t, &mut out);
                worst = worst.max((out[0] - t.cos()).abs());
            }
        }
        worst
    };
    // Dense output of DOPRI5 has local error O(h⁵).
    let ratio = err(0.2) / err(0.1);
    assert!(ratio > 20.0, "ratio {ratio}");
    // RK4 Hermite output, O(h⁴) locally.
    let mut sys = Oscillator { accepted: 0 };
    let mut rk = ExplicitRk::builder(&RK4)
        .control(StepControl::Fixed { step: 0.01 })
        .build(&sys, &[1.0, 0.0])
        .unwrap();
    rk.step(&mut sys, 1.0).unwrap();
    let mut out = [0.0; 2];
    rk.interpolate(0.005, &mut out);
    assert!((out[0] - 0.005f64.cos()).abs() < 1e-10);
}

/// y' = y², y(0) = 1 blows up at t = 1.
struct BlowUp;
impl OdeSystem for BlowUp {
    fn dimension(&self) -> usize {
        1
    }
    fn rhs(&self, _t: f64, y: &[f64], dydt: &mut [f64]) {
        dydt[0] = y[0] * y[0];
    }
}

#[test]
fn reports_failure_instead_of_nan() {
    let mut sys = BlowUp;
    let control = StepControl::Adaptive {
        relative_tolerance: 1e-8,
        max_step: 0.1,
        initial_step: None,
    };
    let mut rk = ExplicitRk::builder(&DOPRI5)
        .control(control)
        .build(&sys, &[1.0])
        .unwrap();
    let mut result = Ok(());
    while rk.t() < 2.0 && result.is_ok() {
        result = rk.step(&mut sys, 2.0);
    }
    // Relative error control can step just past the pole while |y| is
    // huge; what matters is an error, not NaN, and a finite last state.
    assert!(result.is_err(), "integrated through a singularity");
    assert!(
        rk.t() < 1.01 && rk.y()[0].is_finite(),
        "t {} y {} {:?}",
        rk.t(),
        rk.y()[0],
        result
    );
    assert!(
        ExplicitRk::builder(&RK4)
            .control(control)
            .build(&sys, &[1.0])
            .is_err(),
        "RK4 has no error estimate"
    );
}
