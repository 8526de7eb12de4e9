//! `[sensor]`: the accelerometer on the housing and its acquisition,
//! checked with the key of the offending entry; the defaults are the ones
//! docs/case-format.md and docs/signal.md state.

use super::{Invalid, checked, non_negative, positive};
use crate::raw::RawSensor;
use rolldyn::signal::sensor::{HousingMode, SensorSpec};

/// The default housing mode (an assumption, stated in docs/signal.md): a
/// bearing-housing resonance in the band where envelope analysis of small
/// bearings usually demodulates.
pub const DEFAULT_MODE: HousingMode = HousingMode {
    frequency: 3000.0,
    damping_ratio: 0.05,
    mass: 1.0,
};

/// Default noise RMS \[m/s²\].
pub const DEFAULT_NOISE: f64 = 0.01;

/// Default ADC range ± \[m/s²\] (500 g: a 10 mV/g accelerometer; the
/// ±50 g of a 100 mV/g one clips the impacts of a run's start).
pub const DEFAULT_FULL_SCALE: f64 = 500.0 * 9.806_65;

/// The sensor of `[sensor]` acquiring at `sample_rate` \[Hz\] (the run's
/// output rate), or None without the section.
pub(super) fn sensor(
    raw: Option<&RawSensor>,
    sample_rate: f64,
) -> Result<Option<SensorSpec>, Invalid> {
    let Some(raw) = raw else {
        return Ok(None);
    };
    let modes = match &raw.modes {
        None => vec![DEFAULT_MODE],
        Some(modes) => modes
            .iter()
            .enumerate()
            .map(|(i, m)| {
                let key = |name: &str| format!("sensor.modes[{i}].{name}");
                let needed = |name: &str, example: &str| {
                    Invalid::new(
                        key(name),
                        None,
                        format!("a housing mode needs its {name}, e.g. {example}"),
                    )
                };
                let damping_ratio = m.damping_ratio.unwrap_or(DEFAULT_MODE.damping_ratio);
                if !(damping_ratio > 0.0 && damping_ratio < 1.0) {
                    return Err(Invalid::new(
                        key("damping_ratio"),
                        Some(damping_ratio.to_string()),
                        "must lie between 0 and 1 (an underdamped mode; housings: 0.01–0.1)",
                    ));
                }
                Ok(HousingMode {
                    frequency: checked(&key("frequency"), &m.frequency, positive)?
                        .ok_or_else(|| needed("frequency", "\"3 kHz\""))?,
                    damping_ratio,
                    mass: checked(&key("mass"), &m.mass, positive)?
                        .ok_or_else(|| needed("mass", "\"1 kg\""))?,
                })
            })
            .collect::<Result<Vec<_>, _>>()?,
    };
    if modes.is_empty() {
        return Err(Invalid::new(
            "sensor.modes",
            Some("[]".into()),
            "the housing needs at least one mode (leave the key out for the default)",
        ));
    }
    let spec = SensorSpec {
        direction: raw
            .direction
            .as_ref()
            .map_or(0.5 * std::f64::consts::PI, |d| d.si),
        modes,
        noise_rms: checked("sensor.noise", &raw.noise, non_negative)?.unwrap_or(DEFAULT_NOISE),
        seed: raw.seed.unwrap_or(0),
        anti_alias_order: raw.anti_alias_order.unwrap_or(8),
        anti_alias_cutoff: checked("sensor.anti_alias_cutoff", &raw.anti_alias_cutoff, positive)?
            .unwrap_or(0.4 * sample_rate),
        full_scale: checked("sensor.full_scale", &raw.full_scale, positive)?
            .unwrap_or(DEFAULT_FULL_SCALE),
        adc_bits: raw.adc_bits.unwrap_or(24),
        sample_rate,
    };
    spec.validate().map_err(|e| {
        let value = match e.field {
            "sensor.anti_alias_cutoff" => raw.anti_alias_cutoff.as_ref().map(|q| q.to_string()),
            _ => None,
        }
        .or(Some(e.value.clone()));
        Invalid::new(e.field, value, e.rule)
    })?;
    Ok(Some(spec))
}
