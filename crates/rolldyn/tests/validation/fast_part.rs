//! The Jacobian's fast part (`integrate::rosenbrock::fast_part`): the
//! bearing without its ball–raceway contacts, refreshed at every step
//! while the cage limits the steps.
//!
//! * Its balls' blocks are the pockets' terms alone: zero for an open
//!   pocket, and for a closed one the full Jacobian less the same
//!   model's with pockets too wide to close.
//! * Its Jacobian is the model's where the raceway contacts do not reach:
//!   the cage's columns agree with the full Jacobian's to the round-off of
//!   its differences (the raceway contacts do not read the cage), and the balls' rows of the rings'
//!   columns are zero (without raceway contacts the balls do not read the
//!   rings).
//! * A run with the refresh active, checkpointed and continued from the
//!   bytes, gives the uninterrupted run's states bit for bit (the slow
//!   rest and the refresh's window are part of the checkpoint).
//!
//! Configuration: the 7008C default (EHL traction on the 12 × 6 grid,
//! whirling outer-guided cage), the cage turned against the balls so that
//! every pocket is closed.

use super::common::{bearing_7008c, dynamics_7008c};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::{BearingModel, DragParameters};
use rolldyn::integrate::jacobian::{JacobianWork, fast_part_difference, finite_difference};
use rolldyn::integrate::linear::BlockJacobian;
use rolldyn::integrate::{
    BlockSplit, Checkpoint, Integrator, OdeSystem, ROS34PW2, Rosenbrock, StateReader, StateWriter,
};
use rolldyn::material::Material;

fn model() -> (BearingModel, Vec<f64>) {
    let steel = Material::STEEL_52100;
    let (params, eq) = dynamics_7008c(DragParameters::default());
    let model =
        BearingModel::new(&bearing_7008c(), &steel, &steel, HertzModel::Exact, params).unwrap();
    let y0 = model.state_from_equilibrium(&eq);
    (model, y0)
}

#[test]
fn the_fast_part_is_the_model_where_the_raceway_contacts_do_not_reach() {
    let (model, mut y) = model();
    let layout = model.layout();
    // Cage turned by 0.1 mm at its pitch radius and moved off centre:
    // every pocket pushes its ball.
    y[layout.cage() + 2] += 0.1e-3 / 27e-3;
    y[layout.cage()] += 5e-6;
    let t = 1e-3;
    let mut f = vec![0.0; y.len()];
    model.rhs(t, &y, &mut f);
    let shape = model.block_layout();
    let mut work = JacobianWork::new(&model);
    let (mut full, mut fast) = (BlockJacobian::zeros(shape), BlockJacobian::zeros(shape));
    finite_difference(&model, t, &y, &f, &mut full, &mut work);
    let cost = fast_part_difference(&model, t, &y, &mut fast, &mut work);
    assert!(cost.is_some(), "grid traction: the model has a fast part");
    let start = shape.border_start();
    let (mut cage_entries, mut worst) = (0, 0.0f64);
    for col in start..shape.dimension() {
        let cage = (layout.cage()..layout.work()).contains(&col);
        let ring = col < layout.cage();
        for row in 0..shape.dimension() {
            let (a, b) = (full.get(row, col), fast.get(row, col));
            if cage {
                // The full Jacobian differences the pocket's change against
                // the raceway contacts' forces as well: equal to the
                // round-off that leaves, ε |f| / δ (up to 3e-4 of the
                // column in the cage's velocity columns, whose increments
                // are 1.5e-11 m/s against ball accelerations of 1e7 rad/s²).
                worst = worst.max((a - b).abs() / column_norm(&full, col));
                cage_entries += usize::from(a != 0.0);
            }
            if ring && row < start {
                assert_eq!(b, 0.0, "ball row {row} of ring column {col}");
            }
        }
    }
    assert!(cage_entries > 100, "{cage_entries} cage entries");
    assert!(
        worst < 1e-3,
        "cage columns differ by {worst:e} of their largest entry"
    );
}

/// The fast part is the pockets' terms alone: at the equilibrium start
/// (every ball in the middle of its pocket) the balls have no rows or
/// columns in it, and with every pocket pushing its ball each ball's
/// block is what the pocket adds to the full Jacobian: the full Jacobian
/// less that of the same model and point with pockets too wide to close.
#[test]
fn the_fast_part_is_the_pockets_terms() {
    let (model, mut y) = model();
    let shape = model.block_layout();
    let balls_len = shape.border_start();
    let mut work = JacobianWork::new(&model);
    let mut fast = BlockJacobian::zeros(shape);
    let t = 1e-3;
    fast_part_difference(&model, t, &y, &mut fast, &mut work).unwrap();
    for row in 0..shape.dimension() {
        for col in 0..shape.dimension() {
            if row < balls_len || col < balls_len {
                assert_eq!(fast.get(row, col), 0.0, "open pockets: ({row}, {col})");
            }
        }
    }
    let layout = model.layout();
    y[layout.cage() + 2] += 0.1e-3 / 27e-3;
    y[layout.cage()] += 5e-6;
    let steel = Material::STEEL_52100;
    let (mut params, _) = dynamics_7008c(DragParameters::default());
    params.cage.pocket_clearance *= 100.0;
    let wide =
        BearingModel::new(&bearing_7008c(), &steel, &steel, HertzModel::Exact, params).unwrap();
    let jacobian = |m: &BearingModel| {
        let mut f = vec![0.0; y.len()];
        m.rhs(t, &y, &mut f);
        let mut j = BlockJacobian::zeros(shape);
        finite_difference(m, t, &y, &f, &mut j, &mut JacobianWork::new(m));
        j
    };
    let (full, without) = (jacobian(&model), jacobian(&wide));
    fast_part_difference(&model, t, &y, &mut fast, &mut work).unwrap();
    let (b, mut worst, mut entries) = (shape.block_size, 0.0f64, 0);
    for col in 0..balls_len {
        let norm = column_norm(&full, col);
        for row in (col / b) * b..(col / b + 1) * b {
            let pocket = full.get(row, col) - without.get(row, col);
            worst = worst.max((fast.get(row, col) - pocket).abs() / norm);
            entries += usize::from(fast.get(row, col) != 0.0);
        }
    }
    assert!(entries > 200, "{entries} entries in the balls' blocks");
    // To the round-off of the differences, as the cage's columns above.
    assert!(
        worst < 1e-3,
        "balls' blocks differ by {worst:e} of their columns"
    );
}

fn column_norm(j: &BlockJacobian, col: usize) -> f64 {
    let n = j.layout().dimension();
    (0..n).map(|r| j.get(r, col).abs()).fold(0.0, f64::max)
}

#[test]
fn a_run_with_the_refresh_resumes_bit_identically() {
    let (t_end, t_check) = (20e-3, 12e-3);
    let (mut m, mut y0) = model();
    // The cage started off centre and against its balls: it rattles in its
    // pockets and on its land from the first steps.
    let layout = m.layout();
    y0[layout.cage() + 2] += 0.1e-3 / 27e-3;
    y0[layout.cage()] += 20e-6;
    let mut s = Rosenbrock::builder(&ROS34PW2)
        .relative_tolerance(1e-2)
        .max_step(1e-4)
        .energy_tolerance(Some(1e-4))
        .build(&m, &y0)
        .unwrap();
    let mut bytes = None;
    while s.t() < t_end {
        s.step(&mut m, t_end).unwrap();
        if bytes.is_none() && s.t() >= t_check {
            let mut w = StateWriter::new();
            s.save(&mut w);
            m.save(&mut w);
            bytes = Some((w.into_bytes(), s.stats()));
        }
    }
    let (bytes, at_checkpoint) = bytes.unwrap();
    assert!(
        at_checkpoint.fast_part_jacobians > 0,
        "the refresh ran before the checkpoint: {at_checkpoint:?}"
    );
    let (mut m2, _) = model();
    let mut s2 = Rosenbrock::builder(&ROS34PW2)
        .relative_tolerance(1e-2)
        .max_step(1e-4)
        .energy_tolerance(Some(1e-4))
        .build(&m2, &y0)
        .unwrap();
    let mut r = StateReader::new(&bytes);
    s2.restore(&mut r).unwrap();
    m2.restore(&mut r).unwrap();
    assert!(r.is_done());
    while s2.t() < t_end {
        s2.step(&mut m2, t_end).unwrap();
    }
    assert_eq!(s2.t().to_bits(), s.t().to_bits());
    assert!(
        s2.y()
            .iter()
            .zip(s.y())
            .all(|(a, b)| a.to_bits() == b.to_bits()),
        "states differ at the end"
    );
    assert_eq!(s2.stats(), s.stats());
    assert!(s.stats().fast_part_jacobians > at_checkpoint.fast_part_jacobians);
}
