//! Localised defects (spalls) on a raceway or a ball (docs/model.md §6, beyond the
//! source papers).
//!
//! A spall is a pit of depth d and length L along the rolling track
//! (given as an angle or as a length), optionally limited across the track
//! to an axial band. The ball cannot follow the pit floor: over a pit
//! shorter than the contact's rolling curvature allows, the two bodies
//! bridge the gap. With a the distance to the nearer edge and R_x the
//! contact's equivalent radius in the rolling direction, the approach lost
//! is at most the gap a²/(2R_x) of the two surfaces at that distance
//! (the ball path through a spall of Sawalhi & Randall 2008, MSSP 22,
//! 1924–1951, written with the parabolic gap of the two surfaces):
//!
//! ```text
//! sharp edge:   drop(a) = min(d, a²/(2R_x))
//! ramped edge:  drop(a) = min(d · min(1, a/ℓ), a²/(2R_x))       (ℓ: ramp length)
//! ```
//!
//! The drop is continuous (C¹ at the edges, where a²/(2R_x) starts with zero
//! slope), so an adaptive integrator sees entry and exit; the engine also
//! limits the step near a defect (see `BearingModel::step_limit`).
//!
//! Limits: the surface is sampled at the contact centre (the load is not
//! shared between the pit edges and the floor); the tilt of the contact
//! normal on the pit walls enters through the slope force only; a spall's
//! axial band has sharp sides.

use super::waviness::positive;
use crate::error::InvalidParameter;
use std::f64::consts::{PI, TAU};

/// Length of a spall along the rolling track.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SpallSize {
    /// Angular width on the ring (or ball) \[rad\].
    Angle(f64),
    /// Arc length along the track \[m\].
    Length(f64),
}

/// Edge shape.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Edge {
    /// A sharp step (the ball bridges it: drop = min(d, a²/2R_x)).
    Sharp,
    /// A linear ramp of the given length \[m\] from the edge to full depth.
    Ramped {
        /// Ramp length ℓ \[m\].
        length: f64,
    },
}

/// Largest spall growth rate \[m/s\] (10 mm/s). The pit grows between
/// ball passes, while no ball is on it (docs/dynamics.md, "Spall
/// growth"); at a ball pass every millisecond, a faster pit would lengthen
/// by more than 10 µm a pass, a tenth of a small pit, and the steps taken
/// while no ball is on it could not keep up with the rate asked.
pub const MAX_GROWTH_RATE: f64 = 0.01;

/// A spall.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spall {
    /// Angle of the spall centre on the ring, in the ring's own frame
    /// (measured from +y towards +z at zero ring angle), or on the ball
    /// (spin angle ψ) \[rad\].
    pub position: f64,
    /// Length along the track.
    pub size: SpallSize,
    /// Depth d \[m\].
    pub depth: f64,
    /// Centre of the axial band, from the groove's mid-plane along +x \[m\]
    /// (raceways only).
    pub axial_position: f64,
    /// Width of the axial band \[m\]; None: the whole groove.
    pub axial_width: Option<f64>,
    /// Edge shape.
    pub edge: Edge,
    /// Growth of the length along the track per second of simulated time
    /// \[m/s\] (0: a constant spall; needs a length, not a width). The
    /// dynamic model lengthens the spall about its centre in steps taken
    /// while no ball is on it (`dynamics`, "spall growth").
    pub growth_rate: f64,
}

impl Spall {
    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        if !self.position.is_finite() {
            return Err(InvalidParameter::new(
                "position",
                self.position,
                "must be finite",
            ));
        }
        match self.size {
            SpallSize::Angle(a) => {
                if !(a > 0.0 && a < PI) {
                    return Err(InvalidParameter::new(
                        "width",
                        format!("{a} rad"),
                        "must lie in (0, 180°)",
                    ));
                }
            }
            SpallSize::Length(l) => positive("length", l)?,
        }
        positive("depth", self.depth)?;
        if !self.axial_position.is_finite() {
            return Err(InvalidParameter::new(
                "axial_position",
                self.axial_position,
                "must be finite",
            ));
        }
        if let Some(w) = self.axial_width {
            positive("axial_width", w)?;
        }
        if let Edge::Ramped { length } = self.edge {
            positive("ramp", length)?;
        }
        if !(0.0..=MAX_GROWTH_RATE).contains(&self.growth_rate) {
            return Err(InvalidParameter::new(
                "growth_rate",
                self.growth_rate,
                "must lie in [0, 0.01] m/s (10 mm/s: a pit that grows faster outruns the balls, which must leave it for it to grow; run-to-failure trends are compressed in time, not made faster than the passes)",
            ));
        }
        if self.growth_rate > 0.0 && matches!(self.size, SpallSize::Angle(_)) {
            return Err(InvalidParameter::new(
                "growth_rate",
                self.growth_rate,
                "a growing spall needs its length (not its width)",
            ));
        }
        Ok(())
    }

    /// Half its angular width on a track of radius `track_radius` \[rad\].
    pub fn half_angle(&self, track_radius: f64) -> f64 {
        match self.size {
            SpallSize::Angle(a) => 0.5 * a,
            SpallSize::Length(l) => (0.5 * l / track_radius).min(0.5 * PI),
        }
    }

    /// Loss of approach (≥ 0) \[m\] and its derivative with respect to the
    /// track angle \[m/rad\] at `angle` on a track of radius
    /// `track_radius`, at axial coordinate `axial` (raceways; pass
    /// `self.axial_position` for balls), for a contact of equivalent
    /// rolling radius `bridging_radius` (R_x).
    pub fn drop(
        &self,
        angle: f64,
        axial: f64,
        track_radius: f64,
        bridging_radius: f64,
    ) -> (f64, f64) {
        if let Some(w) = self.axial_width {
            if (axial - self.axial_position).abs() > 0.5 * w {
                return (0.0, 0.0);
            }
        }
        let offset = wrap(angle - self.position);
        let half = self.half_angle(track_radius);
        if offset.abs() >= half {
            return (0.0, 0.0);
        }
        // Distance to the nearer edge along the track, and its derivative
        // with respect to the angle.
        let edge_distance = track_radius * (half - offset.abs());
        let d_edge = -track_radius * offset.signum();
        let bridge = edge_distance * edge_distance / (2.0 * bridging_radius);
        let d_bridge = edge_distance / bridging_radius;
        let (floor, d_floor) = match self.edge {
            Edge::Sharp => (self.depth, 0.0),
            Edge::Ramped { length } if edge_distance < length => {
                (self.depth * edge_distance / length, self.depth / length)
            }
            Edge::Ramped { .. } => (self.depth, 0.0),
        };
        if bridge < floor {
            (bridge, d_bridge * d_edge)
        } else {
            (floor, d_floor * d_edge)
        }
    }
}

/// The angle wrapped into (−π, π].
pub fn wrap(angle: f64) -> f64 {
    let a = angle.rem_euclid(TAU);
    if a > PI { a - TAU } else { a }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spall(edge: Edge) -> Spall {
        Spall {
            position: 1.0,
            size: SpallSize::Length(1e-3),
            depth: 5e-6,
            axial_position: 0.0,
            axial_width: Some(2e-3),
            edge,
            growth_rate: 0.0,
        }
    }

    #[test]
    fn the_ball_bridges_a_sharp_pit_and_reaches_its_floor_in_the_middle() {
        let (track, rx) = (0.03, 0.004);
        let s = spall(Edge::Sharp);
        assert_eq!(
            s.drop(1.0 + 0.5e-3 / track * 1.01, 0.0, track, rx),
            (0.0, 0.0)
        );
        // At the centre a = 0.5 mm: a²/2R = 31 µm > 5 µm: full depth.
        assert!((s.drop(1.0, 0.0, track, rx).0 - 5e-6).abs() < 1e-18);
        // 0.05 mm inside the edge: a²/2R = 0.31 µm, the bridge.
        let inside = 1.0 + (0.5e-3 - 0.05e-3) / track;
        let (d, slope) = s.drop(inside, 0.0, track, rx);
        assert!((d - 0.05e-3f64.powi(2) / (2.0 * rx)).abs() < 1e-15);
        let h = 1e-9;
        let fd = (s.drop(inside + h, 0.0, track, rx).0 - s.drop(inside - h, 0.0, track, rx).0)
            / (2.0 * h);
        assert!((slope - fd).abs() < 1e-6 * slope.abs(), "{slope} vs {fd}");
        // Outside the axial band: nothing.
        assert_eq!(s.drop(1.0, 1.1e-3, track, rx), (0.0, 0.0));
        // A short pit is bridged: the ball never reaches its floor.
        let narrow = Spall {
            size: SpallSize::Length(0.1e-3),
            ..s
        };
        assert!(narrow.drop(1.0, 0.0, track, rx).0 < 5e-6 * 0.1);
    }

    #[test]
    fn a_ramped_edge_descends_linearly() {
        let (track, rx) = (0.03, 1e-4);
        let s = spall(Edge::Ramped { length: 0.2e-3 });
        let at = |a: f64| 1.0 - (0.5e-3 - a) / track;
        assert!((s.drop(at(0.1e-3), 0.0, track, rx).0 - 2.5e-6).abs() < 1e-15);
        assert!((s.drop(at(0.3e-3), 0.0, track, rx).0 - 5e-6).abs() < 1e-18);
        // Wraps around the circle.
        let wrapped = s.drop(at(0.1e-3) + TAU, 0.0, track, rx).0;
        assert!((wrapped - 2.5e-6).abs() < 1e-12, "{wrapped}");
    }

    #[test]
    fn bad_spalls_are_refused() {
        let mut s = spall(Edge::Sharp);
        s.depth = 0.0;
        assert_eq!(s.validate().unwrap_err().field, "depth");
        s.depth = 1e-6;
        s.size = SpallSize::Angle(4.0);
        assert_eq!(s.validate().unwrap_err().field, "width");
        s.size = SpallSize::Angle(0.1);
        s.edge = Edge::Ramped { length: 0.0 };
        assert_eq!(s.validate().unwrap_err().field, "ramp");
    }
}
