//! `cargo bench -p rolldyn --bench quasistatic`: one Jones–Harris solve of
//! the 7218B (16 balls) from the built-in start, and warm-started solves,
//! on one core, and the films and natural modes of each solution.
//! Target: ≤ 1 ms per solve; with film outputs still ≤ 1 ms. Then a
//! 7008C back-to-back pair (200 N preload at rest): its solve cold and from
//! a neighbouring point, against one bearing's solve in the same run
//! (target: ≤ 2 ms per pair solve), and its lift-off load.
//! Figures in docs/performance.md.

use rolldyn::contact::HertzModel;
use rolldyn::lubrication::{Lubricant, Supply};
use rolldyn::material::Material;
use rolldyn::operating::Loads;
use rolldyn::quasistatic::films::{FilmInputs, equilibrium_films};
use rolldyn::quasistatic::modes::natural_modes;
use rolldyn::quasistatic::system::{SetKind, ShaftSystem, SystemConditions};
use rolldyn::quasistatic::{Conditions, QuasiStaticSolver, RacewayControl, SolverOptions, sweep};
use std::hint::black_box;
use std::time::Instant;

fn median_time(runs: usize, mut f: impl FnMut()) -> f64 {
    let mut t: Vec<f64> = (0..runs)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[runs / 2]
}

fn main() {
    let g = rolldyn::testing::bearing_7218b();
    let steel = Material {
        elastic_modulus: 206e9,
        poisson_ratio: 0.3,
        density: 7800.0,
    };
    let solver = QuasiStaticSolver::new(&g, &steel, &steel, HertzModel::Exact).expect("tables");
    let options = SolverOptions::default();
    let rpm = std::f64::consts::TAU / 60.0;
    for (name, loads, speed) in [
        (
            "7218B static, F_x 10 kN",
            Loads {
                force: [10e3, 0.0, 0.0],
                moment: [0.0; 2],
            },
            0.0,
        ),
        (
            "7218B J-H 10 000 rpm, F_x 10 kN",
            Loads {
                force: [10e3, 0.0, 0.0],
                moment: [0.0; 2],
            },
            10_000.0 * rpm,
        ),
        (
            "7218B J-H 10 000 rpm, F_x 10 kN, F_z 5 kN",
            Loads {
                force: [10e3, 0.0, 5e3],
                moment: [0.0; 2],
            },
            10_000.0 * rpm,
        ),
        (
            "7218B J-H 14 000 rpm, F_x 40 kN, F_z 20 kN",
            Loads {
                force: [40e3, 0.0, 20e3],
                moment: [0.0; 2],
            },
            14_000.0 * rpm,
        ),
    ] {
        let conditions = Conditions {
            loads,
            inner_speed: speed,
            control: RacewayControl::Outer,
        };
        let sol = solver.solve(&conditions, &options).expect("converges");
        let cold = median_time(21, || {
            black_box(solver.solve(&conditions, &options).ok());
        });
        let mut nearby = conditions;
        nearby.loads.force[0] *= 1.01;
        let warm = median_time(21, || {
            black_box(solver.solve_from(&sol, &nearby, &options).ok());
        });
        // Films of the solution (quasi-static with film outputs).
        let inputs = FilmInputs {
            lubricant: Lubricant {
                viscosity: 0.0275,
                pressure_viscosity: 2e-8,
                pressure_model: Default::default(),
            },
            supply: [Supply::InletDistance(1.3), Supply::Flooded],
            roughness: [0.1e-6, 0.1e-6],
            effective_modulus: rolldyn::material::effective_modulus(&steel, &steel),
        };
        let films = median_time(21, || {
            black_box(equilibrium_films(&g, &sol, &inputs));
        });
        let modes = median_time(21, || {
            black_box(natural_modes(&sol.stiffness, 5.0, 2e-3));
        });
        // The film in the normal approach (dry solve, continuation, re-solves).
        let approach = if speed > 0.0 {
            let t = median_time(5, || {
                black_box(solver.solve_with_films(&conditions, &options, &inputs).ok());
            });
            format!("   film in approach {:>8.3} ms", t * 1e3)
        } else {
            String::new()
        };
        println!(
            "{name:<46} cold {:>8.3} ms ({} it)   warm (+1 % load) {:>8.3} ms   films {:>6.1} µs   modes {:>5.1} µs{approach}",
            cold * 1e3,
            sol.iterations,
            warm * 1e3,
            films * 1e6,
            modes * 1e6
        );
    }

    // 1000-point sweep: 25 speeds (0–20 000 rpm) × 40 axial loads (10 N–50 kN, log).
    let points: Vec<Conditions> = (0..25)
        .flat_map(|i| {
            (0..40).map(move |k| Conditions {
                loads: Loads {
                    force: [10.0 * 5000f64.powf(k as f64 / 39.0), 0.0, 0.0],
                    moment: [0.0; 2],
                },
                inner_speed: 20_000.0 * rpm * i as f64 / 24.0,
                control: RacewayControl::Outer,
            })
        })
        .collect();
    for (label, parallel) in [("serial", false), ("parallel (all cores)", true)] {
        let start = Instant::now();
        let results = sweep(&solver, &points, &options, parallel);
        let elapsed = start.elapsed().as_secs_f64();
        let ok = results.iter().filter(|r| r.is_ok()).count();
        println!(
            "7218B 1000-point speed × load sweep, {label:<21} {:>8.3} s ({ok}/1000 converged)",
            elapsed
        );
    }

    pair();
}

/// The 7008C back-to-back pair at 15 000 rpm under F_x 300 N, F_z 200 N.
fn pair() {
    let g = rolldyn::testing::bearing_7008c();
    let steel = Material {
        elastic_modulus: 208e9,
        poisson_ratio: 0.3,
        density: 7830.0,
    };
    let solver = QuasiStaticSolver::new(&g, &steel, &steel, HertzModel::Exact).expect("tables");
    let options = SolverOptions::default();
    let rpm = std::f64::consts::TAU / 60.0;
    let set = ShaftSystem::matched(&solver, SetKind::BackToBack, 15e-3);
    let offset = set
        .offset_for_preload(200.0, 0.0, RacewayControl::Outer, &options)
        .expect("preload");
    let set = set.with_axial_offset(offset);
    let loads = Loads {
        force: [300.0, 0.0, 200.0],
        moment: [0.0; 2],
    };
    let conditions = SystemConditions {
        loads,
        inner_speed: 15_000.0 * rpm,
        control: RacewayControl::Outer,
    };
    let eq = set.solve(&conditions, &options).expect("pair converges");
    let cold = median_time(11, || {
        black_box(set.solve(&conditions, &options).ok());
    });
    let mut nearby = conditions;
    nearby.loads.force[0] += 5.0;
    let warm = median_time(11, || {
        black_box(set.solve_near(&eq, &nearby, &options).ok());
    });
    let single_conditions = Conditions {
        loads,
        inner_speed: conditions.inner_speed,
        control: RacewayControl::Outer,
    };
    let single = median_time(11, || {
        black_box(solver.solve(&single_conditions, &options).ok());
    });
    let lift_off = median_time(5, || {
        black_box(set.lift_off_load(0.0, RacewayControl::Outer, &options).ok());
    });
    println!(
        "7008C pair 15 000 rpm, F_x 300 N, F_z 200 N: cold {:>7.3} ms ({} shaft it), warm (+5 N) {:>7.3} ms, one bearing's cold solve {:>7.3} ms (ratio {:.1}); lift-off load {:>7.3} ms",
        cold * 1e3,
        eq.iterations,
        warm * 1e3,
        single * 1e3,
        cold / single,
        lift_off * 1e3
    );
}
