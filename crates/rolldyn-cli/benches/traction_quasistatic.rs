//! `cargo bench -p rolldyn-cli --bench traction_quasistatic`: the
//! traction-consistent quasi-static solve (no raceway control) of the
//! 7218B preset (16 balls, FASTSIM μ = 0.1, F_x 10 kN, and with F_z 5 kN) from its
//! Jones–Harris solution, on one core; median of 7 solves.
//! Target: ≤ 5 ms. Figures in docs/performance.md.

use rolldyn::dynamics::{TractionSolveOptions, solve_traction_consistent};
use rolldyn::operating::{LoadProfile, Loads, SpeedProfile};
use rolldyn::quasistatic::{Conditions, QuasiStaticSolver, SolverOptions};
use rolldyn_case::{load_case, presets, simulation};
use std::time::Instant;

fn main() {
    let preset = presets::find("7218B").expect("7218B preset");
    let case = load_case("7218B", preset.text, &[]).expect("preset loads");
    let g = &case.bearing.geometry;
    let (ball, rings) = (
        &case.materials.ball.material,
        &case.materials.rings.material,
    );
    let qs = QuasiStaticSolver::new(g, ball, rings, case.contact_stiffness).expect("tables");
    for (rpm, radial) in [(1000.0, 0.0), (10_000.0, 0.0), (10_000.0, 5e3)] {
        let speed = rpm * std::f64::consts::TAU / 60.0;
        let mut params = case.dynamics_parameters().expect("dynamic case");
        params.speed = SpeedProfile::Constant(speed);
        params.loads = LoadProfile::Constant(Loads {
            force: [10e3, 0.0, radial],
            moment: [0.0; 2],
        });
        let model = simulation::model(&case, params.clone()).expect("model");
        let eq = qs
            .solve(
                &Conditions {
                    loads: params.loads.at(0.0),
                    inner_speed: speed,
                    control: case.raceway_control,
                },
                &SolverOptions::default(),
            )
            .expect("Jones–Harris");
        let start = model.state_from_equilibrium(&eq);
        let mut times: Vec<(f64, usize, usize)> = (0..7)
            .map(|_| {
                let t = Instant::now();
                let s = solve_traction_consistent(
                    &model,
                    &start,
                    0.0,
                    &TractionSolveOptions::default(),
                )
                .expect("converges");
                (
                    t.elapsed().as_secs_f64(),
                    s.ring_iterations,
                    s.ball_iterations,
                )
            })
            .collect();
        times.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (t, ring, balls) = times[3];
        println!(
            "7218B traction-consistent, {rpm:>6.0} rpm, F_x 10 kN, F_z {:.0} kN: {:>8.2} ms ({ring} ring, {balls} ball Newton iterations)",
            radial * 1e-3,
            t * 1e3
        );
    }
}
