//! B1: with all dissipation off (Hertz law, no traction, no pocket damping
//! or friction, no drag), total energy (kinetic + Σ (2/5) K_c δ^{5/2} +
//! pocket springs + potential of the constant load) is conserved to
//! integrator tolerance, and the RK4 energy error shrinks at the method's
//! order when the step halves.
//!
//! Configuration: Shan et al. 2023's 6304 in planar mode (fixed contact angle, so
//! K_c is constant and the force is the exact gradient of the elastic
//! energy), with a preload (P_d = −20 µm, 5 µm per contact) so that every contact stays
//! closed and the motion is smooth, a constant radial load of 100 N on a
//! free inner ring, balls and cage launched at the pure-rolling speeds of
//! 8000 rpm.

use rolldyn::contact::HertzModel;
use rolldyn::dynamics::{
    BearingModel, CageParameters, DynamicsParameters, OuterRing, PocketLaw, PocketShape, Support,
};
use rolldyn::integrate::tableau::{DOPRI5, RK4};
use rolldyn::integrate::{ExplicitRk, Integrator, ROS34PW2, Rosenbrock, StepControl};
use rolldyn::material::Material;
use rolldyn::operating::{LoadProfile, Loads, SpeedProfile};
use rolldyn::traction::{ModifiedCoulomb, TractionIntegration};
use rolldyn::{BearingGeometry, Clearance, GeometrySpec};

fn model(configure: impl Fn(&mut DynamicsParameters)) -> BearingModel {
    let g = BearingGeometry::new(&GeometrySpec {
        ball_diameter: 9.52e-3,
        ball_count: 7,
        pitch_diameter: 36.01e-3,
        inner_groove_curvature: 0.52,
        outer_groove_curvature: 0.52,
        clearance: Clearance::Diametral(-20e-6),
        preload: true,
    })
    .unwrap();
    let steel = Material {
        elastic_modulus: 210e9,
        poisson_ratio: 0.3,
        density: 7800.0,
    };
    let cage = CageParameters {
        pocket_friction: ModifiedCoulomb {
            friction: 0.0,
            stick_speed: 0.0,
            full_speed: 1e-3,
        },
        ..CageParameters::new(
            0.01,
            8.2e-7,
            18.005e-3,
            2e-3,
            PocketLaw::Linear {
                stiffness: 1e6,
                damping: 0.0,
            },
        )
    };
    let mut params = DynamicsParameters {
        traction_integration: TractionIntegration::Centre,
        speed: SpeedProfile::Constant(8000.0 * std::f64::consts::TAU / 60.0),
        loads: LoadProfile::Constant(Loads {
            force: [0.0, 0.0, 100.0],
            moment: [0.0, 0.0],
        }),
        planar: true,
        ..DynamicsParameters::new(0.1, 1e-5, cage)
    };
    configure(&mut params);
    BearingModel::new(&g, &steel, &steel, HertzModel::Exact, params).unwrap()
}

fn energy_error(
    control: StepControl,
    t_end: f64,
    configure: impl Fn(&mut DynamicsParameters),
) -> (f64, f64, u64) {
    let mut m = model(configure);
    let y0 = m.pure_rolling_state([0.0; 5]);
    let e0 = m.energy(0.0, &y0);
    let mut rk = ExplicitRk::builder(if matches!(control, StepControl::Fixed { .. }) {
        &RK4
    } else {
        &DOPRI5
    })
    .control(control)
    .build(&m, &y0)
    .unwrap();
    let mut worst = 0.0f64;
    while rk.t() < t_end {
        rk.step(&mut m, t_end).unwrap();
        worst = worst.max((m.energy(rk.t(), rk.y()).total() - e0.total()).abs());
    }
    (worst / e0.kinetic, e0.kinetic, rk.stats().steps)
}

#[test]
fn b1_energy_conserved_without_dissipation() {
    let control = StepControl::Adaptive {
        relative_tolerance: 1e-8,
        max_step: 1e-5,
        initial_step: None,
    };
    // 20 ms: each ball passes the loaded zone ~6 times and its two contacts
    // see ~2000 cycles of the radial vibration.
    let (rel, ke, steps) = energy_error(control, 0.02, |_| {});
    eprintln!("B1 DOPRI5 rtol 1e-8: max |ΔE|/KE = {rel:.2e} over {steps} steps (KE {ke:.4} J)");
    assert!(rel < 1e-8, "energy drift {rel}");
}

/// B1 with the stiff ROS34PW2: its L-stable damping of unresolved
/// contact vibration is numerical dissipation, so the energy drift follows
/// the tolerance: below 1e-8 of the kinetic energy at rtol 1e-8 over 2 ms
/// (B1's criterion), and at least 10× smaller than at rtol 1e-6.
#[test]
fn b1_stiff_energy_drift_follows_the_tolerance() {
    let drift = |rtol: f64| {
        let mut m = model(|_| {});
        let y0 = m.pure_rolling_state([0.0; 5]);
        let e0 = m.energy(0.0, &y0);
        let mut r = Rosenbrock::builder(&ROS34PW2)
            .relative_tolerance(rtol)
            .max_step(1e-5)
            .build(&m, &y0)
            .unwrap();
        let mut worst = 0.0f64;
        while r.t() < 2e-3 {
            r.step(&mut m, 2e-3).unwrap();
            worst = worst.max((m.energy(r.t(), r.y()).total() - e0.total()).abs());
        }
        (worst / e0.kinetic, r.stats().steps)
    };
    let (loose, loose_steps) = drift(1e-6);
    let (tight, tight_steps) = drift(1e-8);
    eprintln!(
        "B1 ROS34PW2: max |ΔE|/KE = {loose:.2e} at rtol 1e-6 ({loose_steps} steps), {tight:.2e} at 1e-8 ({tight_steps} steps)"
    );
    assert!(tight < 1e-8, "energy drift {tight} at rtol 1e-8");
    assert!(loose / tight > 10.0, "drift {loose} → {tight}");
}

#[test]
fn b1_rk4_energy_error_at_fourth_order() {
    let (e1, _, _) = energy_error(StepControl::Fixed { step: 2e-7 }, 2e-3, |_| {});
    let (e2, _, _) = energy_error(StepControl::Fixed { step: 1e-7 }, 2e-3, |_| {});
    eprintln!(
        "B1 RK4: max |ΔE|/KE = {e1:.3e} (h = 0.2 µs), {e2:.3e} (h = 0.1 µs), ratio {:.1}",
        e1 / e2
    );
    // Local error O(h⁵) per step: the ratio is 2⁴ to 2⁵ over a short run.
    assert!((14.0..40.0).contains(&(e1 / e2)), "ratio {}", e1 / e2);
}

/// B1 with every other conservative element: the outer ring on an
/// undamped housing spring, an inner-ring support spring, spherical pockets
/// with the gupta_film law (film spring inside the clearance, Hertz
/// beyond), cage whirl on. The pockets' film spring acts on every ball.
#[test]
fn b1_energy_conserved_with_housing_supports_and_film_pockets() {
    let control = StepControl::Adaptive {
        relative_tolerance: 1e-8,
        max_step: 1e-5,
        initial_step: None,
    };
    let (rel, ke, steps) = energy_error(control, 0.005, |p| {
        p.outer_ring = Some(OuterRing {
            mass: 0.2,
            housing: Support {
                stiffness: [0.0, 2e7, 2e7],
                damping: [0.0; 3],
            },
        });
        p.inner_support = Support {
            stiffness: [0.0, 1e6, 1e6],
            damping: [0.0; 3],
        };
        p.cage.pocket_shape = PocketShape::Spherical;
        p.cage.pocket_law = PocketLaw::GuptaFilm {
            wall_force: 11.0,
            stiffness: 5e8,
            damping: 0.0,
        };
    });
    eprintln!(
        "B1 (housing, supports, film pockets): max |ΔE|/KE = {rel:.2e} over {steps} steps (KE {ke:.4} J)"
    );
    assert!(rel < 1e-8, "energy drift {rel}");
}
