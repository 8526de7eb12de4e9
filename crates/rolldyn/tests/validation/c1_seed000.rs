//! C1 (Shan et al. 2023 Fig. 6 and §3): SKF 6304 (Table 1), 8000 rpm, clearance
//! c = 0.005 mm, dry friction, L–N contact, planar. Measured cage speed
//! ≈ 2940 rpm for W ≥ 70–100 N; the paper's simulation deviates from the
//! measurement by at most 4.24 %.
//!
//! Shan et al. 2023 does not print its friction coefficient, v₀/v₁, restitution,
//! ring, shaft or cage mass. Assumed here (and in docs/validation.md):
//! μ = 0.1, v₀ = 0, v₁ = 10 mm/s, e = 0.9, inner ring + shaft 0.5 kg, cage
//! 5 g (J_c = 8.2e-7 kg·m² from Table 1), pocket clearance 0.2 mm,
//! pocket stiffness 1e7 N/m with damping, gravity on.
//!
//! The cage turns but does not whirl (Shan et al. 2023 models cage rotation only;
//! rolldyn's cylindrical pockets give a free-whirling cage no radial
//! guidance, and without guide lands it drifts: docs/validation.md).
//! Balls and cage start **at rest**, so friction must bring the cage up to
//! speed: at W = 100 N the 60–100 ms mean is checked against 2940 rpm with
//! the paper's 4.24 %, and at W = 0 (only the ring and shaft weight, 4.9 N)
//! the cage must be markedly slower (sliding).

use super::common::{METHODS, Method, bearing_6304, dynamics_6304, integrator, steel_shan_2023};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::{BearingModel, DynamicsParameters, PocketShape};
use rolldyn::integrate::Integrator;

const RPM: f64 = std::f64::consts::TAU / 60.0;

/// Mean cage speed \[rpm\] over the last `window` s of `t_end` s, started
/// at rest (`from_rest`) or at pure rolling, with the cage whirl locked.
fn cage_speed(load: f64, t_end: f64, window: f64, from_rest: bool) -> (f64, u64) {
    cage_speed_with(Method::Dopri5, load, t_end, window, from_rest)
}

/// [`cage_speed`] with the given integrator.
fn cage_speed_with(
    method: Method,
    load: f64,
    t_end: f64,
    window: f64,
    from_rest: bool,
) -> (f64, u64) {
    let (speed, steps, _) = run(method, load, t_end, window, from_rest, |p| {
        p.cage.whirl = false
    });
    (speed, steps)
}

/// As [`cage_speed`] for any configuration; also the largest cage-centre
/// eccentricity over the window \[m\].
fn run(
    method: Method,
    load: f64,
    t_end: f64,
    window: f64,
    from_rest: bool,
    configure: impl Fn(&mut DynamicsParameters),
) -> (f64, u64, f64) {
    let g = bearing_6304();
    let steel = steel_shan_2023();
    let mut params = dynamics_6304(-load);
    configure(&mut params);
    let mut model =
        BearingModel::new(&g, &steel, &steel, HertzModel::HertzCircular, params).unwrap();
    let mut y0 = model.pure_rolling_state([0.0; 5]);
    let l = model.layout();
    if from_rest {
        for j in 0..l.balls {
            y0[l.ball(j) + 5] = 0.0;
            y0[l.ball(j) + 6] = 0.0;
        }
        y0[l.cage() + 5] = 0.0;
    }
    let mut rk = integrator(method, &model, &y0, 1e-6, 1e-5);
    let cage = l.cage();
    let mut angle_start = None;
    let mut eccentricity = 0.0f64;
    while rk.t() < t_end {
        rk.step(&mut model, t_end).unwrap();
        if angle_start.is_none() && rk.t() >= t_end - window {
            angle_start = Some((rk.t(), rk.y()[cage + 2]));
        }
        if angle_start.is_some() {
            eccentricity = eccentricity.max(rk.y()[cage].hypot(rk.y()[cage + 1]));
        }
    }
    let (t0, a0) = angle_start.unwrap();
    (
        (rk.y()[cage + 2] - a0) / (rk.t() - t0) / RPM,
        rk.stats().steps,
        eccentricity,
    )
}

/// A ball-guided cage: with **spherical** pockets the balls hold the cage
/// radially, so the whirl may be free (no guide land): at W = 100 N the
/// cage speed meets C1's criterion as with the rotation-only cage, and the
/// cage centre stays within the pocket clearance (C_p/2 = 0.1 mm, plus the
/// ball excursions of the clearance c = 5 µm). Cylindrical pockets let the
/// same cage drift (docs/validation.md).
///
/// The pockets are frictionless here: with μ = 0.1 the system has a second
/// attractor, **dry whip** (the cage rolls around the balls at e ≈ 160 µm,
/// pressing 60 µm into the pockets, cage speed −4.4 %), and whether a run
/// reaches it depends on round-off (rtol 1.0e-6 and 1.1e-6 differ).
/// Without pocket friction nothing drives the whip; tolerances 3e-7…1.1e-6
/// all stay centred (2929–2950 rpm, e ≤ 101 µm).
#[test]
fn c1_ball_guided_cage_with_spherical_pockets() {
    let (speed, _, eccentricity) = run(Method::Dopri5, 100.0, 0.1, 0.04, true, |p| {
        p.cage.whirl = true;
        p.cage.pocket_shape = PocketShape::Spherical;
        p.cage.pocket_friction.friction = 0.0;
    });
    eprintln!(
        "C1, whirling cage in spherical pockets: {speed:.1} rpm, max eccentricity {:.1} µm",
        eccentricity * 1e6
    );
    assert!(((speed - 2940.0) / 2940.0).abs() < 0.0424, "{speed} rpm");
    assert!(eccentricity < 0.12e-3, "cage drifted: e = {eccentricity} m");
}

/// C1 with both integrators; they also agree with each other on the
/// loaded cage speed to 0.2 % (the 40 ms mean of a cage that settles from
/// rest through impacts; its run-to-run scatter at rtol 1e-6 is ~0.1 %).
#[test]
fn c1_cage_speed_and_low_load_sliding() {
    let mut loaded_by_method = Vec::new();
    for method in METHODS {
        let (loaded, steps) = cage_speed_with(method, 100.0, 0.1, 0.04, true);
        let (unloaded, _) = cage_speed_with(method, 0.0, 0.1, 0.04, true);
        eprintln!(
            "C1 from rest ({method:?}, {steps} steps): W = 100 N → {loaded:.1} rpm (measured ≈ 2940), W = 0 → {unloaded:.1} rpm"
        );
        assert!(
            ((loaded - 2940.0) / 2940.0).abs() < 0.0424,
            "{method:?}, W = 100 N: {loaded} rpm"
        );
        assert!(
            unloaded < 0.9 * loaded,
            "{method:?}: low load must slide: {unloaded} vs {loaded} rpm"
        );
        loaded_by_method.push(loaded);
    }
    let (explicit, stiff) = (loaded_by_method[0], loaded_by_method[1]);
    assert!(
        ((stiff - explicit) / explicit).abs() < 2e-3,
        "ros34pw2 {stiff} rpm vs dopri5 {explicit} rpm"
    );
}

#[test]
#[ignore = "report (no assertion): cargo test --release -p rolldyn --test validation c1 -- --ignored --nocapture"]
fn c1_report() {
    for load in [0.0, 10.0, 30.0, 70.0, 100.0, 300.0, 1000.0, 1500.0] {
        let (rest, _) = cage_speed(load, 0.1, 0.04, true);
        let (rolling, _) = cage_speed(load, 0.1, 0.04, false);
        eprintln!(
            "C1 W = {load:>6} N: cage from rest {rest:7.1} rpm, from pure rolling {rolling:7.1} rpm (60–100 ms mean)"
        );
    }
}
