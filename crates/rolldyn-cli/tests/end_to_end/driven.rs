//! End-to-end tests of a torque-driven inner ring (docs/dynamics.md,
//! "Driven rotation"): a run-down of the default case loses the speed its
//! friction torque takes, a matched pair and a `[shaft]` turn under their
//! drive, and the refusals name the key.

#![allow(clippy::unwrap_used)]

use crate::common::{SHAFT, pair, rolldyn, run_summary as run, stderr, summary_of, temp_dir};

const RPM: f64 = std::f64::consts::TAU / 60.0;

/// A run-down (no torque) of the default case from 10 000 rpm on a rotor
/// of 1e-4 kg·m²: the speed falls by the mean friction torque over the
/// inertia, to 8 % (the balls and cage give back their kinetic energy as
/// they slow, ~5 % of this inertia; validation test `driven_rotation`).
#[test]
fn a_run_down_loses_what_the_friction_torque_takes() {
    let v = run(
        "run-down",
        None,
        "0.01 s",
        &[
            "operating.drive_torque=\"0 N.m\"",
            "operating.rotor_inertia=\"1e-4 kg.m^2\"",
        ],
    );
    assert_eq!(v["status"], "completed");
    let end = v["final_inner_ring_speed_rpm"].as_f64().unwrap();
    let torque = v["mean_friction_torque_n_m"].as_f64().unwrap();
    assert!(torque > 0.0, "friction resists: {torque} N·m");
    let lost = (10_000.0 - end) * RPM;
    let expected = torque * 0.01 / 1e-4;
    assert!(
        (lost - expected).abs() < 0.08 * expected,
        "lost {lost} rad/s, M t / J = {expected} rad/s"
    );
    assert!(v["energy_balance_relative_error"].as_f64().unwrap() < 1e-4);
    assert_eq!(v["drive_work_j"], 0.0);
}

/// A matched pair and a `[shaft]` turn under their drive: a pair of
/// 7008C runs down (by 1 % in 5 ms on 2e-4 kg·m², the EHL rolling
/// resistance of its 47 mPa·s oil at 10 000 rpm the largest share), the
/// two 6206 speed up under 0.5 N·m on 5e-3 kg·m² by (0.5 N·m − M_f)/J,
/// M_f their friction moment, the dissipated energy over the turned angle
/// (0.086 N·m, mostly their grease's rolling resistance under the shaft's
/// 4 kN), every bearing's series at the shaft's speed.
#[test]
fn sets_and_shafts_turn_under_their_drive() {
    let drive = [
        "operating.drive_torque=\"0 N.m\"",
        "operating.rotor_inertia=\"2e-4 kg.m^2\"",
    ];
    let case = pair("kind = \"back_to_back\"\npreload = \"200 N\"");
    let v = run("driven-pair", Some(&case), "0.005 s", &drive);
    let end = v["final_inner_ring_speed_rpm"].as_f64().unwrap();
    assert!(end < 9950.0 && end > 9850.0, "{end} rpm");
    assert!(v["energy_balance_relative_error"].as_f64().unwrap() < 1e-4);
    let shaft = SHAFT.replace("ORIENTATION", "forward").replace(
        "speed = \"3000 rpm\"",
        "speed = \"3000 rpm\"\ndrive_torque = \"0.5 N.m\"\nrotor_inertia = \"5e-3 kg.m^2\"",
    );
    let v = run("driven-shaft", Some(&shaft), "0.01 s", &[]);
    let (start, end) = (
        3000.0 * RPM,
        v["final_inner_ring_speed_rpm"].as_f64().unwrap() * RPM,
    );
    let friction = v["dissipated_energy_j"].as_f64().unwrap() / (0.5 * (start + end) * 0.01);
    assert!(friction > 0.0 && friction < 0.25, "{friction} N·m");
    let expected = (0.5 - friction) * 0.01 / 5e-3;
    assert!(
        ((end - start) / expected - 1.0).abs() < 0.01,
        "gained {} rad/s, expected {expected}",
        end - start
    );
    assert!(v["energy_balance_relative_error"].as_f64().unwrap() < 1e-4);
}

/// Each refusal names its key.
#[test]
fn a_drive_needs_its_inertia_and_a_starting_speed() {
    for (sets, key) in [
        (
            vec!["operating.drive_torque=\"0.1 N.m\""],
            "operating.rotor_inertia",
        ),
        (
            vec!["operating.rotor_inertia=\"1e-4 kg.m^2\""],
            "operating.rotor_inertia",
        ),
        (
            vec![
                "operating.drive_torque=\"0.1 N.m\"",
                "operating.rotor_inertia=\"-1e-4 kg.m^2\"",
            ],
            "operating.rotor_inertia",
        ),
        (
            vec![
                "operating.drive_torque=\"0.1 N.m\"",
                "operating.drive_torque_profile=[{ time = \"0 s\", torque = \"1 N.m\" }]",
                "operating.rotor_inertia=\"1e-4 kg.m^2\"",
            ],
            "operating.drive_torque_profile",
        ),
        (
            vec![
                "operating.drive_torque_profile=[{ time = \"0 s\", torque = \"1 N.m\" }, { time = \"0 s\", torque = \"2 N.m\" }]",
                "operating.rotor_inertia=\"1e-4 kg.m^2\"",
            ],
            "operating.drive_torque_profile[1].time",
        ),
        (
            vec![
                "operating.drive_torque=\"0.1 N.m\"",
                "operating.rotor_inertia=\"1e-4 kg.m^2\"",
                "operating.speed_profile=[{ time = \"0 s\", speed = \"1000 rpm\" }]",
            ],
            "operating.speed_profile",
        ),
        (
            vec![
                "operating.drive_torque=\"0.1 N.m\"",
                "operating.rotor_inertia=\"1e-4 kg.m^2\"",
                "model.film_in_approach=true",
            ],
            "film_in_approach",
        ),
    ] {
        let dir = temp_dir("drive-refused");
        let mut args = vec!["run", "--duration", "1 ms", "-o", dir.to_str().unwrap()];
        for s in &sets {
            args.extend(["--set", s]);
        }
        let o = rolldyn(&args, None);
        assert!(!o.status.success(), "{sets:?} ran");
        assert!(stderr(&o).contains(key), "{sets:?}: {}", stderr(&o));
        assert!(
            !dir.join("summary.json").exists(),
            "{sets:?} wrote a summary"
        );
    }
}

/// A drive torque far too large for its rotor runs the ring away: the run
/// stops once the speed passes the ±10⁶ rpm a case may give, ends
/// `failed` with the reason and the time (exit 3), and keeps what it
/// computed; for one bearing (the default case) as for a set's shaft (a
/// back-to-back pair of it).
#[test]
fn a_run_away_drive_stops_at_the_speed_limit() {
    let pair = pair("kind = \"back_to_back\"\npreload = \"200 N\"");
    for (tag, case) in [("run-away", None), ("run-away-set", Some(pair.as_str()))] {
        let dir = temp_dir(tag);
        let d = dir.to_str().unwrap();
        let mut args = vec!["run"];
        if case.is_some() {
            args.push("-");
        }
        args.extend([
            "--set",
            "operating.drive_torque=1e5 N.m",
            "--set",
            "operating.rotor_inertia=1e-6 kg.m^2",
            "--duration",
            "1 ms",
            "-o",
            d,
        ]);
        let o = rolldyn(&args, case);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(3), "{tag}: {e}");
        assert!(
            e.contains("beyond the ±1e6 rpm") && e.contains("at t = "),
            "{tag}: {e}"
        );
        let summary: serde_json::Value = summary_of(&dir);
        assert_eq!(summary["status"], "failed", "{tag}");
        assert!(
            summary["simulated_time_s"].as_f64().unwrap() < 1e-3,
            "{tag}"
        );
        std::fs::remove_dir_all(&dir).ok();
    }
}
