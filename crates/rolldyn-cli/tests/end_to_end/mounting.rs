//! The mounting (docs/dynamics.md, "Mounting"): `check` reports the
//! housing's mode and the radial chain's frequencies, and a run whose outer
//! ring sits on a housing spring starts seated in it.

#![allow(clippy::unwrap_used)]

use crate::common::{assert_ok, rolldyn, stdout, summary_of, temp_dir};

/// The 6205 preset's case text (read from standard input as `-`).
fn preset() -> String {
    stdout(&rolldyn(&["new", "--preset", "6205"], None))
}

/// The preset's damping between the rings acts against a fixed outer ring
/// only: a case with `[outer_ring]` sets it to zero.
const NO_BEARING_DAMPING: &str = "model.bearing_damping=\"0 s\"";

/// Sawalhi & Randall's (2008) pedestal under the 6205 preset.
const PEDESTAL: &str = "outer_ring={ mass = \"6.6 kg\", housing_stiffness = \"1.51e7 N/m\", housing_damping = \"2210.7 N.s/m\" }";

#[test]
fn check_reports_the_mounting_frequencies() {
    let case = preset();
    let o = rolldyn(
        &[
            "check",
            "-",
            "--set",
            PEDESTAL,
            "--set",
            NO_BEARING_DAMPING,
            "--set",
            "inner_ring.mass=\"0.5 kg\"",
            "--json",
        ],
        Some(&case),
    );
    assert_ok(&o);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let m = &v["mounting"];
    let f = |k: &str| m[k].as_f64().unwrap();
    // √(k/m)/2π and c/(2√(km)) of the pedestal.
    let omega = (1.51e7f64 / 6.6).sqrt();
    assert!((f("housing_mode_hz") - omega / std::f64::consts::TAU).abs() < 1e-9);
    assert!((f("housing_damping_ratio") - 2210.7 / (2.0 * (1.51e7f64 * 6.6).sqrt())).abs() < 1e-12);
    // The chain's modes straddle the housing's own and the rotor's.
    let k = f("bearing_radial_stiffness_n_per_m");
    assert!(k > 1e7 && k < 1e9, "{k}");
    let [low, high] = [
        m["chain_hz"][0].as_f64().unwrap(),
        m["chain_hz"][1].as_f64().unwrap(),
    ];
    assert!(
        low < f("housing_mode_hz") && high > f("rotor_on_bearing_hz"),
        "{m}"
    );
    let text = rolldyn(
        &["check", "-", "--set", PEDESTAL, "--set", NO_BEARING_DAMPING],
        Some(&case),
    );
    let text = String::from_utf8_lossy(&text.stdout);
    assert!(
        text.contains("housing mode") && text.contains("radial chain"),
        "{text}"
    );
}

/// Under gravity and its load the 6205 on the pedestal deflects the
/// housing spring by (F + W)/k ≈ 11 µm; started unseated it rings at the
/// housing's 240 Hz (1.0 mm/s RMS over the run's second half, measured
/// with the seating taken out). Seated, the housing barely moves.
#[test]
fn a_run_starts_seated_in_its_housing() {
    let summary = run_preset(
        "mounting-seated",
        &[
            "--set",
            PEDESTAL,
            "--set",
            NO_BEARING_DAMPING,
            "--set",
            "model.gravity=true",
            "--set",
            "operating.force_z=\"-100 N\"",
            "--duration",
            "20 ms",
        ],
    );
    let rms = summary["outer_ring_velocity_rms_z_mm_s"].as_f64().unwrap();
    assert!(rms < 0.5, "housing velocity RMS {rms} mm/s");
}

/// The summary of a run of the 6205 preset with `args`.
fn run_preset(tag: &str, args: &[&str]) -> serde_json::Value {
    let dir = temp_dir(tag);
    let mut all = vec!["run", "-", "-o", dir.to_str().unwrap()];
    all.extend_from_slice(args);
    let o = rolldyn(&all, Some(&preset()));
    assert_ok(&o);
    let summary = summary_of(&dir);
    std::fs::remove_dir_all(&dir).ok();
    summary
}

/// `model.bearing_damping` τ: `check` reports c = τ k_r and the damping
/// ratio c/(2√(k_r m)) of the ring's mode on the bearing; a run closes its
/// energy balance with the damper's power in the ledger.
#[test]
fn bearing_damping_is_reported_and_dissipates() {
    let damping = "model.bearing_damping=\"1.25e-5 s\"";
    let o = rolldyn(&["check", "-", "--set", damping, "--json"], Some(&preset()));
    assert_ok(&o);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let m = &v["mounting"];
    let f = |k: &str| m[k].as_f64().unwrap();
    let (k, c, mass) = (
        f("bearing_radial_stiffness_n_per_m"),
        f("bearing_damping_n_s_per_m"),
        f("inner_ring_mass_kg"),
    );
    assert!((c / (1.25e-5 * k) - 1.0).abs() < 1e-12, "{m}");
    let zeta = f("rotor_on_bearing_damping_ratio");
    assert!((zeta - c / (2.0 * (k * mass).sqrt())).abs() < 1e-12, "{m}");
    assert!(zeta > 0.01 && zeta < 0.2, "{zeta}");
    let s = run_preset(
        "bearing-damping",
        &["--set", damping, "--duration", "10 ms"],
    );
    assert_eq!(s["accuracy"]["status"], "ok");
    let support = s["mean_power_loss_by_component_w"]["support_damping"]
        .as_f64()
        .unwrap();
    assert!(support > 0.0, "{support}");
}
