//! The case-format rejection rules of the dynamic model, surfaces,
//! starvation, power and thermal inputs and the practical limits: the
//! message names the key, the value and the rule, and points at the line.

#![allow(clippy::unwrap_used)]

mod common;

use common::{BASE, check, err, replace};
use rolldyn_case::load_case;

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
    // Contact damping and mounting.
    let e = err(&format!(
        "{BASE}\n[model]\nnormal_law = {{ law = \"material\", dissipation = -0.1 }}\n"
    ));
    check(
        &e,
        "model.normal_law.dissipation",
        15,
        &["-0.1", "[0, 10] s/m"],
    );
    let e = err(&format!(
        "{BASE}\n[model]\nnormal_law = {{ law = \"hunt_crossley\", restitution = 1.2 }}\n"
    ));
    check(&e, "model.normal_law.restitution", 15, &["1.2", "(0, 1]"]);
    let e = err(&format!(
        "{BASE}\n[outer_ring]\nmass = \"-1 kg\"\nhousing_stiffness = \"1e7 N/m\"\n"
    ));
    check(&e, "outer_ring.mass", 15, &["-1 kg"]);
    let e = err(&format!(
        "{BASE}\n[outer_ring]\nmass = \"5 kg\"\nhousing_stiffness = \"-1e7 N/m\"\n"
    ));
    check(&e, "outer_ring.housing_stiffness", 16, &["-1e7 N/m"]);
    let e = err(&format!("{BASE}\n[inner_ring]\nmass = \"-2 kg\"\n"));
    check(&e, "inner_ring.mass", 15, &["-2 kg"]);
}

#[test]
fn dynamics_parameters_defaults_and_missing_values() {
    // The default case has everything a run needs.
    let case = rolldyn_case::load_default(&[]).unwrap();
    let p = case.dynamics_parameters().unwrap();
    // Mounted (docs/dynamics.md, "Mounting"): a shaft share, the tilts
    // held, gravity.
    assert_eq!(p.inner_ring_mass, 2.03);
    assert!(p.inner_ring_tilt_held && p.gravity > 9.8);
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
fn pocket_laws_and_the_pocket_squeeze_film() {
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
    // Refused when the case loads, located in the file.
    let e = err(&squeeze);
    assert_eq!(e.key.as_deref(), Some("cage.pocket_squeeze_film"), "{e}");
    assert!(e.to_string().contains("case.toml:"), "{e}");
    assert!(e.rule.contains("[lubricant]"), "{e}");
    let lubricated = format!(
        "{squeeze}\n[lubricant]\nviscosity = \"0.05 Pa.s\"\npressure_viscosity = \"2e-8 1/Pa\"\n"
    );
    let squeeze_of = |text: &str| dynamics(text).unwrap().cage.pocket_squeeze.unwrap();
    let s = squeeze_of(&lubricated);
    assert_eq!((s.viscosity, s.min_film), (0.05, 1e-6));
    assert!((s.ball_radius - 3.175e-3).abs() < 1e-15);
    assert_eq!(s.cavitation, rolldyn::cage::SqueezeCavitation::Vapour);
    assert_eq!(s.tension, rolldyn::cage::squeeze::DEFAULT_POCKET_TENSION);
    let with = |line: &str| {
        lubricated.replace(
            "pocket_squeeze_film = true\n",
            &format!("pocket_squeeze_film = true\n{line}\n"),
        )
    };
    let full = with("pocket_squeeze_cavitation = \"full_film\"");
    assert_eq!(
        squeeze_of(&full).cavitation,
        rolldyn::cage::SqueezeCavitation::FullFilm
    );
    assert_eq!(
        squeeze_of(&with("pocket_squeeze_tension = \"50 kPa\"")).tension,
        5e4
    );
    let e = err(&with("pocket_squeeze_tension = \"-1 kPa\""));
    assert_eq!(e.key.as_deref(), Some("cage.pocket_squeeze_tension"), "{e}");
    // A spherical pocket has the cut-off too, by default.
    let spherical = "pocket_shape = \"spherical\"";
    assert_eq!(
        squeeze_of(&with(spherical)).cavitation,
        rolldyn::cage::SqueezeCavitation::Vapour
    );
    let e = err(&with("pocket_min_film = \"0.1 mm\""));
    assert_eq!(e.key.as_deref(), Some("cage.pocket_min_film"), "{e}");
    assert!(e.rule.contains("half of cage.pocket_clearance"), "{e}");
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
}

/// A load table and constant loads exclude each other, its times increase;
/// an outer ring's mass, the rolling hysteresis and a traction curve's
/// coefficients are refused outside their ranges, located.
#[test]
fn load_tables_housing_and_model_ranges() {
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

/// A shaft's displacements and tilts follow from its bearings: a held tilt
/// or a prescribed displacement beside `[shaft]` is refused, the key and
/// its line named (they were ignored before).
#[test]
fn a_shaft_refuses_prescribed_ring_displacements() {
    let shaft = "[operating]\nspeed = \"3000 rpm\"\n{KEY}\n[shaft]\n[[shaft.bearings]]\npreset = \"6206\"\nposition = \"-60 mm\"\n[[shaft.bearings]]\npreset = \"6206\"\nposition = \"60 mm\"\n";
    for (line, key) in [
        ("fixed_tilt = true", "operating.fixed_tilt"),
        ("tilt_y = \"0.1 deg\"", "operating.tilt_y"),
        ("displacement_z = \"1 um\"", "operating.displacement_z"),
    ] {
        let e = err(&shaft.replace("{KEY}", line));
        check(
            &e,
            key,
            3,
            &["follow from its bearings", "not with [shaft]"],
        );
    }
}

/// A `bearing.preset` brings its pockets' squeeze film only into a case
/// with a `[lubricant]` (the film is of the preset's oil); a file that
/// asks for the film itself without one is refused where it says so, by
/// every command (the case does not load).
#[test]
fn a_presets_pocket_film_needs_the_cases_oil() {
    let dry = "[bearing]\npreset = \"6205\"\n[operating]\nspeed = \"1797 rpm\"\n";
    let case = load_case("case.toml", dry, &[]).unwrap();
    assert!(!case.cage.pocket_squeeze_film);
    assert!(
        !case
            .assumptions
            .iter()
            .any(|(k, _)| k == "cage.pocket_squeeze_film")
    );
    let oiled = format!(
        "{dry}[lubricant]\nviscosity = \"0.01 Pa.s\"\npressure_viscosity = \"2e-8 1/Pa\"\n"
    );
    let case = load_case("case.toml", &oiled, &[]).unwrap();
    assert!(case.cage.pocket_squeeze_film);
    assert!(
        case.assumptions
            .iter()
            .any(|(k, _)| k == "cage.pocket_squeeze_film")
    );
    let asked = format!("{dry}[cage]\npocket_squeeze_film = true\n");
    let e = load_case("case.toml", &asked, &[]).unwrap_err();
    check(&e, "cage.pocket_squeeze_film", 6, &["needs a [lubricant]"]);
}

/// `model.bearing_damping` τ adds c = τ k_r radially to the inner ring's
/// support, k_r the quasi-static radial stiffness at the operating point;
/// a τ outside [0, 1e-3] s, an `[outer_ring]` and a bearing set are
/// refused naming the key.
#[test]
fn bearing_damping_is_tau_times_the_radial_stiffness() {
    // The preset's mounting has τ = 1.25e-5 s.
    let preset = rolldyn_case::presets::find("6205").unwrap().text;
    let case = load_case("6205", preset, &[]).unwrap();
    let k = case.radial_stiffness().unwrap();
    let support = case.dynamics_parameters().unwrap().inner_support;
    assert_eq!(support.damping, [0.0, 1.25e-5 * k, 1.25e-5 * k]);
    // Stiffer under a larger load, so more damping.
    let heavy = preset.replacen("force_z = \"100 N\"", "force_z = \"1 kN\"", 1);
    let heavy = load_case("6205", &heavy, &[]).unwrap();
    assert!(heavy.radial_stiffness().unwrap() > 2.0 * k);
    let e = err(&preset.replacen(
        "bearing_damping = \"1.25e-5 s\"",
        "bearing_damping = \"2e-3 s\"",
        1,
    ));
    let line = 1 + preset
        .lines()
        .position(|l| l.starts_with("bearing_damping"))
        .unwrap();
    check(&e, "model.bearing_damping", line, &["[0, 1e-3] s"]);
    let with_housing =
        format!("{preset}\n[outer_ring]\nmass = \"1 kg\"\nhousing_stiffness = \"1e8 N/m\"\n");
    let e = load_case("6205", &with_housing, &[])
        .unwrap()
        .dynamics_parameters()
        .unwrap_err();
    assert_eq!(e.key, "model.bearing_damping");
    assert!(e.rule.contains("[outer_ring]"), "{}", e.rule);
}
