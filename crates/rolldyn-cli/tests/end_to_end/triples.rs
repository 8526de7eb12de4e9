//! End-to-end tests of matched triples (docs/systems.md, "Triples"): a
//! tandem pair against one bearing, quasi-static and in motion.

#![allow(clippy::unwrap_used)]

use crate::common::{json, pair, run_summary};

/// `rolldyn quasistatic` of a 7008C TBT set with 300 N of preload at
/// 10 000 rpm and no external load: three bearings, the single one
/// carrying the force through the set and each of the pair half of it;
/// the preload grows with speed as a pair's does.
#[test]
fn a_tandem_back_to_back_triple_shares_its_preload() {
    let case = pair("kind = \"tandem_back_to_back\"\npreload = \"300 N\"");
    let v = json(
        &["quasistatic", "-", "--json", "--axial-load", "0 N"],
        Some(&case),
    );
    let a = &v["arrangement"];
    assert_eq!(a["kind"], "tandem_back_to_back");
    let b = a["bearings"].as_array().unwrap();
    assert_eq!(b.len(), 3);
    let load = |i: usize| b[i]["axial_load_n"].as_f64().unwrap();
    let preload = a["preload_n"].as_f64().unwrap();
    assert!(preload > 300.0, "centrifugal force raises it: {preload} N");
    assert!((load(2) - preload).abs() < 1e-6 * preload, "{}", load(2));
    for i in [0, 1] {
        assert!(
            (load(i) - 0.5 * preload).abs() < 1e-6 * preload,
            "{}",
            load(i)
        );
    }
    assert!(a["lift_off_axial_load_n"].as_f64().unwrap() > 2.0 * 300.0);
}

/// `rolldyn run` of a TFT triple: every bearing's dynamics on the shaft;
/// the thrust balance holds in the mean (the pair's loads less the single
/// one's are the applied 200 N).
#[test]
fn a_tandem_face_to_face_triple_runs() {
    let case = pair("kind = \"tandem_face_to_face\"\npreload = \"300 N\"");
    let v = run_summary("triple-run", Some(&case), "3 ms", &[]);
    assert_eq!(v["kind"], "tandem_face_to_face");
    let b = v["bearings"].as_array().unwrap();
    assert_eq!(b.len(), 3);
    let load = |i: usize| b[i]["mean_axial_load_n"].as_f64().unwrap();
    // TFT: the single bearing (−x thrust) at −spacing, the pair after it.
    let thrust = load(1) + load(2) - load(0);
    assert!((thrust - 200.0).abs() < 0.01 * 200.0, "{thrust} N");
    assert!(v["energy_balance_relative_error"].as_f64().unwrap().abs() < 1e-3);
}
