//! The CWRU example against CWRU's measured drive-end record 130 (0.007 in
//! outer-race pit at 6 o'clock, 0 hp), whose statistics
//! scripts/cwru_records.py computed from the record itself into
//! docs/data/cwru_records.csv. Nothing in the example is fitted to the
//! record; the bounds state how far the model is from it today
//! (docs/validation.md, "Against CWRU's measured records": RMS ×2.3, peak
//! ×3.3, crest ×1.4, kurtosis ×2.2, the same five envelope lines), so that
//! a change that moves it much further fails here.

#![allow(clippy::unwrap_used)]

use crate::common::{assert_ok, envelope_json, rolldyn, summary_of, temp_dir};
use std::collections::HashMap;
use std::path::PathBuf;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The measured record's row of docs/data/cwru_records.csv.
fn measured(record: u32) -> HashMap<String, String> {
    let text = std::fs::read_to_string(root().join("docs/data/cwru_records.csv")).unwrap();
    let mut rows = text.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<&str> = rows.next().unwrap().split(',').collect();
    rows.map(|row| {
        header
            .iter()
            .map(|h| h.to_string())
            .zip(row.split(',').map(str::to_string))
            .collect::<HashMap<_, _>>()
    })
    .find(|r| r["record"] == record.to_string())
    .unwrap()
}

#[test]
fn the_outer_race_pit_against_cwru_record_130() {
    let m = measured(130);
    let number = |key: &str| m[key].parse::<f64>().unwrap();
    // The measured envelope's lines, "f:amplitude:line(offset)" each.
    let measured_lines: Vec<String> = m["env_top5_hz_ms2_line"]
        .split(';')
        .map(|l| {
            l.split(':')
                .nth(2)
                .unwrap()
                .split('(')
                .next()
                .unwrap()
                .to_string()
        })
        .collect();
    assert_eq!(measured_lines[0], "BPFO", "the record: {measured_lines:?}");

    let dir = temp_dir("cwru-130");
    let case = root().join("examples/cwru6205/case.toml");
    let o = rolldyn(
        &["run", case.to_str().unwrap(), "-o", dir.to_str().unwrap()],
        None,
    );
    assert_ok(&o);
    let summary: serde_json::Value = summary_of(&dir);
    let sensor = &summary["sensor"];
    let ratio =
        |key: &str, measured_key: &str| sensor[key].as_f64().unwrap() / number(measured_key);
    let (rms, peak, crest, kurtosis) = (
        ratio("rms_m_s2", "rms_ms2"),
        ratio("peak_m_s2", "peak_ms2"),
        ratio("crest_factor", "crest"),
        ratio("kurtosis", "kurtosis"),
    );
    println!(
        "simulated / measured: RMS {rms:.2}, peak {peak:.2}, crest {crest:.2}, kurtosis {kurtosis:.2}"
    );
    for (what, r, low, high) in [
        ("RMS", rms, 1.0, 5.0),
        ("peak", peak, 1.0, 6.0),
        ("crest factor", crest, 0.8, 2.0),
        ("kurtosis", kurtosis, 1.0, 4.0),
    ] {
        assert!(
            (low..=high).contains(&r),
            "{what}: simulated/measured {r:.3} outside [{low}, {high}]"
        );
    }
    let v = envelope_json(
        &dir,
        "sensor_acceleration_m_s2",
        &["--band", "1200:4800 Hz", "--peaks", "4"],
    );
    let simulated: Vec<&str> = v["peaks"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["line"].as_str().unwrap())
        .collect();
    // The measured record's first four lines are BPFO and its harmonics
    // 2–4, largest first; so are the simulated ones.
    let as_written = |l: &str| l.replace('*', "×");
    assert_eq!(
        simulated,
        measured_lines[..4]
            .iter()
            .map(|l| as_written(l))
            .collect::<Vec<_>>(),
        "envelope lines"
    );
    std::fs::remove_dir_all(&dir).ok();
}
