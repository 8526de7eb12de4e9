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
//! Spalls sit at the load zone's centre (the direction of the radial load;
//! 12 o'clock, where the channels look, without one), D_w/15 long and
//! D_w/28 deep (the CWRU 0.021 in pit's proportions on a 6205). Each run lasts 3/f_c, at least 0.05 s, the
//! window (its second half) resolving lines f_c/1.5 apart. The tests in CI
//! check four of the ten bearings (two of the ten miss some signatures at
//! defaults, docs/validation.md; the others are left to the benchmark for
//! CI's time); `fault_matrix_table` (ignored: a benchmark) runs
//! all ten at 0.4 s or 3/f_c, whichever is longer, and prints the table of
//! docs/validation.md.

#![allow(clippy::unwrap_used)]

use crate::common::{envelope_json, line_frequency, rolldyn, stderr, stdout, temp_dir};
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

/// The shortest run in CI \[s\]: at high speed 3/f_c leaves too few
/// impacts in the window (a 25 ms window resolves 40 Hz).
const MIN_DURATION: f64 = 0.05;

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

    /// Whether the envelope's largest peaks show this fault's signature;
    /// the reason if not. A peak belongs to a family when it lies within
    /// one resolution bin (or 1.5 %) of one of the family's lines: the
    /// spectrum command names a peak after the nearest line of any family,
    /// and at low resolution BPFO and 3×f_i, say, share a bin.
    fn check(self, e: &Envelope) -> Result<(), String> {
        let near = |f: f64, line: f64| (f - line).abs() <= e.resolution.max(0.015 * line);
        let harmonics = |f: f64, base: f64, sideband: f64, kmax: u32| {
            (1..=kmax).any(|k| {
                let line = f64::from(k) * base;
                near(f, line)
                    || (sideband > 0.0 && (near(f, line - sideband) || near(f, line + sideband)))
            })
        };
        let [shaft, cage, bpfo, bpfi, bsf] = e.base;
        let outer = |f: f64| harmonics(f, bpfo, 0.0, 6);
        let inner = |f: f64| harmonics(f, bpfi, shaft, 3);
        let shaft_family = |f: f64| harmonics(f, shaft, 0.0, 5);
        let ball = |f: f64| harmonics(f, bsf, cage, 6);
        let cage_family = |f: f64| harmonics(f, cage, 0.0, 5);
        let (top, all) = (e.peaks[0], &e.peaks);
        let ok = match self {
            Fault::Outer => outer(top),
            Fault::Inner => all.iter().any(|&f| inner(f)) && all.iter().any(|&f| shaft_family(f)),
            Fault::Ball => all.iter().any(|&f| ball(f)) && (ball(top) || cage_family(top)),
        };
        if ok {
            Ok(())
        } else {
            Err(format!(
                "{} fault: largest lines {:?}",
                self.name(),
                e.names
            ))
        }
    }
}

/// An envelope spectrum's six largest peaks.
struct Envelope {
    /// Peak frequencies \[Hz\], largest first.
    peaks: Vec<f64>,
    /// The nearest line's name of each, as the spectrum command gives it.
    names: Vec<String>,
    /// Resolution \[Hz\].
    resolution: f64,
    /// f_i, f_c, BPFO, BPFI, BSF of the run \[Hz\].
    base: [f64; 5],
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
    inner_ring: Envelope,
    sensor: Envelope,
    velocity_rms_mm_s: f64,
}

fn run(case: &str, fault: Fault, duration: f64, dir: &Path) -> Signature {
    let check = json(&["check", case, "--json"]);
    let (fy, fz) = (
        check["force_y_n"].as_f64().unwrap(),
        check["force_z_n"].as_f64().unwrap(),
    );
    // The load zone's centre; under a purely axial load every azimuth is
    // loaded alike, and the spall goes to 12 o'clock (+z), where the
    // inner ring's channel and the default sensor look.
    let position = if fy.hypot(fz) > 0.0 {
        fz.atan2(fy).to_degrees()
    } else {
        90.0
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
    let envelope = |channel: &str| {
        let v = envelope_json(Path::new(&out_path), channel, &["--peaks", "6"]);
        let peaks = v["peaks"].as_array().unwrap();
        let line = |name: &str| line_frequency(&v, name).unwrap_or(0.0);
        let e = Envelope {
            peaks: peaks
                .iter()
                .map(|p| p["frequency_hz"].as_f64().unwrap())
                .collect(),
            names: peaks
                .iter()
                .map(|p| p["line"].as_str().unwrap_or("—").to_string())
                .collect(),
            resolution: v["resolution_hz"].as_f64().unwrap(),
            base: [
                line("f_i"),
                line("f_c"),
                line("BPFO"),
                line("BPFI"),
                line("BSF"),
            ],
        };
        (e, v["velocity_rms_mm_s"].as_f64().unwrap())
    };
    let (inner_ring, velocity_rms_mm_s) = envelope("inner_ring_acceleration_z_m_s2");
    let (sensor, _) = envelope("sensor_acceleration_m_s2");
    Signature {
        inner_ring,
        sensor,
        velocity_rms_mm_s,
    }
}

/// The cage frequency at the start of a run of `case` \[Hz\] (a speed
/// profile's first speed, else the case's speed).
fn starting_cage_hz(case: &str) -> f64 {
    let text = std::fs::read_to_string(case).unwrap();
    let first_speed = text.find("speed_profile").and_then(|at| {
        let rest = &text[at..];
        let start = rest.find("speed = \"")? + "speed = \"".len();
        Some(rest[start..start + rest[start..].find('"')?].to_string())
    });
    let mut args = vec!["frequencies", case, "--json"];
    if let Some(speed) = first_speed.as_deref() {
        args.extend(["--speed", speed]);
    }
    json(&args)["cage_hz"].as_f64().unwrap()
}

/// Runs one bearing's three faults, each run lasting the longer of
/// `min_duration` and 3/f_c; returns the failures and the table rows.
fn bearing_matrix(source: &str, name: &str, min_duration: f64) -> (Vec<String>, Vec<String>) {
    let dir = temp_dir(&format!("fault-matrix-{name}"));
    let (mut failures, mut rows) = (Vec::new(), Vec::new());
    let case = case_file(&dir, source, name);
    let duration = (3.0 / starting_cage_hz(&case)).max(min_duration);
    // Three decimals: the run's duration as the table shows it.
    let duration = format!("{duration:.3}").parse::<f64>().unwrap();
    for fault in Fault::ALL {
        let s = run(&case, fault, duration, &dir);
        let mut verdict = |e: &Envelope, channel: &str| match fault.check(e) {
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
            s.inner_ring.names[..3].join(", "),
            s.sensor.names[..3].join(", "),
            s.velocity_rms_mm_s
        ));
    }
    std::fs::remove_dir_all(&dir).ok();
    (failures, rows)
}

/// One test per bearing, so that the test harness runs them side by side.
/// Here four of the eight bearings that show all six signatures at
/// defaults: the 6304 (Shan et al. 2023's rig, dry, no mounting damping),
/// the 7218B (solid-lubricated, FASTSIM), the catalogue 6308 and the 6203
/// (dry deep groove, whose signatures need the mounting's bearing damping;
/// the cheapest of those). Not here, for CI's time: the 6205, 6206, 7008C
/// and 7206B, which pass, and the acbb_30x62 and ceramic_45x75, which miss
/// some (docs/validation.md, "Fault signatures at defaults"); the
/// benchmark below keeps all ten in its table. The 6205 stays covered by
/// the CWRU example's signatures (fault_signatures.rs) and records
/// (cwru_records.rs).
macro_rules! signatures {
    ($($test:ident: $source:literal $name:literal;)*) => {$(
        #[test]
        fn $test() {
            let (failures, rows) = bearing_matrix($source, $name, MIN_DURATION);
            assert!(
                failures.is_empty(),
                "{} of 6 signatures missed:\n{}\n{}",
                failures.len(),
                failures.join("\n"),
                rows.join("\n")
            );
        }
    )*};
}

signatures! {
    signatures_6304: "preset" "6304";
    signatures_7218b: "preset" "7218B";
    signatures_catalogue_6308: "bearing" "6308";
    signatures_6203: "preset" "6203";
}

/// The benchmark: the matrix at 0.4 s (or 3/f_c when longer), printed as
/// docs/validation.md's table:
/// `cargo test --release -p rolldyn-cli --test end_to_end fault_matrix:: -- --ignored --nocapture`;
/// `ROLLDYN_FAULT_MATRIX_MIN_DURATION=0.05` prints it at the CI's durations,
/// `ROLLDYN_FAULT_MATRIX_BEARINGS=6205,7218B` for some bearings only.
#[test]
#[ignore]
fn fault_matrix_table() {
    let (mut failures, mut rows) = (Vec::new(), Vec::new());
    let only = std::env::var("ROLLDYN_FAULT_MATRIX_BEARINGS").ok();
    for (source, name) in BEARINGS {
        if only
            .as_deref()
            .is_some_and(|list| !list.split(',').any(|b| b == name))
        {
            continue;
        }
        let min = std::env::var("ROLLDYN_FAULT_MATRIX_MIN_DURATION")
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(0.4);
        let (f, r) = bearing_matrix(source, name, min);
        failures.extend(f);
        rows.extend(r);
    }
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
