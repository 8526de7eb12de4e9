//! The exact solution extrapolated to zero cell size (Richardson,
//! L. F. Richardson & J. A. Gaunt, *Phil. Trans. R. Soc. A* 226 (1927)
//! 299–361; the order estimated from three grids as in Roache's grid
//! convergence study, P. J. Roache, *Verification and Validation in
//! Computational Science and Engineering*, Hermosa 1998, ch. 5).
//!
//! The solver's resultants approach their limit as F(h) = F₀ − C h^p in
//! the cell size h, plus a non-smooth part from the staircase edge of the
//! numerical contact area. On the grids of 32, 48 and 64 cells a smooth
//! output (the lateral force of a spinning 7218B contact) follows the
//! power law with p ≈ 1.6 to within 0.05 % up to 128 cells, while outputs
//! dominated by the staircase part (the longitudinal force of a small
//! creepage) wander by ~0.1 % without order (docs/dynamics.md, "Kalker's
//! exact theory"). So each output is extrapolated only where its three
//! values converge monotonically at an order between 1 and 2 (the
//! backward difference is first order; its leading term can cancel in a
//! resultant); otherwise the finest grid's value stands, and the change
//! between the two finest grids is its error estimate. The grids are even:
//! an odd grid puts a row of cell centres on the contact's centre line,
//! the spin pole of a pure-spin contact, and falls off the even grids'
//! convergence by ~1 %.

use super::{ContactPatch, Creep, ExactRolling, ExactSolution, TractionResult};
use nalgebra::Vector3;

/// Cells per direction of the three grids of the default exact solve,
/// coarsest first.
pub const EXTRAPOLATION_GRIDS: [usize; 3] = [32, 48, 64];

/// Accepted range of the estimated order of convergence.
const ORDERS: (f64, f64) = (1.0, 2.0);

/// The frame of a solve: x̂ along the flow, ŷ = n × x̂, n the normal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlowFrame {
    /// Along the flow (the rolling direction, signed by the rolling speed).
    pub ex: Vector3<f64>,
    /// Across it.
    pub ey: Vector3<f64>,
    /// The contact normal.
    pub n: Vector3<f64>,
}

/// The tractions' resultants on the ball in the flow frame.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Resultants {
    /// Force along the flow \[N\].
    pub force_along: f64,
    /// Force across it \[N\].
    pub force_across: f64,
    /// Moment about the normal through the contact centre \[N·m\].
    pub spin_moment: f64,
    /// Couple about x̂ of the tractions on the groove-curved surface \[N·m\].
    pub couple_along: f64,
    /// Couple about ŷ \[N·m\].
    pub couple_across: f64,
    /// Power of the tractions on the rigid slip, −Σ p·w V ΔA \[W\].
    pub power: f64,
    /// Frictional power −Σ p·s V ΔA \[W\].
    pub frictional_power: f64,
}

impl Resultants {
    const LEN: usize = 7;

    fn to_array(self) -> [f64; Self::LEN] {
        [
            self.force_along,
            self.force_across,
            self.spin_moment,
            self.couple_along,
            self.couple_across,
            self.power,
            self.frictional_power,
        ]
    }

    fn from_array(a: [f64; Self::LEN]) -> Self {
        Self {
            force_along: a[0],
            force_across: a[1],
            spin_moment: a[2],
            couple_along: a[3],
            couple_across: a[4],
            power: a[5],
            frictional_power: a[6],
        }
    }
}

impl FlowFrame {
    /// The resultants as a [`TractionResult`] (forces and couple about the
    /// contact point, moment left to the caller as FASTSIM's).
    pub fn result(&self, r: &Resultants, creep: Creep) -> TractionResult {
        TractionResult {
            force: r.force_along * self.ex + r.force_across * self.ey,
            moment: Vector3::zeros(),
            couple: r.couple_along * self.ex + r.couple_across * self.ey + r.spin_moment * self.n,
            dissipation: r.power,
            creep: Some(creep),
        }
    }
}

/// An exact solution extrapolated to zero cell size.
#[derive(Debug, Clone)]
pub struct Extrapolated {
    /// The finest grid's solution with its `result` and `resultants`
    /// replaced by the extrapolated ones (its map, stick fraction, sweeps
    /// and frictional power field are the finest grid's).
    pub solution: ExactSolution,
    /// The finest grid's own resultants.
    pub finest: Resultants,
    /// Cells per direction of the grids, coarsest first.
    pub grids: [usize; 3],
    /// The estimated order of each extrapolated output (force along,
    /// across, spin moment, couples, power, frictional power), None where
    /// the finest grid's value stands.
    pub orders: [Option<f64>; 7],
    /// Estimated error of each output: the extrapolation's correction, or
    /// the change between the two finest grids where none was made.
    pub errors: Resultants,
    /// Whether every grid's tangential sweeps converged.
    pub converged: bool,
}

impl Extrapolated {
    /// The force's error estimate |(δF_x, δF_y)| \[N\].
    pub fn force_error(&self) -> f64 {
        self.errors.force_along.hypot(self.errors.force_across)
    }
}

impl ExactRolling {
    /// Solves the contact on the grids of [`EXTRAPOLATION_GRIDS`] (this
    /// solver's own cell counts are not used) and extrapolates every
    /// resultant to zero cell size where its three values converge
    /// (module doc). About 0.4 s per contact (release build).
    pub fn solve_extrapolated(
        &self,
        patch: &ContactPatch,
        slip: &Vector3<f64>,
        spin: &Vector3<f64>,
        rolling: f64,
    ) -> Extrapolated {
        let solve = |cells: usize| {
            ExactRolling {
                cells_along: cells,
                cells_across: cells,
                ..*self
            }
            .solve(patch, slip, spin, rolling)
        };
        let grids = EXTRAPOLATION_GRIDS;
        let [coarse, middle, fine] = grids.map(solve);
        let converged = coarse.converged && middle.converged && fine.converged;
        let values = [&coarse, &middle, &fine].map(|s| s.resultants.to_array());
        let (mut out, mut orders, mut errors) = (values[2], [None; 7], [0.0; 7]);
        for k in 0..Resultants::LEN {
            let e = richardson(grids, [values[0][k], values[1][k], values[2][k]]);
            out[k] = e.value;
            orders[k] = e.order;
            errors[k] = e.error;
        }
        let finest = fine.resultants;
        let resultants = Resultants::from_array(out);
        let mut solution = fine;
        // An unloaded contact has no creepages and no tractions to extrapolate.
        if let Some(creep) = solution.result.creep {
            solution.result = solution.frame.result(&resultants, creep);
            solution.resultants = resultants;
        }
        Extrapolated {
            solution,
            finest,
            grids,
            orders,
            errors: Resultants::from_array(errors),
            converged,
        }
    }
}

/// One output extrapolated from three grids.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Extrapolation {
    pub value: f64,
    pub order: Option<f64>,
    pub error: f64,
}

/// Richardson extrapolation of `values` on grids of `cells` per direction
/// (coarsest first): with h = 1/n, F(h) = F₀ − C h^p through the three
/// points when they converge monotonically at p ∈ [1, 2], else the finest
/// value.
pub(super) fn richardson(cells: [usize; 3], values: [f64; 3]) -> Extrapolation {
    let [f1, f2, f3] = values;
    let (d12, d23) = (f2 - f1, f3 - f2);
    let finest = Extrapolation {
        value: f3,
        order: None,
        error: d23.abs(),
    };
    if d12 == 0.0 || d23 == 0.0 || d12.signum() != d23.signum() {
        return finest;
    }
    let [h1, h2, h3] = cells.map(|n| 1.0 / n as f64);
    // (h1^p − h2^p)/(h2^p − h3^p) rises with p: bisect for the ratio.
    let ratio_at = |p: f64| (h1.powf(p) - h2.powf(p)) / (h2.powf(p) - h3.powf(p));
    let ratio = d12 / d23;
    let (mut lo, mut hi) = ORDERS;
    if !(ratio_at(lo)..=ratio_at(hi)).contains(&ratio) {
        return finest;
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if ratio_at(mid) < ratio {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let p = 0.5 * (lo + hi);
    let correction = d23 * h3.powf(p) / (h2.powf(p) - h3.powf(p));
    Extrapolation {
        value: f3 + correction,
        order: Some(p),
        error: correction.abs(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An unloaded contact gives zero forces, not a panic.
    #[test]
    fn no_load_gives_nothing() {
        let patch = ContactPatch {
            point: Vector3::zeros(),
            normal: Vector3::z(),
            rolling_direction: Vector3::x(),
            semi_major: 1e-3,
            semi_minor: 1e-4,
            load: 0.0,
            deformed_radius: f64::INFINITY,
        };
        let e = ExactRolling::new(0.1, 80e9, 0.3).solve_extrapolated(
            &patch,
            &Vector3::new(1e-3, 0.0, 0.0),
            &Vector3::zeros(),
            1.0,
        );
        assert_eq!(e.solution.result.force, Vector3::zeros());
        assert_eq!(e.force_error(), 0.0);
    }

    /// A power law is recovered exactly, its order too.
    #[test]
    fn recovers_a_power_law() {
        for p in [1.0, 1.3, 1.65, 2.0] {
            let f = |n: usize| 63.0 - 1000.0 * (n as f64).powf(-p);
            let e = richardson(EXTRAPOLATION_GRIDS, EXTRAPOLATION_GRIDS.map(f));
            assert!((e.value - 63.0).abs() < 1e-9, "p {p}: {e:?}");
            assert!((e.order.unwrap() - p).abs() < 1e-9, "p {p}: {e:?}");
            assert!((e.error - (63.0 - f(64))).abs() < 1e-9);
        }
    }

    /// Values that do not converge monotonically, or converge faster or
    /// slower than the accepted orders, keep the finest grid's value with
    /// the last change as the error.
    #[test]
    fn keeps_the_finest_value_outside_the_asymptotic_range() {
        let grids = EXTRAPOLATION_GRIDS;
        for values in [
            [148.39, 151.83, 151.08],
            [767.97, 767.06, 766.81],
            [10.0, 10.0, 10.0],
            [1.0, 1.9, 2.8],
        ] {
            let e = richardson(grids, values);
            assert_eq!(e.value, values[2], "{values:?}");
            assert_eq!(e.order, None);
            assert_eq!(e.error, (values[2] - values[1]).abs());
        }
    }
}
