//! End-to-end tests of the `rolldyn` binary: acceptance checks of the
//! foundation issue, exit codes, and the stable JSON keys.

#![allow(clippy::unwrap_used)]

use crate::common;

use crate::common::{
    FASTSIM, assert_ok, assert_refused, json, keys, rolldyn, run_into, stderr, stdout, summary_of,
    temp_dir,
};
use rolldyn_case::presets::PRESETS;
use serde_json::Value;

#[test]
fn every_preset_round_trips_through_new_and_check() {
    for p in PRESETS {
        let new = rolldyn(&["new", "--preset", p.name], None);
        assert!(new.status.success(), "{}: {}", p.name, stderr(&new));
        let check = rolldyn(&["check", "-"], Some(&stdout(&new)));
        assert!(check.status.success(), "{}: {}", p.name, stderr(&check));
        assert!(stdout(&check).contains("valid"));
    }
}

#[test]
fn frequencies_reproduce_seed001_table3() {
    // Acceptance: 7008C at 10 000 rpm within 0.5 % of Deng et al. 2022 Table 3 "theoretical".
    let new = stdout(&rolldyn(&["new", "--preset", "7008C"], None));
    let f = json(
        &["frequencies", "-", "--speed", "10000 rpm", "--json"],
        Some(&new),
    );
    let rel =
        |key: &str, reference: f64| ((f[key].as_f64().expect(key) - reference) / reference).abs();
    assert!(rel("cage_hz", 73.96) < 0.005);
    assert!(rel("shaft_hz", 166.7) < 0.005);
    assert!(rel("ball_spin_hz", 699.7) < 0.005);
    assert!(rel("bpfo_hz", 1627.2) < 0.005);
    assert!(rel("bpfi_hz", 2040.3) < 0.005);
    let lines = f["waviness"].as_array().expect("waviness");
    let find = |part: &str, order: u64, motion: &str| {
        lines
            .iter()
            .find(|l| l["part"] == part && l["order"] == order && l["motion"] == motion)
            .and_then(|l| l["frequency_hz"].as_f64())
            .expect("line")
    };
    for (order, hz) in [(21, 1873.6), (23, 2207.0)] {
        assert!((find("inner_race", order, "radial") - hz).abs() / hz < 0.005);
    }
    assert!((find("ball", 4, "axial") - 2798.8).abs() / 2798.8 < 0.005);
}

#[test]
fn json_keys_are_stable() {
    let f = json(&["frequencies", "--json"], None);
    assert_eq!(
        keys(&f),
        [
            "ball_defect_hz",
            "ball_spin_hz",
            "bpfi_hz",
            "bpfo_hz",
            "cage_hz",
            "cage_speed_rpm",
            "contact_angle_deg",
            "orders",
            "shaft_hz",
            "speed_rpm",
            "waviness"
        ]
    );
    let c = json(&["contact", "--load", "500 N", "--json"], None);
    assert_eq!(
        keys(&c),
        [
            "contact_stiffness_model",
            "effective_modulus_pa",
            "inner",
            "load_n",
            "outer"
        ]
    );
    assert_eq!(
        keys(&c["inner"]),
        [
            "approach_m",
            "contact_angle_deg",
            "curvature_difference",
            "curvature_sum_per_m",
            "elliptic_e",
            "elliptic_k",
            "ellipticity",
            "load_n",
            "max_pressure_pa",
            "rolling_radius_m",
            "semi_major_m",
            "semi_minor_m",
            "stiffness_n_per_m1_5",
            "transverse_radius_m"
        ]
    );
    let check = json(&["check", "--json"], None);
    for k in [
        "geometry",
        "inner_contact",
        "outer_contact",
        "frequencies",
        "assumptions",
    ] {
        assert!(check.get(k).is_some(), "check --json lacks {k}");
    }
}

#[test]
fn contact_is_consistent_hertz() {
    // Q = K_c δ^1.5 and p₀ = 3Q/(2π a b) on both raceways.
    let c = json(
        &["contact", "--load", "1 kN", "--angle", "20 deg", "--json"],
        None,
    );
    for ring in ["inner", "outer"] {
        let r = &c[ring];
        let f = |k: &str| r[k].as_f64().expect(k);
        assert!((f("contact_angle_deg") - 20.0).abs() < 1e-12);
        let q = f("stiffness_n_per_m1_5") * f("approach_m").powf(1.5);
        assert!((q - 1000.0).abs() < 1e-6, "{ring}: {q}");
        let p0 =
            3.0 * 1000.0 / (2.0 * std::f64::consts::PI * f("semi_major_m") * f("semi_minor_m"));
        assert!((p0 - f("max_pressure_pa")).abs() / p0 < 1e-12);
    }
}

#[test]
fn overrides_apply() {
    let f = json(&["frequencies", "--speed", "60 rpm", "--json"], None);
    assert!((f["shaft_hz"].as_f64().unwrap() - 1.0).abs() < 1e-12);
    let c = json(
        &[
            "check",
            "--axial-load",
            "1 kN",
            "--radial-load",
            "0.5 kN",
            "--json",
        ],
        None,
    );
    assert_eq!(c["force_x_n"].as_f64(), Some(1000.0));
    assert_eq!(c["force_z_n"].as_f64(), Some(500.0));
    let c = json(&["check", "--set", "bearing.ball_count=20", "--json"], None);
    assert_eq!(c["geometry"]["ball_count"].as_u64(), Some(20));
    // Negative loads need no `=`.
    let c = json(&["check", "--radial-load", "-100 N", "--json"], None);
    assert_eq!(c["force_z_n"].as_f64(), Some(-100.0));
}

#[test]
fn bad_input_exits_2_with_a_located_message() {
    let bad = "[bearing]\npreset = \"7008C\"\nball_diameter = \"6.35 mmm\"\n";
    let o = rolldyn(&["check", "-"], Some(bad));
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(
        e.contains("<stdin>:3:17: bearing.ball_diameter = \"6.35 mmm\": unknown unit"),
        "{e}"
    );
    assert!(o.stdout.is_empty(), "nothing written on bad input");

    let o = rolldyn(
        &["check", "--set", "bearing.free_contact_angle=75 deg"],
        None,
    );
    assert_refused(&o, &["--set bearing.free_contact_angle=75 deg"]);

    let o = rolldyn(&["check", "/nonexistent/case.toml"], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("cannot read case file"));

    let o = rolldyn(&["contact", "--load", "500"], None);
    assert_refused(&o, &["--load 500: missing unit"]);

    let o = rolldyn(&["new", "--preset", "nope"], None);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("available: 7008C"));

    let o = rolldyn(
        &["frequencies", "-"],
        Some("[bearing]\npreset = \"6205\"\n"),
    );
    assert_refused(&o, &["no speed"]);
}

#[test]
fn schema_and_presets() {
    let s = json(&["schema"], None);
    assert!(s["properties"]["bearing"].is_object());
    let list = json(&["presets", "--json"], None);
    let names: Vec<&str> = list
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|p| p["name"].as_str())
        .collect();
    for n in [
        "6304",
        "7008C",
        "7218B",
        "ceramic_45x75",
        "acbb_30x62",
        "6205",
        "6203",
        "6206",
    ] {
        assert!(names.contains(&n), "{n}");
    }
    let text = stdout(&rolldyn(&["presets"], None));
    assert!(text.contains("Deng et al. 2022"));
}

#[test]
fn check_lists_assumptions() {
    let o = rolldyn(&["check", "-"], Some("[bearing]\npreset = \"7218B\"\n"));
    assert_ok(&o);
    let out = stdout(&o);
    assert!(
        out.contains("bearing.inner_groove_curvature") && out.contains("0.5232"),
        "{out}"
    );
}

#[test]
fn quasistatic_single_point_and_json_keys() {
    let q = json(&["quasistatic", "--json"], None);
    for k in [
        "speed_rpm",
        "cage_speed_rpm",
        "axial_displacement_m",
        "radial_displacement_y_m",
        "radial_displacement_z_m",
        "tilt_y_rad",
        "tilt_z_rad",
        "stiffness_n_per_m",
        "tilt_stiffness_n_m_per_rad",
        "stiffness_matrix",
        "balls",
    ] {
        assert!(q.get(k).is_some(), "quasistatic --json lacks {k}");
    }
    let ball = &q["balls"][0];
    for k in [
        "contact_angle_inner_deg",
        "contact_angle_outer_deg",
        "load_inner_n",
        "load_outer_n",
        "orbital_speed_rpm",
        "spin_speed_rpm",
        "attitude_deg",
        "spin_to_roll_inner",
        "spin_to_roll_outer",
        "semi_major_inner_m",
        "max_pressure_outer_pa",
    ] {
        assert!(ball.get(k).is_some(), "ball lacks {k}");
    }
    assert_eq!(q["balls"].as_array().unwrap().len(), 22);
    assert_eq!(q["speed_rpm"].as_f64(), Some(10_000.0));
    // Axial equilibrium: Σ Q_i sin α_i = F_x (pure axial load, all balls alike).
    let sum: f64 = q["balls"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| {
            b["load_inner_n"].as_f64().unwrap()
                * b["contact_angle_inner_deg"]
                    .as_f64()
                    .unwrap()
                    .to_radians()
                    .sin()
        })
        .sum();
    assert!((sum - 200.0).abs() < 1e-6, "{sum}");
    let text = stdout(&rolldyn(&["quasistatic", "--speed", "0 rpm"], None));
    assert!(text.contains("Static load distribution"), "{text}");
}

#[test]
fn quasistatic_sweep_writes_csv_and_json() {
    let dir = std::env::temp_dir().join(format!("rolldyn-sweep-test-{}", std::process::id()));
    let dir_s = dir.to_string_lossy().into_owned();
    let o = rolldyn(
        &[
            "quasistatic",
            "--sweep",
            "speed=0rpm..10000rpm/3",
            "--sweep",
            "axial=100N,1kN",
            "-o",
            &dir_s,
        ],
        None,
    );
    assert_ok(&o);
    let csv = std::fs::read_to_string(dir.join("sweep.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 6);
    assert!(csv.starts_with("speed_rpm,force_x_n"));
    let rows: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("sweep.json")).unwrap()).unwrap();
    assert_eq!(rows.as_array().unwrap().len(), 6);
    assert!(
        rows.as_array()
            .unwrap()
            .iter()
            .all(|r| r["converged"] == true)
    );
    assert_eq!(rows[5]["speed_rpm"].as_f64(), Some(10_000.0));
    assert_eq!(rows[5]["force_x_n"].as_f64(), Some(1000.0));
    std::fs::remove_dir_all(&dir).ok();
    let o = rolldyn(&["quasistatic", "--sweep", "speed=0rpm..1rpm"], None);
    assert_refused(&o, &["point count"]);
    let o = rolldyn(&["quasistatic", "--control", "sideways"], None);
    assert_eq!(o.status.code(), Some(2));
}

/// A refused sweep point (7218B with a free ring, F_x = 100 N under F_z =
/// 50 kN: below the least axial load) is counted apart from failures, and
/// its least axial load is a column.
#[test]
fn quasistatic_sweep_reports_refused_points_with_their_least_axial_load() {
    let dir = temp_dir("sweep-refused");
    let dir_s = dir.to_string_lossy().into_owned();
    let case = stdout(&rolldyn(&["new", "--preset", "7218B"], None));
    let o = rolldyn(
        &[
            "quasistatic",
            "-",
            "--sweep",
            "speed=4444rpm",
            "--sweep",
            "axial=100N,20kN",
            "--sweep",
            "radial=50kN",
            // A free ring: held in tilt, the ring carries the radial load
            // with a moment and needs no axial load.
            "--set",
            "operating.fixed_tilt=false",
            "-o",
            &dir_s,
        ],
        Some(&case),
    );
    assert_ok(&o);
    assert!(
        stdout(&o).contains("(1 refused: below the least axial load")
            && stdout(&o).contains("; 0 failed;"),
        "{}",
        stdout(&o)
    );
    let rows: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("sweep.json")).unwrap()).unwrap();
    let least = rows[0]["least_axial_load_n"].as_f64().expect("refused");
    assert!(least > 100.0, "{least}");
    assert_eq!(rows[0]["converged"], false);
    assert!(rows[1]["least_axial_load_n"].is_null());
    assert_eq!(rows[1]["converged"], true);
    let csv = std::fs::read_to_string(dir.join("sweep.csv")).unwrap();
    assert!(
        csv.lines()
            .next()
            .unwrap()
            .ends_with(",error,least_axial_load_n")
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn run_writes_parquet_and_summary() {
    use arrow_array::Float64Array;
    use parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder;
    let dir = temp_dir("run");
    let d = dir.to_string_lossy().into_owned();
    let o = run_into(&d, None, "1 ms", &[]);
    assert_ok(&o);
    let summary: Value = summary_of(&dir);
    assert_eq!(summary["status"], "completed");
    assert_eq!(summary["simulated_time_s"].as_f64(), Some(0.001));
    for k in [
        "mean_cage_speed_rpm",
        "pure_rolling_cage_speed_rpm",
        "cage_speed_ratio",
        "cage_sliding_rate",
        "mean_load_inner_n",
        "max_load_outer_n",
        "energy_balance_relative_error",
        "mean_slide_to_roll_inner",
        "mean_spin_to_roll_outer",
        "mean_attitude_deg",
        "mean_yaw_deg",
        "max_abs_yaw_deg",
        "ball_pass_jitter",
        "ball_pass_interval_s",
        "steps",
        "rejected_steps",
        "rhs_evaluations",
        "jacobian_evaluations",
        "jacobian_rhs_evaluations",
        "fast_part_jacobians",
        "factorizations",
        "wall_time_s",
    ] {
        assert!(summary.get(k).is_some(), "summary lacks {k}");
    }
    // The default case runs `auto`, which stays with the stiff method on
    // a smooth run and reports its work and settings (the preset's
    // tolerance, the stiff method's default largest step).
    assert_eq!(summary["integrator"], "auto");
    assert_eq!(summary["integrator_switches"], 0);
    assert_eq!(summary["explicit_steps"], 0);
    assert_eq!(summary["relative_tolerance"], 2e-3);
    assert_eq!(summary["max_step_s"], 1e-4);
    assert!(summary["jacobian_evaluations"].as_u64().unwrap() >= 1);
    assert!(summary["factorizations"].as_u64().unwrap() >= summary["steps"].as_u64().unwrap() / 50);
    // Outer-raceway control start: the outer contacts roll with little
    // spin, the inner ones spin (Jones–Harris); the ball axis lies near the
    // contact angles (7008C at 200 N: 13–18°) with no yaw under pure axial load.
    let f = |k: &str| summary[k].as_f64().unwrap();
    assert!(f("mean_spin_to_roll_inner") > 5.0 * f("mean_spin_to_roll_outer").abs());
    assert!((10.0..20.0).contains(&f("mean_attitude_deg")));
    assert!(f("max_abs_yaw_deg") < 1.0);
    assert!(
        summary["energy_balance_relative_error"]
            .as_f64()
            .unwrap()
            .abs()
            < 1e-3
    );
    let file = std::fs::File::open(common::first_part(&dir)).unwrap();
    let builder = ParquetRecordBatchReaderBuilder::try_new(file).unwrap();
    let schema = builder.schema().clone();
    let cage = schema.index_of("cage_speed_rpm").unwrap();
    assert_eq!(
        schema
            .field(cage)
            .metadata()
            .get("unit")
            .map(String::as_str),
        Some("rpm")
    );
    for channel in [
        "ball21_load_inner_n",
        "ball21_slide_to_roll_outer",
        "ball21_spin_to_roll_inner",
        "ball21_film_inner_m",
        "ball21_attitude_deg",
        "ball21_yaw_deg",
        "outer_ring_y_m",
    ] {
        assert!(schema.index_of(channel).is_ok(), "no channel {channel}");
    }
    let batch = builder.build().unwrap().next().unwrap().unwrap();
    // 20 kHz over 1 ms: samples at 0, 50 µs, …, 1 ms.
    assert_eq!(batch.num_rows(), 21);
    let t = batch
        .column(0)
        .as_any()
        .downcast_ref::<Float64Array>()
        .unwrap();
    assert!((t.value(20) - 1e-3).abs() < 1e-15);
    std::fs::remove_dir_all(&dir).ok();
}

/// VALIDATION B7 for dynamic runs: the same case gives bit-identical
/// time series (and summaries, but for the wall time), whatever the
/// number of threads the balls' contacts are evaluated on (the default
/// case's 22 balls with grid traction run in parallel on ≥ 2 threads,
/// serially on 1).
#[test]
fn run_reports_missing_dynamic_data() {
    let dir = temp_dir("run-bad");
    let d = dir.to_string_lossy().into_owned();
    let o = rolldyn(
        &["run", "-", "--duration", "1 ms", "-o", &d],
        // A bearing given by its geometry, without a cage.
        Some(
            "[bearing]\nball_diameter = \"7.94 mm\"\nball_count = 9\npitch_diameter = \"39 mm\"\n\
             diametral_clearance = \"0.012 mm\"\ninner_groove_curvature = 0.52\n\
             outer_groove_curvature = 0.52\nbore = \"25 mm\"\noutside_diameter = \"52 mm\"\n\
             width = \"15 mm\"\n[operating]\nspeed = \"1797 rpm\"\nforce_z = \"100 N\"\n",
        ),
    );
    assert_refused(&o, &["cage.mass"]);
    assert!(
        !dir.join("summary.json").exists(),
        "nothing written on bad input"
    );
}

/// `spectrum --harmonics` beyond the band marks the lines up to the
/// spectrum's end, not a million harmonics of each.
#[test]
fn spectrum_lines_stop_at_the_band() {
    let dir = temp_dir("spectrum-band");
    let d = dir.to_string_lossy().into_owned();
    let o = run_into(&d, None, "2 ms", &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = rolldyn(&["spectrum", &d, "--harmonics", "1000000", "--json"], None);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    let nyquist = 0.5 * v["sample_rate_hz"].as_f64().unwrap();
    let lines = v["lines"].as_array().unwrap();
    assert!(
        !lines.is_empty() && lines.len() < 20_000,
        "{} lines",
        lines.len()
    );
    assert!(
        lines
            .iter()
            .all(|l| l["frequency_hz"].as_f64().unwrap() <= nyquist + 1e-9)
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// The ceramic bearing at 15 000 rpm under a held tilt and a film in the
/// approach (examples/seed003's command: the paper's bearing, without the
/// mounting's preload) has negative conventional stiffnesses: the text
/// says what they mean.
#[test]
fn negative_conventional_stiffness_is_explained() {
    let case = PRESETS
        .iter()
        .find(|p| p.name == "ceramic_45x75")
        .unwrap()
        .without_mounting();
    let case = case.as_str();
    let o = rolldyn(
        &[
            "quasistatic",
            "-",
            "--fix-tilt",
            "--set",
            "model.film_in_approach=true",
            "--set",
            "lubricant.inlet_distance_ratio=1.5",
        ],
        Some(case),
    );
    assert_ok(&o);
    let text = stdout(&o);
    assert!(text.contains("axial -"), "{text}");
    assert!(text.contains("K is not positive definite"), "{text}");
}

/// A FASTSIM run records the creepage and stick channels and their means.
#[test]
fn fastsim_run_records_creepages() {
    use parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder;
    let dir = temp_dir("fastsim-run");
    let d = dir.to_string_lossy().into_owned();
    let o = run_into(&d, None, "1 ms", &[FASTSIM]);
    assert_ok(&o);
    let summary: Value = summary_of(&dir);
    for k in [
        "mean_creepage_longitudinal_inner",
        "mean_creepage_longitudinal_outer",
        "mean_creepage_lateral_inner",
        "mean_creepage_lateral_outer",
        "mean_creepage_spin_inner_1_m",
        "mean_creepage_spin_outer_1_m",
        "mean_stick_fraction_inner",
        "mean_stick_fraction_outer",
    ] {
        assert!(summary.get(k).is_some(), "summary lacks {k}");
    }
    let stick = summary["mean_stick_fraction_outer"].as_f64().unwrap();
    assert!((0.0..=1.0).contains(&stick));
    let file = std::fs::File::open(common::first_part(&dir)).unwrap();
    let schema = ParquetRecordBatchReaderBuilder::try_new(file)
        .unwrap()
        .schema()
        .clone();
    for channel in [
        "ball0_creepage_longitudinal_inner",
        "ball21_creepage_spin_outer_1_m",
        "ball21_stick_fraction_inner",
    ] {
        assert!(schema.index_of(channel).is_ok(), "no channel {channel}");
    }
    // Without FASTSIM there are no creepage keys.
    let plain = temp_dir("plain-run");
    let p = plain.to_string_lossy().into_owned();
    assert!(run_into(&p, None, "0.2 ms", &[]).status.success());
    let s: Value = summary_of(&plain);
    assert!(s.get("mean_stick_fraction_inner").is_none());
    std::fs::remove_dir_all(&dir).ok();
    std::fs::remove_dir_all(&plain).ok();
}

/// `quasistatic --control traction` (no raceway control): stable keys, a
/// cage speed between the inner- and outer-control Jones–Harris values,
/// FASTSIM stick fractions.
#[test]
fn traction_consistent_quasistatic() {
    let r = json(&["quasistatic", "--control", "traction", "--json"], None);
    assert_eq!(
        keys(&r),
        [
            "axial_displacement_m",
            "balls",
            "cage_speed_ratio",
            "cage_speed_rpm",
            "force_x_n",
            "force_y_n",
            "force_z_n",
            "raceway_control",
            "radial_displacement_y_m",
            "radial_displacement_z_m",
            "speed_rpm",
            "tilt_y_rad",
            "tilt_z_rad",
            "traction_law"
        ]
    );
    assert_eq!(
        keys(&r["balls"][0]),
        [
            "attitude_deg",
            "azimuth_deg",
            "contact_angle_inner_deg",
            "contact_angle_outer_deg",
            "load_inner_n",
            "load_outer_n",
            "orbital_speed_rpm",
            "slide_to_roll_inner",
            "slide_to_roll_outer",
            "spin_to_roll_inner",
            "spin_to_roll_outer",
            "stick_fraction_inner",
            "stick_fraction_outer",
            "yaw_deg"
        ]
    );
    let csr = r["cage_speed_ratio"].as_f64().unwrap();
    let jh = |control: &str| {
        json(&["quasistatic", "--control", control, "--json"], None)["cage_speed_ratio"]
            .as_f64()
            .unwrap()
    };
    let (inner, outer) = (jh("inner"), jh("outer"));
    assert!(
        csr > inner.min(outer) && csr < inner.max(outer),
        "{csr} outside [{inner}, {outer}]"
    );
    let f = json(
        &[
            "quasistatic",
            "--control",
            "traction",
            "--set",
            FASTSIM,
            "--json",
        ],
        None,
    );
    assert_eq!(f["traction_law"], "fastsim");
    assert!(f["balls"][0]["stick_fraction_outer"].as_f64().is_some());
}

/// `quasistatic --control traction` is refused with --sweep, and gives a
/// clear error where the balls have no rolling equilibrium.
#[test]
fn traction_consistent_quasistatic_refusals() {
    let o = rolldyn(
        &[
            "quasistatic",
            "--control",
            "traction",
            "--sweep",
            "speed=1000rpm,2000rpm",
        ],
        None,
    );
    assert_refused(&o, &["not with --sweep"]);
    let low = "[bearing]\npreset = \"7218B\"\n[operating]\nspeed = \"1000 rpm\"\nforce_x = \"10 kN\"\n[model]\ntraction = { law = \"fastsim\", friction = 0.001 }\n";
    let o = rolldyn(&["quasistatic", "-", "--control", "traction"], Some(low));
    assert_refused(&o, &["no traction-consistent equilibrium"]);
}

/// A run started from the traction-consistent state stays there.
#[test]
fn a_run_starts_from_the_traction_consistent_state() {
    // With a ball-guided cage (the quasi-static state leaves out the guide
    // land's drag on the cage) and without gravity (the quasi-static
    // commands take the operating loads, a run's start adds the ring's
    // weight) the run stays at the quasi-static state.
    let ball_guided = json(
        &[
            "quasistatic",
            "--control",
            "traction",
            "--set",
            "cage.guidance=ball",
            "--set",
            "model.gravity=false",
            "--json",
        ],
        None,
    );
    let dir = temp_dir("traction-start");
    let d = dir.to_string_lossy().into_owned();
    let o = run_into(
        &d,
        None,
        "1 ms",
        &[
            "solver.start=quasistatic_traction",
            "cage.guidance=ball",
            "model.gravity=false",
        ],
    );
    assert_ok(&o);
    let summary: Value = summary_of(&dir);
    let mean = summary["mean_load_inner_n"].as_f64().unwrap();
    let qs = ball_guided["balls"][0]["load_inner_n"].as_f64().unwrap();
    assert!((mean / qs - 1.0).abs() < 1e-4, "{mean} vs {qs}");
    let cage = summary["mean_cage_speed_rpm"].as_f64().unwrap();
    let qs_cage = ball_guided["cage_speed_rpm"].as_f64().unwrap();
    assert!((cage / qs_cage - 1.0).abs() < 1e-6, "{cage} vs {qs_cage}");
    std::fs::remove_dir_all(&dir).ok();
}
