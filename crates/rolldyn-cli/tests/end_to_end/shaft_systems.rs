//! End-to-end tests of bearings on a shaft beyond the quasi-static
//! solution of a rigid one (docs/systems.md): the thermal preload of a
//! pair, sets and shafts in motion, the elastic shaft, moments among the
//! shaft loads, fits on a shaft's bearings and inline bearings.

#![allow(clippy::unwrap_used)]

use crate::common;

use crate::common::{
    SHAFT, assert_refused, json, keys, pair, rolldyn, run_into, stderr, stdout, summary_of,
    temp_dir,
};

/// `rolldyn thermal` of a pair: every bearing's network with the set in
/// the loop; the preload at the operating temperatures above the one at
/// the reference temperature (the inner rings run warmer); the keys; a
/// warm-up is refused.
#[test]
fn thermal_preload_of_a_pair() {
    let case = pair(
        "kind = \"back_to_back\"\npreload = \"200 N\"\n[thermal]\noil_flow = \"0.5 L/min\"\noil_inlet_temperature = \"25 degC\"",
    );
    let v = json(
        &["thermal", "-", "--json", "--axial-load", "0 N"],
        Some(&case),
    );
    assert_eq!(
        keys(&v),
        [
            "axial_strain",
            "bearings",
            "converged",
            "heat_generated_w",
            "history_k",
            "iterations",
            "kind",
            "mounting_preload_n",
            "oil_flow_m3_s",
            "operating_preload_at_speed_n",
            "reference_preload_at_speed_n",
            "warnings",
        ]
    );
    assert_eq!(v["converged"], true);
    assert_eq!(v["warnings"], serde_json::json!([]), "oil flow given, cool");
    assert_eq!(v["kind"], "back_to_back");
    let bearings = v["bearings"].as_array().unwrap();
    assert_eq!(bearings.len(), 2);
    assert_eq!(
        keys(&bearings[0]),
        [
            "heat_generated_w",
            "heat_to_ambient_w",
            "heat_to_oil_w",
            "oil_viscosity_pa_s",
            "operating_axial_load_n",
            "operating_axial_offset_m",
            "operating_clearance_m",
            "orientation",
            "position_m",
            "power",
            "reference_axial_load_n",
            "reference_axial_offset_m",
            "reference_clearance_m",
            "temperatures_c",
        ]
    );
    let f = |b: &serde_json::Value, k: &str| b[k].as_f64().unwrap();
    let (cold, hot) = (
        f(&v, "reference_preload_at_speed_n"),
        f(&v, "operating_preload_at_speed_n"),
    );
    assert!(cold > 200.0 && hot > cold, "{cold} {hot}");
    // Without external load the pair is symmetric: equal temperatures
    // and loads, the heat the sum of both, the balls (heated at both
    // contacts) above both rings, and the clearance closes.
    let (a, b) = (&bearings[0], &bearings[1]);
    for k in [
        "operating_axial_load_n",
        "heat_generated_w",
        "operating_clearance_m",
    ] {
        assert!((f(a, k) - f(b, k)).abs() <= 1e-6 * f(a, k).abs(), "{k}");
    }
    assert!((f(a, "operating_axial_load_n") - hot).abs() < 1e-6 * hot);
    assert!((f(&v, "heat_generated_w") - 2.0 * f(a, "heat_generated_w")).abs() < 1e-9);
    let t = &a["temperatures_c"];
    assert!(f(t, "ball") > f(t, "inner_ring") && f(t, "ball") > f(t, "outer_ring"));
    assert!(f(a, "operating_clearance_m") < f(a, "reference_clearance_m"));
    assert!(f(a, "operating_axial_offset_m") > f(a, "reference_axial_offset_m"));
    let o = rolldyn(&["thermal", "-", "--transient", "10 min"], Some(&case));
    assert_refused(&o, &["--transient"]);
    // Under 200 N of thrust the +x bearing runs hotter and the pair
    // still balances it.
    let v = json(&["thermal", "-", "--json"], Some(&case));
    let bearings = v["bearings"].as_array().unwrap();
    let thrust =
        f(&bearings[0], "operating_axial_load_n") - f(&bearings[1], "operating_axial_load_n");
    assert!((thrust - 200.0).abs() < 1e-6, "{thrust}");
    assert!(f(&bearings[0], "heat_generated_w") > f(&bearings[1], "heat_generated_w"));
    let text = stdout(&rolldyn(&["thermal", "-"], Some(&case)));
    assert!(
        text.contains("preload at speed") && text.contains("axial load N (operating)"),
        "{text}"
    );
}

/// `rolldyn run` of a pair: both bearings' dynamics on the shaft, the
/// series with each bearing's channels and the shaft's, the summary's
/// keys, the preload kept near the quasi-static one, the energy balance
/// closed; what a set's run refuses.
#[test]
fn dynamic_run_of_a_pair() {
    let case = pair("kind = \"back_to_back\"\npreload = \"200 N\"");
    let dir = temp_dir("set-run");
    let out = dir.join("run");
    let o = rolldyn(
        &[
            "run",
            "-",
            "--axial-load",
            "0 N",
            "--duration",
            "4 ms",
            "--set",
            "output.sample_rate=\"5 kHz\"",
            "-o",
            out.to_str().unwrap(),
        ],
        Some(&case),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).contains("back_to_back system"), "{}", stdout(&o));
    assert_pair_summary(&out);
    assert_pair_series(&out);
    // `rolldyn spectrum` analyses the set's channels with bearing 0's lines.
    let o = rolldyn(
        &[
            "spectrum",
            out.to_str().unwrap(),
            "--channel",
            "shaft_z_m",
            "--from",
            "0 s",
        ],
        None,
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).contains("BPFO"), "{}", stdout(&o));
    // The report of a set's run: its own sections.
    let o = rolldyn(&["report", out.to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    for heading in [
        "The bearings",
        "Axial loads and cage speeds",
        "The shaft",
        "Energy balance",
    ] {
        assert!(html.contains(heading), "{heading}");
    }
    assert_pair_sweep(&case, &dir);
    // A completed run is not resumed, only extended.
    let o = rolldyn(&["run", "--resume", out.to_str().unwrap()], None);
    assert_refused(&o, &["--until"]);
}

/// The summary of a pair's run: its keys and each bearing's, the balance
/// closed, the two bearings' preloads equal and near the quasi-static one.
fn assert_pair_summary(out: &std::path::Path) {
    let v: serde_json::Value = summary_of(out);
    assert_eq!(
        keys(&v),
        [
            "averaging_window_s",
            "ball_count",
            "ball_diameter_m",
            "bearings",
            "dissipated_energy_j",
            "drive_work_j",
            "energy_balance_relative_error",
            "energy_tolerance",
            "error",
            "final_inner_ring_speed_rpm",
            "inner_ring_speed_rpm",
            "integrator",
            "kind",
            "mean_cage_speed_rpm",
            "mean_contact_angle_inner_deg",
            "mean_contact_angle_outer_deg",
            "mechanical_energy_change_j",
            "mounting_preload_n",
            "pitch_diameter_m",
            "rejected_steps",
            "relative_tolerance",
            "requested_duration_s",
            "rhs_evaluations",
            "samples",
            "simulated_time_s",
            "status",
            "steps",
            "verify",
            "wall_time_s",
        ]
    );
    assert!(v["verify"].is_null());
    assert_eq!(v["status"], "completed");
    assert_eq!(v["samples"], 21);
    assert!(v["energy_balance_relative_error"].as_f64().unwrap() < 1e-3);
    let b = v["bearings"].as_array().unwrap();
    assert_eq!(
        keys(&b[0]),
        [
            "dissipated_energy_j",
            "drive_work_j",
            "largest_inner_load_n",
            "largest_outer_load_n",
            "mean_axial_load_n",
            "mean_cage_speed_rpm",
            "mean_inner_load_n",
            "orientation",
            "position_m",
            "quasistatic_axial_load_n",
        ]
    );
    let f = |b: &serde_json::Value, k: &str| b[k].as_f64().unwrap();
    let (a0, a1, qs) = (
        f(&b[0], "mean_axial_load_n"),
        f(&b[1], "mean_axial_load_n"),
        f(&b[0], "quasistatic_axial_load_n"),
    );
    assert!((a0 - a1).abs() < 1e-3 * a0, "{a0} {a1}");
    assert!((a0 / qs - 1.0).abs() < 0.1, "{a0} vs {qs}");
}

/// The series of a pair's run: each bearing's channels and the shaft's.
fn assert_pair_series(out: &std::path::Path) {
    let names = rolldyn_io::read_parquet(&out.join("timeseries.parquet"))
        .unwrap()
        .names()
        .to_vec();
    for name in [
        "time_s",
        "bearing0_cage_speed_rpm",
        "bearing1_ball0_load_inner_n",
        "bearing1_axial_load_n",
        "shaft_x_m",
        "mechanical_energy_j",
    ] {
        assert!(names.iter().any(|n| n == name), "{name}");
    }
}

/// A sweep of the set in motion: one row per point with each bearing's
/// numbers.
fn assert_pair_sweep(case: &str, dir: &std::path::Path) {
    let o = rolldyn(
        &[
            "run",
            "-",
            "--sweep",
            "speed=8000rpm,10000rpm",
            "--duration",
            "1 ms",
            "--set",
            "output.sample_rate=\"5 kHz\"",
            "-o",
            dir.join("sweep").to_str().unwrap(),
        ],
        Some(case),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let rows: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.join("sweep").join("sweep.json")).unwrap(),
    )
    .unwrap();
    let rows = rows.as_array().unwrap();
    assert_eq!(rows.len(), 2);
    for row in rows {
        assert_eq!(row["status"], "completed");
        assert!(row["bearings.1.mean_axial_load_n"].as_f64().unwrap() > 100.0);
    }
}

/// `rolldyn run` of a `[shaft]`: two 6206 under a gear force, each with
/// its dynamics; the bearings share the 300 N thrust as the quasi-static
/// solution does (their sum balances it); with the second floating, the
/// first takes all of it; friction of a located bearing's ring is refused.
#[test]
fn dynamic_run_of_a_shaft() {
    let case = SHAFT.replace("ORIENTATION", "forward");
    let dir = temp_dir("shaft-run");
    let out = dir.join("run");
    let o = run_into(out.to_str().unwrap(), Some(&case), "3 ms", &[]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = summary_of(&out);
    assert_eq!(v["kind"], "shaft");
    assert!(v["mounting_preload_n"].is_null());
    let b = v["bearings"].as_array().unwrap();
    let f = |b: &serde_json::Value, k: &str| b[k].as_f64().unwrap();
    let thrust: f64 = b.iter().map(|b| f(b, "mean_axial_load_n")).sum();
    assert!((thrust - 300.0).abs() < 0.01 * 300.0, "{thrust}");
    for bearing in b {
        let (dynamic, quasistatic) = (
            f(bearing, "mean_axial_load_n"),
            f(bearing, "quasistatic_axial_load_n"),
        );
        assert!(
            (dynamic / quasistatic - 1.0).abs() < 0.05,
            "{dynamic} vs {quasistatic}"
        );
    }
    // The second bearing floating: its outer ring slides in its bore
    // (here without friction), so the first takes the whole thrust.
    let floating = case.replacen(
        "orientation = \"forward\"",
        "axial = \"floating\"\nhousing_friction = 0",
        1,
    );
    let o = run_into(
        dir.join("floating").to_str().unwrap(),
        Some(&floating),
        "3 ms",
        &[],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = summary_of(&dir.join("floating"));
    let b = v["bearings"].as_array().unwrap();
    let (locating, floating) = (f(&b[0], "mean_axial_load_n"), f(&b[1], "mean_axial_load_n"));
    assert!((locating - 300.0).abs() < 0.01 * 300.0, "{locating} N");
    assert!(floating.abs() < 1.0, "{floating} N");
    assert!(v["energy_balance_relative_error"].as_f64().unwrap().abs() < 1e-3);
    // Only a floating bearing's ring slides.
    let located = case.replacen("orientation = \"forward\"", "housing_friction = 0.1", 1);
    assert_run_refused(&located, "shaft.bearings[1].housing_friction");
}

/// A 1 ms run of `case` is refused (exit 2) with `key` in its message.
fn assert_run_refused(case: &str, key: &str) {
    let o = run_into("/nonexistent/never", Some(case), "1 ms", &[]);
    assert_refused(&o, &[key]);
}

/// An elastic shaft (`shaft.diameter`): nodes at the bearings, the load
/// and the reference point; the shaft's bending tilts the inner rings far
/// more than the rigid shaft's tilt; the loads still balance; what it
/// does not do yet is refused with the key.
#[test]
fn an_elastic_shaft_tilts_its_bearings() {
    let rigid = SHAFT.replace("ORIENTATION", "forward");
    let elastic = rigid.replacen("[shaft]\n", "[shaft]\ndiameter = \"25 mm\"\n", 1);
    let solve = |text: &str| json(&["quasistatic", "-", "--json"], Some(text));
    let (r, e) = (solve(&rigid), solve(&elastic));
    assert!(r["arrangement"]["shaft_nodes"].is_null());
    let nodes = e["arrangement"]["shaft_nodes"].as_array().unwrap();
    let at: Vec<f64> = nodes
        .iter()
        .map(|n| n["position_m"].as_f64().unwrap())
        .collect();
    assert_eq!(at, [-0.06, 0.0, 0.02, 0.06]);
    let tilt = |v: &serde_json::Value, i: usize| {
        v["arrangement"]["bearings"][i]["misalignment_rad"]
            .as_f64()
            .unwrap()
    };
    for i in 0..2 {
        assert!(
            tilt(&e, i) > 5.0 * tilt(&r, i),
            "{} vs {}",
            tilt(&e, i),
            tilt(&r, i)
        );
    }
    let carried: f64 = e["arrangement"]["bearings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| b["shaft_load"][2].as_f64().unwrap())
        .sum();
    assert!((carried + 4000.0).abs() < 1e-6 * 4000.0, "{carried}");
    let text = stdout(&rolldyn(&["quasistatic", "-"], Some(&elastic)));
    assert!(
        text.contains("elastic shaft") && text.contains("misalignment"),
        "{text}"
    );
    for (case, args, key) in [
        (
            rigid.replacen("[shaft]\n", "[shaft]\nbore = \"10 mm\"\n", 1),
            vec!["quasistatic", "-"],
            "shaft.bore",
        ),
        (
            elastic.replacen("[shaft]\n", "[shaft]\nbore = \"30 mm\"\n", 1),
            vec!["quasistatic", "-"],
            "shaft.bore",
        ),
        (
            elastic.clone(),
            vec!["quasistatic", "-", "--sweep", "speed=1000rpm,2000rpm"],
            "shaft.diameter",
        ),
        (
            elastic.clone(),
            vec!["run", "-", "--duration", "1 ms", "-o", "/nonexistent/never"],
            "shaft.diameter",
        ),
    ] {
        let o = rolldyn(&args, Some(&case));
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(key), "{args:?}: {}", stderr(&o));
    }
}

/// A moment among the shaft loads: on a rigid shaft the same as that
/// moment about the reference point (`operating.moment_y`).
#[test]
fn a_shaft_load_may_be_a_moment() {
    let base = SHAFT.replace("ORIENTATION", "forward");
    let at_load = base.replacen(
        "force_x = \"300 N\"\n",
        "force_x = \"300 N\"\nmoment_y = \"10 N.m\"\n",
        1,
    );
    let solve = |text: &str, extra: &[&str]| {
        let mut args = vec!["quasistatic", "-", "--json"];
        args.extend_from_slice(extra);
        json(&args, Some(text))["arrangement"]["shaft_displacement"].clone()
    };
    let (a, b) = (
        solve(&at_load, &[]),
        solve(&base, &["--set", "operating.moment_y=\"10 N.m\""]),
    );
    for k in 0..5 {
        let (x, y) = (a[k].as_f64().unwrap(), b[k].as_f64().unwrap());
        assert!(
            (x - y).abs() <= 1e-9 * y.abs().max(1e-12),
            "{k}: {x} vs {y}"
        );
    }
}

/// Fits on a shaft's bearing (`[shaft.bearings.fits]`): the same mounted
/// clearance as the bearing alone with `[fits]`; bad fits name the
/// bearing's key.
#[test]
fn a_shaft_bearing_takes_its_fits() {
    let fits = "shaft_tolerance = \"k5\"\nhousing_tolerance = \"H7\"\n";
    let case = SHAFT.replace("ORIENTATION", "forward").replacen(
        "position = \"-60 mm\"\n",
        &format!("position = \"-60 mm\"\n[shaft.bearings.fits]\n{fits}"),
        1,
    );
    let v = json(&["quasistatic", "-", "--json"], Some(&case));
    let bearings = &v["arrangement"]["bearings"];
    let mounted = |f: &serde_json::Value| f["diametral_clearance_mounted_m"].as_f64().unwrap();
    let alone = json(
        &["quasistatic", "-", "--json"],
        Some(&format!(
            "{}\n[fits]\n{fits}",
            stdout(&rolldyn(&["new", "--preset", "6206"], None))
        )),
    );
    assert!(bearings[1]["quasistatic"]["fits"].is_null());
    let on_shaft = mounted(&bearings[0]["quasistatic"]["fits"]);
    assert!(
        (on_shaft - mounted(&alone["fits"])).abs() < 1e-12,
        "{on_shaft}"
    );
    assert!(on_shaft < 12.5e-6);
    let o = rolldyn(
        &["quasistatic", "-"],
        Some(&case.replace("\"k5\"", "\"q9\"")),
    );
    assert_refused(&o, &["shaft.bearings[0].fits"]);
}

/// `rolldyn thermal` of a `[shaft]`: every bearing's network under the
/// case's `[thermal]`; the more loaded bearing runs warmer; the shaft's
/// axial growth moves the located bearings' offsets apart; an elastic
/// shaft is refused with the key.
#[test]
fn thermal_steady_state_of_a_shaft() {
    let case = format!(
        "{}\n[thermal]\noil_flow = \"0.5 L/min\"\n",
        SHAFT.replace("ORIENTATION", "forward")
    );
    let v = json(&["thermal", "-", "--json"], Some(&case));
    assert_eq!(v["kind"], "shaft");
    assert_eq!(v["converged"], true);
    assert!(v["operating_preload_at_speed_n"].is_null());
    let b = v["bearings"].as_array().unwrap();
    let f = |b: &serde_json::Value, k: &str| b[k].as_f64().unwrap();
    // Bearing 1 carries two thirds of the radial load.
    assert!(f(&b[1], "heat_generated_w") > f(&b[0], "heat_generated_w"));
    assert!(f(&b[1]["temperatures_c"], "inner_ring") > f(&b[0]["temperatures_c"], "inner_ring"));
    let strain = f(&v, "axial_strain");
    assert!(strain > 0.0);
    for (bearing, x) in b.iter().zip([-0.06, 0.06]) {
        let moved = f(bearing, "operating_axial_offset_m") - f(bearing, "reference_axial_offset_m");
        assert!(
            (moved - x * strain).abs() < 1e-12,
            "{moved} vs {}",
            x * strain
        );
    }
    let elastic = case.replacen("[shaft]\n", "[shaft]\ndiameter = \"25 mm\"\n", 1);
    let o = rolldyn(&["thermal", "-"], Some(&elastic));
    assert_refused(&o, &["shaft.diameter"]);
}

/// A set's run is the same bytes on one thread as on two (the balls of
/// each bearing are evaluated across threads, summed in ball order).
#[test]
fn a_set_run_is_the_same_whatever_the_threads() {
    use std::process::Command;
    let case = pair("kind = \"back_to_back\"\npreload = \"200 N\"");
    let dir = temp_dir("set-threads");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("case.toml");
    std::fs::write(&path, &case).unwrap();
    let run = |threads: &str| {
        let out = dir.join(format!("run-{threads}"));
        let o = Command::new(env!("CARGO_BIN_EXE_rolldyn"))
            .args([
                "run",
                path.to_str().unwrap(),
                "--duration",
                "3 ms",
                "-o",
                out.to_str().unwrap(),
            ])
            .env("RAYON_NUM_THREADS", threads)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        common::series_bytes(&out)
    };
    assert_eq!(run("1"), run("2"));
    std::fs::remove_dir_all(&dir).ok();
}

/// A gear mesh's fluctuation (`mesh_order`, `mesh_fluctuation` of a
/// `[[shaft.loads]]` entry) shakes the shaft in a run, its work in the
/// energy balance; half a pair of keys is refused.
#[test]
fn a_gear_mesh_shakes_the_shaft() {
    let base = SHAFT.replace("ORIENTATION", "forward");
    let mesh = base.replacen(
        "force_x = \"300 N\"\n",
        "force_x = \"300 N\"\nmesh_order = 23\nmesh_fluctuation = 0.05\n",
        1,
    );
    let dir = temp_dir("mesh");
    let shake = |case: &str, tag: &str| {
        let out = dir.join(tag);
        let o = run_into(out.to_str().unwrap(), Some(case), "4 ms", &[]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let s: serde_json::Value = summary_of(&out);
        assert!(s["energy_balance_relative_error"].as_f64().unwrap() < 1e-3);
        let series = rolldyn_io::read_parquet(&out.join("timeseries.parquet")).unwrap();
        let (t, z) = (
            series.column("time_s").unwrap(),
            series.column("shaft_z_m").unwrap(),
        );
        let late: Vec<f64> = t
            .iter()
            .zip(z)
            .filter(|(t, _)| **t >= 2e-3)
            .map(|(_, z)| *z)
            .collect();
        late.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
            - late.iter().cloned().fold(f64::INFINITY, f64::min)
    };
    let (quiet, shaken) = (shake(&base, "quiet"), shake(&mesh, "mesh"));
    assert!(shaken > 10.0 * quiet, "{shaken} vs {quiet}");
    let half = base.replacen(
        "force_x = \"300 N\"\n",
        "force_x = \"300 N\"\nmesh_order = 23\n",
        1,
    );
    let o = rolldyn(&["check", "-"], Some(&half));
    assert_refused(&o, &["shaft.loads[0].mesh_fluctuation"]);
    std::fs::remove_dir_all(&dir).ok();
}

/// A bearing given inline on the shaft (`[shaft.bearings.bearing]`, here
/// the 6206 preset's geometry written out) is that bearing: the shaft's
/// solution equals the presets'; a bad inline value is named with its
/// shaft key, by `check` too.
#[test]
fn an_inline_bearing_sits_on_a_shaft() {
    let presets = json(
        &["quasistatic", "-", "--json"],
        Some(&SHAFT.replace("ORIENTATION", "forward")),
    );
    let inline = SHAFT.replace("ORIENTATION", "forward").replacen(
        "preset = \"6206\"\nposition = \"60 mm\"\norientation = \"forward\"",
        "position = \"60 mm\"\norientation = \"forward\"\n[shaft.bearings.bearing]\nball_diameter = \"9.525 mm\"\nball_count = 9\npitch_diameter = \"46 mm\"\ndiametral_clearance = \"12.5 um\"\ninner_groove_curvature = 0.52\nouter_groove_curvature = 0.52",
        1,
    );
    assert!(inline.contains("[shaft.bearings.bearing]"));
    let v = json(&["quasistatic", "-", "--json"], Some(&inline));
    for k in 0..2 {
        let load = |v: &serde_json::Value| {
            v["arrangement"]["bearings"][k]["radial_load_n"]
                .as_f64()
                .unwrap()
        };
        assert!(
            (load(&presets) - load(&v)).abs() < 1e-6 * load(&presets),
            "{} vs {}",
            load(&presets),
            load(&v)
        );
    }
    let bad = inline.replace("ball_count = 9", "ball_count = 2");
    for command in ["quasistatic", "check"] {
        let o = rolldyn(&[command, "-"], Some(&bad));
        assert_eq!(o.status.code(), Some(2), "{command}");
        let e = stderr(&o);
        assert!(
            e.contains("shaft.bearings[1].bearing") && e.contains("ball_count"),
            "{command}: {e}"
        );
    }
}

/// An inline bearing takes its own materials (`[shaft.bearings.materials]`):
/// steel written out is the default, silicon nitride balls (a hybrid
/// bearing, E 310 GPa against 208) make it stiffer under the same load;
/// the tables are refused beside a preset, and a bad material is named
/// with its shaft key.
#[test]
fn an_inline_bearing_takes_its_own_materials() {
    let inline = SHAFT.replace("ORIENTATION", "forward").replacen(
        "preset = \"6206\"\nposition = \"60 mm\"\norientation = \"forward\"",
        "position = \"60 mm\"\norientation = \"forward\"\n[shaft.bearings.bearing]\nball_diameter = \"9.525 mm\"\nball_count = 9\npitch_diameter = \"46 mm\"\ndiametral_clearance = \"12.5 um\"\ninner_groove_curvature = 0.52\nouter_groove_curvature = 0.52\n[shaft.bearings.materials]\nball = \"BALL\"",
        1,
    );
    let displacement = |ball: &str| {
        let v = json(
            &["quasistatic", "-", "--json"],
            Some(&inline.replace("BALL", ball)),
        );
        v["arrangement"]["bearings"][1]["quasistatic"]["radial_displacement_z_m"]
            .as_f64()
            .unwrap()
            .abs()
    };
    let plain = SHAFT.replace("ORIENTATION", "forward");
    let preset = json(&["quasistatic", "-", "--json"], Some(&plain))["arrangement"]["bearings"][1]
        ["quasistatic"]["radial_displacement_z_m"]
        .as_f64()
        .unwrap()
        .abs();
    let (steel, hybrid) = (displacement("steel_52100"), displacement("silicon_nitride"));
    assert!(
        (steel - preset).abs() < 1e-9 * preset,
        "{steel} vs {preset}"
    );
    assert!(hybrid < 0.97 * steel, "hybrid {hybrid} vs steel {steel}");
    let beside_preset = plain.replacen(
        "orientation = \"forward\"",
        "orientation = \"forward\"\n[shaft.bearings.materials]\nball = \"silicon_nitride\"",
        1,
    );
    let bad = inline.replace("BALL", "glass");
    for (case, key) in [
        (&beside_preset, "shaft.bearings[1].materials"),
        (&bad, "shaft.bearings[1].bearing"),
    ] {
        let o = rolldyn(&["quasistatic", "-"], Some(case));
        assert_eq!(o.status.code(), Some(2));
        let e = stderr(&o);
        assert!(e.contains(key), "{e}");
    }
    assert!(stderr(&rolldyn(&["quasistatic", "-"], Some(&bad))).contains("glass"));
    // In motion the inline bearing needs its inner ring and cage, asked
    // for with its shaft key.
    assert_run_refused(
        &inline.replace("BALL", "silicon_nitride"),
        "shaft.bearings[1].inner_ring.mass",
    );
}
