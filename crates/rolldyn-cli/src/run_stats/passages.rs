//! The balls' passages through the load zone's centre, watched sample by
//! sample for the summary's `ball_pass_jitter` ([`rolldyn::signal::passage`]).

use rolldyn::integrate::{CheckpointError, StateReader, StateWriter};
use rolldyn::signal::passage::PassageDetector;

/// The watch over the balls' azimuth channels.
#[derive(Debug, Clone)]
pub(super) struct PassageWatch {
    detector: PassageDetector,
    /// Columns of `ball{j}_azimuth_rad`, j = 0, 1, ….
    azimuths: Vec<usize>,
    /// Time of the last passage (any ball) \[s\].
    last: Option<f64>,
    /// The passages found in one sample (reused).
    found: Vec<f64>,
}

impl PassageWatch {
    /// Watches azimuth `at` \[rad\] over the ball azimuths among `names`;
    /// None without any.
    pub(super) fn new(names: &[String], at: f64) -> Option<Self> {
        let azimuths: Vec<usize> = (0..)
            .map_while(|j| {
                let name = format!("ball{j}_azimuth_rad");
                names.iter().position(|n| *n == name)
            })
            .collect();
        (!azimuths.is_empty()).then(|| Self {
            detector: PassageDetector::new(at),
            found: Vec::with_capacity(azimuths.len()),
            azimuths,
            last: None,
        })
    }

    /// Adds the sample `row` (time first); calls `interval(end, length)`
    /// for each interval between successive passages that ends in it.
    pub(super) fn push(&mut self, row: &[f64], interval: &mut impl FnMut(f64, f64)) {
        let t = row.first().copied().unwrap_or(0.0);
        self.found.clear();
        let found = &mut self.found;
        let azimuths = self.azimuths.iter().map(|&i| row[i]);
        self.detector.push(t, azimuths, &mut |p| found.push(p));
        self.found.sort_by(f64::total_cmp);
        for &p in &self.found {
            if let Some(previous) = self.last {
                interval(p, p - previous);
            }
            self.last = Some(p);
        }
    }

    /// Writes the watch into a checkpoint.
    pub(super) fn save(&self, w: &mut StateWriter) {
        let (time, values) = self.detector.state();
        w.f64(time);
        w.u64(u64::from(!values.is_empty()));
        if !values.is_empty() {
            w.f64s(&values);
        }
        w.opt_f64(self.last);
    }

    /// Restores [`Self::save`].
    pub(super) fn restore(&mut self, r: &mut StateReader) -> Result<(), CheckpointError> {
        let time = r.f64()?;
        let mut values = Vec::new();
        if r.u64()? != 0 {
            values.resize(2 * self.azimuths.len(), 0.0);
            r.f64s_into("ball passages", &mut values)?;
        }
        if !self.detector.restore(time, &values) {
            return Err(CheckpointError::Mismatch("ball passages".into()));
        }
        self.last = r.opt_f64()?;
        Ok(())
    }
}
