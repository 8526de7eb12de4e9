//! The cage (MODEL §5): ball–pocket contact laws and pocket shapes
//! ([`pocket`]), the hydrodynamic guide land ([`guide`]) and the cage data
//! the dynamic model needs, including a rotating unbalance.
//!
//! Sources: seed 001 (Gupta-type cage model: eqs 25–39), seed 002 (linear
//! pocket law, eq 6), corrected as MODEL §5 states.

pub mod guide;
pub mod pocket;

pub use guide::{GuideForces, GuideLand};
pub use pocket::{PocketLaw, PocketShape};

use crate::error::{InvalidParameter, require_non_negative, require_positive};
use crate::traction::ModifiedCoulomb;

/// Cage data of the dynamic model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CageParameters {
    /// Mass m_c \[kg\].
    pub mass: f64,
    /// Polar moment of inertia I_c \[kg·m²\].
    pub inertia: f64,
    /// Pocket-centre radius r_cp \[m\] (usually d_m/2).
    pub pitch_radius: f64,
    /// Diametral pocket clearance C_p \[m\] (C_p/2 per side).
    pub pocket_clearance: f64,
    /// Pocket shape.
    pub pocket_shape: PocketShape,
    /// Ball–pocket normal force law.
    pub pocket_law: PocketLaw,
    /// Pocket friction.
    pub pocket_friction: ModifiedCoulomb,
    /// Whether the cage centre may whirl (false: rotation only, seed 002).
    pub whirl: bool,
    /// Guide land, if the cage is ring-guided.
    pub guide: Option<GuideLand>,
    /// Unbalance m_u e \[kg·m\]: a mass m_u at radius e, at the cage angle
    /// θ_c (MODEL §5; seed 001 eqs 37–38).
    pub unbalance: f64,
}

impl CageParameters {
    /// Checks the cage data.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        require_positive("cage_mass", self.mass)?;
        require_positive("cage_inertia", self.inertia)?;
        require_positive("cage_pitch_radius", self.pitch_radius)?;
        require_positive("pocket_clearance", self.pocket_clearance)?;
        self.pocket_law.validate()?;
        self.pocket_friction.validate()?;
        require_non_negative("unbalance", self.unbalance)
    }

    /// Unbalance force on the cage (y, z) \[N\] at cage angle θ_c and speed
    /// ω_c: m_u e ω_c² along the unbalance direction (seed 001 eqs 37–38
    /// print ω_c unsquared; MODEL §5). Treated as an external force: its
    /// power enters the work of the external forces.
    pub fn unbalance_force(&self, angle: f64, speed: f64) -> [f64; 2] {
        let f = self.unbalance * speed * speed;
        [f * angle.cos(), f * angle.sin()]
    }
}
