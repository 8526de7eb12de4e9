//! `summary.json` of a dynamic run (keys and units in docs/cli.md): the
//! run's statistics over the averaging window (the second half of the
//! run), its energy balance, accuracy, power, vibration and integration
//! counters, built from the statistics `run_stats` accumulates while
//! running.

use crate::accuracy::{
    Change, VERIFY_LIMIT_MEANS, VERIFY_LIMIT_VIBRATION, VIBRATION_NOISE_FACTOR, Verification,
};
use crate::power_channels::PowerSummary;
use crate::run_options::DEFAULT_SAMPLE_RATE;
use crate::run_stats::{RunStatistics, Window};
use crate::vibration::VibrationSummary;
use rolldyn::dynamics::BearingModel;
use rolldyn::integrate::{IntegrationStats, RunEnd};
use rolldyn_case::Case;
use rolldyn_case::simulation::SolverSettings;
use serde::Serialize;

/// `summary.json`.
#[derive(Serialize)]
pub struct Summary {
    pub source: String,
    pub title: Option<String>,
    pub status: &'static str,
    pub error: Option<String>,
    pub requested_duration_s: f64,
    pub simulated_time_s: f64,
    pub wall_time_s: f64,
    pub integrator: &'static str,
    pub relative_tolerance: Option<f64>,
    /// Energy-balance tolerance of the step control (null: off).
    pub energy_tolerance: Option<f64>,
    pub max_step_s: f64,
    pub steps: u64,
    pub rejected_steps: u64,
    pub rhs_evaluations: u64,
    pub jacobian_evaluations: u64,
    pub jacobian_rhs_evaluations: u64,
    /// Evaluations of the Jacobian's fast part (pockets and cage).
    pub fast_part_jacobians: u64,
    pub factorizations: u64,
    /// `auto`: accepted steps of its explicit method (DOPRI5) and
    /// hand-overs between its methods (null for the other integrators).
    pub explicit_steps: Option<u64>,
    pub integrator_switches: Option<u64>,
    pub samples: usize,
    pub sample_rate_hz: f64,
    pub averaging_window_s: [f64; 2],
    pub ball_count: usize,
    pub ball_diameter_m: f64,
    pub pitch_diameter_m: f64,
    pub mean_contact_angle_inner_deg: f64,
    pub mean_contact_angle_outer_deg: f64,
    pub inner_ring_speed_rpm: f64,
    pub final_inner_ring_speed_rpm: f64,
    pub mean_cage_speed_rpm: f64,
    pub pure_rolling_cage_speed_rpm: f64,
    pub cage_speed_ratio: f64,
    pub pure_rolling_cage_speed_ratio: f64,
    pub cage_sliding_rate: f64,
    pub mean_load_inner_n: f64,
    pub max_load_inner_n: f64,
    pub mean_load_outer_n: f64,
    pub max_load_outer_n: f64,
    pub mean_slide_to_roll_inner: f64,
    pub mean_slide_to_roll_outer: f64,
    pub mean_spin_to_roll_inner: f64,
    pub mean_spin_to_roll_outer: f64,
    /// FASTSIM creepage and stick means (absent with other traction models).
    #[serde(flatten)]
    pub creep: Option<CreepMeans>,
    pub mean_attitude_deg: f64,
    pub mean_yaw_deg: f64,
    pub max_abs_yaw_deg: f64,
    /// Jitter of the balls' passage through the load zone's centre: the
    /// standard deviation of the intervals between successive balls over
    /// their mean \[1\] (null with fewer than two intervals in the window).
    pub ball_pass_jitter: Option<f64>,
    /// Their mean \[s\].
    pub ball_pass_interval_s: Option<f64>,
    /// Vibration velocity RMS and cage-whirl metrics.
    #[serde(flatten)]
    pub vibration: VibrationSummary,
    /// The spectra's lines of a run with a spall, waviness or a sensor.
    #[serde(flatten)]
    pub surface_lines: crate::vibration::SurfaceLines,
    /// Each growing spall's length against the length its growth rate
    /// asks at the run's end (null without growing spalls).
    pub spall_growth: Option<Vec<SpallGrowth>>,
    /// The sensor's record over the window (null without `[sensor]`).
    pub sensor: Option<crate::vibration::SensorSummary>,
    /// Friction power by component and friction torque.
    #[serde(flatten)]
    pub power: PowerSummary,
    /// The thermal network coupled to the run (null when not coupled).
    pub thermal_coupling: Option<crate::power_channels::ThermalRunSummary>,
    pub drive_work_j: f64,
    pub film_work_j: f64,
    pub dissipated_energy_j: f64,
    pub mechanical_energy_change_j: f64,
    pub energy_balance_error_j: f64,
    pub energy_balance_relative_error: f64,
    /// How accurate the run is (docs/cli.md).
    pub accuracy: crate::accuracy::Accuracy,
    /// The quantities `--verify` compares over each half of the averaging
    /// window (empty with fewer than two blocks of samples in it): how
    /// much they move within the window.
    #[serde(skip)]
    pub window_halves: Vec<(&'static str, [f64; 2])>,
    /// How far the cage centre can move before it touches \[m\]
    /// (`CageParameters::radial_freedom`), for `--verify`'s whirl floor.
    #[serde(skip)]
    pub cage_freedom_m: f64,
}

/// A growing spall at the run's end (`summary.json`).
#[derive(Serialize)]
pub struct SpallGrowth {
    /// Its length \[m\].
    pub length_m: f64,
    /// The length L₀ + g t its growth rate asks \[m\].
    pub asked_length_m: f64,
    /// It lags the asked length by more than two ball passes' growth
    /// (2 g / BPFO) plus the 1 % growth step: it can grow only while no
    /// ball is on it, and once about as long as the balls' spacing a ball
    /// always is.
    pub stalled: bool,
}

/// The growing spalls of `model` at time `t`, with BPFO `bpfo` \[Hz\]
/// (None without growing spalls).
fn spall_growth(model: &BearingModel, t: f64, bpfo: f64) -> Option<Vec<SpallGrowth>> {
    let rows: Vec<SpallGrowth> = model
        .spall_growth_at(t)
        .map(|(length, asked, rate)| {
            let allowance = 2.0 * rate / bpfo.abs().max(f64::MIN_POSITIVE)
                + rolldyn::dynamics::spall_growth::MIN_INCREMENT * asked;
            SpallGrowth {
                length_m: length,
                asked_length_m: asked,
                stalled: asked - length > allowance,
            }
        })
        .collect();
    (!rows.is_empty()).then_some(rows)
}

/// Means of the FASTSIM channels over loaded contacts in the averaging
/// window (`summary.json`, FASTSIM runs only).
#[derive(Serialize)]
pub struct CreepMeans {
    pub mean_creepage_longitudinal_inner: f64,
    pub mean_creepage_longitudinal_outer: f64,
    pub mean_creepage_lateral_inner: f64,
    pub mean_creepage_lateral_outer: f64,
    pub mean_creepage_spin_inner_1_m: f64,
    pub mean_creepage_spin_outer_1_m: f64,
    pub mean_stick_fraction_inner: f64,
    pub mean_stick_fraction_outer: f64,
}

impl CreepMeans {
    /// The means over loaded contacts, `loaded_mean` of a channel suffix.
    fn of(loaded_mean: &dyn Fn(&str) -> f64) -> Self {
        Self {
            mean_creepage_longitudinal_inner: loaded_mean("creepage_longitudinal_inner"),
            mean_creepage_longitudinal_outer: loaded_mean("creepage_longitudinal_outer"),
            mean_creepage_lateral_inner: loaded_mean("creepage_lateral_inner"),
            mean_creepage_lateral_outer: loaded_mean("creepage_lateral_outer"),
            mean_creepage_spin_inner_1_m: loaded_mean("creepage_spin_inner_1_m"),
            mean_creepage_spin_outer_1_m: loaded_mean("creepage_spin_outer_1_m"),
            mean_stick_fraction_inner: loaded_mean("stick_fraction_inner"),
            mean_stick_fraction_outer: loaded_mean("stick_fraction_outer"),
        }
    }
}

/// The run's energy balance from its accumulators \[J\]: drive and
/// film work in, dissipation and the mechanical energy's change out.
struct EnergyBalance {
    drive: f64,
    film_work: f64,
    dissipated: f64,
    delta_e: f64,
    /// drive + film − ΔE − dissipated \[J\].
    imbalance: f64,
    /// The imbalance over the larger of |drive| and |dissipated|.
    relative_error: f64,
}

impl EnergyBalance {
    fn of(stats: &RunStatistics) -> Self {
        let drive = stats.last("drive_work_j");
        let film_work = stats.last("film_work_j");
        let dissipated = stats.last("dissipated_energy_j");
        let delta_e = stats.last("mechanical_energy_j") - stats.first("mechanical_energy_j");
        let imbalance = drive + film_work - delta_e - dissipated;
        let relative_error = if drive.abs() + dissipated.abs() > 0.0 {
            imbalance / drive.abs().max(dissipated.abs())
        } else {
            0.0
        };
        Self {
            drive,
            film_work,
            dissipated,
            delta_e,
            imbalance,
            relative_error,
        }
    }
}

/// The cage speed ratio ω_c/ω_i and the cage's sliding rate
/// 1 − (ω_c/ω_i)/(pure-rolling ratio), 0 where undefined (ring at rest,
/// no rolling ratio).
fn cage_ratios(cage_speed: f64, inner_speed: f64, rolling_ratio: f64) -> (f64, f64) {
    if inner_speed == 0.0 {
        return (0.0, 0.0);
    }
    let ratio = cage_speed / inner_speed;
    let sliding = if rolling_ratio > 0.0 {
        1.0 - ratio / rolling_ratio
    } else {
        0.0
    };
    (ratio, sliding)
}

/// The summary's `status` and `error` of how the run ended.
fn status_of(end: &RunEnd) -> (&'static str, Option<String>) {
    match end {
        RunEnd::Completed => ("completed", None),
        RunEnd::Interrupted { .. } => (
            "interrupted",
            Some("stopped by the user (Ctrl-C); the files hold what was computed".to_string()),
        ),
        RunEnd::Failed { error } => ("failed", Some(error.to_string())),
    }
}

/// What a run's summary is built from.
pub(crate) struct SummaryInputs<'a> {
    pub source: &'a str,
    pub case: &'a Case,
    pub model: &'a BearingModel,
    pub stats: &'a RunStatistics,
    /// The requested duration \[s\].
    pub duration: f64,
    /// Wall time so far \[s\].
    pub wall: f64,
    pub settings: &'a SolverSettings,
    pub integration: IntegrationStats,
    pub end: &'a RunEnd,
}

/// The summary of a run, its statistics over the averaging window; with
/// `halves` also the compared quantities over each half of the window
/// (`Summary::window_halves`, for `--verify`).
pub(crate) fn summarise(inputs: &SummaryInputs, halves: bool) -> Summary {
    let stats = inputs.stats;
    // Means over the second half of the run (the first half is transient).
    let mut summary = summary_over(&stats.window(), inputs);
    if let Some([first, second]) = stats.window_halves().filter(|_| halves) {
        let (first, second) = (
            compared(&summary_over(&first, inputs)),
            compared(&summary_over(&second, inputs)),
        );
        summary.window_halves = first
            .into_iter()
            .zip(second)
            .map(|((key, a, ..), (_, b, ..))| (key, [a, b]))
            .collect();
    }
    summary
}

/// The summary with its statistics over `window`.
fn summary_over(window: &Window, inputs: &SummaryInputs) -> Summary {
    let &SummaryInputs {
        source,
        case,
        model,
        stats,
        duration,
        wall,
        settings,
        integration,
        end,
    } = inputs;
    let [window_start, t_end] = window.span();
    let inner_speed = window.mean("inner_ring_speed_rpm");
    let cage_speed = window.mean("cage_speed_rpm");
    let g = &case.bearing.geometry;
    let rolling_ratio = window.mean("pure_rolling_cage_speed_ratio");
    let balls = g.ball_count;
    let loaded_mean = |suffix: &str| window.loaded_mean(suffix);
    let energy = EnergyBalance::of(stats);
    let (status, error) = status_of(end);
    let signal = window.signal();
    let passages = window.passage_jitter();
    let characteristic = rolldyn::signal::CharacteristicFrequencies::new(
        inner_speed / 60.0,
        cage_speed / 60.0,
        balls,
        g.ball_diameter / g.pitch_diameter,
        (0.5 * (loaded_mean("contact_angle_inner_deg") + loaded_mean("contact_angle_outer_deg")))
            .to_radians(),
    );
    let (csr, sliding_rate) = cage_ratios(cage_speed, inner_speed, rolling_ratio);
    Summary {
        source: source.to_string(),
        title: case.title.clone(),
        status,
        error,
        requested_duration_s: duration,
        simulated_time_s: t_end,
        wall_time_s: wall,
        integrator: settings.integrator,
        relative_tolerance: settings.relative_tolerance,
        energy_tolerance: settings.energy_tolerance,
        max_step_s: settings.max_step,
        steps: integration.steps,
        rejected_steps: integration.rejected_steps,
        rhs_evaluations: integration.rhs_evaluations,
        jacobian_evaluations: integration.jacobian_evaluations,
        jacobian_rhs_evaluations: integration.jacobian_rhs_evaluations,
        fast_part_jacobians: integration.fast_part_jacobians,
        factorizations: integration.factorizations,
        explicit_steps: None,
        integrator_switches: None,
        samples: stats.samples() as usize,
        sample_rate_hz: case.sample_rate.unwrap_or(DEFAULT_SAMPLE_RATE),
        averaging_window_s: [window_start, t_end],
        ball_count: balls,
        ball_diameter_m: g.ball_diameter,
        pitch_diameter_m: g.pitch_diameter,
        mean_contact_angle_inner_deg: loaded_mean("contact_angle_inner_deg"),
        mean_contact_angle_outer_deg: loaded_mean("contact_angle_outer_deg"),
        inner_ring_speed_rpm: inner_speed,
        final_inner_ring_speed_rpm: stats.last("inner_ring_speed_rpm"),
        mean_cage_speed_rpm: cage_speed,
        pure_rolling_cage_speed_rpm: rolling_ratio * inner_speed,
        cage_speed_ratio: csr,
        pure_rolling_cage_speed_ratio: rolling_ratio,
        cage_sliding_rate: sliding_rate,
        mean_load_inner_n: window.pooled_mean("load_inner_n"),
        max_load_inner_n: window.largest_load("inner"),
        mean_load_outer_n: window.pooled_mean("load_outer_n"),
        max_load_outer_n: window.largest_load("outer"),
        mean_slide_to_roll_inner: loaded_mean("slide_to_roll_inner"),
        mean_slide_to_roll_outer: loaded_mean("slide_to_roll_outer"),
        mean_spin_to_roll_inner: loaded_mean("spin_to_roll_inner"),
        mean_spin_to_roll_outer: loaded_mean("spin_to_roll_outer"),
        creep: stats
            .has("ball0_stick_fraction_inner")
            .then(|| CreepMeans::of(&loaded_mean)),
        mean_attitude_deg: window.pooled_mean("attitude_deg"),
        mean_yaw_deg: window.pooled_mean("yaw_deg"),
        max_abs_yaw_deg: window.pooled_max_abs("yaw_deg"),
        ball_pass_jitter: passages.map(|p| p.jitter),
        ball_pass_interval_s: passages.map(|p| p.mean_interval),
        vibration: crate::vibration::summarise(&signal, 0, case.outer_ring.is_some()),
        surface_lines: crate::vibration::surface_lines(
            &signal,
            &characteristic,
            balls,
            &case.surface,
        ),
        spall_growth: spall_growth(model, t_end, characteristic.bpfo),
        sensor: crate::vibration::sensor_summary(&signal, model.sensor()),
        power: crate::power_channels::summarise(
            window,
            model.parameters().drive.as_ref().map(|d| d.inertia),
            case.lubrication_note(),
        ),
        thermal_coupling: model
            .thermal()
            .map(crate::power_channels::ThermalRunSummary::from),
        drive_work_j: energy.drive,
        film_work_j: energy.film_work,
        dissipated_energy_j: energy.dissipated,
        mechanical_energy_change_j: energy.delta_e,
        energy_balance_error_j: energy.imbalance,
        energy_balance_relative_error: energy.relative_error,
        accuracy: crate::accuracy::assess(
            energy.relative_error,
            energy.imbalance,
            energy.drive,
            settings.integrator,
            settings.relative_tolerance,
            settings.energy_tolerance,
        ),
        window_halves: Vec::new(),
        cage_freedom_m: model.parameters().cage.radial_freedom(),
    }
}

/// A sensor record within this many times its accelerometer's noise RMS
/// is left out of `--verify`'s comparison.
const SENSOR_NOISE_FACTOR: f64 = 2.0;

/// A cage whose mean whirl radius is below this fraction of its radial
/// freedom (`Summary::cage_freedom_m`) runs centred: `--verify` does not
/// compare its whirl (the default case at 2000 rpm: 0.08 µm in a
/// freedom of 87.5 µm, moved 22 % by the finer traction grid).
const CENTRED_WHIRL: f64 = 0.01;

/// The quantities `--verify` compares, their limits and the magnitude
/// below which a value is not compared.
fn compared(summary: &Summary) -> Vec<(&'static str, f64, f64, f64)> {
    let v = &summary.vibration;
    let (means, vibration) = (VERIFY_LIMIT_MEANS, VERIFY_LIMIT_VIBRATION);
    let zero = 1e-12;
    let noise_mm_s = VIBRATION_NOISE_FACTOR * summary.relative_tolerance.unwrap_or(0.0);
    let mut out = vec![
        (
            "mean_cage_speed_rpm",
            summary.mean_cage_speed_rpm,
            means,
            zero,
        ),
        ("mean_load_inner_n", summary.mean_load_inner_n, means, zero),
        ("max_load_inner_n", summary.max_load_inner_n, means, zero),
        ("mean_load_outer_n", summary.mean_load_outer_n, means, zero),
        ("max_load_outer_n", summary.max_load_outer_n, means, zero),
        // The exact mean (the dissipated energy's increase over the
        // window), not the mean of the sampled components: impacts make
        // those depend on where the samples fall.
        (
            "mean_dissipated_power_w",
            summary.power.mean_dissipated_power_w,
            means,
            zero,
        ),
    ];
    for (key, value) in v.rms_values() {
        out.push((key, value, vibration, noise_mm_s.max(zero)));
    }
    // Envelope lines of a run with a spall; a line below a tenth of the
    // strongest is the spectrum's floor, not a signature. A smooth
    // bearing's lines (a run with a sensor) are all floor: the sensor's
    // noise and the integration's.
    if let Some(envelope) = summary
        .surface_lines
        .envelope_lines
        .as_ref()
        .filter(|_| summary.surface_lines.spall)
    {
        let strongest = envelope
            .lines
            .iter()
            .map(|l| l.amplitude_m_s2)
            .fold(0.0, f64::max);
        for (line, &(_, key)) in envelope.lines.iter().zip(&crate::vibration::ENVELOPE_LINES) {
            out.push((
                key,
                line.amplitude_m_s2,
                vibration,
                (0.1 * strongest).max(zero),
            ));
        }
    }
    // The housing sensor's record (its noise is the same draw in both
    // runs). Within twice the accelerometer's noise the record is mostly
    // that noise: what differs is a signal the sensor cannot resolve.
    if let Some(sensor) = &summary.sensor {
        out.push((
            "sensor.rms_m_s2",
            sensor.rms_m_s2,
            vibration,
            (SENSOR_NOISE_FACTOR * sensor.noise_rms_m_s2).max(zero),
        ));
    }
    // A whirl below the position tolerance (rtol × 1 µm) is noise too;
    // one within CENTRED_WHIRL of the cage's freedom is a centred cage,
    // whose relative change says nothing.
    let noise_m = 1e-6 * VIBRATION_NOISE_FACTOR * summary.relative_tolerance.unwrap_or(0.0);
    let centred_m = CENTRED_WHIRL * summary.cage_freedom_m;
    out.push((
        "cage_whirl_radius_mean_m",
        v.cage_whirl_radius_mean_m,
        vibration,
        noise_m.max(centred_m).max(zero),
    ));
    out
}

/// A run's value of a quantity `--verify` compares (None: not compared
/// in this run).
pub fn compared_value(summary: &Summary, key: &str) -> Option<f64> {
    compared(summary)
        .into_iter()
        .find(|(k, ..)| *k == key)
        .map(|(_, value, ..)| value)
}

/// Compares a run with its verifying run. Quantities below their noise
/// magnitude in both runs are left out: a planar run's axial vibration, an
/// unloaded ring, the integration noise of a bearing without vibration.
pub fn verify(
    run: &Summary,
    reference: &Summary,
    directory: String,
    energy_tolerance: Option<f64>,
    traction_grid: Option<String>,
) -> Verification {
    let mut changes = Vec::new();
    let mut worst: f64 = 0.0;
    for ((key, value, limit, noise), (_, reference_value, _, _)) in
        compared(run).into_iter().zip(compared(reference))
    {
        let quiet = value.abs() < noise && reference_value.abs() < noise;
        if !value.is_finite() || !reference_value.is_finite() || quiet || reference_value == 0.0 {
            continue;
        }
        let relative_change = (value - reference_value).abs() / reference_value.abs();
        worst = worst.max(relative_change / limit);
        let window_spread = Change::window_spread(&run.window_halves, key, value);
        changes.push(Change {
            key: key.into(),
            value,
            reference: reference_value,
            relative_change,
            limit,
            window_spread,
            grid_change: None,
        });
    }
    let cause = Verification::cause_of(&changes);
    Verification {
        relative_tolerance: reference.relative_tolerance,
        energy_tolerance,
        traction_grid,
        directory,
        wall_time_s: reference.wall_time_s,
        energy_balance_relative_error: reference.energy_balance_relative_error,
        changes,
        worst_ratio_to_limit: worst,
        status: if worst <= 1.0 { "ok" } else { "warning" },
        cause,
    }
}
