//! Seed 003 (Zhang et al. 2020, ceramic ball bearing with starved
//! lubrication), §3, quasi-static part: the ceramic 45×75 preset (Si3N4
//! balls, assumed ISO VG 32 oil) at 15 000 rpm under F_z = 10, 20, 30 N
//! with the inlet distance ratio L = 1.1 … 1.9 and fully flooded: for the
//! most loaded ball's inner contact, the critical ratio L* (seed 003
//! eq 29), the flooded and starved central films (eq 30), the starvation
//! factor, the oil-film stiffness K_oil (eq 37), the Hertz stiffness
//! dQ/dδ and the two in series.
//!
//! `cargo run --release --example seed003 [-- OUT_DIR]` (default
//! `examples/seed003/out`). The dynamic part of seed 003 (vibration against
//! L) needs the film in the normal approach, which this release does not
//! have (docs/lubrication.md); see examples/seed003/README.md.

use rolldyn::RingKind;
use rolldyn::lubrication;
use rolldyn::material::effective_modulus;
use rolldyn::quasistatic::films::{FilmInputs, equilibrium_films};
use rolldyn::quasistatic::{Conditions, QuasiStaticSolver, SolverOptions};
use rolldyn_case::{Override, load_case, presets};
use std::fmt::Write as _;
use std::path::PathBuf;

const RADIAL_LOADS: [f64; 3] = [10.0, 20.0, 30.0];
/// Inlet distance ratios of seed 003 §3, and ∞ (fully flooded).
const RATIOS: [f64; 6] = [1.1, 1.3, 1.5, 1.7, 1.9, f64::INFINITY];

fn main() -> Result<(), String> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| {
        concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/seed003/out").into()
    }));
    std::fs::create_dir_all(&out).map_err(|e| format!("{}: {e}", out.display()))?;
    let preset = presets::find("ceramic_45x75").ok_or("no ceramic_45x75 preset")?;
    let mut table = String::from(
        "Seed 003 §3: ceramic 45x75, 15 000 rpm, most loaded ball, inner contact\n\
         F_z [N]      L   Q_i [N]      L*  h_c flooded [µm]  h_c [µm]  factor  K_oil [N/m]  dQ/dδ [N/m]  series [N/m]\n",
    );
    let mut csv = String::from(
        "radial_load_n,inlet_distance_ratio,load_inner_n,critical_inlet_distance_ratio,flooded_central_film_m,central_film_m,starvation_factor,film_stiffness_n_per_m,contact_stiffness_n_per_m,series_stiffness_n_per_m\n",
    );
    for fz in RADIAL_LOADS {
        let overrides = [Override::flag(
            "--radial-load",
            "operating.force_z",
            &format!("{fz} N"),
        )];
        let case = load_case("ceramic_45x75 preset", preset.text, &overrides)
            .map_err(|e| e.to_string())?;
        let g = &case.bearing.geometry;
        let (ball, rings) = (
            &case.materials.ball.material,
            &case.materials.rings.material,
        );
        let solver = QuasiStaticSolver::new(g, ball, rings, case.contact_stiffness)
            .map_err(|e| e.to_string())?;
        let eq = solver
            .solve(
                &Conditions {
                    loads: case.loads,
                    inner_speed: case.speed.as_ref().map_or(0.0, |s| s.final_speed()),
                    control: case.raceway_control,
                },
                &SolverOptions::default(),
            )
            .map_err(|e| e.to_string())?;
        let lub = case
            .lubricant
            .as_ref()
            .ok_or("the preset has no [lubricant]")?;
        let j = (0..eq.balls.len())
            .max_by(|&a, &b| eq.balls[a].inner.load.total_cmp(&eq.balls[b].inner.load))
            .ok_or("no balls")?;
        let contact = eq.balls[j].inner;
        let hertz_stiffness = 1.5 * contact.load / contact.penetration;
        for l in RATIOS {
            let supply = if l.is_finite() {
                lubrication::Supply::InletDistance(l)
            } else {
                lubrication::Supply::Flooded
            };
            let inputs = FilmInputs {
                lubricant: lubrication::Lubricant {
                    viscosity: lub.viscosity,
                    pressure_viscosity: lub.pressure_viscosity,
                    pressure_model: lub.pressure_viscosity_model,
                },
                supply: [supply, supply],
                roughness: [case.surface.composite_roughness(RingKind::Inner), 0.0],
                effective_modulus: effective_modulus(ball, rings),
            };
            let film = equilibrium_films(g, &eq, &inputs)[j].films[0];
            let series = lubrication::series_stiffness(hertz_stiffness, film.stiffness);
            let _ = writeln!(
                table,
                "{fz:>7.0} {:>6} {:>9.3} {:>7.3} {:>17.4} {:>9.4} {:>7.4} {:>12.4e} {:>12.4e} {:>13.4e}",
                if l.is_finite() {
                    format!("{l:.1}")
                } else {
                    "∞".into()
                },
                contact.load,
                film.critical_ratio,
                film.flooded_central * 1e6,
                film.central * 1e6,
                film.starvation_factor,
                film.stiffness,
                hertz_stiffness,
                series
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
    }
    print!("{table}");
    std::fs::write(out.join("table.txt"), &table).map_err(|e| e.to_string())?;
    std::fs::write(out.join("films.csv"), &csv).map_err(|e| e.to_string())
}
