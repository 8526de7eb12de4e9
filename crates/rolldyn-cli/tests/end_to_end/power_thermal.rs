//! End-to-end tests of friction power and temperatures:
//! `run`'s power channels and means, `rolldyn power`, `rolldyn thermal`.

#![allow(clippy::unwrap_used)]

use crate::common::{assert_ok, assert_refused, rolldyn, run_into, stderr, summary_of, temp_dir};
use serde_json::Value;

/// The default case's run: the component means sum to the mean
/// dissipated power of the energy balance (sampling error only: the
/// accumulator is exact between samples; 2 %), every component key is
/// there, and the friction torque times the ring speed is the drive power.
#[test]
fn run_reports_power_by_component() {
    let dir = temp_dir("power-run");
    let d = dir.to_string_lossy().into_owned();
    let o = run_into(&d, None, "8 ms", &["output.power_per_ball=true"]);
    assert_ok(&o);
    let s: Value = summary_of(&dir);
    let f = |k: &str| s[k].as_f64().unwrap_or_else(|| panic!("{k} missing"));
    let (sum, exact) = (f("mean_sampled_power_loss_w"), f("mean_dissipated_power_w"));
    assert_eq!(f("mean_power_loss_w"), exact);
    assert!(
        sum > 0.0 && ((sum - exact) / exact).abs() < 0.02,
        "{sum} W vs {exact} W"
    );
    let parts = s["mean_power_loss_by_component_w"].as_object().unwrap();
    assert_eq!(parts.len(), 22, "{parts:?}");
    assert!(parts["inner_rolling_resistance"].as_f64().unwrap() > 0.0);
    assert!(s["lubrication_note"].is_string());
    for ring in ["inner", "outer"] {
        for m in [
            "rolling_sliding",
            "transverse_sliding",
            "spin",
            "differential_sliding",
            "hysteresis",
            "damping",
            "rolling_resistance",
        ] {
            assert!(parts.contains_key(&format!("{ring}_{m}")), "{ring}_{m}");
        }
    }
    // The mean torque is the drive's work per radian over the window: at
    // the prescribed speed, torque × ω is the drive power exactly, and
    // the mean of the sampled moment agrees to its sampling (5 %).
    let omega = f("inner_ring_speed_rpm") * std::f64::consts::TAU / 60.0;
    let torque_power = f("mean_friction_torque_n_m") * omega;
    let drive_power = window_drive_power(&dir, &s);
    assert!(
        ((torque_power - drive_power) / drive_power).abs() < 1e-9,
        "{torque_power} W vs {drive_power} W"
    );
    let sampled = f("mean_sampled_friction_torque_n_m") * omega;
    assert!(
        ((sampled - torque_power) / torque_power).abs() < 0.05,
        "{sampled} W vs {torque_power} W"
    );
    let series = rolldyn_io::read_parquet(&dir.join("timeseries.parquet")).unwrap();
    for k in [
        "power_inner_spin_w",
        "power_guide_land_w",
        "power_total_w",
        "friction_torque_n_m",
    ] {
        assert!(series.column(k).is_some(), "{k}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Contact seals (`[seals]`): their moment acts on the drive only, so the
/// motion is the open bearing's (to the step control's tolerance: the
/// energy control sees more energy turned over), the friction torque grows
/// by the seals' moment M_s ω/√(ω² + ω₀²) and their power is that moment
/// times the ring speed, in the energy balance.
#[test]
fn seals_add_their_moment_to_the_drive() {
    let run = |name: &str, sets: &[&str]| {
        let dir = temp_dir(name);
        let d = dir.to_string_lossy().into_owned();
        let mut args = vec!["run", "--duration", "3 ms", "-o", &d];
        for s in sets {
            args.extend(["--set", s]);
        }
        let o = rolldyn(&args, None);
        assert_ok(&o);
        let s: Value = summary_of(&dir);
        let series = rolldyn_io::read_parquet(&dir.join("timeseries.parquet")).unwrap();
        std::fs::remove_dir_all(&dir).ok();
        (s, series)
    };
    let (open, open_series) = run("seals-open", &[]);
    let (sealed, series) = run("seals", &["seals.friction_torque=0.05 N.m"]);
    let column = |t: &rolldyn_io::TimeSeries, k: &str| t.column(k).unwrap().to_vec();
    let f = |s: &Value, k: &str| s[k].as_f64().unwrap();
    let cage = |s: &Value| f(s, "mean_cage_speed_rpm");
    assert!((cage(&sealed) / cage(&open) - 1.0).abs() < 1e-5);
    let omega = f(&open, "inner_ring_speed_rpm") * std::f64::consts::TAU / 60.0;
    let w0 = std::f64::consts::TAU / 60.0;
    let moment = 0.05 * omega / omega.hypot(w0);
    let torque = |s: &Value| f(s, "mean_friction_torque_n_m");
    let added = torque(&sealed) - torque(&open);
    assert!((added / moment - 1.0).abs() < 0.02, "{added} N·m");
    for p in column(&series, "power_seals_w") {
        assert!((p - moment * omega).abs() < 1e-9 * p, "{p}");
    }
    assert!(
        column(&open_series, "power_seals_w")
            .iter()
            .all(|&p| p == 0.0)
    );
    let seal_power = sealed["mean_power_loss_by_component_w"]["seals"]
        .as_f64()
        .unwrap();
    assert!((seal_power / (moment * omega) - 1.0).abs() < 1e-9);
    let gained = f(&sealed, "mean_dissipated_power_w") - f(&open, "mean_dissipated_power_w");
    assert!(
        (gained / seal_power - 1.0).abs() < 0.02,
        "{gained} W vs {seal_power} W"
    );
    // Harris's local method adds the same M_s ω to the power loss.
    let power = |sets: &[&str]| {
        let mut args = vec!["power", "--json"];
        for s in sets {
            args.extend(["--set", s]);
        }
        json_of(&args, None)
    };
    let (open, sealed) = (power(&[]), power(&["seals.friction_torque=0.05 N.m"]));
    let p = |v: &Value, k: &str| v[k].as_f64().unwrap();
    assert_eq!(p(&open, "seals_w"), 0.0);
    assert!((p(&sealed, "seals_w") / (moment * omega) - 1.0).abs() < 1e-12);
    let gained = p(&sealed, "power_loss_w") - p(&open, "power_loss_w");
    assert!((gained / (moment * omega) - 1.0).abs() < 1e-9, "{gained} W");
    // A [seals] table without its moment is refused, naming the key.
    let o = rolldyn(&["check", "--set", "seals.transition_speed=2 rpm"], None);
    assert_refused(&o, &["seals.friction_torque"]);
}

fn preset(name: &str) -> String {
    rolldyn_case::presets::find(name).unwrap().text.to_string()
}

fn json_of(args: &[&str], stdin: Option<&str>) -> Value {
    let o = rolldyn(args, stdin);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    serde_json::from_slice(&o.stdout).unwrap()
}

/// `rolldyn power`: components sum to the total, spin is the largest
/// share on the Lei et al. 2023 bearing (C8), torque = power/ω.
#[test]
fn power_command_reports_components() {
    let case = preset("acbb_30x62");
    let v = json_of(&["power", "-", "--json"], Some(&case));
    let f = |path: &[&str]| {
        let mut x = &v;
        for p in path {
            x = &x[*p];
        }
        x.as_f64().unwrap_or_else(|| panic!("{path:?}"))
    };
    let parts = f(&["inner", "total_w"])
        + f(&["outer", "total_w"])
        + f(&["cage_land_w"])
        + f(&["ball_pocket_w"])
        + f(&["ball_drag_w"])
        + f(&["cage_drag_w"])
        + f(&["seals_w"])
        + f(&["churning_w"]);
    assert!((parts / f(&["power_loss_w"]) - 1.0).abs() < 1e-12);
    // Of the sliding mechanisms Lei et al. 2023 counts, spin is more than
    // half (C8); the EHL rolling resistance comes on top.
    let spin = f(&["inner", "spin_w"]) + f(&["outer", "spin_w"]);
    let rolling = f(&["inner", "rolling_resistance_w"]) + f(&["outer", "rolling_resistance_w"]);
    assert!(rolling > 0.0);
    assert!(
        spin > 0.5 * (f(&["power_loss_w"]) - rolling),
        "spin {spin} W"
    );
    // The torque split sums to the friction torque.
    let split: f64 = v["friction_torque_split_n_m"]
        .as_object()
        .unwrap()
        .values()
        .map(|x| x.as_f64().unwrap())
        .sum();
    assert!((split / f(&["friction_torque_n_m"]) - 1.0).abs() < 1e-12);
    assert_eq!(v["models"]["rolling_resistance"], "houpert");
    let omega = f(&["speed_rpm"]) * std::f64::consts::TAU / 60.0;
    assert!((f(&["friction_torque_n_m"]) * omega / f(&["power_loss_w"]) - 1.0).abs() < 1e-12);
    let text = rolldyn(&["power", "-"], Some(&case));
    assert!(String::from_utf8_lossy(&text.stdout).contains("differential sliding"));
}

/// No traction model and no `power.sliding_friction`: a located error.
#[test]
fn power_needs_a_sliding_friction() {
    // The preset's assumed dry traction left out.
    let case: String = preset("6205")
        .lines()
        .filter(|l| !l.starts_with("traction") && !l.starts_with("\"model.traction\""))
        .map(|l| format!("{l}\n"))
        .collect();
    let o = rolldyn(&["power", "-"], Some(&case));
    assert_refused(&o, &["power.sliding_friction"]);
    let o = rolldyn(
        &["power", "-", "--set", "power.sliding_friction=1.5"],
        Some(&case),
    );
    assert_refused(&o, &["[0, 1]"]);
}

/// `rolldyn thermal`: converged, heat in = heat out, the warm-up rises
/// towards the steady state; bad input is located.
#[test]
fn thermal_command_balances_heat_and_warms_up() {
    let case = preset("acbb_30x62");
    let v = json_of(
        &[
            "thermal",
            "-",
            "--json",
            "--transient",
            "4 h",
            "--steps",
            "400",
        ],
        Some(&case),
    );
    assert_eq!(v["converged"], true);
    let f = |k: &str| v[k].as_f64().unwrap();
    let out = f("heat_to_ambient_w") + f("heat_to_oil_w");
    assert!((out / f("heat_generated_w") - 1.0).abs() < 1e-9, "{out}");
    let t = &v["temperatures_c"];
    let node = |k: &str| t[k].as_f64().unwrap();
    assert!(node("inner_contact") > node("inner_ring") && node("inner_ring") > node("oil"));
    assert!((node("ambient") - 20.0).abs() < 1e-9);
    let rows = v["transient"].as_array().unwrap();
    assert_eq!(rows.len(), 20);
    let outer = |r: &Value| r["temperatures_c"]["outer_ring"].as_f64().unwrap();
    assert!(outer(&rows[0]) < outer(&rows[19]));
    assert!(
        (outer(&rows[19]) - node("outer_ring")).abs() < 0.5,
        "{} vs {}",
        outer(&rows[19]),
        node("outer_ring")
    );
    for (args, key) in [
        (
            vec!["--set", "thermal.housing_diameter=50mm"],
            "housing_diameter",
        ),
        (
            vec![
                "--set",
                "lubricant.second_temperature=100degC",
                "--set",
                "lubricant.second_viscosity=40mPa.s",
            ],
            "lubricant.second_viscosity",
        ),
        (vec!["--transient=-3 s"], "--transient"),
    ] {
        let mut a = vec!["thermal", "-"];
        a.extend(args.iter().copied());
        let o = rolldyn(&a, Some(&case));
        assert_eq!(o.status.code(), Some(2), "{a:?}");
        assert!(stderr(&o).contains(key), "{a:?}: {}", stderr(&o));
    }
}

/// The default case's steady state: the heat falls steeply with the oil's
/// temperature (Walther), so plain substitution alternates between a hot
/// and a cold pass without end; the relaxed iteration converges, and says
/// where the heat goes. A dry bearing at 10 kN and 10 000 rpm (7218B)
/// reaches a steady state no steel bearing runs at: said.
#[test]
fn thermal_steady_states_of_presets_say_what_they_assume() {
    let v = json_of(&["thermal", "--json"], None);
    assert_eq!(v["converged"], true, "{}", v["history_k"]);
    let history = v["history_k"].as_array().unwrap();
    assert!(history.len() < 30, "{} passes", history.len());
    let outer = v["temperatures_c"]["outer_ring"].as_f64().unwrap();
    assert!(outer > 40.0 && outer < 315.0, "{outer}");
    let warnings = v["warnings"].as_array().unwrap();
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert!(warnings[0].as_str().unwrap().contains("no oil flow"));
    let hot = json_of(&["thermal", "-", "--json"], Some(&preset("7218B")));
    let warnings = hot["warnings"].as_array().unwrap();
    assert!(
        warnings[0].as_str().unwrap().contains("beyond the 315 °C"),
        "{warnings:?}"
    );
    // A hybrid bearing seated by its radial load alone, its ring free to
    // tilt (the preset without its mounting): warm, its clearance grows
    // and it is no longer seated; the refusal says where.
    let free = rolldyn_case::presets::find("ceramic_45x75")
        .unwrap()
        .without_mounting();
    let o = rolldyn(&["thermal", "-"], Some(&free));
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    for part in [
        "thermal steady state, pass",
        "operating diametral clearance",
        "axial load",
    ] {
        assert!(stderr(&o).contains(part), "{part}: {}", stderr(&o));
    }
}

/// Quasi-static sweeps carry the local power loss.
#[test]
fn quasistatic_sweep_has_power_columns() {
    let case = preset("acbb_30x62");
    let dir = temp_dir("power-sweep");
    let d = dir.to_string_lossy().into_owned();
    let o = rolldyn(
        &[
            "quasistatic",
            "-",
            "--sweep",
            "speed=9000rpm,17000rpm",
            "-o",
            &d,
        ],
        Some(&case),
    );
    assert_ok(&o);
    let rows: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("sweep.json")).unwrap()).unwrap();
    let p = |i: usize| rows[i]["power_loss_w"].as_f64().unwrap();
    assert!(p(1) > p(0), "power rises with speed");
    assert!(
        std::fs::read_to_string(dir.join("sweep.csv"))
            .unwrap()
            .contains("power_loss_w")
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// A coupled run hotter than any steel bearing runs (315 °C, M50's
/// maximum operating temperature) stops (`failed`, the part and its
/// temperature named, exit 3) and keeps what it computed.
#[test]
fn a_coupled_run_stops_beyond_the_temperature_limit() {
    let case = preset("acbb_30x62");
    let dir = temp_dir("thermal-limit");
    let d = dir.to_string_lossy().into_owned();
    let o = run_into(
        &d,
        Some(&case),
        "1 ms",
        &[
            "thermal.run_coupling=true",
            "thermal.run_start=\"ambient\"",
            "thermal.ambient_temperature=\"350 degC\"",
        ],
    );
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(stderr(&o).contains("beyond the 315 °C"), "{}", stderr(&o));
    let s: Value = summary_of(&dir);
    assert_eq!(s["status"], "failed");
    std::fs::remove_dir_all(&dir).ok();
}

/// `thermal.run_coupling`: the run starts at the quasi-static thermal
/// steady state, updates every interval, records temperatures and the EHL
/// viscosity, and reports the coupling in summary.json.
#[test]
fn run_with_thermal_coupling() {
    let case = preset("acbb_30x62");
    let dir = temp_dir("thermal-run");
    let d = dir.to_string_lossy().into_owned();
    let o = run_into(
        &d,
        Some(&case),
        "3 ms",
        &["thermal.run_coupling=true", "thermal.update_interval=0.5ms"],
    );
    assert_ok(&o);
    let s: Value = summary_of(&dir);
    let t = &s["thermal_coupling"];
    assert_eq!(t["updates"].as_u64(), Some(5), "{t}");
    let steady = json_of(&["thermal", "-", "--json"], Some(&case));
    let start = t["initial_temperatures_c"]["outer_ring"].as_f64().unwrap();
    assert!((start - steady["temperatures_c"]["outer_ring"].as_f64().unwrap()).abs() < 1e-9);
    let series = rolldyn_io::read_parquet(&dir.join("timeseries.parquet")).unwrap();
    let eta = series.column("oil_viscosity_pa_s").unwrap();
    assert!(
        eta.iter().all(|v| *v > 0.0 && *v < 0.0275),
        "warmer than 40 °C: thinner oil"
    );
    assert!(series.column("temperature_outer_ring_c").is_some());
    // Not coupled: the key is null.
    let plain = temp_dir("thermal-run-plain");
    let p = plain.to_string_lossy().into_owned();
    assert!(run_into(&p, Some(&case), "1 ms", &[]).status.success());
    let s: Value = summary_of(&plain);
    assert!(s["thermal_coupling"].is_null());
    let o = run_into(&p, Some(&case), "1 ms", &["thermal.update_interval=1ms"]);
    assert_refused(&o, &["thermal.run_coupling"]);
    // From cold: every part at the ambient temperature, warming.
    let o = run_into(
        &d,
        Some(&case),
        "3 ms",
        &[
            "thermal.run_coupling=true",
            "thermal.run_start=\"ambient\"",
            "thermal.ambient_temperature=\"25 degC\"",
        ],
    );
    assert_ok(&o);
    let s: Value = summary_of(&dir);
    let t = &s["thermal_coupling"];
    for node in ["ball", "inner_ring", "outer_ring", "housing", "oil"] {
        let start = t["initial_temperatures_c"][node].as_f64().unwrap();
        let end = t["final_temperatures_c"][node].as_f64().unwrap();
        assert!((start - 25.0).abs() < 1e-9, "{node} starts at {start}");
        assert!(end > start, "{node} warms: {start} → {end}");
    }
    let o = run_into(&p, Some(&case), "1 ms", &["thermal.run_start=\"ambient\""]);
    assert_refused(&o, &["thermal.run_start"]);
    std::fs::remove_dir_all(&dir).ok();
    std::fs::remove_dir_all(&plain).ok();
}

/// The mean friction torque a run reports is the one that did the work:
/// on every preset, the torque times the ring speed is the drive power
/// over the averaging window (the drive work's channel, exact between
/// samples; 1e-9), including the impacts' impulses that the sampled
/// moment misses.
#[test]
fn every_preset_reports_the_torque_that_did_the_work() {
    for name in rolldyn_case::presets::PRESETS.iter().map(|p| p.name) {
        let dir = temp_dir(&format!("torque-{name}"));
        let d = dir.to_string_lossy().into_owned();
        let o = run_into(&d, Some(&preset(name)), "2 ms", &[]);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let s: Value = summary_of(&dir);
        let f = |k: &str| s[k].as_f64().unwrap_or_else(|| panic!("{name}: {k}"));
        let drive_power = window_drive_power(&dir, &s);
        let omega = f("inner_ring_speed_rpm") * std::f64::consts::TAU / 60.0;
        let torque_power = f("mean_friction_torque_n_m") * omega;
        assert!(
            (torque_power - drive_power).abs() <= 1e-9 * drive_power.abs().max(1e-12),
            "{name}: {torque_power} W vs {drive_power} W"
        );
        std::fs::remove_dir_all(&dir).ok();
    }
}

/// `[lubrication]`'s refusals name the key, its value and the rule, and
/// no run starts: an oil level above the bearing, a level without a bath,
/// a bath without a level, grease with an oil supply flow, a method
/// without a lubricant, a negative flow, a viscosity that rises with
/// temperature.
#[test]
fn lubrication_refusals_name_the_key() {
    let lubricated = preset("7008C");
    for (sets, key, rule) in [
        (
            vec![
                "lubrication.method=\"oil_bath\"",
                "lubrication.oil_level=\"80 mm\"",
            ],
            "lubrication.oil_level",
            "above the bearing",
        ),
        (
            vec!["lubrication.oil_level=\"5 mm\""],
            "lubrication.oil_level",
            "only an oil bath",
        ),
        (
            vec!["lubrication.method=\"oil_bath\""],
            "lubrication.oil_level",
            "needs its level",
        ),
        (
            vec![
                "lubrication.method=\"grease\"",
                "lubricant.oil_flow=\"1 L/min\"",
            ],
            "lubricant.oil_flow",
            "no oil supply flow",
        ),
        (
            vec!["lubricant.oil_flow=\"-1 L/min\""],
            "lubricant.oil_flow",
            "",
        ),
        (
            vec![
                "lubricant.temperature=\"40 degC\"",
                "lubricant.second_viscosity=\"1 Pa.s\"",
                "lubricant.second_temperature=\"100 degC\"",
            ],
            "lubricant.second_viscosity",
            "fall as temperature rises",
        ),
    ] {
        let mut args = vec!["run", "-", "--duration", "1 ms", "-o", "/nonexistent/x"];
        for s in &sets {
            args.extend(["--set", s]);
        }
        let o = rolldyn(&args, Some(&lubricated));
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{sets:?}: {err}");
        assert!(err.contains(key) && err.contains(rule), "{sets:?}: {err}");
    }
    // A method needs the oil: the 6304 preset has no [lubricant].
    let o = rolldyn(
        &["check", "-", "--set", "lubrication.method=\"oil_jet\""],
        Some(&preset("6304")),
    );
    assert_refused(&o, &["[lubricant]"]);
}

/// The drive power over a run's averaging window from its `drive_work_j`
/// channel \[W\].
fn window_drive_power(dir: &std::path::Path, summary: &Value) -> f64 {
    let [t0, t1] = [0, 1].map(|i| summary["averaging_window_s"][i].as_f64().unwrap());
    let series = rolldyn_io::read_parquet(&dir.join("timeseries.parquet")).unwrap();
    let work = series.column("drive_work_j").unwrap();
    let time = series.column("time_s").unwrap();
    let first = time.iter().position(|&t| t >= t0).unwrap();
    (work[work.len() - 1] - work[first]) / (t1 - t0)
}
