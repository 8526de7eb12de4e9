//! End-to-end tests of catalogue bearings: `rolldyn catalogue` and
//! `rolldyn new --bearing` (docs/catalogue.md).

#![allow(clippy::unwrap_used)]

use crate::common::{json, keys, rolldyn, stderr, stdout};

/// `new --bearing` writes a case that checks, with the ball set of
/// `catalogue --json`; `catalogue` lists every series with its keys;
/// bad designations, clearance groups and series exit 2 naming the value
/// and the rule.
#[test]
fn catalogue_bearings_round_trip_through_new_and_check() {
    let list = json(&["catalogue", "--json"], None);
    let list = list.as_array().unwrap();
    assert_eq!(list.len(), 3 * 21 + 3 * 21 * 4);
    assert_eq!(
        keys(&list[0]),
        [
            "ball_count",
            "ball_diameter_mm",
            "bore_mm",
            "clearance_cn_um",
            "contact_angle_deg",
            "designation",
            "dynamic_load_rating_n",
            "kind",
            "outside_diameter_mm",
            "pitch_diameter_mm",
            "published_dynamic_load_rating_n",
            "published_static_load_rating_n",
            "static_load_rating_n",
            "width_mm"
        ]
    );
    for (designation, clearance) in [
        ("6205", "C3"),
        ("7210B", ""),
        ("6320", "C2"),
        ("7000AC", ""),
    ] {
        let mut args = vec!["new", "--bearing", designation];
        if !clearance.is_empty() {
            args.extend(["--clearance", clearance]);
        }
        let case = stdout(&rolldyn(&args, None));
        let check = json(&["check", "-", "--json"], Some(&case));
        let entry = list
            .iter()
            .find(|e| e["designation"] == designation)
            .unwrap();
        assert_eq!(check["geometry"]["ball_count"], entry["ball_count"]);
        let ball = check["geometry"]["ball_diameter_m"].as_f64().unwrap() * 1e3;
        assert!((ball - entry["ball_diameter_mm"].as_f64().unwrap()).abs() < 1e-9);
        // Every estimated value is an assumption `check` prints.
        let assumed = check["assumptions"].as_array().map_or(0, Vec::len);
        assert!(assumed >= 10, "{designation}: {assumed} assumptions");
    }
    let c62 = json(&["catalogue", "--series", "62", "--json"], None);
    assert_eq!(c62.as_array().unwrap().len(), 21);
    let listed = c62
        .as_array()
        .unwrap()
        .iter()
        .find(|e| e["designation"] == "6205")
        .unwrap();
    assert_eq!(listed["published_dynamic_load_rating_n"], 14_000.0);
    for (args, expect) in [
        (
            vec!["new", "--bearing", "7210"],
            "argument --bearing: bearing \"7210\": an angular-contact bearing needs its contact angle code",
        ),
        (vec!["new", "--bearing", "6230"], "bore code 30"),
        (
            vec!["new", "--bearing", "6205", "--clearance", "C7"],
            "argument --clearance: clearance \"C7\"",
        ),
        (
            vec!["new", "--bearing", "7205C", "--clearance", "C3"],
            "clearance groups are for deep-groove bearings",
        ),
        (
            vec!["catalogue", "--series", "64"],
            "series \"64\": not a catalogue series",
        ),
    ] {
        let o = rolldyn(&args, None);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(stderr(&o).contains(expect), "{args:?}: {}", stderr(&o));
    }
}
