//! End-to-end tests of friction power and temperatures (issue 13):
//! `run`'s power channels and means, `rolldyn power`, `rolldyn thermal`.

#![allow(clippy::unwrap_used)]

mod common;

use common::{rolldyn, stderr, temp_dir};
use serde_json::Value;

/// The default case's run: the component means sum to the mean
/// dissipated power of the energy balance (sampling error only: the
/// accumulator is exact between samples; 2 %), every component key is
/// there, and the friction torque times the ring speed is the drive power.
#[test]
fn run_reports_power_by_component() {
    let dir = temp_dir("power-run");
    let d = dir.to_string_lossy().into_owned();
    let o = rolldyn(&["run", "--duration", "8 ms", "-o", &d], None);
    assert!(o.status.success(), "{}", stderr(&o));
    let s: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    let f = |k: &str| s[k].as_f64().unwrap_or_else(|| panic!("{k} missing"));
    let (sum, exact) = (f("mean_power_loss_w"), f("mean_dissipated_power_w"));
    assert!(
        sum > 0.0 && ((sum - exact) / exact).abs() < 0.02,
        "{sum} W vs {exact} W"
    );
    let parts = s["mean_power_loss_by_component_w"].as_object().unwrap();
    assert_eq!(parts.len(), 18, "{parts:?}");
    for ring in ["inner", "outer"] {
        for m in [
            "rolling_sliding",
            "transverse_sliding",
            "spin",
            "differential_sliding",
            "hysteresis",
            "damping",
        ] {
            assert!(parts.contains_key(&format!("{ring}_{m}")), "{ring}_{m}");
        }
    }
    let omega = f("inner_ring_speed_rpm") * std::f64::consts::TAU / 60.0;
    let torque_power = f("mean_friction_torque_n_m") * omega;
    assert!(
        ((torque_power - sum) / sum).abs() < 0.05,
        "{torque_power} W vs {sum} W"
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
