//! What a run records: the channel groups, balls, precision and slow
//! channels of `[output]`, and where they go (docs/cli.md, "Choose what to
//! record" and "Slow channels").

#![allow(clippy::unwrap_used)]

use crate::common::{assert_ok, assert_refused, rolldyn, run_into, stdout, summary_of, temp_dir};
use serde_json::Value;

/// `output.channels`, `output.balls` and `output.precision` choose what the
/// time series holds; the summary is computed from every channel anyway.
#[test]
fn recorded_channels_are_chosen_and_the_summary_does_not_change() {
    let all = temp_dir("record-all");
    let some = temp_dir("record-some");
    let (a, s) = (all.to_str().unwrap(), some.to_str().unwrap());
    let o = run_into(a, None, "2 ms", &[]);
    assert_ok(&o);
    let o = run_into(
        s,
        None,
        "2 ms",
        &[
            "output.channels=[\"cage\", \"contacts\"]",
            "output.balls=[1]",
            "output.precision=\"float32\"",
        ],
    );
    assert_ok(&o);
    let summary = |d: &std::path::Path| {
        let mut v: Value = summary_of(d);
        v["wall_time_s"] = Value::Null;
        v
    };
    assert_eq!(summary(&all), summary(&some));
    let full = rolldyn_io::read_parquet(&all.join("timeseries.parquet")).unwrap();
    let chosen = rolldyn_io::read_parquet(&some.join("timeseries.parquet")).unwrap();
    assert_eq!(chosen.len(), full.len());
    let names = chosen.names();
    assert_eq!(names[0], "time_s");
    assert!(names.iter().any(|n| n == "cage_speed_rpm"));
    assert!(names.iter().any(|n| n == "ball1_load_inner_n"));
    assert!(
        !names
            .iter()
            .any(|n| n.starts_with("ball0_") || n.starts_with("ball2_"))
    );
    assert!(
        !names
            .iter()
            .any(|n| n == "ball1_yaw_deg" || n == "drive_work_j")
    );
    // Float32: the values are the full run's, rounded to 7 digits.
    for (x, y) in chosen
        .column("cage_speed_rpm")
        .unwrap()
        .iter()
        .zip(full.column("cage_speed_rpm").unwrap())
    {
        assert_eq!(*x, f64::from(*y as f32));
    }
    // An unknown group is refused, naming the entry.
    let o = run_into(s, None, "1 ms", &["output.channels=[\"sensors\"]"]);
    assert_refused(&o, &["output.channels[0]"]);
    std::fs::remove_dir_all(&all).ok();
    std::fs::remove_dir_all(&some).ok();
}

/// `output.slow_channels` at `output.slow_rate` go into
/// `timeseries_slow.parquet` (one sample in every rate / slow_rate, the
/// first included), also across a resume; spectrum and report find them.
#[test]
fn slow_channels_are_recorded_at_their_rate_and_resume() {
    let dir = temp_dir("record-slow");
    let d = dir.to_str().unwrap();
    let o = run_into(
        d,
        None,
        "2 ms",
        &[
            "output.sample_rate=\"20 kHz\"",
            "output.slow_channels=[\"energy\", \"power\"]",
            "output.slow_rate=\"2 kHz\"",
        ],
    );
    assert_ok(&o);
    let o = rolldyn(&["run", "--resume", d, "--until", "3 ms", "--report"], None);
    assert_ok(&o);
    let main = rolldyn_io::read_parquet(&dir.join("timeseries.parquet")).unwrap();
    let slow = rolldyn_io::read_parquet(&dir.join("timeseries_slow.parquet")).unwrap();
    assert_eq!(main.len(), 61);
    assert_eq!(slow.len(), 7, "samples 0, 10, …, 60");
    assert!(main.column("power_total_w").is_none() && main.column("drive_work_j").is_none());
    let (t, tm) = (
        slow.column("time_s").unwrap(),
        main.column("time_s").unwrap(),
    );
    for (k, t) in t.iter().enumerate() {
        assert_eq!(*t, tm[10 * k]);
    }
    assert!(slow.column("power_total_w").is_some());
    let o = rolldyn(&["spectrum", d, "--list"], None);
    assert!(stdout(&o).contains("power_total_w [W]"), "{}", stdout(&o));
    let html = std::fs::read_to_string(dir.join("report.html")).unwrap();
    assert!(html.contains("Friction power") && html.contains("Energy balance"));
    std::fs::remove_dir_all(&dir).ok();
}

/// A run into a directory an earlier `--verify` ran into removes the
/// verifying runs it left (`verify/`, `verify-grid/`), which its summary
/// would not name; a folder of such a name that is not a run directory
/// is the user's and stays.
#[test]
fn a_run_removes_an_earlier_runs_verify_runs() {
    let dir = temp_dir("stale-verify");
    let verify = dir.join("verify");
    std::fs::create_dir_all(verify.join("timeseries.parquet")).unwrap();
    std::fs::write(verify.join("run.json"), "{}").unwrap();
    let mine = dir.join("verify-grid");
    std::fs::create_dir_all(&mine).unwrap();
    std::fs::write(mine.join("notes.txt"), "mine").unwrap();
    let d = dir.to_str().unwrap();
    let o = run_into(d, None, "1 ms", &[]);
    assert_ok(&o);
    assert!(!verify.exists());
    assert_eq!(
        std::fs::read_to_string(mine.join("notes.txt")).unwrap(),
        "mine"
    );
    assert!(summary_of(&dir)["accuracy"]["verify"].is_null());
    std::fs::remove_dir_all(&dir).ok();
}

/// `run --sweep axial=100N,200N` of 1 ms into `dir`.
fn sweep_two_points(dir: &str) -> std::process::Output {
    rolldyn(
        &[
            "run",
            "--duration",
            "1 ms",
            "--sweep",
            "axial=100N,200N",
            "-o",
            dir,
        ],
        None,
    )
}

/// A directory holds one run or one sweep: each removes the other.
#[test]
fn a_run_replaces_an_earlier_sweep_in_its_directory_and_a_sweep_a_run() {
    let dir = temp_dir("run-or-sweep");
    let d = dir.to_str().unwrap();
    let o = sweep_two_points(d);
    assert_ok(&o);
    assert!(dir.join("sweep.json").is_file() && dir.join("point-0001").is_dir());
    // A run into the sweep's directory: the sweep goes, and the report
    // describes the run (a report prefers a sweep's table when both are there).
    let o = rolldyn(&["run", "--duration", "1 ms", "-o", d, "--report"], None);
    assert_ok(&o);
    assert!(!dir.join("sweep.json").exists() && !dir.join("sweep.csv").exists());
    assert!(!dir.join("point-0000").exists() && !dir.join("point-0001").exists());
    assert!(summary_of(&dir)["status"] == "completed");
    let report = std::fs::read_to_string(dir.join("report.html")).unwrap();
    assert!(
        !report.contains("<title>rolldyn sweep</title>"),
        "the report is the run's"
    );
    // A sweep into the run's directory: the run's files go.
    let o = sweep_two_points(d);
    assert_ok(&o);
    for gone in ["run.json", "summary.json", "timeseries.parquet"] {
        assert!(!dir.join(gone).exists(), "{gone}");
    }
    assert!(dir.join("sweep.json").is_file());
    std::fs::remove_dir_all(&dir).ok();
}

/// A sweep into a directory an earlier, larger sweep ran into removes the
/// points it does not write again (`sweep.json` would not list them, but
/// `point-*` would find them); folders that are not run directories
/// named `point-` and digits stay.
#[test]
fn a_sweep_removes_an_earlier_sweeps_other_points() {
    let dir = temp_dir("stale-points");
    let plant = |name: &str, record: bool| {
        let point = dir.join(name);
        std::fs::create_dir_all(&point).unwrap();
        if record {
            std::fs::write(point.join("run.json"), "{}").unwrap();
        }
        point
    };
    let stale = plant("point-0007", true);
    let wider = plant("point-00001", true);
    let notes = plant("point-notes", true);
    let bare = plant("point-0009", false);
    let o = sweep_two_points(dir.to_str().unwrap());
    assert_ok(&o);
    assert!(!stale.exists() && !wider.exists());
    assert!(notes.exists() && bare.exists());
    for point in ["point-0000", "point-0001"] {
        assert!(summary_of(&dir.join(point))["status"] == "completed");
    }
    std::fs::remove_dir_all(&dir).ok();
}
