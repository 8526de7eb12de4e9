//! `cargo bench -p rolldyn-cli --bench surface`: cost of surfaces and of
//! the spectrum command (the performance targets), plain `Instant`
//! timing, median of 7 runs; figures in docs/performance.md.
//!
//! 1. One right-hand-side evaluation of the default case (7008C preset,
//!    J–H state) smooth and with surfaces: outer waviness of order 22
//!    (0.3 µm), an inner-race spall, ball waviness of order 2 (ψ states).
//!    The evaluation overhead is what surfaces cost per step; a run with
//!    them also takes more steps, because the vibration they excite must
//!    be resolved (2., reported, not a cost of the implementation).
//! 2. `rolldyn run` of the default case, 0.05 s, smooth and wavy: wall time
//!    and steps from summary.json.
//!    Also the RHS with the EHL films starved (≤ 5 %), and with
//!    the film in the normal approach.
//! 3. Spectra of 1 s of 50 kHz data (50 000 samples): amplitude, Welch
//!    (4096-sample segments, ½ overlap), envelope; and `rolldyn spectrum`
//!    end to end on a written run directory.

use rolldyn::integrate::OdeSystem;
use rolldyn::signal::{Window, amplitude_spectrum, envelope_spectrum, welch_psd};
use rolldyn_case::raw::StartChoice;
use rolldyn_case::simulation::Simulation;
use rolldyn_case::{load_case, presets};
use std::hint::black_box;
use std::process::Command;
use std::time::Instant;

const SURFACES: &str = "[surface.outer]\nradial_waviness = [{ order = 22, amplitude = \"0.3 um\" }]\n\n[[surface.inner.spall]]\nposition = \"0 deg\"\nlength = \"0.5 mm\"\ndepth = \"1.5 um\"\n\n[surface.balls]\nwaviness = [{ order = 2, amplitude = \"0.1 um\" }]\n";

fn median(mut runs: Vec<f64>) -> f64 {
    runs.sort_by(f64::total_cmp);
    runs[runs.len() / 2]
}

fn case_text(surfaces: bool) -> String {
    let text = presets::find("7008C").expect("7008C preset").text;
    if surfaces {
        text.replacen(
            "\n[assumptions]",
            &format!("\n{SURFACES}\n[assumptions]"),
            1,
        )
    } else {
        text.to_string()
    }
}

fn rhs_time(text: &str) -> f64 {
    let case = load_case("bench", text, &[]).expect("valid case");
    let simulation = Simulation::with_start(&case, StartChoice::JonesHarris).expect("J–H start");
    let (model, y) = (simulation.model, simulation.initial_state);
    let mut dy = vec![0.0; y.len()];
    let calls = 2000;
    median(
        (0..7)
            .map(|_| {
                let start = Instant::now();
                for i in 0..calls {
                    model.rhs(1e-6 * i as f64, &y, &mut dy);
                    black_box(&dy);
                }
                start.elapsed().as_secs_f64() / calls as f64
            })
            .collect(),
    )
}

fn cli_run(surfaces: bool, dir: &std::path::Path) -> (f64, u64) {
    use std::io::Write;
    let mut child = Command::new(env!("CARGO_BIN_EXE_rolldyn"))
        .args(["run", "-", "-o"])
        .arg(dir)
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::null())
        .spawn()
        .expect("rolldyn starts");
    child
        .stdin
        .take()
        .expect("stdin")
        .write_all(case_text(surfaces).as_bytes())
        .expect("case written");
    assert!(child.wait().expect("rolldyn finishes").success());
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).expect("summary"))
            .expect("json");
    (
        summary["wall_time_s"].as_f64().unwrap_or(f64::NAN),
        summary["steps"].as_u64().unwrap_or(0),
    )
}

fn main() {
    let smooth = rhs_time(&case_text(false));
    let rough = rhs_time(&case_text(true));
    println!(
        "RHS, default case: smooth {:.1} µs, with surfaces {:.1} µs ({:+.1} %)",
        smooth * 1e6,
        rough * 1e6,
        100.0 * (rough / smooth - 1.0)
    );
    // the EHL film starved on both rings.
    let starved = rhs_time(&case_text(false).replacen(
        "\n[operating]",
        "inlet_distance_ratio = 1.3\n\n[operating]",
        1,
    ));
    println!(
        "RHS, default case starved (L = 1.3): {:.1} µs ({:+.1} % against flooded)",
        starved * 1e6,
        100.0 * (starved / smooth - 1.0)
    );
    // the film in the normal approach (fixed point per
    // contact and the films' power).
    let approach = rhs_time(&case_text(false).replacen(
        "\n[model]\n",
        "\n[model]\nfilm_in_approach = true\n",
        1,
    ));
    println!(
        "RHS, default case with the film in the approach: {:.1} µs ({:+.1} % against without)",
        approach * 1e6,
        100.0 * (approach / smooth - 1.0)
    );

    let dir = std::env::temp_dir().join(format!("rolldyn-bench-surface-{}", std::process::id()));
    for surfaces in [false, true] {
        let (wall, steps) = cli_run(
            surfaces,
            &dir.join(if surfaces { "wavy" } else { "smooth" }),
        );
        println!(
            "rolldyn run default case 0.05 s, {}: {wall:.2} s wall, {steps} steps",
            if surfaces { "with surfaces" } else { "smooth" }
        );
    }

    let fs = 50_000.0;
    let x: Vec<f64> = (0..50_000)
        .map(|k| {
            let t = k as f64 / fs;
            (1.0 + 0.5 * (628.0 * t).cos()) * (2.0 * std::f64::consts::PI * 7000.0 * t).sin()
                + 0.1 * (2.0 * std::f64::consts::PI * 1628.0 * t).sin()
        })
        .collect();
    let time = |f: &dyn Fn() -> usize| {
        median(
            (0..7)
                .map(|_| {
                    let start = Instant::now();
                    black_box(f());
                    start.elapsed().as_secs_f64()
                })
                .collect(),
        )
    };
    let amplitude = time(&|| amplitude_spectrum(&x, fs, Window::Hann).map_or(0, |s| s.value.len()));
    let welch = time(&|| welch_psd(&x, fs, 4096, 0.5, Window::Hann).map_or(0, |s| s.value.len()));
    let envelope = time(&|| {
        envelope_spectrum(&x, fs, (5000.0, 9000.0), Window::Hann).map_or(0, |s| s.value.len())
    });
    println!(
        "1 s at 50 kHz: amplitude {:.2} ms, Welch {:.2} ms, envelope {:.2} ms",
        amplitude * 1e3,
        welch * 1e3,
        envelope * 1e3
    );

    // `rolldyn spectrum` end to end on a run directory holding that record.
    let run = dir.join("signal");
    std::fs::create_dir_all(&run).expect("dir");
    let mut series = rolldyn_io::TimeSeries::default();
    series.channel("time_s", "s");
    series.channel("inner_ring_acceleration_z_m_s2", "m/s^2");
    for (k, v) in x.iter().enumerate() {
        series.push(&[k as f64 / fs, *v]);
    }
    rolldyn_io::write_parquet(&run.join("timeseries.parquet"), &series, &[]).expect("parquet");
    std::fs::write(
        run.join("summary.json"),
        r#"{"inner_ring_speed_rpm": 10000.0, "mean_cage_speed_rpm": 4440.0, "ball_count": 22,
            "ball_diameter_m": 0.00635, "pitch_diameter_m": 0.054, "mean_contact_angle_inner_deg": 17.7,
            "mean_contact_angle_outer_deg": 17.7, "averaging_window_s": [0.0, 1.0]}"#,
    )
    .expect("summary");
    for kind in ["amplitude", "envelope"] {
        let wall = time(&|| {
            let o = Command::new(env!("CARGO_BIN_EXE_rolldyn"))
                .args(["spectrum", "--kind", kind])
                .arg(&run)
                .output()
                .expect("rolldyn spectrum");
            usize::from(o.status.success())
        });
        println!(
            "rolldyn spectrum --kind {kind}, 1 s at 50 kHz: {:.0} ms wall",
            wall * 1e3
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}
