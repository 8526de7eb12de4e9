use super::layout::{Direction, Layout, Normalisation};
use super::*;
use crate::traction::Fastsim;
use crate::traction::exact::ExactRolling;
use crate::traction::{ContactConditions, ContactPatch};

/// The embedded table's grid.
const LAYOUT: Layout = Layout::EMBEDDED;

/// A deterministic sequence in [0, 1).
fn uniform(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    (*state >> 11) as f64 / (1u64 << 53) as f64
}

#[test]
fn embedded_table_reads_and_round_trips() {
    let t = Table::embedded();
    assert_eq!(t.layout, LAYOUT);
    assert_eq!((t.poisson_ratio, t.cells), (0.28, 32));
    assert_eq!(Table::from_bytes(&t.to_bytes()).as_ref(), Ok(t));
    assert!(Table::from_bytes(b"RDKTAB01").is_err());
    let mut cut = t.to_bytes();
    cut.pop();
    assert!(Table::from_bytes(&cut).is_err());
}

/// Nodes recomputed by the builder equal the stored ones to the
/// quantisation (the table is what its builder makes).
#[test]
fn stored_nodes_are_the_builders() {
    let t = Table::embedded();
    for at in [
        [3, 1, 4, 2, 3],
        [7, 3, 6, 7, 6],
        [2, 8, 2, 5, 10],
        [5, 2, 16, 0, 1],
        [9, 6, 11, 3, 8],
        [0, 0, 0, 0, 0],
    ] {
        let fresh = build::node(&LAYOUT, 0.28, 32, at);
        let [g, a, b, c, u] = at;
        let stored = t.node(LAYOUT.index(g, a, b, c, u));
        for k in 0..OUTPUTS {
            assert!(
                (fresh[k] - stored[k]).abs() <= 0.6 / QUANTUM,
                "node {at:?} output {k}: {} stored, {} fresh",
                stored[k],
                fresh[k]
            );
        }
    }
}

/// Kalker's problem is odd in the creepages and symmetric in y; the table
/// keeps it exactly.
#[test]
fn symmetries_hold_exactly() {
    let t = Table::embedded();
    let star = [0.3, 0.2, -0.5, 0.7];
    let base = t.evaluate(0.15, star);
    let all = t.evaluate(0.15, star.map(|v| -v));
    let y = t.evaluate(0.15, [star[0], -star[1], -star[2], star[3]]);
    for k in 0..5 {
        assert_eq!(all[k], -base[k]);
    }
    assert_eq!(all[5], base[5]);
    assert_eq!((y[0], y[3], y[5]), (base[0], base[3], base[5]));
    assert_eq!((y[1], y[2], y[4]), (-base[1], -base[2], -base[4]));
}

/// A flat 7218B-like contact (b = 2.26 mm) of ratio `g`, steel, 2088 N.
fn patch(g: f64, deformed_radius: f64) -> ContactPatch {
    ContactPatch {
        point: Vector3::zeros(),
        normal: Vector3::z(),
        rolling_direction: Vector3::x(),
        semi_major: 2.2609e-3,
        semi_minor: g * 2.2609e-3,
        load: 2088.0,
        deformed_radius,
    }
}

const SHEAR_MODULUS: f64 = 76.923e9;
const SPEED: f64 = 10.0;

/// Slip at P and relative spin of creepages (ξ, η, φ, χ) at `SPEED` on
/// `patch` (χ needs a finite deformed radius).
fn kinematics(p: &ContactPatch, creep: [f64; 4]) -> (Vector3<f64>, Vector3<f64>) {
    let [xi, eta, phi, chi] = creep;
    let slip = SPEED * Vector3::new(xi, eta, 0.0);
    let roll = if chi == 0.0 {
        0.0
    } else {
        chi * 2.0 * p.deformed_radius * SPEED
    };
    (slip, Vector3::new(0.0, roll, SPEED * phi))
}

fn rolling() -> ContactConditions {
    ContactConditions {
        film: 0.0,
        entrainment_speed: SPEED,
        rolling_velocity: SPEED,
    }
}

/// At small creepage the law is Kalker's linear theory, and at large
/// creepage Coulomb sliding, μQ against the slip.
#[test]
fn linear_theory_and_full_sliding() {
    let law = ExactTable::new(0.1, SHEAR_MODULUS, 0.3);
    for g in [0.1, 0.3, 1.0] {
        let p = patch(g, f64::INFINITY);
        let c = super::super::kalker::creep_coefficients(p.semi_minor, p.semi_major, 0.3);
        let cc2 = p.semi_minor * p.semi_major;
        let at = |creep: [f64; 4]| {
            let (slip, spin) = kinematics(&p, creep);
            law.evaluate(&ContactKinematics {
                patch: p,
                ball_centre: Vector3::zeros(),
                slip,
                relative_spin: spin,
                conditions: rolling(),
            })
        };
        let xi = 1e-7;
        let fx = at([xi, 0.0, 0.0, 0.0]).force.x;
        let linear = -SHEAR_MODULUS * cc2 * c.longitudinal * xi;
        assert!((fx / linear - 1.0).abs() < 0.03, "g {g}: {fx} vs {linear}");
        let fy = at([0.0, xi, 0.0, 0.0]).force.y;
        let linear = -SHEAR_MODULUS * cc2 * c.lateral * xi;
        assert!((fy / linear - 1.0).abs() < 0.03, "g {g}: {fy} vs {linear}");
        let sliding = at([0.0, -0.3, 0.0, 0.0]);
        assert!((sliding.force.y - 0.1 * 2088.0).abs() < 2e-3 * 208.8);
        assert!(sliding.force.x.abs() < 1e-9);
        assert!(sliding.dissipation > 0.0);
    }
}

/// The table against the exact theory it was built from, at creepages
/// (any direction) and ratios between its nodes: the interpolation error,
/// stated in docs/validation.md (C8).
#[test]
fn interpolation_error_is_bounded() {
    let t = Table::embedded();
    let mut state = 7;
    let (mut worst, mut mean): (f64, f64) = (0.0, 0.0);
    let samples = 48;
    for _ in 0..samples {
        let ratio = (Layout::LOG_RATIO_MIN * uniform(&mut state)).exp2();
        let u = 0.05 + 0.9 * uniform(&mut state);
        let unit = [0; 4].map(|_| 2.0 * uniform(&mut state) - 1.0);
        let norm = unit.iter().map(|v| v * v).sum::<f64>().sqrt();
        let r = u / (1.0 - u);
        let star = unit.map(|v| r * v / norm);
        let exact = build::exact_at(ratio, 0.28, 32, star);
        let table = t.evaluate(ratio, star);
        let error = (0..3)
            .map(|k| (table[k] - exact[k]).abs())
            .fold(0.0, f64::max);
        worst = worst.max(error);
        mean += error / samples as f64;
    }
    assert!(
        worst < 0.08 && mean < 0.015,
        "error of μQ: worst {worst}, mean {mean}"
    );
}

/// The law's outputs are the table's, scaled to the contact: forces over
/// μQ, the spin moment over μQ b, and the power −(s·F + Ω·M).
#[test]
fn law_scales_the_table_and_closes_the_power() {
    let law = ExactTable::new(0.1, SHEAR_MODULUS, 0.28);
    let p = patch(0.122, 11e-3);
    let creep = [1e-3, -5e-4, 20.0, 0.02 / (2.2609e-3f64).powi(2)];
    let (slip, spin) = kinematics(&p, creep);
    let out = law.evaluate(&ContactKinematics {
        patch: p,
        ball_centre: Vector3::new(0.0, 0.0, -1e-2),
        slip,
        relative_spin: spin,
        conditions: rolling(),
    });
    let n = Normalisation::new(p.semi_minor, p.semi_major, SHEAR_MODULUS, 0.28, 2088.0, 0.1);
    let b2 = p.semi_major * p.semi_major;
    let mean_depth = b2 / (10.0 * p.deformed_radius);
    // The law's speed includes the regularisation, √(V² + v_r²).
    let v = SPEED.hypot(law.regularisation_speed);
    let star = [
        slip.x / v * n.scale[0],
        (slip.y + mean_depth * spin.x) / v * n.scale[1],
        spin.z / v * n.scale[2],
        spin.y / (2.0 * p.deformed_radius * v) * n.scale[3],
    ];
    let v = Table::embedded().evaluate(0.122, star);
    let mu_q = 208.8;
    assert!((out.force.x - mu_q * v[0]).abs() < 1e-9);
    assert!((out.force.y - mu_q * v[1]).abs() < 1e-9);
    assert!((out.couple.z - mu_q * p.semi_major * v[2]).abs() < 1e-12);
    let power = -(slip.dot(&out.force) + spin.dot(&out.couple));
    assert!((out.dissipation - power).abs() < 1e-9 * power.abs());
    assert!(out.dissipation > 0.0);
    // The moment about the ball centre.
    let arm = p.point - Vector3::new(0.0, 0.0, -1e-2);
    assert!((out.moment - out.couple - arm.cross(&out.force)).norm() < 1e-15);
    let d = Direction::of(star);
    assert!(
        d.magnitude > 0.5,
        "a bearing contact at speed slides: {d:?}"
    );
}

/// Against fresh exact solutions of ball-bearing contacts (a/b 0.10–0.22,
/// groove-curved, creepage, spin and Heathcote slip as a bearing runs at;
/// `examples/exact_table_error.rs` with more of them), the table is closer
/// than FASTSIM on its default grid, on average and at worst.
#[test]
fn closer_to_the_exact_theory_than_fastsim() {
    let (mu, nu) = (0.1, 0.28);
    let table = ExactTable::new(mu, SHEAR_MODULUS, nu);
    let fastsim = Fastsim::new(mu, SHEAR_MODULUS, nu);
    let exact = |cells: usize| ExactRolling {
        cells_along: cells,
        cells_across: cells,
        ..ExactRolling::new(mu, SHEAR_MODULUS, nu)
    };
    let (fine, coarse) = (exact(32), exact(16));
    let radius = 11e-3;
    let mut state = 5;
    let samples = 30;
    let (mut worst, mut mean) = ([0.0f64; 2], [0.0f64; 2]);
    for _ in 0..samples {
        let ratio = 0.1 + 0.12 * uniform(&mut state);
        let p = ContactPatch {
            load: 500.0 + 2000.0 * uniform(&mut state),
            ..patch(ratio, radius)
        };
        let b2 = p.semi_major * p.semi_major;
        let creep = [
            4e-3 * (2.0 * uniform(&mut state) - 1.0),
            1e-3 * (2.0 * uniform(&mut state) - 1.0),
            50.0 * uniform(&mut state),
            0.02 * uniform(&mut state) / b2,
        ];
        let (slip, spin) = kinematics(&p, creep);
        let centre = Vector3::zeros();
        let solve = |m: &ExactRolling| m.solve(&p, &slip, &spin, SPEED).result;
        let (f, c) = (solve(&fine), solve(&coarse));
        let (force, moment) = (2.0 * f.force - c.force, 2.0 * f.couple.z - c.couple.z);
        let mu_q = mu * p.load;
        let laws = [
            table.evaluate(&ContactKinematics {
                patch: p,
                ball_centre: centre,
                slip,
                relative_spin: spin,
                conditions: rolling(),
            }),
            fastsim.evaluate(&ContactKinematics {
                patch: p,
                ball_centre: centre,
                slip,
                relative_spin: spin,
                conditions: rolling(),
            }),
        ];
        for (k, r) in laws.iter().enumerate() {
            let error = ((r.force - force).norm() / mu_q)
                .max((r.couple.z - moment).abs() / (mu_q * p.semi_major));
            worst[k] = worst[k].max(error);
            mean[k] += error / samples as f64;
        }
    }
    assert!(
        worst[0] < worst[1] && mean[0] < 0.5 * mean[1],
        "table worst {} mean {}, FASTSIM worst {} mean {} (of μQ)",
        worst[0],
        mean[0],
        worst[1],
        mean[1]
    );
}
