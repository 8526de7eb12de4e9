//! Jitter of the ball passage: how far the balls' arrivals at a fixed
//! place depart from a periodic train.
//!
//! A defect on the outer raceway is struck once per ball passage; were the
//! balls equally spaced and the cage turning steadily, the impacts would
//! be exactly periodic at BPFO and the envelope spectrum's lines sharp at
//! every harmonic. Measured signals are not: the balls slip randomly by
//! 1–2 % (Randall & Antoni 2011), which smears the higher harmonics and
//! makes a bearing's signal cyclostationary rather than periodic; their
//! simulations prescribe it as a random jitter of the impact spacing. The
//! statistic here is that jitter, from the balls' own motion: the
//! intervals Δtₖ between successive balls (any ball) crossing one azimuth,
//! and their standard deviation over their mean,
//!
//! jitter = √(Σ(Δtₖ − Δt̄)²/N) / Δt̄.
//!
//! A perfectly periodic train gives 0; N balls each displaced by an
//! independent uniform error within ±c/2 of a pitch p give √(2/12) c/p.

use crate::surface::spall::wrap;
use std::f64::consts::TAU;

/// The balls' passage of one azimuth over a record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PassageJitter {
    /// Intervals between successive passages counted \[-\].
    pub intervals: usize,
    /// Their mean \[s\] (1/BPFO for the outer ring's azimuth).
    pub mean_interval: f64,
    /// Their standard deviation over their mean \[-\].
    pub jitter: f64,
}

/// The balls' passages through one azimuth, sample by sample (for a run's
/// statistics, which see its samples one at a time).
#[derive(Debug, Clone, PartialEq)]
pub struct PassageDetector {
    /// The azimuth watched \[rad\].
    at: f64,
    /// Per ball, the angle travelled past `at`, unwrapped \[rad\]: a
    /// passage whenever it crosses a multiple of 2π. Empty before the
    /// first sample.
    past: Vec<f64>,
    /// Per ball, its last azimuth \[rad\].
    azimuth: Vec<f64>,
    /// Time of the last sample \[s\].
    time: f64,
}

impl PassageDetector {
    /// Watches the azimuth `at` \[rad\].
    pub fn new(at: f64) -> Self {
        Self {
            at,
            past: Vec::new(),
            azimuth: Vec::new(),
            time: 0.0,
        }
    }

    /// Adds the sample at time `t` of the balls' azimuths \[rad\] (wrapped
    /// or not; the same balls every time), calling `passed` with the time
    /// of each passage since the previous sample, in either direction,
    /// timed by linear interpolation.
    pub fn push(
        &mut self,
        t: f64,
        azimuths: impl Iterator<Item = f64>,
        passed: &mut impl FnMut(f64),
    ) {
        if self.past.is_empty() {
            for a in azimuths {
                self.past.push(wrap(a - self.at).rem_euclid(TAU));
                self.azimuth.push(a);
            }
        } else {
            for ((past, last), a) in self.past.iter_mut().zip(&mut self.azimuth).zip(azimuths) {
                let next = *past + wrap(a - *last);
                let (from, to) = ((*past / TAU).floor(), (next / TAU).floor());
                if from != to {
                    let share = (TAU * from.max(to) - *past) / (next - *past);
                    passed(self.time + share * (t - self.time));
                }
                (*past, *last) = (next, a);
            }
        }
        self.time = t;
    }

    /// The state for a checkpoint: the time, then per ball its angle past
    /// the azimuth and its azimuth (empty before the first sample).
    pub fn state(&self) -> (f64, Vec<f64>) {
        let mut values = self.past.clone();
        values.extend_from_slice(&self.azimuth);
        (self.time, values)
    }

    /// Restores [`Self::state`]; false when `values` is not of that form.
    pub fn restore(&mut self, time: f64, values: &[f64]) -> bool {
        if values.len() % 2 != 0 {
            return false;
        }
        let (past, azimuth) = values.split_at(values.len() / 2);
        (self.time, self.past, self.azimuth) = (time, past.to_vec(), azimuth.to_vec());
        true
    }
}

/// Running statistics of the intervals between successive passages, by
/// Welford's update and Chan et al.'s merge (no cancellation where the
/// jitter is small).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct IntervalSums {
    /// Intervals counted.
    pub count: u64,
    /// Their mean \[s\].
    pub mean: f64,
    /// The sum of their squared deviations from the mean \[s²\].
    pub squared_deviations: f64,
}

impl IntervalSums {
    /// Adds one interval \[s\].
    pub fn add(&mut self, interval: f64) {
        self.count += 1;
        let d = interval - self.mean;
        self.mean += d / self.count as f64;
        self.squared_deviations += d * (interval - self.mean);
    }

    /// Adds the intervals of `other`.
    pub fn merge(&mut self, other: &IntervalSums) {
        let count = self.count + other.count;
        if other.count == 0 || count == 0 {
            return;
        }
        let (n1, n2) = (self.count as f64, other.count as f64);
        let d = other.mean - self.mean;
        self.mean += d * n2 / (n1 + n2);
        self.squared_deviations += other.squared_deviations + d * d * n1 * n2 / (n1 + n2);
        self.count = count;
    }

    /// Their mean and jitter; None with fewer than two intervals.
    pub fn jitter(&self) -> Option<PassageJitter> {
        if self.count < 2 {
            return None;
        }
        let deviation = (self.squared_deviations / self.count as f64).sqrt();
        Some(PassageJitter {
            intervals: self.count as usize,
            mean_interval: self.mean,
            jitter: if self.mean > 0.0 {
                deviation / self.mean
            } else {
                0.0
            },
        })
    }
}

/// The passages of the balls whose azimuths \[rad\] (wrapped or not) are
/// sampled at times `time` through the azimuth `at` \[rad\], in either
/// direction, each timed by linear interpolation between samples. None with
/// fewer than three passages (two intervals).
pub fn passage_jitter(time: &[f64], azimuths: &[&[f64]], at: f64) -> Option<PassageJitter> {
    let mut detector = PassageDetector::new(at);
    let mut passages = Vec::new();
    for (k, &t) in time.iter().enumerate() {
        let row = azimuths
            .iter()
            .map(|a| a.get(k).copied().unwrap_or(f64::NAN));
        detector.push(t, row, &mut |p| passages.push(p));
    }
    passages.sort_by(f64::total_cmp);
    let mut sums = IntervalSums::default();
    for w in passages.windows(2) {
        sums.add(w[1] - w[0]);
    }
    sums.jitter()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Z balls on an orbit at `speed` rad/s, ball j displaced by
    /// `offset(j)` rad, sampled at 10 kHz for `duration` s; wrapped to
    /// [0, 2π) when `wrapped`.
    fn orbit(
        balls: usize,
        speed: f64,
        offset: impl Fn(usize) -> f64,
        wrapped: bool,
    ) -> (Vec<f64>, Vec<Vec<f64>>) {
        let time: Vec<f64> = (0..3000).map(|k| k as f64 * 1e-4).collect();
        let azimuths = (0..balls)
            .map(|j| {
                time.iter()
                    .map(|t| {
                        let a = TAU * j as f64 / balls as f64 + offset(j) + speed * t;
                        if wrapped { a.rem_euclid(TAU) } else { a }
                    })
                    .collect()
            })
            .collect();
        (time, azimuths)
    }

    fn jitter_of(time: &[f64], azimuths: &[Vec<f64>], at: f64) -> PassageJitter {
        let views: Vec<&[f64]> = azimuths.iter().map(Vec::as_slice).collect();
        passage_jitter(time, &views, at).unwrap()
    }

    #[test]
    fn equally_spaced_balls_pass_periodically() {
        // 9 balls at 75 rad/s: a passage every 2π/(9 × 75) s = 9.31 ms.
        for (wrapped, at, speed) in [(false, 0.3, 75.0), (true, -1.5, 75.0), (true, 2.0, -75.0)] {
            let (time, azimuths) = orbit(9, speed, |_| 0.0, wrapped);
            let j = jitter_of(&time, &azimuths, at);
            assert!((j.mean_interval - TAU / (9.0 * 75.0)).abs() < 1e-9);
            assert!(j.jitter < 1e-9, "{j:?}");
            assert!(j.intervals >= 30, "{j:?}");
        }
    }

    #[test]
    fn displaced_balls_give_the_spacings_deviation() {
        // Alternate balls ahead and behind by e of the pitch p: intervals
        // p(1 ± 2e), a deviation of 2e over the mean.
        let (balls, e) = (10, 0.01);
        let pitch = TAU / balls as f64;
        let offset = |j: usize| if j % 2 == 0 { e * pitch } else { -e * pitch };
        let (time, azimuths) = orbit(balls, 60.0, offset, true);
        let j = jitter_of(&time, &azimuths, 1.0);
        assert!((j.jitter - 2.0 * e).abs() < 1e-6, "{j:?}");
    }

    #[test]
    fn merged_sums_are_the_sums_of_the_whole() {
        let intervals = [9.1e-3, 9.4e-3, 9.25e-3, 9.3e-3, 9.2e-3, 9.5e-3, 9.0e-3];
        let mut whole = IntervalSums::default();
        intervals.iter().for_each(|&d| whole.add(d));
        let (mut first, mut second) = (IntervalSums::default(), IntervalSums::default());
        intervals[..3].iter().for_each(|&d| first.add(d));
        intervals[3..].iter().for_each(|&d| second.add(d));
        first.merge(&second);
        first.merge(&IntervalSums::default());
        let (a, b) = (first.jitter().unwrap(), whole.jitter().unwrap());
        assert_eq!(a.intervals, 7);
        assert!((a.mean_interval - b.mean_interval).abs() < 1e-15);
        assert!((a.jitter - b.jitter).abs() < 1e-12);
        // Against the two-pass formula.
        let mean = intervals.iter().sum::<f64>() / 7.0;
        let sd = (intervals.iter().map(|d| (d - mean).powi(2)).sum::<f64>() / 7.0).sqrt();
        assert!((b.jitter - sd / mean).abs() < 1e-12);
    }

    #[test]
    fn too_few_passages_give_none() {
        let (time, azimuths) = orbit(1, 1.0, |_| 0.0, false);
        let views: Vec<&[f64]> = azimuths.iter().map(Vec::as_slice).collect();
        assert_eq!(passage_jitter(&time, &views, 0.5), None);
        assert_eq!(passage_jitter(&[], &[], 0.0), None);
    }
}
