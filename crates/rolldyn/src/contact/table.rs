//! Precomputed Hertz constants per raceway over the contact angle
//! (docs/model.md §2.2, "Precomputed tables", after Zhang et al. 2025 §3.1).
//!
//! κ, K_c, a*, b*, δ* and E(m) depend on a contact only through its
//! contact angle α (via γ = D cos α/d_m). Each raceway gets one table over
//! α ∈ [0°, 90°] on a uniform grid, interpolated by monotone cubics
//! ([`UniformPchip`]); the interpolated values match the exact solve to
//! 1e-6 relative (validation case A4), and a lookup is a handful of flops
//! with no elliptic integral and no allocation.

use super::hertz::{Curvature, HertzCoefficients, HertzModel};
use crate::error::InvalidParameter;
use crate::geometry::{BearingGeometry, Raceway, RingKind};
use crate::math::interp::UniformPchip;
use std::f64::consts::FRAC_PI_2;
use std::sync::{Arc, Mutex, PoisonError};

/// Everything that fixes the Hertz constants of one raceway as a function
/// of the contact angle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RacewayContactModel {
    /// The raceway.
    pub raceway: Raceway,
    /// Ball diameter D \[m\].
    pub ball_diameter: f64,
    /// Pitch diameter d_m \[m\].
    pub pitch_diameter: f64,
    /// Effective modulus E' of ball and ring materials \[Pa\].
    pub effective_modulus: f64,
    /// Stiffness model.
    pub model: HertzModel,
}

impl RacewayContactModel {
    /// The model of one ring's contact in a bearing.
    pub fn new(
        geometry: &BearingGeometry,
        ring: RingKind,
        effective_modulus: f64,
        model: HertzModel,
    ) -> Self {
        Self {
            raceway: *geometry.raceway(ring),
            ball_diameter: geometry.ball_diameter,
            pitch_diameter: geometry.pitch_diameter,
            effective_modulus,
            model,
        }
    }

    /// Relative curvature at contact angle α. For `hertz_circular` it is the
    /// sphere-on-sphere curvature of Shan et al. 2023 eq 12 (independent of α).
    pub fn curvature(&self, contact_angle: f64) -> Curvature {
        match self.model {
            HertzModel::HertzCircular => {
                let rb = self.ball_diameter / 2.0;
                let rl = self.raceway.groove_bottom_diameter / 2.0;
                let r_eff = match self.raceway.kind {
                    RingKind::Inner => rl * rb / (rl + rb),
                    RingKind::Outer => rl * rb / (rl - rb),
                };
                Curvature::circular(r_eff)
            }
            _ => Curvature::of_raceway(
                &self.raceway,
                self.ball_diameter,
                self.pitch_diameter,
                contact_angle,
            ),
        }
    }

    /// Hertz constants at contact angle α, computed directly (the slow path
    /// the table replaces).
    pub fn coefficients(&self, contact_angle: f64) -> Result<HertzCoefficients, InvalidParameter> {
        let c = self.curvature(contact_angle);
        match self.model {
            HertzModel::Exact => HertzCoefficients::exact(&c, self.effective_modulus),
            HertzModel::HamrockBrewe => {
                Ok(HertzCoefficients::hamrock_brewe(&c, self.effective_modulus))
            }
            HertzModel::HertzCircular => Ok(HertzCoefficients::circular(
                c.rolling_radius,
                self.effective_modulus,
            )),
        }
    }
}

/// Default number of table intervals over [0°, 90°] (0.05° spacing);
/// chosen by the A4 accuracy test (1e-6 relative with a wide margin).
pub const DEFAULT_TABLE_INTERVALS: usize = 1800;

/// How many tables the process keeps for [`ContactTable::with_intervals`]
/// (~0.2 MB each at the default size): the two raceways of a few
/// bearings.
const RECENT_TABLES: usize = 8;

/// The tables built last, oldest first.
static RECENT: Mutex<Vec<Arc<ContactTable>>> = Mutex::new(Vec::new());

/// Hertz constants of one raceway tabulated over α ∈ [0, π/2].
#[derive(Debug, Clone, PartialEq)]
pub struct ContactTable {
    model: RacewayContactModel,
    /// K_c(α) (its grid locates every lookup; its derivative for Jacobians).
    stiffness: UniformPchip,
    /// Every column of each node side by side (a lookup reads two nodes'
    /// cache lines, not fourteen columns'), in [`COLUMNS`] order.
    nodes: Vec<TableNode>,
    /// The constants when they do not depend on α (`hertz_circular`): a
    /// lookup returns them as computed, without interpolating.
    uniform: Option<HertzCoefficients>,
}

/// The columns of the table: κ, K(e), E(e), a*, b*, δ*, K_c.
const COLUMNS: [fn(&HertzCoefficients) -> f64; 7] = [
    |c| c.ellipticity,
    |c| c.elliptic_k,
    |c| c.elliptic_e,
    |c| c.semi_major_coefficient,
    |c| c.semi_minor_coefficient,
    |c| c.approach_coefficient,
    |c| c.stiffness,
];

/// One node of the table: each column's value and PCHIP slope times the
/// spacing.
#[derive(Debug, Clone, Copy, PartialEq)]
struct TableNode {
    value: [f64; 7],
    slope_h: [f64; 7],
}

impl ContactTable {
    /// Builds the table with [`DEFAULT_TABLE_INTERVALS`].
    pub fn new(model: RacewayContactModel) -> Result<Self, InvalidParameter> {
        Self::with_intervals(model, DEFAULT_TABLE_INTERVALS)
    }

    /// Builds the table with `intervals` uniform intervals (≥ 2), or copies
    /// it from the tables this process built last (`RECENT_TABLES`): a
    /// table depends on its model and interval count alone, and a run
    /// builds each raceway's for its quasi-static start and again for its
    /// dynamic model, a sweep or a notebook loop for every run.
    pub fn with_intervals(
        model: RacewayContactModel,
        intervals: usize,
    ) -> Result<Self, InvalidParameter> {
        let intervals = intervals.max(2);
        let mut recent = RECENT.lock().unwrap_or_else(PoisonError::into_inner);
        let same = |t: &Arc<ContactTable>| t.model == model && t.nodes.len() == intervals + 1;
        if let Some(table) = recent.iter().find(|t| same(t)) {
            return Ok(ContactTable::clone(table));
        }
        drop(recent);
        let table = Self::build(model, intervals)?;
        recent = RECENT.lock().unwrap_or_else(PoisonError::into_inner);
        if recent.len() == RECENT_TABLES {
            recent.remove(0);
        }
        recent.push(Arc::new(table.clone()));
        Ok(table)
    }

    /// Builds the table with `intervals` uniform intervals (≥ 2): the exact
    /// Hertz constants at each node, and their monotone cubics.
    fn build(model: RacewayContactModel, intervals: usize) -> Result<Self, InvalidParameter> {
        let h = FRAC_PI_2 / intervals as f64;
        let samples = (0..=intervals)
            .map(|i| model.coefficients(i as f64 * h))
            .collect::<Result<Vec<_>, _>>()?;
        let columns = COLUMNS.map(|f| UniformPchip::new(0.0, h, samples.iter().map(f).collect()));
        let nodes = (0..=intervals)
            .map(|i| {
                let mut node = TableNode {
                    value: [0.0; 7],
                    slope_h: [0.0; 7],
                };
                for (k, column) in columns.iter().enumerate() {
                    (node.value[k], node.slope_h[k]) = column.node(i);
                }
                node
            })
            .collect();
        let [.., stiffness] = columns;
        let uniform = match model.model {
            HertzModel::HertzCircular => Some(model.coefficients(0.0)?),
            HertzModel::Exact | HertzModel::HamrockBrewe => None,
        };
        Ok(Self {
            model,
            stiffness,
            nodes,
            uniform,
        })
    }

    /// The model the table was built from.
    pub fn model(&self) -> &RacewayContactModel {
        &self.model
    }

    /// Interpolated Hertz constants at contact angle α \[rad\] (clamped to
    /// [0, π/2]). Allocation-free; each column the same arithmetic as its
    /// own [`UniformPchip::eval`]. Constants independent of α are returned
    /// as computed.
    #[inline]
    pub fn at(&self, contact_angle: f64) -> HertzCoefficients {
        if let Some(uniform) = self.uniform {
            return uniform;
        }
        let cell = self.stiffness.locate(contact_angle);
        let (left, right) = (&self.nodes[cell.index()], &self.nodes[cell.index() + 1]);
        let v: [f64; 7] = std::array::from_fn(|k| {
            cell.combine(
                left.value[k],
                left.slope_h[k],
                right.value[k],
                right.slope_h[k],
            )
        });
        HertzCoefficients {
            ellipticity: v[0],
            elliptic_k: v[1],
            elliptic_e: v[2],
            semi_major_coefficient: v[3],
            semi_minor_coefficient: v[4],
            approach_coefficient: v[5],
            stiffness: v[6],
        }
    }

    /// Interpolated K_c and its derivative dK_c/dα \[N/m^1.5 per rad\]
    /// (for analytic Jacobians).
    #[inline]
    pub fn stiffness_with_derivative(&self, contact_angle: f64) -> (f64, f64) {
        match self.uniform {
            Some(uniform) => (uniform.stiffness, 0.0),
            None => self.stiffness.eval_with_derivative(contact_angle),
        }
    }

    /// Interpolated K_c only (the time loop's most frequent lookup).
    #[inline]
    pub fn stiffness(&self, contact_angle: f64) -> f64 {
        match self.uniform {
            Some(uniform) => uniform.stiffness,
            None => self.stiffness.eval(contact_angle),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::test_bearing;
    use crate::material::{Material, effective_modulus};

    fn model(ring: RingKind, law: HertzModel) -> RacewayContactModel {
        let ep = effective_modulus(&Material::STEEL_52100, &Material::STEEL_52100);
        RacewayContactModel::new(&test_bearing(22), ring, ep, law)
    }

    #[test]
    fn a_kept_table_is_the_one_a_build_gives() {
        for (intervals, modulus) in [(240, 1.0), (240, 1.01), (120, 1.0)] {
            let mut m = model(RingKind::Outer, HertzModel::Exact);
            m.effective_modulus *= modulus;
            let first = ContactTable::with_intervals(m, intervals).unwrap();
            let kept = ContactTable::with_intervals(m, intervals).unwrap();
            let built = ContactTable::build(m, intervals).unwrap();
            assert_eq!(first, built);
            assert_eq!(kept, built);
            assert_eq!(kept.nodes.len(), intervals + 1);
            assert_eq!(kept.model().effective_modulus, m.effective_modulus);
        }
    }

    #[test]
    fn circular_constants_are_returned_as_computed_at_every_angle() {
        for ring in [RingKind::Inner, RingKind::Outer] {
            let m = model(ring, HertzModel::HertzCircular);
            let table = ContactTable::new(m).unwrap();
            let direct = m.coefficients(0.0).unwrap();
            for angle in [0.0, 0.1234, 0.5, 1.2, FRAC_PI_2, -0.3] {
                assert_eq!(table.at(angle), direct);
                assert_eq!(table.stiffness(angle), direct.stiffness);
                assert_eq!(
                    table.stiffness_with_derivative(angle),
                    (direct.stiffness, 0.0)
                );
            }
        }
    }

    #[test]
    fn angle_dependent_constants_are_interpolated() {
        let m = model(RingKind::Inner, HertzModel::Exact);
        let table = ContactTable::new(m).unwrap();
        let (low, high) = (table.at(0.1), table.at(0.6));
        assert_ne!(low.stiffness, high.stiffness);
        let direct = m.coefficients(0.6).unwrap();
        assert!((high.stiffness / direct.stiffness - 1.0).abs() < 1e-6);
        assert!((high.semi_major_coefficient / direct.semi_major_coefficient - 1.0).abs() < 1e-6);
    }
}
