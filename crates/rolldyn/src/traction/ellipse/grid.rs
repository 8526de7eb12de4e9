//! The strip grids over the unit ellipse (docs/dynamics.md, "Traction
//! over the contact ellipse").

use super::{BATCH, Cells, TractionIntegration};
use std::f64::consts::{FRAC_PI_2, PI};

/// The strip grid of a [`TractionIntegration`] over the unit ellipse,
/// prepared once (a model keeps one): per strip its position s and
/// half-width w = √(1 − s²), per cell its position t along the strip, its
/// width and the unit Hertz shape √(1 − s² − t²), and Σ shape · weight for
/// the normalisation. The grid is symmetric in s and in t (mirrored cells are
/// built from the same |s|, |t|), so each shape occurs up to four times:
/// the distinct shapes are the grid's pressure **levels**, at which
/// [`super::integrate`] evaluates a law's pressure term (the EHL viscosity) once.
/// These depend on the grid only; [`super::integrate`] scales them by the
/// contact's semi-axes and load.
///
/// The cells are laid out for the lanes (`StripGroup`): each lane stays
/// on one strip, so what is constant along a strip (its ξ, drop and
/// slip line) is set once per lane and the strip moments need no per-cell
/// product.
#[derive(Debug, Clone, PartialEq)]
pub struct TractionGrid {
    pub(super) method: TractionIntegration,
    /// (s, w) per strip.
    pub(super) strips: Vec<(f64, f64)>,
    /// The cells in lane order.
    pub(super) groups: Vec<StripGroup>,
    /// The distinct unit shapes.
    pub(super) levels: Vec<f64>,
    /// Σ shape · weight over the cells.
    pub(super) shape_sum: f64,
}

/// Consecutive strips `first..first + len` spread over the lanes: lane k
/// is on strip `first + k % len`, and a batch holds m = ⌊BATCH/len⌋ of
/// their cells' columns (lane k in column `c₀ + k / len`). Lanes beyond
/// `len · m`, and columns beyond the strip's cells, are empty (weight 0).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct StripGroup {
    pub(super) first: usize,
    pub(super) len: usize,
    pub(super) batches: Vec<CellBatch>,
}

/// [`BATCH`] cells of a [`StripGroup`].
#[derive(Debug, Clone, PartialEq)]
pub(super) struct CellBatch {
    /// Position along the strip, in units of b (0 where empty).
    pub(super) t: Cells,
    /// Unit Hertz shape √(1 − s² − t²) (0 where empty).
    pub(super) shape: Cells,
    /// The cell's area over the contact's cell size (0 where empty): the
    /// strip's half-width w times the cell's width along it over the
    /// uniform grid's (1 on the uniform grid).
    pub(super) weight: Cells,
    /// Index of `shape` in the grid's levels.
    pub(super) level: [u32; BATCH],
}

/// Most pressure levels [`super::integrate`] holds on the stack (12 × 6 has 18,
/// 24 × 12 has 72); finer grids evaluate the pressure term per cell.
pub(super) const MAX_LEVELS: usize = 96;

/// Midpoints of n equal cells of [−1, 1], mirror-symmetric to the bit:
/// the upper half is the negated lower half.
fn symmetric_midpoints(n: usize) -> impl Iterator<Item = f64> {
    (0..n).map(move |k| {
        let lower = k.min(n - 1 - k);
        let u = -1.0 + (lower as f64 + 0.5) * 2.0 / n as f64;
        if k == lower { u } else { -u }
    })
}

/// n cells of [−1, 1] equal in the angle θ of u = sin θ, as (node, width
/// over 2/n): each cell's exact width sin θ₊ − sin θ₋, its node at the
/// angle's midpoint, mirror-symmetric to the bit. Along a strip of the
/// ellipse the Hertz pressure is √(1 − u²) = cos θ times the strip's
/// middle one: the cells shrink towards the strip's ends, where the
/// pressure falls steeply, and are π/2 times the uniform width at its
/// middle.
fn graded_cells(n: usize) -> impl Iterator<Item = (f64, f64)> {
    let angle = move |i: f64| -FRAC_PI_2 + i * PI / n as f64;
    (0..n).map(move |k| {
        let lower = k.min(n - 1 - k) as f64;
        let u = angle(lower + 0.5).sin();
        let width = (angle(lower + 1.0).sin() - angle(lower).sin()) * n as f64 / 2.0;
        if k == lower as usize {
            (u, width)
        } else {
            (-u, width)
        }
    })
}

/// Strips per [`StripGroup`] for a grid of `across` strips of `along`
/// cells: the fewest batches, and of those the fewest groups (12 × 6:
/// one group of 12 strips, 3 full batches).
fn group_len(across: usize, along: usize) -> usize {
    let batches = |len: usize| -> usize {
        (0..across)
            .step_by(len)
            .map(|first| along.div_ceil(BATCH / len.min(across - first)))
            .sum()
    };
    (1..=across.min(BATCH))
        .rev()
        .min_by_key(|&len| batches(len))
        .unwrap_or(1)
}

impl TractionGrid {
    /// Prepares the grid of `method` (nothing for the contact centre).
    pub fn new(method: TractionIntegration) -> Self {
        let mut grid = Self {
            method,
            strips: Vec::new(),
            groups: Vec::new(),
            levels: Vec::new(),
            shape_sum: 0.0,
        };
        let (across, along, graded) = match method {
            TractionIntegration::Centre => return grid,
            TractionIntegration::Grid { across, along } => (across, along, false),
            TractionIntegration::Graded { across, along } => (across, along, true),
        };
        let (across, along) = (across.max(1), along.max(1));
        let cells_along: Vec<(f64, f64)> = if graded {
            graded_cells(along).collect()
        } else {
            symmetric_midpoints(along).map(|u| (u, 1.0)).collect()
        };
        let mut level_of = std::collections::HashMap::new();
        // Per cell, strip by strip: (t, shape, level, weight).
        let mut cells = Vec::with_capacity(across * along);
        for s in symmetric_midpoints(across) {
            let w = (1.0 - s * s).sqrt();
            grid.strips.push((s, w));
            for &(u, width) in &cells_along {
                let t = w * u;
                let weight = w * width;
                let shape = (1.0 - s * s - t * t).max(0.0).sqrt();
                let next = grid.levels.len();
                let level = *level_of.entry(shape.to_bits()).or_insert(next);
                if level == next {
                    grid.levels.push(shape);
                }
                cells.push((t, shape, level, weight));
                grid.shape_sum += shape * weight;
            }
        }
        let group = group_len(across, along);
        for first in (0..across).step_by(group) {
            let len = group.min(across - first);
            let columns = BATCH / len;
            let batches = (0..along)
                .step_by(columns)
                .map(|first_column| {
                    let mut batch = CellBatch {
                        t: [0.0; BATCH],
                        shape: [0.0; BATCH],
                        weight: [0.0; BATCH],
                        level: [0; BATCH],
                    };
                    for k in 0..len * columns {
                        let (strip, column) = (first + k % len, first_column + k / len);
                        if column < along {
                            let (t, shape, level, weight) = cells[strip * along + column];
                            batch.t[k] = t;
                            batch.shape[k] = shape;
                            batch.weight[k] = weight;
                            batch.level[k] = level as u32;
                        }
                    }
                    batch
                })
                .collect();
            grid.groups.push(StripGroup {
                first,
                len,
                batches,
            });
        }
        grid
    }
}
