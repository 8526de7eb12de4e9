//! `cargo bench -p rolldyn --bench contact`: cost of the contact building
//! blocks the time loop calls (7008C, steel): Hertz tables, torus
//! geometry, and one contact's traction (FASTSIM; Kalker's exact theory
//! tabulated; the Coulomb and EHL stress laws on the graded 12 × 6 grid, and
//! EHL on the uniform one). Plain `Instant` timing
//! of many repetitions (median of 7 runs), no extra dependency. Figures are
//! recorded in docs/performance.md with the machine.

use nalgebra::Vector3;
use rolldyn::RingKind;
use rolldyn::contact::table::{ContactTable, RacewayContactModel};
use rolldyn::contact::{GrooveCircle, HertzModel, RingPose};
use rolldyn::material::{Material, effective_modulus};
use rolldyn::traction::fastsim::combined_elastic_constants;
use rolldyn::traction::{
    ContactConditions, ContactKinematics, ContactPatch, EhlRheology, ExactTable, Fastsim,
    ModifiedCoulomb, TractionGrid, TractionIntegration, TractionModel,
};
use std::hint::black_box;
use std::time::Instant;

fn time_per_call(name: &str, calls: usize, mut f: impl FnMut(usize) -> f64) {
    let mut runs: Vec<f64> = (0..7)
        .map(|_| {
            let start = Instant::now();
            let mut acc = 0.0;
            for i in 0..calls {
                acc += f(i);
            }
            black_box(acc);
            start.elapsed().as_secs_f64() / calls as f64
        })
        .collect();
    runs.sort_by(f64::total_cmp);
    println!("{name:<44} {:>10.1} ns/call", runs[3] * 1e9);
}

fn main() {
    let g = rolldyn::testing::bearing_7008c();
    let steel = Material::STEEL_52100;
    let model = RacewayContactModel::new(
        &g,
        RingKind::Inner,
        effective_modulus(&steel, &steel),
        HertzModel::Exact,
    );
    let angle = |i: usize| 0.2 + 1e-4 * (i % 1000) as f64;

    let start = Instant::now();
    let table = ContactTable::new(model).expect("table builds");
    println!(
        "{:<44} {:>10.3} ms",
        "table build (1801 nodes, exact solve)",
        start.elapsed().as_secs_f64() * 1e3
    );

    time_per_call("exact Hertz constants (ellipticity solve)", 20_000, |i| {
        model.coefficients(angle(i)).map_or(0.0, |c| c.stiffness)
    });
    time_per_call("table lookup, all constants", 2_000_000, |i| {
        table.at(angle(i)).stiffness
    });
    time_per_call("table lookup, K_c only", 2_000_000, |i| {
        table.stiffness(angle(i))
    });
    let circle = GrooveCircle::of(&g.inner, &RingPose::default());
    time_per_call("exact torus contact", 2_000_000, |i| {
        let phi = 1e-3 * i as f64;
        let q = Vector3::new(1e-6, 27e-3 * phi.cos(), 27e-3 * phi.sin());
        circle
            .contact(&q, g.ball_diameter, 0.0)
            .map_or(0.0, |c| c.penetration)
    });

    // Traction of one contact: a 7008C inner contact at 25 N (b 0.12 mm,
    // a 0.62 mm), 10 m/s rolling, partial slip with creep and spin.
    let patch = ContactPatch {
        point: Vector3::new(0.0, 0.0, -3.175e-3),
        normal: Vector3::new(0.0, 0.0, -1.0),
        rolling_direction: Vector3::new(0.0, 1.0, 0.0),
        semi_major: 0.62e-3,
        semi_minor: 0.12e-3,
        load: 25.0,
        deformed_radius: 3.3e-3,
    };
    let conditions = ContactConditions {
        film: 0.0,
        entrainment_speed: 10.0,
        rolling_velocity: 10.0,
    };
    let (shear, nu) = combined_elastic_constants(&steel, &steel);
    let slip = |i: usize| Vector3::new(1e-3 * (i % 7) as f64, 2e-3, 0.0);
    let spin = |i: usize| Vector3::new(0.0, 3000.0, -20.0 - (i % 5) as f64);
    // Contact i of the sweep in `conditions`.
    let at = |i: usize, conditions: ContactConditions| ContactKinematics {
        patch,
        ball_centre: Vector3::zeros(),
        slip: slip(i),
        relative_spin: spin(i),
        conditions,
    };
    let fastsim = Fastsim::new(0.1, shear, nu);
    for (strips, elements) in [(16, 10), (20, 12), (8, 6), (32, 20)] {
        let m = Fastsim {
            strips,
            elements,
            ..fastsim
        };
        time_per_call(
            &format!("FASTSIM contact, {strips} × {elements}"),
            200_000,
            |i| m.evaluate(&at(i, conditions)).force.x,
        );
    }
    // Kalker's exact theory tabulated, on the same contacts.
    let table = ExactTable::new(0.1, shear, nu);
    time_per_call("exact-theory table contact", 2_000_000, |i| {
        table.evaluate(&at(i, conditions)).force.x
    });
    let coulomb = TractionModel::ModifiedCoulomb(ModifiedCoulomb {
        friction: 0.1,
        stick_speed: 0.0,
        full_speed: 1e-3,
    });
    let grid = TractionGrid::new(TractionIntegration::default());
    let uniform = TractionGrid::new(TractionIntegration::Grid {
        across: 12,
        along: 6,
    });
    time_per_call(
        "Coulomb stress law on the graded 12 × 6 grid",
        200_000,
        |i| coulomb.evaluate(&grid, &at(i, conditions)).force.x,
    );
    // The default case's EHL rheology on the same contact with a 0.2 µm
    // film (Eyring 5 MPa, limiting shear 0.08, η₀ 0.0467 Pa·s, α 2.2e-8 1/Pa).
    let ehl = TractionModel::Ehl(EhlRheology {
        eyring_stress: 5e6,
        limiting_shear_coefficient: 0.08,
        lubricant: rolldyn::lubrication::Lubricant {
            viscosity: 0.0467,
            pressure_viscosity: 2.2e-8,
            pressure_model: Default::default(),
        },
    });
    let film = ContactConditions {
        film: 0.2e-6,
        ..conditions
    };
    for (name, grid) in [("graded", &grid), ("uniform", &uniform)] {
        time_per_call(
            &format!("EHL stress law on the {name} 12 × 6 grid"),
            200_000,
            |i| ehl.evaluate(grid, &at(i, film)).force.x,
        );
    }
}
