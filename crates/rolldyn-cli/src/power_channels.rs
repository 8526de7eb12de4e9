//! Friction power of a run by component (MODEL §10; issue 13): the
//! time-series channels and the `summary.json` means of the dynamic
//! model's exact dissipation split ([`rolldyn::power::dissipation`]), and
//! the drive (friction) torque on the inner ring. Keys in docs/cli.md.

use rolldyn::power::Dissipation;
use rolldyn_io::TimeSeries;
use serde::Serialize;
use std::collections::BTreeMap;

/// Prefix of the power channels: `power_<component>_w`.
const PREFIX: &str = "power_";

/// The components in channel order: `inner_<mechanism>`,
/// `outer_<mechanism>`, then the other force elements.
fn components(p: &Dissipation) -> impl Iterator<Item = (String, f64)> {
    let contact = |ring: &'static str, losses: [(&'static str, f64); 6]| {
        losses
            .into_iter()
            .map(move |(name, value)| (format!("{ring}_{name}"), value))
    };
    contact("inner", p.inner.named())
        .chain(contact("outer", p.outer.named()))
        .chain(p.others().into_iter().map(|(n, v)| (n.to_string(), v)))
}

/// Adds the power channels and the friction torque to `series`.
pub fn add_channels(series: &mut TimeSeries) {
    for (name, _) in components(&Dissipation::default()) {
        series.channel(format!("{PREFIX}{name}_w"), "W");
    }
    series.channel("power_total_w", "W");
    series.channel("friction_torque_n_m", "N*m");
}

/// Appends one sample of the channels of [`add_channels`] to `row`.
pub fn push(row: &mut Vec<f64>, p: &Dissipation) {
    row.extend(components(p).map(|(_, v)| v));
    row.push(p.total());
    row.push(p.drive_torque);
}

/// Power keys of `summary.json`, means over the averaging window.
#[derive(Serialize)]
pub struct PowerSummary {
    /// Σ of the component means \[W\].
    pub mean_power_loss_w: f64,
    /// Dissipated energy over the window / its length (the energy
    /// balance's accumulator, exact between samples) \[W\].
    pub mean_dissipated_power_w: f64,
    /// Friction torque on the inner ring \[N·m\].
    pub mean_friction_torque_n_m: f64,
    /// Mean of each component's channel \[W\].
    pub mean_power_loss_by_component_w: BTreeMap<String, f64>,
}

/// The keys over samples `from..` of `series`.
pub fn summarise(series: &TimeSeries, from: usize) -> PowerSummary {
    let window = |name: &str| {
        series
            .column(name)
            .and_then(|c| c.get(from..))
            .unwrap_or(&[])
    };
    let mean = |name: &str| {
        let c = window(name);
        if c.is_empty() {
            0.0
        } else {
            c.iter().sum::<f64>() / c.len() as f64
        }
    };
    let by_component: BTreeMap<String, f64> = components(&Dissipation::default())
        .map(|(name, _)| {
            let m = mean(&format!("{PREFIX}{name}_w"));
            (name, m)
        })
        .collect();
    let (time, energy) = (window("time_s"), window("dissipated_energy_j"));
    let mean_dissipated_power_w = match (time, energy) {
        ([t0, .., t1], [e0, .., e1]) if t1 > t0 => (e1 - e0) / (t1 - t0),
        _ => 0.0,
    };
    PowerSummary {
        mean_power_loss_w: by_component.values().sum(),
        mean_dissipated_power_w,
        mean_friction_torque_n_m: mean("friction_torque_n_m"),
        mean_power_loss_by_component_w: by_component,
    }
}
