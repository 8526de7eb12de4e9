//! End-to-end tests of the quasi-static design outputs: radial
//! load by magnitude and direction, ball 0's azimuth, compliance and the
//! conventional stiffnesses, the balls' orbital-speed range.

#![allow(clippy::unwrap_used)]

use crate::common;

use crate::common::{assert_ok, assert_refused, json, rolldyn, stderr};

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

/// Conflicting keys in one case file are refused, naming the key; on the
/// command line a later override replaces the conflicting key instead
/// (the dedicated flags apply before `--set`).
#[test]
fn radial_load_and_tilt_conflicts_are_located() {
    let preset = rolldyn_case::presets::find("7008C")
        .unwrap()
        .without_mounting();
    for (extra, key) in [
        (
            "radial_load = \"1 kN\"\nforce_z = \"5 N\"\n",
            "operating.radial_load",
        ),
        (
            "radial_load_angle = \"10 deg\"\n",
            "operating.radial_load_angle",
        ),
        (
            "tilt_z = \"1 mrad\"\nmoment_z = \"1 N.m\"\n",
            "operating.tilt_z",
        ),
        (
            "fixed_tilt = true\nmoment_y = \"1 N.m\"\n",
            "operating.fixed_tilt",
        ),
    ] {
        let case = preset.replacen("[operating]\n", &format!("[operating]\n{extra}"), 1);
        let o = rolldyn(&["quasistatic", "-"], Some(&case));
        assert_eq!(o.status.code(), Some(2), "{extra}");
        assert!(stderr(&o).contains(key), "{extra}: {}", stderr(&o));
    }
    let v = json(
        &[
            "quasistatic",
            "--json",
            "--set",
            "operating.radial_load=1 kN",
            "--radial-load",
            "5 N",
        ],
        None,
    );
    // Flags apply before --set: the --set radial load replaces F_z.
    assert_eq!(v["force_z_n"].as_f64(), Some(1000.0));
}

/// `--fix-tilt` and `--misalignment`: the tilts are held, the holding
/// moments reported; applying those moments to the free ring gives the
/// same tilt; conflicts and dynamic runs are refused with the key.
#[test]
fn fixed_tilt_and_misalignment() {
    let v = json(
        &[
            "quasistatic",
            "--json",
            "--radial-load",
            "300 N",
            "--fix-tilt",
        ],
        None,
    );
    assert_eq!(
        v["held_displacements"],
        serde_json::json!(["tilt_y", "tilt_z"])
    );
    assert_eq!(v["tilt_y_rad"].as_f64(), Some(0.0));
    let m = v["reaction_moment_y_n_m"].as_f64().unwrap();
    assert!(
        m.abs() > 0.1,
        "a radial load on an angular-contact bearing tilts it: {m}"
    );
    assert!(v["reaction_force_x_n"].is_null());
    let free = json(
        &[
            "quasistatic",
            "--json",
            "--radial-load",
            "300 N",
            "--set",
            &format!("operating.moment_y={m} N.m"),
        ],
        None,
    );
    assert!(
        free["tilt_y_rad"].as_f64().unwrap().abs() < 1e-9,
        "{}",
        free["tilt_y_rad"]
    );
    let v = json(
        &["quasistatic", "--json", "--misalignment", "0.01 deg"],
        None,
    );
    assert!((v["tilt_y_rad"].as_f64().unwrap() - 0.01f64.to_radians()).abs() < 1e-15);
    assert!(v["reaction_moment_y_n_m"].as_f64().is_some());
    // A run holds both tilts at zero (a shaft held by its other bearing)
    // but refuses a prescribed tilt.
    let o = rolldyn(
        &[
            "run",
            "--misalignment",
            "0.01 deg",
            "--duration",
            "1 ms",
            "-o",
            "/nonexistent-dir-never-made",
        ],
        None,
    );
    assert_refused(&o, &["quasi-static only"]);
    assert!(stderr(&o).contains("operating.tilt_y"), "{}", stderr(&o));
    let dir = common::temp_dir("fixed-tilt-run");
    let d = dir.to_str().unwrap();
    let o = rolldyn(
        &[
            "run",
            "--fix-tilt",
            "--radial-load",
            "300 N",
            "--duration",
            "0.5 ms",
            "-o",
            d,
        ],
        None,
    );
    assert_ok(&o);
    let series = rolldyn_io::read_parquet(&dir.join("timeseries.parquet")).unwrap();
    for name in ["inner_ring_tilt_y_rad", "inner_ring_tilt_z_rad"] {
        assert!(
            series.column(name).unwrap().iter().all(|&v| v == 0.0),
            "{name}"
        );
    }
    let z = series.column("inner_ring_z_m").unwrap();
    assert!(z.iter().any(|&v| v != z[0]), "the ring moves radially");
    std::fs::remove_dir_all(&dir).ok();
}

/// Exit codes (docs/cli.md): an output path that cannot be
/// written is the user's error (2); a quasi-static point without an
/// equilibrium is the model's failure (3). (Ctrl-C, 130: cli.rs,
/// `run_interrupted_keeps_valid_files`.)
#[test]
fn exit_codes() {
    let file = std::env::temp_dir().join(format!("rolldyn-exit-{}", std::process::id()));
    std::fs::write(&file, "not a directory").unwrap();
    let f = file.to_string_lossy().into_owned();
    for args in [
        vec!["run", "--duration", "1 ms", "-o", f.as_str()],
        vec![
            "quasistatic",
            "--sweep",
            "speed=0rpm,1000rpm",
            "-o",
            f.as_str(),
        ],
    ] {
        let o = rolldyn(&args, None);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
    }
    std::fs::remove_file(&file).ok();
    // A point of the stress grid that has no converged solution yet
    // (the 7218B with a free ring, light axial and heavy radial load, at
    // speed); when the solver learns it, force a failure another way.
    let case = rolldyn_case::presets::find("7218B")
        .unwrap()
        .without_mounting();
    let o = rolldyn(
        &[
            "quasistatic",
            "-",
            "--speed",
            "5000 rpm",
            "--axial-load",
            "10 N",
            "--radial-load",
            "10 kN",
        ],
        Some(&case),
    );
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(stderr(&o).contains("no equilibrium"), "{}", stderr(&o));
}

/// Undefined quantities: the orders at 0 rpm are null in JSON
/// and "—" in text.
#[test]
fn undefined_orders_at_rest() {
    let v = json(&["frequencies", "--speed", "0 rpm", "--json"], None);
    assert!(v["orders"]["bpfo"].is_null(), "{}", v["orders"]);
    let o = rolldyn(&["frequencies", "--speed", "0 rpm"], None);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains('—') && !text.contains("NaN"), "{text}");
}

/// ISO 281 rating in `quasistatic`: the CWRU 6205's C_r is the
/// catalogue's 14.0 kN, L10 = (C_r/P_r)³ under its radial load, hours at
/// its speed; a 15° bearing under axial load is not covered (null).
#[test]
fn iso281_rating_life() {
    let case = rolldyn_case::presets::find("6205").unwrap().text;
    let v = json(&["quasistatic", "-", "--json"], Some(case));
    let r = &v["rating_life"];
    let c = r["dynamic_load_rating_n"].as_f64().unwrap();
    assert!((c / 14_000.0 - 1.0).abs() < 5e-3, "{c}");
    let p = r["equivalent_load_n"].as_f64().unwrap();
    assert!((p - v["radial_load_n"].as_f64().unwrap()).abs() < 1e-9);
    let l10 = r["basic_rating_life_mrev"].as_f64().unwrap();
    assert!((l10 / (c / p).powi(3) - 1.0).abs() < 1e-12);
    let hours = r["basic_rating_life_h"].as_f64().unwrap();
    let rpm = v["speed_rpm"].as_f64().unwrap();
    assert!((hours / (l10 * 1e6 / (60.0 * rpm)) - 1.0).abs() < 1e-12);
    // The default 7008C (17.7°, F_x = 200 N): Table 3 between its 15° and
    // 20° rows, so Y lies between the 20° row's 1.00 and the 15° row's
    // largest, 1.47.
    let v = json(&["quasistatic", "--json"], None);
    let p = v["rating_life"]["equivalent_load_n"].as_f64().unwrap();
    assert!(p > 1.00 * 200.0 && p < 1.47 * 200.0, "{p}");
    assert!(v["rating_life"]["basic_rating_life_h"].as_f64().is_some());
}

/// Static rating, fatigue load limit, modified and reference lives
///: the relations between the keys of `rating_life`; the
/// deep-groove axial factors apply; a hybrid bearing has no modified life;
/// a contamination factor outside [0, 1] is refused with its key.
#[test]
fn modified_and_reference_rating_lives() {
    let case = rolldyn_case::presets::find("6205").unwrap().text;
    let v = json(
        &[
            "quasistatic",
            "-",
            "--json",
            "--axial-load",
            "300 N",
            "--set",
            "life.contamination_factor=0.5",
            "--set",
            "life.viscosity_ratio=1.5",
        ],
        Some(case),
    );
    let r = &v["rating_life"];
    let get = |k: &str| r[k].as_f64().unwrap_or_else(|| panic!("{k}: {r}"));
    assert!((get("fatigue_load_limit_n") - get("static_load_rating_n") / 22.0).abs() < 1e-9);
    assert!(get("equivalent_load_n") >= v["radial_load_n"].as_f64().unwrap());
    assert_eq!(get("viscosity_ratio"), 1.5);
    assert_eq!(get("contamination_factor"), 0.5);
    let rel = |a: f64, b: f64| (a / b - 1.0).abs();
    assert!(
        rel(
            get("modified_rating_life_mrev"),
            get("life_modification_factor") * get("basic_rating_life_mrev")
        ) < 1e-12
    );
    assert!(
        rel(
            get("modified_reference_rating_life_mrev"),
            get("reference_life_modification_factor") * get("reference_rating_life_mrev")
        ) < 1e-12
    );
    assert!(
        rel(
            get("reference_equivalent_load_n"),
            get("dynamic_load_rating_n") / get("reference_rating_life_mrev").cbrt()
        ) < 1e-12
    );
    let rpm = v["speed_rpm"].as_f64().unwrap();
    assert!(
        rel(
            get("reference_rating_life_h"),
            get("reference_rating_life_mrev") * 1e6 / (60.0 * rpm)
        ) < 1e-12
    );
    // Without e_C: no modified lives.
    let v = json(&["quasistatic", "-", "--json"], Some(case));
    assert!(v["rating_life"]["modified_rating_life_mrev"].is_null());
    assert!(
        v["rating_life"]["reference_rating_life_mrev"]
            .as_f64()
            .is_some()
    );
    // Hybrid: ratings of the steel bearing, no modified lives.
    let ceramic = rolldyn_case::presets::find("ceramic_45x75").unwrap().text;
    let v = json(
        &[
            "quasistatic",
            "-",
            "--json",
            "--set",
            "life.contamination_factor=0.5",
        ],
        Some(ceramic),
    );
    assert!(v["rating_life"]["viscosity_ratio"].as_f64().is_some());
    assert!(v["rating_life"]["life_modification_factor"].is_null());
    assert!(v["rating_life"]["dynamic_load_rating_n"].as_f64().is_some());
    let o = rolldyn(
        &["quasistatic", "-", "--set", "life.contamination_factor=1.5"],
        Some(case),
    );
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("life.contamination_factor") && err.contains("[0, 1]"),
        "{err}"
    );
}

/// A light axial load under a heavy radial load on a single 40° bearing
/// with its tilt free (the stress grid): the solution branch ends
/// before the given axial load; the solve fails with the model's exit 3
/// and names the least axial load, which then solves.
#[test]
fn least_axial_load_is_named() {
    let case = rolldyn_case::presets::find("7218B")
        .unwrap()
        .without_mounting();
    let args = [
        "quasistatic",
        "-",
        "--speed",
        "0 rpm",
        "--radial-load",
        "50 kN",
    ];
    let o = rolldyn(
        &[&args[..], &["--axial-load", "10 N"]].concat(),
        Some(&case),
    );
    assert_eq!(o.status.code(), Some(3));
    let err = String::from_utf8_lossy(&o.stderr);
    let least: f64 = err
        .split("at least ")
        .nth(1)
        .and_then(|t| t.split(' ').next())
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("{err}"));
    assert!(least > 10.0 && least < 100.0, "{err}");
    let enough = format!("{} N", 1.05 * least + 1.0);
    let o = rolldyn(
        &[&args[..], &["--axial-load", &enough]].concat(),
        Some(&case),
    );
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// Near rest the balls off the load zone are held only by their
/// centrifugal force (~1e-7 N at 1 rpm): the shaft's solve still finds
/// the statics (the reactions of 100 rpm, where speed effects are
/// 1e-6 of the load) on the same branch, with every bearing loaded.
#[test]
fn a_shaft_near_rest_keeps_its_statics() {
    let case = common::SHAFT.replace("ORIENTATION", "reversed");
    let radial = |speed: &str| -> Vec<f64> {
        let v = json(
            &["quasistatic", "-", "--json", "--speed", speed],
            Some(&case),
        );
        v["arrangement"]["bearings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|b| b["radial_load_n"].as_f64().unwrap())
            .collect()
    };
    let reference = radial("100 rpm");
    for speed in ["1 rpm", "30 rpm"] {
        for (r, r0) in radial(speed).iter().zip(&reference) {
            assert!((r / r0 - 1.0).abs() < 1e-4, "{speed}: {r} vs {r0}");
        }
    }
}
