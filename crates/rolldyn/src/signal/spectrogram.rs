//! Short-time amplitude spectra (spectrogram) of a record: how the
//! spectrum moves as the speed changes (a run-up, a speed ramp), where one
//! spectrum over the whole record smears every line over the speed range
//! (Randall 2011, *Vibration-based Condition Monitoring*, §3.5).

use super::spectrum::{SpectrumError, Window, amplitude_spectrum, segments};

/// Amplitude spectra of successive segments.
#[derive(Debug, Clone, PartialEq)]
pub struct Spectrogram {
    /// Centre of each segment from the record's start \[s\].
    pub time: Vec<f64>,
    /// Frequencies \[Hz\] (the same for every segment).
    pub frequency: Vec<f64>,
    /// One amplitude spectrum per segment (record unit), as
    /// [`amplitude_spectrum`] of that segment.
    pub value: Vec<Vec<f64>>,
}

/// The spectrogram of `record` sampled at `sample_rate` \[Hz\]: segments of
/// `segment` samples overlapping by `overlap` (a fraction in [0, 1)), each
/// mean-removed, windowed and transformed as [`amplitude_spectrum`], so a
/// steady sine shows its amplitude in every segment.
pub fn spectrogram(
    record: &[f64],
    sample_rate: f64,
    segment: usize,
    overlap: f64,
    window: Window,
) -> Result<Spectrogram, SpectrumError> {
    let step = segments(record, sample_rate, "a spectrogram", segment, overlap)?;
    let mut out = Spectrogram {
        time: Vec::new(),
        frequency: Vec::new(),
        value: Vec::new(),
    };
    let mut start = 0;
    while start + segment <= record.len() {
        let spectrum = amplitude_spectrum(&record[start..start + segment], sample_rate, window)?;
        if out.frequency.is_empty() {
            out.frequency = spectrum.frequency;
        }
        out.time
            .push((start as f64 + 0.5 * (segment - 1) as f64) / sample_rate);
        out.value.push(spectrum.value);
        start += step;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A tone that steps from 100 Hz to 300 Hz halfway: each segment's
    /// largest line is the tone of its time, at the tone's amplitude.
    #[test]
    fn each_segment_shows_the_tone_of_its_time() {
        let rate = 2000.0;
        let record: Vec<f64> = (0..4000)
            .map(|k| {
                let t = k as f64 / rate;
                let f = if t < 1.0 { 100.0 } else { 300.0 };
                2.0 * (std::f64::consts::TAU * f * t).sin()
            })
            .collect();
        let s = spectrogram(&record, rate, 400, 0.5, Window::Hann).unwrap();
        assert_eq!(s.time.len(), 19);
        assert!((s.time[0] - 199.5 / rate).abs() < 1e-12);
        for (t, spectrum) in s.time.iter().zip(&s.value) {
            let (k, top) =
                spectrum.iter().enumerate().fold(
                    (0, 0.0),
                    |best, (k, &v)| if v > best.1 { (k, v) } else { best },
                );
            // Segments that straddle the step hold both tones.
            if (t - 1.0).abs() < 0.11 {
                continue;
            }
            let expected = if *t < 1.0 { 100.0 } else { 300.0 };
            assert!(
                (s.frequency[k] - expected).abs() < 1e-9,
                "t {t}: {}",
                s.frequency[k]
            );
            assert!((top - 2.0).abs() < 0.05, "t {t}: amplitude {top}");
        }
        assert!(spectrogram(&record, rate, 400, 1.0, Window::Hann).is_err());
        assert!(spectrogram(&record[..10], rate, 400, 0.5, Window::Hann).is_err());
    }
}
