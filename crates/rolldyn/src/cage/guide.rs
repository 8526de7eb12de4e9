//! Hydrodynamic guide land of a ring-guided cage (docs/model.md §5; Deng et al. 2022
//! eqs 30–35, short-bearing theory, with eq 32's R_d³ correction).

use crate::geometry::RingKind;
use nalgebra::Vector3;

/// A cage guide land (docs/model.md §5; Deng et al. 2022 eqs 30–35, short-bearing theory):
/// with eccentricity e of the cage centre from the guiding ring's centre,
/// ε = e/c, land radius R_d, width G, u₁ = R_d (ω_land + ω_c):
/// ```text
/// F_ζ = −η₀ |u₁| G³ ε² / (c² (1 − ε²)²)           along the eccentricity (restoring)
/// F_φ =  π η₀ u₁ G³ ε / (4 c² (1 − ε²)^{3/2})      perpendicular, with the rotation
/// M   =  2π η₀ R_d³ G (ω_land − ω_c) / (c √(1 − ε²))   drag torque on the cage
/// ```
/// Deng et al. 2022 eq 32 prints R_d to the first power; R_d³ makes it a torque
/// (docs/model.md §5). ε is capped at ε_max in these formulas; beyond ε_max c a
/// stiff stop k_s (e − ε_max c) acts (docs/model.md §5: "a stiff contact beyond
/// ε_max"). The guiding ring takes the reactions. c is the **radial**
/// clearance, half of the diametral guide clearance C_g of the case file.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GuideLand {
    /// Guiding ring (outer: fixed land; inner: land turning with ω_i).
    pub ring: RingKind,
    /// Land radius R_d \[m\].
    pub land_radius: f64,
    /// Land width G \[m\].
    pub width: f64,
    /// Radial clearance c \[m\].
    pub radial_clearance: f64,
    /// Lubricant viscosity η₀ \[Pa·s\].
    pub viscosity: f64,
    /// Largest eccentricity ratio of the hydrodynamic law ε_max (e.g. 0.95).
    pub max_eccentricity: f64,
    /// Stop stiffness beyond ε_max c \[N/m\].
    pub stop_stiffness: f64,
}

/// Forces of a guide land on the cage.
pub struct GuideForces {
    /// Force on the cage (radial plane) \[N\].
    pub force: Vector3<f64>,
    /// Torque on the cage about x \[N·m\].
    pub torque: f64,
    /// Penetration of the stop \[m\] (for the elastic energy).
    pub stop: f64,
}

impl GuideLand {
    /// Forces for cage centre offset `rel` from the ring centre (radial plane),
    /// cage speed ω_c and land speed ω_land.
    pub fn forces(&self, rel: &Vector3<f64>, cage_speed: f64, land_speed: f64) -> GuideForces {
        let c = self.radial_clearance;
        let e = rel.norm();
        let (g, eta, rd) = (self.width, self.viscosity, self.land_radius);
        let eps = (e / c).min(self.max_eccentricity);
        let u1 = rd * (land_speed + cage_speed);
        let torque = 2.0 * std::f64::consts::PI * eta * rd.powi(3) * g * (land_speed - cage_speed)
            / (c * (1.0 - eps * eps).sqrt());
        if e == 0.0 {
            return GuideForces {
                force: Vector3::zeros(),
                torque,
                stop: 0.0,
            };
        }
        let zeta = rel / e;
        let phi = Vector3::x().cross(&zeta);
        let one = 1.0 - eps * eps;
        let f_zeta = -eta * u1.abs() * g.powi(3) * eps * eps / (c * c * one * one);
        let f_phi =
            std::f64::consts::PI * eta * u1 * g.powi(3) * eps / (4.0 * c * c * one.powf(1.5));
        let stop = (e - self.max_eccentricity * c).max(0.0);
        GuideForces {
            force: (f_zeta - self.stop_stiffness * stop) * zeta + f_phi * phi,
            torque,
            stop,
        }
    }
}
