//! End-to-end tests of the housing sensor (`[sensor]`, docs/signal.md
//! "Sensor chain"): its channels and summary keys in a run of the CWRU
//! case, the noise's seed, the channel group, and errors that name the key.

#![allow(clippy::unwrap_used)]

use crate::common;

use crate::common::{assert_ok, rolldyn, run_into, stderr, summary_of, temp_dir};
use rolldyn_io::read_parquet;

const CASE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../examples/cwru6205/case.toml"
);

/// The CWRU case (with its `[sensor]`), or without the sensor.
fn case_text(sensor: bool) -> String {
    let text = std::fs::read_to_string(CASE).unwrap();
    if sensor {
        return text;
    }
    let start = text.find("\n[sensor]").unwrap();
    let end = text.find("\n[assumptions]").unwrap();
    let assumptions: Vec<&str> = text[end..]
        .lines()
        .filter(|l| !l.starts_with("\"sensor."))
        .collect();
    format!("{}{}\n", &text[..start], assumptions.join("\n"))
}

/// Runs the case (`sensor`: with its `[sensor]`) for 0.04 s with `extra`
/// arguments; its directory and summary.
fn run(tag: &str, sensor: bool, extra: &[&str]) -> (std::path::PathBuf, serde_json::Value) {
    let dir = temp_dir(tag);
    let mut args = vec![
        "run",
        "-",
        "-o",
        dir.to_str().unwrap(),
        "--duration",
        "0.04 s",
    ];
    args.extend_from_slice(extra);
    let o = rolldyn(&args, Some(&case_text(sensor)));
    assert!(o.status.success(), "{tag}: {}", stderr(&o));
    let text = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    (dir, serde_json::from_str(&text).unwrap())
}

/// A record without noise and without vibration (0.2 ms from rest,
/// without gravity, whose weights move the parts from the start): its
/// crest factor and kurtosis are 0/0, reported null on purpose, with no
/// warning of a non-finite number.
#[test]
fn a_constant_sensor_record_has_no_crest_factor() {
    let dir = temp_dir("sensor-constant");
    let o = run_into(
        dir.to_str().unwrap(),
        None,
        "0.2 ms",
        &["sensor={}", "sensor.noise=0 m/s^2", "model.gravity=false"],
    );
    assert_ok(&o);
    assert!(!stderr(&o).contains("non-finite"), "{}", stderr(&o));
    let summary: serde_json::Value = summary_of(&dir);
    let s = &summary["sensor"];
    assert_eq!(s["rms_m_s2"].as_f64(), Some(0.0), "{s}");
    assert!(
        s["crest_factor"].is_null() && s["kurtosis"].is_null(),
        "{s}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_sensor_records_the_housing_and_the_summary_analyses_it() {
    let (dir, summary) = run("sensor-on", true, &[]);
    let series = read_parquet(&dir.join("timeseries.parquet")).unwrap();
    let acquired = series.column("sensor_acceleration_m_s2").unwrap();
    let housing = series.column("sensor_housing_acceleration_m_s2").unwrap();
    assert_eq!(acquired.len(), series.column("time_s").unwrap().len());
    assert!(acquired.iter().chain(housing).all(|v| v.is_finite()));
    // The pit's impacts ring the housing: far above the 0.01 m/s² noise.
    let rms = |x: &[f64]| (x.iter().map(|v| v * v).sum::<f64>() / x.len() as f64).sqrt();
    assert!(rms(&housing[housing.len() / 2..]) > 1.0);
    let s = &summary["sensor"];
    for key in ["rms_m_s2", "peak_m_s2", "crest_factor", "kurtosis"] {
        assert!(s[key].as_f64().unwrap() > 0.0, "{key}: {s}");
    }
    assert_eq!(s["clipped_samples"], 0);
    assert!(s["kurtosis"].as_f64().unwrap() > 3.0, "impacts: {s}");
    assert_eq!(
        summary["envelope_lines"]["channel"],
        "sensor_acceleration_m_s2"
    );
    // `spectrum` analyses the sensor's record by default.
    let o = rolldyn(
        &[
            "spectrum",
            dir.to_str().unwrap(),
            "--kind",
            "envelope",
            "--json",
        ],
        None,
    );
    assert_ok(&o);
    let spectrum: serde_json::Value = serde_json::from_str(&common::stdout(&o)).unwrap();
    assert_eq!(spectrum["channel"], "sensor_acceleration_m_s2");
    // Without a sensor: no channels, a null key, the ring's channel analysed.
    let (plain, plain_summary) = run("sensor-off", false, &[]);
    let plain_series = read_parquet(&plain.join("timeseries.parquet")).unwrap();
    assert!(plain_series.column("sensor_acceleration_m_s2").is_none());
    assert!(plain_summary["sensor"].is_null());
    assert_eq!(
        plain_summary["envelope_lines"]["channel"],
        "inner_ring_acceleration_z_m_s2"
    );
    // The sensor listens: it leaves the bearing's motion as it was.
    assert_eq!(
        series.column("inner_ring_acceleration_z_m_s2").unwrap(),
        plain_series
            .column("inner_ring_acceleration_z_m_s2")
            .unwrap()
    );
    for d in [dir, plain] {
        std::fs::remove_dir_all(d).ok();
    }
}

#[test]
fn the_seed_draws_the_noise_and_the_group_selects_the_channels() {
    let noisy = |tag: &str, seed: u64| {
        let seed = format!("sensor.seed={seed}");
        let (dir, _) = run(
            tag,
            true,
            &[
                "--set",
                "sensor.noise=\"0.5 m/s^2\"",
                "--set",
                &seed,
                "--set",
                "output.channels=[\"sensor\"]",
            ],
        );
        let series = read_parquet(&dir.join("timeseries.parquet")).unwrap();
        std::fs::remove_dir_all(dir).ok();
        series
    };
    let (a, b, c) = (noisy("seed-a", 1), noisy("seed-b", 1), noisy("seed-c", 2));
    assert_eq!(
        a.names(),
        [
            "time_s",
            "sensor_acceleration_m_s2",
            "sensor_housing_acceleration_m_s2"
        ]
    );
    let acquired =
        |s: &rolldyn_io::TimeSeries| s.column("sensor_acceleration_m_s2").unwrap().to_vec();
    assert_eq!(acquired(&a), acquired(&b));
    assert_ne!(acquired(&a), acquired(&c));
    // The noise is the acquisition's: the housing's true motion is the same.
    let housing = |s: &rolldyn_io::TimeSeries| {
        s.column("sensor_housing_acceleration_m_s2")
            .unwrap()
            .to_vec()
    };
    assert_eq!(housing(&a), housing(&c));
}

#[test]
fn a_small_range_clips_and_warns() {
    let dir = temp_dir("sensor-clip");
    let o = rolldyn(
        &[
            "run",
            CASE,
            "-o",
            dir.to_str().unwrap(),
            "--duration",
            "0.02 s",
            "--set",
            "sensor.full_scale=\"2 g\"",
        ],
        None,
    );
    assert_ok(&o);
    assert!(
        stderr(&o).contains("raise sensor.full_scale"),
        "{}",
        stderr(&o)
    );
    let text = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    let summary: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert!(summary["sensor"]["clipped_samples"].as_u64().unwrap() > 0);
    let series = read_parquet(&dir.join("timeseries.parquet")).unwrap();
    let top = 2.0 * 9.806_65;
    assert!(
        series
            .column("sensor_acceleration_m_s2")
            .unwrap()
            .iter()
            .all(|a| a.abs() <= top)
    );
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn bad_sensor_values_name_the_key() {
    for (set, key) in [
        (
            "sensor.modes=[{ frequency = \"3 kHz\" }]",
            "sensor.modes[0].mass",
        ),
        (
            "sensor.modes=[{ frequency = \"3 kHz\", mass = \"1 kg\", damping_ratio = 1.5 }]",
            "sensor.modes[0].damping_ratio",
        ),
        (
            "sensor.anti_alias_cutoff=\"7 kHz\"",
            "sensor.anti_alias_cutoff",
        ),
        ("sensor.noise=\"-1 m/s^2\"", "sensor.noise"),
        ("sensor.adc_bits=0", "sensor.adc_bits"),
        ("sensor.modes=[]", "sensor.modes"),
        ("sensor.noise=\"1 kg\"", "sensor.noise"),
    ] {
        let o = rolldyn(&["run", CASE, "--duration", "1 ms", "--set", set], None);
        assert_eq!(o.status.code(), Some(2), "{set}");
        assert!(stderr(&o).contains(key), "{set}: {}", stderr(&o));
    }
}

/// An envelope band narrower than twice the fastest defect rate is said
/// (docs/signal.md, "Envelope band"): the CWRU case (12 kHz, band
/// 1.2–4.8 kHz) at 25 000 rpm (BPFI 2.26 kHz) by `check`, which has the
/// spall, and by `spectrum --kind envelope`; at its own 1797 rpm, or
/// sampled at 20 kHz (band 2–8 kHz), not.
#[test]
fn an_envelope_band_too_narrow_for_the_defect_rate_is_said() {
    let fast = "operating.speed=\"25000 rpm\"";
    let check = |sets: &[&str]| {
        let mut args = vec!["check", "-", "--json"];
        for s in sets {
            args.extend(["--set", s]);
        }
        common::json(&args, Some(&case_text(true)))["envelope_band_warning"].clone()
    };
    let warning = check(&[fast]);
    let text = warning.as_str().unwrap();
    assert!(
        text.contains("1200–4800 Hz") && text.contains("16 kHz"),
        "{text}"
    );
    assert!(check(&[]).is_null());
    assert!(check(&[fast, "output.sample_rate=\"20 kHz\""]).is_null());
    for (rate, warned) in [("12 kHz", true), ("20 kHz", false)] {
        let (dir, _) = run(
            "envelope-band",
            true,
            &[
                "--set",
                fast,
                "--set",
                &format!("output.sample_rate=\"{rate}\""),
            ],
        );
        let d = dir.to_str().unwrap();
        let spectrum = common::json(&["spectrum", d, "--kind", "envelope", "--json"], None);
        assert_eq!(
            spectrum["band_warning"].is_string(),
            warned,
            "{rate}: {spectrum}"
        );
        let o = rolldyn(&["spectrum", d, "--kind", "envelope"], None);
        assert_eq!(
            common::stdout(&o).contains("warning: the envelope band"),
            warned
        );
        std::fs::remove_dir_all(&dir).ok();
    }
}

/// The rings' velocity RMS (10–1000 Hz) does not depend on the sample
/// rate: the same trajectory of the CWRU case (the integration does not
/// depend on it) recorded at its 12 kHz and at 48 kHz. Its ring vibrates
/// near 12 kHz too; the velocity's samples at 12 kHz read z 85 % above
/// the 48 kHz value (that vibration folded into the band), the interval
/// means of the displacements 2.5 % below it, asserted within 5 %
/// (docs/signal.md, "Velocity RMS"). `rolldyn spectrum` on the velocity channel reads what the
/// summary does.
#[test]
fn the_rings_velocity_rms_does_not_fold_the_vibration_above_nyquist() {
    let text = case_text(false);
    let at = |rate: &str| {
        let dir = temp_dir(&format!("alias-{rate}"));
        let o = run_into(
            dir.to_str().unwrap(),
            Some(&text),
            "0.1 s",
            &[&format!("output.sample_rate={rate}")],
        );
        assert_ok(&o);
        dir
    };
    let (coarse, fine) = (at("12 kHz"), at("48 kHz"));
    let (c_summary, f_summary) = (summary_of(&coarse), summary_of(&fine));
    for key in [
        "inner_ring_velocity_rms_y_mm_s",
        "inner_ring_velocity_rms_z_mm_s",
    ] {
        let c = c_summary[key].as_f64().unwrap();
        let f = f_summary[key].as_f64().unwrap();
        assert!(
            f > 0.0 && (c / f - 1.0).abs() < 0.05,
            "{key}: {c} at 12 kHz, {f} at 48 kHz"
        );
    }
    let spectrum = common::json(
        &[
            "spectrum",
            coarse.to_str().unwrap(),
            "--channel",
            "inner_ring_velocity_z_m_s",
            "--json",
        ],
        None,
    );
    let (from_spectrum, from_summary) = (
        spectrum["velocity_rms_mm_s"].as_f64().unwrap(),
        c_summary["inner_ring_velocity_rms_z_mm_s"]
            .as_f64()
            .unwrap(),
    );
    // The same method; the summary keeps the window's last half-duration
    // of samples (602 here), the spectrum reads the whole window (619).
    // The velocity's samples would read 0.10 mm/s.
    assert!(
        (from_spectrum / from_summary - 1.0).abs() < 0.01,
        "spectrum {from_spectrum}, summary {from_summary}"
    );
    for dir in [coarse, fine] {
        std::fs::remove_dir_all(dir).ok();
    }
}
