//! An inner ring held in tilt (`DynamicsParameters::inner_ring_tilt_held`,
//! the shaft's other bearing holding it; docs/dynamics.md, "Mounting"):
//! its tilts and tilt rates stay exactly zero, the constraint does no work
//! (drive work = Δ(mechanical energy) + dissipated energy, as B2), and the
//! ring still moves radially and axially under its loads.

use super::common::{METHODS, bearing_7008c, drag_7008c, dynamics_7008c, integrator};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::BearingModel;
use rolldyn::integrate::Integrator;
use rolldyn::material::Material;
use rolldyn::operating::{LoadProfile, Loads};
use rolldyn::quasistatic::{Conditions, QuasiStaticSolver, RacewayControl, SolverOptions};

/// The default case's 7008C with a 2 kg ring (ring and shaft share) under
/// F_x 200 N and F_z 150 N, its tilts held, from the quasi-static
/// solution with the tilts held: 1 ms with each method.
#[test]
fn a_held_tilt_stays_zero_and_does_no_work() {
    let (mut params, _) = dynamics_7008c(drag_7008c());
    let loads = Loads {
        force: [200.0, 0.0, 150.0],
        moment: [0.0; 2],
    };
    params.loads = LoadProfile::Constant(loads);
    params.inner_ring_mass = 2.0;
    params.inner_ring_tilt_held = true;
    let steel = Material::STEEL_52100;
    let g = bearing_7008c();
    let qs = QuasiStaticSolver::new(&g, &steel, &steel, HertzModel::Exact).unwrap();
    let held = SolverOptions {
        prescribed_displacement: [None, None, None, Some(0.0), Some(0.0)],
        ..Default::default()
    };
    let speed = 10_000.0 * std::f64::consts::TAU / 60.0;
    let eq = qs
        .solve(
            &Conditions {
                loads,
                inner_speed: speed,
                control: RacewayControl::Outer,
            },
            &held,
        )
        .unwrap();
    let model = BearingModel::new(&g, &steel, &steel, HertzModel::Exact, params).unwrap();
    let y0 = model.state_from_equilibrium(&eq);
    let r = model.layout().ring();
    for method in METHODS {
        let mut m = model.clone();
        let e0 = m.energy(0.0, &y0).total();
        let mut solver = integrator(method, &m, &y0, 1e-6, 1e-5);
        let mut largest_radial_speed: f64 = 0.0;
        while solver.t() < 1e-3 {
            solver.step(&mut m, 1e-3).unwrap();
            let y = solver.y();
            for k in [3, 4, 8, 9] {
                assert_eq!(y[r + k], 0.0, "{method:?}: ring state {k} moved");
            }
            largest_radial_speed = largest_radial_speed.max(y[r + 7].abs());
        }
        let y = solver.y();
        let (drive, dissipated) = m.work(y);
        let delta = m.energy(solver.t(), y).total() - e0;
        let imbalance = drive - delta - dissipated;
        let scale = drive.abs().max(dissipated.abs());
        eprintln!(
            "held tilt ({method:?}): drive {drive:.4e} J, ΔE {delta:.4e} J, dissipated {dissipated:.4e} J, imbalance {:.1e}; largest radial ring speed {largest_radial_speed:.2e} m/s",
            imbalance / scale
        );
        assert!(dissipated > 0.0);
        assert!(
            (imbalance / scale).abs() < 1e-3,
            "{method:?}: imbalance {imbalance}"
        );
        // The ring is free radially: it moves (it is not frozen).
        assert!(
            largest_radial_speed > 0.0,
            "{method:?}: the ring did not move"
        );
    }
}
