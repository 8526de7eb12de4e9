//! The records the vibration sections read from a run's time series:
//! the analysed channel over the averaging window (a run with a spall or
//! waviness) and over the whole run (a run-up or coast-down), at most
//! [`MAX_SAMPLES`] each.

use rolldyn_io::{InputError, float_columns, for_each_batch, read_schema};
use std::collections::VecDeque;
use std::path::Path;

/// The channel analysed without a sensor: the one of the summary's
/// `envelope_lines` then.
pub const CHANNEL: &str = "inner_ring_acceleration_z_m_s2";

/// The channel the summary's lines analysed (`envelope_lines.channel` or
/// `waviness_lines.channel`: the sensor's in a run with `[sensor]`), else
/// [`CHANNEL`].
pub fn analysed_channel(summary: &serde_json::Value) -> &str {
    ["envelope_lines", "waviness_lines"]
        .iter()
        .find_map(|key| summary.get(key)?.get("channel")?.as_str())
        .unwrap_or(CHANNEL)
}

/// Times \[s\] and values of one channel.
pub type Record = (Vec<f64>, Vec<f64>);

/// Most samples of the window kept (the last ones): 2¹⁶, 1 MB.
pub const MAX_SAMPLES: usize = 1 << 16;

/// Time and `channel` over `[t0, t1]` (the last [`MAX_SAMPLES`]), read in
/// one pass of two columns; None when the run did not record the channel.
pub fn read_window(
    path: &Path,
    channel: &str,
    [t0, t1]: [f64; 2],
) -> Result<Option<Record>, InputError> {
    if read_schema(path)?.unit(channel).is_none() {
        return Ok(None);
    }
    let mut kept = VecDeque::new();
    for_each_batch(path, Some(&["time_s", channel]), |batch| {
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

/// The records the section needs from the time series at `path`: over
/// the averaging `window` for a run with a spall or waviness (its summary
/// has envelope or waviness lines), over the whole run for a run whose shaft speed
/// (`series`' `inner_ring_speed_rpm`) changes ([`is_ramp`]).
pub fn read_records(
    path: &Path,
    summary: &serde_json::Value,
    series: &rolldyn_io::TimeSeries,
    window: [f64; 2],
) -> Result<(Option<Record>, Option<Record>), InputError> {
    let has = |key: &str| summary.get(key).is_some_and(|v| !v.is_null());
    let spalled = has("envelope_lines") || has("waviness_lines");
    let ramp = series.column("inner_ring_speed_rpm").is_some_and(is_ramp);
    let channel = analysed_channel(summary);
    let defect = if spalled {
        read_window(path, channel, window)?
    } else {
        None
    };
    let run_up = if ramp {
        read_window(path, channel, [f64::NEG_INFINITY, f64::INFINITY])?
    } else {
        None
    };
    Ok((defect, run_up))
}

/// Relative change of the shaft speed over a run, of its largest, above
/// which the report shows the spectrogram: a run-up or coast-down.
pub const RAMP_SPEED_CHANGE: f64 = 0.05;

/// Whether the shaft speeds `speed_rpm` of a run change by more than
/// [`RAMP_SPEED_CHANGE`] of the largest.
pub fn is_ramp(speed_rpm: &[f64]) -> bool {
    let (lo, hi) = speed_rpm
        .iter()
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    hi > 0.0 && hi - lo > RAMP_SPEED_CHANGE * hi.abs().max(lo.abs())
}
