//! C4 (Deng et al. 2022 Table 2) and localised defects: surface features excite the
//! rings at the frequencies the kinematics predicts.
//!
//! 7008C of Deng et al. 2022 (the default case's dynamic configuration:
//! 10 000 rpm, F_x = 200 N, EHL traction, whirling cage; `dynamics_7008c`),
//! from the Jones–Harris start. The inner-ring acceleration is recorded at
//! 20 kHz; the first 5 ms (start transient) are left out and 5–45 ms
//! analysed (bin 25 Hz).
//!
//! * C4: waviness of 0.3 µm on one part at a time; the largest peak of the
//!   inner-ring acceleration spectrum above 300 Hz in the predicted
//!   direction lies within one bin of the Table 2 line
//!   ([`rolldyn::kinematics::waviness_frequencies`], validated in A6–A8).
//! * Spalls (0.5 mm × 1.5 µm), with the outer ring on a housing whose
//!   resonance (5 kHz) the impulses ring, as on a test rig: the envelope
//!   spectrum (3–8 kHz) of the outer-ring acceleration peaks at BPFO for an
//!   outer-race spall; an inner-race spall under radial load shows BPFI
//!   with f_i sidebands, which the same spall under axial load alone
//!   lacks; a ball spall 2×BSF with f_c sidebands. Lines from
//!   the run's own mean cage speed
//!   ([`rolldyn::signal::CharacteristicFrequencies`]).
//! * Zero-amplitude raceway waviness reproduces the smooth run bit for bit;
//!   the energy balance (B2) closes with waviness and spalls; a spall
//!   shorter than the unconstrained step is still felt (the step limit).

use super::common::{bearing_7008c, dynamics_7008c};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::{
    BearingModel, ContactSample, DragParameters, DynamicsParameters, OuterRing, Support,
};
use rolldyn::integrate::{Integrator, OdeSystem, ROS34PW2, Rosenbrock, Solver, run};
use rolldyn::kinematics::{Frequencies, WavyPart, waviness_frequencies};
use rolldyn::material::Material;
use rolldyn::operating::{LoadProfile, Loads};
use rolldyn::signal::{
    CharacteristicFrequencies, Spectrum, Window, amplitude_spectrum, envelope_spectrum,
};
use rolldyn::surface::{
    BallSurface, Edge, RaceSurface, Spall, SpallSize, SurfaceModel, Waviness, WavinessTerm,
};
use std::sync::atomic::AtomicBool;

const SAMPLE_RATE: f64 = 20_000.0;
const SKIP: f64 = 5e-3;
const END: f64 = 45e-3;
const RPM: f64 = std::f64::consts::TAU / 60.0;

/// Inner-ring accelerations (x, y, z) and outer-ring accelerations (y, z)
/// from `SKIP` to `END`, and the mean cage speed \[rad/s\].
struct Record {
    acceleration: [Vec<f64>; 3],
    outer_acceleration: [Vec<f64>; 2],
    cage_speed: f64,
}

fn model(configure: impl Fn(&mut DynamicsParameters)) -> (BearingModel, Vec<f64>) {
    let (mut params, eq) = dynamics_7008c(DragParameters::default());
    configure(&mut params);
    let steel = Material::STEEL_52100;
    let model =
        BearingModel::new(&bearing_7008c(), &steel, &steel, HertzModel::Exact, params).unwrap();
    let y0 = model.state_from_equilibrium(&eq);
    (model, y0)
}

fn solver(model: &BearingModel, y0: &[f64], rtol: f64, max_step: f64) -> Solver {
    Solver::Rosenbrock(Box::new(
        Rosenbrock::builder(&ROS34PW2)
            .relative_tolerance(rtol)
            .max_step(max_step)
            .build(model, y0)
            .unwrap(),
    ))
}

/// Records a run at relative tolerance `rtol` and largest step `max_step`.
fn record(configure: impl Fn(&mut DynamicsParameters), rtol: f64, max_step: f64) -> Record {
    let (mut model, y0) = model(configure);
    let mut rk = solver(&model, &y0, rtol, max_step);
    let l = model.layout();
    let (r, o, c) = (l.ring(), l.outer(), l.cage());
    let mut dy = vec![0.0; y0.len()];
    let mut out = Record {
        acceleration: [Vec::new(), Vec::new(), Vec::new()],
        outer_acceleration: [Vec::new(), Vec::new()],
        cage_speed: 0.0,
    };
    let mut cage = Vec::new();
    let report = run(
        &mut model,
        &mut rk,
        END,
        SAMPLE_RATE,
        &AtomicBool::new(false),
        |m, t, y| {
            if t >= SKIP - 1e-12 {
                m.rhs(t, y, &mut dy);
                for k in 0..3 {
                    out.acceleration[k].push(dy[r + 5 + k]);
                }
                for k in 0..2 {
                    out.outer_acceleration[k].push(dy[o + 2 + k]);
                }
                cage.push(y[c + 5]);
            }
        },
        |_| {},
    );
    assert!(matches!(report.end, rolldyn::integrate::RunEnd::Completed));
    out.cage_speed = cage.iter().sum::<f64>() / cage.len() as f64;
    out
}

fn largest_peak(spectrum: &Spectrum, above: f64) -> f64 {
    let (k, _) = spectrum
        .value
        .iter()
        .enumerate()
        .filter(|(k, _)| spectrum.frequency[*k] >= above)
        .max_by(|a, b| a.1.total_cmp(b.1))
        .unwrap();
    spectrum.frequency[k]
}

fn wave(order: u32) -> Waviness {
    Waviness {
        terms: vec![WavinessTerm {
            order,
            amplitude: 0.3e-6,
            phase: 0.0,
        }],
    }
}

/// Runs one C4 family and checks the peak against Table 2.
fn c4(part: WavyPart, order: u32) {
    let surface = match part {
        WavyPart::OuterRace => SurfaceModel {
            outer: RaceSurface {
                radial: wave(order),
                ..RaceSurface::default()
            },
            ..SurfaceModel::default()
        },
        WavyPart::InnerRace => SurfaceModel {
            inner: RaceSurface {
                radial: wave(order),
                ..RaceSurface::default()
            },
            ..SurfaceModel::default()
        },
        WavyPart::Ball => SurfaceModel {
            balls: vec![
                BallSurface {
                    waviness: wave(order),
                    spalls: vec![],
                };
                22
            ],
            ..SurfaceModel::default()
        },
    };
    let rec = record(|p| p.surface = surface.clone(), 1e-3, 2e-5);
    let g = bearing_7008c();
    let freqs = Frequencies::new(
        g.ball_diameter,
        g.pitch_diameter,
        g.ball_count,
        g.nominal_contact_angle(),
        10_000.0 / 60.0,
        0.0,
    );
    let lines = waviness_frequencies(&freqs, part, order);
    let line = lines.first().expect("Table 2 has a line for this order");
    let channel = match line.motion {
        rolldyn::kinematics::Motion::Axial => 0,
        rolldyn::kinematics::Motion::Radial => 1,
    };
    let spectrum =
        amplitude_spectrum(&rec.acceleration[channel], SAMPLE_RATE, Window::Hann).unwrap();
    let peak = largest_peak(&spectrum, 300.0);
    let bin = spectrum.resolution();
    eprintln!(
        "C4 {part:?} l = {order}: predicted {:.1} Hz ({:?}), peak {peak:.1} Hz (bin {bin:.1} Hz), cage {:.1} rpm",
        line.frequency_hz,
        line.motion,
        rec.cage_speed / RPM
    );
    assert!(
        (peak - line.frequency_hz).abs() <= bin,
        "{part:?} l = {order}: peak at {peak} Hz, Table 2 predicts {} Hz",
        line.frequency_hz
    );
}

#[test]
fn c4_outer_waviness_kz_excites_kz_fc_axially() {
    c4(WavyPart::OuterRace, 22);
}

#[test]
fn c4_outer_waviness_kz_plus_one_excites_kz_fc_radially() {
    c4(WavyPart::OuterRace, 23);
}

#[test]
fn c4_outer_waviness_kz_minus_one_excites_kz_fc_radially() {
    c4(WavyPart::OuterRace, 21);
}

#[test]
fn c4_inner_waviness_kz_excites_kz_inner_pass_axially() {
    c4(WavyPart::InnerRace, 22);
}

#[test]
fn c4_inner_waviness_kz_minus_one_excites_the_shaft_sideband_radially() {
    c4(WavyPart::InnerRace, 21);
}

#[test]
fn c4_inner_waviness_kz_plus_one_excites_the_shaft_sideband_radially() {
    c4(WavyPart::InnerRace, 23);
}

#[test]
fn c4_ball_waviness_2k_excites_2k_ball_spin_axially() {
    c4(WavyPart::Ball, 2);
}

fn spall(position: f64, length: f64, depth: f64) -> Spall {
    Spall {
        position,
        size: SpallSize::Length(length),
        depth,
        axial_position: 0.0,
        axial_width: None,
        edge: Edge::Sharp,
        growth_rate: 0.0,
    }
}

/// F_x = 200 N and a radial F_z: a load zone around +z.
fn with_radial_load(p: &mut DynamicsParameters, radial: f64) {
    p.loads = LoadProfile::Constant(Loads {
        force: [200.0, 0.0, radial],
        moment: [0.0; 2],
    });
}

/// The outer ring on a housing: 0.1 kg on 1e8 N/m, 5 % damping, a
/// resonance at 5.0 kHz that the defect impulses ring (as a housing
/// resonance does on a test rig; envelope analysis demodulates it).
fn on_housing(p: &mut DynamicsParameters) {
    p.outer_ring = Some(OuterRing {
        mass: 0.1,
        housing: Support {
            stiffness: [0.0, 1e8, 1e8],
            damping: [0.0, 316.0, 316.0],
        },
    });
}

/// A spall run on the housing at the default case's tolerance (1e-2, step ≤ 0.1 ms).
fn spall_record(configure: impl Fn(&mut DynamicsParameters)) -> Record {
    record(
        |p| {
            on_housing(p);
            configure(p);
        },
        1e-2,
        1e-4,
    )
}

/// Envelope spectrum (3–8 kHz, around the housing resonance) of the
/// outer-ring acceleration `channel` (0: y, 1: z), and the run's
/// characteristic frequencies.
fn envelope(rec: &Record, channel: usize) -> (Spectrum, CharacteristicFrequencies) {
    let g = bearing_7008c();
    let spectrum = envelope_spectrum(
        &rec.outer_acceleration[channel],
        SAMPLE_RATE,
        (3000.0, 8000.0),
        Window::Hann,
    )
    .unwrap();
    let lines = CharacteristicFrequencies::new(
        10_000.0 / 60.0,
        rec.cage_speed / std::f64::consts::TAU,
        g.ball_count,
        g.ball_diameter / g.pitch_diameter,
        g.nominal_contact_angle(),
    );
    (spectrum, lines)
}

/// Value of the spectrum's largest line within one bin of `f`.
fn at(spectrum: &Spectrum, f: f64) -> f64 {
    let bin = spectrum.resolution();
    spectrum
        .frequency
        .iter()
        .zip(&spectrum.value)
        .filter(|(x, _)| (**x - f).abs() <= bin)
        .map(|(_, v)| *v)
        .fold(0.0, f64::max)
}

fn median(spectrum: &Spectrum, from: f64, to: f64) -> f64 {
    let mut v: Vec<f64> = spectrum
        .frequency
        .iter()
        .zip(&spectrum.value)
        .filter(|(f, _)| (from..to).contains(*f))
        .map(|(_, v)| *v)
        .collect();
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// 0.5 mm long, 1.5 µm deep: the ball drops into it without losing contact.
const SPALL_LENGTH: f64 = 0.5e-3;
const SPALL_DEPTH: f64 = 1.5e-6;

#[test]
fn outer_race_spall_gives_an_envelope_peak_at_bpfo_and_harmonics() {
    let rec = spall_record(|p| {
        p.surface.outer.spalls = vec![spall(0.3, SPALL_LENGTH, SPALL_DEPTH)];
    });
    let (env, lines) = envelope(&rec, 0);
    let peak = largest_peak(&env, 100.0);
    let floor = median(&env, 100.0, 5000.0);
    eprintln!(
        "outer spall: envelope peak {peak:.1} Hz, BPFO {:.1} Hz; at BPFO {:.3e}, 2×BPFO {:.3e}, median {floor:.3e}",
        lines.bpfo,
        at(&env, lines.bpfo),
        at(&env, 2.0 * lines.bpfo)
    );
    assert!((peak - lines.bpfo).abs() <= env.resolution());
    assert!(at(&env, 2.0 * lines.bpfo) > 5.0 * floor);
}

#[test]
fn inner_race_spall_under_radial_load_gives_bpfi_with_shaft_sidebands() {
    // (BPFI, its f_i sidebands' mean) over the envelope's median, with and
    // without the radial load's load zone.
    let lines_over_floor = |radial: f64| {
        let rec = spall_record(|p| {
            with_radial_load(p, radial);
            p.surface.inner.spalls = vec![spall(0.0, SPALL_LENGTH, SPALL_DEPTH)];
        });
        let (env, lines) = envelope(&rec, 1);
        let floor = median(&env, 100.0, 5000.0);
        let (bpfi, upper, lower) = (
            at(&env, lines.bpfi),
            at(&env, lines.bpfi + lines.shaft),
            at(&env, lines.bpfi - lines.shaft),
        );
        eprintln!(
            "inner spall, F_z {radial} N: BPFI {:.1} Hz: {bpfi:.3e}, +f_i {upper:.3e}, −f_i {lower:.3e}, median {floor:.3e}",
            lines.bpfi
        );
        (bpfi / floor, 0.5 * (upper + lower) / floor)
    };
    let (bpfi, sidebands) = lines_over_floor(800.0);
    let (bpfi_axial, sidebands_axial) = lines_over_floor(0.0);
    eprintln!(
        "over the median: BPFI {bpfi:.2} (axial only {bpfi_axial:.2}), sidebands {sidebands:.2} (axial only {sidebands_axial:.2})"
    );
    // BPFI stands out either way; the load zone modulates the impacts once
    // per shaft turn, so the sidebands rise out of the median with the
    // radial load (2.3 against 0.3 in 2026-11) and grow from a hundredth
    // of BPFI to a third or more. The whirling cage's impacts set the
    // median, which moves by tens of per cent with the traction's grid.
    assert!(bpfi > 5.0 && bpfi_axial > 5.0);
    assert!(sidebands > 1.0 && sidebands > 5.0 * sidebands_axial);
    assert!(sidebands / bpfi > 10.0 * (sidebands_axial / bpfi_axial));
}

#[test]
fn ball_spall_gives_twice_the_ball_spin_with_cage_sidebands() {
    let rec = spall_record(|p| {
        with_radial_load(p, 300.0);
        let mut balls = vec![BallSurface::default(); 22];
        balls[0].spalls = vec![spall(0.0, SPALL_LENGTH, SPALL_DEPTH)];
        p.surface.balls = balls;
    });
    let (env, lines) = envelope(&rec, 1);
    let floor = median(&env, 100.0, 5000.0);
    let two_bsf = 2.0 * lines.ball_spin;
    let (centre, upper, lower) = (
        at(&env, two_bsf),
        at(&env, two_bsf + lines.cage),
        at(&env, two_bsf - lines.cage),
    );
    eprintln!(
        "ball spall: 2×BSF {two_bsf:.1} Hz: {centre:.3e}, +f_c {upper:.3e}, −f_c {lower:.3e}, median {floor:.3e}"
    );
    assert!(centre > 5.0 * floor);
    assert!(upper.max(lower) > 3.0 * floor);
}

/// Integrates to `t_end` and returns the final state.
fn final_state(configure: impl Fn(&mut DynamicsParameters), t_end: f64) -> Vec<f64> {
    let (mut model, y0) = model(configure);
    let mut rk = solver(&model, &y0, 1e-3, 2e-5);
    while rk.t() < t_end {
        rk.step(&mut model, t_end).unwrap();
    }
    rk.y().to_vec()
}

#[test]
fn zero_amplitude_raceway_waviness_reproduces_the_smooth_run_bit_for_bit() {
    let smooth = final_state(|_| {}, 2e-3);
    let zero = |order| Waviness {
        terms: vec![WavinessTerm {
            order,
            amplitude: 0.0,
            phase: 0.7,
        }],
    };
    let wavy = final_state(
        |p| {
            p.surface.inner = RaceSurface {
                radial: zero(5),
                axial: zero(3),
                spalls: vec![],
                roughness: 0.0,
            };
            p.surface.outer = RaceSurface {
                radial: zero(22),
                axial: zero(7),
                spalls: vec![],
                roughness: 0.0,
            };
        },
        2e-3,
    );
    assert_eq!(smooth, wavy);
}

/// Zero-amplitude ball waviness adds the spin-angle states (one more state
/// per ball in the error norm and the Jacobian), so the run matches the
/// smooth one to the integrator's tolerance rather than bit for bit.
#[test]
fn zero_amplitude_ball_waviness_matches_the_smooth_run() {
    let smooth = final_state(|_| {}, 2e-3);
    let wavy = final_state(
        |p| {
            p.surface.balls = vec![
                BallSurface {
                    waviness: Waviness {
                        terms: vec![WavinessTerm {
                            order: 2,
                            amplitude: 0.0,
                            phase: 0.0,
                        }],
                    },
                    spalls: vec![],
                };
                22
            ]
        },
        2e-3,
    );
    // Ball j's mechanical states sit at 10 j … 10 j + 8 with ψ, at 9 j … without.
    let (mut worst_position, mut worst_speed) = (0.0f64, 0.0f64);
    for j in 0..22 {
        for k in 0..9 {
            let d = (wavy[10 * j + k] - smooth[9 * j + k]).abs();
            match k {
                0 | 1 => worst_position = worst_position.max(d),
                5..=8 => worst_speed = worst_speed.max(d / smooth[9 * j + 5].abs()),
                _ => {}
            }
        }
    }
    eprintln!("zero ball waviness: position {worst_position:.2e} m, speeds {worst_speed:.2e} rel");
    // rtol 1e-3 of the 1 µm position scale: 1 nm.
    assert!(worst_position < 1e-9 && worst_speed < 1e-6);
    // The border (rings, cage, energy) follows the ball blocks.
    let border = smooth.len() - 9 * 22;
    assert_eq!(wavy.len() - 10 * 22, border);
}

#[test]
fn b2_energy_balance_closes_with_waviness_and_spalls() {
    let (mut model, y0) = model(|p| {
        with_radial_load(p, 300.0);
        p.surface.outer.radial = wave(23);
        p.surface.inner.axial = wave(21);
        p.surface.outer.spalls = vec![spall(0.2, 0.5e-3, 10e-6)];
        p.surface.inner.spalls = vec![spall(0.0, 0.5e-3, 10e-6)];
        let mut balls = vec![BallSurface::default(); 22];
        balls[0].waviness = wave(4);
        balls[3].spalls = vec![spall(0.0, 0.4e-3, 10e-6)];
        p.surface.balls = balls;
    });
    let e0 = model.energy(0.0, &y0).total();
    let mut rk = solver(&model, &y0, 1e-6, 1e-5);
    let t_end = 3e-3;
    while rk.t() < t_end {
        rk.step(&mut model, t_end).unwrap();
    }
    let (drive, dissipated) = model.work(rk.y());
    let delta = model.energy(rk.t(), rk.y()).total() - e0;
    let imbalance = drive - delta - dissipated;
    let scale = drive.abs().max(dissipated.abs());
    eprintln!(
        "B2 with surfaces: drive {drive:.4e} J, ΔE {delta:.4e} J, dissipated {dissipated:.4e} J, imbalance {:.1e}",
        imbalance / scale
    );
    assert!((imbalance / scale).abs() < 1e-3);
}

/// The model without its step limit: what an integrator sees if it is not
/// told about the spall.
struct Unlimited(BearingModel);

impl OdeSystem for Unlimited {
    fn dimension(&self) -> usize {
        self.0.dimension()
    }
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        self.0.rhs(t, y, dy);
    }
    fn error_scale(&self, scale: &mut [f64]) {
        self.0.error_scale(scale);
    }
    fn accept_step(&mut self, t: f64, y: &[f64]) -> bool {
        self.0.accept_step(t, y)
    }
}

/// Smallest outer load over accepted steps, relative to the smallest
/// outer load of the smooth bearing at the same steps \[-\], and the
/// median step \[s\].
fn deepest_dip<S: OdeSystem>(
    system: &mut S,
    model: impl Fn(&S) -> &BearingModel,
    y0: &[f64],
) -> (f64, f64) {
    let mut rk = Solver::Rosenbrock(Box::new(
        Rosenbrock::builder(&ROS34PW2)
            .relative_tolerance(1e-2)
            .max_step(1e-4)
            .build(system, y0)
            .unwrap(),
    ));
    let mut samples = vec![ContactSample::default(); 22];
    let mut smallest = f64::INFINITY;
    let mut steps = Vec::new();
    let t_end = 4e-3;
    while rk.t() < t_end {
        let t0 = rk.t();
        rk.step(system, t_end).unwrap();
        steps.push(rk.t() - t0);
        model(system).contact_samples(rk.t(), rk.y(), &mut samples);
        let min = samples
            .iter()
            .map(|s| s.outer.load)
            .fold(f64::INFINITY, f64::min);
        smallest = smallest.min(min);
    }
    steps.sort_by(f64::total_cmp);
    (smallest, steps[steps.len() / 2])
}

#[test]
fn a_spall_shorter_than_the_unconstrained_step_is_still_felt() {
    // 40 µm long, 5 µm deep on the outer race: crossed in ~3 µs; the ball
    // bridges it and loses ~0.06 µm of approach (a few % of its load).
    let short = |p: &mut DynamicsParameters| p.surface.outer.spalls = vec![spall(0.1, 40e-6, 5e-6)];
    let (mut smooth, y0) = model(|_| {});
    let (smooth_min, smooth_step) = deepest_dip(&mut smooth, |m| m, &y0);
    let (mut limited, _) = model(short);
    let (limited_min, _) = deepest_dip(&mut limited, |m| m, &y0);
    let (bare, _) = model(short);
    let mut unlimited = Unlimited(bare);
    let (unlimited_min, _) = deepest_dip(&mut unlimited, |u| &u.0, &y0);
    let crossing = 40e-6 / (0.5 * 60.36e-3 * 4441.0 * RPM);
    eprintln!(
        "short spall: crossing {crossing:.2e} s, unconstrained median step {smooth_step:.2e} s; smallest outer load smooth {smooth_min:.3} N, with step limit {limited_min:.3} N, without {unlimited_min:.3} N"
    );
    assert!(
        crossing < smooth_step,
        "the spall must be shorter than a step"
    );
    assert!(
        limited_min < 0.98 * smooth_min,
        "the step limit lets the contact feel the spall"
    );
}
