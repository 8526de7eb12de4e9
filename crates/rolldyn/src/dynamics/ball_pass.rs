//! The pass over the balls: each ball's contacts evaluated, serially or
//! on all the threads of the current rayon pool, and their couplings to
//! the rings and cage summed **in ball order**.
//!
//! The balls are independent given the ring and cage states (the
//! bordered block structure of docs/model.md §8), so their contact evaluations can
//! run at the same time. Each ball's coupling lands in its own slot and
//! the slots are summed serially from ball 0, exactly as the serial pass
//! sums them: the right-hand side is bit-identical whatever the number of
//! threads, and whether the pass runs in parallel at all (tests below).
//!
//! The dissipated power by component, the contacts' output quantities
//! (once per output sample) and the end-point records (energy shares and
//! raceway records, `dynamics::end_point`) go the same way: each ball's
//! share in its slot, the power summed in ball order into the caller's
//! sink, which is what the serial pass accumulates, the contacts and
//! records copied to the caller's.
//!
//! Parallel only where it pays: a pass whose contacts integrate traction
//! over a grid (EHL, traction curve or stress law on the strip grid, or
//! FASTSIM) costs microseconds per ball, far above rayon's hand-over; a
//! pass with traction at the contact centre (Shan et al. 2023's 6304: ~1 µs per
//! ball) stays serial. The slots are allocated once, with the model.

use super::coupling::BallCoupling;
use super::end_point::EndRecord;
use super::race_contact::ContactSample;
use crate::power::Dissipation;
use rayon::prelude::*;
use std::sync::{Mutex, PoisonError};

/// What a ball's evaluation may also write besides its derivatives and
/// losses: its raceway contacts' outputs and its end-point record.
pub(super) type Extras<'a> = (Option<&'a mut ContactSample>, Option<&'a mut EndRecord>);

/// Fewest balls for which the pass runs in parallel.
const MIN_PARALLEL_BALLS: usize = 4;

/// One coupling slot per ball, reused by every right-hand side.
#[derive(Debug, Default)]
pub(super) struct BallPass {
    /// Whether the raceway contacts integrate traction over a grid.
    expensive: bool,
    /// Whether the balls are evaluated across threads.
    parallel: bool,
    slots: Mutex<Vec<Slot>>,
}

/// One ball's coupling, losses, contact outputs and end-point record.
#[derive(Debug, Clone, Default)]
struct Slot {
    coupling: BallCoupling,
    power: Dissipation,
    sample: ContactSample,
    end: EndRecord,
}

impl BallPass {
    /// Slots for `balls` balls; parallel when `expensive_contacts` (traction
    /// integrated over a grid) and there are enough balls to share.
    pub(super) fn new(balls: usize, expensive_contacts: bool) -> Self {
        Self {
            expensive: expensive_contacts,
            parallel: expensive_contacts && balls >= MIN_PARALLEL_BALLS,
            slots: Mutex::new(vec![Default::default(); balls]),
        }
    }

    /// Whether the raceway contacts integrate traction over a grid (they
    /// then cost far more than the rest of a ball's equations).
    pub(super) fn expensive_contacts(&self) -> bool {
        self.expensive
    }

    /// Whether the pass runs across threads: worth it, and the current
    /// rayon pool has more than one.
    pub(super) fn is_parallel(&self) -> bool {
        self.parallel && rayon::current_num_threads() > 1
    }

    /// Runs `ball(j, dy_j, sink, (sample, end))` for every ball (its
    /// derivatives go into `dy_balls`' j-th chunk of `ball_len`, its
    /// dissipation into `sink`, its contacts into `samples[j]` and its
    /// end-point record into `ends[j]` when given) and returns the sum of
    /// the couplings, added in ball order.
    pub(super) fn sum<F>(
        &self,
        dy_balls: &mut [f64],
        ball_len: usize,
        mut sink: Option<&mut Dissipation>,
        (mut samples, mut ends): (Option<&mut [ContactSample]>, Option<&mut [EndRecord]>),
        ball: F,
    ) -> BallCoupling
    where
        F: Fn(usize, &mut [f64], Option<&mut Dissipation>, Extras<'_>) -> BallCoupling + Sync,
    {
        let mut total = BallCoupling::default();
        if !self.is_parallel() {
            for (j, dy) in dy_balls.chunks_mut(ball_len).enumerate() {
                let sample = samples.as_deref_mut().map(|s| {
                    s[j] = ContactSample::default();
                    &mut s[j]
                });
                let end = ends.as_deref_mut().map(|e| &mut e[j]);
                total.add(&ball(j, dy, sink.as_deref_mut(), (sample, end)));
            }
            return total;
        }
        let (split, sampled, ended) = (sink.is_some(), samples.is_some(), ends.is_some());
        // A poisoned lock only means another pass panicked mid-way; every
        // slot is overwritten before it is read.
        let mut slots = self.slots.lock().unwrap_or_else(PoisonError::into_inner);
        // Each end-point slot starts as the caller's (which asks, or not,
        // for the ball's energy share).
        if let Some(ends) = ends.as_deref() {
            for (slot, end) in slots.iter_mut().zip(ends) {
                slot.end = *end;
            }
        }
        slots
            .par_iter_mut()
            .zip(dy_balls.par_chunks_mut(ball_len))
            .enumerate()
            .for_each(|(j, (slot, dy))| {
                slot.power = Dissipation::default();
                slot.sample = ContactSample::default();
                let extras = (
                    sampled.then_some(&mut slot.sample),
                    ended.then_some(&mut slot.end),
                );
                slot.coupling = ball(j, dy, split.then_some(&mut slot.power), extras);
            });
        for (j, slot) in slots.iter().enumerate() {
            total.add(&slot.coupling);
            if let Some(sink) = sink.as_deref_mut() {
                sink.add(&slot.power);
            }
            if let Some(samples) = samples.as_deref_mut() {
                samples[j] = slot.sample;
            }
            if let Some(ends) = ends.as_deref_mut() {
                ends[j] = slot.end;
            }
        }
        total
    }
}

impl Clone for BallPass {
    /// A clone gets its own slots (a model clone evaluates independently).
    fn clone(&self) -> Self {
        let balls = self
            .slots
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .len();
        Self {
            expensive: self.expensive,
            parallel: self.parallel,
            slots: Mutex::new(vec![Default::default(); balls]),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    /// Couplings whose sum depends on the order of addition in the last
    /// bits (magnitudes spread over 1e-8…1e8).
    fn ball(
        j: usize,
        dy: &mut [f64],
        sink: Option<&mut Dissipation>,
        (sample, end): Extras<'_>,
    ) -> BallCoupling {
        let x = (j as f64 * 0.7).sin() * 10f64.powi((j % 17) as i32 - 8);
        dy.fill(x);
        if let Some(s) = sample {
            s.inner.load = x;
            s.outer.angle = -x;
        }
        if let Some(energy) = end.and_then(|e| e.energy.as_mut()) {
            energy.kinetic = x;
            energy.elastic[2] = -x;
        }
        if let Some(d) = sink {
            d.inner.spin += x;
            d.outer.hysteresis += x / 3.0;
            d.pocket_friction += x * x;
            d.ball_drag -= x / 5.0;
        }
        BallCoupling {
            ring_force: Vector3::new(x, -x / 3.0, x * 1.1),
            ring_moment: Vector3::new(x / 7.0, x, -x),
            outer_force: Vector3::new(0.0, x / 9.0, x),
            cage_force: Vector3::new(x, x, x / 11.0),
            cage_torque: x / 13.0,
            dissipation: x * x,
            film_power: x / 17.0,
            ring_velocity_gradient: [x, 0.0, -x / 19.0, x / 23.0, 0.0],
            outer_velocity_gradient: [x / 29.0, x],
        }
    }

    /// Everything a pass writes: the couplings' sum, the derivatives, the
    /// losses, the samples and the end-point records.
    type Written = (
        BallCoupling,
        Vec<f64>,
        Dissipation,
        Vec<ContactSample>,
        Vec<EndRecord>,
    );

    fn run(pass: &BallPass, balls: usize) -> Written {
        let mut dy = vec![0.0; balls * 9];
        let mut power = Dissipation::default();
        let mut samples = vec![ContactSample::default(); balls];
        // The even balls' records ask for their energy shares.
        let mut ends: Vec<_> = (0..balls)
            .map(|j| EndRecord {
                energy: (j % 2 == 0).then(Default::default),
                ..EndRecord::default()
            })
            .collect();
        let extras = (Some(&mut samples[..]), Some(&mut ends[..]));
        let total = pass.sum(&mut dy, 9, Some(&mut power), extras, ball);
        (total, dy, power, samples, ends)
    }

    fn bits(c: &BallCoupling) -> Vec<u64> {
        let mut out = [0.0; BallCoupling::LEN];
        c.write(&mut out);
        out.iter().map(|v| v.to_bits()).collect()
    }

    #[test]
    fn parallel_pass_is_bit_identical_to_the_serial_one_on_any_pool() {
        let balls = 40;
        let (serial, dy_serial, power_serial, samples_serial, ends_serial) =
            run(&BallPass::new(balls, false), balls);
        assert!(
            samples_serial
                .iter()
                .all(|s| s.inner.load == -s.outer.angle)
        );
        assert!(ends_serial.iter().enumerate().all(|(j, e)| match e.energy {
            Some(energy) => j % 2 == 0 && energy.kinetic == -energy.elastic[2],
            None => j % 2 == 1,
        }));
        let parallel = BallPass::new(balls, true);
        for threads in [1, 2, 3, 8] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let (total, dy, power, samples, ends) = pool.install(|| run(&parallel, balls));
            assert_eq!(bits(&total), bits(&serial), "{threads} threads");
            assert_eq!(dy, dy_serial, "{threads} threads");
            assert_eq!(samples, samples_serial, "{threads} threads");
            assert_eq!(ends, ends_serial, "{threads} threads");
            assert_eq!(
                format!("{power:?}"),
                format!("{power_serial:?}"),
                "{threads} threads"
            );
        }
    }

    #[test]
    fn few_balls_cheap_contacts_or_one_thread_stay_serial() {
        let pool = |threads| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
        };
        pool(2).install(|| {
            assert!(!BallPass::new(3, true).is_parallel());
            assert!(!BallPass::new(22, false).is_parallel());
            assert!(BallPass::new(4, true).clone().is_parallel());
        });
        pool(1).install(|| assert!(!BallPass::new(22, true).is_parallel()));
    }
}
