//! Fuzz findings kept as tests: what an independent fuzzing campaign
//! found, and the streaming writer's files killed and damaged. The
//! generated cases are in `fuzz.rs`.

#![allow(clippy::unwrap_used)]

use crate::common;

use rolldyn_case::presets::PRESETS;
use serde_json::Value;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Runs `rolldyn` and checks what the user meets: the exit code, no
/// panic, and each of `says` in its stderr.
fn expect(args: &[&str], stdin: Option<&str>, code: i32, says: &[&str]) {
    let o = common::rolldyn(args, stdin);
    let err = common::stderr(&o);
    assert_eq!(o.status.code(), Some(code), "{args:?}: {err}");
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    for s in says {
        assert!(err.contains(s), "{args:?}: {err:?} lacks {s:?}");
    }
}

fn preset(name: &str) -> &'static str {
    PRESETS.iter().find(|p| p.name == name).unwrap().text
}

/// What an independent fuzzing campaign (17 000 cases) found, each as the
/// user met it: the command, its exit code and what the message must say.
/// Here the files: a flat sweep's report, a final rename that fails.
#[test]
fn findings_of_independent_fuzzing_stay_fixed() {
    let dir = common::temp_dir("fuzz-findings");
    std::fs::create_dir_all(&dir).unwrap();
    let d = |name: &str| dir.join(name).to_string_lossy().into_owned();
    // A quasi-static sweep whose plotted contact angle is constant: the
    // report's tick labels panicked on a range flat to round-off.
    let sweep = d("sweep");
    expect(
        &[
            "quasistatic",
            "--sweep",
            "radial=100N,-100N",
            "--sweep",
            "axial=1e6N",
            "-o",
            &sweep,
        ],
        None,
        0,
        &[],
    );
    expect(&["report", &sweep], None, 0, &[]);
    // A final rename that fails leaves no temporary file, and says so once.
    let taken = d("taken");
    std::fs::create_dir_all(Path::new(&taken).join("summary.json")).unwrap();
    expect(
        &["run", "--duration", "0.1 ms", "-o", &taken],
        None,
        2,
        &["summary.json"],
    );
    let left: Vec<String> = std::fs::read_dir(&taken)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".tmp"))
        .collect();
    assert!(left.is_empty(), "{left:?}");
    let o = common::rolldyn(&["run", "--duration", "0.1 ms", "-o", &taken], None);
    assert_eq!(common::stderr(&o).matches("cannot write").count(), 1);
    std::fs::remove_dir_all(&dir).ok();
}

/// The independent campaign's absurd inputs: refused before any work,
/// naming the key, or run when they are sound (negative speeds).
#[test]
fn fuzzed_absurd_inputs_are_refused_or_run() {
    let dir = common::temp_dir("fuzz-findings-inputs");
    std::fs::create_dir_all(&dir).unwrap();
    let d = |name: &str| dir.join(name).to_string_lossy().into_owned();
    // Absurd inputs are refused before any work, naming the key.
    let wavy = format!(
        "{}\n[surface.outer]\nradial_waviness = [{{ order = 22, amplitude = \"20 mm\" }}]\n",
        preset("7008C")
    );
    expect(
        &["run", "-", "--duration", "1 ms", "-o", &d("wavy")],
        Some(&wavy),
        2,
        &["surface.outer.radial_waviness", "1 % of the ball diameter"],
    );
    let curve = preset("6304").replace(
        "law = \"modified_coulomb\", friction = 0.1",
        "law = \"traction_curve\", a = -0.06, b = 8.0, c = 60.0, d = 1e9",
    );
    assert!(curve.contains("d = 1e9"));
    expect(
        &["run", "-", "--duration", "1 ms", "-o", &d("curve")],
        Some(&curve),
        2,
        &["model.traction.d", "reaches mu"],
    );
    // No load at all on an angular-contact bearing at speed: a reason,
    // exit 2, as for the deep-groove bearing.
    for name in ["7008C", "6205"] {
        expect(
            &[
                "quasistatic",
                "-",
                "--axial-load",
                "0 N",
                "--radial-load",
                "0 N",
                "--speed",
                "10000 rpm",
            ],
            Some(preset(name)),
            2,
            &["cannot carry this load"],
        );
    }
    // Negative values in the separated form of every value flag.
    expect(
        &["quasistatic", "-", "--speed", "-1000 rpm", "--json"],
        Some(preset("7008C")),
        0,
        &[],
    );
    expect(
        &[
            "run",
            "-",
            "--speed",
            "-1000 rpm",
            "--duration",
            "0.2 ms",
            "-o",
            &d("negative"),
        ],
        Some(preset("7008C")),
        0,
        &[],
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// The independent campaign's spectrum and number findings: a run too
/// short for a spectrum, `--list --json`, a TOML number that overflows.
#[test]
fn fuzzed_spectra_and_numbers_are_located() {
    let dir = common::temp_dir("fuzz-findings-spectra");
    std::fs::create_dir_all(&dir).unwrap();
    let d = |name: &str| dir.join(name).to_string_lossy().into_owned();
    // A spectrum of a run too short for one: the averaging window is
    // blamed, not a --from the user did not give; --list --json is JSON.
    let short = d("short");
    expect(&["run", "--duration", "0.1 ms", "-o", &short], None, 0, &[]);
    expect(
        &["spectrum", &short],
        None,
        2,
        &["averaging window", "--from \"0 s\""],
    );
    let o = common::rolldyn(&["spectrum", &short, "--list", "--json"], None);
    let list: Value = serde_json::from_str(&common::stdout(&o)).unwrap();
    assert_eq!(list[0]["name"], "time_s");
    assert_eq!(list[0]["unit"], "s");
    // Numbers that overflow in the TOML are located.
    let overflow = "title = \"x\"\n[solver]\nrelative_tolerance = 1e999\n";
    expect(
        &["run", "-", "-o", &d("overflow")],
        Some(overflow),
        2,
        &["<stdin>:3:22", "solver.relative_tolerance", "too large"],
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// The streaming writer's files, killed and then damaged as a disk or a
/// user might: `spectrum`, `report` and `--resume` answer each with a
/// located error (exit 2), never a panic or a silent gap.
#[test]
fn damaged_time_series_give_clear_errors() {
    let dir = common::temp_dir("fuzz-damaged");
    let killed = dir.join("killed");
    let k = killed.to_string_lossy().into_owned();
    // 200 kHz: a part file (1 448 rows of the default case) every 7 ms.
    let mut child = Command::new(env!("CARGO_BIN_EXE_rolldyn"))
        .args([
            "run",
            "-o",
            &k,
            "--duration",
            "0.1 s",
            "--checkpoint-interval",
            "0 s",
        ])
        .args(["--set", "output.sample_rate=\"200 kHz\""])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let series = killed.join("timeseries.parquet");
    let begun = Instant::now();
    loop {
        let parts = rolldyn_io::part_files(&series).map_or(0, |p| p.len());
        if parts >= 3 && killed.join("checkpoint.bin").is_file() {
            break;
        }
        assert!(child.try_wait().unwrap().is_none(), "the run ended first");
        assert!(begun.elapsed() < Duration::from_secs(300));
        std::thread::sleep(Duration::from_millis(5));
    }
    child.kill().unwrap(); // SIGKILL
    child.wait().unwrap();
    // What the kill left reads.
    assert!(!rolldyn_io::read_parquet(&series).unwrap().is_empty());
    let part = |d: &Path, k: usize| {
        d.join("timeseries.parquet")
            .join(format!("part-{k:06}.parquet"))
    };
    type Damage = (&'static str, fn(&Path));
    let damages: [Damage; 5] = [
        ("truncated", |p| {
            let bytes = std::fs::read(p).unwrap();
            std::fs::write(p, &bytes[..bytes.len() / 2]).unwrap();
        }),
        ("garbage", |p| std::fs::write(p, b"not parquet").unwrap()),
        ("empty", |p| std::fs::write(p, b"").unwrap()),
        ("missing", |p| std::fs::remove_file(p).unwrap()),
        ("a directory", |p| {
            std::fs::remove_file(p).unwrap();
            std::fs::create_dir(p).unwrap();
        }),
    ];
    for (what, damage) in damages {
        for k in [0, 1] {
            let copy = dir.join(format!("{}-{k}", what.replace(' ', "-")));
            std::fs::remove_dir_all(&copy).ok();
            std::fs::create_dir_all(copy.join("timeseries.parquet")).unwrap();
            for name in ["run.json", "summary.json", "checkpoint.bin"] {
                std::fs::copy(killed.join(name), copy.join(name)).unwrap();
            }
            for p in rolldyn_io::part_files(&series).unwrap() {
                std::fs::copy(
                    &p,
                    copy.join("timeseries.parquet").join(p.file_name().unwrap()),
                )
                .unwrap();
            }
            damage(&part(&copy, k));
            let c = copy.to_string_lossy().into_owned();
            let mut commands = vec![vec!["spectrum", c.as_str()], vec!["report", &c]];
            // Part 0 holds rows of every checkpoint; a later part may lie
            // beyond the last one, which a resume rightly drops.
            if k == 0 {
                commands.push(vec!["run", "--resume", &c]);
            }
            for args in commands {
                let o = common::rolldyn(&args, None);
                let err = common::stderr(&o);
                assert_eq!(o.status.code(), Some(2), "{what} part {k}, {args:?}: {err}");
                assert!(
                    err.starts_with("error: ") && err.contains("part-00000"),
                    "{what} part {k}, {args:?}: {err}"
                );
            }
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}
