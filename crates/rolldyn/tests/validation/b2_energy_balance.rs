//! B2: with dissipation on, drive work = Δ(mechanical energy) + dissipated
//! energy over a run, to 1e-3 relative or better (docs/model.md §10). The drive
//! work and the dissipation are integrated as states of the model, so the
//! balance closes to integrator accuracy.

use super::common::{
    METHODS, Method, bearing_6304, bearing_7008c, drag_7008c, dynamics_6304, dynamics_7008c,
    integrator, steel_shan_2023,
};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::{
    BearingModel, DynamicsParameters, OuterRing, PocketLaw, PocketShape, Support,
};
use rolldyn::integrate::Integrator;
use rolldyn::lubrication::PressureViscosity;
use rolldyn::material::Material;
use rolldyn::operating::{LoadProfile, Loads};
use rolldyn::traction::{SlipMeasure, TractionCurve, TractionModel};

/// Integrates `model` from `y0` to `t_end` with `method`; returns (drive,
/// ΔE, dissipated).
fn balance(
    method: Method,
    mut model: BearingModel,
    y0: &[f64],
    t_end: f64,
    rtol: f64,
) -> (f64, f64, f64) {
    let e0 = model.energy(0.0, y0).total();
    let mut rk = integrator(method, &model, y0, rtol, 1e-5);
    while rk.t() < t_end {
        rk.step(&mut model, t_end).unwrap();
    }
    let (drive, dissipated) = model.work(rk.y());
    (drive, model.energy(rk.t(), rk.y()).total() - e0, dissipated)
}

/// Shan et al. 2023's 6304 in planar mode with clearance (P_d = 20 µm), L–N
/// contact, modified Coulomb traction at the contact centres, damped
/// pockets with friction, gravity, radial load 100 N, 8000 rpm, balls and
/// cage started at rest: contacts open and close, balls skid and impact.
#[test]
fn b2_drive_work_balances_energy_and_dissipation() {
    b2_seed000(|_| {});
}

/// B2 with the other dissipative and external elements on the same run:
/// the traction curve (Lei et al. 2023 eq 18, slide-to-roll) instead of Coulomb,
/// hysteresis rolling resistance (α_h = 0.007), the outer ring on a damped
/// housing, a damped inner-ring support, spherical Hertz pockets with
/// damping and friction, a cage unbalance on a whirling cage, and a load
/// ramp 100 → 300 N over the run (its explicit time dependence is external
/// work).
#[test]
fn b2_balance_with_curve_hysteresis_housing_pockets_unbalance_and_load_ramp() {
    b2_seed000(|p| {
        p.traction = TractionModel::TractionCurve(TractionCurve {
            a: -0.06,
            b: 8.0,
            c: 60.0,
            d: 0.06,
            slip: SlipMeasure::SlideToRoll,
            full_speed: 1e-2,
        });
        p.rolling_hysteresis = 0.007;
        p.outer_ring = Some(OuterRing {
            mass: 0.2,
            housing: Support {
                stiffness: [0.0, 5e7, 5e7],
                damping: [0.0, 200.0, 200.0],
            },
        });
        p.inner_support = Support {
            stiffness: [0.0, 1e6, 1e6],
            damping: [0.0, 50.0, 50.0],
        };
        p.cage.pocket_shape = PocketShape::Spherical;
        p.cage.pocket_law = PocketLaw::Hertz {
            stiffness: 5e8,
            damping: 20.0,
        };
        p.cage.unbalance = 2e-6;
        let at = |fz: f64| Loads {
            force: [0.0, 0.0, fz],
            moment: [0.0; 2],
        };
        p.loads = LoadProfile::piecewise_linear(vec![(0.0, at(100.0)), (0.01, at(300.0))]).unwrap();
    });
}

/// B2 with Kalker's FASTSIM at the raceway contacts: its
/// dissipation is the power of the element forces on the rigid slip at
/// their points, so the balance closes as for the stress laws.
#[test]
fn b2_balance_with_fastsim() {
    b2_seed000(|p| {
        let steel = steel_shan_2023();
        let (g, nu) = rolldyn::traction::fastsim::combined_elastic_constants(&steel, &steel);
        p.traction = TractionModel::Fastsim(rolldyn::traction::Fastsim::new(0.1, g, nu));
    });
}

fn b2_seed000(configure: impl Fn(&mut DynamicsParameters)) {
    let g = bearing_6304();
    let mut params = dynamics_6304(100.0);
    params.inner_ring_mass = 0.1;
    params.inner_ring_tilt_inertia = 1e-5;
    configure(&mut params);
    let steel = steel_shan_2023();
    let model = BearingModel::new(&g, &steel, &steel, HertzModel::HertzCircular, params).unwrap();
    let mut y0 = model.pure_rolling_state([0.0; 5]);
    let l = model.layout();
    for j in 0..l.balls {
        y0[l.ball(j) + 5] = 0.0;
        y0[l.ball(j) + 6] = 0.0;
    }
    y0[l.cage() + 5] = 0.0;
    for method in METHODS {
        let (drive, delta, dissipated) = balance(method, model.clone(), &y0, 0.01, 1e-7);
        let imbalance = drive - delta - dissipated;
        eprintln!(
            "B2 ({method:?}): drive {drive:.6e} J, ΔE {delta:.6e} J, dissipated {dissipated:.6e} J, imbalance {:.1e} of the drive",
            (imbalance / drive).abs()
        );
        assert!(
            drive > 0.0 && dissipated > 0.0 && delta > 0.0,
            "the ring accelerates the balls and friction dissipates"
        );
        assert!(
            (imbalance / drive).abs() < 1e-3,
            "{method:?}: energy balance off by {imbalance} J"
        );
    }
}

/// B2 in 3-D with EHL traction (Roelands viscosity) integrated on the
/// ellipse grid (spin friction couples on balls and rings), hysteresis
/// rolling resistance and ball and cage drag on: 7008C,
/// 10 000 rpm, 200 N, 1 ms from the Jones–Harris state. Guards the traction
/// couple's reaction on the ring (missing it broke the balance by ~50 %)
/// and the drag power.
#[test]
fn b2_energy_balance_with_ehl_grid_traction() {
    let drag = drag_7008c();
    let (mut params, eq) = dynamics_7008c(drag);
    if let TractionModel::Ehl(ehl) = &mut params.traction {
        ehl.lubricant.pressure_model = PressureViscosity::Roelands;
    }
    params.rolling_hysteresis = 0.007;
    let steel = Material::STEEL_52100;
    let model =
        BearingModel::new(&bearing_7008c(), &steel, &steel, HertzModel::Exact, params).unwrap();
    let y0 = model.state_from_equilibrium(&eq);
    for method in METHODS {
        let (drive, delta, dissipated) = balance(method, model.clone(), &y0, 1e-3, 1e-6);
        let imbalance = drive - delta - dissipated;
        let scale = drive.abs().max(dissipated.abs());
        eprintln!(
            "B2 (3-D, EHL grid, drag, {method:?}): drive {drive:.4e} J, ΔE {delta:.4e} J, dissipated {dissipated:.4e} J, imbalance {:.1e} of the larger",
            imbalance / scale
        );
        assert!(dissipated > 0.0);
        assert!(
            (imbalance / scale).abs() < 1e-3,
            "{method:?}: imbalance {imbalance}"
        );
    }
}
