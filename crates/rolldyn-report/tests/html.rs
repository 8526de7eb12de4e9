//! The report is well-formed, self-contained HTML: parsed as XML, every
//! section the run has data for is present, every plot is an SVG with
//! drawn series, nothing is loaded from elsewhere and no value is NaN.

#![allow(clippy::unwrap_used)]

use rolldyn_io::RunDir;
use rolldyn_io::{TimeSeries, write_parquet};
use rolldyn_report::svg::{Plot, Series};
use rolldyn_report::{Report, Section, report_for};
use std::path::PathBuf;

fn temp_dir(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rolldyn-report-{tag}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Checks the page: XML, no external reference, no script; returns the
/// ids of its sections and the number of SVGs with a drawn series.
fn check_page(html: &str) -> (Vec<String>, usize) {
    let doc = roxmltree::Document::parse_with_options(
        html,
        roxmltree::ParsingOptions {
            allow_dtd: true,
            ..Default::default()
        },
    )
    .expect("the report is well-formed XML");
    let mut sections = Vec::new();
    let mut plots = 0;
    for node in doc.descendants().filter(|n| n.is_element()) {
        let name = node.tag_name().name();
        assert_ne!(name, "script", "no script");
        assert_ne!(name, "img", "plots are inline SVG");
        assert_ne!(name, "link", "styles are inline");
        for attr in node.attributes() {
            assert!(
                !attr.value().starts_with("http") || attr.name() == "xmlns",
                "external reference {}={}",
                attr.name(),
                attr.value()
            );
        }
        if name == "section" {
            sections.push(node.attribute("id").unwrap().to_string());
        }
        if name == "svg" {
            let drawn = node
                .descendants()
                .any(|d| matches!(d.tag_name().name(), "polyline" | "circle"));
            assert!(drawn, "an SVG without data");
            plots += 1;
        }
    }
    assert!(
        !html.contains("NaN") && !html.contains("inf<"),
        "non-finite value shown"
    );
    (sections, plots)
}

/// A synthetic run; its inner ring accelerates by `ramp` rpm/s.
fn synthetic_run(dir: &std::path::Path, ramp: f64) {
    let mut s = TimeSeries::default();
    let names = [
        ("time_s", "s"),
        ("inner_ring_speed_rpm", "rpm"),
        ("cage_speed_rpm", "rpm"),
        ("pure_rolling_cage_speed_ratio", "1"),
        ("cage_y_m", "m"),
        ("cage_z_m", "m"),
        ("drive_work_j", "J"),
        ("dissipated_energy_j", "J"),
        ("mechanical_energy_j", "J"),
        ("ball0_load_inner_n", "N"),
        ("ball0_load_outer_n", "N"),
        ("ball1_load_inner_n", "N"),
        ("ball1_load_outer_n", "N"),
    ];
    for (n, u) in names {
        s.channel(n, u);
    }
    for k in 0..500 {
        let t = k as f64 * 1e-5;
        let phase = 2.0 * std::f64::consts::PI * 800.0 * t;
        s.push(&[
            t,
            10_000.0 + ramp * t,
            4440.0 + phase.sin(),
            0.4447,
            1e-6 * phase.cos(),
            1e-6 * phase.sin(),
            t,
            0.99 * t,
            1.0 + 0.01 * t,
            100.0 + phase.sin(),
            110.0,
            f64::NAN, // an undefined sample is not drawn
            120.0,
        ]);
    }
    write_parquet(&dir.join("timeseries.parquet"), &s, &[]).unwrap();
    let summary = serde_json::json!({
        "source": "test",
        "title": "synthetic <run> & co",
        "status": "completed",
        "error": null,
        "simulated_time_s": 5e-3,
        "requested_duration_s": 5e-3,
        "wall_time_s": 0.1,
        "integrator": "ros34pw2",
        "steps": 100,
        "averaging_window_s": [2.5e-3, 5e-3],
        "mean_cage_speed_rpm": 4440.0,
        "pure_rolling_cage_speed_rpm": 4447.0,
        "cage_sliding_rate": 0.0016,
        "outer_ring_velocity_rms_y_mm_s": null,
        "mean_power_loss_by_component_w": {"inner_spin": 1.5, "guide_land": 80.0}
    });
    std::fs::write(dir.join("summary.json"), summary.to_string()).unwrap();
}

#[test]
fn run_report_has_every_section_and_plot() {
    let dir = temp_dir("run");
    synthetic_run(&dir, 0.0);
    let report = report_for(&dir, Some("geometry: <described>".into())).unwrap();
    let html = report.to_html();
    let (sections, plots) = check_page(&html);
    // No slide/spin or power channels: those sections are left out; no
    // run.json: the case section shows the description only.
    assert_eq!(
        sections,
        [
            "summary", "case", "solver", "cage", "contacts", "orbit", "energy", "values"
        ]
    );
    // Cage 1; contacts 2 (loads per ball and of ball 0; no angle channels);
    // orbit 1; energy 2.
    assert_eq!(plots, 6);
    assert!(html.contains("synthetic &lt;run&gt; &amp; co"));
    assert!(html.contains("geometry: &lt;described&gt;"));
    // The undefined summary value shows as a dash, the nested one by its path.
    assert!(html.contains("<td>outer_ring_velocity_rms_y_mm_s</td><td>—</td>"));
    assert!(html.contains("<td>mean_power_loss_by_component_w.guide_land</td>"));
    assert!(!html.contains("Inner-ring speed"));
    // A ring that changes speed gets its own plot.
    synthetic_run(&dir, 1e5);
    let html = report_for(&dir, None).unwrap().to_html();
    assert_eq!(check_page(&html).1, 7);
    assert!(html.contains("Inner-ring speed"));
}

#[test]
fn sweep_report_plots_each_quantity_per_series() {
    let dir = temp_dir("sweep");
    let mut rows = Vec::new();
    for fa in [100.0f64, 1000.0] {
        for rpm in [0.0, 5000.0, 10_000.0] {
            rows.push(serde_json::json!({
                "speed_rpm": rpm, "force_x_n": fa, "force_z_n": 0.0,
                "converged": !(rpm == 10_000.0 && fa == 1000.0),
                "error": null,
                "cage_speed_rpm": 0.44 * rpm,
                "stiffness_axial_n_per_m": 1e7 * fa.sqrt(),
                "constant_n": 1.0
            }));
        }
    }
    std::fs::write(
        dir.join("sweep.json"),
        serde_json::Value::Array(rows).to_string(),
    )
    .unwrap();
    let report = report_for(&dir, None).unwrap();
    let html = report.to_html();
    let (sections, plots) = check_page(&html);
    assert_eq!(sections, ["points", "quantities"]);
    // Two varying outputs (the constant one is left out), speed on the
    // abscissa, one series per axial load.
    assert_eq!(plots, 2);
    assert_eq!(
        html.matches("data-series=\"axial load F_x [N] = 100\"")
            .count(),
        2
    );
    assert!(html.contains("inner-ring speed [rpm]"));
    assert!(html.contains("1 failed"));
}

#[test]
fn not_a_result_directory_is_named() {
    let dir = temp_dir("empty");
    let e = report_for(&dir, None).unwrap_err().to_string();
    assert!(
        e.contains(&dir.display().to_string()) && e.contains("summary.json"),
        "{e}"
    );
    assert_eq!(RunDir::REPORT, "report.html");
}

#[test]
fn sections_are_added_as_data() {
    // A later model adds a section: a title, text and a plot.
    let report = Report {
        title: "t".into(),
        subtitle: "s".into(),
        warnings: vec!["not converged".into()],
        sections: vec![Section::new("spectrum", "Spectrum").paragraph("p").figure(
            Plot::new("PSD", "f [Hz]", "PSD").with(Series::line("x", &[1.0, 2.0], &[3.0, 4.0])),
        )],
    };
    let html = report.to_html();
    assert!(html.contains(
        "<div class=\"warning\" role=\"alert\"><strong>Warning:</strong> not converged</div>"
    ));
    let (sections, plots) = check_page(&html);
    assert_eq!((sections, plots), (vec!["spectrum".to_string()], 1));
}

/// A record longer than the report holds is reduced to bucket extremes:
/// a one-sample spike survives, the window means are exact, and the
/// energy balance's error is computed row by row before the reduction.
#[test]
fn long_records_are_reduced_without_losing_spikes_or_the_balance() {
    use rolldyn_report::run::{PLOT_ROWS, read_for_plots};
    let dir = std::env::temp_dir().join(format!("rolldyn-report-long-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut s = TimeSeries::default();
    for (name, unit) in [
        ("time_s", "s"),
        ("ball0_load_inner_n", "N"),
        ("ball1_load_inner_n", "N"),
        ("drive_work_j", "J"),
        ("dissipated_energy_j", "J"),
        ("mechanical_energy_j", "J"),
    ] {
        s.channel(name, unit);
    }
    let rows = 3 * PLOT_ROWS + 17;
    for k in 0..rows {
        let t = k as f64 * 1e-4;
        let spike = if k == 31_337 { 500.0 } else { 0.0 };
        // W − D − ΔE = 1e-9 k: a drift the extremes of W, D and E alone
        // (each swinging by ±1 J) would bury.
        let swing = (k as f64 * 0.37).sin();
        s.push(&[t, 10.0 + spike, 20.0, 5.0 + swing, swing, -1e-9 * k as f64]);
    }
    let path = dir.join("timeseries.parquet");
    write_parquet(&path, &s, &[]).unwrap();
    let window = [0.5 * (rows - 1) as f64 * 1e-4, (rows - 1) as f64 * 1e-4];
    let (plot, means, _) = read_for_plots(&path, window).unwrap();
    assert!(plot.len() <= PLOT_ROWS, "{} rows", plot.len());
    assert!(
        plot.column("ball1_load_inner_n").is_none(),
        "other balls: means only"
    );
    let load = plot.column("ball0_load_inner_n").unwrap();
    assert_eq!(load.iter().copied().fold(0.0, f64::max), 510.0);
    let error = plot.column("energy_balance_error_j").unwrap();
    let last = error.iter().copied().fold(f64::MIN, f64::max);
    assert!(
        (last - 5.0 - 1e-9 * (rows - 1) as f64).abs() < 1e-9,
        "{last}"
    );
    let from = (rows - 1).div_ceil(2);
    let exact = (from..rows).count() as f64;
    assert_eq!(means["ball1_load_inner_n"], 20.0);
    assert!(
        (means["time_s"] - (from..rows).map(|k| k as f64 * 1e-4).sum::<f64>() / exact).abs() < 1e-9
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// Adds to `dir`'s summary.json a 9-ball deep-groove bearing's geometry
/// and contact angles (the characteristic lines' inputs) and `extra`;
/// returns the summary written.
fn with_speeds(dir: &std::path::Path, extra: serde_json::Value) -> serde_json::Value {
    let mut summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    let bearing = serde_json::json!({
        "ball_count": 9,
        "ball_diameter_m": 0.00794,
        "pitch_diameter_m": 0.039,
        "mean_contact_angle_inner_deg": 0.0,
        "mean_contact_angle_outer_deg": 0.0,
    });
    for part in [bearing, extra] {
        for (k, v) in part.as_object().unwrap() {
            summary[k] = v.clone();
        }
    }
    std::fs::write(dir.join("summary.json"), summary.to_string()).unwrap();
    summary
}

/// A run with a spall gets the vibration section: statistics, the lines'
/// table and three plots (signal, spectrum, envelope spectrum with the
/// lines marked), from the unreduced window of the acceleration.
#[test]
fn a_spalled_run_has_a_vibration_section() {
    let dir = temp_dir("spalled");
    synthetic_run(&dir, 0.0);
    // The acceleration: a 3 kHz resonance rung at BPFO = 100 Hz.
    let mut s = TimeSeries::default();
    s.channel("time_s", "s");
    s.channel("inner_ring_acceleration_z_m_s2", "m/s^2");
    s.channel("cage_speed_rpm", "rpm");
    let rate = 12_000.0;
    for k in 0..6000 {
        let t = k as f64 / rate;
        let since = t % 0.01;
        let ring = (-since / 5e-4).exp() * (std::f64::consts::TAU * 3000.0 * t).sin();
        s.push(&[t, 100.0 * ring, 720.0]);
    }
    write_parquet(&dir.join("timeseries.parquet"), &s, &[]).unwrap();
    let mut summary = with_speeds(
        &dir,
        serde_json::json!({
            "averaging_window_s": [0.25, 0.5],
            "inner_ring_speed_rpm": 1772.0,
            "mean_cage_speed_rpm": 705.8,
            "envelope_lines": {"channel": "inner_ring_acceleration_z_m_s2", "band_hz": [1200.0, 4800.0],
                "resolution_hz": 4.0, "lines": [{"name": "BPFO", "frequency_hz": 105.9, "amplitude_m_s2": 12.0}]}
        }),
    );
    let html = report_for(&dir, None).unwrap().to_html();
    let (sections, _) = check_page(&html);
    assert!(sections.contains(&"vibration".to_string()), "{sections:?}");
    assert!(html.contains("Envelope spectrum (band 1200–4800 Hz)"));
    assert!(html.contains("kurtosis"));
    assert!(
        html.contains("<td>BPFO</td><td>105.90</td>"),
        "the lines' table"
    );
    // Without envelope lines (no spall) there is no such section.
    summary["envelope_lines"] = serde_json::Value::Null;
    std::fs::write(dir.join("summary.json"), summary.to_string()).unwrap();
    let html = report_for(&dir, None).unwrap().to_html();
    assert!(!check_page(&html).0.contains(&"vibration".to_string()));
}

/// A run with waviness (its summary has `waviness_lines`, no spall) gets
/// the vibration section with the amplitude spectrum and the lines its
/// orders excite; without the key it gets none.
#[test]
fn a_wavy_run_has_a_vibration_section() {
    let dir = temp_dir("wavy");
    synthetic_run(&dir, 0.0);
    let mut s = TimeSeries::default();
    s.channel("time_s", "s");
    s.channel("inner_ring_acceleration_z_m_s2", "m/s^2");
    s.channel("cage_speed_rpm", "rpm");
    let rate = 12_000.0;
    for k in 0..6000 {
        let t = k as f64 / rate;
        s.push(&[t, (std::f64::consts::TAU * 900.0 * t).sin(), 720.0]);
    }
    write_parquet(&dir.join("timeseries.parquet"), &s, &[]).unwrap();
    let mut summary = with_speeds(
        &dir,
        serde_json::json!({
            "averaging_window_s": [0.25, 0.5],
            "inner_ring_speed_rpm": 1772.0,
            "mean_cage_speed_rpm": 705.8,
            "envelope_lines": null,
            "waviness_lines": {"channel": "inner_ring_acceleration_z_m_s2", "resolution_hz": 4.0,
                "lines": [{"part": "outer_race", "order": 8, "frequency_hz": 900.0,
                    "motion": "radial", "amplitude_m_s2": 1.0}]}
        }),
    );
    let html = report_for(&dir, None).unwrap().to_html();
    let (sections, _) = check_page(&html);
    assert!(sections.contains(&"vibration".to_string()), "{sections:?}");
    assert!(html.contains("Vibration: the waviness signature"));
    assert!(
        html.contains("<td>outer race</td><td>8</td><td>900</td><td>radial</td>"),
        "the lines' table"
    );
    assert!(!html.contains("Envelope spectrum"));
    summary["waviness_lines"] = serde_json::Value::Null;
    std::fs::write(dir.join("summary.json"), summary.to_string()).unwrap();
    let html = report_for(&dir, None).unwrap().to_html();
    assert!(!check_page(&html).0.contains(&"vibration".to_string()));
}

/// A run whose shaft speed changes gets the run-up spectrogram: a heat map
/// of the whole record with the shaft, cage, BPFO and BPFI orders drawn
/// over it; a run at constant speed does not.
#[test]
fn a_speed_ramp_has_a_spectrogram() {
    let dir = temp_dir("ramp");
    synthetic_run(&dir, 0.0);
    // 600 → 1800 rpm in 1 s (or 1800 rpm throughout); the acceleration
    // rings at BPFO (order 3.6).
    let series = |ramp: bool| {
        let mut s = TimeSeries::default();
        s.channel("time_s", "s");
        s.channel("inner_ring_speed_rpm", "rpm");
        s.channel("inner_ring_acceleration_z_m_s2", "m/s^2");
        let rate = 8_000.0;
        let mut phase = 0.0;
        for k in 0..8000 {
            let t = k as f64 / rate;
            let rpm = if ramp { 600.0 + 1200.0 * t } else { 1800.0 };
            phase += std::f64::consts::TAU * 3.6 * rpm / 60.0 / rate;
            s.push(&[t, rpm, phase.sin()]);
        }
        s
    };
    let s = series(true);
    write_parquet(&dir.join("timeseries.parquet"), &s, &[]).unwrap();
    with_speeds(
        &dir,
        serde_json::json!({
            "averaging_window_s": [0.5, 1.0],
            "inner_ring_speed_rpm": 1800.0,
            "mean_cage_speed_rpm": 720.0,
        }),
    );
    let html = report_for(&dir, None).unwrap().to_html();
    let (sections, _) = check_page(&html);
    assert!(sections.contains(&"vibration".to_string()), "{sections:?}");
    assert!(html.contains("Vibration: the run-up spectrogram"));
    assert!(html.contains(r#"<g class="heat""#), "the heat map");
    for order in ["1× shaft", "cage", "BPFO", "BPFI"] {
        assert!(
            html.contains(&format!(r#"data-series="{order}""#)),
            "{order}"
        );
    }
    assert!(!html.contains("Envelope spectrum"), "no spall: no envelope");
    // At constant speed: no spectrogram, and so no vibration section.
    write_parquet(&dir.join("timeseries.parquet"), &series(false), &[]).unwrap();
    let html = report_for(&dir, None).unwrap().to_html();
    assert!(!check_page(&html).0.contains(&"vibration".to_string()));
    std::fs::remove_dir_all(&dir).ok();
}
