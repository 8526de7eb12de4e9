//! `cargo bench -p rolldyn-cli --bench run`: the issue-4 benchmark cases,
//! run exactly as users run them (`rolldyn run` on the presets), reporting
//! the CLI's own timing from summary.json (wall time, steps, rejected
//! steps, RHS evaluations):
//! (a) 6304 preset (seed 000: planar, L–N, modified Coulomb at the contact
//!     centre, W = 100 N, 8000 rpm), 0.2 s simulated;
//! (b) the built-in default case (7008C, 10 000 rpm, F_x = 200 N, EHL on
//!     the 12 × 6 grid, from the Jones–Harris state), 0.05 s simulated.
//! Targets of issue 4: (a) ≤ 20 s, (b) ≤ 60 s; figures in
//! docs/performance.md. Build in release first (`cargo bench` does).

use std::process::Command;

fn main() {
    let exe = env!("CARGO_BIN_EXE_rolldyn");
    let dir = std::env::temp_dir().join(format!("rolldyn-bench-{}", std::process::id()));
    let cases: [(&str, Vec<&str>); 2] = [
        (
            "(a) 6304 preset, 0.2 s",
            vec!["run", "-", "--duration", "0.2 s"],
        ),
        ("(b) default 7008C case, 0.05 s", vec!["run"]),
    ];
    for (name, args) in cases {
        let out = dir.join(
            name.split_whitespace()
                .next()
                .unwrap_or("case")
                .trim_matches(|c| c == '(' || c == ')'),
        );
        let mut cmd = Command::new(exe);
        cmd.args(&args).arg("-o").arg(&out);
        let output = if args.contains(&"-") {
            use std::io::Write;
            let mut child = cmd
                .stdin(std::process::Stdio::piped())
                .stdout(std::process::Stdio::null())
                .spawn()
                .expect("rolldyn starts");
            let preset = Command::new(exe)
                .args(["new", "--preset", "6304"])
                .output()
                .expect("rolldyn new");
            child
                .stdin
                .take()
                .expect("stdin")
                .write_all(&preset.stdout)
                .expect("write case");
            child.wait_with_output().expect("rolldyn runs")
        } else {
            cmd.output().expect("rolldyn runs")
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
                .map(|v| v.trim().trim_end_matches(',').to_string())
                .unwrap_or_default()
        };
        println!(
            "{name:<34} {:>8} s wall: {} steps, {} rejected, {} RHS evaluations",
            field("wall_time_s"),
            field("steps"),
            field("rejected_steps"),
            field("rhs_evaluations")
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}
