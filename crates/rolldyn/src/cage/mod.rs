//! The cage (docs/model.md §5): ball–pocket contact laws and pocket shapes
//! ([`pocket`]), the pocket oil film's squeeze damping ([`squeeze`]), the
//! hydrodynamic guide land ([`guide`]) and the cage data
//! the dynamic model needs, including a rotating unbalance.
//!
//! Sources: Deng et al. 2022 (Gupta-type cage model: eqs 25–39), Zhang et al. 2025 (linear
//! pocket law, eq 6), corrected as docs/model.md §5 states.

pub mod guide;
pub mod pocket;
pub mod squeeze;

pub use guide::{GuideForces, GuideLand};
pub use pocket::{PocketLaw, PocketShape};
pub use squeeze::{PocketSqueeze, SqueezeCavitation};

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
    /// Squeeze-film damping of the pocket oil film, if lubricated and
    /// asked for (a rolldyn extension; [`squeeze`]).
    pub pocket_squeeze: Option<PocketSqueeze>,
    /// Pocket friction.
    pub pocket_friction: ModifiedCoulomb,
    /// Whether the cage centre may whirl (false: rotation only, Zhang et al. 2025).
    pub whirl: bool,
    /// Guide land, if the cage is ring-guided.
    pub guide: Option<GuideLand>,
    /// Unbalance m_u e \[kg·m\]: a mass m_u at radius e, at the cage angle
    /// θ_c (docs/model.md §5; Deng et al. 2022 eqs 37–38).
    pub unbalance: f64,
}

impl CageParameters {
    /// A cage of `mass` \[kg\] and polar `inertia` \[kg·m²\] whose pockets
    /// sit at `pitch_radius` \[m\] with diametral `pocket_clearance` \[m\]
    /// and `pocket_law`; the rest at the case file's defaults
    /// (docs/case-format.md): cylindrical pockets without squeeze film,
    /// pocket friction μ = 0.05 (full at 1 mm/s), a whirling cage without
    /// guide land or unbalance. Change the rest with struct update syntax:
    /// `CageParameters { whirl: false, ..CageParameters::new(…) }`.
    pub fn new(
        mass: f64,
        inertia: f64,
        pitch_radius: f64,
        pocket_clearance: f64,
        pocket_law: PocketLaw,
    ) -> Self {
        Self {
            mass,
            inertia,
            pitch_radius,
            pocket_clearance,
            pocket_shape: PocketShape::Cylindrical,
            pocket_law,
            pocket_squeeze: None,
            pocket_friction: ModifiedCoulomb {
                friction: 0.05,
                stick_speed: 0.0,
                full_speed: 1e-3,
            },
            whirl: true,
            guide: None,
            unbalance: 0.0,
        }
    }

    /// How far the cage centre can move from the bearing's axis before it
    /// touches \[m\]: half the diametral pocket clearance (the balls
    /// hold a ball-guided cage), or the guide land's radial clearance when
    /// that is smaller.
    pub fn radial_freedom(&self) -> f64 {
        let pockets = 0.5 * self.pocket_clearance;
        self.guide
            .map_or(pockets, |guide| guide.radial_clearance.min(pockets))
    }

    /// Checks the cage data.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        require_positive("cage_mass", self.mass)?;
        require_positive("cage_inertia", self.inertia)?;
        require_positive("cage_pitch_radius", self.pitch_radius)?;
        require_positive("pocket_clearance", self.pocket_clearance)?;
        self.pocket_law.validate()?;
        if let Some(squeeze) = &self.pocket_squeeze {
            squeeze.validate()?;
            if squeeze.min_film >= 0.5 * self.pocket_clearance {
                return Err(InvalidParameter::new(
                    "pocket_min_film",
                    squeeze.min_film,
                    format!(
                        "must be less than the per-side pocket clearance C_p/2 = {} m",
                        0.5 * self.pocket_clearance
                    ),
                ));
            }
        }
        self.pocket_friction.validate()?;
        require_non_negative("unbalance", self.unbalance)
    }

    /// Highest natural frequency of the cage on undamped pocket springs
    /// \[Hz\], or None when every pocket spring is damped or acts only
    /// beyond the clearance. The `gupta_film` law's film term F_w d/(C_p/2)
    /// (Deng et al. 2022 eqs 26–28) is a spring with no damping inside the
    /// clearance (unless `pocket_squeeze` damps it), so the cage can
    /// rattle on the films of its `balls` pockets. With k = F_w/(C_p/2) per pocket and the balls held by their
    /// raceway traction:
    /// - rotation, √(Z k r_cp²/I_c)/2π;
    /// - whirl (if the centre is free), √(Z k/(2 m_c))/2π for cylindrical
    ///   pockets (the film acts along the pocket's circumferential offset
    ///   only), or √(Z k/m_c)/2π for spherical pockets.
    ///
    /// A stiff integrator that takes too few steps per period of this mode
    /// damps it numerically and can hide a rattle (docs/dynamics.md).
    pub fn film_frequency(&self, balls: usize) -> Option<f64> {
        let PocketLaw::GuptaFilm { wall_force, .. } = self.pocket_law else {
            return None;
        };
        let stiffness = balls as f64 * wall_force / (0.5 * self.pocket_clearance);
        if stiffness <= 0.0 {
            return None;
        }
        let rotation = stiffness * self.pitch_radius.powi(2) / self.inertia;
        let whirl = if !self.whirl {
            0.0
        } else {
            match self.pocket_shape {
                PocketShape::Cylindrical => 0.5 * stiffness / self.mass,
                PocketShape::Spherical => stiffness / self.mass,
            }
        };
        Some(rotation.max(whirl).sqrt() / std::f64::consts::TAU)
    }

    /// Unbalance force on the cage (y, z) \[N\] at cage angle θ_c and speed
    /// ω_c: m_u e ω_c² along the unbalance direction (Deng et al. 2022 eqs 37–38
    /// print ω_c unsquared; docs/model.md §5). Treated as an external force: its
    /// power enters the work of the external forces.
    pub fn unbalance_force(&self, angle: f64, speed: f64) -> [f64; 2] {
        let f = self.unbalance * speed * speed;
        [f * angle.cos(), f * angle.sin()]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cage(pocket_law: PocketLaw, pocket_shape: PocketShape, whirl: bool) -> CageParameters {
        CageParameters {
            mass: 3.1e-3,
            inertia: 2.4e-6,
            pitch_radius: 0.027,
            pocket_clearance: 0.175e-3,
            pocket_shape,
            pocket_law,
            pocket_squeeze: None,
            pocket_friction: ModifiedCoulomb {
                friction: 0.1,
                stick_speed: 0.0,
                full_speed: 1e-3,
            },
            whirl,
            guide: None,
            unbalance: 0.0,
        }
    }

    /// The cage with stiff linear cylindrical pockets, free to whirl.
    fn linear_pockets() -> CageParameters {
        let linear = PocketLaw::Linear {
            stiffness: 1e7,
            damping: 0.0,
        };
        cage(linear, PocketShape::Cylindrical, true)
    }

    /// A ball-guided cage moves half its pocket clearance; a land-guided
    /// one the land's radial clearance, or the pockets' when they hold it
    /// first.
    #[test]
    fn radial_freedom_is_the_nearest_stop() {
        let mut c = linear_pockets();
        assert_eq!(c.radial_freedom(), 0.5 * 0.175e-3);
        let mut land = crate::testing::guide_land_7008c();
        land.radial_clearance = 50e-6;
        c.guide = Some(land);
        assert_eq!(c.radial_freedom(), 50e-6);
        land.radial_clearance = 175e-6;
        c.guide = Some(land);
        assert_eq!(c.radial_freedom(), 0.5 * 0.175e-3);
    }

    /// The 7008C's 22 film pockets (F_w = 11 N, C_p = 0.175 mm):
    /// k = 11 N / 87.5 µm per pocket; rotation √(22 k r²/I)/2π = 4.61 kHz
    /// is above the whirl √(11 k/m)/2π = 3.36 kHz, the spherical pockets'
    /// whirl √(22 k/m)/2π = 4.75 kHz above both.
    #[test]
    fn squeeze_film_thinner_than_the_clearance() {
        let mut c = linear_pockets();
        c.pocket_squeeze = Some(PocketSqueeze {
            viscosity: 0.02,
            ball_radius: 4e-3,
            min_film: 1e-6,
            cavitation: SqueezeCavitation::HalfSommerfeld,
            tension: squeeze::DEFAULT_POCKET_TENSION,
        });
        c.validate().unwrap();
        c.pocket_squeeze.as_mut().unwrap().min_film = 0.0875e-3;
        let e = c.validate().unwrap_err();
        assert_eq!(e.field, "pocket_min_film");
        assert!(e.rule.contains("per-side pocket clearance"), "{}", e.rule);
    }

    #[test]
    fn film_frequency_of_the_7008c_cage() {
        let film = PocketLaw::GuptaFilm {
            wall_force: 11.0,
            stiffness: 1e9,
            damping: 0.0,
        };
        let k = 11.0 / 87.5e-6;
        let hz = |x: f64| x.sqrt() / std::f64::consts::TAU;
        let rotation = hz(22.0 * k * 0.027f64.powi(2) / 2.4e-6);
        let f = cage(film, PocketShape::Cylindrical, true)
            .film_frequency(22)
            .unwrap();
        assert!(
            (f - rotation).abs() < 1e-9 * rotation && (f - 4610.0).abs() < 10.0,
            "{f}"
        );
        let f = cage(film, PocketShape::Spherical, true)
            .film_frequency(22)
            .unwrap();
        assert!((f - hz(22.0 * k / 3.1e-3)).abs() < 1e-9 * f, "{f}");
        let f = cage(film, PocketShape::Spherical, false)
            .film_frequency(22)
            .unwrap();
        assert!((f - rotation).abs() < 1e-9 * f, "{f}");
        let linear = PocketLaw::Linear {
            stiffness: 1e7,
            damping: 20.0,
        };
        assert_eq!(
            cage(linear, PocketShape::Cylindrical, true).film_frequency(22),
            None
        );
    }
}
