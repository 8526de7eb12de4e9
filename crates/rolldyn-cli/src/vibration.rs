//! Vibration and cage-whirl quantities of a run for `summary.json`
//! (docs/model.md §9; keys in docs/cli.md): vibration velocity RMS of the rings in
//! the ISO 20816-1 band 10–1000 Hz from the recorded velocities, and the
//! cage-whirl metrics of [`rolldyn::signal::whirl`] (orbit radius, whirl
//! speed, Deng et al. 2022's σ), all over the summary's averaging window.

use rolldyn::signal::{band_rms, whirl_metrics};
use rolldyn_io::TimeSeries;
use serde::Serialize;

/// Band of the vibration velocity RMS \[Hz\] (ISO 20816-1).
pub const VELOCITY_BAND: (f64, f64) = (10.0, 1000.0);

const RPM: f64 = std::f64::consts::TAU / 60.0;

/// Vibration and whirl keys of `summary.json`.
#[derive(Serialize)]
pub struct VibrationSummary {
    pub cage_whirl_radius_mean_m: f64,
    pub cage_whirl_radius_max_m: f64,
    pub cage_whirl_speed_rpm: f64,
    pub cage_whirl_speed_ratio: Option<f64>,
    pub cage_whirl_sigma: f64,
    pub velocity_rms_band_hz: [f64; 2],
    pub inner_ring_velocity_rms_x_mm_s: Option<f64>,
    pub inner_ring_velocity_rms_y_mm_s: Option<f64>,
    pub inner_ring_velocity_rms_z_mm_s: Option<f64>,
    pub outer_ring_velocity_rms_y_mm_s: Option<f64>,
    pub outer_ring_velocity_rms_z_mm_s: Option<f64>,
}

impl VibrationSummary {
    /// The ring velocity RMS values that were computed, by summary key.
    pub fn rms_values(&self) -> Vec<(&'static str, f64)> {
        [
            (
                "inner_ring_velocity_rms_x_mm_s",
                self.inner_ring_velocity_rms_x_mm_s,
            ),
            (
                "inner_ring_velocity_rms_y_mm_s",
                self.inner_ring_velocity_rms_y_mm_s,
            ),
            (
                "inner_ring_velocity_rms_z_mm_s",
                self.inner_ring_velocity_rms_z_mm_s,
            ),
            (
                "outer_ring_velocity_rms_y_mm_s",
                self.outer_ring_velocity_rms_y_mm_s,
            ),
            (
                "outer_ring_velocity_rms_z_mm_s",
                self.outer_ring_velocity_rms_z_mm_s,
            ),
        ]
        .into_iter()
        .filter_map(|(key, value)| value.map(|v| (key, v)))
        .collect()
    }
}

/// The keys over samples `from..` of `series`; `outer_ring` when the outer
/// ring moves (else its RMS keys are null).
pub fn summarise(series: &TimeSeries, from: usize, outer_ring: bool) -> VibrationSummary {
    let window = |name: &str| {
        series
            .column(name)
            .and_then(|c| c.get(from..))
            .unwrap_or(&[])
    };
    let time = window("time_s");
    let whirl = whirl_metrics(
        time,
        window("cage_y_m"),
        window("cage_z_m"),
        window("cage_velocity_y_m_s"),
        window("cage_velocity_z_m_s"),
    );
    let cage_speed = {
        let c = window("cage_speed_rpm");
        if c.is_empty() {
            0.0
        } else {
            c.iter().sum::<f64>() / c.len() as f64
        }
    };
    let sample_rate = match time {
        [first, .., last] if last > first => (time.len() - 1) as f64 / (last - first),
        _ => 0.0,
    };
    let band = (VELOCITY_BAND.0, VELOCITY_BAND.1.min(0.5 * sample_rate));
    let rms = |name: &str| -> Option<f64> {
        (band.1 > band.0)
            .then(|| band_rms(window(name), sample_rate, band).ok())
            .flatten()
            .map(|v| 1e3 * v)
    };
    let whirl_rpm = whirl.whirl_speed / RPM;
    VibrationSummary {
        cage_whirl_radius_mean_m: whirl.orbit_radius_mean,
        cage_whirl_radius_max_m: whirl.orbit_radius_max,
        cage_whirl_speed_rpm: whirl_rpm,
        cage_whirl_speed_ratio: (cage_speed != 0.0).then(|| whirl_rpm / cage_speed),
        cage_whirl_sigma: whirl.sigma,
        velocity_rms_band_hz: [band.0, band.1.max(band.0)],
        inner_ring_velocity_rms_x_mm_s: rms("inner_ring_velocity_x_m_s"),
        inner_ring_velocity_rms_y_mm_s: rms("inner_ring_velocity_y_m_s"),
        inner_ring_velocity_rms_z_mm_s: rms("inner_ring_velocity_z_m_s"),
        outer_ring_velocity_rms_y_mm_s: outer_ring
            .then(|| rms("outer_ring_velocity_y_m_s"))
            .flatten(),
        outer_ring_velocity_rms_z_mm_s: outer_ring
            .then(|| rms("outer_ring_velocity_z_m_s"))
            .flatten(),
    }
}
