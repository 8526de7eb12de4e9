//! `rolldyn run`'s integration: results that do not depend on the thread
//! count (with `auto` switching methods too), the energy balance at the default tolerance in the default
//! case's whirl limit cycle, the step cap of film pockets, and the
//! warning for an odd number of grid cells along the rolling direction.

#![allow(clippy::unwrap_used)]

use crate::common;

use crate::common::{assert_ok, stderr, summary_of, temp_dir};
use serde_json::Value;

#[test]
fn run_is_deterministic_whatever_the_thread_count() {
    let runs: Vec<(Vec<u8>, Value)> = ["1", "2", "3", "2"]
        .iter()
        .enumerate()
        .map(|(k, threads)| {
            let dir = temp_dir(&format!("det-{k}"));
            let o = std::process::Command::new(env!("CARGO_BIN_EXE_rolldyn"))
                .args(["run", "--duration", "0.5 ms", "-o"])
                .arg(&dir)
                .env("RAYON_NUM_THREADS", threads)
                .output()
                .expect("rolldyn runs");
            assert_ok(&o);
            let parquet = common::series_bytes(&dir);
            let mut summary: Value = summary_of(&dir);
            summary["wall_time_s"] = Value::Null;
            std::fs::remove_dir_all(&dir).ok();
            (parquet, summary)
        })
        .collect();
    for (k, run) in runs.iter().enumerate().skip(1) {
        assert!(run.0 == runs[0].0, "time series of run {k} differ");
        assert_eq!(run.1, runs[0].1, "summary of run {k}");
    }
}

/// `auto` hands a run between its methods by counted cost, never by wall
/// time: the default case under a light axial load (balls losing and
/// regaining their contacts, from ~12 ms) switches, identically on one
/// and two threads.
#[test]
fn auto_switches_identically_whatever_the_thread_count() {
    let runs: Vec<Value> = ["1", "2"]
        .iter()
        .map(|threads| {
            let dir = temp_dir(&format!("auto-det-{threads}"));
            let o = std::process::Command::new(env!("CARGO_BIN_EXE_rolldyn"))
                .args(["run", "--axial-load", "20 N", "--duration", "20 ms", "-o"])
                .arg(&dir)
                .env("RAYON_NUM_THREADS", threads)
                .output()
                .expect("rolldyn runs");
            assert_ok(&o);
            let mut summary: Value = summary_of(&dir);
            summary["wall_time_s"] = Value::Null;
            std::fs::remove_dir_all(&dir).ok();
            summary
        })
        .collect();
    assert!(runs[0]["integrator_switches"].as_u64().unwrap() >= 1);
    assert!(runs[0]["explicit_steps"].as_u64().unwrap() > 0);
    assert_eq!(runs[0], runs[1]);
}

/// the default case's energy balance holds at its own
/// tolerance in the cage's whirl limit cycle (from ~0.06 s). Before the
/// Jacobian differenced the turning angles by a fixed increment, the
/// imbalance had reached −3.1e-3 by 0.3 s and grew with every turn.
#[test]
fn default_case_closes_its_energy_balance_in_the_whirl_limit_cycle() {
    let dir = temp_dir("whirl-balance");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_rolldyn"))
        .args(["run", "--duration", "0.3 s", "-o"])
        .arg(&dir)
        .output()
        .expect("rolldyn runs");
    assert_ok(&o);
    let summary: Value = summary_of(&dir);
    std::fs::remove_dir_all(&dir).ok();
    let whirl = summary["cage_whirl_radius_mean_m"].as_f64().unwrap();
    assert!(
        whirl > 3e-5,
        "not in the limit cycle: whirl radius {whirl} m"
    );
    let balance = summary["energy_balance_relative_error"].as_f64().unwrap();
    assert!(balance.abs() <= 1e-3, "energy balance {balance}");
}

/// Film pockets (Deng et al. 2022's `gupta_film`) cap the stiff integrator's
/// default step at 1/16 of the cage's film-mode period, here its rotation
/// on 22 films of k = 11 N / 87.5 µm: √(22 k r²/I)/2π = 4.61 kHz
/// (r = 27 mm, I = 2.4e-6 kg·m²); an explicit `solver.max_step` wins.
#[test]
fn film_pockets_cap_the_default_step() {
    let run = |extra: &[&str]| -> Value {
        let dir = temp_dir(&format!("film-step-{}", extra.len()));
        let mut args = vec![
            "run",
            "--duration",
            "0.5 ms",
            "--set",
            "cage.pocket_law=\"gupta_film\"",
            "--set",
            "cage.material={ name = \"phenolic\", elastic_modulus = \"7 GPa\", poisson_ratio = 0.3, density = \"1400 kg/m^3\" }",
        ];
        args.extend_from_slice(extra);
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_rolldyn"))
            .args(&args)
            .arg("-o")
            .arg(&dir)
            .output()
            .expect("rolldyn runs");
        assert_ok(&o);
        let summary = summary_of(&dir);
        std::fs::remove_dir_all(&dir).ok();
        summary
    };
    let k = 11.0 / 87.5e-6;
    let film = (22.0 * k * 0.027f64.powi(2) / 2.4e-6).sqrt() / std::f64::consts::TAU;
    let capped = run(&[])["max_step_s"].as_f64().unwrap();
    assert!(
        (capped * 16.0 * film - 1.0).abs() < 1e-9,
        "max step {capped} s for a {film} Hz film mode"
    );
    let given = run(&["--set", "solver.max_step=\"50 us\""]);
    assert_eq!(given["max_step_s"], 5e-5);
}

#[test]
fn an_odd_cell_count_along_the_rolling_direction_is_warned_of() {
    let run = |integration: Option<&str>| {
        let dir = temp_dir("odd-grid");
        let mut command = std::process::Command::new(env!("CARGO_BIN_EXE_rolldyn"));
        command.args(["run", "--duration", "1 us", "-o"]).arg(&dir);
        if let Some(value) = integration {
            command.args(["--set", &format!("model.traction_integration={value}")]);
        }
        let o = command.output().expect("rolldyn runs");
        std::fs::remove_dir_all(&dir).ok();
        assert_ok(&o);
        stderr(&o)
    };
    let odd = run(Some(r#"{ method = "graded", across = 12, along = 5 }"#));
    assert!(
        odd.contains("warning: model.traction_integration.along = 5 is odd"),
        "{odd}"
    );
    assert!(!run(None).contains("is odd"));
    assert!(!run(Some(r#"{ method = "grid", across = 8, along = 4 }"#)).contains("is odd"));
}
