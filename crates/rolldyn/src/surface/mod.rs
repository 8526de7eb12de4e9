//! Surface profiles: waviness and localised defects on the raceways and
//! the balls (docs/model.md §6).
//!
//! A raceway carries radial waviness w_r(θ) and axial waviness w_a(θ)
//! (Deng et al. 2022 eq 1) and spalls, all in the ring's own frame: θ is the angle
//! of the contact point measured on the ring, so a rotating inner ring
//! carries its surface with it and Deng et al. 2022's relative frequencies
//! (ω_o − ω_c, ω_i − ω_c) appear by themselves. A ball carries waviness
//! H(ψ) and spalls in its spin angle ψ (docs/model.md §1's optional ball state);
//! its inner contact sees H(ψ), its outer contact H(ψ + π) (docs/model.md §6;
//! Deng et al. 2022 prints the phase as π/ω_b).
//!
//! # How the surface enters the contact
//! The surface moves raceway material by u at the contact point; with n the
//! contact normal (groove centre → ball centre) the approach grows by −n·u
//! (docs/model.md §2.1's δ = d − (r_g − D/2) + w). Positive radial waviness raises
//! the raceway towards the balls (outwards on the inner ring, inwards on the
//! outer ring), so it adds w_r |n·e_r|; positive axial waviness moves the
//! groove along +x and adds −w_a (n·x̂); a spall removes its drop. The
//! surface does not turn the contact normal (waviness slopes are
//! ~1e-4 rad); instead the contact force gets the generalised forces of
//! the changed approach, −Q ∂w/∂(coordinate), so the contact stays
//! conservative and the energy balance (B2) closes: on the ring surface a
//! tangential force pair at the ball centre's azimuth (on the ball
//! −Q w′/r e_t, on the ring the reaction), on a ball surface a moment
//! −Q H′ about its relative spin axis and the matching orbital force.
//! [`crate::dynamics`] does the coupling; this module evaluates heights and
//! slopes.

pub mod spall;
pub mod waviness;

pub use spall::{Edge, Spall, SpallSize};
pub use waviness::{RandomWaviness, Waviness, WavinessTerm};

use crate::error::InvalidParameter;
use std::f64::consts::PI;

/// Where a contact touches a raceway, in the ring's own frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RacePoint {
    /// Angle of the contact point on the ring θ \[rad\].
    pub angle: f64,
    /// Axial coordinate of the contact point from the groove's mid-plane \[m\].
    pub axial: f64,
    /// Distance of the contact point from the ring axis \[m\].
    pub track_radius: f64,
    /// |n·e_r|: share of a radial surface displacement along the normal.
    pub radial_projection: f64,
    /// −n·x̂: share of an axial surface displacement along the normal.
    pub axial_projection: f64,
    /// Equivalent radius of the contact in the rolling direction R_x \[m\].
    pub bridging_radius: f64,
}

/// Change of the approach by a surface: value \[m\] and its derivative
/// with respect to the surface angle (θ on a ring, ψ on a ball) \[m/rad\].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Approach {
    /// Δδ \[m\] (positive: more penetration).
    pub value: f64,
    /// ∂Δδ/∂angle \[m/rad\].
    pub slope: f64,
}

/// The surface of one raceway.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RaceSurface {
    /// Radial waviness (towards the balls positive).
    pub radial: Waviness,
    /// Axial waviness (along +x positive).
    pub axial: Waviness,
    /// Spalls.
    pub spalls: Vec<Spall>,
    /// RMS roughness R_q \[m\] (film parameter Λ; 0: not given).
    pub roughness: f64,
}

impl RaceSurface {
    /// Checks every part; the error's field names the part.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        self.radial.validate()?;
        self.axial.validate()?;
        for s in &self.spalls {
            s.validate()?;
        }
        crate::error::require_non_negative("roughness", self.roughness)
    }

    /// Whether the surface has no form (waviness, spalls) to evaluate;
    /// roughness does not enter the approach.
    pub fn is_smooth(&self) -> bool {
        self.radial.is_empty() && self.axial.is_empty() && self.spalls.is_empty()
    }

    /// Change of the approach at `point`.
    pub fn approach(&self, point: &RacePoint) -> Approach {
        let (wr, dwr) = self.radial.at(point.angle);
        let (wa, dwa) = self.axial.at(point.angle);
        let mut out = Approach {
            value: wr * point.radial_projection + wa * point.axial_projection,
            slope: dwr * point.radial_projection + dwa * point.axial_projection,
        };
        for s in &self.spalls {
            let (drop, d_drop) = s.drop(
                point.angle,
                point.axial,
                point.track_radius,
                point.bridging_radius,
            );
            out.value -= drop;
            out.slope -= d_drop;
        }
        out
    }
}

/// The surface of one ball, in its spin angle ψ.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct BallSurface {
    /// Waviness H(ψ) (outwards positive).
    pub waviness: Waviness,
    /// Spalls on the ball's rolling track.
    pub spalls: Vec<Spall>,
}

impl BallSurface {
    /// Checks every part.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        self.waviness.validate()?;
        for s in &self.spalls {
            s.validate()?;
        }
        Ok(())
    }

    /// Change of the approach at the ball's point ψ (the inner contact
    /// passes ψ, the outer ψ + π), for a ball of radius `radius` in a
    /// contact of equivalent rolling radius `bridging_radius`.
    pub fn approach(&self, psi: f64, radius: f64, bridging_radius: f64) -> Approach {
        let (h, dh) = self.waviness.at(psi);
        let mut out = Approach {
            value: h,
            slope: dh,
        };
        for s in &self.spalls {
            let (drop, d_drop) = s.drop(psi, s.axial_position, radius, bridging_radius);
            out.value -= drop;
            out.slope -= d_drop;
        }
        out
    }

    /// Whether the ball is perfectly smooth.
    pub fn is_smooth(&self) -> bool {
        self.waviness.is_empty() && self.spalls.is_empty()
    }
}

/// Angle between a ball's inner and outer contact points on its track (docs/model.md §6).
pub const BALL_CONTACT_SEPARATION: f64 = PI;

/// All surfaces of a bearing.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SurfaceModel {
    /// Inner raceway.
    pub inner: RaceSurface,
    /// Outer raceway.
    pub outer: RaceSurface,
    /// One surface per ball, or empty: smooth balls.
    pub balls: Vec<BallSurface>,
    /// RMS roughness R_q of the balls \[m\] (film parameter Λ; 0: not given).
    pub ball_roughness: f64,
}

impl SurfaceModel {
    /// Checks the parts and that there is one ball surface per ball (or none).
    pub fn validate(&self, ball_count: usize) -> Result<(), InvalidParameter> {
        self.inner.validate()?;
        self.outer.validate()?;
        if !self.balls.is_empty() && self.balls.len() != ball_count {
            return Err(InvalidParameter::new(
                "surface.balls",
                self.balls.len(),
                format!("needs one entry per ball ({ball_count}) or none"),
            ));
        }
        for b in &self.balls {
            b.validate()?;
        }
        crate::error::require_non_negative("ball_roughness", self.ball_roughness)
    }

    /// Composite roughness σ = √(R_q,ball² + R_q,race²) of a raceway's
    /// contacts \[m\] (0 when neither is given).
    pub fn composite_roughness(&self, ring: crate::geometry::RingKind) -> f64 {
        let race = match ring {
            crate::geometry::RingKind::Inner => &self.inner,
            crate::geometry::RingKind::Outer => &self.outer,
        };
        self.ball_roughness.hypot(race.roughness)
    }

    /// Whether the balls carry surfaces (the dynamic model then integrates
    /// each ball's spin angle ψ).
    pub fn has_ball_surfaces(&self) -> bool {
        self.balls.iter().any(|b| !b.is_smooth())
    }

    /// Every spall with where it sits.
    pub fn spalls(&self) -> impl Iterator<Item = (SpallSite, &Spall)> {
        let inner = self.inner.spalls.iter().map(|s| (SpallSite::Inner, s));
        let outer = self.outer.spalls.iter().map(|s| (SpallSite::Outer, s));
        let balls = self
            .balls
            .iter()
            .enumerate()
            .flat_map(|(j, b)| b.spalls.iter().map(move |s| (SpallSite::Ball(j), s)));
        inner.chain(outer).chain(balls)
    }
}

/// A spall that grows over a run ([`Spall::growth_rate`]): where it sits
/// (its site and its index among that surface's spalls), its length at
/// t = 0 \[m\] and its rate \[m/s\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GrowingSpall {
    /// Its surface.
    pub site: SpallSite,
    /// Its index among that surface's spalls.
    pub index: usize,
    /// Its length at t = 0 \[m\].
    pub initial_length: f64,
    /// Its growth rate \[m/s\].
    pub rate: f64,
}

impl SurfaceModel {
    /// The spalls with a growth rate (given by their length), in the order
    /// of [`Self::spalls`].
    pub fn growing_spalls(&self) -> Vec<GrowingSpall> {
        let mut out = Vec::new();
        let mut push = |site, spalls: &[Spall]| {
            for (index, s) in spalls.iter().enumerate() {
                if let (SpallSize::Length(length), true) = (s.size, s.growth_rate > 0.0) {
                    out.push(GrowingSpall {
                        site,
                        index,
                        initial_length: length,
                        rate: s.growth_rate,
                    });
                }
            }
        };
        push(SpallSite::Inner, &self.inner.spalls);
        push(SpallSite::Outer, &self.outer.spalls);
        for (j, ball) in self.balls.iter().enumerate() {
            push(SpallSite::Ball(j), &ball.spalls);
        }
        out
    }

    /// Spall `index` of the surface at `site`.
    pub fn spall_mut(&mut self, site: SpallSite, index: usize) -> &mut Spall {
        match site {
            SpallSite::Inner => &mut self.inner.spalls[index],
            SpallSite::Outer => &mut self.outer.spalls[index],
            SpallSite::Ball(j) => &mut self.balls[j].spalls[index],
        }
    }

    /// Spall `index` of the surface at `site`.
    pub fn spall(&self, site: SpallSite, index: usize) -> &Spall {
        match site {
            SpallSite::Inner => &self.inner.spalls[index],
            SpallSite::Outer => &self.outer.spalls[index],
            SpallSite::Ball(j) => &self.balls[j].spalls[index],
        }
    }
}

/// Where a spall sits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpallSite {
    /// Inner raceway.
    Inner,
    /// Outer raceway.
    Outer,
    /// Ball j.
    Ball(usize),
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn raceway_approach_projects_waviness_and_subtracts_spalls() {
        let surface = RaceSurface {
            radial: Waviness {
                terms: vec![WavinessTerm {
                    order: 2,
                    amplitude: 1e-6,
                    phase: 0.0,
                }],
            },
            axial: Waviness {
                terms: vec![WavinessTerm {
                    order: 1,
                    amplitude: 2e-6,
                    phase: 0.0,
                }],
            },
            spalls: vec![Spall {
                position: 0.0,
                size: SpallSize::Angle(0.2),
                depth: 1e-6,
                axial_position: 0.0,
                axial_width: None,
                edge: Edge::Sharp,
                growth_rate: 0.0,
            }],
            roughness: 0.1e-6,
        };
        let point = RacePoint {
            angle: 0.0,
            axial: 0.0,
            track_radius: 0.02,
            radial_projection: 0.9,
            axial_projection: -0.4,
            bridging_radius: 0.004,
        };
        let a = surface.approach(&point);
        assert!((a.value - (0.9e-6 - 0.8e-6 - 1e-6)).abs() < 1e-18);
        assert!(!surface.is_smooth());
        assert!(RaceSurface::default().is_smooth());
    }

    #[test]
    fn ball_surfaces_must_match_the_ball_count() {
        let model = SurfaceModel {
            balls: vec![BallSurface::default(); 3],
            ..SurfaceModel::default()
        };
        assert!(model.validate(3).is_ok());
        // Smooth ball surfaces (e.g. a roughness only) add no spin angle.
        assert!(!model.has_ball_surfaces());
        let rough = SurfaceModel {
            ball_roughness: 0.03e-6,
            outer: RaceSurface {
                roughness: 0.04e-6,
                ..RaceSurface::default()
            },
            ..SurfaceModel::default()
        };
        let sigma = rough.composite_roughness(crate::geometry::RingKind::Outer);
        assert!((sigma - 0.05e-6).abs() < 1e-20);
        assert_eq!(model.validate(4).unwrap_err().field, "surface.balls");
    }
}
