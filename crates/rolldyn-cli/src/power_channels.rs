//! Friction power of a run by component (docs/model.md §10): the
//! time-series channels and the `summary.json` means of the dynamic
//! model's exact dissipation split ([`rolldyn::power::dissipation`]), and
//! the drive (friction) torque on the inner ring; with `thermal.run_coupling`
//! the thermal network coupled to the run (docs/thermal.md): its node
//! temperatures and the EHL viscosity as channels, and a summary. Keys in
//! docs/cli.md.

use rolldyn::dynamics::{BearingModel, ThermalCoupling};
use rolldyn::power::Dissipation;
use rolldyn::traction::TractionModel;
use rolldyn_io::TimeSeries;
use serde::Serialize;
use std::collections::BTreeMap;

/// Prefix of the power channels: `power_<component>_w`.
const PREFIX: &str = "power_";

/// The components in channel order: `inner_<mechanism>`,
/// `outer_<mechanism>`, then the other force elements.
fn components(p: &Dissipation) -> impl Iterator<Item = (String, f64)> {
    let contact = |ring: &'static str, losses: [(&'static str, f64); 7]| {
        losses
            .into_iter()
            .map(move |(name, value)| (format!("{ring}_{name}"), value))
    };
    contact("inner", p.inner.named())
        .chain(contact("outer", p.outer.named()))
        .chain(p.others().into_iter().map(|(n, v)| (n.to_string(), v)))
}

/// Temperature channels of a coupled run: `temperature_<node>_c`.
const TEMPERATURE_NODES: [&str; 5] = ["ball", "inner_ring", "outer_ring", "housing", "oil"];

/// Adds the power channels and the friction torque to `series`, and with
/// `thermal` the temperatures and the EHL viscosity.
pub fn add_channels(series: &mut TimeSeries, thermal: bool) {
    for (name, _) in components(&Dissipation::default()) {
        series.channel(format!("{PREFIX}{name}_w"), "W");
    }
    series.channel("power_total_w", "W");
    series.channel("friction_torque_n_m", "N*m");
    if thermal {
        for node in TEMPERATURE_NODES {
            series.channel(format!("temperature_{node}_c"), "degC");
        }
        series.channel("oil_viscosity_pa_s", "Pa*s");
    }
}

/// Appends one sample of the channels of [`add_channels`] to `row`.
pub fn push(row: &mut Vec<f64>, p: &Dissipation, model: &BearingModel) {
    row.extend(components(p).map(|(_, v)| v));
    row.push(p.total());
    row.push(p.friction_torque);
    if let Some(t) = model.thermal() {
        for node in TEMPERATURE_NODES {
            row.push(t.temperature(node).unwrap_or(f64::NAN) - KELVIN);
        }
        let eta = match &model.parameters().traction {
            TractionModel::Ehl(e) => e.lubricant.viscosity,
            _ => f64::NAN,
        };
        row.push(eta);
    }
}

const KELVIN: f64 = 273.15;

/// The run's thermal coupling in `summary.json`.
#[derive(Serialize)]
pub struct ThermalRunSummary {
    pub updates: usize,
    pub update_interval_s: f64,
    pub initial_temperatures_c: BTreeMap<&'static str, f64>,
    pub final_temperatures_c: BTreeMap<&'static str, f64>,
    /// Largest node-temperature rate at the last update \[K/s\].
    pub largest_rate_k_per_s: f64,
}

impl From<&ThermalCoupling> for ThermalRunSummary {
    fn from(t: &ThermalCoupling) -> Self {
        Self {
            updates: t.updates(),
            update_interval_s: t.interval(),
            initial_temperatures_c: crate::thermal_nodes::temperatures(t.initial_temperatures()),
            final_temperatures_c: crate::thermal_nodes::temperatures(t.temperatures()),
            largest_rate_k_per_s: t.largest_rate(),
        }
    }
}

/// Power keys of `summary.json`, means over the averaging window.
#[derive(Serialize)]
pub struct PowerSummary {
    /// Dissipated energy over the window / its length \[W\] (the same as
    /// `mean_dissipated_power_w`: the power the bearing turned into heat,
    /// impacts included).
    pub mean_power_loss_w: f64,
    /// Dissipated energy over the window / its length (the energy
    /// balance's accumulator, exact between samples) \[W\].
    pub mean_dissipated_power_w: f64,
    /// Σ of the component means \[W\]: the samples' split, which misses
    /// what happens between samples (impacts).
    pub mean_sampled_power_loss_w: f64,
    /// Friction torque on the inner ring from the work the drive did
    /// over the window per radian turned \[N·m\] (module doc).
    pub mean_friction_torque_n_m: f64,
    /// Mean of the sampled `friction_torque_n_m` channel \[N·m\].
    pub mean_sampled_friction_torque_n_m: f64,
    /// Mean of each component's channel \[W\].
    pub mean_power_loss_by_component_w: BTreeMap<String, f64>,
    /// Set when a lubricated case states no lubrication method (no
    /// churning counted).
    pub lubrication_note: Option<String>,
}

/// The keys over the averaging window. `rotor_inertia` is the polar
/// inertia J of a torque-driven inner ring (None: its speed is
/// prescribed).
///
/// The mean friction torque is the work that turned the inner ring over
/// the window per radian, M̄ = (ΔW_drive − Δ(½ J ω²)) / ∫ω dt, with
/// ∫ω dt = ω̄ Δt from the sampled speed (exact at a prescribed constant
/// speed): the accumulated drive work is exact between samples, so the
/// impacts' impulses count, which a mean of the sampled moment misses.
/// The drive work also holds the work of time-varying loads and a cage
/// unbalance, whose mean over whole periods vanishes.
pub fn summarise(
    window: &crate::run_stats::Window,
    rotor_inertia: Option<f64>,
    lubrication_note: Option<String>,
) -> PowerSummary {
    let by_component: BTreeMap<String, f64> = components(&Dissipation::default())
        .map(|(name, _)| {
            let m = window.mean(&format!("{PREFIX}{name}_w"));
            (name, m)
        })
        .collect();
    let [t0, t1] = window.span();
    let span = t1 - t0;
    let rate = |name: &str| {
        if span > 0.0 {
            (window.last(name) - window.first(name)) / span
        } else {
            0.0
        }
    };
    let mean_dissipated_power_w = rate("dissipated_energy_j");
    let rpm = std::f64::consts::TAU / 60.0;
    let mean_speed = window.mean("inner_ring_speed_rpm") * rpm;
    let rotor_power = match rotor_inertia {
        Some(j) if span > 0.0 => {
            let (w0, w1) = (
                window.first("inner_ring_speed_rpm") * rpm,
                window.last("inner_ring_speed_rpm") * rpm,
            );
            0.5 * j * (w1 * w1 - w0 * w0) / span
        }
        _ => 0.0,
    };
    let mean_friction_torque_n_m = if mean_speed != 0.0 {
        (rate("drive_work_j") - rotor_power) / mean_speed.abs()
    } else {
        0.0
    };
    PowerSummary {
        mean_power_loss_w: mean_dissipated_power_w,
        mean_dissipated_power_w,
        mean_sampled_power_loss_w: by_component.values().sum(),
        mean_friction_torque_n_m,
        mean_sampled_friction_torque_n_m: window.mean("friction_torque_n_m"),
        mean_power_loss_by_component_w: by_component,
        lubrication_note,
    }
}
