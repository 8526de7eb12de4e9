//! Building the table from Kalker's exact theory ([`super::super::exact`]).
//!
//! Each node is one steady-rolling contact in normalised units (b = 1,
//! a = a/b of the node, G = Q = μ = 1) solved by boundary elements on two
//! grids, `cells` × `cells` and half that, and extrapolated to zero cell
//! size (the exact solver converges at first order in the cell size:
//! F ≈ 2 F_fine − F_coarse, Richardson). At the full-slip node (u = 1) the
//! traction is −μ p_n along the rigid slip, evaluated on a grid four times
//! finer. `cargo run --release -p rolldyn --example build_exact_traction_table`
//! writes the embedded file.

use super::Table;
use super::layout::{Direction, LINEAR_MAGNITUDE, Layout, Normalisation, OUTPUTS, SLOPES};
use crate::traction::exact::{ExactRolling, PreparedContact};
use nalgebra::Vector2;
use rayon::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};

/// Tangential convergence of the builder's solves (relative traction change).
const TOLERANCE: f64 = 1e-6;

/// The normalised outputs of one contact's tractions `p` on `contact`
/// (b = 1, μQ = 1), and its stick flags.
fn resultants(contact: &PreparedContact, p: &[Vector2<f64>], stick: &[bool]) -> [f64; OUTPUTS] {
    let area = contact.cell_area();
    let (mut out, mut loaded, mut stuck) = ([0.0; OUTPUTS], 0usize, 0usize);
    for c in 0..contact.cells() {
        if contact.bound[c] <= 0.0 {
            continue;
        }
        let (x, y) = (contact.x(c), contact.y(c));
        let f = p[c] * area;
        out[0] += f.x;
        out[1] += f.y;
        out[2] += x * f.y - y * f.x;
        out[3] += y * y * f.x;
        out[4] += y * y * f.y;
        loaded += 1;
        stuck += usize::from(stick[c]);
    }
    out[5] = stuck as f64 / loaded.max(1) as f64;
    out
}

/// The rigid slip per unit V of physical creepages [ξ, η, φ, χ] at every
/// cell: (ξ − φy − χy², η + φx).
fn rigid_slip(contact: &PreparedContact, creep: [f64; 4]) -> Vec<Vector2<f64>> {
    let [xi, eta, phi, chi] = creep;
    (0..contact.cells())
        .map(|c| {
            let (x, y) = (contact.x(c), contact.y(c));
            Vector2::new(xi - phi * y - chi * y * y, eta + phi * x)
        })
        .collect()
}

/// One ratio's contacts: the fine and coarse grids and the full-slip grid.
struct RatioContacts {
    fine: PreparedContact,
    coarse: PreparedContact,
    /// The full-slip grid (only when full-slip nodes are wanted).
    sliding: Option<PreparedContact>,
    normalisation: Normalisation,
}

impl RatioContacts {
    fn new(ratio: f64, poisson_ratio: f64, cells: usize, with_sliding: bool) -> Self {
        let solver = |n: usize| ExactRolling {
            cells_along: n,
            cells_across: n,
            tolerance: TOLERANCE,
            max_sweeps: 5000,
            ..ExactRolling::new(1.0, 1.0, poisson_ratio)
        };
        let prepare = |n: usize| solver(n).prepare(ratio, 1.0, 1.0);
        Self {
            fine: prepare(cells),
            coarse: prepare(cells / 2),
            sliding: with_sliding.then(|| prepare(4 * cells)),
            normalisation: Normalisation::new(ratio, 1.0, 1.0, poisson_ratio, 1.0, 1.0),
        }
    }

    /// The outputs at normalised creepages `star` (u < 1).
    fn rolling(&self, star: [f64; 4]) -> [f64; OUTPUTS] {
        let creep = std::array::from_fn(|k| star[k] / self.normalisation.scale[k]);
        let solve = |contact: &PreparedContact| {
            let s = contact.tangential(&rigid_slip(contact, creep), TOLERANCE, 5000);
            resultants(contact, &s.traction, &s.stick)
        };
        let (fine, coarse) = (solve(&self.fine), solve(&self.coarse));
        let mut out: [f64; OUTPUTS] = std::array::from_fn(|k| 2.0 * fine[k] - coarse[k]);
        out[5] = out[5].clamp(0.0, 1.0);
        out
    }

    /// The stored values of node (α, β, γ, u) of this ratio.
    fn stored(&self, layout: &Layout, [a, b, c, u]: [usize; 4]) -> [f64; OUTPUTS] {
        let alpha = Layout::angle(a, layout.alphas, FRAC_PI_2);
        let beta = Layout::angle(b, layout.betas, PI);
        let gamma = Layout::angle(c, layout.gammas, PI);
        let magnitude = layout.magnitude(u).max(LINEAR_MAGNITUDE);
        let mut out = if magnitude >= 1.0 {
            self.sliding(Direction::unit(alpha, beta, gamma))
        } else {
            self.rolling(Direction::creepages(magnitude, alpha, beta, gamma))
        };
        for v in &mut out[..SLOPES] {
            *v /= magnitude;
        }
        if u == 0 {
            // The limit's stick fraction (the trailing edge's cells slip
            // at any creepage on a grid).
            out[SLOPES] = 1.0;
        }
        out
    }

    /// The full-slip limit along the unit direction `unit` (normalised).
    fn sliding(&self, unit: [f64; 4]) -> [f64; OUTPUTS] {
        let Some(contact) = &self.sliding else {
            return [0.0; OUTPUTS];
        };
        let creep = std::array::from_fn(|k| unit[k] / self.normalisation.scale[k]);
        let w = rigid_slip(contact, creep);
        let p: Vec<Vector2<f64>> = w
            .iter()
            .zip(&contact.bound)
            .map(|(w, g)| {
                let size = w.norm();
                if size > 0.0 { -*g * w / size } else { *w }
            })
            .collect();
        resultants(contact, &p, &vec![false; contact.cells()])
    }
}

/// The distinct directions of the grid: (α, β, γ) node indices, with the
/// degenerate ones (α = 0: every β, γ; β = 0 or π: every γ) mapped to
/// their representative.
fn representative(layout: &Layout, a: usize, b: usize, c: usize) -> (usize, usize, usize) {
    if a == 0 {
        (0, 0, 0)
    } else if b == 0 || b == layout.betas - 1 {
        (a, b, 0)
    } else {
        (a, b, c)
    }
}

/// Builds the table for `layout` at Poisson ratio ν on `cells` × `cells`
/// (extrapolated with half as many). Parallel over directions; the result
/// does not depend on the thread count.
pub fn build(layout: Layout, poisson_ratio: f64, cells: usize) -> Table {
    let per_ratio = layout.alphas * layout.betas * layout.gammas * layout.magnitudes;
    let mut values = vec![[0.0; OUTPUTS]; layout.nodes()];
    for g in 0..layout.ratios {
        let contacts = RatioContacts::new(layout.ratio(g), poisson_ratio, cells, true);
        let directions: Vec<(usize, usize, usize)> = (0..layout.alphas)
            .flat_map(|a| {
                (0..layout.betas).flat_map(move |b| (0..layout.gammas).map(move |c| (a, b, c)))
            })
            .filter(|&(a, b, c)| representative(&layout, a, b, c) == (a, b, c))
            .collect();
        let solved: Vec<Vec<[f64; OUTPUTS]>> = directions
            .par_iter()
            .map(|&(a, b, c)| {
                (0..layout.magnitudes)
                    .map(|u| contacts.stored(&layout, [a, b, c, u]))
                    .collect()
            })
            .collect();
        for a in 0..layout.alphas {
            for b in 0..layout.betas {
                for c in 0..layout.gammas {
                    let rep = representative(&layout, a, b, c);
                    let k = directions.iter().position(|&d| d == rep).unwrap_or(0);
                    for u in 0..layout.magnitudes {
                        values[layout.index(g, a, b, c, u)] = solved[k][u];
                    }
                }
            }
        }
        debug_assert_eq!(per_ratio * (g + 1), layout.index(g + 1, 0, 0, 0, 0));
    }
    Table::from_values(layout, poisson_ratio, cells, &values)
}

/// One node's stored values computed afresh (for checking the stored
/// table): the outputs divided by u (at u = 0 the linear theory's slope),
/// the stick fraction as is.
pub fn node(layout: &Layout, poisson_ratio: f64, cells: usize, at: [usize; 5]) -> [f64; OUTPUTS] {
    let [g, a, b, c, u] = at;
    let sliding = layout.magnitude(u) >= 1.0;
    RatioContacts::new(layout.ratio(g), poisson_ratio, cells, sliding).stored(layout, [a, b, c, u])
}

/// The exact theory at arbitrary normalised creepages `star` and ratio
/// (u < 1), extrapolated as the nodes are: the reference the table's
/// interpolation error is measured against.
pub fn exact_at(ratio: f64, poisson_ratio: f64, cells: usize, star: [f64; 4]) -> [f64; OUTPUTS] {
    RatioContacts::new(ratio, poisson_ratio, cells, false).rolling(star)
}
