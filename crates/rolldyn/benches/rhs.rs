//! `cargo bench -p rolldyn --bench rhs`: what one evaluation of the dynamic
//! model costs, whatever number of steps a run takes (the 6304's step
//! count moves by several per cent with round-off: its ball impacts are
//! chaotic). Per call, on one thread: the right-hand side, the mechanical
//! energy (the energy control evaluates it twice per step), the step
//! acceptance's contact bookkeeping, the three at a step's end apart and
//! from one shared pass (`OdeSystem::rhs_at_end`), the
//! finite-difference Jacobian and,
//! where the model has one, its fast part's (refreshed at every step while
//! the cage limits the steps), the factorization of σI − J (also on two
//! threads) and a solve with it, for the 6304 of Shan et al. 2023 (planar, dry, traction at the contact
//! centre, pockets) and the default case's 7008C (EHL traction on the
//! 12 × 6 grid, whirling outer-guided cage), each 5 ms into a run from its
//! start. Figures in docs/performance.md.

use rolldyn::dynamics::BearingModel;
use rolldyn::integrate::jacobian::{JacobianWork, fast_part_difference, finite_difference};
use rolldyn::integrate::linear::{BlockJacobian, BlockLu};
use rolldyn::integrate::{Integrator, OdeSystem};
use rolldyn::testing::{self, Method};
use std::hint::black_box;
use std::time::Instant;

/// Median over 7 rounds of the time per call of `f` \[µs\].
fn time_per_call(name: &str, calls: usize, mut f: impl FnMut() -> f64) {
    let mut rounds: Vec<f64> = (0..7)
        .map(|_| {
            let start = Instant::now();
            let mut sink = 0.0;
            for _ in 0..calls {
                sink += f();
            }
            black_box(sink);
            start.elapsed().as_secs_f64() / calls as f64
        })
        .collect();
    rounds.sort_by(f64::total_cmp);
    println!("{name:<48} {:>9.2} µs/call", rounds[3] * 1e6);
}

/// `model` advanced 5 ms from `y0` (ROS34PW2, rtol 1e-3).
fn state_after_5_ms(model: &mut BearingModel, y0: &[f64]) -> Vec<f64> {
    let mut solver = testing::integrator(Method::Ros34pw2, model, y0, 1e-3, 1e-4);
    while solver.t() < 5e-3 {
        solver.step(model, 5e-3).expect("step");
    }
    solver.y().to_vec()
}

fn bench(name: &str, mut model: BearingModel, y0: &[f64], calls: usize) {
    let y = state_after_5_ms(&mut model, y0);
    let t = 5e-3;
    let mut dy = vec![0.0; y.len()];
    time_per_call(&format!("{name}: right-hand side"), calls, || {
        model.rhs(t, &y, &mut dy);
        dy[0]
    });
    time_per_call(&format!("{name}: mechanical energy"), calls, || {
        model.energy(t, &y).total()
    });
    time_per_call(&format!("{name}: step acceptance"), calls, || {
        f64::from(u8::from(model.accept_step(t, &y)))
    });
    // What an accepted step evaluates at its end: the right-hand side, the
    // energy and the acceptance apart, and from the shared pass.
    time_per_call(&format!("{name}: end point apart"), calls, || {
        model.rhs(t, &y, &mut dy);
        let energy = model.energy(t, &y).total();
        model.accept_step(t, &y);
        energy
    });
    time_per_call(&format!("{name}: end point shared"), calls, || {
        let balance = model.rhs_at_end(t, &y, &mut dy, true);
        model.accept_step(t, &y);
        balance.map_or(0.0, |b| b.mechanical)
    });
    model.rhs(t, &y, &mut dy);
    let layout = model.blocks().expect("blocks").block_layout();
    let mut jacobian = BlockJacobian::zeros(layout);
    let mut work = JacobianWork::new(&model);
    time_per_call(&format!("{name}: Jacobian"), calls / 20, || {
        finite_difference(&model, t, &y, &dy, &mut jacobian, &mut work) as f64
    });
    finite_difference(&model, t, &y, &dy, &mut jacobian, &mut work);
    // σ = 1/(hγ) of a 30 µs ROS34PW2 step.
    let sigma = 1.0 / (30e-6 * 0.435_866_521_508_459);
    let split = model.blocks().expect("blocks");
    // The engine's factorization (positions eliminated) and, as the
    // reference in the same run, the one that keeps them.
    let mut kept = BlockLu::with_inert(layout, |state| split.inert(state));
    kept.factor(&jacobian, sigma).expect("regular");
    let mut lu = BlockLu::with_structure(
        layout,
        |state| split.inert(state),
        |state| split.rate_of(state),
    );
    lu.factor(&jacobian, sigma).expect("regular");
    let mut x = dy.clone();
    for (label, lu) in [("", &mut lu), (", positions kept", &mut kept)] {
        time_per_call(&format!("{name}: factorization{label}"), calls / 4, || {
            lu.refactor(&jacobian, sigma).map_or(0.0, |()| 1.0)
        });
        time_per_call(&format!("{name}: solve{label}"), calls, || {
            x.copy_from_slice(&dy);
            lu.solve(&mut x);
            x[0]
        });
    }
    // The factorization with its blocks on one and on two threads, timed
    // alternately from a thread of a two-thread pool with the other
    // waiting actively, as in a run.
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .expect("two threads");
    pool.install(|| {
        let _helpers = rolldyn::threads::ActiveHelpers::start();
        let median = |v: &[f64]| {
            let mut v = v.to_vec();
            v.sort_by(f64::total_cmp);
            v[v.len() / 2]
        };
        let mut rounds = [Vec::new(), Vec::new()];
        for _ in 0..15 {
            for (parallel, times) in [false, true].into_iter().zip(&mut rounds) {
                lu.set_parallel(parallel);
                let start = Instant::now();
                for _ in 0..calls / 20 {
                    black_box(lu.refactor(&jacobian, sigma).is_ok());
                }
                times.push(start.elapsed().as_secs_f64() / (calls / 20) as f64);
            }
        }
        let ratios: Vec<f64> = rounds[1]
            .iter()
            .zip(&rounds[0])
            .map(|(p, s)| p / s)
            .collect();
        println!(
            "{:<48} {:>9.2} µs/call serial, {:.2} µs on 2 threads (ratio {:.2})",
            format!("{name}: factorization in a 2-thread run"),
            median(&rounds[0]) * 1e6,
            median(&rounds[1]) * 1e6,
            median(&ratios)
        );
    });
    if fast_part_difference(&model, t, &y, &mut jacobian, &mut work).is_some() {
        time_per_call(
            &format!("{name}: Jacobian of the fast part"),
            calls / 4,
            || fast_part_difference(&model, t, &y, &mut jacobian, &mut work).unwrap_or(0) as f64,
        );
        // The fast part differences only the balls whose pockets act: at
        // the state above few do, in a whirl about half. The cage turned
        // by 0.1 mm at its pitch radius closes every pocket (the upper
        // bound of a refresh).
        let mut closed = y.clone();
        closed[model.layout().cage() + 2] += 0.1e-3 / model.parameters().cage.pitch_radius;
        time_per_call(
            &format!("{name}: fast part, every pocket closed"),
            calls / 4,
            || {
                fast_part_difference(&model, t, &closed, &mut jacobian, &mut work).unwrap_or(0)
                    as f64
            },
        );
    }
}

fn main() {
    rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build_global()
        .expect("one thread");
    let (model, y0) = testing::model_6304();
    bench("6304", model, &y0, 20_000);
    let (model, y0) = testing::model_7008c();
    bench("7008C default", model, &y0, 2_000);
}
