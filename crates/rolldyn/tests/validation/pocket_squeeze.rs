//! The pocket oil film's squeeze damping (`cage::squeeze`, a rolldyn
//! extension of docs/model.md §5) in the dynamic model: its power is dissipation,
//! so the instantaneous balance P_drive − P_dissipated = dE/dt of
//! `b2_power_balance` still holds, and it is a large enough share of the
//! powers that leaving it out of either side would show.
//!
//! Case: the 7008C of `b2_power_balance` (EHL traction on the 12 × 6 grid,
//! drag, outer-ring guide land, F_x 200 N + F_z 100 N) with Deng et al. 2022's
//! `gupta_film` pockets (F_w 11 N; K_bc for a phenolic cage, 7 GPa) and
//! the squeeze film of the 7008C's oil (η₀ 0.0467 Pa·s, h_min 1 µm); the
//! cage displaced 20 µm, turned 0.05 mm (inside the 87.5 µm clearance: on
//! the films) and moving at 0.2 m/s, so every ball squeezes its pocket
//! film; 0.2 ms of motion. Cylindrical pockets with the half-Sommerfeld
//! film and with the vapour cut-off (the default), and spherical ones with
//! the cut-off.

use super::b2_power_balance::{power_residual, worst_power_residual};
use super::common::{bearing_7008c, drag_7008c, dynamics_7008c, guide_land_7008c};
use rolldyn::cage::pocket::hertz_pocket_stiffness;
use rolldyn::cage::{PocketLaw, PocketShape, PocketSqueeze, SqueezeCavitation};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::BearingModel;
use rolldyn::material::{Material, effective_modulus};
use rolldyn::operating::{LoadProfile, Loads};

fn model(shape: PocketShape, squeeze: Option<SqueezeCavitation>) -> BearingModel {
    let g = bearing_7008c();
    let (mut params, _) = dynamics_7008c(drag_7008c());
    params.cage.guide = Some(guide_land_7008c());
    params.loads = LoadProfile::Constant(Loads {
        force: [200.0, 0.0, 100.0],
        moment: [0.0; 2],
    });
    let phenolic = Material {
        elastic_modulus: 7e9,
        poisson_ratio: 0.3,
        density: 1400.0,
    };
    let steel = Material::STEEL_52100;
    params.cage.pocket_shape = shape;
    params.cage.pocket_law = PocketLaw::GuptaFilm {
        wall_force: 11.0,
        stiffness: hertz_pocket_stiffness(
            shape,
            g.ball_diameter,
            params.cage.pocket_clearance,
            effective_modulus(&steel, &phenolic),
        )
        .unwrap(),
        damping: 0.0,
    };
    params.cage.pocket_squeeze = squeeze.map(|cavitation| PocketSqueeze {
        viscosity: 0.0467,
        ball_radius: 0.5 * g.ball_diameter,
        min_film: 1e-6,
        cavitation,
        tension: rolldyn::cage::squeeze::DEFAULT_POCKET_TENSION,
    });
    BearingModel::new(&g, &steel, &steel, HertzModel::Exact, params).unwrap()
}

#[test]
fn squeeze_film_power_is_dissipation_and_the_balance_holds() {
    for film in [
        (PocketShape::Cylindrical, SqueezeCavitation::HalfSommerfeld),
        (PocketShape::Cylindrical, SqueezeCavitation::Vapour),
        (PocketShape::Spherical, SqueezeCavitation::Vapour),
    ] {
        balance_holds(film);
    }
}

fn balance_holds((shape, cavitation): (PocketShape, SqueezeCavitation)) {
    let mut squeezed = model(shape, Some(cavitation));
    let (_, eq) = dynamics_7008c(drag_7008c());
    let mut y0 = squeezed.state_from_equilibrium(&eq);
    let c = squeezed.layout().cage();
    y0[c] += 20e-6;
    y0[c + 1] -= 10e-6;
    y0[c + 2] += 0.05e-3 / 27e-3;
    y0[c + 3] = 0.2;

    // The squeeze film's share of the dissipated power at the start.
    let dissipated = |m: &BearingModel| {
        let mut f = vec![0.0; y0.len()];
        m.rhs_with_power(0.0, &y0, &mut f).total()
    };
    let dry = model(shape, None);
    let share = dissipated(&squeezed) - dissipated(&dry);
    let (_, scale, _) = power_residual(&squeezed, 0.0, &y0);
    eprintln!("{shape:?} {cavitation:?} squeeze film: {share:.4} W of {scale:.1} W");
    // 100 times the balance's tolerance below.
    assert!(
        share > 1e-3 * scale,
        "the squeeze film dissipates {share} W of {scale} W: too little to test the balance"
    );

    let worst = worst_power_residual(&mut squeezed, &y0);
    eprintln!("worst power residual with the squeeze film {worst:.2e} of the powers");
    // As in b2_power_balance (≤ 1.1e-6 there, the K_c(α) term); a squeeze
    // power missing from either side would give ≥ 1e-3 (the share above).
    assert!(worst < 1e-5, "worst power residual {worst:e} of the powers");
}
