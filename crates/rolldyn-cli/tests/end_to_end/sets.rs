//! End-to-end tests of bearing sets (`[arrangement]`, docs/systems.md):
//! the keys of `rolldyn quasistatic --json`, the balance of the loads,
//! the preload and lift-off, the sweep files, and the errors.

#![allow(clippy::unwrap_used)]

use crate::common::{
    SHAFT, assert_ok, assert_refused, json, keys, pair, rolldyn, stderr, stdout, temp_dir,
};

#[test]
fn back_to_back_pair_report() {
    let case = pair("kind = \"back_to_back\"\npreload = \"200 N\"");
    let v = json(
        &[
            "quasistatic",
            "-",
            "--json",
            "--axial-load",
            "300 N",
            "--radial-load",
            "1 kN",
        ],
        Some(&case),
    );
    let a = &v["arrangement"];
    assert_eq!(
        keys(a),
        [
            "axial_stiffness_n_per_m",
            "bearings",
            "compliance_matrix",
            "iterations",
            "kind",
            "lift_off_axial_load_n",
            "preload_given",
            "preload_n",
            "preload_offset_m",
            "shaft_displacement",
            "shaft_nodes",
            "spacing_m",
            "stiffness_matrix",
            "system_basic_rating_life_h",
            "system_modified_reference_rating_life_h",
            "system_reference_rating_life_h",
        ]
    );
    assert_eq!(a["kind"], "back_to_back");
    // The spacing defaults to the bearing width (15 mm).
    assert!((a["spacing_m"].as_f64().unwrap() - 15e-3).abs() < 1e-12);
    let bearings = a["bearings"].as_array().unwrap();
    assert_eq!(bearings.len(), 2);
    assert_eq!(bearings[0]["orientation"], "forward");
    assert_eq!(bearings[1]["orientation"], "reversed");
    // The shaft loads of the bearings add up to the applied load.
    for (k, applied) in [(0, 300.0), (1, 0.0), (2, 1000.0), (3, 0.0), (4, 0.0)] {
        let sum: f64 = bearings
            .iter()
            .map(|b| b["shaft_load"][k].as_f64().unwrap())
            .sum();
        assert!((sum - applied).abs() < 1e-6, "component {k}: {sum}");
    }
    let axial: Vec<f64> = bearings
        .iter()
        .map(|b| b["axial_load_n"].as_f64().unwrap())
        .collect();
    assert!((axial[0] - axial[1] - 300.0).abs() < 1e-6, "{axial:?}");
    // Each bearing's own report carries its share.
    let q = &bearings[0]["quasistatic"];
    assert!((q["force_x_n"].as_f64().unwrap() - axial[0]).abs() < 1e-9);
    assert!(q["balls"].as_array().unwrap().len() == 22);
    // Position preload grows with speed (10 000 rpm here) above its value
    // at rest; the lift-off load lies well above the preload.
    let preload = a["preload_n"].as_f64().unwrap();
    let lift_off = a["lift_off_axial_load_n"].as_f64().unwrap();
    assert!(preload > 200.0 && preload < 300.0, "{preload}");
    assert!(
        lift_off > 2.828 * 200.0 && lift_off < 4.0 * 200.0,
        "{lift_off}"
    );
    // The stiffness matrix and its inverse.
    let k = &a["stiffness_matrix"];
    let c = &a["compliance_matrix"];
    for i in 0..5 {
        for j in 0..5 {
            let kc: f64 = (0..5)
                .map(|m| k[i][m].as_f64().unwrap() * c[m][j].as_f64().unwrap())
                .sum();
            assert!(
                (kc - f64::from(u8::from(i == j))).abs() < 1e-8,
                "KC[{i}][{j}] = {kc}"
            );
        }
    }
    // `check` reports the set as given.
    let c = json(&["check", "-", "--json"], Some(&case));
    assert_eq!(c["arrangement"]["kind"], "back_to_back");
    assert_eq!(c["arrangement"]["preload_n"].as_f64(), Some(200.0));
    assert!(c["arrangement"]["preload_displacement_m"].is_null());
    assert!(json(&["check", "--json"], None)["arrangement"].is_null());
    // The text report names the set and both bearings.
    let o = rolldyn(&["quasistatic", "-"], Some(&case));
    let text = stdout(&o);
    assert!(text.contains("Bearing set: back_to_back"), "{text}");
    assert!(text.contains("lift-off axial load"), "{text}");
}

#[test]
fn beyond_lift_off_the_opposed_bearing_is_unloaded() {
    let case = pair("kind = \"face_to_face\"\npreload = \"100 N\"");
    let v = json(
        &[
            "quasistatic",
            "-",
            "--json",
            "--speed",
            "0 rpm",
            "--axial-load",
            "2 kN",
        ],
        Some(&case),
    );
    let b = &v["arrangement"]["bearings"];
    assert!(b[1]["quasistatic"].is_null());
    assert_eq!(b[1]["axial_load_n"].as_f64().unwrap(), 0.0);
    assert!((b[0]["axial_load_n"].as_f64().unwrap() - 2000.0).abs() < 1e-6);
}

#[test]
fn sweep_over_speed_writes_the_preload() {
    let case = pair("kind = \"back_to_back\"\npreload_displacement = \"8 um\"");
    let dir = temp_dir("set-sweep");
    let o = rolldyn(
        &[
            "quasistatic",
            "-",
            "--sweep",
            "speed=0rpm..20000rpm/3",
            "-o",
            dir.to_str().unwrap(),
        ],
        Some(&case),
    );
    assert_ok(&o);
    let rows: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("sweep.json")).unwrap()).unwrap();
    let preload: Vec<f64> = rows
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["preload_n"].as_f64().unwrap())
        .collect();
    assert_eq!(preload.len(), 3);
    assert!(
        preload[0] < preload[1] && preload[1] < preload[2],
        "{preload:?}"
    );
    let csv = std::fs::read_to_string(dir.join("sweep.csv")).unwrap();
    assert!(csv.starts_with("speed_rpm,force_x_n,force_z_n,converged,preload_n,"));
    assert_eq!(csv.lines().count(), 4);
    std::fs::remove_dir_all(&dir).ok();
}

/// A sweep solves each point from its neighbour along the innermost
/// sweep: every row is the single solve at its point (to the solvers'
/// tolerances), and the files are the same bytes on one thread as on all.
#[test]
fn set_sweep_rows_are_the_single_solves_whatever_the_threads() {
    let case = pair("kind = \"back_to_back\"\npreload = \"200 N\"");
    let sweep = |threads: Option<&str>, tag: &str| {
        let dir = temp_dir(tag);
        let mut command = std::process::Command::new(env!("CARGO_BIN_EXE_rolldyn"));
        command.args([
            "quasistatic",
            "-",
            "--sweep",
            "speed=10000rpm,15000rpm",
            "--sweep",
            "axial=0N..400N/5",
            "--radial-load",
            "150 N",
            "-o",
            dir.to_str().unwrap(),
        ]);
        if let Some(n) = threads {
            command.env("RAYON_NUM_THREADS", n);
        }
        let mut child = command
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        use std::io::Write;
        child
            .stdin
            .take()
            .unwrap()
            .write_all(case.as_bytes())
            .unwrap();
        let o = child.wait_with_output().unwrap();
        assert_ok(&o);
        let csv = std::fs::read_to_string(dir.join("sweep.csv")).unwrap();
        let rows: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join("sweep.json")).unwrap())
                .unwrap();
        std::fs::remove_dir_all(&dir).ok();
        (csv, rows)
    };
    let (one, rows) = sweep(Some("1"), "set-sweep-1");
    let (all, _) = sweep(None, "set-sweep-all");
    assert_eq!(one, all);
    for row in rows.as_array().unwrap() {
        let speed = format!("{} rpm", row["speed_rpm"]);
        let axial = format!("{} N", row["force_x_n"]);
        let single = json(
            &[
                "quasistatic",
                "-",
                "--json",
                "--speed",
                &speed,
                "--axial-load",
                &axial,
                "--radial-load",
                "150 N",
            ],
            Some(&case),
        );
        let a = &single["arrangement"];
        for (key, swept) in [
            (
                "axial_displacement_m",
                a["shaft_displacement"][0].as_f64().unwrap(),
            ),
            (
                "axial_stiffness_n_per_m",
                a["axial_stiffness_n_per_m"].as_f64().unwrap(),
            ),
        ] {
            let v = row[key].as_f64().unwrap();
            assert!(
                (v - swept).abs() <= 1e-8 * swept.abs().max(1e-9),
                "{speed}, {axial}: {key} {v} vs {swept}"
            );
        }
    }
}

/// `quasistatic --sweep` of a `[shaft]` system: the swept loads act at
/// the reference point on top of the shaft's own; every row is the single
/// solve at its point.
#[test]
fn a_shaft_sweeps_over_speed_and_load() {
    let case = SHAFT.replace("ORIENTATION", "forward");
    let dir = temp_dir("shaft-sweep");
    let o = rolldyn(
        &[
            "quasistatic",
            "-",
            "--sweep",
            "speed=1000rpm,3000rpm",
            "--sweep",
            "radial=0N..1000N/3",
            "-o",
            dir.to_str().unwrap(),
        ],
        Some(&case),
    );
    assert_ok(&o);
    let rows: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("sweep.json")).unwrap()).unwrap();
    std::fs::remove_dir_all(&dir).ok();
    let rows = rows.as_array().unwrap();
    assert_eq!(rows.len(), 6);
    for row in rows {
        assert_eq!(row["converged"], true, "{row}");
        let speed = format!("{} rpm", row["speed_rpm"]);
        let radial = format!("{} N", row["force_z_n"]);
        let single = json(
            &[
                "quasistatic",
                "-",
                "--json",
                "--speed",
                &speed,
                "--radial-load",
                &radial,
            ],
            Some(&case),
        );
        let a = &single["arrangement"];
        let z = a["shaft_displacement"][2].as_f64().unwrap();
        let k = a["stiffness_matrix"][2][2].as_f64().unwrap();
        assert!(
            (row["radial_stiffness_z_n_per_m"].as_f64().unwrap() - k).abs() <= 1e-7 * k,
            "{speed}, {radial}"
        );
        let axial: Vec<f64> = a["bearings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|b| b["axial_load_n"].as_f64().unwrap())
            .collect();
        let swept: Vec<f64> = row["axial_loads_n"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        for (x, y) in axial.iter().zip(&swept) {
            assert!(
                (x - y).abs() <= 1e-6 * 300.0,
                "{speed}, {radial}: {x} vs {y}"
            );
        }
        assert!(z.is_finite());
    }
}

/// A preloaded pair built bearing by bearing on a `[shaft]` (each inner
/// ring offset 8 µm towards its loaded side) is the `[arrangement]`
/// back-to-back pair with an 8 µm preload displacement: the same
/// stiffness and bearing loads.
#[test]
fn a_shaft_pair_with_preload_offsets_is_the_matched_pair() {
    let matched = pair("kind = \"back_to_back\"\npreload_displacement = \"8 um\"");
    let shaft = r#"
[operating]
speed = "10000 rpm"
force_x = "300 N"
force_z = "200 N"
[shaft]
[[shaft.bearings]]
preset = "7008C"
position = "-7.5 mm"
preload_offset = "8 um"
[[shaft.bearings]]
preset = "7008C"
position = "7.5 mm"
orientation = "reversed"
preload_offset = "8 um"
"#;
    let loads = ["--axial-load", "300 N", "--radial-load", "200 N"];
    let mut args = vec!["quasistatic", "-", "--json"];
    args.extend(loads);
    let a = json(&args, Some(&matched));
    let b = json(&["quasistatic", "-", "--json"], Some(shaft));
    let (a, b) = (&a["arrangement"], &b["arrangement"]);
    for (i, j) in [(0, 0), (2, 2), (3, 3), (0, 3)] {
        let (x, y) = (
            a["stiffness_matrix"][i][j].as_f64().unwrap(),
            b["stiffness_matrix"][i][j].as_f64().unwrap(),
        );
        assert!(
            (x - y).abs() <= 1e-6 * x.abs().max(1.0),
            "K[{i}][{j}]: {x} vs {y}"
        );
    }
    for k in 0..2 {
        let load = |v: &serde_json::Value| v["bearings"][k]["axial_load_n"].as_f64().unwrap();
        assert!(
            (load(a) - load(b)).abs() < 1e-6 * 300.0,
            "{} vs {}",
            load(a),
            load(b)
        );
    }
    let floating = shaft.replacen(
        "preload_offset = \"8 um\"",
        "preload_offset = \"8 um\"\naxial = \"floating\"",
        1,
    );
    let o = rolldyn(&["quasistatic", "-"], Some(&floating));
    assert_refused(&o, &["shaft.bearings[0].preload_offset"]);
}

#[test]
fn errors_name_the_key() {
    for (arrangement, key, rule) in [
        (
            "kind = \"tandem\"\npreload = \"100 N\"",
            "arrangement.preload",
            "takes no preload",
        ),
        (
            "kind = \"back_to_back\"\npreload = \"100 N\"\npreload_displacement = \"5 um\"",
            "arrangement.preload_displacement",
            "not both",
        ),
        (
            "kind = \"back_to_back\"\npreload = \"0 N\"",
            "arrangement.preload",
            "must be positive",
        ),
        (
            // Below what the solve resolves (each ball's approach < 5 nm).
            "kind = \"back_to_back\"\npreload = \"0.001 N\"",
            "arrangement",
            "below the least preload",
        ),
        (
            "kind = \"back_to_back\"\nspacing = \"-1 mm\"",
            "arrangement.spacing",
            "must be positive",
        ),
        ("kind = \"diagonal\"", "arrangement.kind", "unknown variant"),
        (
            "kind = \"back_to_back\"\nunbalance = \"-5 g.mm\"",
            "arrangement.unbalance",
            "must lie in [0",
        ),
        (
            "kind = \"back_to_back\"\nunbalance_position = \"5 mm\"",
            "arrangement.unbalance_position",
            "not given",
        ),
    ] {
        let case = pair(arrangement);
        let o = rolldyn(&["quasistatic", "-"], Some(&case));
        assert_eq!(o.status.code(), Some(2), "{arrangement}");
        let e = stderr(&o);
        assert!(e.contains(key) && e.contains(rule), "{arrangement}: {e}");
    }
    // A held tilt written into a set's case (not a preset's tagged
    // mounting line, which a set leaves out) is refused with its key.
    let held = pair("kind = \"back_to_back\"\npreload = \"100 N\"").replacen(
        "[operating]\n",
        "[operating]\nfixed_tilt = true\n",
        1,
    );
    let o = rolldyn(&["quasistatic", "-"], Some(&held));
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(
        e.contains("operating.fixed_tilt") && e.contains("holds its own tilt"),
        "{e}"
    );
    let case = pair("kind = \"back_to_back\"\npreload = \"100 N\"");
    // The power loss of every bearing at the set's equilibrium, each as
    // the bearing's own power report.
    let v = json(&["power", "-", "--json"], Some(&case));
    assert_eq!(v["kind"], "back_to_back");
    let rows = v["bearings"].as_array().unwrap();
    assert_eq!(rows.len(), 2);
    let sum: f64 = rows
        .iter()
        .map(|r| r["power"]["power_loss_w"].as_f64().unwrap())
        .sum();
    assert!((sum - v["power_loss_w"].as_f64().unwrap()).abs() < 1e-12);
    assert!(sum > 0.0);
    let o = rolldyn(&["quasistatic", "-", "--control", "traction"], Some(&case));
    assert_refused(&o, &["--control traction"]);
}

/// The shaft's loads balance the applied ones; the radial reactions are
/// the lever rule's (4000 × 40/120 and 4000 × 80/120 N) but for the small
/// moments the deep-groove bearings take with the shaft's tilt; a
/// deep-groove bearing carries thrust either way, so its orientation
/// changes nothing.
#[test]
fn a_shaft_on_two_bearings_follows_statics() {
    let solve = |orientation: &str| {
        json(
            &["quasistatic", "-", "--json"],
            Some(&SHAFT.replace("ORIENTATION", orientation)),
        )
    };
    let v = solve("forward");
    let a = &v["arrangement"];
    assert_eq!(a["kind"], "shaft");
    assert!(a["spacing_m"].is_null());
    let bearings = a["bearings"].as_array().unwrap();
    assert_eq!(bearings.len(), 2);
    // The applied load about the reference point: M_y = −0.02 × (−4000).
    let applied = [300.0, 0.0, -4000.0, 80.0, 0.0];
    for (k, expected) in applied.iter().enumerate() {
        let carried: f64 = bearings
            .iter()
            .map(|b| b["shaft_load"][k].as_f64().unwrap())
            .sum();
        assert!(
            (carried - expected).abs() < 1e-6 * 4000.0,
            "{k}: {carried} vs {expected}"
        );
    }
    let radial: Vec<f64> = bearings
        .iter()
        .map(|b| b["radial_load_n"].as_f64().unwrap())
        .collect();
    for (r, lever) in radial.iter().zip([4000.0 / 3.0, 8000.0 / 3.0]) {
        assert!((r / lever - 1.0).abs() < 0.05, "{radial:?}");
    }
    assert!((radial[0] + radial[1] - 4000.0).abs() < 40.0, "{radial:?}");
    let reversed = solve("reversed");
    for (b, r) in reversed["arrangement"]["bearings"]
        .as_array()
        .unwrap()
        .iter()
        .zip(&radial)
    {
        assert!((b["radial_load_n"].as_f64().unwrap() - r).abs() < 1e-6 * r);
    }
    assert!(a["system_basic_rating_life_h"].as_f64().unwrap() > 0.0);
}

/// Catalogue bearings on the shaft: the catalogue's 6206 (CN) has the
/// 6206 preset's ball set, pitch diameter, curvatures and clearance, so
/// the shaft's solution is the presets' to the solver's tolerance; a C3
/// clearance changes it. A case's `[bearing]` can name a catalogue
/// bearing as it names a preset.
#[test]
fn catalogue_bearings_sit_on_a_shaft() {
    let presets = json(
        &["quasistatic", "-", "--json"],
        Some(&SHAFT.replace("ORIENTATION", "forward")),
    );
    let catalogue_case = SHAFT
        .replace("ORIENTATION", "forward")
        .replace("preset = \"6206\"", "catalogue = \"6206\"");
    let catalogue = json(&["quasistatic", "-", "--json"], Some(&catalogue_case));
    let reactions = |v: &serde_json::Value| -> Vec<f64> {
        v["arrangement"]["bearings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|b| b["radial_load_n"].as_f64().unwrap())
            .collect()
    };
    for (a, b) in reactions(&presets).iter().zip(reactions(&catalogue)) {
        assert!((a - b).abs() < 1e-6 * a.abs(), "{a} vs {b}");
    }
    let c3 = json(
        &["quasistatic", "-", "--json"],
        Some(&catalogue_case.replacen(
            "catalogue = \"6206\"",
            "catalogue = \"6206\"\nclearance_group = \"C3\"",
            1,
        )),
    );
    let (r_cn, r_c3) = (reactions(&catalogue), reactions(&c3));
    assert!(
        (r_cn[0] - r_c3[0]).abs() > 1e-4 * r_cn[0],
        "{r_cn:?} vs {r_c3:?}"
    );
    let single = json(
        &["check", "-", "--json"],
        Some("[bearing]\ncatalogue = \"6309\"\nclearance_group = \"C3\"\n"),
    );
    assert_eq!(single["geometry"]["ball_count"], 8);
    let p_d = single["geometry"]["diametral_clearance_m"]
        .as_f64()
        .unwrap();
    assert!((p_d - 27e-6).abs() < 1e-12, "{p_d}");
    for (text, expect) in [
        (
            catalogue_case.replacen("catalogue = \"6206\"", "catalogue = \"6299\"", 1),
            "shaft.bearings[0].catalogue = \"6299\"",
        ),
        (
            catalogue_case.replacen(
                "catalogue = \"6206\"",
                "catalogue = \"6206\"\nclearance_group = \"C9\"",
                1,
            ),
            "shaft.bearings[0].clearance_group = \"C9\"",
        ),
        (
            catalogue_case.replacen(
                "catalogue = \"6206\"",
                "catalogue = \"6206\"\npreset = \"6206\"",
                1,
            ),
            "not both",
        ),
        (
            "[bearing]\ncatalogue = \"7210\"\n".to_string(),
            "bearing.catalogue = \"7210\"",
        ),
        (
            "[bearing]\npreset = \"6206\"\nclearance_group = \"C3\"\n".to_string(),
            "bearing.clearance_group",
        ),
    ] {
        let o = rolldyn(&["quasistatic", "-"], Some(&text));
        assert_eq!(o.status.code(), Some(2), "{text}");
        assert!(stderr(&o).contains(expect), "{expect}: {}", stderr(&o));
    }
}

#[test]
fn shaft_errors_name_the_key() {
    let case = SHAFT.replace("ORIENTATION", "forward");
    for (text, key) in [
        (
            case.replace(
                "preset = \"6206\"\nposition = \"60 mm\"",
                "preset = \"9999\"\nposition = \"60 mm\"",
            ),
            "shaft.bearings[1].preset",
        ),
        (
            case.replace("\"60 mm\"", "\"-60 mm\""),
            "shaft.bearings[1].position",
        ),
        (
            format!("{case}\n[arrangement]\nkind = \"tandem\"\n"),
            "shaft",
        ),
        (
            "[bearing]\npreset = \"6206\"\n[shaft]\n".to_string(),
            "shaft.bearings",
        ),
        (
            format!("{case}\n[fits]\nshaft_tolerance = \"k5\"\n"),
            "fits",
        ),
    ] {
        let o = rolldyn(&["quasistatic", "-"], Some(&text));
        assert_eq!(o.status.code(), Some(2), "{key}: {}", stderr(&o));
        assert!(stderr(&o).contains(key), "{key}: {}", stderr(&o));
    }
    // A shaft's thermal network has its steady state only.
    let o = rolldyn(&["thermal", "-", "--transient", "10 min"], Some(&case));
    assert_refused(&o, &["--transient"]);
}

/// `[fits]`: the 6206's 12.5 µm shrink to −4.3 µm with a 15 µm shaft and a
/// 5 µm housing interference; the report says so, and the mounted bearing
/// (now preloaded) carries the same radial load on more balls.
#[test]
fn fits_reduce_the_clearance_quasistatic_reports() {
    let case = stdout(&rolldyn(&["new", "--preset", "6206"], None));
    let mounted = format!(
        "{case}\n[fits]\nshaft_interference = \"15 um\"\nhousing_interference = \"5 um\"\n"
    );
    let args = ["quasistatic", "-", "--json", "--radial-load", "2 kN"];
    let free = json(&args, Some(&case));
    let fitted = json(&args, Some(&mounted));
    assert!(free["fits"].is_null());
    let f = &fitted["fits"];
    let g = |k: &str| f[k].as_f64().unwrap();
    assert!((g("diametral_clearance_unmounted_m") - 12.5e-6).abs() < 1e-12);
    let lost = g("inner_raceway_expansion_m") + g("outer_raceway_contraction_m");
    assert!((g("diametral_clearance_mounted_m") - (12.5e-6 - lost)).abs() < 1e-12);
    assert!(g("diametral_clearance_mounted_m") < 0.0);
    let loaded = |v: &serde_json::Value| {
        v["balls"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|b| b["load_inner_n"].as_f64().unwrap() > 1.0)
            .count()
    };
    assert!(
        loaded(&fitted) > loaded(&free),
        "{} vs {}",
        loaded(&fitted),
        loaded(&free)
    );
    // By tolerance class: the 6206 (bore 30 mm, 0/−10 µm) on m5 (+8/+17 µm):
    // 8 … 27 µm, 17.5 µm used.
    let by_class = json(
        &args,
        Some(&format!("{case}\n[fits]\nshaft_tolerance = \"m5\"\n")),
    );
    let s = &by_class["fits"]["shaft_fit"];
    assert_eq!(s["class"], "m5");
    for (key, um) in [
        ("interference_min_m", 8.0),
        ("interference_max_m", 27.0),
        ("interference_used_m", 17.5),
    ] {
        assert!(
            (s[key].as_f64().unwrap() - um * 1e-6).abs() < 1e-12,
            "{key}: {}",
            s[key]
        );
    }
    assert!(by_class["fits"]["housing_fit"].is_null());
}

/// A locating and a floating bearing: the floating one carries no thrust,
/// the locating one all of it; the reported compliance (the floating
/// bearing's free axial motion condensed out) predicts the shaft's move
/// under 10 N more of the gear force.
#[test]
fn a_floating_bearing_carries_no_thrust() {
    let case = |force_z: &str| {
        SHAFT
            .replace("orientation = \"ORIENTATION\"", "axial = \"floating\"")
            .replace("force_z = \"-4 kN\"", &format!("force_z = \"{force_z}\""))
    };
    let solve = |force_z: &str| json(&["quasistatic", "-", "--json"], Some(&case(force_z)));
    let v = solve("-4000 N");
    let a = &v["arrangement"];
    let bearings = a["bearings"].as_array().unwrap();
    let axial = |b: &serde_json::Value| b["axial_load_n"].as_f64().unwrap();
    assert!(
        (axial(&bearings[0]) - 300.0).abs() < 1e-6 * 300.0,
        "{}",
        axial(&bearings[0])
    );
    assert!(
        axial(&bearings[1]).abs() < 1e-6 * 300.0,
        "{}",
        axial(&bearings[1])
    );
    let more = solve("-4010 N");
    let u = |v: &serde_json::Value, k: usize| {
        v["arrangement"]["shaft_displacement"][k].as_f64().unwrap()
    };
    // The extra −10 N at x = +20 mm: ΔF_z = −10 N, ΔM_y = +0.2 N·m.
    let c = &a["compliance_matrix"];
    let g = |i: usize, j: usize| c[i][j].as_f64().unwrap();
    for k in [2, 3] {
        let predicted = g(k, 2) * -10.0 + g(k, 3) * 0.2;
        let moved = u(&more, k) - u(&v, k);
        assert!(
            (moved / predicted - 1.0).abs() < 0.02,
            "{k}: {moved} vs {predicted}"
        );
    }
    let o = rolldyn(
        &["quasistatic", "-"],
        Some(&case("-4000 N").replace(
            "preset = \"6206\"\nposition = \"-60 mm\"",
            "preset = \"6206\"\nposition = \"-60 mm\"\naxial = \"floating\"",
        )),
    );
    assert_refused(&o, &["shaft.bearings"]);
}

/// A pair whose second bearing lifts off prints a dash for its contact
/// angles, never NaN.
#[test]
fn an_unloaded_bearing_of_a_set_prints_no_nan() {
    let o = rolldyn(
        &["quasistatic", "--set", "arrangement.kind=back_to_back"],
        None,
    );
    assert_ok(&o);
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.contains("(unloaded beyond lift-off)"), "{text}");
    assert!(!text.contains("NaN"), "{text}");
}

/// A triple of C4 bearings whose 0.1 µm offset the clearance takes up:
/// `thermal` says there is no preload left, with no NaN or signed zero.
#[test]
fn a_preload_the_clearance_takes_up_prints_no_nan() {
    let o = rolldyn(&["new", "--bearing", "6309", "--clearance", "C4"], None);
    assert_ok(&o);
    let case = String::from_utf8(o.stdout).unwrap();
    let o = rolldyn(
        &[
            "thermal",
            "-",
            "--set",
            "arrangement.kind=tandem_face_to_face",
            "--set",
            "arrangement.preload_displacement=0.1 um",
        ],
        Some(&case),
    );
    assert_ok(&o);
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.contains("no preload left"), "{text}");
    assert!(!text.contains("NaN") && !text.contains("-0.0 N"), "{text}");
}

/// `--resume` of a set's completed run is refused at once (before the
/// set's quasi-static start is built), naming `--until`.
#[test]
fn resuming_a_completed_set_is_refused_at_once() {
    let dir = temp_dir("set-resume-complete");
    let d = dir.to_str().unwrap();
    let case = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/spindle_pair/case.toml"
    );
    let o = rolldyn(&["run", case, "--duration", "0.2 ms", "-o", d], None);
    assert_ok(&o);
    let begun = std::time::Instant::now();
    let o = rolldyn(&["run", "--resume", d], None);
    assert_refused(&o, &["--until"]);
    // Not the seconds of a set's start (generous for a loaded machine).
    assert!(begun.elapsed().as_secs_f64() < 5.0);
    std::fs::remove_dir_all(&dir).ok();
}
