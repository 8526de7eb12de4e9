//! End-to-end tests of the report and sweep commands: `rolldyn report DIR`,
//! `rolldyn run --report` and dynamic sweeps `rolldyn run --sweep`
//! (parallel, deterministic whatever the thread count).

#![allow(clippy::unwrap_used)]

use crate::common;

use crate::common::{assert_ok, assert_refused, rolldyn, stderr, stdout, summary_of, temp_dir};
use serde_json::Value;

/// Sections of a report page, checked to be well-formed XML with inline
/// SVG plots only.
fn sections(html: &str) -> (Vec<String>, usize) {
    let doc = roxmltree::Document::parse_with_options(
        html,
        roxmltree::ParsingOptions {
            allow_dtd: true,
            ..Default::default()
        },
    )
    .expect("well-formed report");
    let ids = doc
        .descendants()
        .filter(|n| n.has_tag_name("section"))
        .map(|n| n.attribute("id").unwrap().to_string())
        .collect();
    let plots = doc.descendants().filter(|n| n.has_tag_name("svg")).count();
    assert!(!doc.descendants().any(|n| n.has_tag_name("script")));
    (ids, plots)
}

#[test]
fn run_report_shows_every_section() {
    let dir = temp_dir("run-report");
    let d = dir.to_str().unwrap();
    let o = rolldyn(&["run", "--duration", "2 ms", "--report", "-o", d], None);
    assert_ok(&o);
    assert!(stdout(&o).contains("report.html"));
    let html = std::fs::read_to_string(dir.join("report.html")).unwrap();
    let (ids, plots) = sections(&html);
    assert_eq!(
        ids,
        [
            "summary", "case", "solver", "cage", "contacts", "slip", "orbit", "energy", "power",
            "values"
        ]
    );
    // cage 1, contacts 3, slip 3, orbit 1, energy 2, power 1.
    assert_eq!(plots, 11);
    // The case is described as `rolldyn check` describes it.
    assert!(html.contains("Derived geometry"));
    assert!(html.contains("--set solver.duration=2 ms"));
    // `rolldyn report` rewrites the same page.
    std::fs::remove_file(dir.join("report.html")).unwrap();
    let o = rolldyn(&["report", d], None);
    assert_ok(&o);
    assert_eq!(
        std::fs::read_to_string(dir.join("report.html")).unwrap(),
        html
    );
}

/// A run whose cage centre is held (`cage.whirl = false`) has no orbit
/// section; long cells may wrap.
#[test]
fn report_leaves_out_what_a_run_has_not() {
    let dir = temp_dir("run-report-no-whirl");
    let d = dir.to_str().unwrap();
    let o = rolldyn(
        &[
            "run",
            "--duration",
            "2 ms",
            "--set",
            "cage.whirl=false",
            "--report",
            "-o",
            d,
        ],
        None,
    );
    assert_ok(&o);
    let html = std::fs::read_to_string(dir.join("report.html")).unwrap();
    let (ids, _) = sections(&html);
    assert!(!ids.contains(&"orbit".to_string()), "{ids:?}");
    assert!(ids.contains(&"values".to_string()));
    assert!(html.contains("overflow-wrap:anywhere"));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn report_of_a_directory_without_results_is_refused() {
    let dir = temp_dir("no-results");
    std::fs::create_dir_all(&dir).unwrap();
    let o = rolldyn(&["report", dir.to_str().unwrap()], None);
    assert_refused(&o, &["not a run or sweep directory"]);
    assert!(!dir.join("report.html").exists());
}

#[test]
fn quasistatic_sweep_report() {
    let dir = temp_dir("qs-sweep-report");
    let d = dir.to_str().unwrap();
    let o = rolldyn(
        &[
            "quasistatic",
            "--sweep",
            "speed=0rpm..10000rpm/3",
            "--sweep",
            "axial=100N,1kN",
            "-o",
            d,
        ],
        None,
    );
    assert_ok(&o);
    let o = rolldyn(&["report", d], None);
    assert_ok(&o);
    let html = std::fs::read_to_string(dir.join("report.html")).unwrap();
    let (ids, plots) = sections(&html);
    assert_eq!(ids, ["points", "quantities"]);
    assert!(plots >= 8, "{plots}");
    // The last sweep (axial) is the abscissa; one series per speed.
    assert!(html.contains("axial load F_x [N]</text>"));
    assert!(html.contains("data-series=\"inner-ring speed [rpm] = 5000\""));
}

/// Rows of a sweep without the wall time (the only value that may differ).
fn rows(dir: &std::path::Path) -> Vec<Value> {
    let text = std::fs::read_to_string(dir.join("sweep.json")).unwrap();
    let mut rows: Vec<Value> = serde_json::from_str(&text).unwrap();
    for r in &mut rows {
        r.as_object_mut().unwrap().remove("wall_time_s");
    }
    rows
}

#[test]
fn dynamic_sweep_is_deterministic_whatever_the_thread_count() {
    let serial = temp_dir("run-sweep-1");
    let parallel = temp_dir("run-sweep-2");
    let args = |dir: &str| {
        vec![
            "run".to_string(),
            "--duration".into(),
            "1 ms".into(),
            "--sweep".into(),
            "speed=6000rpm,10000rpm".into(),
            "--sweep".into(),
            "axial=150N,250N".into(),
            "--report".into(),
            "-o".into(),
            dir.to_string(),
        ]
    };
    for (dir, threads) in [(&serial, "1"), (&parallel, "2")] {
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_rolldyn"))
            .args(args(dir.to_str().unwrap()))
            .env("RAYON_NUM_THREADS", threads)
            .output()
            .unwrap();
        assert_ok(&o);
        assert!(
            stdout(&o).contains("4 of 4 runs completed"),
            "{}",
            stdout(&o)
        );
    }
    let (a, b) = (rows(&serial), rows(&parallel));
    assert_eq!(a, b);
    // Grid order, first sweep outermost; the inputs are the case's.
    let inputs: Vec<(f64, f64)> = a
        .iter()
        .map(|r| {
            (
                r["speed_rpm"].as_f64().unwrap(),
                r["force_x_n"].as_f64().unwrap(),
            )
        })
        .collect();
    let expected = [
        (6000.0, 150.0),
        (6000.0, 250.0),
        (10000.0, 150.0),
        (10000.0, 250.0),
    ];
    for ((speed, axial), (s, f)) in inputs.iter().zip(expected) {
        assert!((speed - s).abs() < 1e-9 * s && *axial == f, "{inputs:?}");
    }
    for (k, r) in a.iter().enumerate() {
        assert_eq!(r["status"], "completed");
        assert_eq!(r["point"], format!("point-{k:04}"));
        // Each point is a run directory of its own, resumable and reported.
        let point = serial.join(format!("point-{k:04}"));
        let summary: Value = summary_of(&point);
        assert_eq!(summary["mean_cage_speed_rpm"], r["mean_cage_speed_rpm"]);
        assert!(point.join("run.json").is_file() && point.join("report.html").is_file());
        // The same time series from one thread or two.
        let other = parallel.join(format!("point-{k:04}"));
        assert_eq!(common::series_bytes(&point), common::series_bytes(&other));
    }
    // The CSV has the same rows, inputs first.
    let csv = std::fs::read_to_string(serial.join("sweep.csv")).unwrap();
    assert!(csv.starts_with("point,speed_rpm,force_x_n,force_z_n,status,error,"));
    assert_eq!(csv.lines().count(), 5);
    let (ids, _) = sections(&std::fs::read_to_string(serial.join("report.html")).unwrap());
    assert_eq!(ids, ["points", "quantities"]);
}

/// A sweep over case keys (any `--set` key, an array entry by index): one
/// run per value, each labelled by its key's value in the tables, each
/// run with its value (the spall lengths differ in the point cases).
#[test]
fn dynamic_sweep_over_case_keys_labels_its_rows() {
    let dir = temp_dir("run-sweep-keys");
    let d = dir.to_string_lossy().into_owned();
    let case =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/cwru6205/case.toml");
    let o = rolldyn(
        &[
            "run",
            case.to_str().unwrap(),
            "--duration",
            "2 ms",
            "--sweep",
            "surface.outer.spall.0.length=0.18 mm,0.36 mm",
            "--sweep",
            "cage.pocket_friction=0.05,0.1",
            "-o",
            &d,
        ],
        None,
    );
    assert_ok(&o);
    let csv = std::fs::read_to_string(dir.join("sweep.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    assert_eq!(
        header[..7],
        [
            "point",
            "speed_rpm",
            "force_x_n",
            "force_z_n",
            "surface.outer.spall.0.length",
            "cage.pocket_friction",
            "status"
        ]
    );
    let rows: Vec<Value> =
        serde_json::from_str(&std::fs::read_to_string(dir.join("sweep.json")).unwrap()).unwrap();
    assert_eq!(rows.len(), 4);
    assert_eq!(rows[1]["surface.outer.spall.0.length"], "0.18 mm");
    assert_eq!(rows[1]["cage.pocket_friction"], "0.1");
    assert_eq!(rows[2]["surface.outer.spall.0.length"], "0.36 mm");
    for row in &rows {
        assert_eq!(row["status"], "completed", "{row}");
    }
    // Each point's record holds its override.
    let record = std::fs::read_to_string(dir.join("point-0002").join("run.json")).unwrap();
    assert!(
        record.contains("surface.outer.spall.0.length=0.36 mm"),
        "{record}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// `--sample N --seed S`: N runs at random points, each labelled with its
/// draws; the same seed gives the same points.
#[test]
fn sampled_sweep_is_seeded_and_labelled() {
    let labels = |name: &str| {
        let dir = temp_dir(name);
        let d = dir.to_string_lossy().into_owned();
        let o = rolldyn(
            &[
                "run",
                "--duration",
                "1 ms",
                "--sweep",
                "cage.pocket_friction=0.05..0.1",
                "--sweep",
                "radial=100N,200N",
                "--sample",
                "3",
                "--seed",
                "5",
                "-o",
                &d,
            ],
            None,
        );
        assert_ok(&o);
        let rows = rows(&dir);
        std::fs::remove_dir_all(&dir).ok();
        rows.iter()
            .map(|r| {
                let mu: f64 = r["cage.pocket_friction"].as_str().unwrap().parse().unwrap();
                assert!((0.05..=0.1).contains(&mu), "{r}");
                assert_eq!(r["status"], "completed");
                let radial = r["operating.force_z"].as_str().unwrap().to_string();
                assert!(radial == "100N" || radial == "200N", "{radial}");
                (mu.to_bits(), radial)
            })
            .collect::<Vec<_>>()
    };
    let first = labels("run-sample-a");
    assert_eq!(first.len(), 3);
    assert_eq!(first, labels("run-sample-b"));
}

#[test]
fn dynamic_sweep_input_errors() {
    let o = rolldyn(&["run", "--sweep", "temperature=1,2"], None);
    assert_refused(&o, &["unknown sweep variable"]);
    let o = rolldyn(
        &["run", "--sweep", "speed=1rpm,2rpm", "--resume", "x"],
        None,
    );
    assert_refused(&o, &["not with --sweep"]);
    let o = rolldyn(&["run", "--sweep", "speed=0rpm..1000rpm/2000"], None);
    assert_refused(&o, &["above the limit of 1000"]);
    // A bad point fails before any run starts.
    let dir = temp_dir("run-sweep-bad");
    let o = rolldyn(
        &[
            "run",
            "--sweep",
            "axial=100N,-1e12N",
            "-o",
            dir.to_str().unwrap(),
        ],
        None,
    );
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(!dir.exists());
}

/// The report fits a 1200 px page: rendered in headless Chromium (when
/// the machine has one; else skipped with a note), the page is no wider
/// than the window (long values wrap: the CWRU run's envelope lines, the
/// case's assumptions). The page holds no script; the test adds one that
/// writes the page's scroll width into its title.
#[test]
fn the_report_fits_the_page_in_a_browser() {
    let Some(browser) = ["chromium", "chromium-browser", "google-chrome"]
        .into_iter()
        .find(|b| {
            std::process::Command::new(b)
                .arg("--version")
                .output()
                .is_ok_and(|o| o.status.success())
        })
    else {
        eprintln!("no Chromium: the report is not rendered");
        return;
    };
    let dir = temp_dir("report-width");
    let case = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/cwru6205/case.toml"
    );
    let d = dir.to_str().unwrap();
    let o = rolldyn(
        &["run", case, "--duration", "0.05 s", "-o", d, "--report"],
        None,
    );
    assert_ok(&o);
    let html = std::fs::read_to_string(dir.join("report.html")).unwrap();
    let probe = html.replace(
        "</body>",
        "<script>document.title = String(document.documentElement.scrollWidth)</script></body>",
    );
    let page = dir.join("width.html");
    std::fs::write(&page, probe).unwrap();
    let o = std::process::Command::new(browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--window-size=1200,900",
            "--virtual-time-budget=2000",
            "--dump-dom",
        ])
        .arg(format!("file://{}", page.display()))
        .output()
        .unwrap();
    let dom = String::from_utf8_lossy(&o.stdout);
    let width: f64 = dom
        .split_once("<title>")
        .and_then(|(_, t)| t.split_once("</title>"))
        .and_then(|(w, _)| w.trim().parse().ok())
        .unwrap_or_else(|| panic!("no width in the page: {:.300}", dom));
    assert!(width <= 1200.0, "the report is {width} px wide");
    std::fs::remove_dir_all(&dir).ok();
}
