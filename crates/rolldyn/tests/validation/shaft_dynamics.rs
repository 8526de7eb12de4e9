//! Bearings on a rigid shaft in motion (`dynamics::shaft`, docs/systems.md,
//! "Dynamics"):
//!
//! * one bearing on a shaft of its inner ring's mass and inertia, loaded
//!   as the bearing, has the bearing's equations: the same derivatives and
//!   energy to rounding, whatever the states' order, and its block split
//!   composes to its right-hand side; so has a torque-driven one (the
//!   drive's work then the shaft's);
//! * a 7008C back-to-back pair with a 200 N position preload, started from
//!   its quasi-static state at 10 000 rpm, keeps the preload the
//!   quasi-static set gives (within the raceway-control bracket of one
//!   bearing, B6: the dynamics shares the gyroscopic friction between the
//!   contacts), both bearings alike, and closes its energy balance.

use super::common::{bearing_7008c, dynamics_7008c, rel};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::shaft::{ShaftBody, ShaftDynamics, Unbalance};
use rolldyn::dynamics::{BearingModel, DragParameters};
use rolldyn::integrate::{BlockSplit, Integrator, OdeSystem, ROS34PW2, Rosenbrock};
use rolldyn::material::Material;
use rolldyn::operating::{Loads, TorqueDrive};
use rolldyn::quasistatic::system::{
    MountedBearing, Orientation, SetKind, ShaftSystem, SystemConditions,
};
use rolldyn::quasistatic::{QuasiStaticSolver, RacewayControl, SolverOptions};

fn solver() -> QuasiStaticSolver {
    let steel = Material::STEEL_52100;
    QuasiStaticSolver::new(&bearing_7008c(), &steel, &steel, HertzModel::Exact).unwrap()
}

#[test]
fn one_bearing_on_a_shaft_is_the_bearing() {
    one_bearing_is_the_bearing(None);
}

#[test]
fn one_driven_bearing_on_a_driven_shaft_is_the_driven_bearing() {
    one_bearing_is_the_bearing(Some(TorqueDrive {
        inertia: 1e-3,
        torque: vec![(0.0, 0.3)],
    }));
}

/// The bearing's equations against the shaft's, with `drive` (None: the
/// speed prescribed).
fn one_bearing_is_the_bearing(drive: Option<TorqueDrive>) {
    let g = bearing_7008c();
    let steel = Material::STEEL_52100;
    let (mut params, eq) = dynamics_7008c(DragParameters::default());
    params.drive = drive.clone();
    let (mass, tilt) = (params.inner_ring_mass, params.inner_ring_tilt_inertia);
    let loads = params.loads.at(0.0);
    let model = BearingModel::new(&g, &steel, &steel, HertzModel::Exact, params).unwrap();
    let mount = MountedBearing {
        solver: solver(),
        position: 0.0,
        orientation: Orientation::Forward,
        axial_offset: 0.0,
        floating: false,
    };
    let system = ShaftDynamics::new(
        vec![(model.clone(), &mount)],
        ShaftBody {
            mass,
            tilt_inertia: tilt,
        },
        loads,
    )
    .unwrap();
    // The bearing's start with its ring moving and tilting.
    let mut y = model.state_from_equilibrium(&eq);
    let l = model.layout();
    let r = l.ring();
    y[r + 1] += 0.3e-6;
    y[r + 4] += 2e-5;
    y[r + 6] = 1e-3;
    y[r + 8] = 0.02;
    let mut ys = vec![0.0; system.dimension()];
    let n = l.ring();
    ys[..n].copy_from_slice(&y[..n]);
    let s = system.shaft();
    ys[n..s].copy_from_slice(&y[l.outer()..]);
    ys[s..s + 10].copy_from_slice(&y[r..r + 10]);
    // A driven shaft's angle and speed follow its work.
    ys[s + 11..].copy_from_slice(&y[l.spin()..l.outer()]);
    assert_eq!(system.dimension(), l.len() + 1);
    let mut back = vec![0.0; l.len()];
    system.bearing_state(0, &ys, &mut back);
    assert_eq!(back, y);
    let (mut dy, mut dys) = (vec![0.0; l.len()], vec![0.0; system.dimension()]);
    model.rhs(0.0, &y, &mut dy);
    system.rhs(0.0, &ys, &mut dys);
    let close = |a: &[f64], b: &[f64], what: &str| {
        let size = b.iter().fold(0.0f64, |m, v| m.max(v.abs())).max(1e-300);
        for (k, (x, e)) in a.iter().zip(b).enumerate() {
            assert!((x - e).abs() <= 1e-12 * size, "{what}[{k}]: {x} vs {e}");
        }
    };
    close(&dys[..n], &dy[..n], "balls");
    let w = l.work() - l.outer();
    close(&dys[n..n + w], &dy[l.outer()..l.work()], "outer ring, cage");
    close(&dys[n + w + 1..s], &dy[l.work() + 1..], "dissipation");
    close(&dys[s..s + 5], &dy[r..r + 5], "shaft velocity");
    close(
        &dys[s + 5..s + 10],
        &dy[r + 5..r + 10],
        "shaft acceleration",
    );
    close(&dys[s + 11..], &dy[l.spin()..l.outer()], "shaft rotation");
    // The drive's work is the shaft's; the bearing's only with a
    // prescribed speed.
    let drive_power = drive
        .as_ref()
        .map_or(0.0, |d| d.torque[0].1 * y[l.spin() + 1]);
    assert_eq!(dys[s + 10], drive_power, "no unbalance: the drive's work");
    let work = dys[s + 10] + dys[n + w];
    assert!(
        (work - dy[l.work()]).abs() <= 1e-12 * work.abs(),
        "{work} W"
    );
    let (a, b) = (
        system.energy_balance(0.0, &ys).unwrap(),
        model.energy_balance(0.0, &y).unwrap(),
    );
    assert!(rel(a.mechanical, b.mechanical) < 1e-12, "{a:?} vs {b:?}");
    assert_eq!(a.dissipated, b.dissipated);
    assert!(
        (a.work - b.work).abs() <= 1e-12 * a.work.abs(),
        "{a:?} vs {b:?}"
    );
    // The block split composes to the right-hand side.
    let layout = system.block_layout();
    let c = system.coupling_len();
    let (mut sum, mut coupling) = (vec![0.0; c], vec![0.0; c]);
    let mut split = vec![0.0; system.dimension()];
    let size = layout.block_size;
    for j in 0..layout.blocks {
        system.block_rhs(
            0.0,
            &ys,
            j,
            &mut split[j * size..(j + 1) * size],
            &mut coupling,
        );
        sum.iter_mut().zip(&coupling).for_each(|(s, v)| *s += v);
    }
    system.border_rhs(0.0, &ys, &sum, &mut split[layout.blocks * size..]);
    close(&split, &dys, "block split");
}

/// The 7008C back-to-back pair with a 200 N position preload (offset set
/// at rest), its operating point without external load at the default
/// case's speed (outer raceway control), and the default case's model.
pub(super) fn preloaded_pair() -> (ShaftSystem, SystemConditions, BearingModel) {
    let (params, _) = dynamics_7008c(DragParameters::default());
    let options = SolverOptions::default();
    let set = ShaftSystem::matched(&solver(), SetKind::BackToBack, 15e-3);
    let offset = set
        .offset_for_preload(200.0, 0.0, RacewayControl::Outer, &options)
        .unwrap();
    let conditions = SystemConditions {
        loads: Loads::default(),
        inner_speed: params.speed.speed_at(0.0),
        control: RacewayControl::Outer,
    };
    let steel = Material::STEEL_52100;
    let model =
        BearingModel::new(&bearing_7008c(), &steel, &steel, HertzModel::Exact, params).unwrap();
    (set.with_axial_offset(offset), conditions, model)
}

/// The pair's bearings on a 1 kg shaft (tilt inertia 2e-3 kg·m²)
/// without external load.
pub(super) fn pair_on_its_shaft(set: &ShaftSystem, model: &BearingModel) -> ShaftDynamics {
    ShaftDynamics::new(
        set.bearings.iter().map(|m| (model.clone(), m)).collect(),
        ShaftBody {
            mass: 1.0,
            tilt_inertia: 2e-3,
        },
        Loads::default(),
    )
    .unwrap()
}

#[test]
fn preloaded_pair_in_motion_keeps_its_quasi_static_preload() {
    let (set, conditions, model) = preloaded_pair();
    let speed = conditions.inner_speed;
    let options = SolverOptions::default();
    let eq = set.solve(&conditions, &options).unwrap();
    // The balls' axial push Σ Q_i sin α_i of bearing 0 under outer and
    // inner raceway control: the bracket of B6.
    let push = |eq: &rolldyn::quasistatic::system::SystemEquilibrium| {
        eq.bearings[0]
            .as_ref()
            .unwrap()
            .balls
            .iter()
            .map(|b| b.inner.load * b.inner.contact_angle.sin())
            .sum::<f64>()
    };
    let inner_control = set
        .solve(
            &SystemConditions {
                control: RacewayControl::Inner,
                ..conditions
            },
            &options,
        )
        .unwrap();
    let bracket = [push(&eq), push(&inner_control)];
    let preload = eq.bearings[0].as_ref().unwrap().reaction[0];
    let mut system = pair_on_its_shaft(&set, &model);
    let y0 = system.initial_state(&eq).unwrap();
    let mut rk = Rosenbrock::builder(&ROS34PW2)
        .relative_tolerance(1e-4)
        .max_step(1e-4)
        .build(&system, &y0)
        .unwrap();
    let (t_start, t_end, dt) = (2e-3, 5e-3, 1e-5);
    let l = model.layout();
    let mut own = vec![0.0; l.len()];
    let mut sample = vec![0.0; y0.len()];
    let mut contacts = vec![rolldyn::dynamics::ContactSample::default(); l.balls];
    let mut axial = [0.0; 2];
    let mut count = 0usize;
    let mut next = t_start;
    let start = system.energy_balance(0.0, &y0).unwrap();
    while rk.t() < t_end {
        rk.step(&mut system, t_end).unwrap();
        while next <= rk.t() {
            rk.interpolate(next, &mut sample);
            for (i, a) in axial.iter_mut().enumerate() {
                system.bearing_state(i, &sample, &mut own);
                system.bearing(i).contact_samples(next, &own, &mut contacts);
                // The balls' axial push on the inner ring: Σ Q_i sin α_i.
                *a += contacts
                    .iter()
                    .map(|c| c.inner.load * c.inner.angle.sin())
                    .sum::<f64>();
            }
            count += 1;
            next += dt;
        }
    }
    let mean = axial.map(|a| a / count as f64);
    let end = system.energy_balance(rk.t(), rk.y()).unwrap();
    let balance = (end.work - end.dissipated) - (end.mechanical - start.mechanical);
    eprintln!(
        "7008C pair at {:.0} rpm: quasi-static preload {preload:.2} N, Σ Q_i sin α_i {bracket:?} N (outer, inner control), dynamic {:.2} / {:.2} N; energy balance {balance:.3e} J of {:.3e} J dissipated; {} steps",
        speed * 60.0 / std::f64::consts::TAU,
        mean[0],
        mean[1],
        end.dissipated,
        rk.stats().steps
    );
    assert!(rel(mean[0], mean[1]) < 1e-3, "{mean:?}");
    let (lo, hi) = (bracket[0].min(bracket[1]), bracket[0].max(bracket[1]));
    assert!(
        lo <= mean[0] && mean[0] <= hi,
        "{mean:?} outside {bracket:?}"
    );
    assert!(balance.abs() < 1e-3 * end.dissipated, "{balance}");
}

/// A step's end evaluated once (`OdeSystem::rhs_at_end`): on the
/// preloaded pair after 1 ms in motion, one pass per bearing gives the
/// bits of the right-hand side and of the energy balance evaluated apart,
/// and an acceptance at that point that reads the pass's raceway records
/// records the same peak loads as one that evaluates the contacts, and
/// the same right-hand side after it.
#[test]
fn a_shared_end_pass_gives_the_separate_evaluations_bits() {
    let (set, conditions, model) = preloaded_pair();
    let eq = set.solve(&conditions, &SolverOptions::default()).unwrap();
    let mut system = pair_on_its_shaft(&set, &model);
    let y0 = system.initial_state(&eq).unwrap();
    let mut rk = Rosenbrock::builder(&ROS34PW2)
        .relative_tolerance(1e-4)
        .max_step(1e-4)
        .build(&system, &y0)
        .unwrap();
    while rk.t() < 1e-3 {
        rk.step(&mut system, 1e-3).unwrap();
    }
    let (t, y) = (rk.t(), rk.y().to_vec());
    for i in 0..2 {
        system.bearing(i).take_peak_loads();
    }
    let (mut shared, mut apart) = (system.clone(), system);
    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    let (mut dy_shared, mut dy_apart) = (vec![0.0; y.len()], vec![0.0; y.len()]);
    for balance in [false, true] {
        let end = shared.rhs_at_end(t, &y, &mut dy_shared, balance);
        apart.rhs(t, &y, &mut dy_apart);
        assert_eq!(bits(&dy_shared), bits(&dy_apart), "right-hand side");
        let expected = balance.then(|| apart.energy_balance(t, &y).unwrap());
        assert_eq!(
            end.map(|e| bits(&[e.work, e.dissipated, e.mechanical])),
            expected.map(|e| bits(&[e.work, e.dissipated, e.mechanical])),
            "energy balance"
        );
    }
    assert_eq!(shared.accept_step(t, &y), apart.accept_step(t, &y));
    for i in 0..2 {
        let peaks = shared.bearing(i).take_peak_loads();
        assert!(peaks[0] > 0.0 && peaks[1] > 0.0, "{peaks:?}");
        assert_eq!(peaks, apart.bearing(i).take_peak_loads(), "bearing {i}");
    }
    shared.rhs(t, &y, &mut dy_shared);
    apart.rhs(t, &y, &mut dy_apart);
    assert_eq!(bits(&dy_shared), bits(&dy_apart), "after the acceptance");
}

/// A rotating unbalance on the preloaded pair: the shaft's response at the
/// rotation frequency against the rigid rotor on the set's radial
/// stiffness, U ω² / (k − m ω²) (Den Hartog, *Mechanical Vibrations*,
/// §3.3; m the shaft's mass), the energy balance closed with the
/// unbalance's work. The set's radial stiffness k at speed depends on the
/// raceway-control hypothesis of the quasi-static solution (2.78·10⁸ N/m
/// outer, 3.21·10⁸ inner control): the dynamics, which shares the balls'
/// friction between both contacts, lies between (as its preload does), so
/// the orbit must lie between the two rigid rotors (a constant radial force
/// gives the same stiffness, 2.95·10⁸ N/m: the difference is the state,
/// not the rotation).
#[test]
fn unbalance_response_of_a_pair_is_the_rigid_rotor_on_the_set_stiffness() {
    let (set, conditions, model) = preloaded_pair();
    let speed = conditions.inner_speed;
    let options = SolverOptions::default();
    let eq = set.solve(&conditions, &options).unwrap();
    let mass = 1.0;
    let amount = 2e-5; // 20 g·mm
    let mut system = ShaftDynamics::new(
        set.bearings.iter().map(|m| (model.clone(), m)).collect(),
        ShaftBody {
            mass,
            tilt_inertia: 2e-3,
        },
        Loads::default(),
    )
    .unwrap()
    .with_unbalance(Unbalance {
        amount,
        position: 0.0,
    })
    .unwrap();
    let y0 = system.initial_state(&eq).unwrap();
    let mut rk = Rosenbrock::builder(&ROS34PW2)
        .relative_tolerance(1e-4)
        .max_step(2e-5)
        .build(&system, &y0)
        .unwrap();
    // Ten turns after two for the start's transient; the shaft's y against
    // cos ωt and sin ωt over whole turns.
    let turn = std::f64::consts::TAU / speed;
    let (t_start, t_end) = (2.0 * turn, 12.0 * turn);
    let samples = 2000;
    let dt = (t_end - t_start) / samples as f64;
    let s = system.shaft();
    let mut sample = vec![0.0; y0.len()];
    let (mut c, mut sn, mut next, mut k) = (0.0, 0.0, t_start, 0);
    let start = system.energy_balance(0.0, &y0).unwrap();
    while rk.t() < t_end {
        rk.step(&mut system, t_end).unwrap();
        while k < samples && next <= rk.t() {
            rk.interpolate(next, &mut sample);
            c += sample[s + 1] * (speed * next).cos();
            sn += sample[s + 1] * (speed * next).sin();
            k += 1;
            next = t_start + (k as f64 + 0.5) * dt;
        }
    }
    let amplitude = 2.0 * c.hypot(sn) / k as f64;
    let inner_control = set
        .solve(
            &SystemConditions {
                control: RacewayControl::Inner,
                ..conditions
            },
            &options,
        )
        .unwrap();
    let force = amount * speed * speed;
    let rotor = |k: f64| force / (k - mass * speed * speed);
    let (soft, stiff) = (
        rotor(eq.stiffness[1][1]),
        rotor(inner_control.stiffness[1][1]),
    );
    let end = system.energy_balance(rk.t(), rk.y()).unwrap();
    let balance = (end.work - end.dissipated) - (end.mechanical - start.mechanical);
    eprintln!(
        "unbalance {force:.2} N at {:.0} rpm: shaft orbit {:.4} µm; rigid rotors {:.4} µm (outer control) and {:.4} µm (inner control); energy balance {balance:.3e} J of {:.3e} J work",
        speed * 60.0 / std::f64::consts::TAU,
        amplitude * 1e6,
        soft * 1e6,
        stiff * 1e6,
        end.work
    );
    assert!(
        stiff < amplitude && amplitude < soft,
        "{amplitude} outside [{stiff}, {soft}]"
    );
    assert!(balance.abs() < 1e-3 * end.work.abs(), "{balance}");
}
