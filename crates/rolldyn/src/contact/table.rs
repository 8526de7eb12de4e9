//! Precomputed Hertz constants per raceway over the contact angle
//! (MODEL §2.2, "Precomputed tables", after seed 002 §3.1).
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
    /// sphere-on-sphere curvature of seed 000 eq 12 (independent of α).
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

/// Hertz constants of one raceway tabulated over α ∈ [0, π/2].
#[derive(Debug, Clone, PartialEq)]
pub struct ContactTable {
    model: RacewayContactModel,
    ellipticity: UniformPchip,
    elliptic_k: UniformPchip,
    elliptic_e: UniformPchip,
    semi_major: UniformPchip,
    semi_minor: UniformPchip,
    approach: UniformPchip,
    stiffness: UniformPchip,
}

impl ContactTable {
    /// Builds the table with [`DEFAULT_TABLE_INTERVALS`].
    pub fn new(model: RacewayContactModel) -> Result<Self, InvalidParameter> {
        Self::with_intervals(model, DEFAULT_TABLE_INTERVALS)
    }

    /// Builds the table with `intervals` uniform intervals (≥ 2).
    pub fn with_intervals(
        model: RacewayContactModel,
        intervals: usize,
    ) -> Result<Self, InvalidParameter> {
        let intervals = intervals.max(2);
        let h = FRAC_PI_2 / intervals as f64;
        let nodes = (0..=intervals)
            .map(|i| model.coefficients(i as f64 * h))
            .collect::<Result<Vec<_>, _>>()?;
        let column = |f: fn(&HertzCoefficients) -> f64| {
            UniformPchip::new(0.0, h, nodes.iter().map(f).collect())
        };
        Ok(Self {
            model,
            ellipticity: column(|c| c.ellipticity),
            elliptic_k: column(|c| c.elliptic_k),
            elliptic_e: column(|c| c.elliptic_e),
            semi_major: column(|c| c.semi_major_coefficient),
            semi_minor: column(|c| c.semi_minor_coefficient),
            approach: column(|c| c.approach_coefficient),
            stiffness: column(|c| c.stiffness),
        })
    }

    /// The model the table was built from.
    pub fn model(&self) -> &RacewayContactModel {
        &self.model
    }

    /// Interpolated Hertz constants at contact angle α \[rad\] (clamped to
    /// [0, π/2]). Allocation-free.
    #[inline]
    pub fn at(&self, contact_angle: f64) -> HertzCoefficients {
        let a = contact_angle;
        HertzCoefficients {
            ellipticity: self.ellipticity.eval(a),
            elliptic_k: self.elliptic_k.eval(a),
            elliptic_e: self.elliptic_e.eval(a),
            semi_major_coefficient: self.semi_major.eval(a),
            semi_minor_coefficient: self.semi_minor.eval(a),
            approach_coefficient: self.approach.eval(a),
            stiffness: self.stiffness.eval(a),
        }
    }

    /// Interpolated K_c and its derivative dK_c/dα \[N/m^1.5 per rad\]
    /// (for analytic Jacobians).
    #[inline]
    pub fn stiffness_with_derivative(&self, contact_angle: f64) -> (f64, f64) {
        self.stiffness.eval_with_derivative(contact_angle)
    }

    /// Interpolated K_c only (the time loop's most frequent lookup).
    #[inline]
    pub fn stiffness(&self, contact_angle: f64) -> f64 {
        self.stiffness.eval(contact_angle)
    }
}
