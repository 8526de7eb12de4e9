//! Efficiency snapshots of the stiff solver: the work the
//! ROS34PW2 integrator does on two short benchmark-like runs — accepted and
//! rejected steps, right-hand sides, Jacobians (and their cost in
//! right-hand sides), factorizations — against numbers recorded when the
//! solver was tuned. A change that makes the solver do more than
//! [`SLACK`] × the recorded work fails (an efficiency regression); one that
//! makes it do much less fails too, so that the snapshot is updated with
//! the improvement (and docs/performance.md with it). The band allows for
//! libm differences between machines (step counts of adaptive runs are
//! deterministic on one machine). Wall time is measured by the benchmarks,
//! never here.

use super::common::{bearing_6304, bearing_7008c, dynamics_6304, dynamics_7008c, steel_shan_2023};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::{BearingModel, DragParameters};
use rolldyn::integrate::{IntegrationStats, Integrator, ROS34PW2, Rosenbrock};
use rolldyn::material::Material;

/// Allowed growth of any counter over its snapshot (and shrinkage below
/// its inverse).
const SLACK: f64 = 1.15;

fn run(mut model: BearingModel, y0: &[f64], rtol: f64, t_end: f64) -> IntegrationStats {
    let mut r = Rosenbrock::builder(&ROS34PW2)
        .relative_tolerance(rtol)
        .max_step(1e-4)
        .build(&model, y0)
        .unwrap();
    while r.t() < t_end {
        r.step(&mut model, t_end).unwrap();
    }
    r.stats()
}

fn check(name: &str, got: IntegrationStats, snapshot: IntegrationStats) {
    eprintln!("{name}: {got:?}");
    let pairs = [
        ("steps", got.steps, snapshot.steps),
        (
            "rejected steps",
            got.rejected_steps,
            snapshot.rejected_steps,
        ),
        (
            "RHS evaluations",
            got.rhs_evaluations,
            snapshot.rhs_evaluations,
        ),
        (
            "Jacobian evaluations",
            got.jacobian_evaluations,
            snapshot.jacobian_evaluations,
        ),
        (
            "Jacobian RHS evaluations",
            got.jacobian_rhs_evaluations,
            snapshot.jacobian_rhs_evaluations,
        ),
        (
            "factorizations",
            got.factorizations,
            snapshot.factorizations,
        ),
    ];
    for (what, value, recorded) in pairs {
        let (value, recorded) = (value as f64, recorded.max(1) as f64);
        assert!(
            value <= SLACK * recorded + 2.0,
            "{name}: {what} {value} exceed the snapshot {recorded} by more than {SLACK}×"
        );
        assert!(
            value >= recorded / SLACK - 2.0,
            "{name}: {what} {value} fell well below the snapshot {recorded}: update it"
        );
    }
}

/// Shan et al. 2023's 6304 (planar, L–N, Coulomb at the centre, 100 N, 8000 rpm)
/// from pure rolling, 20 ms at rtol 1e-3.
#[test]
fn stiff_solver_work_on_the_6304() {
    let g = bearing_6304();
    let steel = steel_shan_2023();
    let model = BearingModel::new(
        &g,
        &steel,
        &steel,
        HertzModel::HertzCircular,
        dynamics_6304(-100.0),
    )
    .unwrap();
    let y0 = model.pure_rolling_state([0.0; 5]);
    let got = run(model, &y0, 1e-3, 0.02);
    check(
        "6304, 20 ms",
        got,
        IntegrationStats {
            steps: 2463,
            rejected_steps: 278,
            rhs_evaluations: 10687,
            jacobian_evaluations: 156,
            jacobian_rhs_evaluations: 2496,
            factorizations: 2659,
            fast_part_jacobians: 0,
        },
    );
}

/// The 7008C (EHL on the 12 × 6 grid, whirling cage, 200 N, 10 000 rpm)
/// from the Jones–Harris state, 10 ms at rtol 1e-2.
#[test]
fn stiff_solver_work_on_the_7008c() {
    let (params, eq) = dynamics_7008c(DragParameters::default());
    let steel = Material::STEEL_52100;
    let model =
        BearingModel::new(&bearing_7008c(), &steel, &steel, HertzModel::Exact, params).unwrap();
    let y0 = model.state_from_equilibrium(&eq);
    let got = run(model, &y0, 1e-2, 0.01);
    check(
        "7008C, 10 ms",
        got,
        IntegrationStats {
            steps: 130,
            rejected_steps: 3,
            rhs_evaluations: 530,
            jacobian_evaluations: 7,
            jacobian_rhs_evaluations: 182,
            factorizations: 42,
            fast_part_jacobians: 0,
        },
    );
}
