//! Linear stability of the 7218B's free inner ring under dry traction:
//! at which speed and friction its steady running turns into the whirl
//! docs/dynamics.md ("Dry traction at speed") describes.
//!
//! For each point of a speed sweep (at μ = 0.1) and of a friction sweep
//! (at 10 000 rpm): a run at constant speed to the
//! case's duration (5 ms), then the model's Jacobian averaged over one ball
//! pass (40 states), its eigenvalues ([`rolldyn::stability`]) and the
//! least stable oscillatory mode of the inner ring (its leading state the
//! ring's) between 100 Hz and 5 kHz: its growth rate, frequency, damping
//! ratio, whirl direction relative to the ring's rotation and leading state.
//! Modes led by the balls or the cage, and real eigenvalues, are not
//! reported. Last, at 10 000 rpm and μ = 0.1, the mode's growth rate split
//! over the states whose influence makes it, for all forces and for the
//! traction alone.
//!
//! `cargo run --release --example ring_stability [-- OUT_DIR [SPEEDS_RPM [FRICTIONS]]]`
//! (default `examples/ring_stability/out`, the speeds 1000…12 000 rpm and
//! the frictions 0.001…0.2 below; lists comma-separated). Writes
//! `OUT_DIR/table.txt` (also printed), which plot.py draws. See
//! examples/ring_stability/README.md.

use nalgebra::{Complex, DMatrix};
use rolldyn::integrate::OdeSystem;
use rolldyn::stability::{Eigenmode, averaged_jacobian, eigenmodes, growth_split};
use rolldyn_case::Case;
use rolldyn_case::simulation::Simulation;
use rolldyn_case::{Override, load_case};
use std::fmt::Write as _;
use std::path::PathBuf;

const SPEEDS_RPM: [f64; 10] = [
    1000.0, 2000.0, 3000.0, 4000.0, 5000.0, 6000.0, 7000.0, 8000.0, 10000.0, 12000.0,
];
const FRICTIONS: [f64; 8] = [0.001, 0.003, 0.01, 0.02, 0.03, 0.05, 0.1, 0.2];
/// States sampled over the ball pass.
const SAMPLES: usize = 40;
/// The band of the ring's modes on its contacts \[Hz\].
const BAND: (f64, f64) = (100.0, 5000.0);

/// The least stable mode of one operating point.
struct Point {
    speed_rpm: f64,
    friction: f64,
    mode: Eigenmode,
    whirl: &'static str,
    leading: String,
    /// The averaged Jacobian, the states it averages and the states' names
    /// and error scales.
    jac: DMatrix<f64>,
    states: Vec<(f64, Vec<f64>)>,
    names: Vec<String>,
    scale: Vec<f64>,
}

fn main() -> Result<(), String> {
    let mut args = std::env::args().skip(1);
    let here = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/ring_stability");
    let out = PathBuf::from(args.next().unwrap_or_else(|| format!("{here}/out")));
    let list = |arg: Option<String>, default: &[f64]| -> Result<Vec<f64>, String> {
        match arg {
            None => Ok(default.to_vec()),
            Some(text) => text
                .split(',')
                .map(|v| v.trim().parse().map_err(|e| format!("{v}: {e}")))
                .collect(),
        }
    };
    let speeds = list(args.next(), &SPEEDS_RPM)?;
    let frictions = list(args.next(), &FRICTIONS)?;
    let path = format!("{here}/case.toml");
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{path}: {e}"))?;

    let mut table = String::from(
        "# The free inner ring of examples/ring_stability/case.toml: the inner ring's least \
         stable mode of 100 Hz to 5 kHz of the model's Jacobian averaged over one ball pass, 5 ms into a \
         run at constant speed (rolldyn::stability)\n\
         # sweep | speed [rpm] | friction | growth rate [1/s] | frequency [Hz] | damping ratio | whirl | leading state\n",
    );
    let base_friction = 0.1;
    let base_speed = 10000.0;
    let mut points: Vec<(&str, f64, f64)> = speeds
        .iter()
        .map(|&n| ("speed", n, base_friction))
        .collect();
    points.extend(frictions.iter().map(|&mu| ("friction", base_speed, mu)));
    // The base point, analysed once for its row and its split.
    let mut base: Option<Point> = None;
    for (sweep, speed_rpm, friction) in points {
        let p = analyse(&path, &text, speed_rpm, friction)?;
        let line = format!(
            "{sweep:>8} | {:>6.0} | {:>5} | {:>9.1} | {:>7.1} | {:>8.4} | {} | {}",
            p.speed_rpm,
            p.friction,
            p.mode.growth_rate,
            p.mode.frequency,
            p.mode.damping_ratio,
            p.whirl,
            p.leading
        );
        println!("{line}");
        writeln!(table, "{line}").map_err(|e| e.to_string())?;
        if base.is_none() && speed_rpm == base_speed && friction == base_friction {
            base = Some(p);
        }
    }
    let base = match base {
        Some(p) => p,
        None => analyse(&path, &text, base_speed, base_friction)?,
    };
    split(&path, &text, &base, &mut table)?;
    std::fs::create_dir_all(&out).map_err(|e| format!("{}: {e}", out.display()))?;
    let file = out.join("table.txt");
    std::fs::write(&file, table).map_err(|e| format!("{}: {e}", file.display()))?;
    eprintln!("wrote {}", file.display());
    Ok(())
}

/// The reference friction whose model's Jacobian, taken from the base
/// point's, leaves the traction's part.
const NO_TRACTION: f64 = 0.001;

/// The growth rate of the base point's mode split over the states whose
/// influence makes it (`rolldyn::stability::growth_split`), for all forces
/// and for the traction (the Jacobian's difference from the same model's
/// at μ = 0.001, at the same states), appended to `table`.
fn split(path: &str, text: &str, p: &Point, table: &mut String) -> Result<(), String> {
    let (speed_rpm, friction) = (p.speed_rpm, p.friction);
    let low = Simulation::from_case(&case_at(path, text, speed_rpm, NO_TRACTION)?)
        .map_err(|e| e.to_string())?;
    let traction = &p.jac - averaged_jacobian(&low.model, &p.states);
    let all = growth_split(&p.jac, &p.jac, &p.mode, &p.scale);
    let part = growth_split(&p.jac, &traction, &p.mode, &p.scale);
    // Groups: a ball state by its name without the ball's number; a ring
    // state without its axis.
    let mut groups: Vec<(String, f64, f64)> = Vec::new();
    for (k, name) in p.names.iter().enumerate() {
        let group = match name.strip_prefix("ball ") {
            Some(rest) => format!("balls' {}", rest.split_once(' ').map_or(rest, |(_, s)| s)),
            None => without_axis(name),
        };
        match groups.iter_mut().find(|g| g.0 == group) {
            Some(g) => {
                g.1 += all[k];
                g.2 += part[k];
            }
            None => groups.push((group, all[k], part[k])),
        }
    }
    let _ = writeln!(
        table,
        "# the {speed_rpm} rpm, μ = {friction} mode's growth rate split over the states whose \
         influence makes it (rolldyn::stability::growth_split): split | state | all forces [1/s] | traction [1/s]"
    );
    for (group, a, t) in groups
        .iter()
        .filter(|g| g.1.abs() >= 1.0 || g.2.abs() >= 1.0)
    {
        let line = format!("   split | {group} | {a:>10.1} | {t:>8.1}");
        println!("{line}");
        let _ = writeln!(table, "{line}");
    }
    let (a, t): (f64, f64) = (all.iter().sum(), part.iter().sum());
    let line = format!("   split | sum | {a:>10.1} | {t:>8.1}");
    println!("{line}");
    let _ = writeln!(table, "{line}");
    Ok(())
}

/// A state's name without its trailing axis (`… θ̇_y`, `… velocity z`).
fn without_axis(name: &str) -> String {
    const AXES: [&str; 6] = ["y", "z", "θ_y", "θ_z", "θ̇_y", "θ̇_z"];
    match name.rsplit_once(' ') {
        Some((group, axis)) if AXES.contains(&axis) => group.to_string(),
        _ => name.to_string(),
    }
}

/// The case at `speed_rpm` and `friction`.
fn case_at(path: &str, text: &str, speed_rpm: f64, friction: f64) -> Result<Case, String> {
    let overrides = [
        format!("operating.speed=\"{speed_rpm} rpm\""),
        format!("model.traction={{ law = \"fastsim\", friction = {friction} }}"),
    ]
    .iter()
    .map(|s| Override::parse_set(s).map_err(|e| e.to_string()))
    .collect::<Result<Vec<_>, _>>()?;
    load_case(path, text, &overrides).map_err(|e| e.to_string())
}

/// Runs the case at `speed_rpm` and `friction` and linearizes it.
fn analyse(path: &str, text: &str, speed_rpm: f64, friction: f64) -> Result<Point, String> {
    let case = case_at(path, text, speed_rpm, friction)?;
    let at = case
        .duration
        .ok_or("the case states no duration (solver.duration)")?;
    let mut sim = Simulation::from_case(&case).map_err(|e| e.to_string())?;
    let names: Vec<String> = (0..sim.model.dimension())
        .map(|k| sim.model.state_name(k))
        .collect();
    let index = |name: &str| names.iter().position(|n| n == name);
    let cage_speed = index("cage speed").ok_or("the case's cage has no speed state")?;
    // The ball pass at the cage's speed at `at`.
    let mut speed_at = 0.0;
    sim.run(at, 1.0 / at, |_, t, y| {
        if t >= at * (1.0 - 1e-9) {
            speed_at = y[cage_speed];
        }
    })
    .map_err(|e| e.to_string())?;
    let pass = std::f64::consts::TAU / (case.bearing.geometry.ball_count as f64 * speed_at.abs());
    let mut states: Vec<(f64, Vec<f64>)> = Vec::with_capacity(SAMPLES);
    let mut sim = Simulation::from_case(&case).map_err(|e| e.to_string())?;
    sim.run(at + pass, SAMPLES as f64 / pass, |_, t, y| {
        if t >= at * (1.0 - 1e-9) && states.len() < SAMPLES {
            states.push((t, y.to_vec()));
        }
    })
    .map_err(|e| e.to_string())?;
    let jac = averaged_jacobian(&sim.model, &states);
    let mut scale = vec![1.0; names.len()];
    sim.model.error_scale(&mut scale);
    // The least stable mode in the band whose leading state is the
    // inner ring's (the energy accumulators integrate the others' power
    // and say nothing of the motion).
    let leading = |m: &Eigenmode| {
        m.shape
            .iter()
            .enumerate()
            .filter(|(k, _)| !names[*k].contains("accumulator"))
            .max_by(|a, b| a.1.norm().total_cmp(&b.1.norm()))
            .map(|(k, _)| names[k].clone())
            .unwrap_or_default()
    };
    let mode = eigenmodes(&jac, &scale)
        .into_iter()
        .find(|m| {
            m.frequency > BAND.0 && m.frequency < BAND.1 && leading(m).starts_with("inner ring")
        })
        .ok_or("no mode of the inner ring in the band")?;
    let whirl = whirl(&mode.shape, &index, speed_rpm);
    // Its name without the axis: a whirl's y and z lead alike.
    let leading = without_axis(&leading(&mode));
    Ok(Point {
        speed_rpm,
        friction,
        mode,
        whirl,
        leading,
        jac,
        states,
        names,
        scale,
    })
}

/// The whirl of the inner ring's tilt (or, where its centre leads, of its
/// centre) relative to its rotation about +x (`none` where neither leads
/// the mode). With e^{iωt}, u = y + iz turning forward is y + iz's
/// forward part |y + iz| against its backward part |y − iz| (z = −iy turns
/// from y to z, with the rotation); `planar` where neither dominates.
fn whirl(
    shape: &[Complex<f64>],
    index: &dyn Fn(&str) -> Option<usize>,
    speed_rpm: f64,
) -> &'static str {
    let pair = |y: &str, z: &str| Some((shape[index(y)?], shape[index(z)?]));
    let tilt = pair("inner ring tilt θ_y", "inner ring tilt θ_z");
    let centre = pair("inner ring position y", "inner ring position z");
    let (y, z) = match (tilt, centre) {
        (Some(t), Some(c)) if t.0.norm() + t.1.norm() >= c.0.norm() + c.1.norm() => t,
        (_, Some(c)) => c,
        (Some(t), None) => t,
        (None, None) => return "none",
    };
    // A mode of the ring's axial motion or of the balls moves neither.
    let largest = shape.iter().map(|c| c.norm()).fold(0.0, f64::max);
    if y.norm() + z.norm() < 0.3 * largest {
        return "none";
    }
    let i = Complex::new(0.0, 1.0);
    let (mut forward, mut backward) = ((y + i * z).norm(), (y - i * z).norm());
    if speed_rpm < 0.0 {
        std::mem::swap(&mut forward, &mut backward);
    }
    if forward > 2.0 * backward {
        "forward"
    } else if backward > 2.0 * forward {
        "backward"
    } else {
        "planar"
    }
}
