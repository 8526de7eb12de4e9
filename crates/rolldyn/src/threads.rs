//! The pool's other threads waiting actively while a run integrates.
//!
//! The engine's parallel passes (the balls of a right-hand side, the
//! blocks of a Jacobian) are short: 25–50 µs on the default case, with a
//! few µs of serial work (the linear algebra, the step's bookkeeping)
//! between them, tens of thousands of times per simulated second. A rayon
//! worker that finds no work goes to sleep after a few dozen rounds, and
//! waking it again takes the operating system microseconds to tens of
//! microseconds on a virtual machine; the passes then often run on one
//! thread while the other is still waking. [`ActiveHelpers`] keeps the
//! pool's other threads busy-waiting for work (rayon's `yield_now`, which
//! steals and runs pending jobs) from when it starts until it is dropped,
//! as OpenMP's active wait policy does: measured on the default case, 1 s
//! on two threads, about 10 % less wall time (docs/performance.md). The
//! cost is the other cores at full load while the run lasts, serial
//! stretches included.
//!
//! Meant for a run that has the pool to itself. A thread of another run
//! that waits inside its own pass may steal a helper and spin in it until
//! the run that started it ends; with two sets of helpers two runs could
//! so wait for each other for ever. So one set at a time runs in a
//! process ([`ActiveHelpers::start`] gives None while another is held),
//! and the sweeps, whose points share the pool, run without. Numbers do
//! not change: which thread executes which part of a pass never changes
//! the result (the passes add in a fixed order).

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// Whether a set of helpers runs in this process.
static HELD: AtomicBool = AtomicBool::new(false);

/// Idle rounds of a helper between yields to the operating system.
const IDLE_ROUNDS_PER_YIELD: u32 = 64;

/// Longest wait for the helpers to start before the run goes on without
/// those that have not.
const START_WAIT: Duration = Duration::from_millis(100);

/// The pool's other threads waiting actively until this is dropped.
#[derive(Debug)]
pub struct ActiveHelpers {
    done: Arc<AtomicBool>,
}

impl ActiveHelpers {
    /// Starts the helpers from a thread of a rayon pool with more than one
    /// thread; None elsewhere (outside a pool, or a pool of one) and while
    /// another set is held.
    pub fn start() -> Option<Self> {
        let caller = rayon::current_thread_index()?;
        let helpers = rayon::current_num_threads().checked_sub(1)?;
        if helpers == 0
            || HELD
                .compare_exchange(false, true, Ordering::AcqRel, Ordering::Acquire)
                .is_err()
        {
            return None;
        }
        let done = Arc::new(AtomicBool::new(false));
        let started = Arc::new(AtomicUsize::new(0));
        for _ in 0..helpers {
            let (done, started) = (done.clone(), started.clone());
            rayon::spawn(move || {
                // The caller may run a helper itself while it waits in a
                // pass: it returns at once.
                if rayon::current_thread_index() == Some(caller) {
                    return;
                }
                started.fetch_add(1, Ordering::AcqRel);
                let mut idle = 0u32;
                while !done.load(Ordering::Acquire) {
                    if matches!(rayon::yield_now(), Some(rayon::Yield::Executed)) {
                        idle = 0;
                    } else {
                        idle = idle.wrapping_add(1);
                        // Now and then the operating system may run
                        // something else here (more threads than cores).
                        if idle % IDLE_ROUNDS_PER_YIELD == 0 {
                            std::thread::yield_now();
                        } else {
                            std::hint::spin_loop();
                        }
                    }
                }
            });
        }
        // Let the other threads pick them up (the caller does not run its
        // own jobs while it yields to the operating system).
        let begun = Instant::now();
        while started.load(Ordering::Acquire) < helpers && begun.elapsed() < START_WAIT {
            std::thread::yield_now();
        }
        Some(Self { done })
    }
}

impl Drop for ActiveHelpers {
    /// The helpers return (also when the run unwinds).
    fn drop(&mut self) {
        self.done.store(true, Ordering::Release);
        HELD.store(false, Ordering::Release);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rayon::prelude::*;

    fn pool(threads: usize) -> rayon::ThreadPool {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("pool")
    }

    #[test]
    fn helpers_start_only_on_a_pool_thread_with_company() {
        assert!(ActiveHelpers::start().is_none(), "outside a pool");
        assert!(pool(1).install(ActiveHelpers::start).is_none());
        let pool = pool(3);
        pool.install(|| {
            let helpers = ActiveHelpers::start().expect("helpers");
            assert!(ActiveHelpers::start().is_none(), "one set at a time");
            // Passes run while they wait, with the same sums as serially.
            for _ in 0..100 {
                let parallel: Vec<f64> =
                    (0..64).into_par_iter().map(|k| (k as f64).sqrt()).collect();
                let serial: Vec<f64> = (0..64).map(|k| (k as f64).sqrt()).collect();
                assert_eq!(parallel, serial);
            }
            drop(helpers);
        });
        // Dropped: the helpers returned, so the pool takes other work.
        let sum: u64 = pool.install(|| (0..1000u64).into_par_iter().sum());
        assert_eq!(sum, 499_500);
    }
}
