//! Cage guidance (docs/model.md §5): a whirling, outer-ring-guided cage under a
//! combined load stays inside its guide clearance, and the energy balance
//! (B2) still closes with the guide land's hydrodynamic power counted as
//! dissipation. 7008C default configuration (Deng et al. 2022 Table 1 cage: land
//! radius 28.665 mm, G 10.1 mm, C_g 0.35 mm diametral) with F_z = 100 N
//! added to F_x = 200 N, 2 ms from the Jones–Harris state (axial).

use super::common::{Method, bearing_7008c, dynamics_7008c, guide_land_7008c, integrator};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::{BearingModel, DragParameters};
use rolldyn::integrate::Integrator;
use rolldyn::material::Material;
use rolldyn::operating::{LoadProfile, Loads};

#[test]
fn guided_cage_stays_within_its_clearance() {
    let (mut params, eq) = dynamics_7008c(DragParameters::default());
    let clearance = 0.35e-3 / 2.0;
    let guide = guide_land_7008c();
    assert_eq!(guide.radial_clearance, clearance);
    params.cage.guide = Some(guide);
    params.loads = LoadProfile::Constant(Loads {
        force: [200.0, 0.0, 100.0],
        moment: [0.0; 2],
    });
    let steel = Material::STEEL_52100;
    let model =
        BearingModel::new(&bearing_7008c(), &steel, &steel, HertzModel::Exact, params).unwrap();
    // The stiff method at a looser tolerance (its third order makes 1e-6
    // slow here); the energy balance still closes to 1e-3.
    for (method, rtol) in [(Method::Dopri5, 1e-6), (Method::Ros34pw2, 1e-4)] {
        guided_run(method, rtol, model.clone(), &eq, clearance);
    }
}

fn guided_run(
    method: Method,
    relative_tolerance: f64,
    mut model: BearingModel,
    eq: &rolldyn::quasistatic::Equilibrium,
    clearance: f64,
) {
    let y0 = model.state_from_equilibrium(eq);
    let e0 = model.energy(0.0, &y0).total();
    let mut rk = integrator(method, &model, &y0, relative_tolerance, 1e-5);
    let c = model.layout().cage();
    let mut worst = 0.0f64;
    while rk.t() < 2e-3 {
        rk.step(&mut model, 2e-3).unwrap();
        worst = worst.max(rk.y()[c].hypot(rk.y()[c + 1]));
    }
    let (drive, dissipated) = model.work(rk.y());
    let delta = model.energy(rk.t(), rk.y()).total() - e0;
    let imbalance = (drive - delta - dissipated) / drive.abs().max(dissipated.abs());
    eprintln!(
        "guided cage ({method:?}): max eccentricity {:.3e} m (radial clearance {clearance:.3e} m), energy imbalance {imbalance:.1e}",
        worst
    );
    assert!(
        worst > 0.0 && worst < clearance,
        "{method:?}: cage left its guide clearance: {worst}"
    );
    assert!(
        imbalance.abs() < 1e-3,
        "{method:?}: energy balance {imbalance}"
    );
}
