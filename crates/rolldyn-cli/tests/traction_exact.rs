//! `rolldyn traction --method exact`: Kalker's exact steady-rolling theory
//! from the command line, for an explicit contact and a case's contact,
//! with its map and its errors.

#![allow(clippy::unwrap_used)]

mod common;

use common::{json, rolldyn, stderr, temp_dir};

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
            "fastsim traction law",
        ),
        (
            [EXPLICIT.as_slice(), &["--method", "exact", "--cells", "3"]].concat(),
            "--cells",
        ),
        (
            [EXPLICIT.as_slice(), &["--method", "exakt"]].concat(),
            "--method",
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
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("rolling speed"), "{}", stderr(&out));
}
