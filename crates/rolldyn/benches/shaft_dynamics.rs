//! `cargo bench -p rolldyn --bench shaft_dynamics`: the wall time per
//! simulated second of a 7008C back-to-back pair on a rigid shaft (200 N
//! preload, 10 000 rpm, each bearing with the default case's EHL grid
//! traction, whirling cage) against one 7008C under its preload's thrust,
//! both by ROS34PW2 at rtol 1e-3 from their quasi-static states, in the
//! same run, alternating (target: the pair ≤ 2.2 × the single bearing).
//! Figures in docs/performance.md.

use rolldyn::contact::HertzModel;
use rolldyn::dynamics::shaft::{ShaftBody, ShaftDynamics};
use rolldyn::dynamics::{BearingModel, DragParameters};
use rolldyn::integrate::{Integrator, OdeSystem, ROS34PW2, Rosenbrock};
use rolldyn::material::Material;
use rolldyn::operating::{LoadProfile, Loads};
use rolldyn::quasistatic::system::{SetKind, ShaftSystem, SystemConditions};
use rolldyn::quasistatic::{Conditions, QuasiStaticSolver, RacewayControl, SolverOptions};
use std::time::Instant;

/// Wall time and steps of `duration` simulated seconds of `system` from `y0`.
fn timed<S: OdeSystem>(system: &mut S, y0: &[f64], duration: f64) -> (f64, u64) {
    let mut rk = Rosenbrock::builder(&ROS34PW2)
        .relative_tolerance(1e-3)
        .max_step(1e-4)
        .build(system, y0)
        .expect("start");
    let start = Instant::now();
    while rk.t() < duration {
        rk.step(system, duration).expect("step");
    }
    (start.elapsed().as_secs_f64(), rk.stats().steps)
}

fn main() {
    let g = rolldyn::testing::bearing_7008c();
    let steel = Material::STEEL_52100;
    let (params, _) = rolldyn::testing::dynamics_7008c(DragParameters::default());
    let speed = params.speed.speed_at(0.0);
    let qs = QuasiStaticSolver::new(&g, &steel, &steel, HertzModel::Exact).expect("tables");
    let options = SolverOptions::default();
    let set = ShaftSystem::matched(&qs, SetKind::BackToBack, 15e-3);
    let offset = set
        .offset_for_preload(200.0, 0.0, RacewayControl::Outer, &options)
        .expect("preload");
    let set = set.with_axial_offset(offset);
    let eq = set
        .solve(
            &SystemConditions {
                loads: Loads::default(),
                inner_speed: speed,
                control: RacewayControl::Outer,
            },
            &options,
        )
        .expect("set");
    let model =
        BearingModel::new(&g, &steel, &steel, HertzModel::Exact, params.clone()).expect("model");
    let mut pair = ShaftDynamics::new(
        set.bearings.iter().map(|m| (model.clone(), m)).collect(),
        ShaftBody {
            mass: 1.0,
            tilt_inertia: 2e-3,
        },
        Loads::default(),
    )
    .expect("pair");
    let y_pair = pair.initial_state(&eq).expect("start");
    // One bearing under the pair's preload at speed as a thrust.
    let thrust = eq.bearings[0].as_ref().expect("loaded").reaction[0];
    let loads = Loads {
        force: [thrust, 0.0, 0.0],
        moment: [0.0; 2],
    };
    let single_eq = qs
        .solve(
            &Conditions {
                loads,
                inner_speed: speed,
                control: RacewayControl::Outer,
            },
            &options,
        )
        .expect("single");
    let mut single = BearingModel::new(
        &g,
        &steel,
        &steel,
        HertzModel::Exact,
        rolldyn::dynamics::DynamicsParameters {
            loads: LoadProfile::Constant(loads),
            ..params
        },
    )
    .expect("model");
    let y_single = single.state_from_equilibrium(&single_eq);
    let duration = 0.02;
    let mut ratios = Vec::new();
    for round in 0..3 {
        let (ts, ss) = timed(&mut single, &y_single, duration);
        let (tp, sp) = timed(&mut pair, &y_pair, duration);
        ratios.push(tp / ts);
        println!(
            "round {round}: {duration} s simulated: single 7008C {ts:.3} s ({ss} steps), back-to-back pair {tp:.3} s ({sp} steps): {:.2} x",
            tp / ts
        );
    }
    ratios.sort_by(f64::total_cmp);
    println!("median pair / single: {:.2} (target <= 2.2)", ratios[1]);
}
