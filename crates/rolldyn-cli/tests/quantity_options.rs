//! Every option that takes a quantity reads it as case files do: with
//! its unit, and a bare number refused with the same message ("missing
//! unit in …; expected a time such as …"), naming the option.

#![allow(clippy::unwrap_used)]

mod common;

use common::{rolldyn, stderr, temp_dir};

#[test]
fn every_quantity_option_refuses_a_bare_number_alike() {
    let dir = temp_dir("quantity-options");
    let d = dir.to_str().unwrap();
    let o = rolldyn(&["run", "--duration", "1 ms", "-o", d], None);
    assert!(o.status.success(), "{}", stderr(&o));
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
