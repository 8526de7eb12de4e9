use super::*;

/// A deterministic pseudo-random bordered matrix.
fn sample(layout: BlockLayout) -> BlockJacobian {
    let mut j = BlockJacobian::zeros(layout);
    let mut state = 12345u64;
    let mut next = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 11) as f64 / (1u64 << 53) as f64) - 0.5
    };
    for v in j
        .diag
        .iter_mut()
        .chain(j.upper.iter_mut())
        .chain(j.lower.iter_mut())
        .chain(j.border.iter_mut())
    {
        *v = next();
    }
    j
}

fn residual(layout: BlockLayout, sigma: f64) -> f64 {
    let jac = sample(layout);
    let n = layout.dimension();
    let rhs: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin()).collect();
    let mut lu = BlockLu::new(layout);
    lu.factor(&jac, sigma).unwrap();
    let mut x = rhs.clone();
    lu.solve(&mut x);
    let mut jx = vec![0.0; n];
    jac.multiply(&x, &mut jx);
    (0..n)
        .map(|i| (sigma * x[i] - jx[i] - rhs[i]).abs())
        .fold(0.0, f64::max)
}

#[test]
fn block_solve_matches_the_full_system() {
    // (σI − J) x = r to round-off, for bordered and dense shapes, with σ
    // small enough that pivoting matters.
    for layout in [
        BlockLayout {
            blocks: 5,
            block_size: 4,
            border: 3,
        },
        BlockLayout {
            blocks: 3,
            block_size: 9,
            border: 22,
        },
        BlockLayout::dense(7),
    ] {
        for sigma in [0.01, 1.0, 100.0] {
            let r = residual(layout, sigma);
            assert!(r < 1e-10, "{layout:?} σ {sigma}: residual {r:e}");
        }
    }
}

/// The test layout of the inert-state tests: a free ball's 9 states,
/// 22 border states, and which of them have zero Jacobian columns.
const INERT_LAYOUT: BlockLayout = BlockLayout {
    blocks: 4,
    block_size: 9,
    border: 22,
};

fn inert(state: usize) -> bool {
    let (b, s) = (INERT_LAYOUT.block_size, INERT_LAYOUT.border_start());
    if state < s {
        matches!(state % b, 0 | 3 | 7 | 8)
    } else {
        matches!(state - s, 0 | 3 | 4 | 5 | 8 | 9 | 10..=13 | 20 | 21)
    }
}

/// `jac` with the entries (row, col) where `zero` holds set to 0.
fn zeroed(jac: &BlockJacobian, zero: impl Fn(usize, usize) -> bool) -> BlockJacobian {
    let layout = jac.layout();
    let (b, m, s) = (layout.block_size, layout.border, layout.border_start());
    let at = |r: usize, c: usize| if zero(r, c) { 0.0 } else { jac.get(r, c) };
    let mut out = BlockJacobian::zeros(layout);
    for j in 0..layout.blocks {
        for r in 0..b {
            for c in 0..b {
                out.diag[j * b * b + r * b + c] = at(j * b + r, j * b + c);
            }
            for c in 0..m {
                out.upper[j * b * m + r * m + c] = at(j * b + r, s + c);
            }
        }
        for r in 0..m {
            for c in 0..b {
                out.lower[j * m * b + r * b + c] = at(s + r, j * b + c);
            }
        }
    }
    for r in 0..m {
        for c in 0..m {
            out.border[r * m + c] = at(s + r, s + c);
        }
    }
    out
}

/// Solves with the reduced factorization and with the one that keeps
/// every state; checks the residual of the full system and that both
/// agree.
fn check_reduced(reduced: &mut BlockLu, jac: &BlockJacobian, sigma: f64) {
    let layout = jac.layout();
    let n = layout.dimension();
    let rhs: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin()).collect();
    reduced.factor(jac, sigma).unwrap();
    let mut x = rhs.clone();
    reduced.solve(&mut x);
    let mut kept = BlockLu::new(layout);
    kept.factor(jac, sigma).unwrap();
    let mut x_kept = rhs.clone();
    kept.solve(&mut x_kept);
    let mut jx = vec![0.0; n];
    jac.multiply(&x, &mut jx);
    for i in 0..n {
        let r = (sigma * x[i] - jx[i] - rhs[i]).abs();
        assert!(r < 1e-10, "σ {sigma}, state {i}: residual {r:e}");
        let d = (x[i] - x_kept[i]).abs();
        assert!(
            d < 1e-9 * (1.0 + x_kept[i].abs()),
            "σ {sigma}, state {i}: {d:e}"
        );
    }
}

/// With zero Jacobian columns for some states (inert in every block,
/// and in the border), the reduced factorization solves the full
/// system to round-off, and equals the factorization that keeps them.
#[test]
fn inert_states_are_left_out_and_recovered() {
    let jac = zeroed(&sample(INERT_LAYOUT), |_, c| inert(c));
    let mut reduced = BlockLu::with_inert(INERT_LAYOUT, inert);
    assert_eq!(reduced.block_active.len(), 5);
    assert_eq!(reduced.border_active.len(), 10);
    for sigma in [0.01, 1.0, 100.0] {
        check_reduced(&mut reduced, &jac, sigma);
    }
}

/// Zero couplings, as a ball out of contact has: block 1 decoupled
/// from the border (Uⱼ = Lⱼ = 0), block 2 reaching only border state 2,
/// and inert states whose rows are zero. The same factorization then
/// refactors the fully coupled matrix (the flags follow the matrix).
#[test]
fn zero_couplings_and_rows_are_skipped_exactly() {
    let (b, s) = (INERT_LAYOUT.block_size, INERT_LAYOUT.border_start());
    let block = |state: usize| (state < s).then_some(state / b);
    let coupled = zeroed(&sample(INERT_LAYOUT), |_, c| inert(c));
    let sparse = zeroed(&coupled, |r, c| {
        let across = block(r) != block(c);
        (across && (block(r) == Some(1) || block(c) == Some(1)))
            || (block(c) == Some(2) && r >= s && r != s + 2)
            || (inert(r) && r % 2 == 0)
    });
    let mut reduced = BlockLu::with_inert(INERT_LAYOUT, inert);
    for sigma in [0.01, 1.0, 100.0] {
        check_reduced(&mut reduced, &sparse, sigma);
        assert!(!reduced.coupled_nonzero[1] && reduced.coupled_nonzero[2]);
        let mk = reduced.border_kept.len();
        let rows = |j: usize| reduced.lower_row_nonzero[j * mk..(j + 1) * mk].to_vec();
        assert!(rows(1).iter().all(|nz| !nz));
        assert_eq!(rows(2).iter().filter(|nz| **nz).count(), 1);
        assert!(reduced.inert_row_is_zero.iter().any(|z| *z));
        check_reduced(&mut reduced, &coupled, sigma);
        assert!(reduced.coupled_nonzero.iter().all(|c| *c));
        assert!(reduced.inert_row_is_zero.iter().all(|z| !z));
    }
}

/// The positions of the test layout and their velocities, as a bearing's
/// (ball r, φ; the ring's and the cage's), on the active states.
fn rate(state: usize) -> Option<usize> {
    let (b, s) = (INERT_LAYOUT.block_size, INERT_LAYOUT.border_start());
    if state < s {
        return matches!(state % b, 0..=2).then_some(state + 3);
    }
    match state - s {
        0..=4 => Some(state + 5),
        14..=16 => Some(state + 3),
        _ => None,
    }
}

/// `jac` with the rows of the positions that [`rate`] declares: the unit
/// row of the velocity, or zero where the velocity is `frozen` (as a
/// planar model's axial position, held by a zero rate).
fn positioned(jac: &BlockJacobian, frozen: impl Fn(usize) -> bool) -> BlockJacobian {
    let n = jac.layout().dimension();
    let mut out = zeroed(jac, |r, _| rate(r).is_some());
    let (b, m, s) = (
        INERT_LAYOUT.block_size,
        INERT_LAYOUT.border,
        INERT_LAYOUT.border_start(),
    );
    for (q, v) in (0..n).filter_map(|q| Some((q, rate(q)?))) {
        if frozen(v) {
            continue;
        }
        if q < s {
            out.diag[(q / b) * b * b + (q % b) * b + v % b] = 1.0;
        } else {
            out.border[(q - s) * m + (v - s)] = 1.0;
        }
    }
    out
}

/// Positions with their velocities' unit rows, on top of inert states:
/// the positions whose velocity is active are eliminated (ball r, φ; the
/// border's five), the others are inert anyway; the solve recovers them.
#[test]
fn positions_are_eliminated_and_recovered() {
    let jac = positioned(&zeroed(&sample(INERT_LAYOUT), |_, c| inert(c)), inert);
    let mut reduced = BlockLu::with_structure(INERT_LAYOUT, inert, rate);
    assert_eq!(reduced.kept_states(), (3, 5));
    for sigma in [0.01, 1.0, 100.0, 1e6] {
        check_reduced(&mut reduced, &jac, sigma);
    }
    // Without inert states: every position goes.
    let jac = positioned(&sample(INERT_LAYOUT), |_| false);
    let mut reduced = BlockLu::with_structure(INERT_LAYOUT, |_| false, rate);
    assert_eq!(reduced.kept_states(), (6, 14));
    for sigma in [0.01, 1.0, 100.0] {
        check_reduced(&mut reduced, &jac, sigma);
    }
}

/// A Jacobian with inert columns, some inert rows zero on the active
/// states, a block without border couplings, and the positions' unit rows.
fn partly_zero() -> BlockJacobian {
    positioned(
        &zeroed(&sample(INERT_LAYOUT), |r, c| {
            inert(c) || (inert(r) && r % 3 == 0) || (r < 9 && c >= 36)
        }),
        inert,
    )
}

/// Refactoring for a new σ gives the bits of a fresh factorization.
#[test]
fn refactor_equals_factor_bit_for_bit() {
    let jac = partly_zero();
    let n = INERT_LAYOUT.dimension();
    let rhs: Vec<f64> = (0..n).map(|i| (i as f64 * 0.3).cos()).collect();
    let mut reused = BlockLu::with_structure(INERT_LAYOUT, inert, rate);
    reused.factor(&jac, 5.0).unwrap();
    for sigma in [0.01, 1.0, 100.0] {
        reused.refactor(&jac, sigma).unwrap();
        let mut fresh = BlockLu::with_structure(INERT_LAYOUT, inert, rate);
        fresh.factor(&jac, sigma).unwrap();
        let (mut x, mut y) = (rhs.clone(), rhs.clone());
        reused.solve(&mut x);
        fresh.solve(&mut y);
        assert!(x.iter().zip(&y).all(|(a, b)| a.to_bits() == b.to_bits()));
    }
}

/// The factorization across threads gives the bits of the serial one
/// (and reports a singular block as it does).
#[test]
fn parallel_factorization_equals_serial_bit_for_bit() {
    let jac = partly_zero();
    let n = INERT_LAYOUT.dimension();
    let rhs: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin()).collect();
    let mut serial = BlockLu::with_structure(INERT_LAYOUT, inert, rate);
    serial.factor(&jac, 3.0).unwrap();
    let mut expected = rhs.clone();
    serial.solve(&mut expected);
    for threads in [1, 2, 3] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let mut parallel = BlockLu::with_structure(INERT_LAYOUT, inert, rate);
        parallel.set_parallel(true);
        let x = pool.install(|| {
            parallel.factor(&jac, 3.0).unwrap();
            let mut x = rhs.clone();
            parallel.solve(&mut x);
            x
        });
        assert!(
            x.iter()
                .zip(&expected)
                .all(|(a, b)| a.to_bits() == b.to_bits()),
            "{threads} threads"
        );
        // σ = 0 on a zero block: singular, reported from any thread.
        let singular = zeroed(&jac, |r, _| {
            r < INERT_LAYOUT.block_size && rate(r).is_none()
        });
        assert_eq!(
            pool.install(|| parallel.factor(&singular, 0.0)),
            Err(Singular)
        );
    }
}

#[test]
fn singular_matrix_is_reported() {
    let layout = BlockLayout::dense(2);
    let mut jac = BlockJacobian::zeros(layout);
    jac.border.copy_from_slice(&[1.0, 1.0, 1.0, 1.0]);
    // σ = 1: σI − J = [[0, −1], [−1, 0]] is regular (needs a row swap);
    // σ = 2 gives [[1, −1], [−1, 1]], singular.
    let mut lu = BlockLu::new(layout);
    assert!(lu.factor(&jac, 1.0).is_ok());
    assert_eq!(lu.factor(&jac, 2.0), Err(Singular));
}
