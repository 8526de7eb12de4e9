//! Input refused before work. The work bound of every command
//! (docs/reliability.md, "Work bounds"): what would take unbounded work
//! is refused before the work starts, naming the setting and its limit
//! (exit 2, no output written); one row per bound; the bounds whose worst
//! accepted input is instant (`check`, `frequencies`, `contact`,
//! `presets`, `new`, `catalogue`, `schema`) have none beyond the case's
//! own ranges (the first row). And every option that takes a quantity
//! reads it as case files do: with its unit, a bare number refused with
//! the same message ("missing unit in …; expected a time such as …"),
//! naming the option.

#![allow(clippy::unwrap_used)]

use crate::common::{assert_ok, pair, rolldyn, run_into, stderr, temp_dir};

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

#[test]
fn every_quantity_option_refuses_a_bare_number_alike() {
    let dir = temp_dir("quantity-options");
    let d = dir.to_str().unwrap();
    let o = run_into(d, None, "1 ms", &[]);
    assert_ok(&o);
    let rows: [(&[&str], &str); 13] = [
        (&["run", "--duration", "0.01"], "--duration"),
        (
            &["run", "--checkpoint-interval", "5"],
            "--checkpoint-interval",
        ),
        (&["run", "--resume", d, "--until", "2"], "--until"),
        (&["thermal", "--transient", "100"], "--transient"),
        (&["quasistatic", "--speed", "100"], "--speed"),
        (&["quasistatic", "--axial-load", "100"], "--axial-load"),
        (&["quasistatic", "--radial-load", "100"], "--radial-load"),
        (&["quasistatic", "--misalignment", "0.1"], "--misalignment"),
        (&["contact", "--load", "100"], "--load"),
        (
            &["contact", "--load", "100 N", "--entrainment-speed", "5"],
            "--entrainment-speed",
        ),
        (
            &[
                "traction",
                "--load",
                "100 N",
                "--rolling-speed",
                "1",
                "--creepages",
                "0,0,0",
            ],
            "--rolling-speed",
        ),
        (&["spectrum", d, "--from", "0.1"], "--from"),
        (
            &["spectrum", d, "--kind", "envelope", "--band", "1000:2000"],
            "--band",
        ),
    ];
    for (args, option) in rows {
        let o = rolldyn(args, None);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {e}");
        assert!(
            e.contains(option) && e.contains("missing unit in") && e.contains("such as"),
            "{args:?}: {e}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}
