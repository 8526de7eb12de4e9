//! `rolldyn spectrum DIR`: the spectrum of one channel of a run
//! (DIR/timeseries.parquet) with the bearing's characteristic lines from the
//! run's own mean shaft and cage speeds and contact angles (DIR/summary.json),
//! a peak list naming the nearest line, and the vibration velocity RMS
//! (10–1000 Hz) of acceleration and velocity channels. Writes
//! `DIR/spectrum_<channel>_<kind>.csv` (frequency_hz,value; a spectrogram:
//! time_s,frequency_hz,value) and `.json`;
//! keys in docs/cli.md.

use crate::vibration::VELOCITY_BAND;
use crate::{Failure, bad_arg, emit, json};
use clap::Args;
use rolldyn::signal::{
    CharacteristicFrequencies, Fault, Spectrogram, Spectrum, Window, amplitude_spectrum, band_rms,
    band_velocity_rms, band_velocity_rms_of_displacement, default_envelope_band, envelope_spectrum,
    find_peaks, spectrogram, welch_psd,
};
use rolldyn::surface::SpallSite;
use rolldyn_io::RunDir;
use serde::Serialize;
use std::fmt::Write;
use std::path::Path;

/// `--kind`, `--window`, `--overlap`, `--harmonics` and `--peaks` by default.
pub const DEFAULT_KIND: &str = "amplitude";
pub const DEFAULT_WINDOW: &str = "hann";
pub const DEFAULT_OVERLAP: f64 = 0.5;
pub const DEFAULT_HARMONICS: usize = 5;
pub const DEFAULT_PEAKS: usize = 10;

/// Arguments of `rolldyn spectrum` (`Default`: the command line's defaults,
/// no run directory: give one).
#[derive(Args, Debug)]
pub struct SpectrumArgs {
    /// Run directory (timeseries.parquet, summary.json).
    pub dir: String,
    /// Channel to analyse (`rolldyn spectrum DIR --list` lists them;
    /// default: the housing sensor's `sensor_acceleration_m_s2` when the
    /// run has one, else `inner_ring_acceleration_z_m_s2`).
    #[arg(long)]
    pub channel: Option<String>,
    /// amplitude, psd (Welch), envelope or spectrogram (amplitude spectra
    /// of overlapping segments, for speed ramps).
    #[arg(long, default_value = DEFAULT_KIND)]
    pub kind: String,
    /// Window: hann or rectangular.
    #[arg(long, default_value = DEFAULT_WINDOW)]
    pub window: String,
    /// Segment length in samples (psd, spectrogram; default: a power of two
    /// near an eighth of the record).
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    pub segment: Option<usize>,
    /// Overlap fraction of the segments (psd, spectrogram).
    #[arg(long, default_value_t = DEFAULT_OVERLAP, allow_hyphen_values = true)]
    pub overlap: f64,
    /// Envelope band "LOW:HIGH", frequencies with their unit, e.g.
    /// "2 kHz:8 kHz" or "2000:8000 Hz" (envelope; default: 0.1 to 0.4 of
    /// the sample rate).
    #[arg(long, value_name = "LOW:HIGH", allow_hyphen_values = true)]
    pub band: Option<String>,
    /// Analyse samples from this time, e.g. "0.1 s" (default: the
    /// summary's averaging window, the second half of the run).
    #[arg(long, value_name = "TIME", allow_hyphen_values = true, value_parser = crate::time_value)]
    pub from: Option<f64>,
    /// Harmonics of each characteristic frequency to mark.
    #[arg(long, default_value_t = DEFAULT_HARMONICS, allow_hyphen_values = true)]
    pub harmonics: usize,
    /// Number of peaks to list.
    #[arg(long, default_value_t = DEFAULT_PEAKS, allow_hyphen_values = true)]
    pub peaks: usize,
    /// List the channels and exit.
    #[arg(long)]
    pub list: bool,
    /// Print the JSON report instead of text.
    #[arg(long)]
    pub json: bool,
}

impl Default for SpectrumArgs {
    fn default() -> Self {
        Self {
            dir: String::new(),
            channel: None,
            kind: DEFAULT_KIND.into(),
            window: DEFAULT_WINDOW.into(),
            segment: None,
            overlap: DEFAULT_OVERLAP,
            band: None,
            from: None,
            harmonics: DEFAULT_HARMONICS,
            peaks: DEFAULT_PEAKS,
            list: false,
            json: false,
        }
    }
}

#[derive(Serialize)]
struct LineEntry {
    name: String,
    frequency_hz: f64,
}

#[derive(Serialize)]
struct PeakEntry {
    frequency_hz: f64,
    value: f64,
    line: Option<String>,
    line_frequency_hz: Option<f64>,
    /// The other lines within the naming tolerance (1.5 bins).
    other_lines: Vec<String>,
}

#[derive(Serialize)]
struct Characteristic {
    shaft_hz: f64,
    cage_hz: f64,
    bpfo_hz: f64,
    bpfi_hz: f64,
    ball_spin_hz: f64,
    contact_angle_deg: f64,
}

#[derive(Serialize)]
pub struct Report {
    channel: String,
    unit: String,
    kind: String,
    value_unit: String,
    window: String,
    sample_rate_hz: f64,
    samples: usize,
    from_s: f64,
    to_s: f64,
    resolution_hz: f64,
    band_hz: Option<[f64; 2]>,
    /// Envelope: why the band cannot show the bearing's fastest defect
    /// rate (narrower than twice it), with the sample rate that would;
    /// null when it can (or for the other kinds).
    band_warning: Option<String>,
    segment: Option<usize>,
    /// Spectrogram: the number of segments (spectra) in the CSV.
    segments: Option<usize>,
    velocity_rms_mm_s: Option<f64>,
    velocity_rms_band_hz: Option<[f64; 2]>,
    characteristic: Characteristic,
    peaks: Vec<PeakEntry>,
    lines: Vec<LineEntry>,
    csv: String,
}

/// The subset of summary.json the lines need.
#[derive(serde::Deserialize)]
struct RunSummary {
    inner_ring_speed_rpm: f64,
    mean_cage_speed_rpm: f64,
    ball_count: usize,
    ball_diameter_m: f64,
    pitch_diameter_m: f64,
    mean_contact_angle_inner_deg: f64,
    mean_contact_angle_outer_deg: f64,
    averaging_window_s: [f64; 2],
}

pub fn command(args: SpectrumArgs) -> Result<(), Failure> {
    if args.list {
        let dir = Path::new(&args.dir);
        let mut series = rolldyn_io::read_schema(&RunDir::new(dir).series())
            .map_err(|e| Failure::BadInput(e.to_string()))?;
        let slow = RunDir::new(dir).slow_series();
        if slow.is_dir() {
            let more =
                rolldyn_io::read_schema(&slow).map_err(|e| Failure::BadInput(e.to_string()))?;
            for (name, unit) in more.names().iter().zip(more.units()).skip(1) {
                series.channel(name.clone(), unit.clone());
            }
        }
        if args.json {
            #[derive(serde::Serialize)]
            struct Channel<'a> {
                name: &'a str,
                unit: &'a str,
            }
            let channels: Vec<Channel> = series
                .names()
                .iter()
                .map(|name| Channel {
                    name,
                    unit: series.unit(name).unwrap_or(""),
                })
                .collect();
            return json(&channels);
        }
        let mut text = String::new();
        for name in series.names() {
            let _ = writeln!(text, "{name} [{}]", series.unit(name).unwrap_or(""));
        }
        return emit(&text);
    }
    let report = report(&args)?;
    if args.json {
        return json(&report);
    }
    emit(&report.to_text())
}

/// The record a spectrum is taken of: the channel from the start of
/// the window, with the run's summary.
struct Record {
    channel: String,
    unit: String,
    time: Vec<f64>,
    values: Vec<f64>,
    /// A velocity channel's displacement channel, where the series has it
    /// (the velocity RMS from its interval means, as the summary's).
    displacement: Option<Vec<f64>>,
    summary: RunSummary,
}

/// The displacement channel of a velocity channel by the recorder's names
/// (`inner_ring_velocity_z_m_s` → `inner_ring_z_m`); None for others.
fn displacement_channel(velocity: &str) -> Option<String> {
    let (body, axis) = velocity.strip_suffix("_m_s")?.split_once("_velocity_")?;
    Some(format!("{body}_{axis}_m"))
}

/// Reads the channel of `args` (the sensor's, else the envelope
/// channel's) from `--from` (the summary's averaging window) on; only the
/// time and that channel are read, so a long record is not loaded whole.
fn read_record(args: &SpectrumArgs, dir: &Path) -> Result<Record, Failure> {
    let mut path = RunDir::new(dir).series();
    let mut channels =
        rolldyn_io::read_schema(&path).map_err(|e| Failure::BadInput(e.to_string()))?;
    let channel = match &args.channel {
        Some(channel) => channel.clone(),
        None if channels.unit(crate::vibration::SENSOR_CHANNEL).is_some() => {
            crate::vibration::SENSOR_CHANNEL.to_string()
        }
        None => crate::vibration::ENVELOPE_CHANNEL.to_string(),
    };
    let slow = RunDir::new(dir).slow_series();
    if channels.unit(&channel).is_none() && slow.is_dir() {
        // A channel recorded at output.slow_rate.
        path = slow;
        channels = rolldyn_io::read_schema(&path).map_err(|e| Failure::BadInput(e.to_string()))?;
    }
    let no_channel = || {
        bad_arg(
            "--channel",
            &channel,
            "no such channel (rolldyn spectrum DIR --list shows them)",
        )
    };
    let no_time = || Failure::BadInput("timeseries.parquet has no time_s column".into());
    if channels.unit(&channel).is_none() {
        return Err(no_channel());
    }
    if channels.unit("time_s").is_none() {
        return Err(no_time());
    }
    let displacement =
        displacement_channel(&channel).filter(|name| channels.unit(name) == Some("m"));
    let mut columns = vec!["time_s", channel.as_str()];
    columns.extend(displacement.as_deref());
    let series = rolldyn_io::read_columns(&path, Some(&columns))
        .map_err(|e| Failure::BadInput(e.to_string()))?;
    let summary_path = RunDir::new(dir).summary();
    let summary: RunSummary = std::fs::read_to_string(&summary_path)
        .map_err(|e| e.to_string())
        .and_then(|t| serde_json::from_str(&t).map_err(|e| e.to_string()))
        .map_err(|e| {
            Failure::BadInput(format!(
                "{}: {e} (a summary.json of rolldyn run is needed for the characteristic lines)",
                summary_path.display()
            ))
        })?;
    let values = series.column(&channel).ok_or_else(no_channel)?;
    let time = series.column("time_s").ok_or_else(no_time)?;
    let from_time = args.from.unwrap_or(summary.averaging_window_s[0]);
    if !from_time.is_finite() {
        return Err(bad_arg("--from", &from_time.to_string(), "must be finite"));
    }
    let from = time
        .iter()
        .position(|&t| t >= from_time)
        .unwrap_or(time.len());
    let samples = time.len() - from;
    if samples < 16 {
        let rule = format!("leaves {samples} samples; a spectrum needs at least 16");
        return Err(match args.from {
            Some(_) => bad_arg("--from", &from_time.to_string(), rule),
            // The user gave no --from: the window is the summary's.
            None => Failure::BadInput(format!(
                "{}: the run's averaging window (from t = {from_time} s, its second half) holds {samples} samples of {channel}; a spectrum needs at least 16: run longer or at a higher output.sample_rate, or pass --from \"0 s\" for the whole record",
                dir.display(),
            )),
        });
    }
    Ok(Record {
        unit: series.unit(&channel).unwrap_or("").to_string(),
        time: time[from..].to_vec(),
        values: values[from..].to_vec(),
        displacement: displacement
            .and_then(|name| series.column(&name))
            .map(|x| x[from..].to_vec()),
        channel,
        summary,
    })
}

/// A spectrum of `--kind`: the spectrum (a spectrogram's mean over its
/// segments), its value unit, the envelope band, the segment length and
/// a spectrogram's frames.
struct Analysis {
    spectrum: Spectrum,
    value_unit: String,
    band: Option<[f64; 2]>,
    segment: Option<usize>,
    frames: Option<Spectrogram>,
}

fn analyse(
    args: &SpectrumArgs,
    band: Option<(f64, f64)>,
    record: &[f64],
    unit: &str,
    sample_rate: f64,
) -> Result<Analysis, Failure> {
    let window = match args.window.as_str() {
        "hann" => Window::Hann,
        "rectangular" => Window::Rectangular,
        w => return Err(bad_arg("--window", w, "expected hann or rectangular")),
    };
    let spectrum_error = |e: rolldyn::signal::SpectrumError| Failure::BadInput(e.to_string());
    let segment = args
        .segment
        .unwrap_or_else(|| (record.len() / 8).max(16).next_power_of_two() / 2);
    let plain = |spectrum, value_unit: String, band, segment| Analysis {
        spectrum,
        value_unit,
        band,
        segment,
        frames: None,
    };
    Ok(match args.kind.as_str() {
        "amplitude" => plain(
            amplitude_spectrum(record, sample_rate, window).map_err(spectrum_error)?,
            unit.to_string(),
            None,
            None,
        ),
        "psd" => plain(
            welch_psd(record, sample_rate, segment, args.overlap, window)
                .map_err(spectrum_error)?,
            format!("({unit})^2/Hz"),
            None,
            Some(segment),
        ),
        "envelope" => {
            let band = band.unwrap_or_else(|| default_envelope_band(sample_rate));
            plain(
                envelope_spectrum(record, sample_rate, band, window).map_err(spectrum_error)?,
                unit.to_string(),
                Some([band.0, band.1]),
                None,
            )
        }
        "spectrogram" => {
            let sg = spectrogram(record, sample_rate, segment, args.overlap, window)
                .map_err(spectrum_error)?;
            // Peaks and lines from the segments' mean spectrum.
            let n = sg.value.len().max(1) as f64;
            let mean = Spectrum {
                frequency: sg.frequency.clone(),
                value: (0..sg.frequency.len())
                    .map(|k| sg.value.iter().map(|v| v[k]).sum::<f64>() / n)
                    .collect(),
            };
            Analysis {
                frames: Some(sg),
                ..plain(mean, unit.to_string(), None, Some(segment))
            }
        }
        k => {
            return Err(bad_arg(
                "--kind",
                k,
                "expected amplitude, psd, envelope or spectrogram",
            ));
        }
    })
}

/// The CSV of an analysis: `frequency_hz,value` rows, or of a
/// spectrogram one row per segment and frequency, the segment by the
/// time of its centre (`start` the record's first time).
fn spectrum_csv(analysis: &Analysis, start: f64) -> String {
    let mut csv = String::new();
    match &analysis.frames {
        Some(sg) => {
            csv.push_str("time_s,frequency_hz,value\n");
            for (t, spectrum) in sg.time.iter().zip(&sg.value) {
                for (f, v) in sg.frequency.iter().zip(spectrum) {
                    let _ = writeln!(csv, "{},{f},{v:e}", start + t);
                }
            }
        }
        None => {
            csv.push_str("frequency_hz,value\n");
            let spectrum = &analysis.spectrum;
            for (f, v) in spectrum.frequency.iter().zip(&spectrum.value) {
                let _ = writeln!(csv, "{f},{v:e}");
            }
        }
    }
    csv
}

/// The spectrum `rolldyn spectrum --json` prints; writes its CSV and JSON
/// files into the run directory.
pub fn report(args: &SpectrumArgs) -> Result<Report, Failure> {
    // The options' values first: refused before the record is read.
    let band = args.band.as_deref().map(parse_band).transpose()?;
    let dir = Path::new(&args.dir);
    let Record {
        channel,
        unit,
        time,
        values: record,
        displacement,
        summary,
    } = read_record(args, dir)?;
    let sample_rate = (time.len() - 1) as f64 / (time[time.len() - 1] - time[0]);
    let analysis = analyse(args, band, &record, &unit, sample_rate)?;
    let spectrum = &analysis.spectrum;
    let alpha = 0.5
        * (summary.mean_contact_angle_inner_deg + summary.mean_contact_angle_outer_deg)
            .to_radians();
    let characteristic = CharacteristicFrequencies::new(
        summary.inner_ring_speed_rpm / 60.0,
        summary.mean_cage_speed_rpm / 60.0,
        summary.ball_count,
        summary.ball_diameter_m / summary.pitch_diameter_m,
        alpha,
    );
    // Lines up to the spectrum's end: the marked ones (`--harmonics`), and
    // every family's harmonics for naming the peaks.
    let band_end = spectrum.frequency.last().copied().unwrap_or(0.0);
    let lines = characteristic.lines_up_to(band_end, args.harmonics);
    let naming = characteristic.lines_up_to(band_end, MAX_NAMING_HARMONICS);
    let resolution = spectrum.resolution();
    let peaks = find_peaks(
        spectrum,
        resolution,
        args.peaks,
        &naming,
        1.5 * resolution,
        &faults(dir),
    );
    let velocity_band = (VELOCITY_BAND.0, VELOCITY_BAND.1.min(0.5 * sample_rate));
    let velocity_rms = match (unit.as_str(), &displacement) {
        ("m/s^2", _) => band_velocity_rms(&record, sample_rate, velocity_band).ok(),
        ("m/s", Some(x)) => band_velocity_rms_of_displacement(x, sample_rate, velocity_band).ok(),
        ("m/s", None) => band_rms(&record, sample_rate, velocity_band).ok(),
        _ => None,
    }
    .map(|v| 1e3 * v);
    let stem = format!("spectrum_{}_{}", channel, args.kind);
    let csv_path = dir.join(format!("{stem}.csv"));
    rolldyn_io::write_atomic(&csv_path, spectrum_csv(&analysis, time[0]).as_bytes())
        .map_err(|e| Failure::BadInput(e.to_string()))?;
    let report = Report {
        channel: channel.clone(),
        unit,
        kind: args.kind.clone(),
        value_unit: analysis.value_unit.clone(),
        window: args.window.clone(),
        sample_rate_hz: sample_rate,
        samples: record.len(),
        from_s: time[0],
        to_s: time[time.len() - 1],
        resolution_hz: resolution,
        band_hz: analysis.band,
        band_warning: analysis
            .band
            .and_then(|[lo, hi]| crate::vibration::band_warning((lo, hi), &characteristic)),
        segment: analysis.segment,
        segments: analysis.frames.as_ref().map(|sg| sg.time.len()),
        velocity_rms_mm_s: velocity_rms,
        velocity_rms_band_hz: velocity_rms.map(|_| [velocity_band.0, velocity_band.1]),
        characteristic: Characteristic {
            shaft_hz: characteristic.shaft,
            cage_hz: characteristic.cage,
            bpfo_hz: characteristic.bpfo,
            bpfi_hz: characteristic.bpfi,
            ball_spin_hz: characteristic.ball_spin,
            contact_angle_deg: alpha.to_degrees(),
        },
        peaks: peaks
            .into_iter()
            .map(|p| PeakEntry {
                frequency_hz: p.frequency,
                value: p.value,
                line: p.line,
                line_frequency_hz: p.line_frequency,
                other_lines: p.other_lines,
            })
            .collect(),
        lines: lines
            .into_iter()
            .map(|l| LineEntry {
                name: l.name,
                frequency_hz: l.frequency,
            })
            .collect(),
        csv: csv_path.display().to_string(),
    };
    let text = crate::finite::to_json(&report).map_err(|e| Failure::Internal(e.to_string()))?;
    rolldyn_io::write_atomic(&dir.join(format!("{stem}.json")), (text + "\n").as_bytes())
        .map_err(|e| Failure::BadInput(e.to_string()))?;
    Ok(report)
}

/// Most harmonics of the lowest line (the cage's) the peaks are named
/// by: 20 000 reach 100 kHz at a 5 Hz cage.
const MAX_NAMING_HARMONICS: usize = 20_000;

/// The families of the faults of the run's case (its spalls), whose lines
/// name the peaks they could share with another line; none when the
/// directory's record cannot be read.
fn faults(dir: &Path) -> Vec<Fault> {
    let Ok(record) = crate::checkpoint::RunRecord::read(dir) else {
        return Vec::new();
    };
    let Ok(case) = record
        .overrides
        .load_text(&record.source, record.case_text.as_deref())
    else {
        return Vec::new();
    };
    let mut faults: Vec<Fault> = case
        .surface
        .spalls()
        .map(|(site, _)| match site {
            SpallSite::Outer => Fault::OuterRace,
            SpallSite::Inner => Fault::InnerRace,
            SpallSite::Ball(_) => Fault::Ball,
        })
        .collect();
    faults.dedup();
    faults
}

fn parse_band(text: &str) -> Result<(f64, f64), Failure> {
    use rolldyn_case::units::{Frequency, parse_quantity};
    let rule = "expected LOW:HIGH, two frequencies with 0 ≤ LOW < HIGH, e.g. \"2 kHz:8 kHz\" or \"2000:8000 Hz\" (LOW without a unit takes HIGH's)";
    let Some((low, high)) = text.split_once(':') else {
        return Err(bad_arg("--band", text, rule));
    };
    let (low, high) = (low.trim(), high.trim());
    let hi = parse_quantity::<Frequency>(high).map_err(|e| bad_arg("--band", text, e))?;
    // LOW's unit may be left to HIGH's: "2000:8000 Hz".
    let unit = high.trim_start_matches(|c: char| c.is_ascii_digit() || ".eE+-_".contains(c));
    let lo = parse_quantity::<Frequency>(low)
        .or_else(|e| {
            let bare = low.parse::<f64>().is_ok();
            if bare {
                parse_quantity::<Frequency>(&format!("{low} {unit}"))
            } else {
                Err(e)
            }
        })
        .map_err(|e| bad_arg("--band", text, e))?;
    if (0.0..hi).contains(&lo) {
        Ok((lo, hi))
    } else {
        Err(bad_arg("--band", text, rule))
    }
}

impl Report {
    fn to_text(&self) -> String {
        let mut t = String::new();
        let c = &self.characteristic;
        let _ = writeln!(
            t,
            "{} spectrum of {} [{}], {} samples at {:.0} Hz from {:.4} s to {:.4} s, resolution {:.3} Hz, {} window",
            self.kind,
            self.channel,
            self.unit,
            self.samples,
            self.sample_rate_hz,
            self.from_s,
            self.to_s,
            self.resolution_hz,
            self.window
        );
        if let Some([lo, hi]) = self.band_hz {
            let _ = writeln!(t, "envelope band {lo:.0}–{hi:.0} Hz");
        }
        if let Some(warning) = &self.band_warning {
            let _ = writeln!(t, "warning: {warning}");
        }
        if let (Some(n), Some(segment)) = (self.segments, self.segment) {
            let _ = writeln!(
                t,
                "{n} segments of {segment} samples; the peaks are of their mean spectrum"
            );
        }
        let _ = writeln!(
            t,
            "lines from the run: f_i {:.2} Hz, f_c {:.2} Hz, BPFO {:.1} Hz, BPFI {:.1} Hz, BSF {:.1} Hz (α {:.2}°)",
            c.shaft_hz, c.cage_hz, c.bpfo_hz, c.bpfi_hz, c.ball_spin_hz, c.contact_angle_deg
        );
        if let (Some(v), Some([lo, hi])) = (self.velocity_rms_mm_s, self.velocity_rms_band_hz) {
            let _ = writeln!(t, "vibration velocity RMS {v:.4} mm/s ({lo:.0}–{hi:.0} Hz)");
        }
        let _ = writeln!(t, "{:>12} {:>14}  nearest line", "f [Hz]", self.value_unit);
        for p in &self.peaks {
            let mut line = match (&p.line, p.line_frequency_hz) {
                (Some(name), Some(f)) => format!("{name} ({f:.1} Hz)"),
                _ => "—".to_string(),
            };
            if !p.other_lines.is_empty() {
                line += &format!(", or {}", p.other_lines.join(", "));
            }
            let _ = writeln!(t, "{:>12.2} {:>14.4e}  {line}", p.frequency_hz, p.value);
        }
        let _ = writeln!(t, "wrote {}", self.csv);
        t
    }
}
