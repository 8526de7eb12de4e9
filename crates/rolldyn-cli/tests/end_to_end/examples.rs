//! Every directory of `examples/` (one per source paper, the CWRU 6205,
//! the minute-long warm-up, the spindle pair, the run-down and the ring's
//! stability)
//! holds a README, its case file and a matplotlib script; its case is
//! valid and runs, shortened; a scripted example (the CWRU test matrix)
//! holds a README, its script and its table script, and runs, shortened.
//! The full reproductions are the commands in each README.

#![allow(clippy::unwrap_used)]

use crate::common::{assert_ok, rolldyn, run_into, stderr, temp_dir};
use std::path::PathBuf;

fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// (directory, the shortened command after the case path).
const EXAMPLES: [(&str, &[&str]); 10] = [
    ("seed000", &["run", "--duration", "2 ms"]),
    ("seed001", &["run", "--duration", "2 ms"]),
    ("seed002", &["run", "--duration", "2 ms"]),
    // Zhang et al. 2020's case shortened: its quasi-static point (the example adds dynamic runs).
    ("seed003", &["quasistatic", "--radial-load", "20 N"]),
    ("seed004", &["run", "--duration", "2 ms"]),
    ("cwru6205", &["run", "--duration", "2 ms"]),
    // The minute-long warm-up, shortened (its run-up starts at 1000 rpm).
    ("warmup60s", &["run", "--duration", "1 ms"]),
    // A matched pair: its quasi-static solution at the case's speed.
    ("spindle_pair", &["quasistatic"]),
    // The free ring held at 10 000 rpm (the example linearizes its runs).
    ("ring_stability", &["run", "--duration", "2 ms"]),
    // The default case coasting down (a torque-driven ring).
    ("run_down", &["run", "--duration", "2 ms"]),
];

/// Examples that are a shell script over other examples' cases.
const SCRIPTED: [&str; 1] = ["cwru_matrix"];

#[test]
fn every_example_has_its_files_and_its_case_runs() {
    // The directories: examples/plotting.py is the plot scripts' helper,
    // and importing it leaves Python's __pycache__ beside it.
    let mut dirs: Vec<String> = std::fs::read_dir(examples())
        .unwrap()
        .map(|e| e.unwrap())
        .filter(|e| e.file_type().unwrap().is_dir())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|name| !name.starts_with(['_', '.']))
        .collect();
    dirs.sort();
    let mut listed: Vec<&str> = EXAMPLES.iter().map(|(d, _)| *d).chain(SCRIPTED).collect();
    listed.sort();
    assert_eq!(dirs, listed, "every example directory is tested");
    for (name, command) in EXAMPLES {
        let dir = examples().join(name);
        for file in ["README.md", "case.toml", "plot.py"] {
            assert!(dir.join(file).is_file(), "{name}/{file}");
        }
        let case = dir.join("case.toml");
        let case = case.to_str().unwrap();
        let o = rolldyn(&["check", case], None);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let out = temp_dir(&format!("example-{name}"));
        let mut args = vec![command[0], case];
        args.extend_from_slice(&command[1..]);
        if command[0] == "run" {
            args.extend_from_slice(&["-o", out.to_str().unwrap()]);
        }
        let o = rolldyn(&args, None);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        // The README gives the commands for the case file and the script.
        let readme = std::fs::read_to_string(dir.join("README.md")).unwrap();
        assert!(readme.contains("plot.py"), "{name}: README names plot.py");
    }
}

/// The CWRU test matrix, each run shortened to 8 ms: 64 labelled runs,
/// their envelope spectra and the features table.
#[test]
fn the_cwru_matrix_script_writes_its_labelled_table() {
    let dir = examples().join("cwru_matrix");
    for file in ["README.md", "run.sh", "features.py"] {
        assert!(dir.join(file).is_file(), "cwru_matrix/{file}");
    }
    let out = temp_dir("example-cwru-matrix");
    let o = std::process::Command::new("sh")
        .arg(dir.join("run.sh"))
        .arg(&out)
        .current_dir(examples().join(".."))
        .env("ROLLDYN", env!("CARGO_BIN_EXE_rolldyn"))
        .env("DURATION", "8 ms")
        .output()
        .expect("sh runs");
    assert_ok(&o);
    let table = std::fs::read_to_string(out.join("features.csv")).unwrap();
    let rows: Vec<&str> = table.lines().collect();
    assert_eq!(rows.len(), 1 + 64);
    assert!(rows[0].starts_with("fault,position_oclock,size_in,load_hp,speed_rpm,status"));
    for fault in [
        "healthy,",
        "outer,6,0.007,0,1797.0,completed",
        "inner,",
        "ball,",
    ] {
        assert!(rows.iter().any(|r| r.starts_with(fault)), "{fault}");
    }
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn every_plot_script_is_valid_python() {
    for (name, _) in EXAMPLES {
        let script = examples().join(name).join("plot.py");
        let o = std::process::Command::new("python3")
            .args(["-c", "import ast, sys; ast.parse(open(sys.argv[1]).read())"])
            .arg(&script)
            .output()
            .expect("python3 runs (the machine has Python 3.11)");
        assert!(o.status.success(), "{name}: {}", stderr(&o));
    }
}

/// Every preset is a complete case: `rolldyn new --preset P` runs as it
/// is (cage, ring mass or width, traction given or assumed in the preset),
/// and states its simulated time (a first look; the wall times of the
/// runs as written are in docs/performance.md, "The presets and
/// examples"). Here each runs 1 ms, for the test's time.
#[test]
fn every_preset_runs() {
    for preset in rolldyn_case::presets::PRESETS {
        let o = rolldyn(&["new", "--preset", preset.name], None);
        assert!(o.status.success(), "{}: {}", preset.name, stderr(&o));
        let case = String::from_utf8(o.stdout).unwrap();
        let written = rolldyn_case::load_case(preset.name, &case, &[]).unwrap();
        let duration = written
            .duration
            .unwrap_or_else(|| panic!("{}: the preset states no solver.duration", preset.name));
        assert!(
            (0.01..=2.0).contains(&duration),
            "{}: a first look of {duration} s",
            preset.name
        );
        let out = temp_dir(&format!("preset-{}", preset.name));
        let o = run_into(out.to_str().unwrap(), Some(&case), "1 ms", &[]);
        assert!(o.status.success(), "{}: {}", preset.name, stderr(&o));
        std::fs::remove_dir_all(&out).ok();
    }
}
