//! The vibration section of a run report, for a run with a spall: the
//! inner ring's vertical acceleration over the averaging window as a
//! diagnostics engineer reads a measured record (docs/signal.md): its
//! RMS, peak, crest factor and kurtosis, the time signal, the amplitude
//! spectrum and the envelope spectrum with the characteristic lines
//! marked (f_c, BPFO, BPFI ± f_i, 2×BSF ± f_c; Randall & Antoni 2011's
//! envelope analysis, the lines of `rolldyn::signal::lines`).

use crate::run::RunData;
use crate::svg::{Plot, Series};
use crate::{Section, cell};
use rolldyn::signal::{CharacteristicFrequencies, Spectrum, Window};
use rolldyn::signal::{amplitude_spectrum, envelope_spectrum};
use rolldyn_io::{InputError, float_columns, for_each_batch, read_schema};
use std::collections::VecDeque;
use std::path::Path;

/// The channel analysed: the one of the summary's `envelope_lines`.
pub const CHANNEL: &str = "inner_ring_acceleration_z_m_s2";

/// Times \[s\] and values of one channel.
pub type Record = (Vec<f64>, Vec<f64>);

/// Most samples of the window kept (the last ones): 2¹⁶, 1 MB.
pub const MAX_SAMPLES: usize = 1 << 16;

/// Time and [`CHANNEL`] over `[t0, t1]` (the last [`MAX_SAMPLES`]), read in
/// one pass of two columns; None when the run did not record the channel.
pub fn read_window(path: &Path, [t0, t1]: [f64; 2]) -> Result<Option<Record>, InputError> {
    if read_schema(path)?.unit(CHANNEL).is_none() {
        return Ok(None);
    }
    let mut kept = VecDeque::new();
    for_each_batch(path, Some(&["time_s", CHANNEL]), |batch| {
        let columns = float_columns(batch)?;
        for (&t, &a) in columns[0].iter().zip(columns[1]) {
            if t >= t0 && t <= t1 {
                if kept.len() == MAX_SAMPLES {
                    kept.pop_front();
                }
                kept.push_back((t, a));
            }
        }
        Ok(())
    })?;
    Ok(Some(kept.into_iter().unzip()))
}

/// RMS, peak |a|, crest factor (peak / RMS) and kurtosis (m₄ / m₂², 3 for
/// a Gaussian record; impacts raise it) of `record` about its mean.
pub fn statistics(record: &[f64]) -> [f64; 4] {
    let n = record.len() as f64;
    let mean = record.iter().sum::<f64>() / n;
    let (mut m2, mut m4, mut peak) = (0.0, 0.0, 0.0f64);
    for &x in record {
        let d = x - mean;
        m2 += d * d;
        m4 += d * d * d * d;
        peak = peak.max(d.abs());
    }
    let (m2, m4) = (m2 / n, m4 / n);
    let rms = m2.sqrt();
    [rms, peak, peak / rms, m4 / (m2 * m2)]
}

/// The run's characteristic frequencies from its summary.
fn characteristic(data: &RunData) -> Option<CharacteristicFrequencies> {
    let n = |key: &str| data.summary.get(key).and_then(serde_json::Value::as_f64);
    let angle = 0.5 * (n("mean_contact_angle_inner_deg")? + n("mean_contact_angle_outer_deg")?);
    Some(CharacteristicFrequencies::new(
        n("inner_ring_speed_rpm")? / 60.0,
        n("mean_cage_speed_rpm")? / 60.0,
        n("ball_count")? as usize,
        n("ball_diameter_m")? / n("pitch_diameter_m")?,
        angle.to_radians(),
    ))
}

/// A family of lines marked on a spectrum: each line's marker sits on the
/// spectrum's largest value within 1.5 bins of it.
fn marks(spectrum: &Spectrum, name: &str, frequencies: &[f64], up_to: f64) -> Series {
    let resolution = spectrum.resolution();
    let (x, y): (Vec<f64>, Vec<f64>) = frequencies
        .iter()
        .filter(|&&f| f > 0.0 && f <= up_to)
        .map(|&f| {
            let top = spectrum
                .frequency
                .iter()
                .zip(&spectrum.value)
                .filter(|(g, _)| (**g - f).abs() <= 1.5 * resolution)
                .map(|(_, v)| *v)
                .fold(0.0, f64::max);
            (f, top)
        })
        .unzip();
    Series::markers(name, &x, &y)
}

/// The section: only for a run whose summary has envelope lines (a spall)
/// and whose window holds at least 64 samples of [`CHANNEL`].
pub fn section(data: &RunData) -> Option<Section> {
    let lines = data
        .summary
        .get("envelope_lines")
        .filter(|v| !v.is_null())?;
    let (time, record) = data.vibration.as_ref()?;
    if record.len() < 64 {
        return None;
    }
    let (first, last) = (time[0], time[time.len() - 1]);
    let rate = (time.len() - 1) as f64 / (last - first);
    let lines_at = characteristic(data)?;
    let [rms, peak, crest, kurtosis] = statistics(record);
    let spectrum = amplitude_spectrum(record, rate, Window::Hann).ok()?;
    let band = (0.1 * rate, 0.4 * rate);
    let envelope = envelope_spectrum(record, rate, band, Window::Hann).ok()?;
    let c = lines_at;
    let envelope_top = (4.0 * c.bpfi.max(c.bpfo).max(2.0 * c.ball_spin)).min(0.5 * rate);
    let cut = |s: &Spectrum, up_to: f64| {
        let k = s.frequency.iter().take_while(|&&f| f <= up_to).count();
        (s.frequency[..k].to_vec(), s.value[..k].to_vec())
    };
    let (ef, ev) = cut(&envelope, envelope_top);
    let harmonics = |base: f64, side: f64| -> Vec<f64> {
        (1..=4)
            .flat_map(|k| {
                let f = k as f64 * base;
                [f - side, f, f + side]
            })
            .collect()
    };
    let envelope_plot = Plot::new(
        format!("Envelope spectrum (band {:.0}–{:.0} Hz)", band.0, band.1),
        "frequency [Hz]",
        "envelope amplitude [m/s²]",
    )
    .with(Series::line("envelope", &ef, &ev))
    .with(marks(
        &envelope,
        "BPFO",
        &harmonics(c.bpfo, 0.0),
        envelope_top,
    ))
    .with(marks(
        &envelope,
        "BPFI ± f_i",
        &harmonics(c.bpfi, c.shaft),
        envelope_top,
    ))
    .with(marks(
        &envelope,
        "2×BSF ± f_c",
        &harmonics(2.0 * c.ball_spin, c.cage),
        envelope_top,
    ))
    .with(marks(
        &envelope,
        "f_c, f_i",
        &[c.cage, c.shaft],
        envelope_top,
    ));
    let (sf, sv) = cut(&spectrum, 0.5 * rate);
    let spectrum_plot = Plot::new("Amplitude spectrum", "frequency [Hz]", "amplitude [m/s²]")
        .with(Series::line("spectrum", &sf, &sv));
    let t_ms: Vec<f64> = time.iter().map(|t| 1e3 * t).collect();
    let signal_plot = Plot::new(
        "Inner-ring vertical acceleration",
        "time [ms]",
        "acceleration [m/s²]",
    )
    .with(Series::line("a_z", &t_ms, record));
    let line_rows = lines
        .get("lines")
        .and_then(serde_json::Value::as_array)
        .map(|all| {
            all.iter()
                .map(|l| {
                    vec![
                        l.get("name")
                            .and_then(serde_json::Value::as_str)
                            .unwrap_or("")
                            .to_string(),
                        cell(l.get("frequency_hz").and_then(serde_json::Value::as_f64)),
                        cell(l.get("amplitude_m_s2").and_then(serde_json::Value::as_f64)),
                    ]
                })
                .collect()
        })
        .unwrap_or_default();
    Some(
        Section::new("vibration", "Vibration: the defect's signature")
            .paragraph(format!(
                "The inner ring's vertical acceleration over the averaging window ({} samples at {} Hz, {}–{} ms). Kurtosis is m₄/m₂² (3 for a Gaussian record; impacts raise it). The envelope spectrum band-passes the record to 0.1–0.4 of the sample rate and takes its Hilbert envelope; markers sit on the characteristic lines from the run's mean shaft and cage speeds and contact angles (BPFO {} Hz, BPFI {} Hz, 2×BSF {} Hz, f_c {} Hz).",
                record.len(),
                cell(Some(rate)),
                cell(Some(1e3 * first)),
                cell(Some(1e3 * last)),
                cell(Some(c.bpfo)),
                cell(Some(c.bpfi)),
                cell(Some(2.0 * c.ball_spin)),
                cell(Some(c.cage)),
            ))
            .table(
                &["RMS [m/s²]", "peak [m/s²]", "crest factor", "kurtosis"],
                vec![vec![
                    cell(Some(rms)),
                    cell(Some(peak)),
                    cell(Some(crest)),
                    cell(Some(kurtosis)),
                ]],
            )
            .table(&["line", "frequency [Hz]", "envelope amplitude [m/s²]"], line_rows)
            .figure(signal_plot)
            .figure(spectrum_plot)
            .figure(envelope_plot),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn statistics_of_a_sine_and_of_impacts() {
        let sine: Vec<f64> = (0..10_000)
            .map(|k| (std::f64::consts::TAU * k as f64 / 100.0).sin())
            .collect();
        let [rms, peak, crest, kurtosis] = statistics(&sine);
        assert!((rms - 0.5f64.sqrt()).abs() < 1e-9);
        assert!((peak - 1.0).abs() < 1e-9);
        assert!((crest - 2.0f64.sqrt()).abs() < 1e-9);
        // A sine's kurtosis is 1.5; sparse impacts raise it far above 3.
        assert!((kurtosis - 1.5).abs() < 1e-6);
        let impacts: Vec<f64> = (0..10_000)
            .map(|k| if k % 1000 == 0 { 10.0 } else { 0.0 })
            .collect();
        assert!(statistics(&impacts)[3] > 100.0);
    }
}
