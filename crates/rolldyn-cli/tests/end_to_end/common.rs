//! Helpers of the end-to-end tests: run the `rolldyn` binary, read its
//! output, temporary directories.

#![allow(dead_code, clippy::unwrap_used)]

use serde_json::Value;

/// The FASTSIM law as a `--set` override (μ = 0.1).
pub const FASTSIM: &str = "model.traction={ law = \"fastsim\", friction = 0.1 }";
use std::io::Write;
use std::process::{Command, Output, Stdio};

/// Runs `rolldyn` with `args` and `stdin`. On one thread unless the
/// environment sets `RAYON_NUM_THREADS`: the test threads already fill
/// the cores, and two runs with two threads each on a two-core machine
/// took 1.5 times as long as one after the other (their pools' threads
/// wait actively, docs/performance.md). The results do not depend on
/// the threads (the tests that compare thread counts set their own).
pub fn rolldyn(args: &[&str], stdin: Option<&str>) -> Output {
    let threads = std::env::var("RAYON_NUM_THREADS").unwrap_or_else(|_| "1".into());
    let mut child = Command::new(env!("CARGO_BIN_EXE_rolldyn"))
        .env("RAYON_NUM_THREADS", threads)
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("rolldyn starts");
    {
        let mut pipe = child.stdin.take().expect("stdin");
        if let Some(text) = stdin {
            // The command may refuse its arguments and exit before reading
            // the case: a broken pipe is then expected.
            if let Err(e) = pipe.write_all(text.as_bytes()) {
                assert_eq!(e.kind(), std::io::ErrorKind::BrokenPipe, "write stdin: {e}");
            }
        }
    }
    child.wait_with_output().expect("rolldyn finishes")
}

pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Asserts that a command succeeded, showing its stderr where not.
#[track_caller]
pub fn assert_ok(o: &Output) {
    assert!(o.status.success(), "{}", stderr(o));
}

/// Asserts that a command was refused as bad input (exit 2) with each of
/// `needles` in its message.
#[track_caller]
pub fn assert_refused(o: &Output, needles: &[&str]) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    for needle in needles {
        assert!(err.contains(needle), "no {needle:?} in: {err}");
    }
}

/// `rolldyn run` of `case` (None: the built-in default) for `duration`
/// into `dir`, each of `sets` given as a `--set`.
pub fn run_into(
    dir: impl AsRef<std::path::Path>,
    case: Option<&str>,
    duration: &str,
    sets: &[&str],
) -> Output {
    let dir = dir.as_ref().to_str().unwrap();
    let mut args = vec!["run"];
    if case.is_some() {
        args.push("-");
    }
    args.extend(["--duration", duration, "-o", dir]);
    for s in sets {
        args.extend(["--set", s]);
    }
    rolldyn(&args, case)
}

pub fn json(args: &[&str], stdin: Option<&str>) -> Value {
    let o = rolldyn(args, stdin);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    serde_json::from_str(&stdout(&o)).expect("valid JSON")
}

pub fn keys(v: &Value) -> Vec<String> {
    let mut k: Vec<String> = v.as_object().expect("object").keys().cloned().collect();
    k.sort();
    k
}

/// A fresh directory name under the system's temporary directory, unique
/// to this process and this call (the test modules share one process).
pub fn temp_dir(tag: &str) -> std::path::PathBuf {
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("rolldyn-{tag}-{}-{call}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    dir
}

/// The first part file of a run's time series (a Parquet dataset).
pub fn first_part(run: &std::path::Path) -> std::path::PathBuf {
    run.join("timeseries.parquet").join("part-000000.parquet")
}

/// The bytes of a run's time series: its part files in order, each
/// preceded by its name.
pub fn series_bytes(run: &std::path::Path) -> Vec<u8> {
    let parts = rolldyn_io::part_files(&run.join("timeseries.parquet")).unwrap();
    assert!(!parts.is_empty(), "{}: no part file", run.display());
    let mut bytes = Vec::new();
    for part in parts {
        bytes.extend_from_slice(part.file_name().unwrap().to_string_lossy().as_bytes());
        bytes.extend(std::fs::read(part).unwrap());
    }
    bytes
}

/// The summary.json of run directory `dir`.
pub fn summary_of(dir: &std::path::Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap()
}

/// Runs `case` (None: the built-in default) for `duration` with `sets`
/// and returns its summary (the run directory removed).
pub fn run_summary(tag: &str, case: Option<&str>, duration: &str, sets: &[&str]) -> Value {
    let dir = temp_dir(tag);
    assert_ok(&run_into(&dir, case, duration, sets));
    let summary = summary_of(&dir);
    std::fs::remove_dir_all(&dir).ok();
    summary
}

/// The default case (7008C) as a matched set.
pub fn pair(arrangement: &str) -> String {
    let o = rolldyn(&["new", "--preset", "7008C"], None);
    // The pair is its own mounting: the single bearing's lines go; each
    // ring keeps the 0.5 kg of Deng et al. 2022's case (examples/seed001).
    let bearing = rolldyn_case::presets::without_mounting(&stdout(&o))
        .replace("[inner_ring]\n", "[inner_ring]\nmass = \"0.5 kg\"\n");
    format!("{bearing}\n[arrangement]\n{arrangement}\n")
}

/// Two 6206 on a rigid shaft 120 mm apart, a gear force of 4 kN at
/// x = +20 mm with a 300 N thrust (`[shaft]`).
pub const SHAFT: &str = r#"
[operating]
speed = "3000 rpm"
[shaft]
[[shaft.bearings]]
preset = "6206"
position = "-60 mm"
[[shaft.bearings]]
preset = "6206"
position = "60 mm"
orientation = "ORIENTATION"
[[shaft.loads]]
position = "20 mm"
force_z = "-4 kN"
force_x = "300 N"
"#;

/// Waits until the run `child` writing into `dir` has written two
/// checkpoints, then kills it (SIGKILL).
pub fn kill_after_two_checkpoints(child: &mut std::process::Child, dir: &std::path::Path) {
    use std::time::{Duration, Instant};
    let begun = Instant::now();
    let mut seen = Vec::new();
    while seen.len() < 2 {
        assert!(
            child.try_wait().unwrap().is_none(),
            "the run ended before it could be killed; lengthen it"
        );
        assert!(begun.elapsed() < Duration::from_secs(120));
        if let Ok(m) = std::fs::metadata(dir.join("checkpoint.bin")) {
            let stamp = m.modified().unwrap();
            if !seen.contains(&stamp) {
                seen.push(stamp);
            }
        }
        std::thread::sleep(Duration::from_millis(5));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    // The second stamp may be the end's own write (a completed run keeps
    // its checkpoint), seen after the run finished.
    let summary = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    assert!(
        summary.contains("\"status\": \"partial\""),
        "the run ended before it could be killed; lengthen it"
    );
}

/// `rolldyn spectrum RUN --channel CHANNEL --kind envelope --json` with
/// `extra` options (a band, a number of peaks), as JSON.
pub fn envelope_json(run: &std::path::Path, channel: &str, extra: &[&str]) -> Value {
    let mut args = vec![
        "spectrum",
        run.to_str().unwrap(),
        "--channel",
        channel,
        "--kind",
        "envelope",
        "--json",
    ];
    args.extend_from_slice(extra);
    let o = rolldyn(&args, None);
    assert!(o.status.success(), "{}", stderr(&o));
    serde_json::from_slice(&o.stdout).unwrap()
}

/// The frequency \[Hz\] of the characteristic line `name` of a spectrum's
/// JSON (None if it has no such line).
pub fn line_frequency(spectrum: &Value, name: &str) -> Option<f64> {
    spectrum["lines"]
        .as_array()?
        .iter()
        .find(|l| l["name"] == name)?["frequency_hz"]
        .as_f64()
}
