//! `cargo bench -p rolldyn-cli --bench thermal`: cost of power and thermal
//! (the targets), plain `Instant` timing, median of 7 runs; figures
//! in docs/performance.md.
//!
//! 1. Harris's local power loss of a solved Jones–Harris state (Lei et al. 2023
//!    bearing, 9000 rpm).
//! 2. The bearing network: build + steady solve (target ≤ 1 ms).
//! 3. The coupled quasi-static thermal iteration (target ≤ 50 ms).
//! 4. One RHS of the default case with and without the dissipation split
//!    (`rhs_with_power`, what `run` evaluates once per sample).

// A benchmark stops at the first failure.
#![allow(clippy::unwrap_used)]

use rolldyn::integrate::OdeSystem;
use rolldyn::power::local_power_loss;
use rolldyn::quasistatic::{Conditions, QuasiStaticSolver, SolverOptions};
use rolldyn::thermal::BearingThermal;
use rolldyn::thermal::coupled::{CoupledOptions, CoupledProblem, coupled_steady, heat_sources};
use rolldyn_case::raw::StartChoice;
use rolldyn_case::simulation::Simulation;
use rolldyn_case::{Case, load_case, presets};
use std::hint::black_box;
use std::time::Instant;

fn median(mut runs: Vec<f64>) -> f64 {
    runs.sort_by(f64::total_cmp);
    runs[runs.len() / 2]
}

fn time(repeats: usize, mut f: impl FnMut()) -> f64 {
    median(
        (0..7)
            .map(|_| {
                let start = Instant::now();
                for _ in 0..repeats {
                    f();
                }
                start.elapsed().as_secs_f64() / repeats as f64
            })
            .collect(),
    )
}

fn preset_case(name: &str) -> Case {
    load_case(name, presets::find(name).expect("preset").text, &[]).expect("case")
}

fn main() {
    let case = preset_case("acbb_30x62");
    let g = &case.bearing.geometry;
    let (ball, rings) = (
        &case.materials.ball.material,
        &case.materials.rings.material,
    );
    let solver = QuasiStaticSolver::new(g, ball, rings, case.contact_stiffness).unwrap();
    let conditions = Conditions {
        loads: case.loads,
        inner_speed: 9000.0 * std::f64::consts::TAU / 60.0,
        control: case.raceway_control,
    };
    let eq = solver
        .solve(&conditions, &SolverOptions::default())
        .unwrap();
    let inputs = case.local_method_inputs().unwrap();
    let t = time(1000, || {
        black_box(local_power_loss(g, &eq, &inputs));
    });
    println!("local power loss: {:.2} µs", t * 1e6);
    let power = local_power_loss(g, &eq, &inputs);
    let thermal = case.thermal_inputs().unwrap();
    let heat = heat_sources(g, &eq, &power);
    let t = time(1000, || {
        let net = BearingThermal::new(&thermal, &heat).unwrap();
        black_box(net.steady().unwrap());
    });
    println!("network build + steady solve: {:.2} µs", t * 1e6);
    let problem = CoupledProblem {
        geometry: g,
        ball,
        rings,
        hertz: case.contact_stiffness,
        conditions,
        options: SolverOptions::default(),
        power: inputs.clone(),
        thermal: thermal.clone(),
        viscosity: case.lubricant.as_ref().and_then(|l| l.viscosity_law),
        expansion: case.thermal.expansion,
    };
    let t_new = time(5, || {
        black_box(QuasiStaticSolver::new(g, ball, rings, case.contact_stiffness).unwrap());
    });
    let t_solve = time(5, || {
        black_box(
            solver
                .solve(&conditions, &SolverOptions::default())
                .unwrap(),
        );
    });
    let t_warm = time(5, || {
        black_box(
            solver
                .solve_from(&eq, &conditions, &SolverOptions::default())
                .unwrap(),
        );
    });
    println!(
        "  of which per pass: contact tables {:.2} ms, J–H solve {:.2} ms cold, {:.2} ms warm",
        t_new * 1e3,
        t_solve * 1e3,
        t_warm * 1e3
    );
    let mut passes = 0;
    let t = time(5, || {
        let s = coupled_steady(&problem, &CoupledOptions::default()).unwrap();
        passes = s.history.len();
        black_box(s);
    });
    println!(
        "coupled thermal iteration: {:.2} ms ({passes} passes)",
        t * 1e3
    );

    let default = preset_case("7008C");
    let simulation = Simulation::with_start(&default, StartChoice::JonesHarris).unwrap();
    let (model, y) = (simulation.model, simulation.initial_state);
    let mut dy = vec![0.0; model.dimension()];
    let plain = time(2000, || {
        model.rhs(0.0, &y, &mut dy);
        black_box(&dy);
    });
    let split = time(2000, || {
        black_box(model.rhs_with_power(0.0, &y, &mut dy));
    });
    println!(
        "default-case RHS: {:.2} µs, with the dissipation split {:.2} µs ({:+.1} %)",
        plain * 1e6,
        split * 1e6,
        100.0 * (split / plain - 1.0)
    );
}
