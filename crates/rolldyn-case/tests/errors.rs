//! Every rejection rule of the case format: the message names the key,
//! the value (where there is one) and the rule, and points at the line.

#![allow(clippy::unwrap_used)]

mod common;

use common::{BASE, check, err, replace};
use rolldyn_case::{Origin, Override, OverrideSource, load_case, presets};

#[test]
fn base_case_is_valid() {
    load_case("case.toml", BASE, &[]).unwrap();
}

#[test]
fn missing_unit() {
    let e = err(&replace("\"6.35 mm\"", "6.35"));
    check(
        &e,
        "bearing.ball_diameter",
        3,
        &["missing unit", "6.35", "mm"],
    );
    let e = err(&replace("\"6.35 mm\"", "\"6.35\""));
    check(&e, "bearing.ball_diameter", 3, &["missing unit"]);
}

#[test]
fn unknown_unit() {
    let e = err(&replace("\"6.35 mm\"", "\"6.35 mmm\""));
    check(
        &e,
        "bearing.ball_diameter",
        3,
        &["unknown unit \"mmm\"", "length"],
    );
}

#[test]
fn unit_of_the_wrong_kind() {
    let e = err(&replace("\"10000 rpm\"", "\"10000 N\""));
    check(
        &e,
        "operating.speed",
        11,
        &["unit of force", "rotational speed"],
    );
}

#[test]
fn unknown_key_typo() {
    let e = err(&replace("ball_count = 22", "ball_cuont = 22"));
    check(
        &e,
        "bearing.ball_cuont",
        4,
        &["unknown field `ball_cuont`", "ball_count"],
    );
    let e = err(&format!("{BASE}\n[operatng]\nspeed = \"1 rpm\"\n"));
    assert_eq!(e.key.as_deref(), Some("operatng"), "{e}");
    assert!(e.to_string().contains("unknown field `operatng`"), "{e}");
}

#[test]
fn wrong_type() {
    let e = err(&replace("ball_count = 22", "ball_count = \"22\""));
    check(&e, "bearing.ball_count", 4, &["invalid type", "\"22\""]);
    let e = err(&replace(
        "inner_groove_curvature = 0.55",
        "inner_groove_curvature = \"0.55\"",
    ));
    check(&e, "bearing.inner_groove_curvature", 6, &["invalid type"]);
}

#[test]
fn groove_curvature_at_most_half() {
    let e = err(&replace(
        "inner_groove_curvature = 0.55",
        "inner_groove_curvature = 0.5",
    ));
    check(
        &e,
        "bearing.inner_groove_curvature",
        6,
        &["= 0.5", "must exceed 0.5"],
    );
    let e = err(&replace(
        "inner_groove_curvature = 0.55",
        "inner_groove_radius = \"3.1 mm\"",
    ));
    check(
        &e,
        "bearing.inner_groove_radius",
        6,
        &["\"3.1 mm\"", "must exceed 0.5"],
    );
}

#[test]
fn balls_overlap() {
    let e = err(&replace("ball_count = 22", "ball_count = 27"));
    check(&e, "bearing.ball_count", 4, &["= 27", "balls overlap"]);
}

#[test]
fn ball_count_limits() {
    let e = err(&replace("ball_count = 22", "ball_count = 2"));
    check(&e, "bearing.ball_count", 4, &["= 2", "at least 3 balls"]);
    let e = err(&replace("ball_count = 22", "ball_count = 5000"));
    check(
        &e,
        "bearing.ball_count",
        4,
        &["= 5000", "not a plausible bearing"],
    );
}

#[test]
fn contact_angle_range() {
    let e = err(&replace("\"17.7 deg\"", "\"65 deg\""));
    check(
        &e,
        "bearing.free_contact_angle",
        8,
        &["\"65 deg\"", "[0, 60] deg"],
    );
    let e = err(&replace("\"17.7 deg\"", "\"-1 deg\""));
    check(&e, "bearing.free_contact_angle", 8, &["[0, 60] deg"]);
}

#[test]
fn raceways_crossing() {
    let text = replace("pitch_diameter = \"54 mm\"\n", "").replace(
        "free_contact_angle = \"17.7 deg\"",
        "inner_raceway_diameter = \"60 mm\"\nouter_raceway_diameter = \"48 mm\"",
    );
    let e = err(&text);
    check(
        &e,
        "bearing.outer_raceway_diameter",
        8,
        &["\"48 mm\"", "raceways cross"],
    );
}

#[test]
fn negative_clearance_needs_preload() {
    let text = replace(
        "free_contact_angle = \"17.7 deg\"",
        "diametral_clearance = \"-0.004 mm\"",
    );
    let e = err(&text);
    check(
        &e,
        "bearing.diametral_clearance",
        8,
        &["\"-0.004 mm\"", "preload = true"],
    );
    let ok = text.replace("[operating]", "preload = true\n\n[operating]");
    load_case("case.toml", &ok, &[]).unwrap();
    let too_much = ok.replace("-0.004 mm", "-1 mm");
    check(
        &err(&too_much),
        "bearing.diametral_clearance",
        8,
        &["raceways cross", "interference"],
    );
}

#[test]
fn nan_and_infinity() {
    let e = err(&replace(
        "inner_groove_curvature = 0.55",
        "inner_groove_curvature = nan",
    ));
    check(&e, "bearing.inner_groove_curvature", 6, &["finite"]);
    let e = err(&replace("\"200 N\"", "\"inf N\""));
    check(
        &e,
        "operating.force_x",
        12,
        &["does not start with a number"],
    );
}

#[test]
fn non_positive_sizes() {
    let e = err(&replace("\"6.35 mm\"", "\"-6.35 mm\""));
    check(
        &e,
        "bearing.ball_diameter",
        3,
        &["\"-6.35 mm\"", "must be positive"],
    );
    let e = err(&replace("\"54 mm\"", "\"0 mm\""));
    check(&e, "bearing.pitch_diameter", 5, &["must be positive"]);
}

#[test]
fn parametrization_must_be_unique_and_present() {
    let e = err(&replace(
        "free_contact_angle = \"17.7 deg\"",
        "free_contact_angle = \"17.7 deg\"\ndiametral_clearance = \"0.01 mm\"",
    ));
    check(
        &e,
        "bearing.diametral_clearance",
        9,
        &["conflicts with bearing.free_contact_angle", "exactly one"],
    );
    let e = err(&replace("free_contact_angle = \"17.7 deg\"\n", ""));
    assert_eq!(e.key.as_deref(), Some("bearing.free_contact_angle"));
    assert!(
        e.to_string().contains("give one clearance parametrization"),
        "{e}"
    );
}

#[test]
fn model_and_material_rules() {
    let e = err(&format!(
        "{BASE}\n[model]\nnormal_law = {{ law = \"lankarani_nikravesh\", restitution = 1.2 }}\n"
    ));
    check(&e, "model.normal_law.restitution", 15, &["(0, 1]"]);
    let e = err(&format!("{BASE}\n[model]\nnormal_law = \"lankarani\"\n"));
    check(
        &e,
        "model.normal_law",
        15,
        &["unknown normal law", "lankarani_nikravesh"],
    );
    let e = err(&format!("{BASE}\n[model]\nnormal_law = \"flores\"\n"));
    check(
        &e,
        "model.normal_law",
        15,
        &["needs parameters", "restitution"],
    );
    let e = err(&format!(
        "{BASE}\n[model]\ncontact_stiffness = \"hamrock\"\n"
    ));
    check(
        &e,
        "model.contact_stiffness",
        15,
        &["unknown variant", "hamrock_brewe"],
    );
    let e = err(&format!("{BASE}\n[materials]\nball = \"unobtainium\"\n"));
    check(
        &e,
        "materials.ball",
        15,
        &["unknown material", "silicon_nitride"],
    );
    let e = err(&format!(
        "{BASE}\n[materials]\nball = {{ elastic_modulus = \"310 GPa\", poisson_ratio = 0.6, density = \"3200 kg/m^3\" }}\n"
    ));
    check(&e, "materials.ball.poisson_ratio", 15, &["(-1, 0.5)"]);
}

#[test]
fn speed_profile_rules() {
    let text = replace(
        "speed = \"10000 rpm\"",
        "speed_profile = [\n  { time = \"0 s\", speed = \"1000 rpm\" },\n  { time = \"0 s\", speed = \"2000 rpm\" },\n]",
    );
    let e = err(&text);
    check(
        &e,
        "operating.speed_profile[1].time",
        13,
        &["increase strictly"],
    );
    let both = text.replace("force_x", "speed = \"1 rpm\"\nforce_x");
    assert!(err(&both).to_string().contains("not both"));
}

#[test]
fn syntax_error_points_at_the_line() {
    let e = err(&replace("ball_count = 22", "ball_count = = 22"));
    assert!(matches!(*e.origin, Origin::File { line: 4, .. }), "{e}");
    assert!(e.to_string().contains("TOML syntax error"), "{e}");
}

#[test]
fn assumptions_must_name_set_keys() {
    let e = err(&format!(
        "{BASE}\n[assumptions]\n\"bearing.inner_groove_curvatur\" = \"typo\"\n"
    ));
    assert!(e.to_string().contains("does not set"), "{e}");
}

#[test]
fn overrides_are_validated_like_the_file() {
    let e = load_case(
        "case.toml",
        BASE,
        &[Override::flag("--speed", "operating.speed", "100 N")],
    )
    .unwrap_err();
    assert_eq!(
        *e.origin,
        Origin::Override("command-line override `--speed 100 N`".into())
    );
    assert!(e.to_string().contains("unit of force"), "{e}");
    let e = load_case(
        "case.toml",
        BASE,
        &[Override::parse_set("bearing.ball_cnt=3").unwrap()],
    )
    .unwrap_err();
    assert!(e.to_string().contains("unknown field `ball_cnt`"), "{e}");
    assert!(
        e.to_string()
            .starts_with("command-line override `--set bearing.ball_cnt=3`"),
        "{e}"
    );
    // From Python's Case.set the same error names its source so.
    let e = load_case(
        "case.toml",
        BASE,
        &[Override::parse_from("bearing.ball_cnt=3", OverrideSource::Python).unwrap()],
    )
    .unwrap_err();
    assert!(
        e.to_string()
            .starts_with("override `bearing.ball_cnt=3` (Case.set)"),
        "{e}"
    );
    let ok = load_case(
        "case.toml",
        BASE,
        &[Override::parse_set("bearing.ball_count=20").unwrap()],
    )
    .unwrap();
    assert_eq!(ok.bearing.geometry.ball_count, 20);
    // A parametrization set on the command line replaces the file's one.
    let ok = load_case(
        "case.toml",
        BASE,
        &[Override::parse_set("bearing.diametral_clearance=0.01 mm").unwrap()],
    )
    .unwrap();
    assert_eq!(ok.bearing.geometry.nominal_contact_angle(), 0.0);
}

/// An override that makes a table the case does not have, or indexes an
/// array it does not have, is blamed, not the file.
#[test]
fn overrides_are_named_in_their_errors() {
    let blamed = |set: &str| {
        let e = load_case("case.toml", BASE, &[Override::parse_set(set).unwrap()]).unwrap_err();
        assert_eq!(
            *e.origin,
            Origin::Override(format!("command-line override `--set {set}`")),
            "{e}"
        );
        e.to_string()
    };
    assert!(blamed("bogus.key=1").contains("unknown field `bogus`"));
    assert!(blamed("arrangement.preload=200 N").contains("missing field `kind`"));
    for (set, array) in [
        ("shaft.loads.0.mesh_order=23", "shaft.loads"),
        ("sensor.modes.0.frequency=3 kHz", "sensor.modes"),
        ("surface.outer.spall.0.length=1 mm", "surface.outer.spall"),
    ] {
        let e = blamed(set);
        assert!(
            e.contains(&format!("the case has no {array}")) && e.contains("give the array whole"),
            "{e}"
        );
    }
}

/// A spall growing faster than the balls leave it (1000 m/s) is refused
/// with the key, the value and the bound.
#[test]
fn a_spall_cannot_outgrow_the_ball_passes() {
    let set = r#"surface.outer.spall=[{ position = "0 deg", length = "1 mm", depth = "0.1 mm", growth_rate = "1000 m/s" }]"#;
    let e = load_case("case.toml", BASE, &[Override::parse_set(set).unwrap()]).unwrap_err();
    let text = e.to_string();
    assert!(
        text.contains("growth_rate") && text.contains("[0, 0.01] m/s"),
        "{text}"
    );
    let ok = set.replace("1000 m/s", "2 mm/s");
    load_case("case.toml", BASE, &[Override::parse_set(&ok).unwrap()]).unwrap();
}

#[test]
fn presets_merge_and_report_assumptions() {
    let case = load_case("case.toml", "[bearing]\npreset = \"7218b\"\n", &[]).unwrap();
    assert_eq!(case.bearing.geometry.ball_count, 16);
    assert!(
        case.assumptions
            .iter()
            .any(|(k, _)| k == "bearing.inner_groove_curvature")
    );
    assert!(
        !case
            .assumptions
            .iter()
            .any(|(k, _)| k.starts_with("operating.")),
        "only imported sections"
    );
    // Overriding an assumed value removes the assumption.
    let case = load_case(
        "case.toml",
        "[bearing]\npreset = \"7218B\"\ninner_groove_curvature = 0.52\n",
        &[],
    )
    .unwrap();
    assert!(
        !case
            .assumptions
            .iter()
            .any(|(k, _)| k == "bearing.inner_groove_curvature")
    );
    let e = err("[bearing]\npreset = \"7009\"\n");
    check(&e, "bearing.preset", 2, &["unknown preset", "7008C"]);
}

#[test]
fn every_preset_is_a_valid_case() {
    for p in presets::PRESETS {
        let case = load_case(p.name, p.text, &[]).unwrap_or_else(|e| panic!("{e}"));
        assert!(case.speed.is_some(), "{}", p.name);
        let by_ref =
            load_case("ref", &format!("[bearing]\npreset = \"{}\"\n", p.name), &[]).unwrap();
        assert_eq!(by_ref.bearing.geometry, case.bearing.geometry, "{}", p.name);
    }
}
