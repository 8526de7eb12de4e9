//! A bearing's mounting (docs/dynamics.md, "Mounting"): the natural
//! frequencies `rolldyn check` reports, and a rule for the share of a
//! shaft the inner ring carries and the pedestal housing the outer ring
//! sits in. The presets and `rolldyn new --bearing` write the shaft share,
//! the held tilt, gravity and a housing sensor
//! (`crate::presets::MOUNTING_ASSUMPTIONS`); the pedestal is not yet
//! written into them (docs/dynamics.md says why).
//!
//! * **Shaft share.** The inner ring carries half of a solid steel shaft of
//!   the bore diameter d, 10 d long between two bearings (an assumption:
//!   a motor or test-rig shaft), with the ring itself (a steel annulus from
//!   the bore to the inner raceway, d_m − D_w).
//! * **Held tilt.** The shaft's other bearing, 10 d away, holds the ring's
//!   tilt: its radial stiffness times the span squared is hundreds of
//!   times a single bearing's own moment stiffness, so the ring's tilts
//!   are held at zero (`operating.fixed_tilt`). A free ring as heavy as a
//!   shaft share but with a ring's small tilt inertia flutters
//!   (docs/dynamics.md).
//! * **Pedestal.** Sawalhi & Randall (2008) model the housing of a 6205-size
//!   test bearing (9 balls of 7.94 mm on a 39.3 mm pitch circle) as a
//!   pedestal of mass m_p = 6.6 kg on stiffness k_p = 1.51e7 N/m with
//!   damping c_p = 2210.7 N·s/m: a first housing mode at 240 Hz with a
//!   damping ratio of 0.11 (values as their model is reproduced in public
//!   code; the mass is given as 5–6.6 kg there). Other sizes scale by
//!   geometric similarity with the outside diameter D against the 6205's
//!   52 mm: m_p ∝ D³, k_p ∝ D (a structure's stiffness scales with its
//!   length for one material), c_p ∝ D² (the same damping ratio), so the
//!   housing mode's frequency goes as 1/D. The outer ring (an annulus from
//!   d_m + D_w to D) moves with the pedestal.

use std::f64::consts::PI;

/// Reference outside diameter of the pedestal values (a 6205) \[m\].
pub const REFERENCE_OUTSIDE_DIAMETER: f64 = 0.052;
/// Sawalhi & Randall's (2008) pedestal mass \[kg\].
pub const PEDESTAL_MASS: f64 = 6.6;
/// Sawalhi & Randall's (2008) pedestal stiffness \[N/m\].
pub const PEDESTAL_STIFFNESS: f64 = 1.51e7;
/// Sawalhi & Randall's (2008) pedestal damping \[N·s/m\].
pub const PEDESTAL_DAMPING: f64 = 2210.7;
/// Shaft length between two bearings, in bore diameters (assumed).
pub const SHAFT_LENGTH_IN_BORES: f64 = 10.0;
/// Density of the steel shaft and rings \[kg/m³\].
pub const STEEL_DENSITY: f64 = 7850.0;

/// The mounting of one bearing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mounting {
    /// The inner ring alone \[kg\].
    pub inner_ring: f64,
    /// The share of the shaft the inner ring carries \[kg\].
    pub shaft_share: f64,
    /// The outer ring alone \[kg\].
    pub outer_ring: f64,
    /// The pedestal's moving mass \[kg\].
    pub pedestal: f64,
    /// The pedestal's stiffness per radial direction \[N/m\].
    pub housing_stiffness: f64,
    /// The pedestal's damping per radial direction \[N·s/m\].
    pub housing_damping: f64,
}

impl Mounting {
    /// The mounting of a bearing of bore `bore`, outside diameter
    /// `outside_diameter`, width `width`, pitch diameter `pitch_diameter`
    /// and ball diameter `ball_diameter` \[m\].
    pub fn by_rule(
        bore: f64,
        outside_diameter: f64,
        width: f64,
        pitch_diameter: f64,
        ball_diameter: f64,
    ) -> Self {
        let annulus = |inner: f64, outer: f64| {
            STEEL_DENSITY * 0.25 * PI * (outer * outer - inner * inner).max(0.0) * width
        };
        let scale = outside_diameter / REFERENCE_OUTSIDE_DIAMETER;
        Self {
            inner_ring: annulus(bore, pitch_diameter - ball_diameter),
            shaft_share: 0.5
                * STEEL_DENSITY
                * 0.25
                * PI
                * bore
                * bore
                * SHAFT_LENGTH_IN_BORES
                * bore,
            outer_ring: annulus(pitch_diameter + ball_diameter, outside_diameter),
            pedestal: PEDESTAL_MASS * scale.powi(3),
            housing_stiffness: PEDESTAL_STIFFNESS * scale,
            housing_damping: PEDESTAL_DAMPING * scale * scale,
        }
    }

    /// The inner ring with its shaft share \[kg\].
    pub fn inner_ring_mass(&self) -> f64 {
        self.inner_ring + self.shaft_share
    }

    /// The outer ring with the pedestal \[kg\].
    pub fn outer_ring_mass(&self) -> f64 {
        self.outer_ring + self.pedestal
    }
}

/// Frequency \[Hz\] and damping ratio of a mass `mass` \[kg\] on a spring
/// `stiffness` \[N/m\] with damper `damping` \[N·s/m\].
pub fn oscillator(mass: f64, stiffness: f64, damping: f64) -> (f64, f64) {
    let omega = (stiffness / mass).sqrt();
    (
        omega / (2.0 * PI),
        damping / (2.0 * (stiffness * mass).sqrt()),
    )
}

/// Natural frequencies \[Hz\] of the radial chain rotor–bearing–housing: the
/// inner ring with its shaft share `rotor` \[kg\] on the bearing's radial
/// stiffness `bearing` \[N/m\], the outer ring with the pedestal `housing`
/// \[kg\] on `housing_stiffness` \[N/m\] to ground; lower first.
pub fn chain_frequencies(
    rotor: f64,
    bearing: f64,
    housing: f64,
    housing_stiffness: f64,
) -> [f64; 2] {
    // det([k_b − ω² m_r, −k_b; −k_b, k_b + k_h − ω² m_h]) = 0.
    let a = rotor * housing;
    let b = -(bearing * housing + (bearing + housing_stiffness) * rotor);
    let c = bearing * housing_stiffness;
    let root = (b * b - 4.0 * a * c).max(0.0).sqrt();
    let low = (-b - root) / (2.0 * a);
    let high = (-b + root) / (2.0 * a);
    [low.max(0.0).sqrt() / (2.0 * PI), high.sqrt() / (2.0 * PI)]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The 6205 reference gives Sawalhi & Randall's pedestal: 240 Hz,
    /// damping ratio 0.11; a bearing twice as large halves the frequency
    /// and keeps the ratio.
    #[test]
    fn pedestal_scales_by_similarity() {
        let m = Mounting::by_rule(0.025, 0.052, 0.015, 0.0385, 0.0079375);
        let (f, zeta) = oscillator(m.pedestal, m.housing_stiffness, m.housing_damping);
        assert!((f - 240.7).abs() < 1.0, "{f}");
        assert!((zeta - 0.1106).abs() < 1e-3, "{zeta}");
        let big = Mounting::by_rule(0.05, 0.104, 0.03, 0.077, 0.016);
        let (f2, zeta2) = oscillator(big.pedestal, big.housing_stiffness, big.housing_damping);
        assert!((f2 / f - 0.5).abs() < 1e-12);
        assert!((zeta2 - zeta).abs() < 1e-12);
        // Half of a 25 mm shaft 250 mm long.
        assert!((m.shaft_share - 0.5 * 7850.0 * PI / 4.0 * 0.025f64.powi(2) * 0.25).abs() < 1e-12);
    }

    /// The chain's frequencies bracket each part's own and reduce to them
    /// when the parts decouple.
    #[test]
    fn chain_frequencies_decouple() {
        let [lo, hi] = chain_frequencies(1.0, 1e8, 10.0, 1e7);
        let (rotor, _) = oscillator(1.0, 1e8, 0.0);
        let (housing, _) = oscillator(11.0, 1e7, 0.0);
        assert!(lo < housing && hi > rotor);
        // A rigid housing: the rotor's own frequency.
        let [_, hi] = chain_frequencies(1.0, 1e8, 10.0, 1e14);
        assert!((hi / oscillator(10.0, 1e14, 0.0).0 - 1.0).abs() < 1e-3);
        let [lo, _] = chain_frequencies(1.0, 1e8, 10.0, 1e14);
        assert!((lo / rotor - 1.0).abs() < 1e-3);
    }
}
