//! Sweeps of quasi-static solutions over lists or grids of operating
//! points, in parallel and deterministic.
//!
//! The points are cut, in input order, into fixed chunks of
//! [`SWEEP_CHUNK`] consecutive points. Each chunk solves its first point
//! from the built-in start and warm-starts every next point from its
//! neighbour ([`QuasiStaticSolver::solve_from`], which falls back to the
//! built-in start). Chunks run in parallel (rayon). Because the chunking
//! does not depend on the number of threads, results come back in input
//! order and are bit-identical to a serial run (VALIDATION B7).

use super::equilibrium::{
    Conditions, Equilibrium, QuasiStaticError, QuasiStaticSolver, SolverOptions,
};
use rayon::prelude::*;

/// Points per warm-started chain.
pub const SWEEP_CHUNK: usize = 32;

fn solve_chunk(
    solver: &QuasiStaticSolver,
    points: &[Conditions],
    options: &SolverOptions,
) -> Vec<Result<Equilibrium, QuasiStaticError>> {
    let mut out: Vec<Result<Equilibrium, QuasiStaticError>> = Vec::with_capacity(points.len());
    let mut previous: Option<Equilibrium> = None;
    for point in points {
        let result = match &previous {
            Some(p) => solver.solve_from(p, point, options),
            None => solver.solve(point, options),
        };
        if let Ok(sol) = &result {
            previous = Some(sol.clone());
        }
        out.push(result);
    }
    out
}

/// Solves every point; `parallel` chooses rayon or one thread (same results).
pub fn sweep(
    solver: &QuasiStaticSolver,
    points: &[Conditions],
    options: &SolverOptions,
    parallel: bool,
) -> Vec<Result<Equilibrium, QuasiStaticError>> {
    if parallel {
        points
            .par_chunks(SWEEP_CHUNK)
            .flat_map_iter(|c| solve_chunk(solver, c, options))
            .collect()
    } else {
        points
            .chunks(SWEEP_CHUNK)
            .flat_map(|c| solve_chunk(solver, c, options))
            .collect()
    }
}
