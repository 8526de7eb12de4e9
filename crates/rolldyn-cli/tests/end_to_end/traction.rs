//! `rolldyn traction`: one contact's traction with every law, an explicit
//! flat contact against Kalker's linear theory, the stick/slip map, Kalker's
//! exact steady-rolling theory (`--method exact`), and the errors.

#![allow(clippy::unwrap_used)]

use crate::common::{FASTSIM, assert_refused, json, keys, rolldyn, stderr, temp_dir};

/// `rolldyn traction`: stable keys; an explicit flat contact reproduces
/// Kalker's linear theory (F_x = −G c² C₁₁ ξ, C₁₁ = 3.44 at g = 0.3,
/// ν = 0.25, Kalker 1990 Table E.3) and saturates at μQ.
#[test]
fn traction_evaluates_one_contact() {
    let explicit = |creepages: &str| {
        json(
            &[
                "traction",
                "--semi-axes",
                "0.3 mm,1 mm",
                "--load",
                "1 kN",
                "--shear-modulus",
                "80 GPa",
                "--poisson-ratio",
                "0.25",
                "--friction",
                "0.2",
                "--rolling-speed",
                "10 m/s",
                "--creepages",
                creepages,
                "--json",
            ],
            None,
        )
    };
    let small = explicit("1e-6,0,0");
    assert_eq!(
        keys(&small),
        [
            "contact_angle_deg",
            "creepage_lateral",
            "creepage_longitudinal",
            "creepage_spin_1_m",
            "exact",
            "force_n",
            "force_x_n",
            "force_y_n",
            "load_n",
            "map_cells",
            "method",
            "power_w",
            "ring",
            "rolling_speed_m_s",
            "semi_axis_across_m",
            "semi_axis_along_m",
            "spin_moment_nm",
            "stick_fraction",
            "traction_coefficient",
            "traction_law"
        ]
    );
    let linear = -80e9 * 0.3e-3 * 1e-3 * 3.44 * 1e-6;
    let fx = small["force_x_n"].as_f64().unwrap();
    assert!((fx / linear - 1.0).abs() < 0.01, "{fx} vs {linear}");
    assert_eq!(small["stick_fraction"].as_f64(), Some(1.0));
    let slide = explicit("-1,0,0");
    assert!((slide["force_x_n"].as_f64().unwrap() - 200.0).abs() < 1e-6);
    assert!(slide["power_w"].as_f64().unwrap() > 0.0);
}

/// Every case traction law evaluates one contact of the default case.
#[test]
fn every_traction_law_evaluates_one_contact() {
    for law in [
        FASTSIM,
        "model.traction={ law = \"modified_coulomb\", friction = 0.1 }",
        "model.traction={ law = \"traction_curve\", a = -0.06, b = 8, c = 60, d = 0.06 }",
        "model.traction={ law = \"ehl\", eyring_stress = \"5 MPa\", limiting_shear_coefficient = 0.08 }",
    ] {
        let r = json(
            &[
                "traction",
                "--set",
                law,
                "--ring",
                "outer",
                "--load",
                "300 N",
                "--rolling-speed",
                "10 m/s",
                "--slip",
                "-0.1 m/s,0 m/s",
                "--json",
            ],
            None,
        );
        // Sliding backwards: the traction drives the ball forwards, at most μQ.
        let fx = r["force_x_n"].as_f64().unwrap();
        assert!(fx > 0.0 && fx <= 0.1 * 300.0 + 1e-9, "{law}: {fx}");
        assert!(r["power_w"].as_f64().unwrap() > 0.0, "{law}");
        assert_eq!(r["ring"], "outer");
    }
}

/// The stick/slip map has one row per element of FASTSIM's grid.
#[test]
fn the_traction_map_has_one_row_per_element() {
    let dir = temp_dir("traction-map");
    std::fs::create_dir_all(&dir).unwrap();
    let map = dir.join("map.csv");
    let r = json(
        &[
            "traction",
            "--set",
            FASTSIM,
            "--approach",
            "5 um",
            "--rolling-speed",
            "10 m/s",
            "--creepages",
            "2e-4,0,5",
            "--map",
            &map.to_string_lossy(),
            "--json",
        ],
        None,
    );
    let text = std::fs::read_to_string(&map).unwrap();
    let rows: Vec<&str> = text.lines().collect();
    assert_eq!(
        rows[0],
        "x_m,y_m,traction_x_pa,traction_y_pa,bound_pa,state"
    );
    assert_eq!(rows.len() - 1, r["map_cells"].as_u64().unwrap() as usize);
    assert_eq!(rows.len() - 1, 16 * 10);
    let stuck = rows[1..].iter().filter(|l| l.ends_with(",stick")).count();
    let fraction = r["stick_fraction"].as_f64().unwrap();
    assert!(
        stuck > 0 && fraction > 0.0 && fraction < 1.0,
        "{stuck} {fraction}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn traction_bad_input_exits_2() {
    for (args, needle) in [
        (
            vec![
                "traction",
                "--load",
                "1 kN",
                "--rolling-speed",
                "1 m/s",
                "--creepages",
                "1,2",
            ],
            "three finite numbers",
        ),
        (
            vec![
                "traction",
                "--load",
                "1 kN",
                "--rolling-speed",
                "1 m/s",
                "--creepages",
                "0,0,0",
                "--map",
                "x.csv",
            ],
            "needs the fastsim traction law",
        ),
        (
            vec![
                "traction",
                "--semi-axes",
                "3 mm,0.2 mm",
                "--load",
                "1 kN",
                "--shear-modulus",
                "80 GPa",
                "--poisson-ratio",
                "0.3",
                "--friction",
                "0.1",
                "--rolling-speed",
                "1 m/s",
                "--creepages",
                "0,0,0",
            ],
            "--semi-axes",
        ),
        (
            vec![
                "traction",
                "--set",
                "model.traction={ law = \"fastsim\", friction = 0.1, strips = 0 }",
                "--load",
                "1 kN",
                "--rolling-speed",
                "1 m/s",
                "--creepages",
                "0,0,0",
            ],
            "model.traction.strips",
        ),
        // No rolling, or sliding beyond any contact's: refused, not NaN.
        (
            vec![
                "traction",
                "--load",
                "1 kN",
                "--rolling-speed",
                "0 m/s",
                "--creepages",
                "1e-3,0,0",
            ],
            "--rolling-speed 0 m/s: must lie in (0",
        ),
        (
            vec![
                "traction",
                "--load",
                "1 kN",
                "--rolling-speed",
                "1 m/s",
                "--creepages",
                "1e300,0,0",
            ],
            "|ξ| and |η| must be at most 10",
        ),
        (
            vec![
                "traction",
                "--load",
                "1 kN",
                "--rolling-speed",
                "1 mm/s",
                "--slip",
                "5 m/s,0 m/s",
            ],
            "argument --slip: creepages ξ 5.000e3",
        ),
    ] {
        let o = rolldyn(&args, None);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(stderr(&o).contains(needle), "{args:?}: {}", stderr(&o));
    }
}

const EXPLICIT: [&str; 12] = [
    "--semi-axes",
    "0.3 mm,1.5 mm",
    "--load",
    "1 kN",
    "--shear-modulus",
    "80 GPa",
    "--poisson-ratio",
    "0.25",
    "--friction",
    "0.1",
    "--rolling-speed",
    "5 m/s",
];

fn traction(extra: &[&str]) -> serde_json::Value {
    let mut args = vec!["traction"];
    args.extend(EXPLICIT);
    args.extend(extra);
    args.push("--json");
    json(&args, None)
}

/// A missing or doubled load or motion is refused saying which: neither
/// was given, or both were.
#[test]
fn load_and_motion_errors_say_which() {
    for (args, needle) in [
        (
            vec!["traction", "--load", "1 kN", "--rolling-speed", "1 m/s"],
            "(--slip VX,VY): neither was given",
        ),
        (
            vec![
                "traction",
                "--rolling-speed",
                "1 m/s",
                "--creepages",
                "0,0,0",
            ],
            "(--approach): neither was given",
        ),
        (
            vec![
                "traction",
                "--load",
                "1 kN",
                "--approach",
                "1 um",
                "--rolling-speed",
                "1 m/s",
                "--creepages",
                "0,0,0",
            ],
            "(--approach), not both",
        ),
    ] {
        let o = rolldyn(&args, None);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(stderr(&o).contains(needle), "{args:?}: {}", stderr(&o));
    }
}

/// The exact theory and FASTSIM agree on the linear (small creepage)
/// longitudinal force within FASTSIM's known error, both sit below μQ,
/// and the exact run reports its grid, convergence and map.
#[test]
fn exact_method_reports_forces_grid_and_map() {
    let dir = temp_dir("traction-exact");
    std::fs::create_dir_all(&dir).unwrap();
    let map = dir.join("map.csv");
    let exact = traction(&[
        "--creepages",
        "2e-4,0,0",
        "--method",
        "exact",
        "--cells",
        "20",
        "--map",
        &map.to_string_lossy(),
    ]);
    let fastsim = traction(&["--creepages", "2e-4,0,0"]);
    assert_eq!(exact["method"], "exact");
    assert_eq!(fastsim["method"], "fastsim");
    assert!(fastsim["exact"].is_null());
    let (fe, ff) = (
        exact["force_x_n"].as_f64().unwrap(),
        fastsim["force_x_n"].as_f64().unwrap(),
    );
    assert!(fe < 0.0 && fe.abs() < 100.0);
    assert!((fe / ff - 1.0).abs() < 0.15, "{fe} vs {ff}");
    let e = &exact["exact"];
    assert_eq!(e["cells_along"], 20);
    assert_eq!(e["cells_across"], 20);
    assert_eq!(e["extrapolated_from"], serde_json::json!([]));
    assert!(e["force_error_estimate_n"].is_null());
    assert_eq!(e["converged"], true);
    let cells = e["contact_cells"].as_u64().unwrap() as usize;
    // The loaded cells cover the ellipse: π/4 of the 20 × 20 box over
    // 1.05² of its area.
    assert!((cells as f64 / (400.0 * std::f64::consts::FRAC_PI_4 / 1.1025) - 1.0).abs() < 0.1);
    let text = std::fs::read_to_string(&map).unwrap();
    assert_eq!(text.lines().count() - 1, cells);
    assert_eq!(exact["map_cells"].as_u64().unwrap() as usize, cells);
    let stick = exact["stick_fraction"].as_f64().unwrap();
    assert!(stick > 0.3 && stick < 1.0, "{stick}");
    assert!(e["frictional_power_w"].as_f64().unwrap() > 0.0);
}

/// A case's contact with the fastsim law runs; another law, a bad grid, a
/// bad method and zero rolling speed are refused with the flag named.
#[test]
fn exact_method_on_a_case_and_its_errors() {
    let r = json(
        &[
            "traction",
            "--set",
            "model.traction={ law = \"fastsim\", friction = 0.1 }",
            "--load",
            "500 N",
            "--rolling-speed",
            "10 m/s",
            "--creepages",
            "1e-3,0,2",
            "--method",
            "exact",
            "--cells",
            "16",
            "--json",
        ],
        None,
    );
    assert_eq!(r["ring"], "inner");
    assert!(r["force_n"].as_f64().unwrap() <= 0.1 * 500.0 + 1e-9);
    for (args, needle) in [
        (
            vec!["--load", "500 N", "--method", "exact"],
            "fastsim or exact_table traction law",
        ),
        (
            [EXPLICIT.as_slice(), &["--method", "exact", "--cells", "3"]].concat(),
            "--cells",
        ),
        (
            [EXPLICIT.as_slice(), &["--method", "exakt"]].concat(),
            "--method",
        ),
        // Bounded work: at most 128 cells each way, an ellipse no thinner
        // than 1:100 for the exact theory.
        (
            [
                EXPLICIT.as_slice(),
                &["--method", "exact", "--cells", "129"],
            ]
            .concat(),
            "between 4 and 128",
        ),
        (
            [
                &EXPLICIT[2..],
                &["--semi-axes", "1 nm,1 m", "--method", "exact"],
            ]
            .concat(),
            "ratio must be at most 100",
        ),
        (
            [EXPLICIT.as_slice(), &["--cells", "20"]].concat(),
            "--method exact",
        ),
    ] {
        let mut all = vec!["traction", "--creepages", "1e-3,0,0"];
        if !args.contains(&"--rolling-speed") {
            all.extend(["--rolling-speed", "1 m/s"]);
        }
        all.extend(args);
        let out = rolldyn(&all, None);
        assert_eq!(out.status.code(), Some(2), "{all:?}");
        assert!(stderr(&out).contains(needle), "{all:?}: {}", stderr(&out));
    }
    let mut still = vec!["traction"];
    still.extend(&EXPLICIT[..10]);
    still.extend([
        "--rolling-speed",
        "0 m/s",
        "--creepages",
        "1e-3,0,0",
        "--method",
        "exact",
    ]);
    let out = rolldyn(&still, None);
    assert_refused(&out, &["rolling speed"]);
}

/// `--method table` interpolates the exact theory: on an explicit contact
/// in partial slip it lies within a few % of μQ of the exact solver, and a
/// case with the `exact_table` law gives the same as `--method table` on
/// the fastsim law; a law without elastic constants is refused.
#[test]
fn table_method_follows_the_exact_theory() {
    let creep = ["--creepages", "1e-3,2e-4,20"];
    let table = traction(&[creep.as_slice(), &["--method", "table"]].concat());
    let exact = traction(&[creep.as_slice(), &["--method", "exact"]].concat());
    // The default exact solve: three grids extrapolated, its error stated.
    let e = &exact["exact"];
    assert_eq!(e["extrapolated_from"], serde_json::json!([32, 48, 64]));
    assert_eq!(e["cells_along"], 64);
    let error = e["force_error_estimate_n"].as_f64().unwrap();
    assert!((0.0..0.01 * 0.1 * 1000.0).contains(&error), "{error} N");
    assert_eq!(table["method"], "table");
    assert_eq!(table["traction_law"], "exact_table");
    let mu_q = 0.1 * 1000.0;
    for key in ["force_x_n", "force_y_n"] {
        let (t, e) = (table[key].as_f64().unwrap(), exact[key].as_f64().unwrap());
        assert!((t - e).abs() < 0.06 * mu_q, "{key}: table {t}, exact {e}");
    }
    assert!(table["power_w"].as_f64().unwrap() > 0.0);
    let on_case = |law: &str, method: &str| {
        let set = format!("model.traction={{ law = \"{law}\", friction = 0.1 }}");
        json(
            &[
                "traction",
                "--set",
                &set,
                "--load",
                "500 N",
                "--rolling-speed",
                "10 m/s",
                "--creepages",
                "1e-3,0,2",
                "--method",
                method,
                "--json",
            ],
            None,
        )
    };
    let law = on_case("exact_table", "fastsim");
    let method = on_case("fastsim", "table");
    assert_eq!(law["traction_law"], "exact_table");
    for key in ["force_x_n", "force_y_n", "spin_moment_nm", "power_w"] {
        assert_eq!(law[key], method[key], "{key}");
    }
    let out = rolldyn(
        &[
            "traction",
            "--load",
            "500 N",
            "--rolling-speed",
            "10 m/s",
            "--creepages",
            "1e-3,0,0",
            "--method",
            "table",
        ],
        None,
    );
    assert_refused(&out, &["exact_table"]);
}
