//! Vibration and cage-whirl quantities of a run for `summary.json`
//! (docs/model.md §9; keys in docs/cli.md): vibration velocity RMS of the rings in
//! the ISO 20816-1 band 10–1000 Hz from the recorded velocities, and the
//! cage-whirl metrics of [`rolldyn::signal::whirl`] (orbit radius, whirl
//! speed, Deng et al. 2022's σ), all over the summary's averaging window;
//! for a run with a spall, the envelope-spectrum amplitudes of the
//! characteristic lines (the diagnostic signature, docs/signal.md).

use rolldyn::signal::{
    CharacteristicFrequencies, Window, band_rms, envelope_spectrum, whirl_metrics,
};
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

/// The channel whose envelope spectrum the summary reports: the inner
/// ring's vertical acceleration (the accelerometer direction of the CWRU
/// records; the presets' radial load acts along z).
pub const ENVELOPE_CHANNEL: &str = "inner_ring_acceleration_z_m_s2";

/// The characteristic lines whose envelope amplitudes are reported, and
/// their keys under `--verify`.
pub const ENVELOPE_LINES: [(&str, &str); 4] = [
    ("f_c", "envelope_lines.f_c"),
    ("BPFO", "envelope_lines.BPFO"),
    ("BPFI", "envelope_lines.BPFI"),
    ("2×BSF", "envelope_lines.2×BSF"),
];

/// One line of the envelope spectrum.
#[derive(Serialize, Clone, Debug)]
pub struct EnvelopeLine {
    pub name: &'static str,
    pub frequency_hz: f64,
    /// Largest envelope amplitude within 1.5 bins of the line \[m/s²\].
    pub amplitude_m_s2: f64,
}

/// The envelope spectrum's characteristic lines over the averaging window.
#[derive(Serialize, Clone, Debug)]
pub struct EnvelopeLines {
    pub channel: &'static str,
    /// Band-pass before the envelope \[Hz\]: 0.1–0.4 of the sample rate,
    /// as `rolldyn spectrum --kind envelope`.
    pub band_hz: [f64; 2],
    pub resolution_hz: f64,
    pub lines: Vec<EnvelopeLine>,
}

/// The envelope lines of [`ENVELOPE_CHANNEL`] over samples `from..` of
/// `series` at the lines of `characteristic`; None when the channel is
/// missing or the record is shorter than 64 samples.
pub fn envelope_lines(
    series: &TimeSeries,
    from: usize,
    characteristic: &CharacteristicFrequencies,
) -> Option<EnvelopeLines> {
    let record = series.column(ENVELOPE_CHANNEL)?.get(from..)?;
    let time = series.column("time_s")?.get(from..)?;
    let (&first, &last) = (time.first()?, time.last()?);
    if record.len() < 64 || last <= first {
        return None;
    }
    let sample_rate = (time.len() - 1) as f64 / (last - first);
    let band = (0.1 * sample_rate, 0.4 * sample_rate);
    let spectrum = envelope_spectrum(record, sample_rate, band, Window::Hann).ok()?;
    let resolution = spectrum.resolution();
    let frequencies = [
        characteristic.cage,
        characteristic.bpfo,
        characteristic.bpfi,
        2.0 * characteristic.ball_spin,
    ];
    let lines = ENVELOPE_LINES
        .iter()
        .zip(frequencies)
        .map(|(&(name, _), frequency)| {
            let amplitude = spectrum
                .frequency
                .iter()
                .zip(&spectrum.value)
                .filter(|(f, _)| (**f - frequency).abs() <= 1.5 * resolution)
                .map(|(_, v)| *v)
                .fold(0.0, f64::max);
            EnvelopeLine {
                name,
                frequency_hz: frequency,
                amplitude_m_s2: amplitude,
            }
        })
        .collect();
    Some(EnvelopeLines {
        channel: ENVELOPE_CHANNEL,
        band_hz: [band.0, band.1],
        resolution_hz: resolution,
        lines,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 2 kHz carrier modulated at the outer-race pass frequency (the
    /// impacts' signature): the envelope line at BPFO has the modulation's
    /// amplitude, the other lines next to none.
    #[test]
    fn envelope_lines_find_the_modulation() {
        let lines = CharacteristicFrequencies {
            shaft: 30.0,
            cage: 12.0,
            bpfo: 100.0,
            bpfi: 170.0,
            ball_spin: 70.0,
        };
        let (rate, modulation) = (10_000.0, 0.5);
        let mut series = TimeSeries::default();
        series.channel("time_s", "s");
        series.channel(ENVELOPE_CHANNEL, "m/s^2");
        for i in 0..5000 {
            let t = i as f64 / rate;
            let carrier = (std::f64::consts::TAU * 2000.0 * t).sin();
            let envelope = 1.0 + modulation * (std::f64::consts::TAU * lines.bpfo * t).cos();
            series.push(&[t, envelope * carrier]);
        }
        let found = envelope_lines(&series, 0, &lines).unwrap();
        assert_eq!(found.band_hz, [1000.0, 4000.0]);
        let amplitude = |name: &str| {
            found
                .lines
                .iter()
                .find(|l| l.name == name)
                .unwrap()
                .amplitude_m_s2
        };
        assert!(
            (amplitude("BPFO") - modulation).abs() < 0.05 * modulation,
            "{}",
            amplitude("BPFO")
        );
        for other in ["BPFI", "2×BSF"] {
            assert!(
                amplitude(other) < 0.02 * modulation,
                "{other}: {}",
                amplitude(other)
            );
        }
        // Too short a record: no lines.
        let mut short = TimeSeries::default();
        short.channel("time_s", "s");
        short.channel(ENVELOPE_CHANNEL, "m/s^2");
        for i in 0..10 {
            short.push(&[i as f64 / rate, 0.0]);
        }
        assert!(envelope_lines(&short, 0, &lines).is_none());
    }
}
