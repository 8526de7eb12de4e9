//! Operating conditions (docs/model.md §8): the inner-ring speed profile and the
//! loads applied to the inner ring (constant or tabulated), in SI units.

use crate::error::InvalidParameter;

/// Inner-ring speed as a function of time.
#[derive(Debug, Clone, PartialEq)]
pub enum SpeedProfile {
    /// Constant speed \[rad/s\].
    Constant(f64),
    /// Piecewise-linear table of (time \[s\], speed \[rad/s\]), times strictly
    /// increasing; held constant outside the table (Zhang et al. 2025's ramp).
    PiecewiseLinear(Vec<(f64, f64)>),
}

impl SpeedProfile {
    /// Builds a piecewise-linear profile, checking the table. The error's
    /// field is `speed_profile[i]`-style: the index of the offending point.
    pub fn piecewise_linear(points: Vec<(f64, f64)>) -> Result<Self, (usize, InvalidParameter)> {
        if points.is_empty() {
            return Err((
                0,
                InvalidParameter::new("speed_profile", "[]", "needs at least one point"),
            ));
        }
        for (i, &(t, w)) in points.iter().enumerate() {
            if !t.is_finite() || !w.is_finite() {
                return Err((
                    i,
                    InvalidParameter::new("time", t, "time and speed must be finite"),
                ));
            }
            if i > 0 && t <= points[i - 1].0 {
                return Err((
                    i,
                    InvalidParameter::new(
                        "time",
                        format!("{t} s"),
                        format!(
                            "times must increase strictly (previous point: {} s)",
                            points[i - 1].0
                        ),
                    ),
                ));
            }
        }
        Ok(Self::PiecewiseLinear(points))
    }

    /// Speed at time t \[rad/s\].
    pub fn speed_at(&self, t: f64) -> f64 {
        match self {
            Self::Constant(w) => *w,
            Self::PiecewiseLinear(points) => interpolate(points, t),
        }
    }

    /// Angle turned since t = 0, ∫₀ᵗ ω dt \[rad\] (exact for both profiles;
    /// carries the inner ring's surface, docs/model.md §6).
    pub fn angle_at(&self, t: f64) -> f64 {
        match self {
            Self::Constant(w) => w * t,
            Self::PiecewiseLinear(points) => {
                // Speed held at the first point from t = 0 (and before it).
                let mut angle = 0.0;
                let mut t_prev = 0.0;
                let mut w_prev = self.speed_at(0.0);
                for &(tp, wp) in points.iter().filter(|p| p.0 > 0.0) {
                    if tp >= t {
                        break;
                    }
                    angle += 0.5 * (w_prev + wp) * (tp - t_prev);
                    (t_prev, w_prev) = (tp, wp);
                }
                angle + 0.5 * (w_prev + self.speed_at(t)) * (t - t_prev)
            }
        }
    }

    /// The speed the profile ends at (the constant speed, or the last point).
    pub fn final_speed(&self) -> f64 {
        match self {
            Self::Constant(w) => *w,
            Self::PiecewiseLinear(points) => points.last().map_or(0.0, |p| p.1),
        }
    }
}

/// The value at t of a piecewise-linear table of (time, value), held
/// constant outside it (the table is not empty).
fn interpolate(points: &[(f64, f64)], t: f64) -> f64 {
    let i = points.partition_point(|p| p.0 <= t);
    match i {
        0 => points[0].1,
        i if i == points.len() => points[i - 1].1,
        i => {
            let (t0, v0) = points[i - 1];
            let (t1, v1) = points[i];
            v0 + (v1 - v0) * (t - t0) / (t1 - t0)
        }
    }
}

/// The inner ring driven by a torque instead of a prescribed speed: its
/// speed is then a state of the run, J ω̇ = T(t) + M_x, M_x the moment of
/// the bearing's forces (contacts, guide land, seals) on the ring about
/// its axis (Euler's equation of a rotor about a fixed axis). The speed
/// profile of the parameters gives the speed at t = 0 (docs/dynamics.md,
/// "Driven rotation").
#[derive(Debug, Clone, PartialEq)]
pub struct TorqueDrive {
    /// Polar moment of inertia J of everything turning with the inner
    /// ring (ring, shaft, rotor) \[kg·m²\].
    pub inertia: f64,
    /// Drive torque about the bearing axis as (time \[s\], torque \[N·m\]),
    /// piecewise linear and held constant outside the table (one point:
    /// a constant torque; 0: a run-down).
    pub torque: Vec<(f64, f64)>,
}

impl TorqueDrive {
    /// A drive of constant torque \[N·m\] on a rotor of polar inertia
    /// `inertia` \[kg·m²\].
    pub fn constant(inertia: f64, torque: f64) -> Self {
        Self {
            inertia,
            torque: vec![(0.0, torque)],
        }
    }

    /// Drive torque at time t \[N·m\].
    pub fn torque_at(&self, t: f64) -> f64 {
        interpolate(&self.torque, t)
    }

    /// Checks the inertia and the torque table (times strictly increasing,
    /// values finite).
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        crate::error::require_positive("rotor_inertia", self.inertia)?;
        SpeedProfile::piecewise_linear(self.torque.clone())
            .map(|_| ())
            .map_err(|(i, e)| {
                InvalidParameter::new("drive_torque", e.value, format!("point {i}: {}", e.rule))
            })
    }
}

/// A rotating unbalance on the inner ring (with its shaft): the force
/// U ω² (cos(θ + φ), sin(θ + φ)) in (y, z), θ the ring's angle, turning
/// with it (Den Hartog's rotating unbalance). An inner-race defect then
/// meets the load at one place of the ring: no load-zone modulation at the
/// shaft rate (Randall & Antoni 2011).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RingUnbalance {
    /// Mass times eccentricity U = m_u e \[kg·m\].
    pub amount: f64,
    /// Its direction φ on the ring at θ = 0, from +y towards +z \[rad\].
    pub phase: f64,
}

impl RingUnbalance {
    /// The force (F_y, F_z) at ring speed `speed` and angle `angle` \[N\].
    pub fn force(&self, speed: f64, angle: f64) -> [f64; 2] {
        let (s, c) = (angle + self.phase).sin_cos();
        let magnitude = self.amount * speed * speed;
        [magnitude * c, magnitude * s]
    }

    /// Checks the amount (finite, ≥ 0) and the phase (finite).
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        crate::error::require_non_negative("unbalance", self.amount)?;
        if self.phase.is_finite() {
            Ok(())
        } else {
            Err(InvalidParameter::new(
                "unbalance_phase",
                self.phase,
                "must be finite",
            ))
        }
    }
}

/// Loads on the inner ring in the global frame (x: bearing axis).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Loads {
    /// Forces (F_x, F_y, F_z) \[N\].
    pub force: [f64; 3],
    /// Moments (M_y, M_z) \[N·m\].
    pub moment: [f64; 2],
}

impl Loads {
    /// Sum of `self` and `other` scaled by `factor`.
    fn add_scaled(&self, other: &Loads, factor: f64) -> Loads {
        let mut out = *self;
        for k in 0..3 {
            out.force[k] += factor * other.force[k];
        }
        for k in 0..2 {
            out.moment[k] += factor * other.moment[k];
        }
        out
    }

    /// Difference `self − other`.
    fn minus(&self, other: &Loads) -> Loads {
        self.add_scaled(other, -1.0)
    }
}

/// Loads on the inner ring as a function of time (docs/model.md §8).
#[derive(Debug, Clone, PartialEq)]
pub enum LoadProfile {
    /// Constant loads.
    Constant(Loads),
    /// Piecewise-linear table of (time \[s\], loads), times strictly
    /// increasing; held constant outside the table.
    PiecewiseLinear(Vec<(f64, Loads)>),
}

impl Default for LoadProfile {
    fn default() -> Self {
        Self::Constant(Loads::default())
    }
}

impl LoadProfile {
    /// Builds a piecewise-linear profile, checking the times (the error
    /// carries the index of the offending point).
    pub fn piecewise_linear(points: Vec<(f64, Loads)>) -> Result<Self, (usize, InvalidParameter)> {
        let times: Vec<(f64, f64)> = points.iter().map(|p| (p.0, 0.0)).collect();
        SpeedProfile::piecewise_linear(times)?;
        Ok(Self::PiecewiseLinear(points))
    }

    /// The interval of the table holding t: (loads at t, d loads/dt).
    fn segment(&self, t: f64) -> (Loads, Loads) {
        match self {
            Self::Constant(l) => (*l, Loads::default()),
            Self::PiecewiseLinear(points) => {
                let i = points.partition_point(|p| p.0 <= t);
                match i {
                    0 => (points[0].1, Loads::default()),
                    i if i == points.len() => (points[i - 1].1, Loads::default()),
                    i => {
                        let (t0, l0) = points[i - 1];
                        let (t1, l1) = points[i];
                        let rate = Loads::default().add_scaled(&l1.minus(&l0), 1.0 / (t1 - t0));
                        (l0.add_scaled(&rate, t - t0), rate)
                    }
                }
            }
        }
    }

    /// Loads at time t.
    pub fn at(&self, t: f64) -> Loads {
        self.segment(t).0
    }

    /// Time derivative of the loads at t (zero outside ramps) \[N/s, N·m/s\].
    pub fn rate(&self, t: f64) -> Loads {
        self.segment(t).1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angle_is_the_integral_of_the_speed() {
        assert_eq!(SpeedProfile::Constant(3.0).angle_at(2.0), 6.0);
        let ramp = SpeedProfile::piecewise_linear(vec![(0.5, 100.0), (1.5, 1100.0), (2.0, 1100.0)])
            .unwrap();
        // 0.5 s at 100, then a ramp to 1100 over 1 s, then 1100.
        assert!((ramp.angle_at(0.25) - 25.0).abs() < 1e-12);
        assert!((ramp.angle_at(1.0) - (50.0 + 0.5 * (100.0 + 600.0) * 0.5)).abs() < 1e-12);
        assert!((ramp.angle_at(3.0) - (50.0 + 600.0 + 1100.0 * 1.5)).abs() < 1e-9);
        // Against a fine trapezoid rule.
        let n = 100_000;
        let h = 1.7 / n as f64;
        let numeric: f64 = (0..n)
            .map(|k| 0.5 * h * (ramp.speed_at(k as f64 * h) + ramp.speed_at((k + 1) as f64 * h)))
            .sum();
        assert!((ramp.angle_at(1.7) - numeric).abs() < 1e-6);
    }

    #[test]
    fn seed002_ramp() {
        let rpm = std::f64::consts::TAU / 60.0;
        let p = SpeedProfile::piecewise_linear(vec![
            (0.0, 1000.0 * rpm),
            (0.5, 1000.0 * rpm),
            (1.4, 10_000.0 * rpm),
        ])
        .unwrap();
        assert_eq!(p.speed_at(0.2), 1000.0 * rpm);
        assert!((p.speed_at(0.6) - 2000.0 * rpm).abs() < 1e-9);
        assert_eq!(p.speed_at(3.0), 10_000.0 * rpm);
        assert_eq!(p.final_speed(), 10_000.0 * rpm);
    }

    #[test]
    fn load_table_interpolates_with_its_rate() {
        let at = |fx: f64| Loads {
            force: [fx, 0.0, 0.0],
            moment: [0.0, 0.0],
        };
        let p = LoadProfile::piecewise_linear(vec![(0.0, at(100.0)), (0.1, at(300.0))]).unwrap();
        assert!((p.at(0.05).force[0] - 200.0).abs() < 1e-9);
        assert!((p.rate(0.05).force[0] - 2000.0).abs() < 1e-9);
        assert_eq!(p.at(1.0).force[0], 300.0);
        assert_eq!(p.rate(1.0).force[0], 0.0);
        assert!(LoadProfile::piecewise_linear(vec![(0.1, at(1.0)), (0.1, at(2.0))]).is_err());
    }

    #[test]
    fn rejects_non_increasing_times() {
        let err = SpeedProfile::piecewise_linear(vec![(0.0, 1.0), (0.0, 2.0)]).unwrap_err();
        assert_eq!(err.0, 1);
    }
}
