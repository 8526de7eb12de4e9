//! Spectra of uniformly sampled records.
//!
//! * amplitude spectrum: A_k = 2|X_k| / Σw (one-sided; a sine of amplitude A
//!   on a bin reads A);
//! * Welch PSD (Welch 1967): mean-removed, windowed segments with overlap,
//!   |X_k|² / (f_s Σw²), doubled except at 0 and Nyquist — `scipy.signal.welch`
//!   with `scaling = "density"`;
//! * envelope spectrum (Randall & Antoni 2011, MSSP 25, 485–520): band-pass
//!   by zeroing the FFT outside [f_lo, f_hi], analytic signal by the inverse
//!   FFT of the doubled positive frequencies (Hilbert transform), envelope
//!   |x_a|, then its amplitude spectrum;
//! * RMS in a band (Hann window, power-normalised Parseval), of a velocity
//!   record directly or of an acceleration record with V_k = A_k / (2π f_k)
//!   (ISO 20816-1 evaluates vibration velocity over 10–1000 Hz).

use realfft::RealFftPlanner;
use realfft::num_complex::Complex;
use std::f64::consts::PI;

/// Data window.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Window {
    /// Hann (periodic, as `scipy.signal.get_window("hann", n)`).
    #[default]
    Hann,
    /// Rectangular (no window).
    Rectangular,
}

impl Window {
    /// The window's n coefficients.
    pub fn coefficients(self, n: usize) -> Vec<f64> {
        match self {
            Self::Rectangular => vec![1.0; n],
            Self::Hann => (0..n)
                .map(|k| 0.5 - 0.5 * (2.0 * PI * k as f64 / n as f64).cos())
                .collect(),
        }
    }
}

/// A one-sided spectrum.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Spectrum {
    /// Frequencies \[Hz\].
    pub frequency: Vec<f64>,
    /// Values (amplitude in the record's unit, or PSD in unit²/Hz).
    pub value: Vec<f64>,
}

impl Spectrum {
    /// Frequency resolution \[Hz\] (0 for fewer than two lines).
    pub fn resolution(&self) -> f64 {
        if self.frequency.len() > 1 {
            self.frequency[1] - self.frequency[0]
        } else {
            0.0
        }
    }
}

/// A record that cannot be analysed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SpectrumError {
    /// Fewer samples than the analysis needs.
    #[error("{what} needs at least {needed} samples, the record has {got}")]
    TooShort {
        /// Which analysis.
        what: &'static str,
        /// Samples needed.
        needed: usize,
        /// Samples present.
        got: usize,
    },
    /// A parameter outside its range.
    #[error("{field} = {value}: {rule}")]
    Invalid {
        /// Parameter.
        field: &'static str,
        /// Value.
        value: f64,
        /// Rule.
        rule: String,
    },
    /// A non-finite sample.
    #[error("sample {index} is not finite ({value})")]
    NonFinite {
        /// Index of the sample.
        index: usize,
        /// Its value.
        value: f64,
    },
}

fn check(
    record: &[f64],
    sample_rate: f64,
    what: &'static str,
    needed: usize,
) -> Result<(), SpectrumError> {
    if !(sample_rate.is_finite() && sample_rate > 0.0) {
        return Err(SpectrumError::Invalid {
            field: "sample_rate",
            value: sample_rate,
            rule: "must be positive".into(),
        });
    }
    if record.len() < needed {
        return Err(SpectrumError::TooShort {
            what,
            needed,
            got: record.len(),
        });
    }
    if let Some((index, &value)) = record.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        return Err(SpectrumError::NonFinite { index, value });
    }
    Ok(())
}

/// Smallest 5-smooth number ≥ n (2ᵃ3ᵇ5ᶜ).
pub fn smooth_length(n: usize) -> usize {
    let mut m = n.max(1);
    loop {
        let mut k = m;
        for p in [2, 3, 5] {
            while k % p == 0 {
                k /= p;
            }
        }
        if k == 1 {
            return m;
        }
        m += 1;
    }
}

/// FFT of the windowed, mean-removed record, zero-padded to `len`.
fn windowed_fft(record: &[f64], window: &[f64], len: usize) -> Vec<Complex<f64>> {
    let mean = record.iter().sum::<f64>() / record.len() as f64;
    let mut buffer = vec![0.0; len];
    for (b, (x, w)) in buffer.iter_mut().zip(record.iter().zip(window)) {
        *b = (x - mean) * w;
    }
    let fft = RealFftPlanner::<f64>::new().plan_fft_forward(len);
    let mut out = fft.make_output_vec();
    // Lengths match by construction: the plan's own buffers.
    if fft.process(&mut buffer, &mut out).is_err() {
        out.iter_mut().for_each(|c| *c = Complex::new(0.0, 0.0));
    }
    out
}

/// One-sided amplitude spectrum of `record` sampled at `sample_rate` \[Hz\],
/// mean removed.
pub fn amplitude_spectrum(
    record: &[f64],
    sample_rate: f64,
    window: Window,
) -> Result<Spectrum, SpectrumError> {
    check(record, sample_rate, "an amplitude spectrum", 2)?;
    let w = window.coefficients(record.len());
    let gain: f64 = w.iter().sum();
    let len = smooth_length(record.len());
    let x = windowed_fft(record, &w, len);
    let df = sample_rate / len as f64;
    Ok(Spectrum {
        frequency: (0..x.len()).map(|k| k as f64 * df).collect(),
        value: x
            .iter()
            .enumerate()
            .map(|(k, c)| {
                let one_sided = if k == 0 || (len % 2 == 0 && k == len / 2) {
                    1.0
                } else {
                    2.0
                };
                one_sided * c.norm() / gain
            })
            .collect(),
    })
}

/// Checks a record for analysis by segments of `segment` samples
/// overlapping by `overlap`; returns the hop between segments.
pub(super) fn segments(
    record: &[f64],
    sample_rate: f64,
    what: &'static str,
    segment: usize,
    overlap: f64,
) -> Result<usize, SpectrumError> {
    if !(0.0..1.0).contains(&overlap) {
        return Err(SpectrumError::Invalid {
            field: "overlap",
            value: overlap,
            rule: "must lie in [0, 1)".into(),
        });
    }
    if segment < 2 {
        return Err(SpectrumError::Invalid {
            field: "segment",
            value: segment as f64,
            rule: "needs at least 2 samples".into(),
        });
    }
    check(record, sample_rate, what, segment)?;
    Ok(((segment as f64 * (1.0 - overlap)).round() as usize).max(1))
}

/// Welch PSD: segments of `segment` samples overlapping by `overlap`
/// (fraction in [0, 1)), each mean-removed and windowed; unit²/Hz.
pub fn welch_psd(
    record: &[f64],
    sample_rate: f64,
    segment: usize,
    overlap: f64,
    window: Window,
) -> Result<Spectrum, SpectrumError> {
    let step = segments(record, sample_rate, "a Welch PSD", segment, overlap)?;
    let w = window.coefficients(segment);
    let power: f64 = w.iter().map(|v| v * v).sum();
    let fft = RealFftPlanner::<f64>::new().plan_fft_forward(segment);
    let mut buffer = fft.make_input_vec();
    let mut out = fft.make_output_vec();
    let mut sum = vec![0.0; out.len()];
    let mut count = 0usize;
    let mut start = 0;
    while start + segment <= record.len() {
        let part = &record[start..start + segment];
        let mean = part.iter().sum::<f64>() / segment as f64;
        for (b, (x, wk)) in buffer.iter_mut().zip(part.iter().zip(&w)) {
            *b = (x - mean) * wk;
        }
        if fft.process(&mut buffer, &mut out).is_ok() {
            for (s, c) in sum.iter_mut().zip(&out) {
                *s += c.norm_sqr();
            }
            count += 1;
        }
        start += step;
    }
    let df = sample_rate / segment as f64;
    let scale = 1.0 / (sample_rate * power * count.max(1) as f64);
    Ok(Spectrum {
        frequency: (0..sum.len()).map(|k| k as f64 * df).collect(),
        value: sum
            .iter()
            .enumerate()
            .map(|(k, s)| {
                let one_sided = if k == 0 || (segment % 2 == 0 && k == segment / 2) {
                    1.0
                } else {
                    2.0
                };
                one_sided * s * scale
            })
            .collect(),
    })
}

/// The envelope band's default, as fractions of the sample rate: 0.1–0.4,
/// clear of the record's low-frequency motion and of the anti-alias
/// filter's roll-off.
pub const DEFAULT_ENVELOPE_BAND: (f64, f64) = (0.1, 0.4);

/// The default envelope band at `sample_rate` \[Hz\].
pub fn default_envelope_band(sample_rate: f64) -> (f64, f64) {
    (
        DEFAULT_ENVELOPE_BAND.0 * sample_rate,
        DEFAULT_ENVELOPE_BAND.1 * sample_rate,
    )
}

/// Whether an envelope band \[Hz\] can show impacts that repeat at `rate`
/// \[Hz\]: the impacts modulate a resonance inside the band, and the
/// band-pass must keep that carrier with at least its first pair of
/// sidebands at ±`rate` (Randall & Antoni 2011, envelope analysis), so it
/// must be at least 2 × `rate` wide. Necessary, not sufficient: a band
/// this wide still needs a resonance in it. Measured on the
/// ceramic_45x75 preset with an inner-race pit at 15 000 rpm (BPFI
/// 2.53 kHz, docs/signal.md): at 10 kHz sampling (band 1–4 kHz) no
/// BPFI line; at 20 kHz (2–8 kHz) BPFI among the three largest; at 50
/// kHz (5–20 kHz) BPFI the largest line of both channels.
pub fn envelope_band_holds(band: (f64, f64), rate: f64) -> bool {
    band.1 - band.0 >= 2.0 * rate
}

/// Envelope spectrum: band-pass [f_lo, f_hi] \[Hz\], Hilbert envelope, then
/// its amplitude spectrum (mean removed).
pub fn envelope_spectrum(
    record: &[f64],
    sample_rate: f64,
    band: (f64, f64),
    window: Window,
) -> Result<Spectrum, SpectrumError> {
    check(record, sample_rate, "an envelope spectrum", 4)?;
    let nyquist = 0.5 * sample_rate;
    if !(band.0 >= 0.0 && band.1 > band.0 && band.1 <= nyquist) {
        return Err(SpectrumError::Invalid {
            field: "band",
            value: band.1,
            rule: format!(
                "the band [{}, {}] Hz must satisfy 0 ≤ low < high ≤ Nyquist ({nyquist} Hz)",
                band.0, band.1
            ),
        });
    }
    let envelope = band_envelope(record, sample_rate, band);
    amplitude_spectrum(&envelope, sample_rate, window)
}

/// Hilbert envelope of the band-passed record (same length as the record).
pub fn band_envelope(record: &[f64], sample_rate: f64, band: (f64, f64)) -> Vec<f64> {
    let n = record.len();
    let len = smooth_length(n);
    let rectangular = vec![1.0; n];
    let spectrum = windowed_fft(record, &rectangular, len);
    let df = sample_rate / len as f64;
    // Analytic signal: positive frequencies in the band doubled, the rest zero.
    let mut analytic = vec![Complex::new(0.0, 0.0); len];
    for (k, c) in spectrum.iter().enumerate() {
        let f = k as f64 * df;
        if f >= band.0 && f <= band.1 {
            let factor = if k == 0 || (len % 2 == 0 && k == len / 2) {
                1.0
            } else {
                2.0
            };
            analytic[k] = *c * factor;
        }
    }
    let mut planner = rustfft::FftPlanner::<f64>::new();
    planner.plan_fft_inverse(len).process(&mut analytic);
    analytic[..n]
        .iter()
        .map(|c| c.norm() / len as f64)
        .collect()
}

/// RMS of the record's content in [f_lo, f_hi] \[Hz\] (mean removed):
/// Hann-windowed FFT, power-normalised, RMS² = 2 Σ_band |X_k|² / (N Σw²)
/// (N: FFT length), exact for a tone on a bin and free of the leakage a
/// rectangular window spreads over the band.
pub fn band_rms(record: &[f64], sample_rate: f64, band: (f64, f64)) -> Result<f64, SpectrumError> {
    band_power(record, sample_rate, band, LineGain::One).map(f64::sqrt)
}

/// RMS vibration velocity in [f_lo, f_hi] \[Hz\] from an acceleration
/// record (the record's unit × s; m/s² gives m/s): as [`band_rms`] with each
/// line divided by 2πf.
pub fn band_velocity_rms(
    acceleration: &[f64],
    sample_rate: f64,
    band: (f64, f64),
) -> Result<f64, SpectrumError> {
    band_power(acceleration, sample_rate, band, LineGain::Integrator).map(f64::sqrt)
}

/// RMS vibration velocity in [f_lo, f_hi] \[Hz\] from displacement samples
/// x_k taken at the sample rate f_s (the record's unit × Hz; m gives m/s),
/// free of aliasing by the vibration above f_s/2.
///
/// Samples of the velocity itself fold every component near a multiple of
/// f_s into the band at full strength. The interval means
/// v̄_k = (x_k − x_{k−1}) f_s are instead the velocity averaged over one
/// sample interval before it is sampled: a boxcar anti-alias filter,
/// exact because x is the integral of v, whose gain sinc(f/f_s) =
/// sin(π f/f_s)/(π f/f_s) vanishes at every multiple of f_s. A component at
/// m f_s ± f keeps about f/(m f_s ± f) of its amplitude (−21 dB for the 1 kHz
/// band edge at 12 kHz, −33 dB at 48 kHz). In the band the gain is
/// divided out line by line (it is 0.989 at 1 kHz of 12 kHz, 2/π at f_s/2);
/// otherwise as [`band_rms`] over the N − 1 means. Aliasing and
/// anti-alias prefilters: Oppenheim & Schafer 2010, §4.2, §4.8
/// (docs/references.md).
pub fn band_velocity_rms_of_displacement(
    displacement: &[f64],
    sample_rate: f64,
    band: (f64, f64),
) -> Result<f64, SpectrumError> {
    check(
        displacement,
        sample_rate,
        "a band RMS from displacements",
        3,
    )?;
    let interval_means: Vec<f64> = displacement
        .windows(2)
        .map(|pair| (pair[1] - pair[0]) * sample_rate)
        .collect();
    band_power(&interval_means, sample_rate, band, LineGain::IntervalMean).map(f64::sqrt)
}

/// What a line of [`band_power`] is divided by.
#[derive(Clone, Copy)]
enum LineGain {
    /// Nothing.
    One,
    /// 2πf: velocity from acceleration.
    Integrator,
    /// sinc(f/f_s): the interval mean's gain.
    IntervalMean,
}

impl LineGain {
    fn at(self, f: f64, sample_rate: f64) -> f64 {
        match self {
            Self::One => 1.0,
            Self::Integrator => 2.0 * PI * f,
            Self::IntervalMean => {
                let x = PI * f / sample_rate;
                if x == 0.0 { 1.0 } else { x.sin() / x }
            }
        }
    }
}

fn band_power(
    record: &[f64],
    sample_rate: f64,
    band: (f64, f64),
    gain: LineGain,
) -> Result<f64, SpectrumError> {
    check(record, sample_rate, "a band RMS", 2)?;
    let n = record.len();
    let len = smooth_length(n);
    let w = Window::Hann.coefficients(n);
    let power: f64 = w.iter().map(|v| v * v).sum();
    let x = windowed_fft(record, &w, len);
    let df = sample_rate / len as f64;
    let mut sum = 0.0;
    for (k, c) in x.iter().enumerate().skip(1) {
        let f = k as f64 * df;
        if f < band.0 || f > band.1 {
            continue;
        }
        let one_sided = if len % 2 == 0 && k == len / 2 {
            1.0
        } else {
            2.0
        };
        let magnitude = c.norm() / gain.at(f, sample_rate);
        sum += one_sided * magnitude * magnitude;
    }
    Ok(sum / (len as f64 * power))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Impacts repeating at `rate` each ringing a resonance at 12 kHz
    /// (damping ratio 0.05), 0.1 s at 100 kHz.
    fn impacts(rate: f64) -> (Vec<f64>, f64) {
        let (fs, f0, zeta) = (100e3, 12e3, 0.05);
        let omega = 2.0 * PI * f0;
        let ring =
            |t: f64| (-zeta * omega * t).exp() * (omega * (1.0 - zeta * zeta).sqrt() * t).sin();
        let record = (0..10_000)
            .map(|n| {
                let t = n as f64 / fs;
                let last = (t * rate).floor();
                // Earlier impacts have rung down (e^{-2π ζ f0 × 8/rate} ≈ 1e-6).
                (0..8)
                    .map(|k| t - (last - k as f64) / rate)
                    .filter(|&dt| dt >= 0.0)
                    .map(ring)
                    .sum()
            })
            .collect();
        (record, fs)
    }

    /// The envelope spectrum's largest value within 50 Hz of `f`.
    fn envelope_at(record: &[f64], fs: f64, band: (f64, f64), f: f64) -> f64 {
        let s = envelope_spectrum(record, fs, band, Window::Hann).unwrap();
        s.frequency
            .iter()
            .zip(&s.value)
            .filter(|(g, _)| (*g - f).abs() <= 50.0)
            .map(|(_, v)| *v)
            .fold(0.0, f64::max)
    }

    /// A periodic impact train has lines every `rate`: a band narrower
    /// than 2 × rate may hold only one of them around the resonance, and
    /// the envelope of one line is flat; a band that holds the rule keeps
    /// the rate's line (Randall & Antoni 2011).
    #[test]
    fn an_envelope_band_narrower_than_twice_the_rate_loses_it() {
        let rate = 2500.0;
        let (record, fs) = impacts(rate);
        let (narrow, wide) = ((10.5e3, 13.5e3), (5e3, 20e3));
        assert!(!envelope_band_holds(narrow, rate));
        assert!(envelope_band_holds(wide, rate));
        let (lost, kept) = (
            envelope_at(&record, fs, narrow, rate),
            envelope_at(&record, fs, wide, rate),
        );
        assert!(
            kept > 20.0 * lost,
            "rate's line: {kept:e} wide, {lost:e} narrow"
        );
        assert_eq!(default_envelope_band(50e3), (5e3, 20e3));
    }

    fn tone(n: usize, fs: f64, f: f64, a: f64) -> Vec<f64> {
        (0..n)
            .map(|k| a * (2.0 * PI * f * k as f64 / fs).sin())
            .collect()
    }

    #[test]
    fn a_tone_on_a_bin_reads_its_amplitude() {
        let (n, fs) = (1000, 1000.0);
        let x = tone(n, fs, 50.0, 3.0);
        for window in [Window::Hann, Window::Rectangular] {
            let s = amplitude_spectrum(&x, fs, window).unwrap();
            let k = s
                .frequency
                .iter()
                .position(|&f| (f - 50.0).abs() < 1e-9)
                .unwrap();
            assert!(
                (s.value[k] - 3.0).abs() < 1e-9,
                "{window:?}: {}",
                s.value[k]
            );
        }
    }

    #[test]
    fn welch_integrates_to_the_variance() {
        // White-ish deterministic signal: sum of tones; ∫PSD df = variance.
        let (n, fs) = (8192, 2048.0);
        let x: Vec<f64> = (0..n)
            .map(|k| {
                let t = k as f64 / fs;
                (2.0 * PI * 100.0 * t).sin() + 0.5 * (2.0 * PI * 300.0 * t).cos()
            })
            .collect();
        let psd = welch_psd(&x, fs, 1024, 0.5, Window::Hann).unwrap();
        let area: f64 = psd.value.iter().sum::<f64>() * psd.resolution();
        let variance = 0.5 + 0.125;
        assert!((area - variance).abs() < 0.01 * variance, "{area}");
        // The 100 Hz line dominates.
        let peak = psd
            .value
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(b.1))
            .unwrap()
            .0;
        assert!((psd.frequency[peak] - 100.0).abs() <= psd.resolution());
    }

    #[test]
    fn the_envelope_of_a_modulated_carrier_shows_the_modulation() {
        // 2 kHz carrier, amplitude modulated at 37 Hz (depth 0.5).
        let (n, fs) = (20_000, 20_000.0);
        let x: Vec<f64> = (0..n)
            .map(|k| {
                let t = k as f64 / fs;
                (1.0 + 0.5 * (2.0 * PI * 37.0 * t).cos()) * (2.0 * PI * 2000.0 * t).sin()
            })
            .collect();
        let env = envelope_spectrum(&x, fs, (1500.0, 2500.0), Window::Hann).unwrap();
        let k = (37.0 / env.resolution()).round() as usize;
        assert!((env.value[k] - 0.5).abs() < 0.01, "{}", env.value[k]);
        // The carrier is gone from the envelope.
        let k2 = (2000.0 / env.resolution()).round() as usize;
        assert!(env.value[k2] < 1e-3);
        // Mid-record envelope equals the modulation.
        let e = band_envelope(&x, fs, (1500.0, 2500.0));
        let t = 5000.0 / fs;
        assert!((e[5000] - (1.0 + 0.5 * (2.0 * PI * 37.0 * t).cos())).abs() < 1e-3);
    }

    #[test]
    fn velocity_rms_of_a_tone_is_a_over_omega_sqrt2() {
        let (n, fs) = (10_000, 10_000.0);
        let a = tone(n, fs, 100.0, 2.0);
        let v = band_velocity_rms(&a, fs, (10.0, 1000.0)).unwrap();
        let expected = 2.0 / (2.0 * PI * 100.0) / 2f64.sqrt();
        // The Hann lobe spans 99–101 Hz: 1/f differs by 1e-4 across it.
        assert!((v - expected).abs() < 1e-4 * expected, "{v} vs {expected}");
        assert!((band_rms(&a, fs, (10.0, 1000.0)).unwrap() - 2f64.sqrt()).abs() < 1e-12);
        // Outside the band: only the window's far sidelobes.
        assert!(band_velocity_rms(&a, fs, (200.0, 1000.0)).unwrap() < 1e-5 * expected);
        // A tone between bins, off the FFT grid, still reads its RMS within 1 %.
        let off = tone(n, fs, 100.37, 2.0);
        let rms = band_rms(&off, fs, (10.0, 1000.0)).unwrap();
        assert!((rms - 2f64.sqrt()).abs() < 1e-2, "{rms}");
    }

    /// A ring vibrating at 300 Hz (in the band) and at f_s − 500 Hz
    /// (above Nyquist) with the same velocity amplitude: its velocity
    /// samples read both (the second folded to 500 Hz), its displacements'
    /// interval means the in-band tone alone.
    #[test]
    fn interval_means_do_not_fold_vibration_above_nyquist_into_the_band() {
        let fs = 12_000.0;
        let (f_in, f_above, amplitude) = (300.0, fs - 500.0, 1e-3);
        let omega = |f: f64| 2.0 * PI * f;
        let at = |k: usize| k as f64 / fs;
        // 1 s: every tone on a bin of the 12 000 intervals.
        let displacement: Vec<f64> = (0..=12_000)
            .map(|k| {
                let t = at(k);
                amplitude
                    * ((omega(f_in) * t).sin() / omega(f_in)
                        + (omega(f_above) * t).sin() / omega(f_above))
            })
            .collect();
        let velocity: Vec<f64> = (0..=12_000)
            .map(|k| {
                let t = at(k);
                amplitude * ((omega(f_in) * t).cos() + (omega(f_above) * t).cos())
            })
            .collect();
        let band = (10.0, 1000.0);
        let truth = amplitude / 2f64.sqrt();
        let sampled = band_rms(&velocity, fs, band).unwrap();
        assert!((sampled / truth - 2f64.sqrt()).abs() < 1e-3, "{sampled}");
        // What is left of the folded tone: sinc(11.5/12) = 0.043 of it,
        // 0.09 % of the RMS.
        let means = band_velocity_rms_of_displacement(&displacement, fs, band).unwrap();
        assert!(
            (means / truth - 1.0).abs() < 2e-3,
            "{means} against {truth}"
        );
        // In the band the interval mean's gain is divided out: a 900 Hz tone
        // alone (sinc(0.075) = 0.991) reads its RMS.
        let edge: Vec<f64> = (0..=12_000)
            .map(|k| amplitude * (omega(900.0) * at(k)).sin() / omega(900.0))
            .collect();
        let edge_rms = band_velocity_rms_of_displacement(&edge, fs, band).unwrap();
        assert!((edge_rms / truth - 1.0).abs() < 1e-3, "{edge_rms}");
    }
    #[test]
    fn bad_records_are_refused() {
        assert!(matches!(
            amplitude_spectrum(&[1.0], 1.0, Window::Hann),
            Err(SpectrumError::TooShort { .. })
        ));
        assert!(matches!(
            amplitude_spectrum(&[1.0, f64::NAN], 1.0, Window::Hann),
            Err(SpectrumError::NonFinite { index: 1, .. })
        ));
        assert!(matches!(
            envelope_spectrum(&[0.0; 16], 100.0, (10.0, 80.0), Window::Hann),
            Err(SpectrumError::Invalid { field: "band", .. })
        ));
        assert!(welch_psd(&[0.0; 16], 100.0, 8, 1.0, Window::Hann).is_err());
        assert_eq!(smooth_length(7), 8);
        assert_eq!(smooth_length(121), 125);
    }
}
