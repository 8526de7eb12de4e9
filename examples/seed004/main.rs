//! Lei et al. 2023 (under-race lubricated angular-contact
//! bearing), §5–6: the 30×62×16 preset (its oil, cage land and traction are
//! assumed: Lei et al. 2023 gives none) at F_a 3000 N, F_r 780 N, 9000 … 17 000 rpm.
//! For each speed: Harris's local power loss by component (inner and outer
//! raceway, cage, drag), and the coupled thermal steady state (viscosity
//! and operating clearance fed back), the outer-ring temperature next to
//! Lei et al. 2023 Table 2. Then the dynamic model's exact dissipation by
//! component at 9000 rpm (a 40 ms run from the Jones–Harris state) next to
//! the quasi-static estimate.
//!
//! `cargo run --release --example seed004 [-- OUT_DIR]` (default
//! `examples/seed004/out`; about 15 s). Writes `table.txt` (also printed)
//! and `power_temperature.csv`.

use rolldyn::integrate::{DEFAULT_ENERGY_TOLERANCE, Integrator, OdeSystem, ROS34PW2, Rosenbrock};
use rolldyn::thermal::coupled::{CoupledOptions, CoupledProblem, coupled_steady};
use rolldyn_case::{Override, load_case, presets, simulation};
use std::fmt::Write as _;
use std::path::PathBuf;

/// Lei et al. 2023 Table 2: speed [rpm], friction power of the inner and outer
/// ring [W], outer-ring temperature of the dynamics-based network and of
/// the finite-element model [°C].
const TABLE2: [(f64, f64, f64, f64, f64); 9] = [
    (9000.0, 33.38, 21.19, 58.18, 63.1),
    (10_000.0, 35.305, 23.65, 59.92, 64.5),
    (11_000.0, 39.3, 24.1, 63.02, 68.02),
    (12_000.0, 43.42, 27.65, 66.14, 71.0),
    (13_000.0, 46.57, 31.65, 69.38, 72.0),
    (14_000.0, 50.86, 34.505, 72.97, 77.1),
    (15_000.0, 57.23, 38.445, 76.34, 81.9),
    (16_000.0, 64.1, 40.125, 80.5, 85.0),
    (17_000.0, 69.34, 42.125, 85.09, 90.0),
];

fn case_at(rpm: f64) -> Result<rolldyn_case::Case, String> {
    let preset = presets::find("acbb_30x62").ok_or("no acbb_30x62 preset")?;
    let overrides = [
        Override::flag("--speed", "operating.speed", &format!("{rpm} rpm")),
        Override::parse_set("cage.pocket_squeeze_film=false").map_err(|e| e.to_string())?,
    ];
    // Lei et al. 2023's bearing alone: the preset without its mounting, and
    // its pockets without an oil film, as in the paper.
    load_case("acbb_30x62 preset", &preset.without_mounting(), &overrides)
        .map_err(|e| e.to_string())
}

fn main() -> Result<(), String> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| {
        concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/seed004/out").into()
    }));
    std::fs::create_dir_all(&out).map_err(|e| format!("{}: {e}", out.display()))?;
    let mut table = String::from(
        "Lei et al. 2023 §5-6: 30x62x16, F_a 3000 N, F_r 780 N; local method + coupled network\n\
         speed    inner W  outer W  spin W  hyst W  diff W  cage W   total W   T_outer °C | Table 2: inner W  outer W  T_outer °C (FE)\n",
    );
    let mut csv = String::from(
        "speed_rpm,inner_w,outer_w,spin_w,hysteresis_w,differential_sliding_w,cage_w,total_w,outer_ring_c,inner_ring_c,ball_c,oil_c,passes,paper_inner_w,paper_outer_w,paper_outer_ring_c,paper_fe_outer_ring_c\n",
    );
    for row in TABLE2 {
        coupled_row(row, &mut table, &mut csv)?;
    }
    dynamic_against_local(&mut table)?;
    print!("{table}");
    let write = |name: &str, text: &str| {
        std::fs::write(out.join(name), text).map_err(|e| format!("{name}: {e}"))
    };
    write("table.txt", &table)?;
    write("power_temperature.csv", &csv)?;
    Ok(())
}

/// One speed of Lei et al. 2023's Table 2: the local method's power by
/// component and the coupled network's temperatures, as a row of the
/// table and of the CSV file, beside the paper's values.
fn coupled_row(
    (rpm, p_in, p_out, t_paper, t_fe): (f64, f64, f64, f64, f64),
    table: &mut String,
    csv: &mut String,
) -> Result<(), String> {
    let case = case_at(rpm)?;
    let bad = |e: rolldyn_case::case::Invalid| format!("{}: {}", e.key, e.rule);
    let problem = CoupledProblem {
        geometry: &case.bearing.geometry,
        ball: &case.materials.ball.material,
        rings: &case.materials.rings.material,
        hertz: case.contact_stiffness,
        conditions: rolldyn::quasistatic::Conditions {
            loads: case.loads,
            inner_speed: rpm * std::f64::consts::TAU / 60.0,
            control: case.raceway_control,
        },
        options: case.solver_options(),
        power: case.local_method_inputs().map_err(bad)?,
        thermal: case.thermal_inputs().map_err(bad)?,
        viscosity: case.lubricant.as_ref().and_then(|l| l.viscosity_law),
        expansion: case.thermal.expansion,
    };
    let s = coupled_steady(&problem, &CoupledOptions::default()).map_err(|e| e.to_string())?;
    let p = &s.power;
    let c = |n: &str| s.thermal.temperature(n).unwrap_or(f64::NAN) - 273.15;
    let spin = p.inner.spin + p.outer.spin;
    let hyst = p.inner.hysteresis + p.outer.hysteresis;
    let diff = p.inner.differential_sliding + p.outer.differential_sliding;
    let cage = p.cage_land + p.ball_pocket + p.ball_drag + p.cage_drag;
    let _ = writeln!(
        table,
        "{rpm:>6.0} {:>9.2} {:>8.2} {spin:>7.2} {hyst:>7.2} {diff:>7.2} {cage:>6.2} {:>9.2} {:>10.2}   | {p_in:>15.2} {p_out:>8.2} {t_paper:>7.2} ({t_fe:.1})",
        p.inner.total(),
        p.outer.total(),
        p.total(),
        c("outer_ring"),
    );
    let _ = writeln!(
        csv,
        "{rpm},{},{},{spin},{hyst},{diff},{cage},{},{},{},{},{},{},{p_in},{p_out},{t_paper},{t_fe}",
        p.inner.total(),
        p.outer.total(),
        p.total(),
        c("outer_ring"),
        c("inner_ring"),
        c("ball"),
        c("oil"),
        s.history.len()
    );
    Ok(())
}

/// The dynamic model at 9000 rpm against the local method, power by
/// component (the dynamic model's exact dissipation, step-weighted over
/// its last 20 ms), appended to the table.
fn dynamic_against_local(table: &mut String) -> Result<(), String> {
    let case = case_at(9000.0)?;
    let params = case
        .dynamics_parameters()
        .map_err(|e| format!("{}: {}", e.key, e.rule))?;
    let g = &case.bearing.geometry;
    let mut model = simulation::model(&case, params).map_err(|e| e.to_string())?;
    let eq = simulation::QuasiStatic::from_case(&case)
        .and_then(|q| Ok(q.solve()?))
        .map_err(|e| e.to_string())?;
    let y0 = model.state_from_equilibrium(&eq);
    let mut rk = Rosenbrock::builder(&ROS34PW2)
        .relative_tolerance(1e-3)
        .max_step(1e-4)
        .energy_tolerance(Some(DEFAULT_ENERGY_TOLERANCE))
        .build(&model, &y0)
        .map_err(|e| e.to_string())?;
    let (t_end, window) = (0.04, 0.02);
    let mut dy = vec![0.0; model.dimension()];
    let mut mean = rolldyn::power::Dissipation::default();
    let mut weight = 0.0;
    while rk.t() < t_end {
        let t0 = rk.t();
        rk.step(&mut model, t_end).map_err(|e| e.to_string())?;
        if rk.t() > t_end - window {
            let h = rk.t() - t0;
            let p = model.rhs_with_power(rk.t(), rk.y(), &mut dy);
            mean.inner.add(&scaled(&p.inner, h));
            mean.outer.add(&scaled(&p.outer, h));
            mean.pocket_friction += h * p.pocket_friction;
            mean.pocket_damping += h * p.pocket_damping;
            mean.guide_land += h * p.guide_land;
            mean.ball_drag += h * p.ball_drag;
            mean.cage_drag += h * p.cage_drag;
            weight += h;
        }
    }
    let qs =
        rolldyn::power::local_power_loss(g, &eq, &case.local_method_inputs().map_err(|e| e.rule)?);
    let w = 1.0 / weight;
    let _ = writeln!(
        table,
        "\nDynamic model vs local method at 9000 rpm (dynamic: step-weighted mean over {:.0}-{:.0} ms)\n\
         component               dynamic W   local W",
        (t_end - window) * 1e3,
        t_end * 1e3
    );
    for (name, d, q) in [
        ("inner spin", mean.inner.spin * w, qs.inner.spin),
        ("outer spin", mean.outer.spin * w, qs.outer.spin),
        (
            "inner hysteresis",
            mean.inner.hysteresis * w,
            qs.inner.hysteresis,
        ),
        (
            "outer hysteresis",
            mean.outer.hysteresis * w,
            qs.outer.hysteresis,
        ),
        (
            "inner sliding+diff.",
            (mean.inner.rolling_sliding
                + mean.inner.transverse_sliding
                + mean.inner.differential_sliding)
                * w,
            qs.inner.differential_sliding,
        ),
        (
            "outer sliding+diff.",
            (mean.outer.rolling_sliding
                + mean.outer.transverse_sliding
                + mean.outer.differential_sliding)
                * w,
            qs.outer.differential_sliding,
        ),
        (
            "inner rolling res.",
            mean.inner.rolling_resistance * w,
            qs.inner.rolling_resistance,
        ),
        (
            "outer rolling res.",
            mean.outer.rolling_resistance * w,
            qs.outer.rolling_resistance,
        ),
        ("cage land", mean.guide_land * w, qs.cage_land),
        (
            "ball-pocket",
            (mean.pocket_friction + mean.pocket_damping) * w,
            qs.ball_pocket,
        ),
    ] {
        let _ = writeln!(table, "{name:<22} {d:>10.2} {q:>9.2}");
    }
    let _ = writeln!(
        table,
        "{:<22} {:>10.2} {:>9.2}",
        "total",
        mean.total() * w,
        qs.total()
    );
    Ok(())
}

fn scaled(c: &rolldyn::power::ContactLosses, h: f64) -> rolldyn::power::ContactLosses {
    rolldyn::power::ContactLosses {
        rolling_sliding: h * c.rolling_sliding,
        transverse_sliding: h * c.transverse_sliding,
        spin: h * c.spin,
        differential_sliding: h * c.differential_sliding,
        hysteresis: h * c.hysteresis,
        damping: h * c.damping,
        rolling_resistance: h * c.rolling_resistance,
    }
}
