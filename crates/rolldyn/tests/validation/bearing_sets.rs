//! Bearing sets on a rigid shaft (`quasistatic::system`, docs/systems.md),
//! against the textbook thrust curve of one angular-contact bearing at rest
//! (Harris & Kotzalas, *Essential Concepts*, eq. 7.30 form):
//!
//! ```text
//! F_a(α) = Z K_n(α) (BD)^1.5 sin α (cos α₀/cos α − 1)^1.5,   δ_a(α) = BD cos α₀ (tan α − tan α₀)
//! ```
//!
//! with K_n the series stiffness of the two contacts at α. A matched pair
//! with no external load has u = 0, so each bearing sits at δ_a = s, the
//! offset of its preload: F_a(s) = F_p. At lift-off the opposed bearing is
//! back at δ_a = 0, so the loaded one is at 2s and the lift-off load is
//! F_a(2s) (2^{3/2} F_p if the contact angle did not change; it does, and
//! the lift-off ratio of the 7008C at 200 N is printed). Also: the pair's
//! axial stiffness without external load is twice the bearing's at the
//! preload; a tandem pair halves the thrust; tandem triples (TBT, TFT)
//! against the same curve; equilibrium and stiffness
//! under combined load; back-to-back is stiffer against moments than
//! face-to-face.

use super::common::{bearing_7008c, rel, steel_solver, thrust_curve};
use rolldyn::BearingGeometry;
use rolldyn::operating::Loads;
use rolldyn::quasistatic::system::{SetKind, ShaftSystem, SystemConditions};
use rolldyn::quasistatic::{Conditions, RacewayControl, SolverOptions};

const SPACING: f64 = 15e-3;

/// The contact angle at which the textbook curve gives `target` (of δ_a
/// with `pick = 0`, of F_a with `pick = 1`), by bisection.
fn angle_for(g: &BearingGeometry, target: f64, pick: usize) -> f64 {
    let value = |a: f64| {
        let (d, f) = thrust_curve(g, a);
        if pick == 0 { d } else { f }
    };
    let (mut lo, mut hi) = (g.offset_contact_angle, 80f64.to_radians());
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if value(mid) < target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

fn at_rest(loads: Loads) -> SystemConditions {
    SystemConditions {
        loads,
        inner_speed: 0.0,
        control: RacewayControl::Outer,
    }
}

#[test]
fn back_to_back_preload_and_lift_off_follow_the_thrust_curve() {
    let g = bearing_7008c();
    let options = SolverOptions::default();
    for preload in [50.0, 200.0, 1000.0] {
        let set = ShaftSystem::matched(&steel_solver(&g), SetKind::BackToBack, SPACING);
        let offset = set
            .offset_for_preload(preload, 0.0, RacewayControl::Outer, &options)
            .unwrap();
        let (textbook_offset, _) = thrust_curve(&g, angle_for(&g, preload, 1));
        assert!(
            rel(offset, textbook_offset) < 1e-6,
            "{preload} N: offset {offset} vs textbook {textbook_offset}"
        );
        let set = set.with_axial_offset(offset);
        let lift_off = set
            .lift_off_load(0.0, RacewayControl::Outer, &options)
            .unwrap()
            .unwrap();
        let (_, textbook) = thrust_curve(&g, angle_for(&g, 2.0 * textbook_offset, 0));
        eprintln!(
            "7008C back-to-back, {preload} N preload: offset {:.4} µm, lift-off {lift_off:.2} N (textbook {textbook:.2} N), {:.3} × the preload (2^1.5 = 2.828 at constant contact angle)",
            offset * 1e6,
            lift_off / preload
        );
        assert!(
            rel(lift_off, textbook) < 1e-5,
            "{preload} N: lift-off {lift_off} vs textbook {textbook}"
        );
        // Face-to-face: the same preload and lift-off along the axis.
        let df = ShaftSystem::matched(&steel_solver(&g), SetKind::FaceToFace, SPACING)
            .with_axial_offset(offset)
            .lift_off_load(0.0, RacewayControl::Outer, &options)
            .unwrap()
            .unwrap();
        assert!(rel(df, lift_off) < 1e-9, "face-to-face {df} vs {lift_off}");
    }
}

/// A triple with a tandem pair against one bearing (TBT, TFT) and the
/// common offset s: without external load the shaft moves by x₀ until the
/// pair's two loads balance the single one's, 2 F_a(s + x₀) = F_a(s − x₀) =
/// F_p (the preload, the force through the set); at lift-off the single
/// bearing is back at δ_a = 0, x = s, and the pair carries 2 F_a(2s).
#[test]
fn tandem_triples_preload_and_lift_off_follow_the_thrust_curve() {
    let g = bearing_7008c();
    let options = SolverOptions::default();
    for kind in [SetKind::TandemBackToBack, SetKind::TandemFaceToFace] {
        for preload in [100.0, 500.0] {
            let set = ShaftSystem::matched(&steel_solver(&g), kind, SPACING);
            let offset = set
                .offset_for_preload(preload, 0.0, RacewayControl::Outer, &options)
                .unwrap();
            let (single, _) = thrust_curve(&g, angle_for(&g, preload, 1));
            let (tandem, _) = thrust_curve(&g, angle_for(&g, 0.5 * preload, 1));
            let textbook_offset = 0.5 * (single + tandem);
            assert!(
                rel(offset, textbook_offset) < 1e-6,
                "{kind:?} {preload} N: offset {offset} vs textbook {textbook_offset}"
            );
            let set = set.with_axial_offset(offset);
            let eq = set.solve(&at_rest(Loads::default()), &options).unwrap();
            assert!(rel(set.preload_of(&eq), preload) < 1e-8);
            let loads: Vec<f64> = eq
                .bearings
                .iter()
                .map(|b| b.as_ref().unwrap().reaction[0])
                .collect();
            let (pair, one) = match kind {
                SetKind::TandemBackToBack => ([loads[0], loads[1]], loads[2]),
                _ => ([loads[1], loads[2]], loads[0]),
            };
            assert!(rel(one, preload) < 1e-8, "{kind:?}: {loads:?}");
            for l in pair {
                assert!(rel(l, 0.5 * preload) < 1e-8, "{kind:?}: {loads:?}");
            }
            let lift_off = set
                .lift_off_load(0.0, RacewayControl::Outer, &options)
                .unwrap()
                .unwrap();
            let (_, pair_at_2s) = thrust_curve(&g, angle_for(&g, 2.0 * textbook_offset, 0));
            assert!(
                rel(lift_off, 2.0 * pair_at_2s) < 1e-5,
                "{kind:?} {preload} N: lift-off {lift_off} vs textbook {}",
                2.0 * pair_at_2s
            );
        }
    }
}

#[test]
fn pair_axial_stiffness_is_twice_the_bearing_stiffness_at_the_preload() {
    let g = bearing_7008c();
    let options = SolverOptions::default();
    let preload = 200.0;
    let set = ShaftSystem::matched(&steel_solver(&g), SetKind::BackToBack, SPACING);
    let offset = set
        .offset_for_preload(preload, 0.0, RacewayControl::Outer, &options)
        .unwrap();
    let pair = set
        .with_axial_offset(offset)
        .solve(&at_rest(Loads::default()), &options)
        .unwrap();
    assert!(
        pair.displacement.iter().all(|u| u.abs() < 1e-12),
        "{:?}",
        pair.displacement
    );
    let single = steel_solver(&g)
        .solve(
            &Conditions {
                loads: Loads {
                    force: [preload, 0.0, 0.0],
                    moment: [0.0; 2],
                },
                inner_speed: 0.0,
                control: RacewayControl::Outer,
            },
            &options,
        )
        .unwrap();
    let (k_pair, k_single) = (pair.stiffness[0][0], single.stiffness[0][0]);
    eprintln!(
        "axial stiffness: pair {k_pair:.5e} N/m, one bearing at the preload {k_single:.5e} N/m"
    );
    assert!(
        rel(k_pair, 2.0 * k_single) < 1e-6,
        "{k_pair} vs 2 × {k_single}"
    );
}

#[test]
fn combined_load_balances_and_the_stiffness_predicts_small_changes() {
    let g = bearing_7008c();
    let options = SolverOptions::default();
    for speed_rpm in [0.0, 10_000.0] {
        let speed = speed_rpm * std::f64::consts::TAU / 60.0;
        let set = ShaftSystem::matched(&steel_solver(&g), SetKind::BackToBack, SPACING);
        let offset = set
            .offset_for_preload(200.0, speed, RacewayControl::Outer, &options)
            .unwrap();
        let set = set.with_axial_offset(offset);
        let conditions = |fx: f64| SystemConditions {
            loads: Loads {
                force: [fx, 0.0, 500.0],
                moment: [0.0, 5.0],
            },
            inner_speed: speed,
            control: RacewayControl::Outer,
        };
        let eq = set.solve(&conditions(300.0), &options).unwrap();
        let applied = [300.0, 0.0, 500.0, 0.0, 5.0];
        for k in 0..5 {
            let sum: f64 = eq.shaft_loads.iter().map(|s| s[k]).sum();
            let scale = if k < 3 { 500.0 } else { 500.0 * SPACING };
            assert!(
                (sum - applied[k]).abs() < 1e-8 * scale,
                "{speed_rpm} rpm, load {k}: {sum}"
            );
        }
        let axial: Vec<f64> = eq
            .bearings
            .iter()
            .map(|b| b.as_ref().unwrap().reaction[0])
            .collect();
        assert!((axial[0] - axial[1] - 300.0).abs() < 1e-6, "{axial:?}");
        // +1 N axially: the displacement changes by the compliance's column.
        let more = set.solve(&conditions(301.0), &options).unwrap();
        let k = nalgebra::SMatrix::<f64, 5, 5>::from_fn(|i, j| eq.stiffness[i][j]);
        let predicted = k
            .lu()
            .solve(&nalgebra::SVector::<f64, 5>::new(1.0, 0.0, 0.0, 0.0, 0.0))
            .unwrap();
        for i in 0..5 {
            let change = more.displacement[i] - eq.displacement[i];
            assert!(
                (change - predicted[i]).abs() < 1e-2 * predicted.amax(),
                "{speed_rpm} rpm, u{i}: {change:e} vs {:e}",
                predicted[i]
            );
        }
    }
}

#[test]
fn tandem_pair_shares_the_thrust() {
    let g = bearing_7008c();
    let options = SolverOptions::default();
    let set = ShaftSystem::matched(&steel_solver(&g), SetKind::Tandem, SPACING);
    let eq = set
        .solve(
            &at_rest(Loads {
                force: [1000.0, 0.0, 0.0],
                moment: [0.0; 2],
            }),
            &options,
        )
        .unwrap();
    for b in &eq.bearings {
        let r = b.as_ref().unwrap().reaction[0];
        assert!(rel(r, 500.0) < 1e-8, "{r}");
    }
    assert!(
        set.lift_off_load(0.0, RacewayControl::Outer, &options)
            .unwrap()
            .is_none()
    );
}

#[test]
fn back_to_back_is_stiffer_against_tilt_than_face_to_face() {
    let g = bearing_7008c();
    let options = SolverOptions::default();
    let tilt_stiffness = |kind| {
        let set = ShaftSystem::matched(&steel_solver(&g), kind, SPACING);
        let offset = set
            .offset_for_preload(200.0, 0.0, RacewayControl::Outer, &options)
            .unwrap();
        let eq = set
            .with_axial_offset(offset)
            .solve(&at_rest(Loads::default()), &options)
            .unwrap();
        eq.stiffness[3][3]
    };
    let (db, df) = (
        tilt_stiffness(SetKind::BackToBack),
        tilt_stiffness(SetKind::FaceToFace),
    );
    eprintln!("tilt stiffness: back-to-back {db:.4e} N·m/rad, face-to-face {df:.4e} N·m/rad");
    assert!(db > 2.0 * df, "back-to-back {db} vs face-to-face {df}");
}
