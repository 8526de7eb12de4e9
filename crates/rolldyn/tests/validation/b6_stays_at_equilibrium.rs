//! B6: dynamics started from the quasi-static (Jones–Harris) state at
//! constant speed stays there: contact loads within 1 % after transients.
//!
//! 7008C (Deng et al. 2022 Table 1), 10 000 rpm, F_x = 200 N, EHL traction (Eyring
//! τ₀ = 5 MPa, Λ_L = 0.08, η₀ = 46.7 mPa·s, α_p = 2.2e-8 1/Pa: assumed,
//! docs/validation.md) integrated on the 12 × 6 ellipse grid, cage with
//! whirl, inner ring 0.5 kg free in 5 DOF. The loads of every ball are
//! averaged over 2–6 ms (the inner ring's axial vibration, ~1 kHz, is the
//! transient) and compared with the J–H solution.
//!
//! **Finding.** Against outer-control J–H (the start) the mean loads differ
//! by −1.21 % (inner) and −1.06 % (outer): VALIDATION B6's 1 % criterion is
//! missed, and docs/validation.md reports it as failing. The reason found:
//! J–H's raceway-control hypothesis puts the whole gyroscopic friction on
//! the outer contact (λ_o = 2), while the dynamics lets EHL traction share
//! it between both contacts; the friction's axial component (~M_g/D ≈
//! 0.46 N per ball against Q_i sin α_i ≈ 9 N) shifts the loads by percents.
//! Inner-control J–H gives Q_i 24.77 N, outer-control 26.62 N; the dynamics
//! settles at 26.30 N, inside that bracket. The test asserts that physical
//! property: the dynamic loads lie between the two J–H extremes.

use super::common::{Method, bearing_7008c, dynamics_7008c, integrator};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::{BearingModel, DragParameters};
use rolldyn::dynamics::{TractionSolveOptions, solve_traction_consistent};
use rolldyn::integrate::Integrator;
use rolldyn::material::Material;
use rolldyn::quasistatic::{Conditions, QuasiStaticSolver, RacewayControl, SolverOptions};

/// Mean inner and outer contact loads over 2–6 ms \[N\] and the steps,
/// from the Jones–Harris start or, with `traction_start`, from the
/// traction-consistent quasi-static state.
fn mean_loads(
    method: Method,
    relative_tolerance: f64,
    max_step: f64,
    traction_start: bool,
) -> (f64, f64, u64) {
    let g = bearing_7008c();
    let steel = Material::STEEL_52100;
    let (params, eq) = dynamics_7008c(DragParameters::default());
    let mut model = BearingModel::new(&g, &steel, &steel, HertzModel::Exact, params).unwrap();
    let mut y0 = model.state_from_equilibrium(&eq);
    if traction_start {
        y0 = solve_traction_consistent(&model, &y0, 0.0, &TractionSolveOptions::default())
            .unwrap()
            .state;
    }
    let mut rk = integrator(method, &model, &y0, relative_tolerance, max_step);
    let z = g.ball_count;
    let (t_start, t_end, dt) = (2e-3, 6e-3, 1e-5);
    let mut sample = vec![0.0; y0.len()];
    let mut loads_now = vec![rolldyn::dynamics::ContactSample::default(); z];
    let (mut sum_i, mut sum_o, mut n) = (0.0, 0.0, 0usize);
    let mut next = t_start;
    while rk.t() < t_end {
        rk.step(&mut model, t_end).unwrap();
        while next <= rk.t() {
            rk.interpolate(next, &mut sample);
            model.contact_samples(next, &sample, &mut loads_now);
            sum_i += loads_now.iter().map(|l| l.inner.load).sum::<f64>();
            sum_o += loads_now.iter().map(|l| l.outer.load).sum::<f64>();
            n += z;
            next += dt;
        }
    }
    (sum_i / n as f64, sum_o / n as f64, rk.stats().steps)
}

/// B6 with the explicit method at rtol 1e-5 and the stiff one at the
/// CLI's default 1e-3; both lie in the bracket and agree to 1e-3.
#[test]
fn b6_dynamics_from_jones_harris_stays_within_the_raceway_control_bracket() {
    let g = bearing_7008c();
    let steel = Material::STEEL_52100;
    let (params, eq) = dynamics_7008c(DragParameters::default());
    let (loads, speed) = (params.loads.at(0.0), params.speed.speed_at(0.0));
    let qs = QuasiStaticSolver::new(&g, &steel, &steel, HertzModel::Exact).unwrap();
    let (jh_i, jh_o) = (eq.balls[0].inner.load, eq.balls[0].outer.load);
    let inner_control = qs
        .solve(
            &Conditions {
                loads,
                inner_speed: speed,
                control: RacewayControl::Inner,
            },
            &SolverOptions::default(),
        )
        .unwrap();
    let (lo_i, lo_o) = (
        inner_control.balls[0].inner.load,
        inner_control.balls[0].outer.load,
    );
    let mut by_method = Vec::new();
    for (method, rtol, max_step) in [(Method::Dopri5, 1e-5, 1e-5), (Method::Ros34pw2, 1e-3, 1e-4)] {
        let (mean_i, mean_o, steps) = mean_loads(method, rtol, max_step, false);
        eprintln!(
            "B6 ({method:?}, rtol {rtol:e}): mean Q_i {mean_i:.4} N (J-H {jh_i:.3}, {:+.2} %), Q_o {mean_o:.4} N (J-H {jh_o:.3}, {:+.2} %), {steps} steps",
            100.0 * (mean_i / jh_i - 1.0),
            100.0 * (mean_o / jh_o - 1.0),
        );
        assert!(
            (lo_i..=jh_i).contains(&mean_i),
            "{method:?}: Q_i {mean_i} outside the J–H bracket [{lo_i}, {jh_i}]"
        );
        assert!(
            (lo_o..=jh_o).contains(&mean_o),
            "{method:?}: Q_o {mean_o} outside the J–H bracket [{lo_o}, {jh_o}]"
        );
        by_method.push((mean_i, mean_o));
    }
    let ((ei, eo), (si, so)) = (by_method[0], by_method[1]);
    assert!(
        ((si - ei) / ei).abs() < 1e-3 && ((so - eo) / eo).abs() < 1e-3,
        "stiff ({si}, {so}) vs explicit ({ei}, {eo}) N"
    );
}

/// B6 closed: started from the traction-consistent quasi-static state
/// (no raceway control; the EHL traction shares the gyroscopic moment
/// between the contacts as the dynamics does), the dynamic loads stay at
/// the quasi-static ones within 1 % (VALIDATION B6), with both methods.
#[test]
fn b6_dynamics_from_the_traction_consistent_state_stays_there() {
    let g = bearing_7008c();
    let steel = Material::STEEL_52100;
    let (params, eq) = dynamics_7008c(DragParameters::default());
    let model = BearingModel::new(&g, &steel, &steel, HertzModel::Exact, params).unwrap();
    let y0 = model.state_from_equilibrium(&eq);
    let started = std::time::Instant::now();
    let solved =
        solve_traction_consistent(&model, &y0, 0.0, &TractionSolveOptions::default()).unwrap();
    let mut samples = vec![rolldyn::dynamics::ContactSample::default(); g.ball_count];
    model.contact_samples(0.0, &solved.state, &mut samples);
    let qs_i = samples.iter().map(|s| s.inner.load).sum::<f64>() / g.ball_count as f64;
    let qs_o = samples.iter().map(|s| s.outer.load).sum::<f64>() / g.ball_count as f64;
    eprintln!(
        "B6 traction-consistent start: Q_i {qs_i:.4} N, Q_o {qs_o:.4} N (J-H outer control {:.4}, {:.4}); {} ring and {} ball iterations, residual {:.1e}, {:.1} ms",
        eq.balls[0].inner.load,
        eq.balls[0].outer.load,
        solved.ring_iterations,
        solved.ball_iterations,
        solved.residual,
        started.elapsed().as_secs_f64() * 1e3
    );
    for (method, rtol, max_step) in [(Method::Dopri5, 1e-5, 1e-5), (Method::Ros34pw2, 1e-3, 1e-4)] {
        let (mean_i, mean_o, _) = mean_loads(method, rtol, max_step, true);
        eprintln!(
            "B6 from the traction state ({method:?}): mean Q_i {mean_i:.4} N ({:+.3} %), Q_o {mean_o:.4} N ({:+.3} %)",
            100.0 * (mean_i / qs_i - 1.0),
            100.0 * (mean_o / qs_o - 1.0),
        );
        assert!(
            (mean_i / qs_i - 1.0).abs() < 0.01,
            "{method:?}: Q_i {mean_i} vs {qs_i}"
        );
        assert!(
            (mean_o / qs_o - 1.0).abs() < 0.01,
            "{method:?}: Q_o {mean_o} vs {qs_o}"
        );
    }
}
