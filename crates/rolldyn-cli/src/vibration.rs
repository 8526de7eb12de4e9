//! Vibration and cage-whirl quantities of a run for `summary.json`
//! (docs/model.md §9; keys in docs/cli.md): vibration velocity RMS of the rings in
//! the ISO 20816-1 band 10–1000 Hz from the interval means of the recorded
//! displacements (an anti-alias filter: docs/signal.md, "Velocity RMS";
//! [`rolldyn::signal::band_velocity_rms_of_displacement`]), and the
//! cage-whirl metrics of [`rolldyn::signal::whirl`] (orbit radius, whirl
//! speed, Deng et al. 2022's σ), all over the summary's averaging window;
//! for a run with a spall, the envelope-spectrum amplitudes of the
//! characteristic lines (the diagnostic signature, docs/signal.md); for a
//! run with waviness, the amplitude spectrum at the lines its orders
//! excite (Deng et al. 2022 Table 2, [`rolldyn::kinematics::waviness_frequencies`]).

use rolldyn::kinematics::{Frequencies, Motion, WavyPart, waviness_frequencies};
use rolldyn::signal::{
    CharacteristicFrequencies, DEFAULT_ENVELOPE_BAND, Spectrum, Window, amplitude_spectrum,
    band_velocity_rms_of_displacement, default_envelope_band, envelope_band_holds,
    envelope_spectrum, whirl_metrics,
};
use rolldyn::surface::{SurfaceModel, Waviness};
use rolldyn_io::TimeSeries;
use serde::Serialize;
use std::collections::BTreeSet;

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
    let rms = |displacement: &str| -> Option<f64> {
        (band.1 > band.0)
            .then(|| {
                band_velocity_rms_of_displacement(window(displacement), sample_rate, band).ok()
            })
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
        inner_ring_velocity_rms_x_mm_s: rms("inner_ring_x_m"),
        inner_ring_velocity_rms_y_mm_s: rms("inner_ring_y_m"),
        inner_ring_velocity_rms_z_mm_s: rms("inner_ring_z_m"),
        outer_ring_velocity_rms_y_mm_s: outer_ring.then(|| rms("outer_ring_y_m")).flatten(),
        outer_ring_velocity_rms_z_mm_s: outer_ring.then(|| rms("outer_ring_z_m")).flatten(),
    }
}

/// The channel whose envelope spectrum the summary reports without a
/// sensor: the inner ring's vertical acceleration (the accelerometer
/// direction of the CWRU records; the presets' radial load acts along z).
pub const ENVELOPE_CHANNEL: &str = "inner_ring_acceleration_z_m_s2";

/// The acquired channel of a run with `[sensor]`: the one its summary
/// analyses.
pub const SENSOR_CHANNEL: &str = "sensor_acceleration_m_s2";

/// The channel the summary analyses in `series`: the sensor's when the run
/// has one, else [`ENVELOPE_CHANNEL`].
pub fn analysed_channel(series: &TimeSeries) -> &'static str {
    if series.column(SENSOR_CHANNEL).is_some() {
        SENSOR_CHANNEL
    } else {
        ENVELOPE_CHANNEL
    }
}

/// The condition indicators of the sensor's record over the averaging
/// window (`sensor` in `summary.json`, docs/cli.md).
#[derive(Serialize, Clone, Debug)]
pub struct SensorSummary {
    /// RMS about the mean \[m/s²\].
    pub rms_m_s2: f64,
    /// Largest |a − mean| \[m/s²\].
    pub peak_m_s2: f64,
    /// Peak / RMS; None (null) for a constant record (no noise, no
    /// vibration), whose ratios are 0/0.
    pub crest_factor: Option<f64>,
    /// m₄ / m₂² (3 for Gaussian noise; impacts raise it); None as the
    /// crest factor.
    pub kurtosis: Option<f64>,
    /// Samples of the whole run beyond the ADC's range (clipped).
    pub clipped_samples: u64,
    /// The accelerometer's white noise, RMS over 0 to half the sample
    /// rate (`sensor.noise`) \[m/s²\]: a record whose RMS is within twice
    /// it reads mostly its own noise.
    pub noise_rms_m_s2: f64,
}

/// The sensor's indicators over `series` (the window); None without a
/// sensor or with fewer than 2 samples.
pub fn sensor_summary(
    series: &TimeSeries,
    sensor: Option<&rolldyn::signal::SensorChain>,
) -> Option<SensorSummary> {
    let sensor = sensor?;
    let record = series.column(SENSOR_CHANNEL).filter(|r| r.len() > 1)?;
    let [rms, peak, crest_factor, kurtosis] = rolldyn::signal::statistics(record);
    Some(SensorSummary {
        rms_m_s2: rms,
        peak_m_s2: peak,
        crest_factor: (rms > 0.0).then_some(crest_factor),
        kurtosis: (rms > 0.0).then_some(kurtosis),
        clipped_samples: sensor.clipped(),
        noise_rms_m_s2: sensor.spec().noise_rms,
    })
}

/// The characteristic lines whose envelope amplitudes are reported, and
/// their keys under `--verify`.
pub const ENVELOPE_LINES: [(&str, &str); 4] = [
    ("f_c", "envelope_lines.f_c"),
    ("BPFO", "envelope_lines.BPFO"),
    ("BPFI", "envelope_lines.BPFI"),
    ("2×BSF", "envelope_lines.2×BSF"),
];

/// Why the envelope band (lo, hi) \[Hz\] cannot show the impacts of the
/// bearing's fastest defect (`envelope_band_holds`), with the sample rate
/// whose default band would; None when it can.
pub fn band_warning(band: (f64, f64), lines: &CharacteristicFrequencies) -> Option<String> {
    let rate = lines.fastest_defect_rate();
    if envelope_band_holds(band, rate) || rate <= 0.0 {
        return None;
    }
    let (lo, hi) = DEFAULT_ENVELOPE_BAND;
    let needed = 2.0 * rate / (hi - lo);
    Some(format!(
        "the envelope band {:.0}–{:.0} Hz is narrower than twice the fastest defect rate ({rate:.0} Hz): \
         a resonance with its first sidebands does not fit, and the defect's lines may not show; \
         sample the run at {:.0} kHz or more (output.sample_rate; the default band is {lo}–{hi} of it), \
         or give `rolldyn spectrum` a wider --band",
        band.0,
        band.1,
        (needed / 1e3).ceil()
    ))
}

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

/// The envelope lines of the [`analysed_channel`] over samples `from..` of
/// `series` at the lines of `characteristic`; None when the channel is
/// missing or the record is shorter than 64 samples.
pub fn envelope_lines(
    series: &TimeSeries,
    from: usize,
    characteristic: &CharacteristicFrequencies,
) -> Option<EnvelopeLines> {
    let (record, sample_rate) = analysed_record(series, from)?;
    let band = default_envelope_band(sample_rate);
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
        .map(|(&(name, _), frequency)| EnvelopeLine {
            name,
            frequency_hz: frequency,
            amplitude_m_s2: peak_near(&spectrum, frequency),
        })
        .collect();
    Some(EnvelopeLines {
        channel: analysed_channel(series),
        band_hz: [band.0, band.1],
        resolution_hz: resolution,
        lines,
    })
}

/// The spectra's lines a run's surfaces call for, over the whole of
/// `series` (the summary's window).
#[derive(Serialize, Clone, Debug)]
pub struct SurfaceLines {
    /// Envelope-spectrum amplitudes of the characteristic lines (runs with
    /// a spall or a sensor; null otherwise).
    pub envelope_lines: Option<EnvelopeLines>,
    /// Amplitude spectrum at the lines the case's waviness excites (runs
    /// with waviness; null otherwise).
    pub waviness_lines: Option<WavinessLines>,
    /// The run has a spall: its envelope lines are a defect's signature,
    /// not the floor of a smooth bearing's record.
    #[serde(skip)]
    pub spall: bool,
}

/// [`envelope_lines`] for a surface with a spall or a run with a sensor,
/// and [`waviness_lines`].
pub fn surface_lines(
    series: &TimeSeries,
    characteristic: &CharacteristicFrequencies,
    ball_count: usize,
    surface: &SurfaceModel,
) -> SurfaceLines {
    let spall = surface.spalls().next().is_some();
    SurfaceLines {
        envelope_lines: (spall || series.column(SENSOR_CHANNEL).is_some())
            .then(|| envelope_lines(series, 0, characteristic))
            .flatten(),
        waviness_lines: waviness_lines(series, 0, characteristic, ball_count, surface),
        spall,
    }
}

/// The [`analysed_channel`] over samples `from..` of `series` and its
/// sample rate; None when the channel is missing or has fewer than 64
/// samples.
fn analysed_record(series: &TimeSeries, from: usize) -> Option<(&[f64], f64)> {
    let record = series.column(analysed_channel(series))?.get(from..)?;
    let time = series.column("time_s")?.get(from..)?;
    let (&first, &last) = (time.first()?, time.last()?);
    if record.len() < 64 || last <= first {
        return None;
    }
    Some((record, (time.len() - 1) as f64 / (last - first)))
}

/// The largest value of `spectrum` within 1.5 bins of `frequency`.
fn peak_near(spectrum: &Spectrum, frequency: f64) -> f64 {
    let resolution = spectrum.resolution();
    spectrum
        .frequency
        .iter()
        .zip(&spectrum.value)
        .filter(|(f, _)| (**f - frequency).abs() <= 1.5 * resolution)
        .map(|(_, v)| *v)
        .fold(0.0, f64::max)
}

/// Most waviness lines reported (the lowest frequencies).
pub const MAX_WAVINESS_LINES: usize = 40;

/// One line a waviness order excites, with the amplitude spectrum there.
#[derive(Serialize, Clone, Debug)]
pub struct WavinessLine {
    /// `outer_race`, `inner_race` or `ball`.
    pub part: &'static str,
    pub order: u32,
    pub frequency_hz: f64,
    /// Direction of the vibration the rule predicts (the channel is radial).
    pub motion: Motion,
    /// Largest amplitude within 1.5 bins of the line \[m/s²\].
    pub amplitude_m_s2: f64,
}

/// The amplitude spectrum at the lines the case's waviness excites.
#[derive(Serialize, Clone, Debug)]
pub struct WavinessLines {
    pub channel: &'static str,
    pub resolution_hz: f64,
    pub lines: Vec<WavinessLine>,
}

/// The waviness lines of the [`analysed_channel`]'s amplitude spectrum over
/// samples `from..` of `series`: every order of `surface`'s raceway
/// (radial and axial) and ball waviness, mapped to its principal
/// frequencies by Deng et al. 2022's Table 2 at the run's mean speeds
/// (`characteristic`), below the Nyquist frequency, the lowest
/// [`MAX_WAVINESS_LINES`]. None without waviness or with fewer than 64
/// samples.
pub fn waviness_lines(
    series: &TimeSeries,
    from: usize,
    characteristic: &CharacteristicFrequencies,
    ball_count: usize,
    surface: &SurfaceModel,
) -> Option<WavinessLines> {
    let orders = |parts: &mut dyn Iterator<Item = &Waviness>| -> BTreeSet<u32> {
        parts
            .flat_map(|w| {
                w.terms
                    .iter()
                    .filter(|t| t.amplitude > 0.0)
                    .map(|t| t.order)
            })
            .collect()
    };
    let parts = [
        (
            "outer_race",
            WavyPart::OuterRace,
            orders(&mut [&surface.outer.radial, &surface.outer.axial].into_iter()),
        ),
        (
            "inner_race",
            WavyPart::InnerRace,
            orders(&mut [&surface.inner.radial, &surface.inner.axial].into_iter()),
        ),
        (
            "ball",
            WavyPart::Ball,
            orders(&mut surface.balls.iter().map(|b| &b.waviness)),
        ),
    ];
    if parts.iter().all(|(_, _, o)| o.is_empty()) {
        return None;
    }
    let (record, sample_rate) = analysed_record(series, from)?;
    let spectrum = amplitude_spectrum(record, sample_rate, Window::Hann).ok()?;
    let c = characteristic;
    let frequencies = Frequencies {
        shaft_hz: c.shaft,
        outer_ring_hz: 0.0,
        contact_angle_deg: 0.0,
        cage_hz: c.cage,
        bpfo_hz: c.bpfo,
        bpfi_hz: c.bpfi,
        ball_spin_hz: c.ball_spin,
        ball_count,
    };
    let mut lines: Vec<WavinessLine> = parts
        .iter()
        .flat_map(|(name, part, orders)| {
            orders.iter().flat_map(move |&order| {
                waviness_frequencies(&frequencies, *part, order)
                    .into_iter()
                    .map(move |l| (*name, order, l))
            })
        })
        .filter(|(_, _, l)| l.frequency_hz > 0.0 && l.frequency_hz < 0.5 * sample_rate)
        .map(|(part, order, l)| WavinessLine {
            part,
            order,
            frequency_hz: l.frequency_hz,
            motion: l.motion,
            amplitude_m_s2: peak_near(&spectrum, l.frequency_hz),
        })
        .collect();
    lines.sort_by(|a, b| a.frequency_hz.total_cmp(&b.frequency_hz));
    lines.truncate(MAX_WAVINESS_LINES);
    Some(WavinessLines {
        channel: analysed_channel(series),
        resolution_hz: spectrum.resolution(),
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

    /// Waviness lines: an inner-race order Z + 1 excites a radial line at
    /// Z(f_i − f_c) + f_i, found with the amplitude of a sine there; a
    /// smooth surface gives none.
    #[test]
    fn waviness_lines_follow_the_orders() {
        use rolldyn::surface::{Waviness, WavinessTerm};
        let lines = CharacteristicFrequencies {
            shaft: 30.0,
            cage: 12.0,
            bpfo: 120.0,
            bpfi: 180.0,
            ball_spin: 70.0,
        };
        let z = 10;
        let expected = z as f64 * (lines.shaft - lines.cage) + lines.shaft;
        let rate = 4096.0;
        let mut series = TimeSeries::default();
        series.channel("time_s", "s");
        series.channel(ENVELOPE_CHANNEL, "m/s^2");
        for i in 0..4096 {
            let t = i as f64 / rate;
            series.push(&[t, 0.5 * (std::f64::consts::TAU * expected * t).sin()]);
        }
        let smooth = SurfaceModel::default();
        assert!(waviness_lines(&series, 0, &lines, z, &smooth).is_none());
        let mut wavy = SurfaceModel::default();
        wavy.inner.radial = Waviness {
            terms: vec![
                WavinessTerm {
                    order: z as u32 + 1,
                    amplitude: 1e-7,
                    phase: 0.0,
                },
                // An order no rule maps: no line.
                WavinessTerm {
                    order: 3,
                    amplitude: 1e-7,
                    phase: 0.0,
                },
            ],
        };
        let found = waviness_lines(&series, 0, &lines, z, &wavy).unwrap();
        assert_eq!(found.lines.len(), 1);
        let line = &found.lines[0];
        assert_eq!(
            (line.part, line.order, line.motion),
            ("inner_race", 11, Motion::Radial)
        );
        assert!((line.frequency_hz - expected).abs() < 1e-9);
        assert!(
            (line.amplitude_m_s2 - 0.5).abs() < 0.05,
            "{}",
            line.amplitude_m_s2
        );
    }
}
