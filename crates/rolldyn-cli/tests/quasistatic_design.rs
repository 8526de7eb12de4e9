//! End-to-end tests of the quasi-static design outputs (issue 16): radial
//! load by magnitude and direction, ball 0's azimuth, compliance and the
//! conventional stiffnesses, the balls' orbital-speed range.

#![allow(clippy::unwrap_used)]

mod common;

use common::{json, rolldyn, stderr};

#[test]
fn radial_load_direction_ball_azimuth_and_compliance() {
    let v = json(
        &[
            "quasistatic",
            "--json",
            "--set",
            "operating.radial_load=1 kN",
            "--set",
            "operating.radial_load_angle=30 deg",
            "--set",
            "operating.first_ball_azimuth=12 deg",
        ],
        None,
    );
    let f = |k: &str| v[k].as_f64().unwrap_or_else(|| panic!("{k}"));
    assert!((f("force_y_n") - 1000.0 * 30f64.to_radians().cos()).abs() < 1e-9);
    assert!((f("force_z_n") - 500.0).abs() < 1e-9);
    assert!((f("radial_load_n") - 1000.0).abs() < 1e-9);
    assert!((f("radial_load_angle_deg") - 30.0).abs() < 1e-9);
    assert!((f("first_ball_azimuth_deg") - 12.0).abs() < 1e-9);
    assert!((v["balls"][0]["azimuth_deg"].as_f64().unwrap() - 12.0).abs() < 1e-9);
    assert!(
        f("orbital_speed_min_rpm") <= f("cage_speed_rpm")
            && f("cage_speed_rpm") <= f("orbital_speed_max_rpm")
    );
    let k = &v["stiffness_matrix"];
    let c = &v["compliance_matrix"];
    for i in 0..5 {
        for j in 0..5 {
            let ck: f64 = (0..5)
                .map(|m| c[i][m].as_f64().unwrap() * k[m][j].as_f64().unwrap())
                .sum();
            assert!(
                (ck - f64::from(u8::from(i == j))).abs() < 1e-8,
                "({i},{j}) {ck}"
            );
        }
    }
    let conventional = v["conventional_stiffness"]["axial_n_per_m"]
        .as_f64()
        .unwrap();
    assert!((conventional - 1.0 / c[0][0].as_f64().unwrap()).abs() < 1e-6 * conventional);
}

#[test]
fn radial_load_conflicts_are_located() {
    for (args, key) in [
        (
            vec![
                "--set",
                "operating.radial_load=1 kN",
                "--radial-load",
                "5 N",
            ],
            "operating.radial_load",
        ),
        (
            vec!["--set", "operating.radial_load_angle=10 deg"],
            "operating.radial_load_angle",
        ),
    ] {
        let mut a = vec!["quasistatic"];
        a.extend(args);
        let o = rolldyn(&a, None);
        assert_eq!(o.status.code(), Some(2), "{a:?}");
        assert!(stderr(&o).contains(key), "{a:?}: {}", stderr(&o));
    }
}
