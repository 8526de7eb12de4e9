//! The accuracy regression suite: regimes bearing engineers run, at the
//! default settings of their case, held to the bounds a converged run
//! keeps (docs/dynamics.md, "Accuracy at default settings"):
//!
//! * the energy balance closes to 1e-3 of the drive work
//!   (`accuracy.status` = `ok`);
//! * `--verify` (the same case at ten times tighter tolerances and a
//!   two-fold finer traction grid) moves the cage speed and the mean and
//!   maximum contact loads by less than 1 % and the ring vibration RMS by
//!   less than 5 %.
//!
//! The cases failed the balance before the energy-balance step control
//! and the `auto` switch between the stiff and the explicit method
//! (docs/performance.md has the before/after table). A run whose settings
//! are loosened on purpose must say that it is not converged.

#![allow(clippy::unwrap_used)]

use crate::common::{assert_refused, rolldyn, stderr, summary_of, temp_dir};
use serde_json::Value;

/// Runs `rolldyn run` with `args` (and the case text on stdin when
/// given) into a fresh directory; returns the summary and stderr (and the
/// report, when `--report` wrote one, appended to stderr's text).
fn run(tag: &str, args: &[&str], case: Option<&str>) -> (Value, String) {
    let dir = temp_dir(&format!("accuracy-{tag}"));
    let dir_text = dir.display().to_string();
    let mut all = vec!["run"];
    if case.is_some() {
        all.push("-");
    }
    all.extend_from_slice(args);
    all.extend_from_slice(&["-o", &dir_text]);
    let o = rolldyn(&all, case);
    assert!(o.status.success(), "{tag}: {}", stderr(&o));
    let summary: Value = summary_of(&dir);
    let report = std::fs::read_to_string(dir.join("report.html")).unwrap_or_default();
    std::fs::remove_dir_all(&dir).ok();
    (summary, stderr(&o) + &report)
}

/// The energy balance closes and, with `verify`, the main results stay
/// within their limits at ten times tighter tolerances.
fn assert_converged(tag: &str, summary: &Value, quantities: &[&str]) {
    let accuracy = &summary["accuracy"];
    let balance = accuracy["energy_balance_relative_error"].as_f64().unwrap();
    assert!(
        balance.abs() <= 1e-3 && accuracy["status"] == "ok",
        "{tag}: energy balance {balance:e} ({})",
        accuracy["reason"]
    );
    let Some(changes) = accuracy["verify"]["changes"].as_array() else {
        return;
    };
    for key in quantities {
        let change = changes
            .iter()
            .find(|c| c["key"] == *key)
            .unwrap_or_else(|| panic!("{tag}: --verify compared no {key}"));
        let (relative, limit) = (
            change["relative_change"].as_f64().unwrap(),
            change["limit"].as_f64().unwrap(),
        );
        assert!(
            relative <= limit,
            "{tag}: {key} moved by {relative:e} at ten times tighter tolerances (limit {limit})"
        );
    }
}

const MEANS: [&str; 6] = [
    "mean_cage_speed_rpm",
    "mean_load_inner_n",
    "max_load_inner_n",
    "mean_load_outer_n",
    "max_load_outer_n",
    "mean_dissipated_power_w",
];

/// Runs with impacts: the largest loads are the peaks of impacts shorter
/// than the sample interval, taken from the samples, so they depend on
/// where the samples fall; the dissipated power still moves by 1–4 % at
/// ten times tighter tolerances (docs/dynamics.md, limits). The cage
/// speed and the mean loads.
const IMPACT_MEANS: [&str; 3] = [
    "mean_cage_speed_rpm",
    "mean_load_inner_n",
    "mean_load_outer_n",
];

/// The default case (7008C, EHL traction, rtol 1e-2) at low speed: the
/// balance was −0.37 of the drive work at 500 rpm and −0.13 at 100 rpm,
/// the power loss at 100 rpm 82 % too high. At 100 rpm, where spin and
/// differential sliding dominate the losses, the uniform 12 × 6 traction
/// grid was the limit of the power loss (the 24 × 12 grid of `--verify`
/// raised it by 2.9 %, and `--verify` said so); the graded grid, the
/// default, holds it within 1 % of its refinement (docs/dynamics.md,
/// "Traction grid"), and the uniform grid, still available, is still
/// flagged.
#[test]
fn low_speed_ehl_closes_its_balance() {
    // The case's 50 ms: after about 30 ms at this speed the cage rests on
    // light pocket contacts and jitters on them, which took a hundred times
    // the steps with the half-Sommerfeld pocket film and takes few with the
    // vapour cut-off, the default (docs/dynamics.md, "Limits"); the balance
    // failed from the first milliseconds.
    let at_500 = ["--speed", "500 rpm", "--duration", "50 ms", "--verify"];
    let (s, _) = run("500rpm", &at_500, None);
    assert_converged("500 rpm", &s, &MEANS);
    // Without gravity at 100 rpm: the 3 g cage, started centred, drops
    // onto its guide land in the first 6 ms (no lift at that speed), a
    // transient a 10 ms window cannot average (its cage speed moves 1.1 %
    // at tighter tolerances; over 30 ms with gravity, 1.3e-4:
    // docs/dynamics.md, "Mounting").
    let low = [
        "--speed",
        "100 rpm",
        "--duration",
        "10 ms",
        "--verify",
        "--set",
        "model.gravity=false",
    ];
    let (s, _) = run("100rpm", &low, None);
    assert_converged("100 rpm", &s, &MEANS);
    let verify = &s["accuracy"]["verify"];
    assert_eq!(
        verify["traction_grid"],
        "graded 24 × 12 cells (run: 12 × 6)"
    );
    assert_eq!(verify["status"], "ok");
    let uniform = [
        &low[..],
        &[
            "--set",
            "model.traction_integration={ method = \"grid\", across = 12, along = 6 }",
            // The traction's share alone: the EHL rolling resistance, which
            // no grid integrates, would dilute the grid's error.
            "--set",
            "lubrication.rolling_resistance=\"none\"",
        ],
    ]
    .concat();
    let (s, err) = run("100rpm-uniform", &uniform, None);
    let verify = &s["accuracy"]["verify"];
    assert_eq!(verify["traction_grid"], "24 × 12 cells (run: 12 × 6)");
    let power = verify["changes"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["key"] == "mean_dissipated_power_w")
        .unwrap();
    let moved = power["relative_change"].as_f64().unwrap();
    assert!((0.015..0.05).contains(&moved), "power moved by {moved}");
    assert!(
        err.contains("and a finer traction grid mean_dissipated_power_w"),
        "{err}"
    );
}

/// The built-in default case as a user first runs it (0.05 s at its
/// defaults): `--verify` finds no integration error. Its smooth housing
/// sensor read the integration's noise at the rtol 1e-2 it had until
/// 2026-11-30 (0.037 against 0.0093 m/s², moved 301 %; docs/dynamics.md,
/// "Tolerance and accuracy"); at its 2e-3 the record is within the
/// accelerometer's noise. Only the whirl radius, still growing from
/// rest, may move, by no more than between its window's halves.
#[test]
fn the_default_case_is_converged_at_its_defaults() {
    let (s, _) = run("default", &["--verify"], None);
    assert_converged("default", &s, &MEANS);
    let verify = &s["accuracy"]["verify"];
    assert_ne!(verify["cause"], "tolerance", "{verify}");
    let changes = verify["changes"].as_array().unwrap();
    let sensor = changes.iter().find(|c| c["key"] == "sensor.rms_m_s2");
    assert!(
        sensor.is_none_or(|c| {
            c["relative_change"].as_f64().unwrap() <= c["limit"].as_f64().unwrap()
        }),
        "{sensor:?}"
    );
    let rms = s["sensor"]["rms_m_s2"].as_f64().unwrap();
    let noise = s["sensor"]["noise_rms_m_s2"].as_f64().unwrap();
    assert!(
        rms < 2.0 * noise,
        "sensor RMS {rms} m/s² against noise {noise}"
    );
}

/// The default case at 2000 rpm: with linear pockets alone its cage
/// rattled round the pocket clearance (whirl radius 87 µm, balls striking
/// the pockets at up to 19 N, sensor RMS 5.7 m/s², 19 616 steps in 20 ms);
/// the pocket oil's squeeze film, on in the preset, damps it
/// (docs/dynamics.md, "Limits"): the cage stays within a micrometre of
/// centre and `--verify` passes on every quantity, the vibration too.
#[test]
fn the_default_cage_stays_quiet_at_low_speed() {
    let args = ["--speed", "2000 rpm", "--duration", "20 ms", "--verify"];
    let (s, _) = run("2000rpm", &args, None);
    assert_converged("2000 rpm", &s, &MEANS);
    assert_eq!(s["accuracy"]["verify"]["status"], "ok");
    let whirl = s["cage_whirl_radius_max_m"].as_f64().unwrap();
    assert!(whirl < 1e-6, "cage whirl radius {whirl:e} m");
    let (s, _) = run(
        "2000rpm-dry-pockets",
        &[
            "--speed",
            "2000 rpm",
            "--duration",
            "20 ms",
            "--set",
            "cage.pocket_squeeze_film=false",
        ],
        None,
    );
    let whirl = s["cage_whirl_radius_max_m"].as_f64().unwrap();
    assert!(
        whirl > 5e-5,
        "without the film: cage whirl radius {whirl:e} m"
    );
}

/// The greased CWRU 6205 preset under 1 kN at 1772 rpm: the balls of the
/// unloaded zone stay on the outer race (their centrifugal force, 0.22 N,
/// holds them), with the pockets' squeeze film damping the cage's pushes;
/// `--verify` passes. Without the film the pocket friction lifts them off
/// the race (docs/dynamics.md, "Limits"): the control run.
#[test]
fn the_greased_cwru_balls_stay_on_their_race() {
    let case = String::from_utf8(rolldyn(&["new", "--preset", "6205"], None).stdout).unwrap();
    let least_outer_load = |tag: &str, extra: &[&str]| {
        let dir = temp_dir(&format!("accuracy-{tag}"));
        let dir_text = dir.display().to_string();
        let mut args = vec![
            "run",
            "-",
            "--radial-load",
            "1 kN",
            "--speed",
            "1772 rpm",
            "--duration",
            "50 ms",
            "-o",
            &dir_text,
        ];
        args.extend_from_slice(extra);
        let o = rolldyn(&args, Some(&case));
        assert!(o.status.success(), "{tag}: {}", stderr(&o));
        let summary: Value = summary_of(&dir);
        let series = rolldyn_io::read_parquet(&dir.join("timeseries.parquet")).unwrap();
        let time = series.column("time_s").unwrap();
        // After the start's first 10 ms.
        let least = (0..9)
            .flat_map(|ball| {
                let load = series.column(&format!("ball{ball}_load_outer_n")).unwrap();
                time.iter()
                    .zip(load)
                    .filter(|(t, _)| **t > 0.01)
                    .map(|(_, q)| *q)
                    .collect::<Vec<_>>()
            })
            .fold(f64::INFINITY, f64::min);
        std::fs::remove_dir_all(&dir).ok();
        (summary, least)
    };
    let (s, least) = least_outer_load("cwru-greased", &["--verify"]);
    assert_converged("greased 6205", &s, &MEANS);
    assert!(least > 0.05, "greased: least outer load {least} N");
    let (_, least) = least_outer_load(
        "cwru-dry-pockets",
        &["--set", "cage.pocket_squeeze_film=false"],
    );
    assert!(least < 1e-9, "without the film: least outer load {least} N");
}

/// Heavy load on the default case.
#[test]
fn heavy_load_closes_its_balance() {
    let (s, _) = run("heavy", &["--axial-load", "2 kN", "--verify"], None);
    assert_converged("2 kN", &s, &MEANS);
}

/// A start at 1 rpm under 5 kN (EHL traction near zero entrainment): ran
/// at nanosecond steps for minutes before; the balance only (the
/// verifying run at rtol 1e-3 takes minutes).
#[test]
fn a_one_rpm_start_closes_its_balance() {
    let (s, _) = run(
        "1rpm",
        &[
            "--speed",
            "1 rpm",
            "--radial-load",
            "5 kN",
            "--duration",
            "10 ms",
        ],
        None,
    );
    assert_converged("1 rpm", &s, &[]);
}

/// `--verify` refines the traction grid of a case that relies on the
/// default grid too (the ceramic_45x75 preset writes no
/// `traction_integration`): the verifying run must not fail on a grid
/// table without its method, and names the grids it compared.
#[test]
fn verify_refines_the_default_grid() {
    let case =
        String::from_utf8(rolldyn(&["new", "--preset", "ceramic_45x75"], None).stdout).unwrap();
    assert!(!case.contains("traction_integration"));
    let (s, _) = run("ceramic", &["--duration", "5 ms", "--verify"], Some(&case));
    let verify = &s["accuracy"]["verify"];
    assert_eq!(
        verify["traction_grid"],
        "graded 24 × 12 cells (run: 12 × 6)"
    );
    assert!(verify["changes"].as_array().is_some_and(|c| !c.is_empty()));
}

/// Catalogue bearings at the defaults `rolldyn new --bearing` writes
/// (EHL traction on a graded 16 × 8 grid; docs/catalogue.md): a
/// deep-groove one under radial load and a 40° angular-contact one under
/// axial load, whose spin losses the uniform 16 × 8 grid left 2 % from its
/// refinement, both converged in everything.
#[test]
fn catalogue_bearings_close_their_balance() {
    for (bearing, quantities) in [("6205", &MEANS[..]), ("7210B", &MEANS[..])] {
        let case = String::from_utf8(rolldyn(&["new", "--bearing", bearing], None).stdout).unwrap();
        let (s, _) = run(bearing, &["--duration", "20 ms", "--verify"], Some(&case));
        assert_converged(bearing, &s, quantities);
    }
}

/// Zhang et al. 2025's 7218B with FASTSIM (its preset) and with Kalker's
/// exact theory tabulated (`exact_table`): solid-lubricated rolling,
/// where the traction law alone carries the balls.
#[test]
fn kalker_traction_closes_its_balance() {
    let case = String::from_utf8(rolldyn(&["new", "--preset", "7218B"], None).stdout).unwrap();
    for (tag, law) in [
        ("fastsim", "{ law = \"fastsim\", friction = 0.1 }"),
        ("exact-table", "{ law = \"exact_table\", friction = 0.1 }"),
    ] {
        let set = format!("model.traction={law}");
        let (s, _) = run(
            tag,
            &["--set", &set, "--duration", "20 ms", "--verify"],
            Some(&case),
        );
        assert_converged(tag, &s, &MEANS);
    }
}

/// Shan et al. 2023's 6304 (clearance, pocket impacts, modified Coulomb traction):
/// the first 20 ms, where the pockets and the rings settle.
#[test]
fn pocket_impacts_close_their_balance() {
    let case = String::from_utf8(rolldyn(&["new", "--preset", "6304"], None).stdout).unwrap();
    let (s, _) = run("6304", &["--duration", "20 ms", "--verify"], Some(&case));
    assert_converged("6304", &s, &IMPACT_MEANS);
}

/// The CWRU example's bridged sharp outer-race spall (Lankarani–Nikravesh
/// contacts): −2.0e-2 before over 0.3 s; here its first 0.1 s. Its
/// balance and means converge; its vertical vibration RMS does not yet
/// (the known gap of docs/dynamics.md: the ringing the impacts excite is
/// damped numerically by different amounts at different tolerances and
/// aliases into the 10–1000 Hz band), and `--verify` must say so.
#[test]
fn a_bridged_spall_with_damped_contacts_closes_its_balance() {
    let case = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/cwru6205/case.toml"
    ))
    .unwrap();
    let (s, err) = run("cwru", &["--duration", "0.1 s", "--verify"], Some(&case));
    assert_converged("cwru", &s, &IMPACT_MEANS);
    // Its vibration RMS and largest loads over 50 ms of impacts are not
    // statistics of the motion yet: DOPRI5 references at rtol 1e-5 and
    // 1e-6 differ by 29 % in the vertical RMS (docs/dynamics.md). Whatever
    // --verify finds beyond its limits, the run must say so.
    let verify = &s["accuracy"]["verify"];
    let beyond = verify["changes"].as_array().unwrap().iter().any(|c| {
        c["relative_change"]
            .as_f64()
            .is_some_and(|r| r > c["limit"].as_f64().unwrap())
    });
    if beyond {
        assert_eq!(verify["status"], "warning");
        assert!(err.contains("warning: --verify:"), "{err}");
    } else {
        assert_eq!(verify["status"], "ok");
    }
}

/// The same case with its pit growing (2 mm/s: 0.18 → 0.38 mm over the
/// run): the growth steps between ball passes keep the balance closed.
#[test]
fn a_growing_spall_closes_its_balance() {
    let case = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/cwru6205/case.toml"
    ))
    .unwrap();
    let (s, _) = run(
        "cwru-growth",
        &[
            "--duration",
            "0.1 s",
            "--set",
            "surface.outer.spall.0.growth_rate=\"2 mm/s\"",
        ],
        Some(&case),
    );
    assert_converged("cwru-growth", &s, &IMPACT_MEANS);
}

/// A 0.533 mm × 0.28 mm outer-race spall under 1 kN on the 6205 preset
/// (Coulomb traction, the material law's light contact damping): the ball
/// drops into the pit and strikes its far edge, and the contact
/// vibrations it excites ring on while the drive exchanges many times
/// more energy back and forth than it supplies net. With ros34pw2 alone the balance was +5e-2
/// at the defaults; `auto` hands the ringing to dopri5 and the energy
/// control counts the drive's net work (docs/dynamics.md).
fn deep_spall_case() -> String {
    spalled_6205(
        "[surface.outer]\n[[surface.outer.spall]]\nposition = \"270 deg\"\nlength = \"0.533 mm\"\ndepth = \"0.28 mm\"\n",
    )
}

/// The 6205 preset with `surface` (TOML) appended.
fn spalled_6205(surface: &str) -> String {
    let mut case = String::from_utf8(rolldyn(&["new", "--preset", "6205"], None).stdout).unwrap();
    case.push('\n');
    case.push_str(surface);
    case
}

const DEEP_SPALL: [&str; 6] = [
    "--radial-load",
    "-1 kN",
    "--speed",
    "1772 rpm",
    "--duration",
    "20 ms",
];

#[test]
fn a_deep_spall_with_undamped_contacts_closes_its_balance() {
    let mut args = DEEP_SPALL.to_vec();
    args.push("--verify");
    let (s, _) = run("deep-spall", &args, Some(&deep_spall_case()));
    assert_converged("deep spall", &s, &IMPACT_MEANS);
    // The impacts went to the explicit method.
    assert!(s["integrator_switches"].as_u64().unwrap() >= 1);
    assert!(s["explicit_steps"].as_u64().unwrap() > 0);
}

/// The same on the inner race (in the load zone once per shaft turn) and
/// on a ball (striking both raceways once per spin).
#[test]
fn inner_race_and_ball_spalls_close_their_balances() {
    for (tag, surface) in [
        (
            "inner-spall",
            "[surface.inner]\n[[surface.inner.spall]]\nposition = \"270 deg\"\nlength = \"0.533 mm\"\ndepth = \"0.2 mm\"\n",
        ),
        (
            "ball-spall",
            "[surface.balls]\n[[surface.balls.spall]]\nball = 0\nposition = \"0 deg\"\nlength = \"0.533 mm\"\ndepth = \"0.2 mm\"\n",
        ),
    ] {
        let (s, _) = run(tag, &DEEP_SPALL, Some(&spalled_6205(surface)));
        assert_converged(tag, &s, &[]);
        assert!(s["envelope_lines"]["lines"].as_array().unwrap().len() == 4);
    }
}

/// A run that is not converged says so: the deep spall with the stiff
/// method alone, the energy control off and rtol 1e-2 (its balance
/// closes to -7.5e-3; at the default 1e-3 the preset's damped pockets
/// leave it within the limit, -2.1e-4).
#[test]
fn an_unconverged_run_says_so() {
    let mut args = DEEP_SPALL.to_vec();
    args.extend_from_slice(&[
        "--set",
        "solver.integrator=ros34pw2",
        "--set",
        "solver.energy_tolerance=0",
        "--set",
        "solver.relative_tolerance=1e-2",
        "--report",
    ]);
    let (s, err) = run("loose-spall", &args, Some(&deep_spall_case()));
    let balance = s["accuracy"]["energy_balance_relative_error"]
        .as_f64()
        .unwrap();
    assert!(balance.abs() > 1e-3, "balance {balance:e}");
    assert_eq!(s["accuracy"]["status"], "warning");
    assert!(
        s["accuracy"]["hint"]
            .as_str()
            .unwrap()
            .contains("solver.energy_tolerance = 0")
    );
    assert!(
        err.contains("warning: the energy balance closes to"),
        "{err}"
    );
    // The report's banner.
    assert!(
        err.contains(
            "<div class=\"warning\" role=\"alert\"><strong>Warning:</strong> The energy balance closes to"
        ),
        "no banner in the report"
    );
}

/// Bad settings get a clear error naming the key or flag and the rule.
#[test]
fn bad_accuracy_settings_are_refused() {
    let o = rolldyn(
        &[
            "run",
            "--set",
            "solver.energy_tolerance=0.5",
            "--duration",
            "1 ms",
        ],
        None,
    );
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(
        err.contains("solver.energy_tolerance")
            && err.contains("0.5")
            && err.contains("[1e-9, 0.1]"),
        "{err}"
    );
    let o = rolldyn(&["run", "--sweep", "axial=100N,200N", "--verify"], None);
    assert_refused(&o, &["--verify: not with --sweep"]);
}

/// A bearing set in motion (`examples/spindle_pair`: two 7008C back to
/// back, 200 N preload, 15 000 rpm, the case's `auto` integrator at rtol
/// 1e-2): the system's energy balance closes, and `--verify` (ten times
/// tighter tolerances, a two-fold finer traction grid) moves each
/// bearing's mean axial load, cage speed and mean inner load by less than
/// 1 %.
#[test]
fn spindle_pair_in_motion_is_converged_at_its_defaults() {
    let case = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/spindle_pair/case.toml"
    );
    let (summary, _) = run("pair", &[case, "--duration", "15 ms", "--verify"], None);
    let balance = summary["energy_balance_relative_error"].as_f64().unwrap();
    assert!(balance <= 1e-3, "energy balance {balance:e}");
    let verify = &summary["verify"];
    let changes = verify["changes"].as_array().unwrap();
    assert_eq!(changes.len(), 6, "{verify}");
    for c in changes {
        assert!(
            c["relative_change"].as_f64().unwrap() <= c["limit"].as_f64().unwrap(),
            "{} moved by {} at ten times tighter tolerances",
            c["key"],
            c["relative_change"]
        );
    }
    assert_eq!(verify["status"], "ok");
}

/// The bearing's damping between its rings (`model.bearing_damping`, the
/// ROSS default τ = 1.25e-5 s) on the 6205 preset with the fault matrix's
/// outer-race pit (D_w/15 × D_w/28 at the load zone's centre): an impact
/// run with the damper in its ledger, its first 20 ms.
#[test]
fn bearing_damping_closes_its_balance() {
    let case = String::from_utf8(rolldyn(&["new", "--preset", "6205"], None).stdout).unwrap();
    let (s, _) = run(
        "bearing-damping",
        &[
            "--duration",
            "20 ms",
            "--verify",
            "--set",
            "model.bearing_damping=\"1.25e-5 s\"",
            "--set",
            "surface.outer.spall=[{ position = \"90 deg\", length = \"0.529336 mm\", depth = \"0.283573 mm\" }]",
        ],
        Some(&case),
    );
    assert_converged("bearing damping", &s, &IMPACT_MEANS);
    assert!(
        s["mean_power_loss_by_component_w"]["support_damping"]
            .as_f64()
            .unwrap()
            > 0.0
    );
}

/// A run on a traction grid too coarse for its vibration: `--verify`
/// runs the grid refined alone, finds that it moves what moved, and
/// names the grid (not the tolerances) as the cause, in summary.json,
/// on stderr and in the report's banner.
#[test]
fn verify_names_the_grid_when_the_grid_alone_moves_the_results() {
    let (s, text) = run(
        "coarse-grid",
        &[
            "--duration",
            "10 ms",
            "--set",
            "model.traction_integration={ method = \"graded\", across = 2, along = 2 }",
            "--verify",
            "--report",
        ],
        None,
    );
    let verify = &s["accuracy"]["verify"];
    assert_eq!(verify["cause"], "grid", "{verify}");
    let changes = verify["changes"].as_array().unwrap();
    let beyond: Vec<&Value> = changes
        .iter()
        .filter(|c| c["relative_change"].as_f64() > c["limit"].as_f64())
        .collect();
    assert!(!beyond.is_empty(), "{verify}");
    for c in beyond {
        let (whole, grid) = (c["relative_change"].as_f64(), c["grid_change"].as_f64());
        assert!(grid >= whole.map(|w| 0.5 * w), "{c}");
    }
    assert!(
        text.contains("not converged in the traction grid (refine it)"),
        "{text}"
    );
    // A run without a grid makes no third run.
    let (s, _) = run(
        "no-grid",
        &[
            "--duration",
            "2 ms",
            "--set",
            "model.traction_integration={ method = \"centre\" }",
            "--verify",
        ],
        None,
    );
    let verify = &s["accuracy"]["verify"];
    assert!(verify["traction_grid"].is_null(), "{verify}");
    assert_ne!(verify["cause"], "grid", "{verify}");
    let changes = verify["changes"].as_array().unwrap();
    assert!(changes.iter().all(|c| c["grid_change"].is_null()));
    // A set: its bearings' loads on a one-strip grid move with the grid.
    let pair = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/spindle_pair/case.toml"
    );
    let (s, text) = run(
        "coarse-grid-pair",
        &[
            pair,
            "--duration",
            "5 ms",
            "--set",
            "model.traction_integration={ method = \"grid\", across = 1, along = 2 }",
            "--verify",
            "--report",
        ],
        None,
    );
    assert_eq!(s["verify"]["cause"], "grid", "{}", s["verify"]);
    assert!(text.contains("refine the grid"), "{text}");
    // The set's report states it in its banner, as a single bearing's.
    assert!(
        text.contains("not converged in the traction grid (refine it)"),
        "{text}"
    );
    // Its cage speeds and inner loads have their window's spread as a
    // single bearing's; the axial loads, means over the whole run, none.
    for c in s["verify"]["changes"].as_array().unwrap() {
        let key = c["key"].as_str().unwrap();
        let spread = &c["window_spread"];
        if key.ends_with("mean_axial_load_n") {
            assert!(spread.is_null(), "{c}");
        } else {
            assert!(spread.as_f64().is_some_and(|s| s >= 0.0), "{c}");
        }
    }
}
