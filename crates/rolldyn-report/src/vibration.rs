//! The vibration section of a run report, for a run with a spall,
//! waviness, a sensor or a speed ramp: the housing accelerometer's signal
//! (a run with `[sensor]`) or else the inner ring's vertical acceleration,
//! as a diagnostics engineer reads a measured record (docs/signal.md). For a spall, over
//! the averaging window: its RMS, peak, crest factor and kurtosis, the
//! time signal, the amplitude spectrum and the envelope spectrum with the
//! characteristic lines marked (f_c, BPFO, BPFI ± f_i, 2×BSF ± f_c;
//! Randall & Antoni 2011's envelope analysis, the lines of
//! `rolldyn::signal::lines`). For waviness, the same statistics and the
//! amplitude spectrum with the lines its orders excite marked (Deng et
//! al. 2022 Table 2, the summary's `waviness_lines`). For a run whose shaft speed changes (a
//! run-up or coast-down), over the whole run: the spectrogram with the
//! shaft, cage, BPFO and BPFI orders drawn over it (order tracking).

use crate::run_data::{RunData, rows};
use crate::svg::{HeatMap, Plot, Series};
pub use crate::vibration_data::{
    CHANNEL, MAX_SAMPLES, RAMP_SPEED_CHANGE, Record, analysed_channel, is_ramp, read_records,
    read_window,
};
use crate::{Section, cell};
use rolldyn::signal::{CharacteristicFrequencies, Spectrogram, Spectrum, Window, spectrogram};
use rolldyn::signal::{amplitude_spectrum, envelope_spectrum, statistics};

/// How the report names `channel`.
fn describe(channel: &str) -> &'static str {
    if channel.starts_with("sensor_") {
        "The housing accelerometer's acquired signal"
    } else {
        "The inner ring's vertical acceleration"
    }
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

/// The section: the defect's signature for a run whose summary has
/// envelope lines (a spall), the spectrogram for a run whose speed
/// changes; none when neither has 64 samples of [`CHANNEL`].
pub fn section(data: &RunData) -> Option<Section> {
    let defect = defect(data);
    let waviness = waviness(data);
    let run_up = run_up(data);
    let sensed = data.summary.get("sensor").is_some_and(|v| !v.is_null());
    let title = match (&defect, &waviness, &run_up) {
        (Some(_), _, _) if sensed => "Vibration: the housing sensor's record",
        (Some(_), _, _) => "Vibration: the defect's signature",
        (None, Some(_), _) => "Vibration: the waviness signature",
        (None, None, Some(_)) => "Vibration: the run-up spectrogram",
        (None, None, None) => return None,
    };
    let mut section = Section::new("vibration", title);
    for part in [defect, waviness, run_up].into_iter().flatten() {
        section.blocks.extend(part.blocks);
    }
    Some(section)
}

/// The sample rate of a record's times \[Hz\].
fn rate_of(time: &[f64]) -> f64 {
    (time.len() - 1) as f64 / (time[time.len() - 1] - time[0])
}

/// The spall's part: statistics, lines and spectra of the averaging window.
fn defect(data: &RunData) -> Option<Section> {
    let lines = data
        .summary
        .get("envelope_lines")
        .filter(|v| !v.is_null())?;
    let (time, record) = data.vibration.as_ref()?;
    if record.len() < 64 {
        return None;
    }
    let (first, last) = (time[0], time[time.len() - 1]);
    let rate = rate_of(time);
    let lines_at = characteristic(data)?;
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
    let signal_plot = signal_plot(time, record, analysed_channel(&data.summary));
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
    let passages = rows(
        data,
        &[
            (
                "ball_pass_interval_s",
                "mean interval between ball passages [s]",
            ),
            (
                "ball_pass_jitter",
                "ball-pass jitter: σ/mean of those intervals [1]",
            ),
        ],
    );
    Some(
        Section::new("vibration", "Vibration: the defect's signature")
            .paragraph(format!(
                "{} over the averaging window ({} samples at {} Hz, {}–{} ms). Kurtosis is m₄/m₂² (3 for a Gaussian record; impacts raise it). The envelope spectrum band-passes the record to 0.1–0.4 of the sample rate and takes its Hilbert envelope; markers sit on the characteristic lines from the run's mean shaft and cage speeds and contact angles (BPFO {} Hz, BPFI {} Hz, 2×BSF {} Hz, f_c {} Hz).",
                describe(analysed_channel(&data.summary)),
                record.len(),
                cell(Some(rate)),
                cell(Some(1e3 * first)),
                cell(Some(1e3 * last)),
                cell(Some(c.bpfo)),
                cell(Some(c.bpfi)),
                cell(Some(2.0 * c.ball_spin)),
                cell(Some(c.cage)),
            ))
            .table(STATISTICS_HEADER, vec![statistics_row(record)])
            .table(&["quantity", "value", "summary.json key"], passages)
            .table(&["line", "frequency [Hz]", "envelope amplitude [m/s²]"], line_rows)
            .figure(signal_plot)
            .figure(spectrum_plot)
            .figure(envelope_plot),
    )
}

/// Header of the record's statistics table.
const STATISTICS_HEADER: &[&str] = &["RMS [m/s²]", "peak [m/s²]", "crest factor", "kurtosis"];

/// The record's [`statistics`] as a table row.
fn statistics_row(record: &[f64]) -> Vec<String> {
    statistics(record).iter().map(|v| cell(Some(*v))).collect()
}

/// The record against time.
fn signal_plot(time: &[f64], record: &[f64], channel: &str) -> Plot {
    let t_ms: Vec<f64> = time.iter().map(|t| 1e3 * t).collect();
    Plot::new(describe(channel), "time [ms]", "acceleration [m/s²]")
        .with(Series::line(channel, &t_ms, record))
}

/// The waviness's part (a run whose summary has `waviness_lines` and no
/// spall): statistics, the time signal and the amplitude spectrum with
/// the lines each part's orders excite marked.
fn waviness(data: &RunData) -> Option<Section> {
    if data
        .summary
        .get("envelope_lines")
        .is_some_and(|v| !v.is_null())
    {
        return None;
    }
    let lines = data
        .summary
        .get("waviness_lines")?
        .get("lines")?
        .as_array()?;
    let (time, record) = data.vibration.as_ref()?;
    if record.len() < 64 {
        return None;
    }
    let rate = rate_of(time);
    let spectrum = amplitude_spectrum(record, rate, Window::Hann).ok()?;
    let text = |l: &serde_json::Value, key: &str| {
        l.get(key)
            .and_then(serde_json::Value::as_str)
            .unwrap_or("")
            .to_string()
    };
    let number = |l: &serde_json::Value, key: &str| l.get(key).and_then(serde_json::Value::as_f64);
    let top = lines
        .iter()
        .filter_map(|l| number(l, "frequency_hz"))
        .fold(0.0, f64::max);
    let up_to = (1.25 * top).clamp(0.0, 0.5 * rate);
    let k = spectrum
        .frequency
        .iter()
        .take_while(|&&f| f <= up_to)
        .count();
    let mut plot = Plot::new("Amplitude spectrum", "frequency [Hz]", "amplitude [m/s²]").with(
        Series::line("spectrum", &spectrum.frequency[..k], &spectrum.value[..k]),
    );
    for part in ["outer_race", "inner_race", "ball"] {
        let at: Vec<f64> = lines
            .iter()
            .filter(|l| text(l, "part") == part)
            .filter_map(|l| number(l, "frequency_hz"))
            .collect();
        if !at.is_empty() {
            plot = plot.with(marks(&spectrum, &part.replace('_', " "), &at, up_to));
        }
    }
    let rows = lines
        .iter()
        .map(|l| {
            vec![
                text(l, "part").replace('_', " "),
                cell(number(l, "order")),
                cell(number(l, "frequency_hz")),
                text(l, "motion"),
                cell(number(l, "amplitude_m_s2")),
            ]
        })
        .collect();
    Some(
        Section::new("vibration", "Vibration: the waviness signature")
            .paragraph(format!(
                "{} over the averaging window ({} samples at {} Hz). The lines are those the case's waviness orders excite (Deng et al. 2022 Table 2: a raceway order kZ ± 1 gives a radial line at kZ f_c on the outer race and kZ(f_i − f_c) ± f_i on the inner, an order kZ an axial one; a ball order 2k gives 2k f_b and 2k f_b ± f_c), at the run's mean shaft and cage speeds; the amplitude is the spectrum's largest within 1.5 bins.",
                describe(analysed_channel(&data.summary)),
                record.len(),
                cell(Some(rate)),
            ))
            .table(STATISTICS_HEADER, vec![statistics_row(record)])
            .table(
                &["part", "order", "frequency [Hz]", "motion", "amplitude [m/s²]"],
                rows,
            )
            .figure(signal_plot(time, record, analysed_channel(&data.summary)))
            .figure(plot),
    )
}

/// Most columns (segments) of the drawn spectrogram; beyond, cells are
/// pooled to their largest amplitude.
pub const HEAT_COLUMNS: usize = 120;
/// Most rows (frequency bins) of the drawn spectrogram, pooled alike.
pub const HEAT_ROWS: usize = 100;
/// The darkest level drawn \[dB below the reference\].
pub const HEAT_FLOOR_DB: f64 = -60.0;
/// The rank of the cell that sets 0 dB: the 99.5th percentile.
pub const HEAT_REFERENCE_RANK: f64 = 0.995;

/// The spectrogram of a record starting at `start` \[s\] as a heat map of
/// levels in dB, pooled to at most [`HEAT_COLUMNS`] × [`HEAT_ROWS`] cells
/// (each the largest it covers), 0 dB at the cells' 99.5th percentile
/// (brighter cells saturate), down to [`HEAT_FLOOR_DB`].
pub fn heat_map(sg: &Spectrogram, start: f64) -> HeatMap {
    let (columns, rows) = (sg.time.len(), sg.frequency.len());
    let pool_x = columns.div_ceil(HEAT_COLUMNS).max(1);
    let pool_y = rows.div_ceil(HEAT_ROWS).max(1);
    let hop = if columns > 1 {
        sg.time[1] - sg.time[0]
    } else {
        2.0 * sg.time.first().copied().unwrap_or(0.5)
    };
    let df = if rows > 1 {
        sg.frequency[1] - sg.frequency[0]
    } else {
        1.0
    };
    let edges = |centres: &[f64], pool: usize, width: f64, lowest: f64| -> Vec<f64> {
        let mut e: Vec<f64> = centres
            .iter()
            .step_by(pool)
            .map(|c| (c - 0.5 * width).max(lowest))
            .collect();
        e.push(centres.last().map_or(0.0, |c| c + 0.5 * width));
        e
    };
    let x_edges: Vec<f64> = edges(&sg.time, pool_x, hop, f64::NEG_INFINITY)
        .into_iter()
        .map(|t| start + t)
        .collect();
    let y_edges = edges(&sg.frequency, pool_y, df, 0.0);
    let mut pooled = Vec::with_capacity((x_edges.len() - 1) * (y_edges.len() - 1));
    for cols in sg.value.chunks(pool_x) {
        for k in (0..rows).step_by(pool_y) {
            pooled.push(
                cols.iter()
                    .flat_map(|spectrum| &spectrum[k..(k + pool_y).min(rows)])
                    .copied()
                    .fold(0.0, f64::max),
            );
        }
    }
    // 0 dB at the cells' 99.5th percentile: a start transient's few bright
    // cells saturate instead of darkening the rest of the run.
    let mut sorted = pooled.clone();
    sorted.sort_by(f64::total_cmp);
    let reference = sorted
        .get((HEAT_REFERENCE_RANK * sorted.len() as f64) as usize)
        .or(sorted.last())
        .copied()
        .unwrap_or(1.0)
        .max(f64::MIN_POSITIVE);
    let levels = pooled
        .iter()
        .map(|v| (20.0 * (v / reference).log10()).clamp(HEAT_FLOOR_DB, 0.0))
        .collect();
    HeatMap {
        x_edges,
        y_edges,
        levels,
        floor: HEAT_FLOOR_DB,
        label: "dB".into(),
    }
}

/// The run-up part: the spectrogram of the whole record with the orders.
fn run_up(data: &RunData) -> Option<Section> {
    let (time, record) = data.run_up.as_ref()?;
    if record.len() < 64 {
        return None;
    }
    let rate = rate_of(time);
    // About 64 columns at half overlap: segments of a power of two.
    let segment = (2 * record.len() / 65)
        .next_power_of_two()
        .clamp(32, 8192)
        .min(record.len());
    let sg = spectrogram(record, rate, segment, 0.5, Window::Hann).ok()?;
    let heat = heat_map(&sg, time[0]);
    let top = heat.y_edges.last().copied().unwrap_or(0.5 * rate);
    let channel = analysed_channel(&data.summary);
    let mut plot = Plot::new(
        format!("Spectrogram: {}", describe(channel).to_lowercase()),
        "time [s]",
        "frequency [Hz]",
    )
    .with_heat(heat);
    let speed = data.channel("inner_ring_speed_rpm");
    let speed_time = data.time_of("inner_ring_speed_rpm");
    let mut orders = Vec::new();
    if let (Some(speed), Some(c)) = (speed, characteristic(data)) {
        let shaft = c.shaft.max(f64::MIN_POSITIVE);
        for (name, order) in [
            ("1× shaft", 1.0),
            ("cage", c.cage / shaft),
            ("BPFO", c.bpfo / shaft),
            ("BPFI", c.bpfi / shaft),
        ] {
            // Drawn where inside the plot: beyond the top the line breaks.
            let f: Vec<f64> = speed
                .iter()
                .map(|n| {
                    let f = order * n / 60.0;
                    if f <= top { f } else { f64::NAN }
                })
                .collect();
            plot = plot.with(Series::line(name, speed_time, &f));
            orders.push(format!("{name} {order:.3}"));
        }
    }
    Some(
        Section::new("vibration", "")
            .paragraph(format!(
                "The shaft speed changes over the run, so the spectrum changes with it: the spectrogram of {} over the whole run ({} samples at {} Hz; Hann segments of {} samples overlapping by half; levels in dB, 0 dB at the 99.5th percentile of the cells so that a start transient saturates rather than darkens the rest, down to {HEAT_FLOOR_DB} dB). Lines follow the orders of the shaft speed ({}): a component that rises with them is speed-locked, one that stays at a frequency is a resonance.",
                describe(channel).to_lowercase(),
                record.len(),
                cell(Some(rate)),
                segment,
                if orders.is_empty() {
                    "not known for this run".to_string()
                } else {
                    orders.join(", ")
                }
            ))
            .figure(plot),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_heat_map_puts_a_sine_in_its_row_and_pools_to_its_limits() {
        // 1 kHz at 16 kHz, 4 s: 1024-sample segments, 125 columns.
        let rate = 16_000.0;
        let record: Vec<f64> = (0..64_000)
            .map(|k| (std::f64::consts::TAU * 1000.0 * k as f64 / rate).sin())
            .collect();
        let sg = spectrogram(&record, rate, 1024, 0.5, Window::Hann).unwrap();
        let heat = heat_map(&sg, 2.0);
        let (columns, rows) = (heat.x_edges.len() - 1, heat.y_edges.len() - 1);
        assert!(
            columns <= HEAT_COLUMNS && rows <= HEAT_ROWS,
            "{columns} × {rows}"
        );
        assert_eq!(heat.levels.len(), columns * rows);
        assert!(
            (heat.x_edges[0] - 2.0).abs() < 0.05,
            "starts at the record's start"
        );
        assert!(
            heat.levels
                .iter()
                .all(|&l| (HEAT_FLOOR_DB..=0.0).contains(&l))
        );
        // In every column the loudest row holds 1 kHz, at 0 dB within 1 dB
        // (the sine's cells are more than half a percent of the cells).
        for column in heat.levels.chunks(rows) {
            let (k, top) = column
                .iter()
                .enumerate()
                .fold((0, f64::MIN), |a, (k, &l)| if l > a.1 { (k, l) } else { a });
            assert!(top > -1.0, "{top}");
            assert!(heat.y_edges[k] <= 1000.0 && 1000.0 <= heat.y_edges[k + 1]);
        }
    }

    #[test]
    fn a_ramp_is_a_speed_change_of_more_than_five_percent() {
        assert!(is_ramp(&[1000.0, 1100.0]));
        assert!(!is_ramp(&[1000.0, 1040.0, f64::NAN]));
        assert!(!is_ramp(&[]));
    }
}
