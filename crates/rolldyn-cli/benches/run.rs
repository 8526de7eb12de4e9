//! `cargo bench -p rolldyn-cli --bench run`: the four benchmark runs of
//! docs/performance.md, run exactly as users run them (`rolldyn run` on the
//! presets), reporting the CLI's own timing from summary.json (wall time,
//! integrator, steps, rejected steps, RHS evaluations, Jacobians and
//! factorizations):
//! (a) 6304 preset (Shan et al. 2023: planar, L–N, modified Coulomb at the contact
//!     centre, W = 100 N, 8000 rpm), 0.2 s simulated;
//! (b) the built-in default case (7008C, 10 000 rpm, F_x = 200 N, EHL on
//!     the 12 × 6 grid, from the Jones–Harris state), 0.05 s simulated;
//! (c) the 7218B preset on Zhang et al. 2025's speed ramp (1000 → 10 000 rpm,
//!     FASTSIM traction, μ = 0.1), the full 2.5 s, on FASTSIM's default
//!     16 × 10 grid (the workload of its history; the preset's own grid,
//!     48 × 20, costs 3.6 times as much);
//! (d) the default case over 1 s (its cage whirl limit cycle from ~0.06 s).
//! Targets (one core: `RAYON_NUM_THREADS=1`): (a) ≤
//! 0.3 s, (b) ≤ 2 s, (c) ≤ 60 s, (d) ≤ 40 s; figures in
//! docs/performance.md. Build in release first (`cargo bench` does).
//! `ROLLDYN_BENCH=a,b` runs a subset (default a, b, c, d).

use std::process::Command;

fn main() {
    let exe = env!("CARGO_BIN_EXE_rolldyn");
    let dir = std::env::temp_dir().join(format!("rolldyn-bench-{}", std::process::id()));
    let only = std::env::var("ROLLDYN_BENCH").unwrap_or_else(|_| "a,b,c,d".into());
    // (key, label, preset (None: built-in default case), extra arguments)
    let cases: [(&str, &str, Option<&str>, &[&str]); 4] = [
        (
            "a",
            "(a) 6304 preset, 0.2 s",
            Some("6304"),
            &["--duration", "0.2 s"],
        ),
        ("b", "(b) default 7008C case, 0.05 s", None, &[]),
        (
            "c",
            "(c) 7218B Zhang et al. 2025 ramp, 2.5 s, FASTSIM 16 × 10",
            Some("7218B"),
            &[
                "--duration",
                "2.5 s",
                "--set",
                "model.traction={ law = \"fastsim\", friction = 0.1 }",
            ],
        ),
        (
            "d",
            "(d) default 7008C case, 1 s",
            None,
            &["--duration", "1 s"],
        ),
    ];
    for (key, name, preset, extra) in cases {
        if !only.split(',').any(|k| k.trim() == key) {
            continue;
        }
        let out = dir.join(key);
        let mut cmd = Command::new(exe);
        cmd.arg("run");
        if preset.is_some() {
            cmd.arg("-");
        }
        cmd.args(extra).arg("-o").arg(&out);
        let output = match preset {
            Some(preset) => {
                use std::io::Write;
                let mut child = cmd
                    .stdin(std::process::Stdio::piped())
                    .stdout(std::process::Stdio::piped())
                    .stderr(std::process::Stdio::piped())
                    .spawn()
                    .expect("rolldyn starts");
                let text = Command::new(exe)
                    .args(["new", "--preset", preset])
                    .output()
                    .expect("rolldyn new");
                child
                    .stdin
                    .take()
                    .expect("stdin")
                    .write_all(&text.stdout)
                    .expect("write case");
                child.wait_with_output().expect("rolldyn runs")
            }
            None => cmd.output().expect("rolldyn runs"),
        };
        if !output.status.success() {
            println!(
                "{name}: failed: {}",
                String::from_utf8_lossy(&output.stderr)
            );
            continue;
        }
        let summary = std::fs::read_to_string(out.join("summary.json")).unwrap_or_default();
        let field = |key: &str| {
            summary
                .lines()
                .find(|l| l.trim_start().starts_with(&format!("\"{key}\"")))
                .and_then(|l| l.split(':').nth(1))
                .map(|v| v.trim().trim_end_matches(',').trim_matches('"').to_string())
                .unwrap_or_default()
        };
        println!(
            "{name:<34} {:>8} s wall ({}): {} steps, {} rejected, {} RHS, {} Jacobians ({} RHS), {} factorizations",
            field("wall_time_s"),
            field("integrator"),
            field("steps"),
            field("rejected_steps"),
            field("rhs_evaluations"),
            field("jacobian_evaluations"),
            field("jacobian_rhs_evaluations"),
            field("factorizations"),
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}
