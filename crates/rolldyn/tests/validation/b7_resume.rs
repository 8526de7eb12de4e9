//! B7 (determinism), resumed runs: a run checkpointed part-way
//! ([`rolldyn::integrate::Checkpoint`]) and continued from the bytes in a
//! freshly built model and integrator gives the same samples, bit for
//! bit, as the uninterrupted run, with both adaptive integrators.
//!
//! Configuration: Shan et al. 2023's 6304 (Lankarani–Nikravesh law, so the
//! contact-episode memory is part of the state; modified Coulomb traction;
//! cage with whirl and damped pockets), 100 N radial load, 8000 rpm,
//! from pure rolling.

use crate::common::{METHODS, bearing_6304, dynamics_6304, integrator, steel_shan_2023};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::BearingModel;
use rolldyn::integrate::{
    Checkpoint, Integrator, RunEnd, Sampling, StateReader, StateWriter, run_from,
};
use std::sync::atomic::AtomicBool;

const RATE: f64 = 20_000.0;

/// Samples (t, y).
type Samples = Vec<(f64, Vec<f64>)>;
/// Checkpoint bytes and the index of the next sample.
type Saved = Option<(Vec<u8>, u64)>;

fn model() -> BearingModel {
    let steel = steel_shan_2023();
    BearingModel::new(
        &bearing_6304(),
        &steel,
        &steel,
        HertzModel::HertzCircular,
        dynamics_6304(100.0),
    )
    .unwrap()
}

/// Samples (t, y) from `sampling` to `t_end`; the checkpoint taken after
/// the first accepted step past `checkpoint_at`, with its sample index.
fn advance(
    model: &mut BearingModel,
    solver: &mut rolldyn::integrate::Solver,
    t_end: f64,
    sampling: Sampling,
    checkpoint_at: f64,
) -> (Samples, Saved) {
    let stop = AtomicBool::new(false);
    let mut samples = Vec::new();
    let mut checkpoint = None;
    let report = run_from(
        model,
        solver,
        t_end,
        sampling,
        &stop,
        |_, t, y| samples.push((t, y.to_vec())),
        |m, i, next| {
            if checkpoint.is_none() && i.t() >= checkpoint_at {
                let mut w = StateWriter::new();
                i.save(&mut w);
                m.save(&mut w);
                checkpoint = Some((w.into_bytes(), next));
            }
        },
    );
    assert_eq!(report.end, RunEnd::Completed);
    (samples, checkpoint)
}

#[test]
fn b7_resumed_run_is_bit_identical() {
    let (t_end, t_check) = (4e-3, 1.5e-3);
    for method in METHODS {
        let mut m = model();
        let y0 = m.pure_rolling_state([0.0; 5]);
        let mut s = integrator(method, &m, &y0, 1e-4, 2e-5);
        let fresh = Sampling {
            t0: 0.0,
            rate: RATE,
            next: 0,
        };
        let (whole, checkpoint) = advance(&mut m, &mut s, t_end, fresh, t_check);
        let (bytes, next) = checkpoint.unwrap();

        // A new model and integrator, built as the first ones were.
        let mut m2 = model();
        let mut s2 = integrator(method, &m2, &y0, 1e-4, 2e-5);
        let mut r = StateReader::new(&bytes);
        s2.restore(&mut r).unwrap();
        m2.restore(&mut r).unwrap();
        assert!(r.is_done());
        let stats_at_checkpoint = s2.stats();
        let (rest, _) = advance(
            &mut m2,
            &mut s2,
            t_end,
            Sampling { next, ..fresh },
            f64::INFINITY,
        );

        let tail = &whole[next as usize..];
        assert_eq!(rest.len(), tail.len(), "{method:?}");
        assert!(!rest.is_empty());
        for ((ta, ya), (tb, yb)) in rest.iter().zip(tail) {
            assert_eq!(ta.to_bits(), tb.to_bits());
            assert!(
                ya.iter().zip(yb).all(|(a, b)| a.to_bits() == b.to_bits()),
                "{method:?}: samples differ at t = {ta}"
            );
        }
        assert_eq!(s2.stats(), s.stats(), "{method:?}: counters continue");
        assert!(stats_at_checkpoint.steps > 0 && stats_at_checkpoint.steps < s.stats().steps);
        eprintln!(
            "{method:?}: resumed at sample {next} of {}, {} steps before, {} after",
            whole.len(),
            stats_at_checkpoint.steps,
            s.stats().steps - stats_at_checkpoint.steps
        );
    }
}

#[test]
fn b7_checkpoint_of_another_model_is_refused() {
    let mut m = model();
    let y0 = m.pure_rolling_state([0.0; 5]);
    let s = integrator(METHODS[0], &m, &y0, 1e-4, 2e-5);
    let mut w = StateWriter::new();
    s.save(&mut w);
    m.save(&mut w);
    let bytes = w.into_bytes();
    // Restored into the other integrator: its tag differs.
    let mut other = integrator(METHODS[1], &m, &y0, 1e-4, 2e-5);
    assert!(other.restore(&mut StateReader::new(&bytes)).is_err());
    // Truncated bytes.
    let mut same = integrator(METHODS[0], &m, &y0, 1e-4, 2e-5);
    let mut r = StateReader::new(&bytes[..bytes.len() / 2]);
    assert!(same.restore(&mut r).is_err() || m.restore(&mut r).is_err());
}
