//! What an inner-race pit shows in the envelope spectrum depends on
//! whether the load stands still or turns with the inner ring (Randall &
//! Antoni 2011): under a stationary load the pit meets the load zone once
//! per shaft turn, so the bursts are modulated at f_r; under a load that
//! turns with the ring (an unbalance) the pit meets the same load at every
//! ball, and BPFI with its harmonics leads. docs/validation.md, "Fault
//! signatures".
//!
//! The CWRU 6205 example with a 0.014 in inner-race pit at 1797 rpm,
//! 0.3 s through its housing sensor, envelope band 1.2–4.8 kHz: the
//! case's 500 N along gravity, against 100 N along gravity with a
//! 9.9 kg·mm unbalance (350 N turning, phased onto the pit), and between
//! them 100 N with 177 N turning (5 kg·mm), where BPFI leads with its
//! ±f_r sidebands as in CWRU's inner-race records.
//!
//! And how periodic the balls' passage is (`ball_pass_jitter`) with the
//! cage turning about a fixed centre and with it whirling.

#![allow(clippy::unwrap_used)]

use crate::common::{envelope_json, line_frequency, rolldyn, stderr, summary_of, temp_dir};
use std::path::{Path, PathBuf};

fn case() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/cwru6205/case.toml")
}

const PIT: &str =
    "surface.inner.spall=[{ position = \"0 deg\", length = \"0.3556 mm\", depth = \"0.2794 mm\" }]";

/// What the envelope spectrum shows of an inner-race fault.
struct InnerRaceLines {
    /// Amplitudes at f_r, BPFI, BPFI − f_r and BPFI + f_r, each the
    /// largest within a bin of the line.
    shaft: f64,
    bpfi: f64,
    sidebands: [f64; 2],
    /// The line the largest peak is nearest to.
    top: String,
}

fn envelope(run: &Path) -> InnerRaceLines {
    let v = envelope_json(run, "sensor_acceleration_m_s2", &["--band", "1200:4800 Hz"]);
    let line = |name: &str| line_frequency(&v, name).unwrap();
    let resolution = v["resolution_hz"].as_f64().unwrap();
    let csv = std::fs::read_to_string(v["csv"].as_str().unwrap()).unwrap();
    let at = |f: f64| {
        csv.lines()
            .skip(1)
            .filter_map(|row| {
                let (x, y) = row.split_once(',')?;
                let (x, y): (f64, f64) = (x.parse().ok()?, y.parse().ok()?);
                ((x - f).abs() <= resolution).then_some(y)
            })
            .fold(0.0, f64::max)
    };
    let (shaft, bpfi) = (line("f_i"), line("BPFI"));
    InnerRaceLines {
        shaft: at(shaft),
        bpfi: at(bpfi),
        sidebands: [at(bpfi - shaft), at(bpfi + shaft)],
        top: v["peaks"][0]["line"].as_str().unwrap().to_string(),
    }
}

#[test]
fn a_load_turning_with_the_ring_takes_the_shaft_rate_off_an_inner_race_fault() {
    let dir = temp_dir("fault-signatures");
    let mut ratios = Vec::new();
    for (name, load) in [
        ("stationary", vec![]),
        (
            "rotating",
            vec![
                "operating.radial_load=\"100 N\"",
                "operating.unbalance=\"9.9 kg.mm\"",
            ],
        ),
        (
            "mixed",
            vec![
                "operating.radial_load=\"100 N\"",
                "operating.unbalance=\"5 kg.mm\"",
            ],
        ),
    ] {
        let out = dir.join(name);
        let (case_path, out_path) = (
            case().to_string_lossy().into_owned(),
            out.to_string_lossy().into_owned(),
        );
        let mut args = vec![
            "run",
            case_path.as_str(),
            "-o",
            out_path.as_str(),
            "--set",
            "surface.outer.spall=[]",
            "--set",
            PIT,
        ];
        for s in &load {
            args.extend(["--set", s]);
        }
        let o = rolldyn(&args, None);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let lines = envelope(&out);
        if name != "stationary" {
            assert_eq!(lines.top, "BPFI", "{name}: BPFI leads");
        }
        if name == "mixed" {
            // Measured: sidebands at 0.66 and 0.55 of BPFI (CWRU's pattern).
            for (side, a) in ["BPFI − f_r", "BPFI + f_r"].iter().zip(lines.sidebands) {
                assert!(
                    a > lines.bpfi / 3.0,
                    "mixed load: {side} {a} against BPFI {}",
                    lines.bpfi
                );
            }
        }
        ratios.push(lines.shaft / lines.bpfi);
    }
    // Measured: f_r/BPFI 1.40 stationary, 0.16 rotating (0.3 s).
    assert!(
        ratios[0] > 4.0 * ratios[1],
        "f_r/BPFI {} (stationary) against {} (rotating)",
        ratios[0],
        ratios[1]
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// The jitter of the ball passage (`ball_pass_jitter`): measured signals
/// show 1–2 % (Randall & Antoni 2011). The CWRU case's outer-race fault
/// with its cage turning about a fixed centre: the balls settle into a
/// periodic pattern (measured 0.04 %); with the cage free to whirl in its
/// cylindrical pockets, which do not hold it radially, they space
/// themselves around the drifting cage. The whirl is chaotic, so one run's
/// jitter is one draw: over 30 runs at relative tolerances within 0.4 %
/// of the case's, median 1.5 %, standard deviation 0.6 %, 0.48–3.0 %, one
/// in 30 below 0.7 %. The test takes the mean of three draws (standard
/// deviation ~0.36 %: a mean below 0.7 % is a 2.4σ event on an
/// unchanged model, a cage that stops drifting falls to ~0.1 %). These
/// were measured on the example before it carried its grease, which the
/// runs here leave out (no rolling resistance, no pocket film): with it
/// the unguided cage drifts 1.4 mm off centre and the jitter is 4 %.
/// docs/validation.md, "Fault signatures".
#[test]
fn the_ball_passage_jitters_as_measured_only_around_a_drifting_cage() {
    let dir = temp_dir("passage-jitter");
    let mut jitter = Vec::new();
    // The case's relative tolerance 1e-3, and 0.1 % off it either way.
    let runs = [
        ("fixed", "false", "1e-3"),
        ("whirling", "true", "1e-3"),
        ("whirling-a", "true", "1.001e-3"),
        ("whirling-b", "true", "0.999e-3"),
    ];
    for (name, whirl, tolerance) in runs {
        let out = dir.join(name);
        let (case_path, out_path) = (
            case().to_string_lossy().into_owned(),
            out.to_string_lossy().into_owned(),
        );
        let set = format!("cage.whirl={whirl}");
        let tolerance = format!("solver.relative_tolerance={tolerance}");
        let o = rolldyn(
            &[
                "run",
                case_path.as_str(),
                "-o",
                out_path.as_str(),
                "--set",
                &set,
                "--set",
                &tolerance,
                "--set",
                "lubrication.rolling_resistance=\"none\"",
                "--set",
                "cage.pocket_squeeze_film=false",
            ],
            None,
        );
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let summary: serde_json::Value = summary_of(&out);
        // The passages at 1/BPFO (107.5 Hz at 1797 rpm); a drifting cage
        // slips behind it (12 runs: 0.3–1.1 % longer intervals, the cage
        // at 711–715 rpm), as measured bearings do by 1–2 %.
        let interval = summary["ball_pass_interval_s"].as_f64().unwrap();
        let slip = if whirl == "true" { 0.02 } else { 0.01 };
        assert!(
            (interval * 107.5 - 1.0).abs() < slip,
            "{name}: {interval} s"
        );
        jitter.push(summary["ball_pass_jitter"].as_f64().unwrap());
    }
    assert!(jitter[0] < 0.002, "fixed cage: jitter {}", jitter[0]);
    let draws = &jitter[1..];
    let whirling = draws.iter().sum::<f64>() / draws.len() as f64;
    assert!(
        whirling > 0.007,
        "whirling cage: jitter {draws:?}, mean {whirling}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
