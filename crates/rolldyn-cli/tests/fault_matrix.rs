//! Fault signatures from any bearing at its defaults: every preset and two
//! catalogue bearings, each with an outer-race, an inner-race and a ball
//! spall, through the inner ring's acceleration and a default housing
//! sensor (`[sensor]` with its defaults). The envelope spectrum (the
//! spectrum command's default band, 0.1–0.4 of the sample rate) must show
//! what the literature reports of each fault (Randall & Antoni 2011;
//! docs/validation.md, "Fault signatures at defaults"):
//!
//! * outer race: a BPFO harmonic is the largest line;
//! * inner race: BPFI or one of its ±f_r sidebands, and the shaft family
//!   (a stationary load meets the pit once per turn), among the six
//!   largest lines;
//! * ball: the ball-defect family (k × BSF and its sidebands) among the six
//!   largest lines, the largest line in the ball or the cage family
//!   (measured ball-fault records often show the cage's, Smith & Randall
//!   2015).
//!
//! Spalls sit at the load zone's centre (the direction of the radial load,
//! 0° without one), D_w/15 long and D_w/28 deep (the CWRU 0.021 in pit's
//! proportions on a 6205). Each run lasts 3/f_c, the window (its second
//! half) resolving lines f_c/1.5 apart. The test in CI checks the whole
//! matrix; `fault_matrix_table` (ignored: a benchmark) runs it at 0.4 s or
//! 3/f_c, whichever is longer, and prints the table of docs/validation.md.

#![allow(clippy::unwrap_used)]

mod common;

use common::{rolldyn, stderr, stdout, temp_dir};
use std::path::Path;

/// The bearings: presets by name, catalogue bearings by designation.
const BEARINGS: [(&str, &str); 10] = [
    ("preset", "6203"),
    ("preset", "6205"),
    ("preset", "6206"),
    ("preset", "6304"),
    ("preset", "7008C"),
    ("preset", "7218B"),
    ("preset", "acbb_30x62"),
    ("preset", "ceramic_45x75"),
    ("bearing", "6308"),
    ("bearing", "7206B"),
];

#[derive(Clone, Copy, Debug, PartialEq)]
enum Fault {
    Outer,
    Inner,
    Ball,
}

impl Fault {
    const ALL: [Fault; 3] = [Fault::Outer, Fault::Inner, Fault::Ball];

    fn name(self) -> &'static str {
        match self {
            Fault::Outer => "outer",
            Fault::Inner => "inner",
            Fault::Ball => "ball",
        }
    }

    /// The `--set` override placing this fault.
    fn spall(self, position_deg: f64, ball_diameter: f64) -> String {
        let pit = format!(
            "position = \"{position_deg:.3} deg\", length = \"{:.6} mm\", depth = \"{:.6} mm\"",
            ball_diameter / 15.0 * 1e3,
            ball_diameter / 28.0 * 1e3
        );
        match self {
            Fault::Outer => format!("surface.outer.spall=[{{ {pit} }}]"),
            Fault::Inner => format!("surface.inner.spall=[{{ {pit} }}]"),
            Fault::Ball => format!("surface.balls.spall=[{{ ball = 0, {pit} }}]"),
        }
    }

    /// Whether the largest `lines` (named as the spectrum command names
    /// them, largest first) show this fault's signature; the reason if not.
    fn check(self, lines: &[String]) -> Result<(), String> {
        let family = |line: &str, base: &str| {
            line == base || line.strip_suffix(base).is_some_and(|k| k.ends_with('×'))
        };
        let shaft = |l: &String| family(l, "f_i");
        let cage = |l: &String| family(l, "f_c");
        let bpfi = |l: &String| l.contains("BPFI") && !l.contains("BPFO");
        let bsf = |l: &String| l.contains("BSF");
        let top = &lines[0];
        let ok = match self {
            Fault::Outer => family(top, "BPFO"),
            Fault::Inner => lines.iter().any(bpfi) && lines.iter().any(shaft),
            Fault::Ball => lines.iter().any(bsf) && (bsf(top) || cage(top)),
        };
        if ok {
            Ok(())
        } else {
            Err(format!("{} fault: largest lines {lines:?}", self.name()))
        }
    }
}

fn json(args: &[&str]) -> serde_json::Value {
    let o = rolldyn(args, None);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    serde_json::from_slice(&o.stdout).unwrap()
}

/// The case file of a bearing, written to `dir`.
fn case_file(dir: &Path, source: &str, name: &str) -> String {
    let flag = format!("--{source}");
    let o = rolldyn(&["new", &flag, name], None);
    assert!(o.status.success(), "{name}: {}", stderr(&o));
    std::fs::create_dir_all(dir).unwrap();
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, stdout(&o)).unwrap();
    path.to_string_lossy().into_owned()
}

/// One run's six largest envelope lines: inner ring, housing sensor.
struct Signature {
    inner_ring: Vec<String>,
    sensor: Vec<String>,
    velocity_rms_mm_s: f64,
}

fn run(case: &str, fault: Fault, duration: f64, dir: &Path) -> Signature {
    let check = json(&["check", case, "--json"]);
    let (fy, fz) = (
        check["force_y_n"].as_f64().unwrap(),
        check["force_z_n"].as_f64().unwrap(),
    );
    let position = if fy.hypot(fz) > 0.0 {
        fz.atan2(fy).to_degrees()
    } else {
        0.0
    };
    let ball_diameter = check["geometry"]["ball_diameter_m"].as_f64().unwrap();
    let out = dir.join(fault.name());
    let out_path = out.to_string_lossy().into_owned();
    let duration = format!("{duration} s");
    let o = rolldyn(
        &[
            "run",
            case,
            "--duration",
            &duration,
            "--set",
            "sensor={}",
            "--set",
            &fault.spall(position, ball_diameter),
            "-o",
            &out_path,
        ],
        None,
    );
    assert!(o.status.success(), "{case} {fault:?}: {}", stderr(&o));
    let lines = |channel: &str| {
        let v = json(&[
            "spectrum",
            &out_path,
            "--channel",
            channel,
            "--kind",
            "envelope",
            "--peaks",
            "6",
            "--json",
        ]);
        let names = v["peaks"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| p["line"].as_str().unwrap_or("—").to_string())
            .collect::<Vec<_>>();
        (names, v["velocity_rms_mm_s"].as_f64().unwrap())
    };
    let (inner_ring, velocity_rms_mm_s) = lines("inner_ring_acceleration_z_m_s2");
    let (sensor, _) = lines("sensor_acceleration_m_s2");
    Signature {
        inner_ring,
        sensor,
        velocity_rms_mm_s,
    }
}

/// Runs the matrix with each run lasting the longer of `min_duration` and
/// 3/f_c; returns the failures and the table rows.
fn matrix(min_duration: f64) -> (Vec<String>, Vec<String>) {
    let dir = temp_dir("fault-matrix");
    let (mut failures, mut rows) = (Vec::new(), Vec::new());
    for (source, name) in BEARINGS {
        let case = case_file(&dir, source, name);
        let cage_hz = json(&["frequencies", &case, "--json"])["cage_hz"]
            .as_f64()
            .unwrap();
        let duration = (3.0 / cage_hz).max(min_duration);
        // Three significant digits: the run's duration as the table shows it.
        let duration = format!("{duration:.3}").parse::<f64>().unwrap();
        for fault in Fault::ALL {
            let run_dir = dir.join(name);
            let s = run(&case, fault, duration, &run_dir);
            let mut verdict = |lines: &[String], channel: &str| match fault.check(lines) {
                Ok(()) => "yes".to_string(),
                Err(e) => {
                    failures.push(format!("{name} ({duration} s), {channel}: {e}"));
                    "**no**".to_string()
                }
            };
            let a = verdict(&s.inner_ring, "inner ring");
            let b = verdict(&s.sensor, "sensor");
            rows.push(format!(
                "| {name} | {} | {duration} | {a}: {} | {b}: {} | {:.3} |",
                fault.name(),
                s.inner_ring[..3].join(", "),
                s.sensor[..3].join(", "),
                s.velocity_rms_mm_s
            ));
        }
        std::fs::remove_dir_all(dir.join(name)).ok();
    }
    std::fs::remove_dir_all(&dir).ok();
    (failures, rows)
}

#[test]
fn every_bearing_shows_its_fault_signatures_at_defaults() {
    let (failures, rows) = matrix(0.0);
    assert!(
        failures.is_empty(),
        "{} of 60 signatures missed:\n{}\n{}",
        failures.len(),
        failures.join("\n"),
        rows.join("\n")
    );
}

/// The benchmark: the matrix at 0.4 s (or 3/f_c when longer), printed as
/// docs/validation.md's table:
/// `cargo test --release -p rolldyn-cli --test fault_matrix -- --ignored --nocapture`.
#[test]
#[ignore]
fn fault_matrix_table() {
    let (failures, rows) = matrix(0.4);
    println!(
        "| bearing | fault | duration [s] | inner ring: largest lines | sensor: largest lines | inner-ring velocity RMS [mm/s] |"
    );
    println!("|---|---|---|---|---|---|");
    for r in rows {
        println!("{r}");
    }
    println!("missed: {}", failures.len());
    for f in failures {
        println!("  {f}");
    }
}
