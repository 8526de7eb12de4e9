//! Basic reference rating life L_10r of ISO/TS 16281:2008 for single-row
//! radial ball bearings: the Lundberg–Palmgren life of each raceway from
//! the actual ball loads of a quasi-static solution (clearance,
//! misalignment, combined load and speed included), not from Stribeck's
//! assumed distribution.
//!
//! ```text
//! Q_ci = C_r/(0.407 Z cos α i^0.7) · [1 + (1.044 ((1−γ)/(1+γ))^1.72 (f_i(2f_e−1)/(f_e(2f_i−1)))^0.41)^(10/3)]^0.3
//! Q_ce = C_r/(0.389 Z cos α i^0.7) · [1 + (1.044 ((1−γ)/(1+γ))^1.72 (f_i(2f_e−1)/(f_e(2f_i−1)))^0.41)^(−10/3)]^0.3
//! Q_e  = (Σ Q_j³/Z)^(1/3)           ring rotating relative to the load
//! Q_e  = (Σ Q_j^(10/3)/Z)^(3/10)    ring stationary relative to the load
//! L_10r = [(Q_ci/Q_ei)^(−10/3) + (Q_ce/Q_ee)^(−10/3)]^(−9/10)   [10⁶ rev]
//! P_ref = C_r / L_10r^(1/3)
//! ```
//! γ = D_w cos α/D_pw and α the nominal contact angle, as in C_r (the
//! capacities Q_c depend on α only through γ); f = r/D_w the groove
//! curvatures. The constants 0.407 and 0.389 are J_r/J_1 and J_r/J_2 of the
//! half-loaded zone (ε = 0.5) and 1.044 their ratio, so a continuous
//! Stribeck distribution (zero clearance, pure radial load) gives
//! L_10r = (C_r/F_r)³ exactly: the ISO 281 result (unit test). The inner
//! ring turns and the load is fixed in space (rolldyn's rotating inner
//! ring); each raceway takes its own ball loads, so at speed the outer ring
//! carries the centrifugal force.

use crate::geometry::BearingGeometry;

/// J_r/J_1 of ISO/TS 16281 (rotating ring).
const ROTATING: f64 = 0.407;
/// J_r/J_2 of ISO/TS 16281 (stationary ring).
const STATIONARY: f64 = 0.389;
/// Ratio of the two, rounded as in the standard.
const RATIO: f64 = 1.044;

/// Ball loads for the basic dynamic load rating of each raceway.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactCapacities {
    /// Q_ci \[N\].
    pub inner: f64,
    /// Q_ce \[N\].
    pub outer: f64,
}

/// Q_ci, Q_ce of a single-row bearing of basic dynamic radial rating C_r
/// \[N\] (ISO 281, at the nominal contact angle).
pub fn contact_capacities(geometry: &BearingGeometry, dynamic_rating: f64) -> ContactCapacities {
    let alpha = geometry.nominal_contact_angle();
    let gamma = geometry.gamma(alpha);
    let (fi, fe) = (
        geometry.inner.groove_curvature,
        geometry.outer.groove_curvature,
    );
    let conformity = (fi * (2.0 * fe - 1.0) / (fe * (2.0 * fi - 1.0))).powf(0.41);
    let x = RATIO * ((1.0 - gamma) / (1.0 + gamma)).powf(1.72) * conformity;
    let base = dynamic_rating / (geometry.ball_count as f64 * alpha.cos());
    ContactCapacities {
        inner: base / ROTATING * (1.0 + x.powf(10.0 / 3.0)).powf(0.3),
        outer: base / STATIONARY * (1.0 + x.powf(-10.0 / 3.0)).powf(0.3),
    }
}

/// Dynamic equivalent ball load Q_e \[N\] of a raceway carrying `loads`
/// (one per ball): rotating relative to the load or not.
pub fn equivalent_ball_load(loads: &[f64], rotating: bool) -> f64 {
    let w = if rotating { 3.0 } else { 10.0 / 3.0 };
    let mean = loads.iter().map(|q| q.max(0.0).powf(w)).sum::<f64>() / loads.len() as f64;
    mean.powf(1.0 / w)
}

/// L_10r \[10⁶ revolutions\] of a bearing whose inner ring turns under a
/// load fixed in space: ball loads on the inner and outer raceways \[N\].
/// Infinite when no ball is loaded.
pub fn reference_rating_life(
    capacities: ContactCapacities,
    inner_loads: &[f64],
    outer_loads: &[f64],
) -> f64 {
    let inner = (capacities.inner / equivalent_ball_load(inner_loads, true)).powf(-10.0 / 3.0);
    let outer = (capacities.outer / equivalent_ball_load(outer_loads, false)).powf(-10.0 / 3.0);
    (inner + outer).powf(-0.9)
}

/// Dynamic equivalent reference load P_ref = C_r/L_10r^(1/3) \[N\].
pub fn reference_equivalent_load(dynamic_rating: f64, reference_life: f64) -> f64 {
    dynamic_rating / reference_life.cbrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{Clearance, GeometrySpec};
    use crate::life::iso281::BallSet;

    /// A continuous Stribeck distribution (zero clearance, pure radial
    /// load, Q(ψ) = Q_max cos^1.5 ψ over the half circle; here 20 000 balls
    /// as quadrature) gives L_10r = (C_r/F_r)³, the ISO 281 life: the
    /// standard's constants are the half-zone Sjövall integrals rounded to
    /// three figures, so 0.5 %.
    #[test]
    fn stribeck_distribution_gives_the_iso_281_life() {
        let geometry = BearingGeometry::new(&GeometrySpec {
            ball_diameter: 7.94e-3,
            ball_count: 9,
            pitch_diameter: 39e-3,
            inner_groove_curvature: 0.52,
            outer_groove_curvature: 0.53,
            clearance: Clearance::Diametral(0.0),
            preload: false,
        })
        .unwrap();
        let c = BallSet::of(&geometry).dynamic_load_rating().unwrap();
        // Q_c of the continuous ring: the 9-ball capacities scaled to Z.
        let z = 20_000;
        let caps9 = contact_capacities(&geometry, c);
        let caps = ContactCapacities {
            inner: caps9.inner * 9.0 / z as f64,
            outer: caps9.outer * 9.0 / z as f64,
        };
        let q_max = 1.0;
        let loads: Vec<f64> = (0..z)
            .map(|j| {
                let psi = 2.0 * std::f64::consts::PI * (j as f64 + 0.5) / z as f64;
                q_max * psi.cos().max(0.0).powf(1.5)
            })
            .collect();
        let fr: f64 = (0..z)
            .map(|j| {
                let psi = 2.0 * std::f64::consts::PI * (j as f64 + 0.5) / z as f64;
                loads[j] * psi.cos()
            })
            .sum();
        let l10r = reference_rating_life(caps, &loads, &loads);
        let l10 = (c / fr).powi(3);
        assert!((l10r / l10 - 1.0).abs() < 5e-3, "{l10r} vs {l10}");
        let p_ref = reference_equivalent_load(c, l10r);
        assert!((p_ref / fr - 1.0).abs() < 2e-3);
    }

    #[test]
    fn equivalent_loads() {
        assert_eq!(equivalent_ball_load(&[2.0, 2.0], true), 2.0);
        let q = equivalent_ball_load(&[1.0, 0.0], false);
        assert!((q - 0.5f64.powf(0.3)).abs() < 1e-15);
        assert!(equivalent_ball_load(&[1.0, 0.0], true) < q);
    }
}
