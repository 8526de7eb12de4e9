//! Every rejection rule of the case format: the message names the key,
//! the value (where there is one) and the rule, and points at the line.

#![allow(clippy::unwrap_used)]

use rolldyn_case::{CaseError, Origin, Override, OverrideSource, load_case, presets};

/// A valid minimal case; tests break one thing at a time.
const BASE: &str = r#"
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

fn err(text: &str) -> CaseError {
    match load_case("case.toml", text, &[]) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(e) => e,
    }
}

fn replace(from: &str, to: &str) -> String {
    assert!(BASE.contains(from), "{from}");
    BASE.replacen(from, to, 1)
}

/// Asserts the error names `key`, points at `line` of the file, and its
/// message contains every fragment.
fn check(e: &CaseError, key: &str, line: usize, fragments: &[&str]) {
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

#[test]
fn dynamic_model_rules() {
    let e = err(&format!(
        "{BASE}\n[model]\ntraction = {{ law = \"ehl\", eyring_stress = \"5 MPa\", limiting_shear_coefficient = 0.08 }}\n"
    ));
    check(&e, "model.traction", 15, &["needs a [lubricant] section"]);
    let e = err(&format!("{BASE}\n[model]\ntraction = \"coulomb\"\n"));
    check(
        &e,
        "model.traction",
        15,
        &["unknown traction law", "modified_coulomb"],
    );
    let e = err(&format!(
        "{BASE}\n[model]\ntraction = {{ law = \"modified_coulomb\", friction = -0.1 }}\n"
    ));
    check(&e, "model.traction.friction", 15, &["[0, 5]"]);
    // Friction coefficients and drag coefficients have practical upper ends.
    let e = err(&format!(
        "{BASE}\n[model]\ntraction = {{ law = \"modified_coulomb\", friction = 50.0 }}\n"
    ));
    check(&e, "model.traction.friction", 15, &["[0, 5]"]);
    let e = err(&format!("{BASE}\n[cage]\npocket_friction = 1e300\n"));
    assert_eq!(e.key.as_deref(), Some("cage.pocket_friction"), "{e}");
    let e = err(&format!("{BASE}\n[drag]\nball_drag_coefficient = 1e9\n"));
    assert_eq!(e.key.as_deref(), Some("drag.ball_drag_coefficient"), "{e}");
    let e = err(&format!("{BASE}\n[solver]\nintegrator = \"rk4\"\n"));
    assert_eq!(e.key.as_deref(), Some("solver.time_step"), "{e}");
    assert!(e.to_string().contains("fixed step"), "{e}");
    let e = err(&format!("{BASE}\n[cage]\npocket_stiffness = \"-1 N/m\"\n"));
    check(&e, "cage.pocket_stiffness", 15, &["must be positive"]);
}

#[test]
fn dynamics_parameters_defaults_and_missing_values() {
    // The default case has everything a run needs.
    let case = rolldyn_case::load_default(&[]).unwrap();
    let p = case.dynamics_parameters().unwrap();
    assert_eq!(p.inner_ring_mass, 0.5);
    assert!(matches!(
        p.traction,
        rolldyn::traction::TractionModel::Ehl(_)
    ));
    // A bearing given by its geometry, without cage data: the missing key
    // is named.
    let case = load_case(
        "case.toml",
        "[bearing]\nball_diameter = \"7.94 mm\"\nball_count = 9\npitch_diameter = \"39 mm\"\n\
         diametral_clearance = \"0.012 mm\"\ninner_groove_curvature = 0.52\n\
         outer_groove_curvature = 0.52\nbore = \"25 mm\"\nwidth = \"15 mm\"\n\
         [operating]\nspeed = \"1797 rpm\"\n",
        &[],
    )
    .unwrap();
    let e = case.dynamics_parameters().unwrap_err();
    assert_eq!(e.key, "cage.mass");
    // The inner-ring mass defaults to the ring annulus from bore and width.
    let case = load_case(
        "case.toml",
        "[bearing]\npreset = \"6205\"\n[operating]\nspeed = \"1797 rpm\"\n[cage]\nmass = \"5 g\"\ninertia = \"1e-6 kg.m^2\"\npocket_clearance = \"0.2 mm\"\npocket_stiffness = \"1e7 N/m\"\n",
        &[],
    )
    .unwrap();
    let p = case.dynamics_parameters().unwrap();
    // 6205: bore 25 mm, inner raceway ≈ 31.1 mm, width 15 mm, 7830 kg/m³ → ≈ 0.033 kg.
    assert!(
        p.inner_ring_mass > 0.02 && p.inner_ring_mass < 0.05,
        "{}",
        p.inner_ring_mass
    );
}

#[test]
fn pocket_laws_supports_and_load_tables() {
    const CAGE: &str = "\n[inner_ring]\nmass = \"0.5 kg\"\ntilt_inertia = \"1e-4 kg.m^2\"\n\n[cage]\nmass = \"3 g\"\ninertia = \"2e-6 kg.m^2\"\npocket_clearance = \"0.175 mm\"\n";
    // The Hertz pocket laws need the cage material; the linear law its stiffness.
    let case = load_case(
        "case.toml",
        &format!("{BASE}{CAGE}pocket_law = \"hertz\"\n"),
        &[],
    )
    .unwrap();
    assert_eq!(case.dynamics_parameters().unwrap_err().key, "cage.material");
    let case = load_case("case.toml", &format!("{BASE}{CAGE}"), &[]).unwrap();
    let e = case.dynamics_parameters().unwrap_err();
    assert_eq!(e.key, "cage.pocket_stiffness");
    assert!(e.rule.contains("linear pocket law"), "{}", e.rule);
    // gupta_film: 11 N at the wall by default, K_bc from the materials.
    let case = load_case(
        "case.toml",
        &format!("{BASE}{CAGE}pocket_law = \"gupta_film\"\npocket_shape = \"spherical\"\nmaterial = \"steel_52100\"\nunbalance = \"50 g.mm\"\n"),
        &[],
    )
    .unwrap();
    let p = case.dynamics_parameters().unwrap();
    match p.cage.pocket_law {
        rolldyn::cage::PocketLaw::GuptaFilm {
            wall_force,
            stiffness,
            ..
        } => {
            assert_eq!(wall_force, 11.0);
            assert!(stiffness > 1e9, "{stiffness}");
        }
        other => panic!("{other:?}"),
    }
    assert!((p.cage.unbalance - 5e-5).abs() < 1e-18);
    let e = err(&format!(
        "{BASE}{CAGE}pocket_law = \"gupta_film\"\npocket_wall_force = \"-1 N\"\n"
    ));
    check(&e, "cage.pocket_wall_force", 23, &["must not be negative"]);
    // The pocket squeeze film needs the lubricant's viscosity; its least
    // film defaults to 1 µm and must be positive.
    let squeeze =
        format!("{BASE}{CAGE}pocket_stiffness = \"1e7 N/m\"\npocket_squeeze_film = true\n");
    let dynamics = |text: &str| {
        load_case("case.toml", text, &[])
            .unwrap()
            .dynamics_parameters()
    };
    let e = dynamics(&squeeze).unwrap_err();
    assert_eq!(e.key, "cage.pocket_squeeze_film");
    assert!(e.rule.contains("[lubricant]"), "{}", e.rule);
    let lubricated = format!(
        "{squeeze}\n[lubricant]\nviscosity = \"0.05 Pa.s\"\npressure_viscosity = \"2e-8 1/Pa\"\n"
    );
    let s = dynamics(&lubricated).unwrap().cage.pocket_squeeze.unwrap();
    assert_eq!((s.viscosity, s.min_film), (0.05, 1e-6));
    assert!((s.ball_radius - 3.175e-3).abs() < 1e-15);
    assert_eq!(
        s.cavitation,
        rolldyn::cage::SqueezeCavitation::HalfSommerfeld
    );
    let with = |line: &str| {
        lubricated.replace(
            "pocket_squeeze_film = true\n",
            &format!("pocket_squeeze_film = true\n{line}\n"),
        )
    };
    let full = with("pocket_squeeze_cavitation = \"full_film\"");
    assert_eq!(
        dynamics(&full)
            .unwrap()
            .cage
            .pocket_squeeze
            .unwrap()
            .cavitation,
        rolldyn::cage::SqueezeCavitation::FullFilm
    );
    let e = dynamics(&with("pocket_min_film = \"0.1 mm\"")).unwrap_err();
    assert_eq!(e.key, "cage.pocket_min_film");
    assert!(
        e.rule.contains("half of cage.pocket_clearance"),
        "{}",
        e.rule
    );
    let e = err(&full.replace("\"full_film\"", "\"gumbel\""));
    assert_eq!(
        e.key.as_deref(),
        Some("cage.pocket_squeeze_cavitation"),
        "{e}"
    );
    assert!(e.to_string().contains("half_sommerfeld"), "{e}");
    let off = format!("{BASE}{CAGE}pocket_stiffness = \"1e7 N/m\"\n");
    assert!(dynamics(&off).unwrap().cage.pocket_squeeze.is_none());
    let e = err(&format!("{BASE}{CAGE}pocket_min_film = \"0 um\"\n"));
    check(&e, "cage.pocket_min_film", 22, &["must be positive"]);
    // Constant loads and a load table exclude each other.
    let e = err(&format!(
        "{BASE}load_profile = [{{ time = \"0 s\", force_x = \"100 N\" }}]\n"
    ));
    assert_eq!(e.key.as_deref(), Some("operating.load_profile"), "{e}");
    assert!(e.to_string().contains("not both"), "{e}");
    let table = BASE.replace(
        "force_x = \"200 N\"",
        "load_profile = [{ time = \"0 s\", force_x = \"100 N\" }, { time = \"0 s\", force_x = \"300 N\" }]",
    );
    let e = err(&table);
    assert_eq!(
        e.key.as_deref(),
        Some("operating.load_profile[1].time"),
        "{e}"
    );
    assert!(e.to_string().contains("increase"), "{e}");
    // Outer ring on a housing; bad hysteresis coefficient.
    let e = err(&format!(
        "{BASE}\n[outer_ring]\nmass = \"0 kg\"\nhousing_stiffness = \"1e8 N/m\"\n"
    ));
    check(&e, "outer_ring.mass", 15, &["must be positive"]);
    let e = err(&format!("{BASE}\n[model]\nrolling_hysteresis = 1.5\n"));
    check(&e, "model.rolling_hysteresis", 15, &["[0, 1)"]);
    let e = err(&format!(
        "{BASE}\n[model]\ntraction = {{ law = \"traction_curve\", a = 0.0, b = 1.0, c = -1.0, d = 0.05 }}\n"
    ));
    check(&e, "model.traction.c", 15, &["must not be negative"]);
}

#[test]
fn surface_errors_are_located() {
    let case = |surface: &str| format!("{BASE}\n{surface}");
    // Line 1 of the appended text is BASE's line count + 2.
    let first = BASE.lines().count() + 2;
    let e = err(&case(
        "[surface.outer]\nradial_waviness = [{ order = 0, amplitude = \"0.3 um\" }]\n",
    ));
    check(
        &e,
        "surface.outer.radial_waviness[0].order",
        first + 1,
        &["must lie in [1, 10000]"],
    );
    let e = err(&case(
        "[[surface.inner.spall]]\nposition = \"0 deg\"\nlength = \"1 mm\"\ndepth = \"-2 um\"\n",
    ));
    check(
        &e,
        "surface.inner.spall[0].depth",
        first + 3,
        &["must be positive"],
    );
    let e = err(&case(
        "[[surface.inner.spall]]\nposition = \"0 deg\"\ndepth = \"2 um\"\n",
    ));
    assert_eq!(
        e.key.as_deref(),
        Some("surface.inner.spall[0].width"),
        "{e}"
    );
    assert!(
        e.to_string().contains("either width (angle) or length"),
        "{e}"
    );
    let e = err(&case(
        "[[surface.balls.spall]]\nball = 22\nposition = \"0 deg\"\nlength = \"1 mm\"\ndepth = \"2 um\"\n",
    ));
    check(&e, "surface.balls.spall[0].ball", first + 1, &["0 to 21"]);
    let e = err(&case(
        "[surface.outer]\nrandom_radial_waviness = { min_order = 5, max_order = 2, amplitude = \"0.1 um\" }\n",
    ));
    assert_eq!(
        e.key.as_deref(),
        Some("surface.outer.random_radial_waviness.max_order"),
        "{e}"
    );
    let e = err(&case(
        "[[surface.outer.spall]]\nposition = \"0 deg\"\nlength = \"1 mm\"\ndepth = \"2 um\"\nedge = \"ramped\"\n",
    ));
    assert_eq!(e.key.as_deref(), Some("surface.outer.spall[0].ramp"), "{e}");
    // A valid surface loads, random waviness included.
    let ok = load_case(
        "case.toml",
        &case(
            "[surface.outer]\nradial_waviness = [{ order = 22, amplitude = \"0.3 um\" }]\nrandom_axial_waviness = { min_order = 2, max_order = 9, amplitude = \"0.1 um\", seed = 3 }\n[surface.balls]\nballs = [1]\nwaviness = [{ order = 2, amplitude = \"0.1 um\" }]\n",
        ),
        &[],
    )
    .unwrap();
    assert_eq!(ok.surface.outer.radial.terms.len(), 1);
    assert_eq!(ok.surface.outer.axial.terms.len(), 8);
    assert_eq!(ok.surface.balls.len(), 22);
    assert!(ok.surface.balls[0].is_smooth() && !ok.surface.balls[1].is_smooth());
}

#[test]
fn starvation_inputs_are_checked() {
    let lub = |extra: &str| {
        format!(
            "{BASE}\n[lubricant]\nviscosity = \"0.05 Pa.s\"\npressure_viscosity = \"2e-8 1/Pa\"\n{extra}"
        )
    };
    let e = err(&lub("inlet_distance_ratio = 0.9\n"));
    assert_eq!(
        e.key.as_deref(),
        Some("lubricant.inlet_distance_ratio"),
        "{e}"
    );
    assert!(e.to_string().contains("> 1"), "{e}");
    let e = err(&lub(
        "inlet_distance_ratio = 1.5\ninlet_distance_ratio_inner = 1.2\n",
    ));
    assert_eq!(
        e.key.as_deref(),
        Some("lubricant.inlet_distance_ratio"),
        "{e}"
    );
    let e = err(&lub("oil_flow = \"0.1 L/min\"\n"));
    assert_eq!(e.key.as_deref(), Some("lubricant.density"), "{e}");
    let e = err(&lub(
        "oil_flow = \"0.1 L/min\"\ndensity = \"860 kg/m^3\"\ninlet_distance_ratio = 1.5\n",
    ));
    assert_eq!(e.key.as_deref(), Some("lubricant.oil_flow"), "{e}");
    let ok = load_case("case.toml", &lub("inlet_distance_ratio_outer = 1.3\n"), &[]).unwrap();
    let supply = ok.lubricant.unwrap().supply;
    assert_eq!(supply[0], rolldyn::lubrication::Supply::Flooded);
    assert_eq!(supply[1], rolldyn::lubrication::Supply::InletDistance(1.3));
}

#[test]
fn power_and_thermal_inputs_are_checked() {
    let lub = |extra: &str| {
        format!(
            "{BASE}\n[lubricant]\nviscosity = \"0.05 Pa.s\"\npressure_viscosity = \"2e-8 1/Pa\"\n{extra}"
        )
    };
    let e = err(&lub("second_viscosity = \"5 mPa.s\"\n"));
    assert_eq!(
        e.key.as_deref(),
        Some("lubricant.second_temperature"),
        "{e}"
    );
    let e = err(&lub(
        "second_viscosity = \"5 mPa.s\"\nsecond_temperature = \"100 degC\"\n",
    ));
    assert_eq!(e.key.as_deref(), Some("lubricant.temperature"), "{e}");
    let e = err(&lub(
        "temperature = \"40 degC\"\nsecond_viscosity = \"80 mPa.s\"\nsecond_temperature = \"100 degC\"\n",
    ));
    assert_eq!(e.key.as_deref(), Some("lubricant.second_viscosity"), "{e}");
    assert!(e.to_string().contains("fall"), "{e}");
    let e = err(&format!("{BASE}\n[power]\nsliding_friction = -0.1\n"));
    assert_eq!(e.key.as_deref(), Some("power.sliding_friction"), "{e}");
    let e = err(&format!("{BASE}\n[thermal]\noil_flow = \"-1 L/min\"\n"));
    assert_eq!(e.key.as_deref(), Some("thermal.oil_flow"), "{e}");
    let e = err(&format!(
        "{BASE}\n[thermal]\nhousing_convection = \"15 W/m\"\n"
    ));
    assert_eq!(e.key.as_deref(), Some("thermal.housing_convection"), "{e}");
    let e = err(&format!("{BASE}\n[thermal]\nupdate_interval = \"1 ms\"\n"));
    assert_eq!(e.key.as_deref(), Some("thermal.update_interval"), "{e}");
    let ok = load_case(
        "case.toml",
        &format!("{BASE}\n[thermal]\nhousing_convection = \"20 W/(m^2.K)\"\nring_expansion = \"12 ppm/K\"\nrun_coupling = true\n"),
        &[],
    )
    .unwrap();
    assert_eq!(ok.thermal.housing_convection, 20.0);
    assert!((ok.thermal.expansion.ring - 12e-6).abs() < 1e-20);
    assert_eq!(ok.thermal.run_coupling, Some(1e-3));
    let e = ok.thermal_inputs().unwrap_err();
    assert_eq!(e.key, "bearing.bore");
}

#[test]
fn practical_limits_are_checked() {
    for (extra, key) in [
        (
            "[solver]\nrelative_tolerance = 1e-300\n",
            "solver.relative_tolerance",
        ),
        ("[solver]\nmax_step = \"1e-300 s\"\n", "solver.max_step"),
        ("[solver]\ntime_step = \"1e-12 s\"\n", "solver.time_step"),
        (
            "[output]\nsample_rate = \"1e12 Hz\"\n",
            "output.sample_rate",
        ),
        (
            "[model]\ntraction_integration = { method = \"grid\", across = 100000, along = 100000 }\n",
            "model.traction_integration",
        ),
    ] {
        let e = err(&format!("{BASE}\n{extra}"));
        assert_eq!(e.key.as_deref(), Some(key), "{e}");
    }
    let e = err(&format!("{BASE}\n[solver]\nrelative_tolerance = 1e-300\n"));
    assert!(e.to_string().contains("1e-300"), "{e}");
}

#[test]
fn physical_ranges_are_checked() {
    for (from, to, key) in [
        (
            "speed = \"10000 rpm\"",
            "speed = \"1e300 rpm\"",
            "operating.speed",
        ),
        (
            "force_x = \"200 N\"",
            "force_x = \"1e300 N\"",
            "operating.force_x",
        ),
    ] {
        let e = err(&replace(from, to));
        assert_eq!(e.key.as_deref(), Some(key), "{e}");
    }
    let e = err(&format!(
        "{BASE}\n[materials]\nball = {{ elastic_modulus = \"1e-300 Pa\", poisson_ratio = 0.3, density = \"7800 kg/m^3\" }}\n"
    ));
    assert_eq!(
        e.key.as_deref(),
        Some("materials.ball.elastic_modulus"),
        "{e}"
    );
}
