//! The statistics of a run's summary, accumulated sample by sample while
//! the run goes (the time series itself is on disk, not in memory).
//!
//! Time is cut into blocks of equal length, [`BLOCKS`] of them over the
//! requested duration; each block keeps, per channel, the count, sum,
//! extremes and the sum and count over loaded contacts (for the per-ball
//! channels of one raceway: samples where that ball's load on it is
//! positive), and its first row. Any window that starts on a block
//! boundary is the merge of its blocks: the summary's averaging window,
//! the second half of the run, is blocks `BLOCKS/2 …` for a completed run
//! and, for an interrupted or partial one, the blocks from the one holding
//! half its simulated time. A run extended beyond its duration (`--until`)
//! goes on with more blocks; beyond [`MAX_BLOCKS`] neighbours merge in
//! pairs (the blocks double in length). Memory: at most `MAX_BLOCKS` × 5
//! numbers per channel, whatever the duration.
//!
//! Each block also keeps the intervals between successive ball passages
//! that end in it (count, mean, squared deviations: `ball_pass_jitter`),
//! timed sample by sample (`passages`).
//!
//! The vibration RMS and the cage-whirl metrics need the signal itself
//! (a band filter, the orbit's centre): the few channels they use are kept
//! for the last half of the duration, at most [`SIGNAL_SAMPLES`] samples.
//!
//! The statistics are part of a run's checkpoint ([`RunStatistics::save`]),
//! so a resumed run ends with the same numbers as a run never interrupted,
//! whatever channels it chose to record, without reading its series back.

mod passages;

use passages::PassageWatch;
use rolldyn::integrate::{CheckpointError, StateReader, StateWriter};
use rolldyn::signal::passage::{IntervalSums, PassageJitter};
use rolldyn_io::TimeSeries;
use std::collections::VecDeque;

/// Blocks of the requested duration.
pub const BLOCKS: usize = 64;

/// Most blocks kept (an extended run merges pairs beyond it).
pub const MAX_BLOCKS: usize = 2 * BLOCKS;

/// Most samples of the vibration and whirl channels kept (0.8 s at the
/// default case's 20 kHz: eight periods of the RMS band's 10 Hz edge and
/// sixty cage revolutions; 1.6 s at 10 kHz); longer windows use their last
/// part, so that memory stays put (1.6 MB, and as much for the summary's
/// copy).
pub const SIGNAL_SAMPLES: usize = 1 << 14;

/// The channels the vibration and whirl metrics read.
const SIGNAL_CHANNELS: [&str; 13] = [
    "time_s",
    "cage_speed_rpm",
    "cage_y_m",
    "cage_z_m",
    "cage_velocity_y_m_s",
    "cage_velocity_z_m_s",
    // The rings' velocity RMS, from interval means of the displacements
    // (`rolldyn::signal::band_velocity_rms_of_displacement`).
    "inner_ring_x_m",
    "inner_ring_y_m",
    "inner_ring_z_m",
    "outer_ring_y_m",
    "outer_ring_z_m",
    // The envelope lines of a run with a spall or a sensor
    // (`crate::vibration`).
    "inner_ring_acceleration_z_m_s2",
    "sensor_acceleration_m_s2",
];

/// The block of time `t` for blocks of `length` \[s\].
fn block_index(t: f64, length: f64) -> usize {
    let k = (t / length).floor();
    if k.is_finite() && k > 0.0 {
        k as usize
    } else {
        0
    }
}

/// One block's statistics.
#[derive(Debug, Clone)]
struct Block {
    count: u64,
    first: Vec<f64>,
    sum: Vec<f64>,
    max: Vec<f64>,
    min: Vec<f64>,
    loaded_sum: Vec<f64>,
    loaded_count: Vec<u64>,
    /// Intervals between successive ball passages ending in the block.
    passages: IntervalSums,
}

impl Block {
    /// Adds `other`, the block that follows this one.
    fn merge(&mut self, other: &Block) {
        if other.count == 0 {
            return;
        }
        if self.count == 0 {
            self.first = other.first.clone();
        }
        self.count += other.count;
        self.passages.merge(&other.passages);
        for i in 0..self.sum.len() {
            self.sum[i] += other.sum[i];
            self.max[i] = self.max[i].max(other.max[i]);
            self.min[i] = self.min[i].min(other.min[i]);
            self.loaded_sum[i] += other.loaded_sum[i];
            self.loaded_count[i] += other.loaded_count[i];
        }
    }

    fn new(width: usize) -> Self {
        Self {
            count: 0,
            first: Vec::new(),
            sum: vec![0.0; width],
            max: vec![f64::NEG_INFINITY; width],
            min: vec![f64::INFINITY; width],
            loaded_sum: vec![0.0; width],
            loaded_count: vec![0; width],
            passages: IntervalSums::default(),
        }
    }
}

/// Statistics of a run's channels, sample by sample.
#[derive(Debug, Clone)]
pub struct RunStatistics {
    names: Vec<String>,
    units: Vec<String>,
    /// Length of a block \[s\].
    block_length: f64,
    blocks: Vec<Block>,
    /// For each channel, the load channel that says whether it is loaded.
    load_of: Vec<Option<usize>>,
    first: Vec<f64>,
    last: Vec<f64>,
    samples: u64,
    signal_index: Vec<usize>,
    signal: VecDeque<[f64; SIGNAL_CHANNELS.len()]>,
    signal_capacity: usize,
    passages: Option<PassageWatch>,
}

impl RunStatistics {
    /// Statistics of the channels of `template` over a run of `duration`
    /// recorded at `sample_rate`; the balls' passages are timed at azimuth
    /// `passage_azimuth` \[rad\].
    pub fn new(
        template: &TimeSeries,
        duration: f64,
        sample_rate: f64,
        passage_azimuth: f64,
    ) -> Self {
        let names: Vec<String> = template.names().to_vec();
        let index = |name: &str| names.iter().position(|n| n == name);
        let load_of = names
            .iter()
            .map(|name| {
                let ball = name.strip_prefix("ball")?;
                let (j, rest) = ball.split_once('_')?;
                let ring = if rest.contains("_inner") || rest.ends_with("inner") {
                    "inner"
                } else if rest.contains("_outer") || rest.ends_with("outer") {
                    "outer"
                } else {
                    return None;
                };
                index(&format!("ball{j}_load_{ring}_n"))
            })
            .collect();
        let signal_index = SIGNAL_CHANNELS
            .iter()
            .map(|n| index(n).unwrap_or(usize::MAX))
            .collect();
        let half = (0.5 * duration * sample_rate).ceil();
        let signal_capacity = if half.is_finite() {
            (half as usize + 2).min(SIGNAL_SAMPLES)
        } else {
            SIGNAL_SAMPLES
        };
        Self {
            blocks: vec![Block::new(names.len()); BLOCKS],
            units: template.units().to_vec(),
            names,
            block_length: duration / BLOCKS as f64,
            load_of,
            first: Vec::new(),
            last: Vec::new(),
            samples: 0,
            signal_index,
            signal: VecDeque::new(),
            signal_capacity,
            passages: PassageWatch::new(template.names(), passage_azimuth),
        }
    }

    /// The block of time `t`.
    fn block_of(&self, t: f64) -> usize {
        block_index(t, self.block_length)
    }

    /// Adds one sample (the recorder's row; its first value is the time).
    pub fn push(&mut self, row: &[f64]) {
        let t = row.first().copied().unwrap_or(0.0);
        let mut b = self.block_of(t);
        while b >= MAX_BLOCKS {
            // Pairs merge: blocks twice as long, half as many.
            let merged: Vec<Block> = self
                .blocks
                .chunks(2)
                .map(|pair| {
                    let mut block = pair[0].clone();
                    if let Some(next) = pair.get(1) {
                        block.merge(next);
                    }
                    block
                })
                .collect();
            self.blocks = merged;
            self.block_length *= 2.0;
            b = self.block_of(t);
        }
        if self.blocks.len() <= b {
            self.blocks.resize(b + 1, Block::new(self.names.len()));
        }
        let block = &mut self.blocks[b];
        if block.count == 0 {
            block.first = row.to_vec();
        }
        block.count += 1;
        for (i, &v) in row.iter().enumerate() {
            block.sum[i] += v;
            block.max[i] = block.max[i].max(v);
            block.min[i] = block.min[i].min(v);
            if let Some(load) = self.load_of[i] {
                if row[load] > 0.0 {
                    block.loaded_sum[i] += v;
                    block.loaded_count[i] += 1;
                }
            }
        }
        if self.first.is_empty() {
            self.first = row.to_vec();
        }
        self.last.clear();
        self.last.extend_from_slice(row);
        self.samples += 1;
        if let Some(watch) = &mut self.passages {
            let (blocks, length) = (&mut self.blocks, self.block_length);
            watch.push(row, &mut |end, interval| {
                if let Some(block) = blocks.get_mut(block_index(end, length)) {
                    block.passages.add(interval);
                }
            });
        }
        let mut signal = [0.0; SIGNAL_CHANNELS.len()];
        for (s, &i) in signal.iter_mut().zip(&self.signal_index) {
            *s = row.get(i).copied().unwrap_or(0.0);
        }
        if self.signal.len() == self.signal_capacity {
            self.signal.pop_front();
        }
        self.signal.push_back(signal);
    }

    /// Writes the statistics into a checkpoint.
    pub fn save(&self, w: &mut StateWriter) {
        w.tag("run-statistics");
        w.u64(self.names.len() as u64);
        w.u64(self.samples);
        let optional = |w: &mut StateWriter, row: &[f64]| {
            w.u64(u64::from(!row.is_empty()));
            if !row.is_empty() {
                w.f64s(row);
            }
        };
        optional(w, &self.first);
        optional(w, &self.last);
        w.f64(self.block_length);
        w.u64(self.blocks.len() as u64);
        for block in &self.blocks {
            w.u64(block.count);
            optional(w, &block.first);
            for values in [&block.sum, &block.max, &block.min, &block.loaded_sum] {
                w.f64s(values);
            }
            for &n in &block.loaded_count {
                w.u64(n);
            }
            let p = &block.passages;
            w.u64(p.count);
            w.f64(p.mean);
            w.f64(p.squared_deviations);
        }
        w.u64(self.signal.len() as u64);
        for row in &self.signal {
            w.f64s(row);
        }
        if let Some(watch) = &self.passages {
            watch.save(w);
        }
    }

    /// Restores the statistics of a checkpoint (of a run with the same
    /// channels).
    pub fn restore(&mut self, r: &mut StateReader) -> Result<(), CheckpointError> {
        r.tag("run-statistics")?;
        let width = self.names.len();
        let stored = r.u64()?;
        if stored != width as u64 {
            return Err(CheckpointError::Mismatch(format!(
                "statistics of {stored} channels, this run {width}"
            )));
        }
        self.samples = r.u64()?;
        let optional = |r: &mut StateReader, what: &str| -> Result<Vec<f64>, CheckpointError> {
            if r.u64()? == 0 {
                return Ok(Vec::new());
            }
            let mut row = vec![0.0; width];
            r.f64s_into(what, &mut row)?;
            Ok(row)
        };
        self.first = optional(r, "first sample")?;
        self.last = optional(r, "last sample")?;
        // The checkpoint's blocks (a run extended with --until goes on
        // with them).
        self.block_length = r.f64()?;
        let blocks = r.u64()? as usize;
        if !(self.block_length > 0.0 && (1..=MAX_BLOCKS).contains(&blocks)) {
            return Err(CheckpointError::Mismatch(format!(
                "{blocks} statistics blocks of {} s",
                self.block_length
            )));
        }
        self.blocks = vec![Block::new(width); blocks];
        for block in &mut self.blocks {
            block.count = r.u64()?;
            block.first = optional(r, "block's first sample")?;
            for (what, values) in [
                ("sums", &mut block.sum),
                ("maxima", &mut block.max),
                ("minima", &mut block.min),
                ("loaded sums", &mut block.loaded_sum),
            ] {
                r.f64s_into(what, values)?;
            }
            for n in &mut block.loaded_count {
                *n = r.u64()?;
            }
            block.passages = IntervalSums {
                count: r.u64()?,
                mean: r.f64()?,
                squared_deviations: r.f64()?,
            };
        }
        // A run extended with --until keeps more (half its new duration);
        // one given a shorter duration keeps the newest that fit.
        let kept = r.u64()? as usize;
        self.signal.clear();
        for _ in 0..kept {
            let mut row = [0.0; SIGNAL_CHANNELS.len()];
            r.f64s_into("signal sample", &mut row)?;
            if self.signal.len() == self.signal_capacity {
                self.signal.pop_front();
            }
            self.signal.push_back(row);
        }
        if let Some(watch) = &mut self.passages {
            watch.restore(r)?;
        }
        Ok(())
    }

    /// Samples pushed.
    pub fn samples(&self) -> u64 {
        self.samples
    }

    /// Whether the series has channel `name`.
    pub fn has(&self, name: &str) -> bool {
        self.index(name).is_some()
    }

    fn index(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| n == name)
    }

    /// Value of `name` in the run's first sample (0 without samples).
    pub fn first(&self, name: &str) -> f64 {
        self.index(name)
            .and_then(|i| self.first.get(i))
            .copied()
            .unwrap_or(0.0)
    }

    /// Value of `name` in the run's last sample (0 without samples).
    pub fn last(&self, name: &str) -> f64 {
        self.index(name)
            .and_then(|i| self.last.get(i))
            .copied()
            .unwrap_or(0.0)
    }

    /// The averaging window: the second half of the run (from the block
    /// holding half the last sample's time).
    pub fn window(&self) -> Window<'_> {
        self.window_over(self.window_start()..self.blocks.len())
    }

    /// The averaging window's two halves (its blocks split in the middle),
    /// for how much its statistics move within it; None with fewer than
    /// two blocks of samples in it, or when the kept signal
    /// ([`SIGNAL_SAMPLES`]) does not reach back to the window's start (a
    /// long run: its first half would have no vibration record).
    pub fn window_halves(&self) -> Option<[Window<'_>; 2]> {
        let from = self.window_start();
        let to = self.blocks.len();
        let middle = from + (to - from) / 2;
        let filled = |range: std::ops::Range<usize>| self.blocks[range].iter().any(|b| b.count > 0);
        if middle <= from || !filled(from..middle) || !filled(middle..to) {
            return None;
        }
        let [first, second] = [self.window_over(from..middle), self.window_over(middle..to)];
        let signal_start = self.signal.front().map_or(f64::INFINITY, |r| r[0]);
        (signal_start <= first.span()[0]).then_some([first, second])
    }

    fn window_start(&self) -> usize {
        let t_end = self.last.first().copied().unwrap_or(0.0);
        self.block_of(0.5 * t_end).min(self.blocks.len())
    }

    /// The window of `blocks`; it ends at the first sample of the next
    /// block that has one, or at the run's last sample.
    fn window_over(&self, blocks: std::ops::Range<usize>) -> Window<'_> {
        let mut merged = Block::new(self.names.len());
        for block in &self.blocks[blocks.clone()] {
            merged.merge(block);
        }
        let end = self.blocks[blocks.end..]
            .iter()
            .find(|b| b.count > 0)
            .map_or(self.last.as_slice(), |b| b.first.as_slice());
        Window {
            stats: self,
            merged,
            end,
        }
    }
}

/// The statistics over the averaging window.
pub struct Window<'a> {
    stats: &'a RunStatistics,
    merged: Block,
    /// The row at the window's end: the next block's first sample, or the
    /// run's last.
    end: &'a [f64],
}

impl Window<'_> {
    /// Time of the window's first sample and of its end (the run's last
    /// sample for the averaging window) \[s\].
    pub fn span(&self) -> [f64; 2] {
        [
            self.merged.first.first().copied().unwrap_or(0.0),
            self.end.first().copied().unwrap_or(0.0),
        ]
    }

    /// Value of `name` at the window's end (the run's last sample for the
    /// averaging window).
    pub fn last(&self, name: &str) -> f64 {
        self.stats
            .index(name)
            .and_then(|i| self.end.get(i))
            .copied()
            .unwrap_or(0.0)
    }

    /// Value of `name` at the window's first sample.
    pub fn first(&self, name: &str) -> f64 {
        self.stats
            .index(name)
            .and_then(|i| self.merged.first.get(i))
            .copied()
            .unwrap_or(0.0)
    }

    /// Mean of `name` over the window (0 when empty or absent).
    pub fn mean(&self, name: &str) -> f64 {
        match self.stats.index(name) {
            Some(i) if self.merged.count > 0 => self.merged.sum[i] / self.merged.count as f64,
            _ => 0.0,
        }
    }

    /// The channels `ball{j}_{suffix}` of every ball present.
    fn per_ball(&self, suffix: &str) -> Vec<usize> {
        (0..)
            .map_while(|j| self.stats.index(&format!("ball{j}_{suffix}")))
            .collect()
    }

    /// Mean of `ball{j}_{suffix}` over all balls and the window.
    pub fn pooled_mean(&self, suffix: &str) -> f64 {
        let channels = self.per_ball(suffix);
        let count = self.merged.count * channels.len() as u64;
        if count == 0 {
            return 0.0;
        }
        channels.iter().map(|&i| self.merged.sum[i]).sum::<f64>() / count as f64
    }

    /// Largest `ball{j}_{suffix}` over all balls and the window (at least 0).
    pub fn pooled_max(&self, suffix: &str) -> f64 {
        self.per_ball(suffix)
            .iter()
            .map(|&i| self.merged.max[i])
            .fold(0.0, f64::max)
    }

    /// Largest contact load on raceway `ring` ("inner" or "outer") over
    /// the window \[N\]: of the loads at every accepted step
    /// (`peak_load_{ring}_n`) and the sampled ones, per ball.
    pub fn largest_load(&self, ring: &str) -> f64 {
        let stepped = match self.stats.index(&format!("peak_load_{ring}_n")) {
            Some(i) if self.merged.count > 0 => self.merged.max[i],
            _ => 0.0,
        };
        stepped.max(self.pooled_max(&format!("load_{ring}_n")))
    }

    /// Largest |`ball{j}_{suffix}`| over all balls and the window.
    pub fn pooled_max_abs(&self, suffix: &str) -> f64 {
        self.per_ball(suffix)
            .iter()
            .map(|&i| self.merged.max[i].abs().max(self.merged.min[i].abs()))
            .filter(|v| v.is_finite())
            .fold(0.0, f64::max)
    }

    /// Mean of `ball{j}_{suffix}` over the samples where the ball is loaded
    /// on the raceway the channel belongs to (0 when none is).
    pub fn loaded_mean(&self, suffix: &str) -> f64 {
        let channels = self.per_ball(suffix);
        let count: u64 = channels.iter().map(|&i| self.merged.loaded_count[i]).sum();
        if count == 0 {
            return 0.0;
        }
        channels
            .iter()
            .map(|&i| self.merged.loaded_sum[i])
            .sum::<f64>()
            / count as f64
    }

    /// The jitter of the balls' passages ending in the window (None
    /// without ball channels or with fewer than two intervals).
    pub fn passage_jitter(&self) -> Option<PassageJitter> {
        self.merged.passages.jitter()
    }

    /// The vibration and whirl channels the run has over the window (their
    /// last [`SIGNAL_SAMPLES`] samples).
    pub fn signal(&self) -> TimeSeries {
        let [from, to] = self.span();
        let mut series = TimeSeries::default();
        let mut kept = Vec::with_capacity(SIGNAL_CHANNELS.len());
        for (k, name) in SIGNAL_CHANNELS.iter().enumerate() {
            if let Some(i) = self.stats.index(name) {
                series.channel(*name, self.stats.units[i].as_str());
                kept.push(k);
            }
        }
        let mut row = Vec::with_capacity(kept.len());
        for signal in self
            .stats
            .signal
            .iter()
            .filter(|r| r[0] >= from && r[0] <= to)
        {
            row.clear();
            row.extend(kept.iter().map(|&k| signal[k]));
            series.push(&row);
        }
        series
    }
}

#[cfg(test)]
mod tests;
