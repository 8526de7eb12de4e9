//! `cargo bench -p rolldyn --bench step` (divan): what one evaluation and
//! one step of the dynamic model cost, for the 6304 of Shan et al. 2023
//! (planar, dry, traction at the contact centre, pockets) and the default
//! case's 7008C (EHL traction on the graded grid, whirling outer-guided
//! cage), each 5 ms into a run from its start: the right-hand side, the
//! shared pass at a step's end, the finite-difference Jacobian, the
//! factorization of σI − J and a solve with it, and ten accepted steps of
//! ROS34PW2 and of DOPRI5 at rtol 1e-3 in a run in progress (a fresh copy
//! of the warmed integrator and the model per sample, not timed). One
//! thread. `cargo test` runs every
//! benchmark once (divan's test mode): the CI smoke run. Figures in
//! docs/performance.md; `--bench rhs` has the same evaluations with the
//! factorization's two-thread comparison.

use rolldyn::dynamics::BearingModel;
use rolldyn::integrate::jacobian::{JacobianWork, finite_difference};
use rolldyn::integrate::linear::{BlockJacobian, BlockLu};
use rolldyn::integrate::{Integrator, OdeSystem, Solver};
use rolldyn::testing::{self, Method};
use std::sync::OnceLock;

fn main() {
    rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build_global()
        .expect("one thread");
    divan::main();
}

/// The two bearings.
const BEARINGS: [&str; 2] = ["6304", "7008C"];
/// Time of the benchmarked state \[s\].
const AT: f64 = 5e-3;

/// A model, its state 5 ms into a run and f there.
struct Point {
    model: BearingModel,
    y: Vec<f64>,
    dy: Vec<f64>,
}

fn model(bearing: &str) -> (BearingModel, Vec<f64>) {
    if bearing == "6304" {
        testing::model_6304()
    } else {
        testing::model_7008c()
    }
}

/// The bearing's model 5 ms into its run (ROS34PW2, rtol 1e-3), computed
/// once per process.
fn point(bearing: &str) -> &'static Point {
    static POINTS: [OnceLock<Point>; 2] = [OnceLock::new(), OnceLock::new()];
    let k = BEARINGS.iter().position(|b| *b == bearing).expect("known");
    POINTS[k].get_or_init(|| {
        let (mut model, y0) = model(bearing);
        let mut solver = testing::integrator(Method::Ros34pw2, &model, &y0, 1e-3, 1e-4);
        while solver.t() < AT {
            solver.step(&mut model, AT).expect("step");
        }
        let y = solver.y().to_vec();
        let mut dy = vec![0.0; y.len()];
        model.rhs(AT, &y, &mut dy);
        Point { model, y, dy }
    })
}

#[divan::bench(args = BEARINGS)]
fn right_hand_side(bencher: divan::Bencher, bearing: &str) {
    let p = point(bearing);
    let mut dy = vec![0.0; p.y.len()];
    bencher.bench_local(|| p.model.rhs(AT, &p.y, &mut dy));
}

#[divan::bench(args = BEARINGS)]
fn end_point_shared(bencher: divan::Bencher, bearing: &str) {
    let p = point(bearing);
    let mut model = p.model.clone();
    let mut dy = vec![0.0; p.y.len()];
    bencher.bench_local(|| {
        let balance = model.rhs_at_end(AT, &p.y, &mut dy, true);
        (balance.map(|b| b.mechanical), model.accept_step(AT, &p.y))
    });
}

#[divan::bench(args = BEARINGS, sample_count = 20)]
fn jacobian(bencher: divan::Bencher, bearing: &str) {
    let p = point(bearing);
    let layout = p.model.blocks().expect("blocks").block_layout();
    let mut jacobian = BlockJacobian::zeros(layout);
    let mut work = JacobianWork::new(&p.model);
    bencher.bench_local(|| finite_difference(&p.model, AT, &p.y, &p.dy, &mut jacobian, &mut work));
}

/// The iteration matrix σI − J of a 30 µs ROS34PW2 step, factored as the
/// engine factors it (positions eliminated).
fn factored(p: &Point) -> (BlockJacobian, BlockLu, f64) {
    let split = p.model.blocks().expect("blocks");
    let layout = split.block_layout();
    let mut jacobian = BlockJacobian::zeros(layout);
    let mut work = JacobianWork::new(&p.model);
    finite_difference(&p.model, AT, &p.y, &p.dy, &mut jacobian, &mut work);
    let sigma = 1.0 / (30e-6 * rolldyn::integrate::ROS34PW2.gamma);
    let mut lu = BlockLu::with_structure(
        layout,
        |state| split.inert(state),
        |state| split.rate_of(state),
    );
    lu.factor(&jacobian, sigma).expect("regular");
    (jacobian, lu, sigma)
}

#[divan::bench(args = BEARINGS)]
fn factorization(bencher: divan::Bencher, bearing: &str) {
    let (jacobian, mut lu, sigma) = factored(point(bearing));
    bencher.bench_local(|| lu.refactor(&jacobian, sigma).is_ok());
}

#[divan::bench(args = BEARINGS)]
fn solve(bencher: divan::Bencher, bearing: &str) {
    let p = point(bearing);
    let (_, mut lu, _) = factored(p);
    let mut x = p.dy.clone();
    bencher.bench_local(|| {
        x.copy_from_slice(&p.dy);
        lu.solve(&mut x);
    });
}

/// Ten accepted steps of a run in progress by `method`: the integrator
/// started at the 5 ms state and warmed by 20 steps (its step size and, for
/// ROS34PW2, its Jacobian's age as in a run), copied with the model for
/// each sample.
fn ten_steps(bencher: divan::Bencher, bearing: &str, method: Method) {
    let p = point(bearing);
    let mut model = p.model.clone();
    let mut solver = testing::integrator(method, &model, &p.y, 1e-3, 1e-4);
    for _ in 0..20 {
        solver.step(&mut model, AT + 1.0).expect("step");
    }
    bencher
        .with_inputs(|| (solver.clone(), model.clone()))
        .bench_local_values(|(mut solver, mut model): (Solver, BearingModel)| {
            for _ in 0..10 {
                solver.step(&mut model, AT + 1.0).expect("step");
            }
            solver.t()
        });
}

#[divan::bench(args = BEARINGS, sample_count = 20)]
fn ten_steps_ros34pw2(bencher: divan::Bencher, bearing: &str) {
    ten_steps(bencher, bearing, Method::Ros34pw2);
}

#[divan::bench(args = BEARINGS, sample_count = 20)]
fn ten_steps_dopri5(bencher: divan::Bencher, bearing: &str) {
    ten_steps(bencher, bearing, Method::Dopri5);
}
