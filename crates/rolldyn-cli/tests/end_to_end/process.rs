//! How the `rolldyn` program behaves as a process: Ctrl-C (a bearing's
//! run and a set's both exit 130 with an `interrupted` summary and valid
//! files), a closed pipe (quiet), and each command's help against what
//! the command accepts.

#![allow(clippy::unwrap_used)]

use crate::common::{rolldyn, stderr, summary_of, temp_dir};
use serde_json::Value;
use std::process::{Command, Stdio};

/// Runs `rolldyn run ARGS -o DIR` for 10 s of simulated time, sends
/// SIGINT once the run writes its series (its Ctrl-C handler is then set)
/// and `settle` later, and checks the exit code 130 and the summary's
/// `interrupted`; returns the summary.
fn interrupted_run(tag: &str, args: &[&str], settle: u64) -> (std::path::PathBuf, Value) {
    let dir = temp_dir(tag);
    let d = dir.to_string_lossy().into_owned();
    let child = Command::new(env!("CARGO_BIN_EXE_rolldyn"))
        .arg("run")
        .args(args)
        .args(["--duration", "10 s", "-o", &d])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let begun = std::time::Instant::now();
    while !dir.join("timeseries.parquet").exists() {
        assert!(
            begun.elapsed().as_secs() < 120,
            "{tag}: the run did not start"
        );
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    std::thread::sleep(std::time::Duration::from_millis(settle));
    let status = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(status.success());
    let out = child.wait_with_output().unwrap();
    // Exit code 130: interrupted, the files are valid.
    assert_eq!(
        out.status.code(),
        Some(130),
        "{tag}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let summary: Value = summary_of(&dir);
    assert_eq!(summary["status"], "interrupted", "{tag}");
    (dir, summary)
}

#[test]
fn run_interrupted_keeps_valid_files() {
    let (dir, summary) = interrupted_run("run-int", &[], 1000);
    let t = summary["simulated_time_s"].as_f64().unwrap();
    assert!(t > 0.0 && t < 10.0);
    assert!(
        !rolldyn_io::read_parquet(&dir.join("timeseries.parquet"))
            .unwrap()
            .is_empty()
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// A set's run stopped by Ctrl-C exits as a single bearing's does (130),
/// its summary saying `interrupted`.
#[test]
fn set_run_interrupted_exits_130() {
    let case = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/spindle_pair/case.toml"
    );
    let (dir, _) = interrupted_run("set-int", &[case], 500);
    std::fs::remove_dir_all(&dir).ok();
}

/// A reader that closes the pipe early (`rolldyn catalogue --json | head`)
/// ends the command quietly: no message, exit 0. The output (150 kB) is
/// larger than a pipe holds, so the write meets the closed pipe.
#[test]
fn a_closed_pipe_ends_quietly() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_rolldyn"))
        .args(["catalogue", "--json"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Every command's help offers only what the command accepts: each
/// shared case flag its `--help` lists (`--speed`, `--axial-load`,
/// `--radial-load`, `--misalignment`, `--fix-tilt`, `--set`), given a
/// valid value, is not refused (the command may still fail otherwise, but
/// never naming the flag); the flags a command hides it refuses.
#[test]
fn every_help_offers_only_what_its_command_accepts() {
    let dir = temp_dir("help-walk");
    let d = dir.to_str().unwrap().to_string();
    let commands: [(&str, Vec<&str>); 8] = [
        ("check", vec![]),
        ("frequencies", vec![]),
        ("contact", vec!["--load", "500 N"]),
        ("quasistatic", vec![]),
        ("power", vec![]),
        ("thermal", vec![]),
        (
            "traction",
            vec![
                "--load",
                "500 N",
                "--rolling-speed",
                "1 m/s",
                "--creepages",
                "1e-3,0,0",
            ],
        ),
        ("run", vec!["--duration", "0.2 ms", "-o", &d]),
    ];
    let flags: [(&str, Option<&str>, &str); 6] = [
        ("--speed", Some("2000 rpm"), "operating.speed"),
        ("--axial-load", Some("150 N"), "operating.axial_load"),
        ("--radial-load", Some("50 N"), "operating.radial_load"),
        ("--misalignment", Some("0.01 deg"), "operating.tilt_y"),
        ("--fix-tilt", None, "operating.fixed_tilt"),
        (
            "--set",
            Some("life.contamination_factor=0.5"),
            "life.contamination_factor",
        ),
    ];
    for (command, base) in &commands {
        let o = rolldyn(&[command, "--help"], None);
        let help = String::from_utf8(o.stdout).unwrap();
        for (flag, value, key) in flags {
            let mut args = vec![*command];
            args.extend(base.iter().copied());
            args.push(flag);
            args.extend(value);
            let o = rolldyn(&args, None);
            let e = stderr(&o);
            let refused = !o.status.success() && (e.contains(flag) || e.contains(key));
            let offered = help.contains(&format!("{flag} ")) || help.contains(&format!("{flag}\n"));
            assert_eq!(
                offered, !refused,
                "{command} {flag}: offered {offered}, {e}"
            );
            std::fs::remove_dir_all(&dir).ok();
        }
    }
}
