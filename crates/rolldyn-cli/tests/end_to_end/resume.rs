//! Nothing lost: a run killed with SIGKILL at a random moment leaves a
//! readable time series of everything up to its last checkpoint, and
//! `rolldyn run --resume DIR` finishes it with the same part files and
//! the same summary as an uninterrupted run (both adaptive integrators). `scripts/kill-resume.sh`
//! repeats this for 20 runs at random moments.

#![allow(clippy::unwrap_used)]

use crate::common;

use crate::common::{
    assert_ok, assert_refused, pair, rolldyn, run_into, stderr, summary_of, temp_dir,
};
use std::path::Path;
use std::process::{Command, Stdio};

/// The default case with a sensor, shortened to `duration`; `integrator`
/// chosen.
/// At 40 kHz the ROS34PW2 run's time series spans two part files, so
/// that a kill can fall on either side of the boundary.
fn args<'a>(dir: &'a str, integrator: &'a str, duration: &'a str) -> Vec<&'a str> {
    vec![
        "run",
        "-o",
        dir,
        "--duration",
        duration,
        "--set",
        integrator,
        "--set",
        "output.sample_rate=\"40 kHz\"",
        // The sensor chain's state (modes, filter, noise generator) is in
        // the checkpoint too.
        "--set",
        "sensor={ noise = \"0.05 m/s^2\" }",
        "--checkpoint-interval",
        "0 s",
    ]
}

fn summary(dir: &Path) -> serde_json::Value {
    let text = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v.as_object_mut().unwrap().remove("wall_time_s");
    v
}

#[test]
fn killed_run_is_readable_and_resumes_bit_identically() {
    // Long enough (a few seconds each) for two checkpoints before the kill.
    for (tag, integrator, duration) in [
        ("ros", "solver.integrator=\"ros34pw2\"", "0.15 s"),
        ("dopri", "solver.integrator=\"dopri5\"", "0.02 s"),
    ] {
        let whole = temp_dir(&format!("resume-whole-{tag}"));
        let killed = temp_dir(&format!("resume-killed-{tag}"));
        let (w, k) = (whole.to_str().unwrap(), killed.to_str().unwrap());
        let o = rolldyn(&args(w, integrator, duration), None);
        assert_ok(&o);
        assert!(
            whole.join("checkpoint.bin").exists(),
            "a completed run keeps its last state (for --until)"
        );

        // Kill the same run once two checkpoints have been written.
        let mut child = Command::new(env!("CARGO_BIN_EXE_rolldyn"))
            .args(args(k, integrator, duration))
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        common::kill_after_two_checkpoints(&mut child, &killed);

        // What is left is readable: the Parquet file and a partial summary.
        let partial = rolldyn_io::read_parquet(&killed.join("timeseries.parquet")).unwrap();
        assert!(!partial.is_empty());
        let s = summary(&killed);
        assert_eq!(s["status"], "partial", "{tag}");
        assert!(
            s["simulated_time_s"].as_f64().unwrap() < s["requested_duration_s"].as_f64().unwrap()
        );
        let leftovers: Vec<_> = std::fs::read_dir(&killed)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|n| n.starts_with('.'))
            .collect();
        // A temporary file can remain only from a write the kill cut short.
        assert!(leftovers.len() <= 1, "{tag}: {leftovers:?}");

        // An edited record no longer matches the checkpoint.
        let record = std::fs::read_to_string(killed.join("run.json")).unwrap();
        let edited = record.replace("\"force\": false", "\"force\": true");
        assert_ne!(edited, record);
        std::fs::write(killed.join("run.json"), &edited).unwrap();
        let o = rolldyn(&["run", "--resume", k], None);
        assert_refused(&o, &["does not belong"]);
        std::fs::write(killed.join("run.json"), &record).unwrap();

        let o = rolldyn(&["run", "--resume", k], None);
        assert!(o.status.success(), "{tag}: {}", stderr(&o));
        assert_eq!(
            common::series_bytes(&killed),
            common::series_bytes(&whole),
            "{tag}: the resumed time series differs from the uninterrupted one"
        );
        assert_eq!(summary(&killed), summary(&whole), "{tag}");
        std::fs::remove_dir_all(&whole).ok();
        std::fs::remove_dir_all(&killed).ok();
    }
}

/// A run extended with `--until` rewrites the report an earlier run left
/// in its directory, which would describe the shorter run.
#[test]
fn an_extended_run_rewrites_its_report() {
    let dir = temp_dir("resume-report");
    let d = dir.to_str().unwrap();
    let o = rolldyn(&["run", "-o", d, "--duration", "0.2 ms", "--report"], None);
    assert_ok(&o);
    let before = std::fs::read_to_string(dir.join("report.html")).unwrap();
    let o = rolldyn(&["run", "--resume", d, "--until", "0.4 ms"], None);
    assert_ok(&o);
    assert!(String::from_utf8_lossy(&o.stdout).contains("report.html"));
    let after = std::fs::read_to_string(dir.join("report.html")).unwrap();
    assert_ne!(before, after);
    assert!(
        after.contains("--set solver.duration=0.0004 s"),
        "the extended record"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn resume_refuses_what_it_cannot_continue() {
    let dir = temp_dir("resume-refuse");
    let d = dir.to_str().unwrap();
    // Nothing there.
    let o = rolldyn(&["run", "--resume", d], None);
    assert_refused(&o, &["run.json"]);
    // A completed run is complete: --until extends it, not --resume alone.
    let o = run_into(d, None, "0.2 ms", &[]);
    assert_ok(&o);
    let o = rolldyn(&["run", "--resume", d], None);
    assert_refused(&o, &["--until"]);
    // --until must go beyond where the run is, and only with --resume.
    let o = rolldyn(&["run", "--resume", d, "--until", "0.1 ms"], None);
    assert_refused(&o, &["already at"]);
    let o = rolldyn(&["run", "--until", "1 ms"], None);
    assert_refused(&o, &["--resume"]);
    // The case comes from the directory, not the command line.
    let o = rolldyn(&["run", "--resume", d, "--speed", "1000 rpm"], None);
    assert_refused(&o, &["--resume"]);
    // The checkpoint's own checks, on a run whose summary says it did not
    // complete (a completed one is refused before them, above).
    let summary = std::fs::read_to_string(dir.join("summary.json"))
        .unwrap()
        .replace("\"completed\"", "\"partial\"");
    std::fs::write(dir.join("summary.json"), summary).unwrap();
    // No checkpoint at all (removed): refused, naming it.
    std::fs::remove_file(dir.join("checkpoint.bin")).unwrap();
    let o = rolldyn(&["run", "--resume", d], None);
    assert_refused(&o, &["checkpoint.bin"]);
    // A damaged checkpoint is refused with the reason.
    std::fs::write(dir.join("checkpoint.bin"), b"not a checkpoint").unwrap();
    let o = rolldyn(&["run", "--resume", d], None);
    assert_refused(&o, &["checkpoint"]);
    // A run of another format (an older rolldyn's) is refused, saying so.
    let record = std::fs::read_to_string(dir.join("run.json")).unwrap();
    let mut old: serde_json::Value = serde_json::from_str(&record).unwrap();
    old["format"] = 2.into();
    std::fs::write(dir.join("run.json"), old.to_string()).unwrap();
    let o = rolldyn(&["run", "--resume", d], None);
    assert_refused(&o, &["format 2"]);
    // Same version, another build: named as such.
    assert!(
        stderr(&o).contains("written by another build of rolldyn")
            && stderr(&o).contains("build that started it"),
        "{}",
        stderr(&o)
    );
    // Another version: named.
    old["rolldyn_version"] = "0.0.9".into();
    std::fs::write(dir.join("run.json"), old.to_string()).unwrap();
    let o = rolldyn(&["run", "--resume", d], None);
    assert_refused(&o, &["written by rolldyn 0.0.9 (this rolldyn reads format"]);
    std::fs::remove_dir_all(&dir).ok();
}

/// `--resume DIR --until T` extends a finished run: the time series goes
/// on without a gap, the summary is over the new duration, and the cage
/// speed is the one of a run asked for T from the start.
#[test]
fn until_extends_a_finished_run() {
    let dir = temp_dir("resume-until");
    let straight = temp_dir("resume-until-straight");
    let (d, s) = (dir.to_str().unwrap(), straight.to_str().unwrap());
    let o = run_into(d, None, "2 ms", &[]);
    assert_ok(&o);
    let o = rolldyn(&["run", "--resume", d, "--until", "4 ms"], None);
    assert_ok(&o);
    let o = run_into(s, None, "4 ms", &[]);
    assert_ok(&o);
    let (extended, whole) = (summary(&dir), summary(&straight));
    assert_eq!(extended["status"], "completed");
    assert_eq!(extended["requested_duration_s"], 0.004);
    assert_eq!(extended["samples"], whole["samples"]);
    let series = rolldyn_io::read_parquet(&dir.join("timeseries.parquet")).unwrap();
    let time = series.column("time_s").unwrap();
    assert_eq!(time.len() as u64, extended["samples"].as_u64().unwrap());
    assert!(time.windows(2).all(|w| w[1] > w[0]), "time runs on");
    // The same motion, integrated with one more step boundary at 2 ms.
    let cage = |v: &serde_json::Value| v["mean_cage_speed_rpm"].as_f64().unwrap();
    assert!((cage(&extended) - cage(&whole)).abs() < 1e-4 * cage(&whole));
    // The record now says 4 ms, and the run extends again from there.
    let record = std::fs::read_to_string(dir.join("run.json")).unwrap();
    assert!(record.contains("solver.duration=0.004 s"), "{record}");
    let o = rolldyn(&["run", "--resume", d, "--until", "5 ms"], None);
    assert_ok(&o);
    assert_eq!(summary(&dir)["requested_duration_s"], 0.005);
    std::fs::remove_dir_all(&dir).ok();
    std::fs::remove_dir_all(&straight).ok();
}

/// A set's run killed after two checkpoints resumes to the bytes of the
/// uninterrupted run (series and summary), as a single bearing's does;
/// `--until` extends a finished one without a gap.
#[test]
fn a_set_run_resumes_bit_identically() {
    let case = pair("kind = \"back_to_back\"\npreload = \"200 N\"");
    let dir = temp_dir("set-resume");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("case.toml");
    std::fs::write(&path, &case).unwrap();
    let args = |out: &str| {
        vec![
            "run".to_string(),
            path.to_str().unwrap().to_string(),
            // Long enough that the second checkpoint (the first one's
            // cost times 50 later: ~3.5 s in a debug build) comes well
            // before the end.
            "--duration".into(),
            "160 ms".into(),
            "--set".into(),
            "output.sample_rate=\"5 kHz\"".into(),
            "--checkpoint-interval".into(),
            "0 s".into(),
            "-o".into(),
            out.to_string(),
        ]
    };
    let (whole, killed) = (dir.join("whole"), dir.join("killed"));
    let o = Command::new(env!("CARGO_BIN_EXE_rolldyn"))
        .args(args(whole.to_str().unwrap()))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut child = Command::new(env!("CARGO_BIN_EXE_rolldyn"))
        .args(args(killed.to_str().unwrap()))
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    common::kill_after_two_checkpoints(&mut child, &killed);
    let read = |d: &std::path::Path| {
        let mut v: serde_json::Value = summary_of(d);
        v.as_object_mut().unwrap().remove("wall_time_s");
        v
    };
    assert_eq!(read(&killed)["status"], "partial");
    let o = rolldyn(&["run", "--resume", killed.to_str().unwrap()], None);
    assert_ok(&o);
    assert_eq!(
        common::series_bytes(&killed),
        common::series_bytes(&whole),
        "the resumed series differs from the uninterrupted one"
    );
    assert_eq!(read(&killed), read(&whole));
    let o = rolldyn(
        &[
            "run",
            "--resume",
            whole.to_str().unwrap(),
            "--until",
            "164 ms",
        ],
        None,
    );
    assert_ok(&o);
    let extended = read(&whole);
    assert_eq!(extended["status"], "completed");
    assert_eq!(extended["samples"], 821);
    std::fs::remove_dir_all(&dir).ok();
}
