//! Rating life of a single-row radial ball bearing (
//! docs/quasistatic.md, "Rating life").
//!
//! * [`iso281`] — basic dynamic load rating C_r from the ball set, the
//!   dynamic equivalent load (Table 3 X, Y) and the basic rating life
//!   L_10 = (C_r/P_r)³ by ISO 281:2007;
//! * [`iso76`] — basic static load rating C_0r (ISO 76: 4 200 MPa) and the
//!   fatigue load limit C_u;
//! * [`modified`] — the life modification factor a_ISO from the viscosity
//!   ratio κ, the contamination factor e_C and C_u/P (ISO 281 §9.3);
//! * [`mod@reference`] — ISO/TS 16281's basic reference rating life L_10r from
//!   the actual ball loads of a quasi-static solution.
//!
//! [`RatingLife::new`] gathers them for one operating point. All ratings
//! are those of the all-steel bearing of the geometry, as the standards
//! define them; for a hybrid bearing (ceramic balls) the modified lives
//! are not given (ISO/TS 16281 excludes hybrids; ISO 20056 rates them).
//! Reliability 90 % (a_1 = 1).

pub mod iso281;
pub mod iso76;
pub mod modified;
pub mod reference;

use crate::geometry::BearingGeometry;
use iso281::BallSet;

/// What the modified lives need beyond the loads.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LifeConditions {
    /// Contamination factor e_C ∈ \[0, 1\] (ISO 281 Table 13); None: the
    /// modified lives are not computed.
    pub contamination_factor: Option<f64>,
    /// Operating kinematic viscosity ν \[m²/s\] of the lubricant, if known.
    pub kinematic_viscosity: Option<f64>,
    /// Viscosity ratio κ given directly (instead of ν/ν₁).
    pub viscosity_ratio: Option<f64>,
    /// Ceramic balls: ISO 281 and ISO/TS 16281 give no modified life.
    pub hybrid: bool,
}

/// Ball loads of a solved operating point, one per ball \[N\].
#[derive(Debug, Clone, Copy)]
pub struct BallLoads<'a> {
    /// Inner-raceway contact loads.
    pub inner: &'a [f64],
    /// Outer-raceway contact loads.
    pub outer: &'a [f64],
}

/// The ratings and lives of one operating point; None where a standard
/// does not cover the case or a life is infinite.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RatingLife {
    /// Basic dynamic radial load rating C_r \[N\].
    pub dynamic_load_rating: Option<f64>,
    /// Basic static radial load rating C_0r \[N\].
    pub static_load_rating: Option<f64>,
    /// Fatigue load limit C_u \[N\].
    pub fatigue_load_limit: Option<f64>,
    /// Dynamic equivalent radial load P_r \[N\].
    pub equivalent_load: Option<f64>,
    /// Basic rating life L_10 \[10⁶ revolutions\].
    pub basic_rating_life: Option<f64>,
    /// Reference kinematic viscosity ν₁ \[m²/s\].
    pub reference_viscosity: Option<f64>,
    /// Viscosity ratio κ.
    pub viscosity_ratio: Option<f64>,
    /// a_ISO at P_r.
    pub life_modification_factor: Option<f64>,
    /// Modified rating life L_10m = a_ISO L_10 \[10⁶ revolutions\].
    pub modified_rating_life: Option<f64>,
    /// ISO/TS 16281 basic reference rating life L_10r \[10⁶ revolutions\].
    pub reference_rating_life: Option<f64>,
    /// Dynamic equivalent reference load P_ref = C_r/L_10r^(1/3) \[N\].
    pub reference_equivalent_load: Option<f64>,
    /// a_ISO at P_ref.
    pub reference_life_modification_factor: Option<f64>,
    /// Modified reference rating life L_10mr = a_ISO L_10r \[10⁶ revolutions\].
    pub modified_reference_rating_life: Option<f64>,
}

impl RatingLife {
    /// Ratings and lives of `geometry` under radial load F_r and axial
    /// load F_a \[N\] at shaft speed n \[r/min\]; the reference life from
    /// `balls` where a solution is given.
    pub fn new(
        geometry: &BearingGeometry,
        radial: f64,
        axial: f64,
        speed_rpm: f64,
        balls: Option<BallLoads>,
        conditions: &LifeConditions,
    ) -> Self {
        let finite = |v: f64| v.is_finite().then_some(v);
        let set = BallSet::of(geometry);
        let c = set.dynamic_load_rating().ok();
        let c0 = iso76::static_load_rating(geometry).ok();
        let cu = c0.map(|c0| iso76::fatigue_load_limit(c0, geometry.pitch_diameter));
        let p = set.equivalent_load(radial, axial).filter(|p| *p > 0.0);
        let l10 = c
            .zip(p)
            .and_then(|(c, p)| finite(iso281::basic_rating_life(c, p)));
        let reference_viscosity = (speed_rpm != 0.0)
            .then(|| modified::reference_viscosity(speed_rpm, geometry.pitch_diameter));
        let viscosity_ratio = conditions.viscosity_ratio.or_else(|| {
            conditions
                .kinematic_viscosity
                .zip(reference_viscosity)
                .map(|(nu, nu1)| nu / nu1)
        });
        let factor = |load: Option<f64>| {
            if conditions.hybrid {
                return None;
            }
            let (e_c, kappa, cu, load) = (
                conditions.contamination_factor?,
                viscosity_ratio?,
                cu?,
                load?,
            );
            modified::life_modification_factor(kappa, e_c * cu / load)
        };
        let l10r = c.zip(balls).and_then(|(c, b)| {
            finite(reference::reference_rating_life(
                reference::contact_capacities(geometry, c),
                b.inner,
                b.outer,
            ))
        });
        let p_ref = c
            .zip(l10r)
            .map(|(c, l)| reference::reference_equivalent_load(c, l));
        let a_iso = factor(p);
        let a_iso_ref = factor(p_ref);
        Self {
            dynamic_load_rating: c,
            static_load_rating: c0,
            fatigue_load_limit: cu,
            equivalent_load: p,
            basic_rating_life: l10,
            reference_viscosity,
            viscosity_ratio,
            life_modification_factor: a_iso,
            modified_rating_life: a_iso.zip(l10).map(|(a, l)| a * l),
            reference_rating_life: l10r,
            reference_equivalent_load: p_ref,
            reference_life_modification_factor: a_iso_ref,
            modified_reference_rating_life: a_iso_ref.zip(l10r).map(|(a, l)| a * l),
        }
    }
}

/// A life in 10⁶ revolutions as hours at shaft speed n \[r/min\]; None at
/// standstill or when infinite.
pub fn hours(life: Option<f64>, speed_rpm: f64) -> Option<f64> {
    life.filter(|_| speed_rpm != 0.0)
        .map(|l| l * 1e6 / (speed_rpm.abs() * 60.0))
        .filter(|h| h.is_finite())
}
