//! End-to-end tests of the surface, vibration and film commands (issues
//! 11 and 12): `run` with waviness and the vibration keys, `spectrum`,
//! films and natural modes in `quasistatic`, and `contact` for
//! tribologists.

#![allow(clippy::unwrap_used)]

use crate::common;

use crate::common::{
    assert_ok, json, keys, rolldyn, run_into, stderr, stdout, summary_of, temp_dir,
};
use rolldyn_case::presets::PRESETS;
use serde_json::Value;

/// Films (the default case has a lubricant) and the ring's natural modes
/// (given its tilt inertia); starvation on the inner ring thins only the
/// inner films by the Zhang et al. 2020 eq 30 factor.
#[test]
fn quasistatic_films_and_modes() {
    let flooded = json(&["quasistatic", "--json"], None);
    assert!(
        flooded["modes"].is_null(),
        "the preset gives no tilt inertia"
    );
    let f = &flooded["films"][0];
    for k in [
        "entrainment_speed_m_s",
        "central_film_m",
        "minimum_film_m",
        "flooded_central_film_m",
        "flooded_minimum_film_m",
        "starvation_factor",
        "inlet_distance_ratio",
        "critical_inlet_distance_ratio",
        "film_parameter",
        "film_stiffness_n_per_m",
        "asperity_share",
    ] {
        assert!(f["inner"].get(k).is_some(), "films lack {k}");
    }
    assert!(f["inner"]["asperity_share"].is_null());
    assert_eq!(f["inner"]["starvation_factor"], 1.0);
    assert!(f["inner"]["inlet_distance_ratio"].is_null());
    assert!(f["inner"]["film_parameter"].is_null());
    let q = json(
        &[
            "quasistatic",
            "--json",
            "--set",
            "lubricant.inlet_distance_ratio_inner=1.3",
            "--set",
            "surface.inner.roughness=\"0.1 um\"",
            "--set",
            "inner_ring.tilt_inertia=\"1e-4 kg.m^2\"",
            "--set",
            "inner_ring.mass=\"0.5 kg\"",
        ],
        None,
    );
    let (i, o) = (&q["films"][0]["inner"], &q["films"][0]["outer"]);
    let l_star = i["critical_inlet_distance_ratio"].as_f64().unwrap();
    let factor = ((1.3 - 1.0) / (l_star - 1.0)).powf(0.25);
    let g = |v: &serde_json::Value| v.as_f64().unwrap();
    assert!((g(&i["central_film_m"]) / g(&f["inner"]["central_film_m"]) - factor).abs() < 1e-9);
    assert_eq!(o["central_film_m"], f["outer"]["central_film_m"]);
    assert!((g(&i["film_parameter"]) - g(&i["minimum_film_m"]) / 0.1e-6).abs() < 1e-6);
    let modes = q["modes"]["modes"].as_array().unwrap();
    assert_eq!(modes.len(), 5);
    // The axial mode is √(k_xx/m)/2π (pure axial load: x decouples).
    let kxx = q["stiffness_matrix"][0][0].as_f64().unwrap();
    let axial = (kxx / 0.5).sqrt() / std::f64::consts::TAU;
    assert!(
        modes
            .iter()
            .any(|m| (m["frequency_hz"].as_f64().unwrap() / axial - 1.0).abs() < 1e-6),
        "{modes:?} vs {axial}"
    );
    let text = stdout(&rolldyn(
        &[
            "quasistatic",
            "--set",
            "inner_ring.tilt_inertia=\"1e-4 kg.m^2\"",
        ],
        None,
    ));
    assert!(text.contains("natural modes of the inner ring"), "{text}");
    assert!(text.contains("films (Hamrock–Dowson"), "{text}");
}

/// A wavy outer race (order 22 = Z, Deng et al. 2022's C3 setting): `run` records
/// the vibration channels and whirl keys, and `spectrum` finds BPFO (=
/// 22 f_c, Deng et al. 2022 Table 2) as the largest peak of the axial acceleration.
#[test]
fn spectrum_of_a_wavy_run_names_bpfo() {
    let preset = PRESETS.iter().find(|p| p.name == "7008C").unwrap().text;
    let case = preset.replacen(
        "\n[assumptions]",
        "\n[surface.outer]\nradial_waviness = [{ order = 22, amplitude = \"0.3 um\" }]\n\n[assumptions]",
        1,
    );
    let dir = temp_dir("spectrum");
    let d = dir.to_string_lossy().into_owned();
    let o = run_into(&d, Some(&case), "12 ms", &[]);
    assert_ok(&o);
    assert_summary_of_a_wavy_run(&dir);
    let check = json(&["check", "-", "--json"], Some(&case));
    assert_eq!(check["surfaces"][0]["part"], "outer");
    assert_eq!(check["surfaces"][0]["max_order"], 22);
    assert!(
        json(&["check", "--json"], None)["surfaces"]
            .as_array()
            .unwrap()
            .is_empty()
    );
    let list = stdout(&rolldyn(&["spectrum", &d, "--list"], None));
    for channel in [
        "inner_ring_acceleration_x_m_s2 [m/s^2]",
        "outer_ring_acceleration_z_m_s2 [m/s^2]",
        "housing_force_y_n [N]",
        "cage_velocity_z_m_s [m/s]",
        "pocket_force_max_n [N]",
        "pocket_force_sum_n [N]",
    ] {
        assert!(list.contains(channel), "--list lacks {channel}");
    }
    assert_spectrum_finds_bpfo(&dir);
    assert_spectrogram(&dir);
    assert_spectrum_refuses_bad_arguments(&d);
    let o = rolldyn(&["spectrum", "/nonexistent-dir"], None);
    assert_eq!(o.status.code(), Some(2));
    std::fs::remove_dir_all(&dir).ok();
}

/// The summary of the wavy run: its vibration keys, the waviness line at
/// 22 f_c and the sensor's envelope lines.
fn assert_summary_of_a_wavy_run(dir: &std::path::Path) {
    let summary: Value = summary_of(dir);
    for k in [
        "cage_whirl_radius_mean_m",
        "cage_whirl_radius_max_m",
        "cage_whirl_speed_rpm",
        "cage_whirl_speed_ratio",
        "cage_whirl_sigma",
        "velocity_rms_band_hz",
        "inner_ring_velocity_rms_x_mm_s",
        "inner_ring_velocity_rms_y_mm_s",
        "inner_ring_velocity_rms_z_mm_s",
        "outer_ring_velocity_rms_y_mm_s",
        "outer_ring_velocity_rms_z_mm_s",
        "sample_rate_hz",
        "ball_count",
        "ball_diameter_m",
        "pitch_diameter_m",
        "mean_contact_angle_inner_deg",
        "mean_contact_angle_outer_deg",
    ] {
        assert!(summary.get(k).is_some(), "summary lacks {k}");
    }
    assert!(summary["outer_ring_velocity_rms_y_mm_s"].is_null());
    // Outer-race order 22 on 22 balls: one axial line at 22 f_c (Deng et
    // al. 2022 Table 2), at the run's mean cage speed.
    let lines = &summary["waviness_lines"]["lines"];
    assert_eq!(lines.as_array().map(Vec::len), Some(1), "{lines}");
    assert_eq!(lines[0]["part"], "outer_race");
    assert_eq!(lines[0]["order"], 22);
    assert_eq!(lines[0]["motion"], "axial");
    let cage_hz = summary["mean_cage_speed_rpm"].as_f64().unwrap() / 60.0;
    let f = lines[0]["frequency_hz"].as_f64().unwrap();
    assert!((f - 22.0 * cage_hz).abs() < 1e-9 * f, "{f}");
    assert!(lines[0]["amplitude_m_s2"].as_f64().unwrap() >= 0.0);
    // No spall: the envelope lines are the preset's housing sensor's.
    assert_eq!(
        summary["envelope_lines"]["channel"], "sensor_acceleration_m_s2",
        "{}",
        summary["envelope_lines"]
    );
}

/// The amplitude spectrum of the axial acceleration names BPFO first and
/// writes its CSV and JSON; the PSD and the envelope spectrum run.
fn assert_spectrum_finds_bpfo(dir: &std::path::Path) {
    let d = dir.to_string_lossy().into_owned();
    let s = json(
        &[
            "spectrum",
            &d,
            "--channel",
            "inner_ring_acceleration_x_m_s2",
            "--from",
            "2 ms",
            "--json",
        ],
        None,
    );
    assert_eq!(
        keys(&s),
        [
            "band_hz",
            "band_warning",
            "channel",
            "characteristic",
            "csv",
            "from_s",
            "kind",
            "lines",
            "peaks",
            "resolution_hz",
            "sample_rate_hz",
            "samples",
            "segment",
            "segments",
            "to_s",
            "unit",
            "value_unit",
            "velocity_rms_band_hz",
            "velocity_rms_mm_s",
            "window"
        ]
    );
    assert_eq!(s["peaks"][0]["line"], "BPFO", "{}", s["peaks"]);
    let bpfo = s["characteristic"]["bpfo_hz"].as_f64().unwrap();
    let f = s["peaks"][0]["frequency_hz"].as_f64().unwrap();
    assert!((f - bpfo).abs() <= 1.5 * s["resolution_hz"].as_f64().unwrap());
    assert!(s["velocity_rms_mm_s"].as_f64().unwrap() >= 0.0);
    let csv =
        std::fs::read_to_string(dir.join("spectrum_inner_ring_acceleration_x_m_s2_amplitude.csv"))
            .unwrap();
    assert!(csv.starts_with("frequency_hz,value\n"));
    assert!(
        dir.join("spectrum_inner_ring_acceleration_x_m_s2_amplitude.json")
            .exists()
    );
    for kind in [["--kind", "psd"], ["--kind", "envelope"]] {
        let s = json(&["spectrum", &d, kind[0], kind[1], "--json"], None);
        assert_eq!(s["kind"], kind[1]);
    }
}

/// A spectrogram: segments of 16 samples half overlapping, one CSV row per
/// segment and frequency.
fn assert_spectrogram(dir: &std::path::Path) {
    let d = dir.to_string_lossy().into_owned();
    let s = json(
        &[
            "spectrum",
            &d,
            "--kind",
            "spectrogram",
            "--channel",
            "inner_ring_acceleration_z_m_s2",
            "--segment",
            "16",
            "--from",
            "0 s",
            "--json",
        ],
        None,
    );
    let segments = s["segments"].as_u64().unwrap() as usize;
    let samples = s["samples"].as_u64().unwrap() as usize;
    assert_eq!(segments, (samples - 16) / 8 + 1);
    let csv = std::fs::read_to_string(
        dir.join("spectrum_inner_ring_acceleration_z_m_s2_spectrogram.csv"),
    )
    .unwrap();
    assert!(csv.starts_with("time_s,frequency_hz,value\n"));
    // 9 frequencies (0 … Nyquist) per segment of 16.
    assert_eq!(csv.lines().count(), 1 + 9 * segments);
}

/// Bad arguments: exit 2, the argument named.
fn assert_spectrum_refuses_bad_arguments(d: &str) {
    for (args, fragment) in [
        (vec!["--channel", "nope"], "--channel nope"),
        (vec!["--kind", "cepstrum"], "--kind cepstrum"),
        (
            vec!["--kind", "envelope", "--band", "9000:100 Hz"],
            "--band",
        ),
        (vec!["--from", "1 s"], "--from"),
        // A bare number: the case files' message.
        (vec!["--from", "0.1"], "missing unit"),
    ] {
        let mut all = vec!["spectrum", d];
        all.extend(args);
        let o = rolldyn(&all, None);
        assert_eq!(o.status.code(), Some(2), "{all:?}");
        assert!(stderr(&o).contains(fragment), "{}", stderr(&o));
    }
}

/// Ball surfaces add a spin-angle state per ball: the traction-consistent
/// quasi-static solve and a run from it still work.
#[test]
fn ball_surfaces_work_with_the_traction_quasistatic() {
    let preset = PRESETS.iter().find(|p| p.name == "7008C").unwrap().text;
    let case = preset.replacen(
        "\n[assumptions]",
        "\n[surface.balls]\nwaviness = [{ order = 2, amplitude = \"0.1 um\" }]\n\n[assumptions]",
        1,
    );
    let o = rolldyn(
        &["quasistatic", "-", "--control", "traction", "--json"],
        Some(&case),
    );
    assert_ok(&o);
    let dir = temp_dir("ball-surface");
    let d = dir.to_string_lossy().into_owned();
    let o = run_into(
        &d,
        Some(&case),
        "1 ms",
        &["solver.start=\"quasistatic_traction\""],
    );
    assert_ok(&o);
    std::fs::remove_dir_all(&dir).ok();
}

/// `contact` for tribologists: an explicit ball-on-flat contact with a
/// starved film, Hertz and film results; raceway films with
/// --entrainment-speed; the errors.
#[test]
fn contact_with_films_and_explicit_contacts() {
    let flat = json(
        &[
            "contact",
            "--ball-on-flat",
            "19.05 mm",
            "--load",
            "20 N",
            "--entrainment-speed",
            "0.5 m/s",
            "--inlet-distance-ratio",
            "1.5",
            "--json",
        ],
        None,
    );
    assert_eq!(
        keys(&flat),
        [
            "approach_m",
            "contact_stiffness_n_per_m",
            "effective_modulus_pa",
            "ellipticity",
            "film",
            "load_n",
            "max_pressure_pa",
            "rolling_radius_m",
            "semi_major_m",
            "semi_minor_m",
            "series_stiffness_n_per_m",
            "transverse_radius_m"
        ]
    );
    let g = |v: &Value| v.as_f64().unwrap();
    assert!((g(&flat["ellipticity"]) - 1.0).abs() < 1e-12);
    // Hertz sphere on flat: a = (3QR/(2E'))^{1/3} with R = D/2 (E' = 2/Σ(1−ν²)/E).
    let ep = g(&flat["effective_modulus_pa"]);
    let a = (3.0 * 20.0 * 9.525e-3 / (2.0 * ep)).cbrt();
    assert!((g(&flat["semi_major_m"]) / a - 1.0).abs() < 1e-9);
    let film = &flat["film"];
    let l_star = g(&film["critical_inlet_distance_ratio"]);
    let factor = ((1.5 - 1.0) / (l_star - 1.0)).powf(0.25);
    assert!((g(&film["starvation_factor"]) - factor).abs() < 1e-12);
    assert!(
        (g(&film["central_film_m"]) / g(&film["flooded_central_film_m"]) - factor).abs() < 1e-12
    );
    let k = g(&flat["contact_stiffness_n_per_m"]);
    let koil = g(&film["film_stiffness_n_per_m"]);
    assert!((g(&flat["series_stiffness_n_per_m"]) - k * koil / (k + koil)).abs() < 1e-6 * k);
    // Raceways with a film; without --entrainment-speed no film keys.
    let r = json(
        &[
            "contact",
            "--load",
            "50 N",
            "--entrainment-speed",
            "14 m/s",
            "--json",
        ],
        None,
    );
    assert_eq!(g(&r["entrainment_speed_m_s"]), 14.0);
    assert!(g(&r["inner"]["film"]["central_film_m"]) > 0.0);
    assert!(g(&r["outer"]["series_stiffness_n_per_m"]) > 0.0);
    assert!(
        json(&["contact", "--load", "50 N", "--json"], None)["inner"]
            .get("film")
            .is_none()
    );
    for (args, fragment) in [
        (vec!["--radii", "3 mm,2 mm", "--load", "1 N"], "R_x ≤ R_y"),
        (
            vec![
                "--radii",
                "3 mm,4 mm",
                "--ball-on-flat",
                "5 mm",
                "--load",
                "1 N",
            ],
            "not both",
        ),
        (
            vec!["--load", "1 N", "--inlet-distance-ratio", "1.5"],
            "only for explicit contacts",
        ),
        (
            vec![
                "--ball-on-flat",
                "5 mm",
                "--load",
                "1 N",
                "--inlet-distance-ratio",
                "0.5",
            ],
            "--inlet-distance-ratio",
        ),
        (
            vec!["--load", "1 N", "--entrainment-speed", "-1 m/s"],
            "must not be negative",
        ),
    ] {
        let mut all = vec!["contact"];
        all.extend(args);
        let o = rolldyn(&all, None);
        assert_eq!(o.status.code(), Some(2), "{all:?}");
        assert!(stderr(&o).contains(fragment), "{}", stderr(&o));
    }
}

/// The film in the normal approach: `quasistatic` solves
/// with it and reports the dry stiffness beside; `run` starts from that
/// equilibrium, records the films' work and closes its energy balance;
/// cases it cannot serve are refused naming the key.
#[test]
fn the_film_in_the_approach_in_quasistatic_and_run() {
    let film = ["--set", "model.film_in_approach=true"];
    let dry = json(&["quasistatic", "--json"], None);
    let wet = json(&["quasistatic", "--json", film[0], film[1]], None);
    assert_eq!(dry["film_in_approach"], false);
    assert!(dry["stiffness_matrix_without_film"].is_null());
    assert_eq!(wet["film_in_approach"], true);
    assert_eq!(
        wet["stiffness_matrix_without_film"],
        dry["stiffness_matrix"]
    );
    assert_eq!(
        wet["conventional_stiffness_without_film"],
        dry["conventional_stiffness"]
    );
    let g = |v: &Value| v.as_f64().unwrap();
    // Under the preset's axial load the film adds its compliance.
    let axial = |v: &Value| g(&v["conventional_stiffness"]["axial_n_per_m"]);
    assert!(axial(&wet) < axial(&dry), "{} {}", axial(&wet), axial(&dry));
    let text = stdout(&rolldyn(&["quasistatic", film[0], film[1]], None));
    assert!(text.contains("without the film"), "{text}");

    let dir = temp_dir("film-approach");
    let d = dir.to_string_lossy().into_owned();
    let o = rolldyn(
        &["run", "--duration", "4 ms", "-o", &d, film[0], film[1]],
        None,
    );
    assert_ok(&o);
    let summary: Value = summary_of(&dir);
    assert!(summary["film_work_j"].is_f64());
    let balance = g(&summary["energy_balance_relative_error"]);
    assert!(balance.abs() < 1e-3, "{balance}");
    std::fs::remove_dir_all(&dir).ok();

    for (set, rule) in [
        ("model.traction=\"none\"", "needs a film model"),
        ("lubricant.oil_flow=\"0.1 L/min\"", "not lubricant.oil_flow"),
    ] {
        let o = rolldyn(
            &[
                "quasistatic",
                film[0],
                film[1],
                "--set",
                set,
                "--set",
                "lubricant.density=\"860 kg/m^3\"",
            ],
            None,
        );
        assert!(!o.status.success());
        let e = stderr(&o);
        assert!(
            e.contains("model.film_in_approach") && e.contains(rule),
            "{e}"
        );
    }
}

/// `[model.mixed_lubrication]` on the default case: the run records each
/// contact's asperity share, and a case without what the model needs is
/// refused naming the key and the rule.
#[test]
fn mixed_lubrication_in_run_and_its_refusals() {
    let mixed = "model.mixed_lubrication={ boundary_friction = 0.1, sigma_beta_eta = 0.04, sigma_over_beta = 0.001 }";
    let rough = [
        "--set",
        "surface.inner.roughness=\"0.15 um\"",
        "--set",
        "surface.outer.roughness=\"0.15 um\"",
    ];
    let dir = temp_dir("mixed-lubrication");
    let d = dir.to_string_lossy().into_owned();
    let mut args = vec!["run", "--duration", "2 ms", "-o", &d, "--set", mixed];
    args.extend_from_slice(&rough);
    let o = rolldyn(&args, None);
    assert_ok(&o);
    let table = parquet::file::reader::SerializedFileReader::new(
        std::fs::File::open(common::first_part(&dir)).unwrap(),
    )
    .unwrap();
    use parquet::file::reader::FileReader;
    let schema = table.metadata().file_metadata().schema_descr();
    let names: Vec<String> = schema
        .columns()
        .iter()
        .map(|c| c.name().to_string())
        .collect();
    assert!(
        names.iter().any(|n| n == "ball0_asperity_share_inner"),
        "{names:?}"
    );
    assert!(names.iter().any(|n| n == "ball0_asperity_share_outer"));
    std::fs::remove_dir_all(&dir).ok();
    // The quasi-static films give each contact's share: φ = min(1, p_a/p̄)
    // falls as Λ rises, between the balls of a loaded bearing.
    let mut args = vec![
        "quasistatic",
        "--json",
        "--speed",
        "2000 rpm",
        "--set",
        mixed,
    ];
    args.extend_from_slice(&rough);
    let q = json(&args, None);
    let g = |v: &Value| v.as_f64().unwrap();
    let films = q["films"].as_array().unwrap();
    for f in films {
        let share = g(&f["inner"]["asperity_share"]);
        assert!(share > 0.0 && share < 1.0, "{share}");
    }
    let text_args: Vec<&str> = args.iter().copied().filter(|a| *a != "--json").collect();
    let text = stdout(&rolldyn(&text_args, None));
    assert!(text.contains("asperity share"), "{text}");

    for (extra, rule) in [
        (vec![], "surface.inner.roughness"),
        (
            vec![
                "--set",
                "model.traction={ law = \"modified_coulomb\", friction = 0.1 }",
            ],
            "needs model.traction law \"ehl\"",
        ),
        (
            vec!["--set", "model.mixed_lubrication.sigma_over_beta=2.0"],
            "sigma_over_beta",
        ),
    ] {
        let mut args = vec!["check", "--set", mixed];
        if rule != "surface.inner.roughness" {
            args.extend_from_slice(&rough);
        }
        args.extend(extra);
        let o = rolldyn(&args, None);
        assert!(!o.status.success(), "{args:?}");
        let e = stderr(&o);
        assert!(
            e.contains("model.mixed_lubrication") && e.contains(rule),
            "{e}"
        );
    }
}
