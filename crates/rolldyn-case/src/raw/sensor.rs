//! `[sensor]`: an accelerometer on the housing and its acquisition, as
//! written.

use crate::units::*;
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// An accelerometer on the bearing housing and its acquisition
/// (docs/signal.md, "Sensor chain"; dynamic engine). The run records
/// `sensor_acceleration_m_s2` (acquired) and
/// `sensor_housing_acceleration_m_s2` (the housing's true acceleration at
/// the sensor) at `output.sample_rate`.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawSensor {
    /// Direction of the accelerometer's axis in the radial plane, as a
    /// ball azimuth (cos φ e_y + sin φ e_z). Default "90 deg": +z, a
    /// vertical accelerometer on top of the housing (12 o'clock).
    pub direction: Option<Quantity<Angle>>,
    /// The housing's structural modes seen from the bearing seat. Default:
    /// one mode of 3 kHz, damping ratio 0.05, modal mass 1 kg (assumed).
    pub modes: Option<Vec<RawHousingMode>>,
    /// The accelerometer's white noise as an RMS over 0 to half the
    /// sample rate, before the anti-alias filter. Default "0.01 m/s^2"
    /// (about 1 mg).
    pub noise: Option<Quantity<Acceleration>>,
    /// Seed of the noise (default 0).
    pub seed: Option<u64>,
    /// Order of the anti-alias Butterworth low-pass, 1–8 (default 8).
    pub anti_alias_order: Option<u32>,
    /// Cutoff (−3 dB) of the anti-alias filter, below half the sample rate
    /// (default 0.4 × output.sample_rate).
    pub anti_alias_cutoff: Option<Quantity<Frequency>>,
    /// The ADC's range ± (default "500 g").
    pub full_scale: Option<Quantity<Acceleration>>,
    /// The ADC's resolution in bits, 1–32 (default 24).
    pub adc_bits: Option<u32>,
}

/// One structural mode of the housing: a single-degree-of-freedom
/// oscillator, isotropic in the radial plane, at the bearing seat.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawHousingMode {
    /// Natural frequency.
    pub frequency: Option<Quantity<Frequency>>,
    /// Damping ratio ζ, between 0 and 1 (default 0.05).
    pub damping_ratio: Option<f64>,
    /// Modal mass at the bearing seat.
    pub mass: Option<Quantity<Mass>>,
}
