//! Zhang et al. 2020 §3's dynamic part: the inner ring's vibration against the
//! inlet distance ratio L, from dynamic runs of the ceramic 45×75 preset
//! with the film in the normal approach (docs/model.md §4).
//!
//! Each run starts from the quasi-static equilibrium with the same films
//! (tilts held, as the example's stiffness table; the dynamic ring then
//! moves freely in all five directions), runs [`DURATION`] and analyses the
//! inner ring's velocity after [`SKIP`]: its RMS along z (the load), y and
//! x (axial) with the mean removed, the largest |v_z − mean|, the amplitude
//! of the ball-pass line Z f_c in the v_z spectrum (the varying compliance
//! that a radial load excites), and the frequency of the largest v_z
//! spectral peak above [`PEAK_ABOVE`] that is not a ball-pass harmonic (the
//! ring's resonance; interpolated between bins by a parabola through the
//! log amplitudes).
//!
//! **Damping is an assumption.** Zhang et al. 2020 gives its contacts no damping,
//! and without one the model's ring keeps its start transient (Hertz
//! springs, no support). The runs use the viscous contact law with a
//! damping ratio ζ (c_n = 2ζ√(k_n m_b) at the contact's linearised
//! stiffness; docs/contact.md), [`DAMPING_RATIO`] for the table and
//! [`SENSITIVITY`] to show what depends on it.

use rolldyn::integrate::{DEFAULT_ENERGY_TOLERANCE, ROS34PW2, Rosenbrock, RunEnd, run};
use rolldyn::lubrication;
use rolldyn::quasistatic::films::FilmInputs;
use rolldyn::quasistatic::{Conditions, QuasiStaticSolver, SolverOptions};
use rolldyn::signal::{Window, amplitude_spectrum};
use rolldyn_case::{Override, load_case, simulation};
use std::fmt::Write as _;
use std::sync::atomic::AtomicBool;

/// Simulated time of each run \[s\] (80 ms analysed: 12.5 Hz bins).
pub const DURATION: f64 = 0.1;
/// Start transient left out of the analysis \[s\].
pub const SKIP: f64 = 0.02;
/// Sample rate of the ring velocity \[Hz\].
const SAMPLE_RATE: f64 = 50_000.0;
/// Largest integrator step \[s\] (resolves the kHz ring and ball modes).
const MAX_STEP: f64 = 2e-5;
/// Spectral peaks are searched above this frequency \[Hz\] (the cage and
/// shaft lines lie below).
pub const PEAK_ABOVE: f64 = 500.0;
/// Harmonics k Z f_c (k ≤ 6) are excluded from the resonance search within
/// this many bins.
const HARMONIC_BINS: f64 = 3.0;
/// Contact damping ratio of the table (assumed: Zhang et al. 2020 gives none).
pub const DAMPING_RATIO: f64 = 0.05;
/// Damping ratios of the sensitivity rows (20 N, L = 1.1 and 1.9).
pub const SENSITIVITY: [f64; 2] = [0.02, 0.1];

/// One run: radial load \[N\], supply (None: dry, no film in the approach;
/// Some(∞): flooded) and contact damping ratio.
#[derive(Debug, Clone, Copy)]
pub struct Job {
    pub radial_load: f64,
    pub ratio: Option<f64>,
    pub damping_ratio: f64,
}

/// What one run gives.
#[derive(Debug, Clone)]
pub struct Vibration {
    /// RMS of the inner ring's velocity along z, y, x (mean removed) \[m/s\].
    pub rms: [f64; 3],
    /// Largest |v_z − mean| \[m/s\].
    pub peak_z: f64,
    /// Ball-pass frequency Z f_c from the mean cage speed \[Hz\].
    pub ball_pass: f64,
    /// Amplitude of the v_z spectrum at the ball-pass line \[m/s\].
    pub ball_pass_amplitude: f64,
    /// Frequency of the largest v_z spectral peak above [`PEAK_ABOVE`]
    /// away from the ball-pass harmonics \[Hz\].
    pub peak_frequency: f64,
    /// How the run ended, with its steps and wall time.
    pub status: String,
}

/// The jobs of the table and of the sensitivity rows.
pub fn jobs(loads: &[f64], ratios: &[f64]) -> Vec<Job> {
    let mut jobs = Vec::new();
    for &radial_load in loads {
        for ratio in std::iter::once(None).chain(ratios.iter().map(|&l| Some(l))) {
            jobs.push(Job {
                radial_load,
                ratio,
                damping_ratio: DAMPING_RATIO,
            });
        }
    }
    for damping_ratio in SENSITIVITY {
        for l in [1.1, 1.9] {
            jobs.push(Job {
                radial_load: 20.0,
                ratio: Some(l),
                damping_ratio,
            });
        }
    }
    jobs
}

/// Runs the jobs on two threads (each run is deterministic; the order of
/// the results is the order of the jobs).
pub fn run_all(preset: &str, jobs: &[Job]) -> Vec<Result<Vibration, String>> {
    let next = std::sync::atomic::AtomicUsize::new(0);
    let results = std::sync::Mutex::new(vec![None; jobs.len()]);
    std::thread::scope(|s| {
        for _ in 0..2 {
            s.spawn(|| {
                loop {
                    let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                    let Some(job) = jobs.get(i) else { break };
                    let r = simulate(preset, job);
                    eprintln!(
                        "F_z {} N, L {}, ζ {}: {}",
                        job.radial_load,
                        label(job.ratio),
                        job.damping_ratio,
                        r.as_ref().map_or_else(|e| e.clone(), |v| v.status.clone())
                    );
                    if let Ok(mut slots) = results.lock() {
                        slots[i] = Some(r);
                    }
                }
            });
        }
    });
    results
        .into_inner()
        .unwrap_or_default()
        .into_iter()
        .map(|r| r.unwrap_or_else(|| Err("not run".into())))
        .collect()
}

/// L as the tables print it (dry: no film in the approach; ∞: flooded).
pub fn label(ratio: Option<f64>) -> String {
    match ratio {
        None => "dry".into(),
        Some(l) if l.is_finite() => format!("{l:.1}"),
        Some(_) => "∞".into(),
    }
}

fn simulate(preset: &str, job: &Job) -> Result<Vibration, String> {
    let set = |s: String| Override::parse_set(&s).map_err(|e| e.to_string());
    let mut overrides = vec![
        Override::flag(
            "--radial-load",
            "operating.force_z",
            &format!("{} N", job.radial_load),
        ),
        set(format!(
            "model.normal_law={{ law = \"viscous\", damping_ratio = {} }}",
            job.damping_ratio
        ))?,
        // Zhang et al. 2020's model has no EHL rolling resistance (the
        // preset's lubricated default since 2026-11-28).
        set("lubrication.rolling_resistance=\"none\"".into())?,
    ];
    if let Some(l) = job.ratio {
        overrides.push(set("model.film_in_approach=true".into())?);
        if l.is_finite() {
            overrides.push(set(format!("lubricant.inlet_distance_ratio={l}"))?);
        }
    }
    let case = load_case("ceramic_45x75 preset", preset, &overrides).map_err(|e| e.to_string())?;
    let params = case
        .dynamics_parameters()
        .map_err(|e| format!("{}: {}", e.key, e.rule))?;
    let g = &case.bearing.geometry;
    let (ball, rings) = (
        &case.materials.ball.material,
        &case.materials.rings.material,
    );
    let mut model = simulation::model(&case, params.clone()).map_err(|e| e.to_string())?;
    let solver = QuasiStaticSolver::new(g, ball, rings, case.contact_stiffness)
        .map_err(|e| e.to_string())?;
    let conditions = Conditions {
        loads: params.loads.at(0.0),
        inner_speed: params.speed.speed_at(0.0),
        control: case.raceway_control,
    };
    let options = SolverOptions {
        prescribed_displacement: [None, None, None, Some(0.0), Some(0.0)],
        ..SolverOptions::default()
    };
    let eq = match job.ratio {
        None => solver.solve(&conditions, &options),
        Some(l) => {
            let inputs = film_inputs(&case, l)?;
            solver.solve_with_films(&conditions, &options, &inputs)
        }
    }
    .map_err(|e| e.to_string())?;
    let y0 = model.state_from_equilibrium(&eq);
    let rtol = case.relative_tolerance.unwrap_or(1e-3);
    let mut integrator = Rosenbrock::builder(&ROS34PW2)
        .relative_tolerance(rtol)
        .max_step(MAX_STEP)
        .energy_tolerance(Some(DEFAULT_ENERGY_TOLERANCE))
        .build(&model, &y0)
        .map_err(|e| e.to_string())?;
    let (r, c) = (model.layout().ring(), model.layout().cage());
    let mut velocity: [Vec<f64>; 3] = Default::default();
    let mut cage_speed = Vec::new();
    let started = std::time::Instant::now();
    let report = run(
        &mut model,
        &mut integrator,
        DURATION,
        SAMPLE_RATE,
        &AtomicBool::new(false),
        |_, t, y| {
            if t >= SKIP {
                // Ring states: x, y, z, θ_y, θ_z, then their rates.
                velocity[0].push(y[r + 7]);
                velocity[1].push(y[r + 6]);
                velocity[2].push(y[r + 5]);
                cage_speed.push(y[c + 5]);
            }
        },
        |_| {},
    );
    let status = match report.end {
        RunEnd::Completed => format!(
            "completed, {} steps, {:.1} s wall",
            report.stats.steps,
            started.elapsed().as_secs_f64()
        ),
        RunEnd::Interrupted { t } => return Err(format!("interrupted at {t} s")),
        RunEnd::Failed { error } => return Err(format!("failed: {error}")),
    };
    vibration(&velocity, &cage_speed, model.layout().balls, status)
}

/// The record's statistics: the ring's RMS velocities, the ball-pass line
/// and the strongest peak off its harmonics.
fn vibration(
    velocity: &[Vec<f64>; 3],
    cage_speed: &[f64],
    balls: usize,
    status: String,
) -> Result<Vibration, String> {
    let centred = |v: &[f64]| {
        let mean = v.iter().sum::<f64>() / v.len().max(1) as f64;
        v.iter().map(|x| x - mean).collect::<Vec<f64>>()
    };
    let rms = |v: &[f64]| (v.iter().map(|x| x * x).sum::<f64>() / v.len().max(1) as f64).sqrt();
    let vz = centred(&velocity[0]);
    let spectrum = amplitude_spectrum(&vz, SAMPLE_RATE, Window::Hann).map_err(|e| e.to_string())?;
    let df = spectrum.resolution();
    let mean_cage = cage_speed.iter().sum::<f64>() / cage_speed.len().max(1) as f64;
    let ball_pass = balls as f64 * mean_cage / std::f64::consts::TAU;
    let bin = |f: f64| ((f / df).round() as usize).min(spectrum.value.len() - 1);
    let ball_pass_amplitude = spectrum.value[bin(ball_pass)];
    let harmonic = |f: f64| (1..=6).any(|k| (f - k as f64 * ball_pass).abs() <= HARMONIC_BINS * df);
    let v = &spectrum.value;
    let peak_frequency = (1..v.len() - 1)
        .filter(|&k| spectrum.frequency[k] >= PEAK_ABOVE && !harmonic(spectrum.frequency[k]))
        .filter(|&k| v[k] >= v[k - 1] && v[k] >= v[k + 1])
        .max_by(|&a, &b| v[a].total_cmp(&v[b]))
        .map_or(f64::NAN, |k| {
            // Parabola through the log amplitudes of the peak bin and its
            // neighbours (Gaussian-peak interpolation).
            let (a, b, g) = (v[k - 1].ln(), v[k].ln(), v[k + 1].ln());
            let shift = 0.5 * (a - g) / (a - 2.0 * b + g);
            spectrum.frequency[k] + if shift.is_finite() { shift * df } else { 0.0 }
        });
    Ok(Vibration {
        rms: [
            rms(&vz),
            rms(&centred(&velocity[1])),
            rms(&centred(&velocity[2])),
        ],
        peak_z: vz.iter().fold(0.0, |m, x| m.max(x.abs())),
        ball_pass,
        ball_pass_amplitude,
        peak_frequency,
        status,
    })
}

/// The films' inputs of the case with both rings supplied at inlet
/// distance ratio L (∞: flooded).
pub fn film_inputs(case: &rolldyn_case::Case, l: f64) -> Result<FilmInputs, String> {
    let lub = case
        .lubricant
        .as_ref()
        .ok_or("the preset has no [lubricant]")?;
    let supply = if l.is_finite() {
        lubrication::Supply::InletDistance(l)
    } else {
        lubrication::Supply::Flooded
    };
    let (ball, rings) = (
        &case.materials.ball.material,
        &case.materials.rings.material,
    );
    Ok(FilmInputs {
        lubricant: lubrication::Lubricant {
            viscosity: lub.viscosity,
            pressure_viscosity: lub.pressure_viscosity,
            pressure_model: lub.pressure_viscosity_model,
        },
        supply: [supply, supply],
        roughness: [
            case.surface.composite_roughness(rolldyn::RingKind::Inner),
            case.surface.composite_roughness(rolldyn::RingKind::Outer),
        ],
        effective_modulus: rolldyn::material::effective_modulus(ball, rings),
    })
}

/// The table (text) and CSV of the runs.
pub fn tables(results: &[Result<Vibration, String>], jobs: &[Job]) -> (String, String) {
    let mut text = format!(
        "\nDynamic runs (film in the approach, from the held-tilt equilibrium), {:.0} ms, analysed from {:.0} ms: inner-ring velocity\n\
         F_z [N]      L     ζ  v_z RMS [mm/s]  v_y RMS [mm/s]  v_x RMS [mm/s]  max |v_z| [mm/s]  Z f_c [Hz]  v_z at Z f_c [mm/s]  resonance peak [Hz]\n",
        DURATION * 1e3,
        SKIP * 1e3
    );
    let mut csv = String::from(
        "radial_load_n,inlet_distance_ratio,damping_ratio,velocity_rms_z_m_s,velocity_rms_y_m_s,velocity_rms_x_m_s,max_velocity_z_m_s,ball_pass_hz,ball_pass_velocity_z_m_s,resonance_peak_hz\n",
    );
    for (job, r) in jobs.iter().zip(results) {
        let l = label(job.ratio);
        match r {
            Ok(v) => {
                let _ = writeln!(
                    text,
                    "{:>7.0} {l:>6} {:>5.2} {:>15.4} {:>15.4} {:>15.4} {:>17.4} {:>11.1} {:>20.4} {:>20.0}",
                    job.radial_load,
                    job.damping_ratio,
                    v.rms[0] * 1e3,
                    v.rms[1] * 1e3,
                    v.rms[2] * 1e3,
                    v.peak_z * 1e3,
                    v.ball_pass,
                    v.ball_pass_amplitude * 1e3,
                    v.peak_frequency
                );
                let _ = writeln!(
                    csv,
                    "{},{},{},{},{},{},{},{},{},{}",
                    job.radial_load,
                    job.ratio.map_or("dry".into(), |l| l.to_string()),
                    job.damping_ratio,
                    v.rms[0],
                    v.rms[1],
                    v.rms[2],
                    v.peak_z,
                    v.ball_pass,
                    v.ball_pass_amplitude,
                    v.peak_frequency
                );
            }
            Err(e) => {
                let _ = writeln!(
                    text,
                    "{:>7.0} {l:>6} {:>5.2}  {e}",
                    job.radial_load, job.damping_ratio
                );
            }
        }
    }
    (text, csv)
}
