//! The error of the exact-theory traction table and of FASTSIM against
//! Kalker's exact theory on ball-bearing contacts (docs/validation.md, C8):
//!
//! ```text
//! cargo run --release -p rolldyn --example exact_table_error [-- SAMPLES [CELLS]]
//! ```
//!
//! Random contacts of a 7218B-sized raceway (b = 2.26 mm across the
//! rolling direction, a/b from 0.10 to 0.22, 500–2500 N, groove-curved
//! with deformed radius 11 mm, steel, μ = 0.1, V = 10 m/s) with creepages
//! a ball bearing runs at: |ξ| ≤ 4e-3, |η| ≤ 1e-3, spin φ ≤ 50 1/m and
//! Heathcote slip up to 2 % of V at the contact's edge. The reference is
//! the exact solver on CELLS × CELLS (default 32) and half that,
//! extrapolated to zero cell size as the table's nodes are. Errors are
//! the larger of |ΔF|/(μQ) and |ΔM_n|/(μQ b).

use nalgebra::Vector3;
use rolldyn::traction::exact::ExactRolling;
use rolldyn::traction::{
    ContactConditions, ContactKinematics, ContactPatch, ExactTable, Fastsim, TractionResult,
};

fn main() -> Result<(), String> {
    let mut args = std::env::args().skip(1);
    let samples: usize = args.next().map_or(Ok(60), |s| {
        s.parse().map_err(|e| format!("samples {s}: {e}"))
    })?;
    let cells: usize = args
        .next()
        .map_or(Ok(32), |s| s.parse().map_err(|e| format!("cells {s}: {e}")))?;
    let (mu, nu, shear) = (0.1, 0.28, 76.923e9);
    let (b, radius, speed) = (2.26e-3, 11e-3, 10.0);
    let table = ExactTable::new(mu, shear, nu);
    let fastsim = Fastsim::new(mu, shear, nu);
    let exact = |n: usize| ExactRolling {
        cells_along: n,
        cells_across: n,
        ..ExactRolling::new(mu, shear, nu)
    };
    let (fine, coarse) = (exact(cells), exact(cells / 2));
    let mut state = 5u64;
    let mut uniform = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let rolling = ContactConditions {
        film: 0.0,
        entrainment_speed: speed,
        rolling_velocity: speed,
    };
    let mut errors = [Vec::new(), Vec::new()];
    for _ in 0..samples {
        let patch = ContactPatch {
            point: Vector3::zeros(),
            normal: Vector3::z(),
            rolling_direction: Vector3::x(),
            semi_major: b,
            semi_minor: (0.1 + 0.12 * uniform()) * b,
            load: 500.0 + 2000.0 * uniform(),
            deformed_radius: radius,
        };
        let xi = 4e-3 * (2.0 * uniform() - 1.0);
        let eta = 1e-3 * (2.0 * uniform() - 1.0);
        let phi = 50.0 * uniform();
        let edge_slip = 0.02 * uniform();
        // Heathcote: slip d(b) Ω·ŷ = edge_slip V at the edge, d ≈ b²/(2R_d).
        let roll = edge_slip * speed * 2.0 * radius / (b * b);
        let slip = speed * Vector3::new(xi, eta, 0.0);
        let spin = Vector3::new(0.0, roll, speed * phi);
        let centre = Vector3::zeros();
        let solve = |m: &ExactRolling| m.solve(&patch, &slip, &spin, speed).result;
        let (f, c) = (solve(&fine), solve(&coarse));
        let force = 2.0 * f.force - c.force;
        let moment = 2.0 * f.couple.z - c.couple.z;
        let mu_q = mu * patch.load;
        let error = |r: &TractionResult| {
            ((r.force - force).norm() / mu_q).max((r.couple.z - moment).abs() / (mu_q * b))
        };
        errors[0].push(error(&table.evaluate(&ContactKinematics {
            patch,
            ball_centre: centre,
            slip,
            relative_spin: spin,
            conditions: rolling,
        })));
        errors[1].push(error(&fastsim.evaluate(&ContactKinematics {
            patch,
            ball_centre: centre,
            slip,
            relative_spin: spin,
            conditions: rolling,
        })));
    }
    println!(
        "{samples} bearing contacts against the exact theory ({cells} and {} cells, extrapolated)",
        cells / 2
    );
    println!("{:<22} {:>8} {:>8} {:>8}", "", "mean", "90 %", "worst");
    for (name, e) in ["exact-theory table", "FASTSIM 16 × 10"]
        .iter()
        .zip(&mut errors)
    {
        e.sort_by(f64::total_cmp);
        let mean = e.iter().sum::<f64>() / e.len() as f64;
        let p90 = e[(0.9 * (e.len() - 1) as f64).round() as usize];
        println!("{name:<22} {mean:>8.4} {p90:>8.4} {:>8.4}", e[e.len() - 1]);
    }
    Ok(())
}
