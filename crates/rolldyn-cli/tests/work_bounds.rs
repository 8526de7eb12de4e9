//! The work bound of every command (docs/reliability.md, "Work bounds"):
//! what would take unbounded work is refused before the work starts,
//! naming the setting and its limit (exit 2, no output written). One
//! row per bound; the bounds whose worst accepted input is instant
//! (`check`, `frequencies`, `contact`, `presets`, `new`, `catalogue`,
//! `schema`) have none beyond the case's own ranges (the first row).

#![allow(clippy::unwrap_used)]

mod common;

use common::{pair, rolldyn, stderr, temp_dir};

#[test]
fn unbounded_work_is_refused_before_it_starts() {
    let dir = temp_dir("work-bounds");
    let d = dir.to_str().unwrap();
    let b7218 = rolldyn_case::presets::find("7218B").unwrap().text;
    let speeds: String = (0..1001)
        .map(|i| format!("{} rpm", 1000 + i))
        .collect::<Vec<_>>()
        .join(",");
    let run_sweep = format!("operating.speed={speeds}");
    let set = pair("kind = \"back_to_back\"\npreload = \"0.001 N\"");
    let rows: Vec<(Vec<&str>, Option<&str>, &str)> = vec![
        // Every command: the case's ranges (here the ball count).
        (
            vec!["check", "--set", "bearing.ball_count=1001"],
            None,
            "more than 1000 balls",
        ),
        // traction --method exact: at most 128 cells each way.
        (
            vec![
                "traction",
                "-",
                "--load",
                "10 kN",
                "--rolling-speed",
                "10 m/s",
                "--creepages",
                "1e-3,1e-3,50",
                "--method",
                "exact",
                "--cells",
                "129",
            ],
            Some(b7218),
            "between 4 and 128",
        ),
        // quasistatic (and power, thermal) of a set: a preload force the
        // solve cannot resolve.
        (vec!["quasistatic", "-"], Some(&set), "least preload"),
        (vec!["power", "-"], Some(&set), "least preload"),
        // quasistatic --sweep: at most 10⁶ points.
        (
            vec![
                "quasistatic",
                "--sweep",
                "speed=0rpm..20000rpm/100000",
                "--sweep",
                "axial=10N..1kN/100000",
            ],
            None,
            "above the limit of 1e6 (time and memory); use fewer points or pass --force",
        ),
        // thermal --transient: at most 10⁶ steps.
        (
            vec!["thermal", "--transient", "1 h", "--steps", "1000001"],
            None,
            "[1, 1000000]",
        ),
        // run: at most 10⁹ steps, 32 GiB of record, 1000 sweep runs.
        (
            vec![
                "run",
                "--set",
                "solver.max_step=\"1 ns\"",
                "--duration",
                "10 s",
                "-o",
                d,
            ],
            None,
            "above the limit of 1e9",
        ),
        (vec!["run", "--duration", "1000 s", "-o", d], None, "GiB"),
        (
            vec!["run", "--sweep", &run_sweep, "--duration", "1 ms", "-o", d],
            None,
            "above the limit of 1000",
        ),
    ];
    for (args, case, rule) in rows {
        let o = rolldyn(&args, case);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(rule), "{args:?}: {}", stderr(&o));
        assert!(!dir.exists(), "{args:?} wrote {d}");
    }
}
