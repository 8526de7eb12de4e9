//! The largest contact loads between output samples.
//!
//! An impact (a ball striking a spall edge, a pocket, a ball re-entering
//! the load zone) lasts tens of microseconds; samples at a few kHz miss its
//! peak, and the largest *sampled* load then depends on where the samples
//! fall (the CWRU example's largest load was 25 % low at 12 kHz). The model
//! records every contact's normal load at every accepted step (where it
//! already evaluates the contacts for their episodes, so at no extra
//! cost) and keeps the largest per raceway until the sampler takes it.

use std::sync::atomic::{AtomicU64, Ordering};

/// Largest inner and outer normal loads \[N\] at the accepted steps since
/// they were last taken. Taking them needs only `&self` (the sampler
/// holds the model shared), hence the atomics; one thread raises and takes
/// them, so the values are deterministic.
#[derive(Debug, Default)]
pub struct PeakLoads {
    bits: [AtomicU64; 2],
}

impl Clone for PeakLoads {
    fn clone(&self) -> Self {
        let loads = self.peek();
        let mut me = Self::default();
        for (k, load) in loads.into_iter().enumerate() {
            *me.bits[k].get_mut() = load.to_bits();
        }
        me
    }
}

impl PeakLoads {
    /// Raises raceway `k`'s (0 inner, 1 outer) peak to `load` if larger.
    pub fn raise(&mut self, k: usize, load: f64) {
        let bits = self.bits[k].get_mut();
        if load > f64::from_bits(*bits) {
            *bits = load.to_bits();
        }
    }

    /// The peaks \[N\] (inner, outer), left in place.
    pub fn peek(&self) -> [f64; 2] {
        [0, 1].map(|k| f64::from_bits(self.bits[k].load(Ordering::Relaxed)))
    }

    /// The peaks \[N\] (inner, outer) since the last take; zero afterwards.
    pub fn take(&self) -> [f64; 2] {
        [0, 1].map(|k| f64::from_bits(self.bits[k].swap(0.0f64.to_bits(), Ordering::Relaxed)))
    }

    /// Sets the peaks (a checkpoint restored).
    pub fn set(&mut self, loads: [f64; 2]) {
        for (k, load) in loads.into_iter().enumerate() {
            *self.bits[k].get_mut() = load.to_bits();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn peaks_rise_and_are_taken_once() {
        let mut peaks = PeakLoads::default();
        for (k, load) in [(0, 10.0), (1, 5.0), (0, 30.0), (0, 20.0), (1, 2.0)] {
            peaks.raise(k, load);
        }
        assert_eq!(peaks.clone().peek(), [30.0, 5.0]);
        assert_eq!(peaks.take(), [30.0, 5.0]);
        assert_eq!(peaks.take(), [0.0, 0.0]);
        peaks.raise(1, 7.0);
        assert_eq!(peaks.peek(), [0.0, 7.0]);
    }
}
