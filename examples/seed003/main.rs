//! Zhang et al. 2020 (ceramic ball bearing with starved
//! lubrication), §3, quasi-static part: the ceramic 45×75 preset (Si3N4
//! balls, assumed ISO VG 32 oil) at 15 000 rpm under F_z = 10, 20, 30 N
//! with the inlet distance ratio L = 1.1 … 1.9 and fully flooded: for the
//! most loaded ball's inner contact, the critical ratio L* (Zhang et al. 2020
//! eq 29), the flooded and starved central films (eq 30), the starvation
//! factor, the oil-film stiffness K_oil (eq 37), the Hertz stiffness
//! dQ/dδ and the two in series.
//!
//! With assumed surfaces, that contact's film parameter Λ = h_min/σ and
//! its asperity share φ (mixed lubrication, docs/model.md §3 model 5).
//!
//! Then, with the film in the normal approach (docs/model.md §4; Zhang et al. 2020 eqs
//! 39–46): the equilibrium solved with each contact compressed by δ + h(Q),
//! the radial stiffness K_zz (the film's compliance in series with Hertz,
//! and its take-up of clearance), and the radial natural frequency
//! f_z = √(K_zz/M)/2π (Zhang et al. 2020 eq 46, which prints 0.5π for 1/2π) against
//! the dry bearing's. M is the inner-ring mass of the dynamic runs below
//! (the preset's estimate: a steel annulus from the bore to the inner
//! raceway, 16 mm wide; Zhang et al. 2020 gives no mass).
//!
//!
//! Last, the dynamic part ([`dynamic`]): the inner ring's vibration
//! velocity (RMS, largest, and the spectral peak frequency) from dynamic
//! runs with the film in the approach against L, dry and flooded, at an
//! assumed contact damping ratio (Zhang et al. 2020 gives none).
//!
//! `cargo run --release --example seed003 [-- OUT_DIR [static]]` (default
//! `examples/seed003/out`; about two minutes on two cores, the dynamic
//! runs; `static` leaves them out: the quasi-static tables alone, as the
//! test of the expected table compares them). See examples/seed003/README.md.

mod dynamic;

use rolldyn::lubrication;
use rolldyn::material::effective_modulus;
use rolldyn::quasistatic::films::equilibrium_films;
use rolldyn::quasistatic::{Conditions, QuasiStaticSolver, SolverOptions};
use rolldyn_case::{Override, load_case, presets};
use std::fmt::Write as _;
use std::path::PathBuf;

const RADIAL_LOADS: [f64; 3] = [10.0, 20.0, 30.0];
/// Composite roughness of the mixed-lubrication table \[m\]: assumed
/// (Zhang et al. 2020 gives none), steel raceways R_q 0.1 µm and Si3N4 balls 0.02 µm.
const MIXED_ROUGHNESS: f64 = 0.101_98e-6;
/// Mixed-lubrication parameters of that table: assumed typical values
/// (docs/lubrication.md), boundary friction 0.1.
const MIXED: rolldyn::traction::mixed::MixedLubrication =
    rolldyn::traction::mixed::MixedLubrication {
        boundary: rolldyn::traction::ModifiedCoulomb {
            friction: 0.1,
            stick_speed: 0.0,
            full_speed: 1e-3,
        },
        sigma_beta_eta: 0.04,
        sigma_over_beta: 1e-3,
    };
/// Inlet distance ratios of Zhang et al. 2020 §3, and ∞ (fully flooded).
const RATIOS: [f64; 6] = [1.1, 1.3, 1.5, 1.7, 1.9, f64::INFINITY];
/// The film-in-the-approach table adds ratios up to and past L* (8–12).
const APPROACH_RATIOS: [f64; 10] = [1.1, 1.3, 1.5, 1.7, 1.9, 3.0, 5.0, 8.0, 12.0, f64::INFINITY];

fn main() -> Result<(), String> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| {
        concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/seed003/out").into()
    }));
    let dynamic_runs = match std::env::args().nth(2).as_deref() {
        None => true,
        Some("static") => false,
        Some(other) => return Err(format!("{other}: expected \"static\" or nothing")),
    };
    std::fs::create_dir_all(&out).map_err(|e| format!("{}: {e}", out.display()))?;
    // Zhang et al. 2020's bearing alone: the preset without its mounting.
    let preset = presets::find("ceramic_45x75")
        .ok_or("no ceramic_45x75 preset")?
        .without_mounting();
    let mut table = String::from(
        "Zhang et al. 2020 §3: ceramic 45x75, 15 000 rpm, most loaded ball, inner contact\n\
         F_z [N]      L   Q_i [N]      L*  h_c flooded [µm]  h_c [µm]  factor  K_oil [N/m]  dQ/dδ [N/m]  series [N/m]\n",
    );
    let mut csv = String::from(
        "radial_load_n,inlet_distance_ratio,load_inner_n,critical_inlet_distance_ratio,flooded_central_film_m,central_film_m,starvation_factor,film_stiffness_n_per_m,contact_stiffness_n_per_m,series_stiffness_n_per_m\n",
    );
    // The inner-ring mass of the dynamic runs (the preset's estimate).
    let ring_mass = load_case("ceramic_45x75 preset", &preset, &[])
        .map_err(|e| e.to_string())?
        .dynamics_parameters()
        .map_err(|e| format!("{}: {}", e.key, e.rule))?
        .inner_ring_mass;
    let mut mixed = format!(
        "\nMixed lubrication (docs/model.md §3 model 5, assumed surfaces: σ = {:.3} µm, σβη = {}, σ/β = {}): film parameter and asperity share of the same contact\n\
         F_z [N]      L  h_min [µm]        Λ         φ\n",
        MIXED_ROUGHNESS * 1e6,
        MIXED.sigma_beta_eta,
        MIXED.sigma_over_beta
    );
    let mut approach = format!(
        "\nFilm in the normal approach (docs/model.md §4): radial stiffness K_zz and f_z = √(K_zz/M)/2π, M = {:.1} g (the preset's inner ring)\n\
         F_z [N]      L   loaded balls  max Q_i [N]  K_zz [N/m]  f_z [Hz]  dry K_zz [N/m]  dry f_z [Hz]\n",
        ring_mass * 1e3
    );
    let mut approach_csv = String::from(
        "radial_load_n,inlet_distance_ratio,loaded_balls,max_load_inner_n,radial_stiffness_n_per_m,radial_frequency_hz,dry_radial_stiffness_n_per_m,dry_radial_frequency_hz\n",
    );
    let mut tables = Tables {
        table: &mut table,
        csv: &mut csv,
        mixed: &mut mixed,
        approach: &mut approach,
        approach_csv: &mut approach_csv,
    };
    for fz in RADIAL_LOADS {
        load_rows(&preset, fz, ring_mass, &mut tables)?;
    }
    table.push_str(&mixed);
    table.push_str(&approach);
    let mut vibration_csv = String::new();
    if dynamic_runs {
        let jobs = dynamic::jobs(&RADIAL_LOADS, &RATIOS);
        let results = dynamic::run_all(&preset, &jobs);
        let vibration;
        (vibration, vibration_csv) = dynamic::tables(&results, &jobs);
        table.push_str(&vibration);
    }
    print!("{table}");
    std::fs::write(out.join("table.txt"), &table).map_err(|e| e.to_string())?;
    std::fs::write(out.join("films.csv"), &csv).map_err(|e| e.to_string())?;
    std::fs::write(out.join("approach.csv"), &approach_csv).map_err(|e| e.to_string())?;
    if dynamic_runs {
        std::fs::write(out.join("vibration.csv"), &vibration_csv).map_err(|e| e.to_string())?;
    }
    Ok(())
}

/// The tables' texts, filled load by load.
struct Tables<'a> {
    table: &'a mut String,
    csv: &'a mut String,
    mixed: &'a mut String,
    approach: &'a mut String,
    approach_csv: &'a mut String,
}

/// The rows of radial load `fz` \[N\]: the most loaded ball's inner
/// contact's film, its mixed lubrication, and the film in the approach
/// (tilts held) against the dry bearing.
fn load_rows(preset: &str, fz: f64, ring_mass: f64, tables: &mut Tables) -> Result<(), String> {
    let Tables {
        table,
        csv,
        mixed,
        approach,
        approach_csv,
    } = tables;
    let overrides = [Override::flag(
        "--radial-load",
        "operating.force_z",
        &format!("{fz} N"),
    )];
    let case = load_case("ceramic_45x75 preset", preset, &overrides).map_err(|e| e.to_string())?;
    let g = &case.bearing.geometry;
    let (ball, rings) = (
        &case.materials.ball.material,
        &case.materials.rings.material,
    );
    let solver = QuasiStaticSolver::new(g, ball, rings, case.contact_stiffness)
        .map_err(|e| e.to_string())?;
    let conditions = Conditions {
        loads: case.loads,
        inner_speed: case.speed.as_ref().map_or(0.0, |s| s.final_speed()),
        control: case.raceway_control,
    };
    let eq = solver
        .solve(&conditions, &SolverOptions::default())
        .map_err(|e| e.to_string())?;
    let j = (0..eq.balls.len())
        .max_by(|&a, &b| eq.balls[a].inner.load.total_cmp(&eq.balls[b].inner.load))
        .ok_or("no balls")?;
    let contact = eq.balls[j].inner;

    let hertz_stiffness = 1.5 * contact.load / contact.penetration;
    let inputs_at = |l: f64| dynamic::film_inputs(&case, l);
    for l in RATIOS {
        let inputs = inputs_at(l)?;
        let film = equilibrium_films(g, &eq, &inputs)[j].films[0];
        let series = lubrication::series_stiffness(hertz_stiffness, film.stiffness);
        let _ = writeln!(
            table,
            "{fz:>7.0} {:>6} {:>9.3} {:>7.3} {:>17.4} {:>9.4} {:>7.4} {:>12.4e} {:>12.4e} {:>13.4e}",
            ratio_label(l),
            contact.load,
            film.critical_ratio,
            film.flooded_central * 1e6,
            film.central * 1e6,
            film.starvation_factor,
            film.stiffness,
            hertz_stiffness,
            series
        );
        // Mixed lubrication (docs/model.md §3 model 5) with assumed surfaces.
        let lambda = film.minimum / MIXED_ROUGHNESS;
        let e = contact.hertz;
        let share = MIXED.asperity_share(
            lambda,
            contact.load / (std::f64::consts::PI * e.semi_major * e.semi_minor),
            effective_modulus(ball, rings),
        );
        let _ = writeln!(
            mixed,
            "{fz:>7.0} {:>6} {:>13.4} {lambda:>7.2} {share:>9.2e}",
            ratio_label(l),
            film.minimum * 1e6
        );
        let _ = writeln!(
            csv,
            "{fz},{l},{},{},{},{},{},{},{hertz_stiffness},{series}",
            contact.load,
            film.critical_ratio,
            film.flooded_central,
            film.central,
            film.starvation_factor,
            film.stiffness
        );
    }
    // The film in the approach, tilts held (Zhang et al. 2020's ring moves in
    // its radial plane only; under a pure radial load at 15 000 rpm the
    // free-tilt solution is not found with the film).
    let options = SolverOptions {
        prescribed_displacement: [None, None, None, Some(0.0), Some(0.0)],
        ..SolverOptions::default()
    };
    let frequency = |k: f64| (k / ring_mass).sqrt() / std::f64::consts::TAU;
    let dry = solver
        .solve(&conditions, &options)
        .map_err(|e| e.to_string())?;
    let dry_k = dry.stiffness[2][2];
    for l in APPROACH_RATIOS {
        let label = ratio_label(l);
        match solver.solve_with_films(&conditions, &options, &inputs_at(l)?) {
            Ok(wet) => {
                let k = wet.stiffness[2][2];
                let loaded = wet.balls.iter().filter(|b| b.inner.load > 0.0).count();
                let max_q = wet.balls.iter().map(|b| b.inner.load).fold(0.0, f64::max);
                let _ = writeln!(
                    approach,
                    "{fz:>7.0} {label:>6} {loaded:>13} {max_q:>12.3} {k:>11.4e} {:>9.1} {dry_k:>15.4e} {:>13.1}",
                    frequency(k),
                    frequency(dry_k)
                );
                let _ = writeln!(
                    approach_csv,
                    "{fz},{l},{loaded},{max_q},{k},{},{dry_k},{}",
                    frequency(k),
                    frequency(dry_k)
                );
            }
            Err(e) => {
                let _ = writeln!(approach, "{fz:>7.0} {label:>6}  no equilibrium: {e}");
            }
        }
    }
    Ok(())
}

/// L as the tables print it (∞: flooded).
fn ratio_label(l: f64) -> String {
    if l.is_finite() {
        format!("{l:.1}")
    } else {
        "∞".into()
    }
}
