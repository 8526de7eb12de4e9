//! C8, dynamic part (docs/model.md §10): the dissipated power split by
//! component sums to the energy balance's dissipated power, and the drive
//! torque times the ring speed is the drive power, at every step of a run
//! in which every dissipative element acts.
//!
//! 7008C default configuration (EHL traction on the 12 × 6 grid) with
//! hysteresis (α_h = 0.007), the EHL rolling resistance with inlet
//! heating, the churning of an oil bath at the lowest ball's centre, ball
//! and cage drag, an outer-ring guide land,
//! the outer ring on a damped housing, a damped inner-ring support and
//! F_z = 100 N added to F_x = 200 N; 1 ms from the Jones–Harris state with
//! balls started 2 % slow (the pockets push them). Tolerance: 1e-9 of the
//! total (the parts are summed in a different order than the total).

use super::common::{
    Method, bearing_7008c, drag_7008c, dynamics_7008c, guide_land_7008c, integrator,
    rolling_resistance_7008c,
};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::{BearingModel, OuterRing, Support};
use rolldyn::integrate::{Integrator, OdeSystem};
use rolldyn::lubrication::churning::{ANGULAR_CONTACT_TYPE_CONSTANT, Bath, Churning};
use rolldyn::material::Material;
use rolldyn::operating::{LoadProfile, Loads};

#[test]
fn c8_components_sum_to_the_dissipated_power_and_drive_torque_gives_drive_power() {
    let drag = drag_7008c();
    let (mut params, eq) = dynamics_7008c(drag);
    params.rolling_hysteresis = 0.007;
    let lubricant = *params.traction.lubricant().unwrap();
    params.rolling_resistance = Some(rolling_resistance_7008c(lubricant));
    params.churning = Some(Churning {
        bore: 40e-3,
        outside_diameter: 68e-3,
        ball_diameter: 7.938e-3,
        type_constant: ANGULAR_CONTACT_TYPE_CONSTANT,
        bath: Bath::Level(7e-3),
        viscosity: lubricant.viscosity,
        density: 860.0,
    });
    params.cage.guide = Some(guide_land_7008c());
    params.outer_ring = Some(OuterRing {
        mass: 0.2,
        housing: Support {
            stiffness: [0.0, 5e7, 5e7],
            damping: [0.0, 200.0, 200.0],
        },
    });
    params.inner_support = Support {
        stiffness: [0.0, 1e6, 1e6],
        damping: [0.0, 50.0, 50.0],
    };
    params.loads = LoadProfile::Constant(Loads {
        force: [200.0, 0.0, 100.0],
        moment: [0.0; 2],
    });
    let speed = match params.speed {
        rolldyn::operating::SpeedProfile::Constant(w) => w,
        _ => unreachable!("the default case runs at constant speed"),
    };
    let steel = Material::STEEL_52100;
    let mut model =
        BearingModel::new(&bearing_7008c(), &steel, &steel, HertzModel::Exact, params).unwrap();
    let mut y0 = model.state_from_equilibrium(&eq);
    let l = model.layout();
    for j in 0..l.balls {
        let b = l.ball(j);
        for k in 5..9 {
            y0[b + k] *= 0.98;
        }
    }
    let mut rk = integrator(Method::Dopri5, &model, &y0, 1e-6, 1e-5);
    let mut dy = vec![0.0; model.dimension()];
    let w = l.work();
    let (mut checked, mut seen) = (0, [0.0f64; 15]);
    while rk.t() < 1e-3 {
        rk.step(&mut model, 1e-3).unwrap();
        let p = model.rhs_with_power(rk.t(), rk.y(), &mut dy);
        let total = dy[w + 1];
        assert!(
            (p.total() - total).abs() <= 1e-9 * total.abs(),
            "t = {}: components {} W, dissipated power {total} W",
            rk.t(),
            p.total()
        );
        // A prescribed speed is held by the bearing's friction torque.
        assert_eq!(p.friction_torque, p.drive_torque);
        let drive_power = p.drive_torque * speed;
        assert!(
            (drive_power - dy[w]).abs() <= 1e-9 * dy[w].abs(),
            "t = {}: drive torque × ω {drive_power} W, drive power {} W",
            rk.t(),
            dy[w]
        );
        for (k, v) in [
            p.inner.rolling_sliding,
            p.inner.spin,
            p.inner.differential_sliding,
            p.inner.hysteresis,
            p.outer.spin,
            p.outer.hysteresis,
            p.pocket_friction,
            p.pocket_damping,
            p.guide_land,
            p.ball_drag,
            p.cage_drag,
            p.support_damping,
            p.inner.rolling_resistance,
            p.outer.rolling_resistance,
            p.churning,
        ]
        .into_iter()
        .enumerate()
        {
            seen[k] = seen[k].max(v.abs());
        }
        checked += 1;
    }
    eprintln!("C8 dynamic power: {checked} steps checked; largest |component| {seen:?} W");
    // The check is not vacuous: every element contributed.
    assert!(
        seen.iter().all(|&v| v > 0.0),
        "an element never acted: {seen:?}"
    );
}
