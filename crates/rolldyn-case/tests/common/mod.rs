//! The case-format error tests' shared base case and assertions.

#![allow(dead_code, clippy::unwrap_used)]

use rolldyn_case::{CaseError, Origin, load_case};

/// A valid minimal case; tests break one thing at a time.
pub const BASE: &str = r#"
[bearing]
ball_diameter = "6.35 mm"
ball_count = 22
pitch_diameter = "54 mm"
inner_groove_curvature = 0.55
outer_groove_curvature = 0.52
free_contact_angle = "17.7 deg"

[operating]
speed = "10000 rpm"
force_x = "200 N"
"#;

pub fn err(text: &str) -> CaseError {
    match load_case("case.toml", text, &[]) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(e) => e,
    }
}

pub fn replace(from: &str, to: &str) -> String {
    assert!(BASE.contains(from), "{from}");
    BASE.replacen(from, to, 1)
}

/// Asserts the error names `key`, points at `line` of the file, and its
/// message contains every fragment.
pub fn check(e: &CaseError, key: &str, line: usize, fragments: &[&str]) {
    let msg = e.to_string();
    assert_eq!(e.key.as_deref(), Some(key), "{msg}");
    match e.origin.as_ref() {
        Origin::File { line: l, .. } => assert_eq!(*l, line, "{msg}"),
        other => panic!("expected a file position, got {other:?}: {msg}"),
    }
    for f in fragments {
        assert!(msg.contains(f), "message lacks {f:?}:\n{msg}");
    }
    assert!(msg.starts_with(&format!("case.toml:{line}:")), "{msg}");
}
