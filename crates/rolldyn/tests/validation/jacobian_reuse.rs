//! The Jacobian's border columns reuse what a perturbed border state does
//! not reach (`dynamics::ball_equations`): a ball's contacts other than
//! the one the state touches keep their shares of the unperturbed point.
//! That must change nothing: for every ball and every border state, the
//! evaluation with the memo gives the bits of the full evaluation.
//!
//! The 7008C default (EHL traction, cage whirl) with the outer ring on a
//! housing support, so that inner-ring, outer-ring and cage states are all
//! active, and the cage turned against the balls so that pockets are
//! closed.

use super::common::{bearing_7008c, dynamics_7008c};
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::{BearingModel, DragParameters, OuterRing, Support};
use rolldyn::integrate::BlockSplit;
use rolldyn::material::Material;

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

#[test]
fn border_columns_with_the_contacts_memo_are_bit_identical() {
    let g = bearing_7008c();
    let steel = Material::STEEL_52100;
    let (mut params, eq) = dynamics_7008c(DragParameters::default());
    params.outer_ring = Some(OuterRing {
        mass: 0.2,
        housing: Support {
            stiffness: [0.0, 2e8, 2e8],
            damping: [0.0, 500.0, 500.0],
        },
    });
    let model = BearingModel::new(&g, &steel, &steel, HertzModel::Exact, params).unwrap();
    let mut y = model.state_from_equilibrium(&eq);
    // At the quasi-static state the balls sit mid-pocket.
    assert_eq!(model.pocket_forces(&y), (0.0, 0.0));
    let layout = model.layout();
    // Cage turned by 0.1 mm at its pitch radius (half clearance 87.5 µm)
    // and moved off centre: every pocket pushes its ball.
    y[layout.cage() + 2] += 0.1e-3 / 27e-3;
    y[layout.cage()] += 5e-6;
    let t = 1e-3;
    let shape = model.block_layout();
    let (b, start, c) = (shape.block_size, shape.border_start(), model.coupling_len());
    let mut memo = vec![0.0; model.memo_len()];
    assert!(!memo.is_empty());
    let (mut dy, mut coupling) = (vec![0.0; b], vec![0.0; c]);
    let (mut dy_full, mut coupling_full) = (vec![0.0; b], vec![0.0; c]);
    let mut compared = 0;
    for j in 0..shape.blocks {
        model.block_rhs_memo(t, &y, j, &mut dy, &mut coupling, &mut memo);
        model.block_rhs(t, &y, j, &mut dy_full, &mut coupling_full);
        assert_eq!(
            bits(&dy),
            bits(&dy_full),
            "ball {j} at the unperturbed point"
        );
        assert_eq!(bits(&coupling), bits(&coupling_full));
        for p in 0..shape.border {
            let mut perturbed = y.clone();
            perturbed[start + p] += 1e-7 * (1.0 + y[start + p].abs());
            model.block_rhs_border_column(t, &perturbed, j, p, &memo, &mut dy, &mut coupling);
            model.block_rhs(t, &perturbed, j, &mut dy_full, &mut coupling_full);
            assert_eq!(bits(&dy), bits(&dy_full), "ball {j}, border state {p}");
            assert_eq!(
                bits(&coupling),
                bits(&coupling_full),
                "ball {j}, border state {p}"
            );
            compared += 1;
        }
    }
    assert_eq!(compared, shape.blocks * shape.border);
    // The pockets are closed (the cage's columns are not trivially equal).
    let cage_torque: f64 = (0..shape.blocks)
        .map(|j| {
            model.block_rhs(t, &y, j, &mut dy, &mut coupling);
            coupling[12]
        })
        .sum();
    assert!(cage_torque.abs() > 1e-3, "cage torque {cage_torque}");
    let (sum, largest) = model.pocket_forces(&y);
    assert!(
        largest > 0.0 && sum >= largest * 2.0,
        "{sum} N, {largest} N"
    );
}
