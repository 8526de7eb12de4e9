//! Validation of the fault signatures a housing accelerometer records
//! (`[sensor]`) against what the diagnostics literature reports for
//! localised bearing faults (Randall & Antoni 2011, "Rolling element
//! bearing diagnostics — a tutorial"; the CWRU records): on the CWRU 6205
//! case, the envelope spectrum of the acquired signal (band 1.2–4.8 kHz,
//! around the housing's resonance) leads with BPFO for an outer-race pit
//! in the load zone, shows 2×BSF above the raceway lines for a ball pit,
//! and its lines grow with the pit and with the load. docs/validation.md ("Fault signatures")
//! has the numbers.

#![allow(clippy::unwrap_used)]

use crate::common::{assert_ok, rolldyn, stderr, temp_dir};
use serde_json::Value;
use std::path::Path;

const CASE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../examples/cwru6205/case.toml"
);

/// Runs the CWRU case (0.3 s: 6.4 Hz lines over the summary's second
/// half) with `sets` and `sweeps`; the points' `envelope_lines`, in the
/// sweep's order, as name → amplitude.
fn envelope_lines(tag: &str, sets: &[&str], sweeps: &[&str]) -> Vec<Vec<(String, f64)>> {
    let dir = temp_dir(tag);
    let mut args = vec!["run", CASE, "-o", dir.to_str().unwrap()];
    for s in sets {
        args.extend_from_slice(&["--set", s]);
    }
    for s in sweeps {
        args.extend_from_slice(&["--sweep", s]);
    }
    let o = rolldyn(&args, None);
    assert!(o.status.success(), "{tag}: {}", stderr(&o));
    let mut points: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.join("summary.json").is_file())
        .collect();
    points.sort();
    let lines = points.iter().map(|p| lines_of(p)).collect();
    std::fs::remove_dir_all(&dir).ok();
    lines
}

fn lines_of(point: &Path) -> Vec<(String, f64)> {
    let text = std::fs::read_to_string(point.join("summary.json")).unwrap();
    let summary: Value = serde_json::from_str(&text).unwrap();
    let envelope = &summary["envelope_lines"];
    assert_eq!(envelope["channel"], "sensor_acceleration_m_s2");
    envelope["lines"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| {
            (
                l["name"].as_str().unwrap().to_string(),
                l["amplitude_m_s2"].as_f64().unwrap(),
            )
        })
        .collect()
}

fn amplitude(lines: &[(String, f64)], name: &str) -> f64 {
    lines.iter().find(|(n, _)| n == name).unwrap().1
}

fn leader(lines: &[(String, f64)]) -> &str {
    &lines.iter().max_by(|a, b| a.1.total_cmp(&b.1)).unwrap().0
}

/// An outer-race pit at 6 o'clock: BPFO leads, and grows with the pit
/// (0.007 → 0.021 in, 500 N) and with the radial load (0.021 in, 500 →
/// 1000 N).
#[test]
fn an_outer_race_pit_gives_bpfo_growing_with_size_and_load() {
    let sizes = envelope_lines(
        "diagnostics-outer-size",
        &[],
        &["surface.outer.spall.0.length=0.1778 mm,0.5334 mm"],
    );
    let loaded = envelope_lines(
        "diagnostics-outer-load",
        &["surface.outer.spall.0.length=\"0.5334 mm\""],
        &["operating.radial_load=1000 N"],
    );
    for p in sizes.iter().chain(&loaded) {
        assert_eq!(leader(p), "BPFO", "{p:?}");
    }
    let bpfo = |p: &[(String, f64)]| amplitude(p, "BPFO");
    assert!(bpfo(&sizes[1]) > bpfo(&sizes[0]), "size: {sizes:?}");
    assert!(
        bpfo(&loaded[0]) > bpfo(&sizes[1]),
        "load: {loaded:?} vs {sizes:?}"
    );
}

/// A pit on a ball strikes both races once per ball turn, and the ball
/// carries it through the load zone once per cage turn: 2×BSF stands
/// above the raceway lines and grows with the pit; the cage line f_c
/// (the modulation) is of the same order (docs/validation.md).
#[test]
fn a_ball_pit_gives_twice_the_ball_spin_frequency() {
    let points = envelope_lines(
        "diagnostics-ball",
        &[
            "surface.outer.spall=[]",
            "surface.balls.spall=[{ ball = 0, position = \"0 deg\", length = \"0.1778 mm\", depth = \"0.2794 mm\" }]",
        ],
        &["surface.balls.spall.0.length=0.1778 mm,0.5334 mm"],
    );
    for p in &points {
        let ball = amplitude(p, "2×BSF");
        assert!(
            ball > amplitude(p, "BPFO") && ball > amplitude(p, "BPFI"),
            "{p:?}"
        );
        assert!(amplitude(p, "f_c") > 0.3 * ball, "{p:?}");
    }
    assert!(amplitude(&points[1], "2×BSF") > amplitude(&points[0], "2×BSF"));
}

/// A growing spall (`growth_rate`) follows L₀ + g t in steps taken
/// between ball passes, with the energy balance closed, and a resumed run
/// (`--until`) continues from the length it had reached.
#[test]
fn a_spall_grows_between_ball_passes_and_a_resumed_run_keeps_its_length() {
    let dir = temp_dir("diagnostics-growth");
    let d = dir.to_str().unwrap();
    let growth = "surface.outer.spall.0.growth_rate=\"2 mm/s\"";
    let o = rolldyn(
        &[
            "run",
            CASE,
            "-o",
            d,
            "--duration",
            "0.03 s",
            "--set",
            growth,
        ],
        None,
    );
    assert_ok(&o);
    let o = rolldyn(&["run", "--resume", d, "--until", "0.06 s"], None);
    assert_ok(&o);
    let series = rolldyn_io::read_parquet(&dir.join("timeseries.parquet")).unwrap();
    let (time, length) = (
        series.column("time_s").unwrap(),
        series.column("spall0_length_m").unwrap(),
    );
    assert!(length.windows(2).all(|w| w[1] >= w[0]), "never shrinks");
    let (l0, rate) = (0.178e-3, 2e-3); // the case's pit: 0.178 mm
    // Ball passes over the 6 o'clock pit every 1/BPFO = 9.3 ms; between
    // them the pit catches up to within 1 % of its length.
    for (&t, &l) in time.iter().zip(length) {
        let target = l0 + rate * t;
        // A sample between two steps reads the length of the later one.
        assert!(l <= target + rate * 2e-4, "t {t}: {l} ahead of {target}");
        assert!(
            l >= target - rate * 0.0093 - 0.01 * target,
            "t {t}: {l} behind {target}"
        );
    }
    let text = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    let summary: Value = serde_json::from_str(&text).unwrap();
    let balance = summary["energy_balance_relative_error"].as_f64().unwrap();
    assert!(balance.abs() < 1e-3, "{balance}");
    let growth = &summary["spall_growth"][0];
    assert_eq!(growth["stalled"], false, "{growth}");
    assert!((growth["asked_length_m"].as_f64().unwrap() - (l0 + rate * 0.06)).abs() < 1e-12);
    std::fs::remove_dir_all(&dir).ok();
}

/// A pit longer than the balls' spacing on the outer race (16.4 mm on
/// the 6205) always has a ball on it in the load zone: it cannot grow,
/// and the run says so (a warning and `stalled` in the summary).
#[test]
fn a_spall_that_cannot_grow_says_so() {
    let dir = temp_dir("diagnostics-stall");
    let o = rolldyn(
        &[
            "run",
            CASE,
            "-o",
            dir.to_str().unwrap(),
            "--duration",
            "0.05 s",
            "--set",
            "surface.outer.spall.0.length=\"17 mm\"",
            "--set",
            "surface.outer.spall.0.depth=\"2 um\"",
            "--set",
            "surface.outer.spall.0.growth_rate=\"10 mm/s\"",
        ],
        None,
    );
    assert_ok(&o);
    assert!(
        stderr(&o).contains("growing spall 0 reached"),
        "{}",
        stderr(&o)
    );
    let text = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    let summary: Value = serde_json::from_str(&text).unwrap();
    let growth = &summary["spall_growth"][0];
    assert_eq!(growth["stalled"], true, "{growth}");
    assert!(growth["length_m"].as_f64().unwrap() < 17.1e-3, "{growth}");
    std::fs::remove_dir_all(&dir).ok();
}
