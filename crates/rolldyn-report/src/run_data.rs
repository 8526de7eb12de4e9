//! What a run report reads from a run directory: `summary.json`, the time
//! series thinned for plotting with each channel's window mean, the cage
//! orbit, and `run.json` ([`RunData`]).

use crate::cell;
use crate::svg::Series;
use rolldyn_io::{TimeSeries, float_columns, for_each_batch, read_schema, row_count};
use serde_json::Value;
use std::collections::{HashMap, VecDeque};
use std::path::Path;

/// What the sections read.
pub struct RunData {
    /// `summary.json`.
    pub summary: Value,
    /// `timeseries.parquet`'s channels for the plots: every sample, or for
    /// a long record the extremes of [`PLOT_ROWS`]/2 equal buckets (what
    /// a plot of it shows); the other balls' channels are left out.
    pub series: TimeSeries,
    /// The channels recorded at `output.slow_rate`
    /// (`timeseries_slow.parquet`), reduced alike, when there are any.
    pub slow: Option<TimeSeries>,
    /// Each channel's mean over the summary's averaging window.
    pub window_means: HashMap<String, f64>,
    /// The cage centre's (y, z) over the last [`PLOT_ROWS`] samples.
    pub orbit: Option<(Vec<f64>, Vec<f64>)>,
    /// `run.json`, when present.
    pub record: Option<Value>,
    /// The case as `rolldyn check` describes it, when known.
    pub case_description: Option<String>,
    /// Time and the inner ring's vertical acceleration over the averaging
    /// window, unreduced, for a run with a spall ([`crate::vibration`]).
    pub vibration: Option<crate::vibration_data::Record>,
    /// The same over the whole run (its last
    /// [`crate::vibration_data::MAX_SAMPLES`]) when the shaft speed changes.
    pub run_up: Option<crate::vibration_data::Record>,
}

impl RunData {
    pub(crate) fn number(&self, key: &str) -> Option<f64> {
        self.summary.get(key).and_then(Value::as_f64)
    }

    pub(crate) fn text(&self, key: &str) -> Option<&str> {
        self.summary.get(key).and_then(Value::as_str)
    }

    /// The series that holds channel `name` (the slow one for a channel
    /// recorded at the slow rate).
    pub(crate) fn series_of(&self, name: &str) -> Option<&TimeSeries> {
        std::iter::once(&self.series)
            .chain(self.slow.as_ref())
            .find(|s| s.column(name).is_some_and(|c| !c.is_empty()))
    }

    pub(crate) fn channel(&self, name: &str) -> Option<&[f64]> {
        self.series_of(name)?.column(name)
    }

    /// The times of channel `name`'s samples.
    pub(crate) fn time_of(&self, name: &str) -> &[f64] {
        self.series_of(name)
            .and_then(|s| s.column("time_s"))
            .unwrap_or(&[])
    }

    pub(crate) fn ball_count(&self) -> usize {
        (0..)
            .take_while(|j| {
                self.window_means
                    .contains_key(&format!("ball{j}_load_inner_n"))
            })
            .count()
    }

    /// Mean of a channel over the summary's averaging window.
    pub(crate) fn window_mean(&self, name: &str) -> Option<f64> {
        self.window_means.get(name).copied()
    }

    /// Per-ball window means of a per-ball channel (`ball{j}_{suffix}`).
    pub(crate) fn per_ball(&self, suffix: &str) -> Vec<f64> {
        (0..self.ball_count())
            .map(|j| {
                self.window_mean(&format!("ball{j}_{suffix}"))
                    .unwrap_or(f64::NAN)
            })
            .collect()
    }

    /// A channel against time in milliseconds.
    pub(crate) fn against_time(&self, name: &str, legend: &str, scale: f64) -> Option<Series> {
        let t: Vec<f64> = self.time_of(name).iter().map(|t| 1e3 * t).collect();
        let y: Vec<f64> = self.channel(name)?.iter().map(|v| scale * v).collect();
        Some(Series::line(legend, &t, &y))
    }
}

/// Most rows of a channel the report holds (see [`RunData::series`]).
pub const PLOT_ROWS: usize = 16_384;

/// The report's own channel: the energy balance's error W + F − D − ΔE
/// row by row \[J\].
pub(crate) const BALANCE_ERROR: &str = "energy_balance_error_j";

/// Whether a channel is another ball's than ball 0 (window means only),
/// also of a bearing of a set (`bearing{i}_ball{j}_…`).
fn other_ball(name: &str) -> bool {
    let name = name
        .strip_prefix("bearing")
        .and_then(|rest| rest.split_once('_'))
        .map_or(name, |(_, rest)| rest);
    name.strip_prefix("ball")
        .and_then(|rest| rest.split_once('_'))
        .is_some_and(|(j, _)| j != "0")
}

/// What [`read_for_plots`] gives: the plotted series, the window means
/// and an orbit's last samples.
pub type PlotData = (
    TimeSeries,
    HashMap<String, f64>,
    Option<(Vec<f64>, Vec<f64>)>,
);

/// One pass over the time series at `path`, one batch in memory: the
/// channels to plot (reduced to bucket extremes when longer than
/// [`PLOT_ROWS`]), every channel's mean over `window` (finite values with
/// t in it) and the cage orbit's last [`PLOT_ROWS`] samples.
pub fn read_for_plots(path: &Path, window: [f64; 2]) -> Result<PlotData, rolldyn_io::InputError> {
    read_with_orbit(path, window, ["cage_y_m", "cage_z_m"])
}

/// The columns of the energy balance (drive work, film work if any,
/// dissipated and mechanical energy), with its error channel added to
/// `series`, if the record has them. The error is computed row by row,
/// before any reduction (extremes of its terms at different instants
/// would not difference to it).
fn balance_columns(
    index: &dyn Fn(&str) -> Option<usize>,
    series: &mut TimeSeries,
) -> Option<(usize, Option<usize>, usize, usize)> {
    match (
        index("drive_work_j"),
        index("dissipated_energy_j"),
        index("mechanical_energy_j"),
    ) {
        (Some(w), Some(d), Some(e)) => {
            series.channel(BALANCE_ERROR, "J");
            Some((w, index("film_work_j"), d, e))
        }
        _ => None,
    }
}

/// [`read_for_plots`] with the orbit of the channels `orbit` (y, z).
pub fn read_with_orbit(
    path: &Path,
    [t0, t1]: [f64; 2],
    orbit: [&str; 2],
) -> Result<PlotData, rolldyn_io::InputError> {
    let all = read_schema(path)?;
    let rows = row_count(path)? as usize;
    let names = all.names().to_vec();
    let plotted: Vec<usize> = (0..names.len())
        .filter(|&i| !other_ball(&names[i]))
        .collect();
    let mut series = TimeSeries::default();
    for &i in &plotted {
        series.channel(names[i].clone(), all.units()[i].clone());
    }
    let index = |name: &str| names.iter().position(|n| n == name);
    let balance = balance_columns(&index, &mut series);
    let width = series.width();
    let mut first_energy = None;
    let time = index("time_s");
    let orbit_columns = (
        names.iter().position(|n| n == orbit[0]),
        names.iter().position(|n| n == orbit[1]),
    );
    // Rows per bucket; each bucket gives two rows (its extremes in order).
    let bucket = if rows > PLOT_ROWS {
        rows.div_ceil(PLOT_ROWS / 2)
    } else {
        1
    };
    // Per plotted channel: (min, its row, max, its row) over the bucket.
    let mut extremes = vec![(f64::INFINITY, 0usize, f64::NEG_INFINITY, 0usize); width];
    let mut in_bucket = 0usize;
    let mut sums = vec![(0.0f64, 0usize); names.len()];
    let mut orbit = VecDeque::new();
    let mut row = vec![0.0; width];
    let mut second = vec![0.0; width];
    let mut values = Vec::with_capacity(width);
    let mut seen = 0usize;
    let mut flush = |extremes: &mut [(f64, usize, f64, usize)], series: &mut TimeSeries| {
        for (k, e) in extremes.iter().enumerate() {
            let (first, last) = if e.1 <= e.3 { (e.0, e.2) } else { (e.2, e.0) };
            row[k] = first;
            second[k] = last;
        }
        series.push(&row);
        series.push(&second);
        extremes.fill((f64::INFINITY, 0, f64::NEG_INFINITY, 0));
    };
    for_each_batch(path, None, |batch| {
        let columns = float_columns(batch)?;
        for r in 0..batch.num_rows() {
            let t = time.map_or(f64::NAN, |i| columns[i][r]);
            if t >= t0 && t <= t1 {
                for (sum, column) in sums.iter_mut().zip(&columns) {
                    if column[r].is_finite() {
                        sum.0 += column[r];
                        sum.1 += 1;
                    }
                }
            }
            if let (Some(y), Some(z)) = orbit_columns {
                if orbit.len() == PLOT_ROWS {
                    orbit.pop_front();
                }
                orbit.push_back((columns[y][r], columns[z][r]));
            }
            values.clear();
            values.extend(plotted.iter().map(|&i| columns[i][r]));
            if let Some((w, f, d, e)) = balance {
                let e0 = *first_energy.get_or_insert(columns[e][r]);
                let film = f.map_or(0.0, |f| columns[f][r]);
                values.push(columns[w][r] + film - columns[d][r] - (columns[e][r] - e0));
            }
            if bucket == 1 {
                series.push(&values);
            } else {
                for (e, &v) in extremes.iter_mut().zip(&values) {
                    // NaN never compares: a bucket of NaN stays a gap.
                    if v < e.0 {
                        (e.0, e.1) = (v, seen);
                    }
                    if v > e.2 {
                        (e.2, e.3) = (v, seen);
                    }
                }
                in_bucket += 1;
                if in_bucket == bucket {
                    flush(&mut extremes, &mut series);
                    in_bucket = 0;
                }
            }
            seen += 1;
        }
        Ok(())
    })?;
    if in_bucket > 0 {
        flush(&mut extremes, &mut series);
    }
    let means = names
        .iter()
        .zip(&sums)
        .filter(|(_, (_, n))| *n > 0)
        .map(|(name, (sum, n))| (name.clone(), sum / *n as f64))
        .collect();
    let orbit = (!orbit.is_empty()).then(|| orbit.into_iter().unzip());
    Ok((series, means, orbit))
}

/// Table rows (label, value, key) of the summary's `keys` that it has.
pub(crate) fn rows(data: &RunData, keys: &[(&str, &str)]) -> Vec<Vec<String>> {
    keys.iter()
        .filter(|(key, _)| data.summary.get(*key).is_some())
        .map(|(key, label)| vec![label.to_string(), cell(data.number(key)), key.to_string()])
        .collect()
}
