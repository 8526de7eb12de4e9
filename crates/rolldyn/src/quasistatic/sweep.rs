//! Sweeps of quasi-static solutions over lists or grids of operating
//! points, in parallel and deterministic.
//!
//! The points are cut, in input order, into chunks of consecutive points
//! ([`chunk_length`]: at least [`SWEEP_CHUNK`], and at most
//! [`SWEEP_CHUNKS`] chunks). Each chunk solves its first point from the
//! built-in start and warm-starts every next point from the point solved
//! last, or from a solved point more than twice as near
//! ([`QuasiStaticSolver::solve_from`], which falls back to the built-in
//! start): on a grid, the neighbour along the fastest axis, or, at the
//! start of a line, the start of the line before. Chunks run in parallel
//! (rayon). Because the chunking depends on the number of points only,
//! not on the number of threads, results come back in input order and are
//! bit-identical to a serial run (VALIDATION B7).

use super::equilibrium::{
    Conditions, Equilibrium, QuasiStaticError, QuasiStaticSolver, SolverOptions,
};
use rayon::prelude::*;

/// Fewest points per warm-started chain.
pub const SWEEP_CHUNK: usize = 32;

/// Most chains of a sweep: longer chains start cold less often (a cold
/// start at speed costs tens of warm ones) and still share the work
/// evenly among the cores of a workstation.
pub const SWEEP_CHUNKS: usize = 64;

/// Solved points searched for a nearer one than the latest (the latest
/// ones): on a grid, more than a line.
const NEAREST_WINDOW: usize = 256;

/// Points per chain for a sweep of `points` points.
pub fn chunk_length(points: usize) -> usize {
    points.div_ceil(SWEEP_CHUNKS).max(SWEEP_CHUNK)
}

/// The operating point's coordinates: inner-ring speed, forces, moments.
fn coordinates(c: &Conditions) -> [f64; 6] {
    let [fx, fy, fz] = c.loads.force;
    let [my, mz] = c.loads.moment;
    [c.inner_speed, fx, fy, fz, my, mz]
}

/// The solved point of the chunk to warm-start `point` from: the latest,
/// unless another is more than twice as near. Distances are sums of
/// coordinate differences, each over the largest magnitude of that
/// coordinate in the chunk, with points under another raceway control
/// last; the last [`NEAREST_WINDOW`] solved points are searched. On a
/// grid the latest is the neighbour along the line; at the start of a
/// line, the start of the line before. (Strictly the nearest would, where
/// the grid is finer across lines than along them, start each point from
/// the line before, which may lie on another branch: the light-axial
/// line of a heavy radial load.)
fn warm_start<'a>(
    point: &Conditions,
    solved: &'a [(Conditions, Equilibrium)],
    scale: &[f64; 6],
) -> Option<&'a Equilibrium> {
    let here = coordinates(point);
    let distance = |c: &Conditions| {
        let there = coordinates(c);
        let d: f64 = (0..6)
            .filter(|&i| scale[i] > 0.0)
            .map(|i| (here[i] - there[i]).abs() / scale[i])
            .sum();
        if c.control == point.control {
            d
        } else {
            d + 1e3
        }
    };
    let (latest_conditions, latest) = solved.last()?;
    let to_latest = distance(latest_conditions);
    let (nearest_conditions, nearest) = solved
        .iter()
        .rev()
        .take(NEAREST_WINDOW)
        .min_by(|a, b| distance(&a.0).total_cmp(&distance(&b.0)))?;
    Some(if to_latest <= 2.0 * distance(nearest_conditions) {
        latest
    } else {
        nearest
    })
}

fn solve_chunk(
    solver: &QuasiStaticSolver,
    points: &[Conditions],
    options: &SolverOptions,
) -> Vec<Result<Equilibrium, QuasiStaticError>> {
    let mut scale = [0.0f64; 6];
    for p in points {
        for (s, v) in scale.iter_mut().zip(coordinates(p)) {
            *s = s.max(v.abs());
        }
    }
    let mut out: Vec<Result<Equilibrium, QuasiStaticError>> = Vec::with_capacity(points.len());
    let mut solved: Vec<(Conditions, Equilibrium)> = Vec::with_capacity(points.len());
    for point in points {
        let result = match warm_start(point, &solved, &scale) {
            Some(p) => solver.solve_from(p, point, options),
            None => solver.solve(point, options),
        };
        if let Ok(sol) = &result {
            solved.push((*point, sol.clone()));
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
    let length = chunk_length(points.len());
    if parallel {
        points
            .par_chunks(length)
            .flat_map_iter(|c| solve_chunk(solver, c, options))
            .collect()
    } else {
        points
            .chunks(length)
            .flat_map(|c| solve_chunk(solver, c, options))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::operating::Loads;
    use crate::quasistatic::RacewayControl;

    #[test]
    fn chains_are_at_least_32_points_and_at_most_64() {
        assert_eq!(chunk_length(1), SWEEP_CHUNK);
        assert_eq!(chunk_length(2048), SWEEP_CHUNK);
        assert_eq!(chunk_length(2049), 33);
        assert_eq!(chunk_length(10_000), 157);
        assert!(10_000usize.div_ceil(chunk_length(10_000)) <= SWEEP_CHUNKS);
    }

    /// On a grid (speed outer, radial load inner), a point warm-starts from
    /// its neighbour along the line (the point solved last), also where a
    /// point of the line before is nearer but not twice as near, and the
    /// start of a line from the start of the line before, not from the
    /// end of the last line.
    #[test]
    fn warm_starts_come_from_the_latest_unless_another_is_twice_as_near() {
        let point = |rpm: f64, fz: f64| Conditions {
            loads: Loads {
                force: [1000.0, 0.0, fz],
                moment: [0.0, 0.0],
            },
            inner_speed: rpm,
            control: RacewayControl::Outer,
        };
        let g = crate::geometry::test_bearing(15);
        let solver = QuasiStaticSolver::new(
            &g,
            &crate::Material::STEEL_52100,
            &crate::Material::STEEL_52100,
            crate::contact::HertzModel::Exact,
        )
        .unwrap();
        let eq = solver
            .solve(&point(0.0, 0.0), &SolverOptions::default())
            .unwrap();
        let mut solved = Vec::new();
        for rpm in [0.0, 100.0] {
            for fz in [0.0, 500.0, 1000.0] {
                let mut e = eq.clone();
                // Tag each solution by its point.
                e.iterations = (rpm + fz) as usize;
                solved.push((point(rpm, fz), e));
            }
        }
        let scale = [1000.0, 1000.0, 0.0, 1000.0, 0.0, 0.0];
        let tag = |p: &Conditions| warm_start(p, &solved, &scale).map(|e| e.iterations);
        assert_eq!(tag(&point(200.0, 0.0)), Some(100));
        assert_eq!(tag(&point(100.0, 1500.0)), Some(1100));
        // From (100 rpm, 1500 N): 0.5 to the latest (100 rpm, 1000 N),
        // 0.3 to (0, 1300 N): the latest…
        let mut partial = solved.clone();
        let mut e = eq.clone();
        e.iterations = 1300;
        partial.insert(2, (point(0.0, 1300.0), e));
        let tag_partial = |p: &Conditions| warm_start(p, &partial, &scale).map(|e| e.iterations);
        assert_eq!(tag_partial(&point(100.0, 1500.0)), Some(1100));
        // …and from (100 rpm, 1350 N): 0.35 to the latest, 0.15 to
        // (0, 1300 N), more than twice as near.
        assert_eq!(tag_partial(&point(100.0, 1350.0)), Some(1300));
        assert_eq!(tag(&point(0.0, 500.0)), Some(500));
        assert_eq!(tag(&point(0.0, 0.0)), Some(0));
        assert_eq!(
            warm_start(&point(0.0, 0.0), &[], &scale).map(|e| e.iterations),
            None
        );
    }
}
