//! Bearing internal geometry (docs/model.md §2): ball set, groove curvatures and the
//! two groove-curvature-centre circles that carry all contact geometry.
//!
//! # Parametrizations
//! A bearing is given by ball diameter D, ball count Z, groove curvature
//! factors f_i = r_i/D, f_o = r_o/D and one of
//! * (a) the free contact angle α₀ and the pitch diameter d_m
//!   (angular-contact; the clearance is encoded in α₀),
//! * (b) the diametral clearance P_d and d_m (deep-groove, α₀ = 0),
//! * (c) the groove-bottom diameters d_i, d_o (then d_m = (d_i + d_o)/2 and
//!   P_d = d_o − d_i − 2D; this reduces to (b)).
//!
//! # Groove-centre circles
//! With the ball centre at its nominal position (x = 0, r = d_m/2):
//! ```text
//! inner: ρ_ci = d_m/2 + (f_i − ½) D cos α₀ − P_d/4,   x_ci = +(f_i − ½) D sin α₀
//! outer: ρ_co = d_m/2 − (f_o − ½) D cos α₀ + P_d/4,   x_co = −(f_o − ½) D sin α₀
//! ```
//! **Signs of the clearance term** (docs/model.md §2): with the opposite
//! signs (`+ P_d/4` inner, `− P_d/4` outer) a ball at the pitch radius would
//! *penetrate* both raceways by P_d/4, and Shan et al. 2023 eq 1
//! (R_i + 2(r_b + c) = R_o with P_d = 4c) would read R_i + 2(r_b − c) = R_o.
//! With the signs above the ball has a gap of P_d/4 at each raceway and
//! Shan et al. 2023 eq 1 holds exactly (validation case A7).
//!
//! Groove-bottom diameters follow as d_i = 2(ρ_ci − r_i), d_o = 2(ρ_co + r_o).
//! Positive axial force F_x on the inner ring loads the balls (the inner
//! groove centre sits at +x of the ball centre).
//!
//! Sources: Harris & Kotzalas, *Essential Concepts of Bearing Technology*
//! (5th ed., 2006), ch. 2 (clearance, free contact angle
//! cos α_f = 1 − P_d/(2BD), B = f_i + f_o − 1); Shan et al. 2023 eq 1; Deng et al. 2022 Table 1.

use crate::error::InvalidParameter;
use serde::Serialize;

/// Which ring a raceway belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RingKind {
    /// Inner ring (convex raceway in the rolling direction).
    Inner,
    /// Outer ring (concave raceway in the rolling direction).
    Outer,
}

impl RingKind {
    /// Both rings, inner first.
    pub const BOTH: [RingKind; 2] = [RingKind::Inner, RingKind::Outer];
    /// Lower-case name ("inner"/"outer").
    pub fn name(self) -> &'static str {
        match self {
            RingKind::Inner => "inner",
            RingKind::Outer => "outer",
        }
    }
}

/// How the clearance of a bearing was specified.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Clearance {
    /// (a) Free contact angle α₀ \[rad\] in [0°, 60°].
    FreeContactAngle(f64),
    /// (b) Diametral clearance P_d \[m\]; negative only with `preload`.
    Diametral(f64),
    /// (c) Groove-bottom (raceway) diameters d_i, d_o \[m\]; d_m is derived.
    RacewayDiameters { inner: f64, outer: f64 },
}

/// Everything needed to build a [`BearingGeometry`], in SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GeometrySpec {
    /// Ball diameter D \[m\].
    pub ball_diameter: f64,
    /// Number of balls Z, 3 ≤ Z ≤ 1000.
    pub ball_count: usize,
    /// Pitch diameter d_m \[m\]; ignored (derived) for [`Clearance::RacewayDiameters`].
    pub pitch_diameter: f64,
    /// Inner groove curvature factor f_i = r_i/D, in (0.5, 1).
    pub inner_groove_curvature: f64,
    /// Outer groove curvature factor f_o = r_o/D, in (0.5, 1).
    pub outer_groove_curvature: f64,
    /// The clearance parametrization.
    pub clearance: Clearance,
    /// Allows a negative diametral clearance (interference, preloaded set).
    pub preload: bool,
}

/// One raceway: its groove torus, in the ring's own frame.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Raceway {
    /// Inner or outer ring.
    pub kind: RingKind,
    /// Groove curvature factor f = r/D.
    pub groove_curvature: f64,
    /// Groove (cross-section) radius r = f D \[m\].
    pub groove_radius: f64,
    /// Radius of the groove-curvature-centre circle ρ_c \[m\].
    pub groove_centre_radius: f64,
    /// Axial position of the groove-curvature-centre circle x_c \[m\].
    pub groove_centre_axial: f64,
    /// Groove-bottom (raceway) diameter d_i or d_o \[m\].
    pub groove_bottom_diameter: f64,
}

/// A validated bearing geometry with its groove-centre circles (docs/model.md §2).
#[derive(Debug, Clone, PartialEq)]
pub struct BearingGeometry {
    /// Ball diameter D \[m\].
    pub ball_diameter: f64,
    /// Number of balls Z.
    pub ball_count: usize,
    /// Pitch diameter d_m \[m\].
    pub pitch_diameter: f64,
    /// Inner raceway.
    pub inner: Raceway,
    /// Outer raceway.
    pub outer: Raceway,
    /// The parametrization the geometry was built from.
    pub clearance: Clearance,
    /// The P_d term of the groove-centre formulas (0 for parametrization (a)).
    pub diametral_clearance: f64,
    /// α₀ in the groove-centre formulas (0 for (b) and (c)) \[rad\].
    pub offset_contact_angle: f64,
}

/// Largest accepted free contact angle (docs/model.md §2: α₀ ∈ [0°, 60°]).
pub const MAX_FREE_CONTACT_ANGLE_DEG: f64 = 60.0;
/// Largest accepted ball count; anything above is treated as a typo.
pub const MAX_BALL_COUNT: usize = 1000;
/// Largest accepted interference per contact with `preload`, as a fraction
/// of D. Beyond ~1 % of D the steel contact is far past its elastic limit
/// (Hertz deflections at the 4 GPa static limit are ~0.5 % of D), so the
/// raceways are treated as crossing.
pub const MAX_PRELOAD_INTERFERENCE_FRACTION: f64 = 0.01;

fn positive_finite(field: &'static str, value: f64, unit: &str) -> Result<(), InvalidParameter> {
    if !value.is_finite() {
        return Err(InvalidParameter::new(
            field,
            value,
            "must be a finite number",
        ));
    }
    if value <= 0.0 {
        return Err(InvalidParameter::new(
            field,
            format!("{value} {unit}"),
            "must be positive",
        ));
    }
    Ok(())
}

fn groove_curvature(field: &'static str, f: f64) -> Result<(), InvalidParameter> {
    if !f.is_finite() {
        return Err(InvalidParameter::new(field, f, "must be a finite number"));
    }
    if f <= 0.5 {
        return Err(InvalidParameter::new(
            field,
            f,
            "groove curvature factor f = r/D must exceed 0.5 (a groove radius of at most D/2 cannot hold the ball)",
        ));
    }
    if f >= 1.0 {
        return Err(InvalidParameter::new(
            field,
            f,
            "groove curvature factor f = r/D must be below 1.0 (real grooves use 0.505–0.58)",
        ));
    }
    Ok(())
}

/// The ball count's rules: at least 3, at most [`MAX_BALL_COUNT`].
fn ball_count(z: usize) -> Result<(), InvalidParameter> {
    if z < 3 {
        return Err(InvalidParameter::new(
            "ball_count",
            z,
            "a bearing needs at least 3 balls",
        ));
    }
    if z > MAX_BALL_COUNT {
        return Err(InvalidParameter::new(
            "ball_count",
            z,
            format!("more than {MAX_BALL_COUNT} balls is not a plausible bearing"),
        ));
    }
    Ok(())
}

/// The pitch diameter, the diametral clearance and the offset contact
/// angle of the spec's way of giving the clearance (docs/geometry.md).
fn pitch_clearance_and_angle(spec: &GeometrySpec) -> Result<(f64, f64, f64), InvalidParameter> {
    let d = spec.ball_diameter;
    Ok(match spec.clearance {
        Clearance::FreeContactAngle(a0) => {
            if !a0.is_finite() {
                return Err(InvalidParameter::new(
                    "free_contact_angle",
                    a0,
                    "must be a finite number",
                ));
            }
            let deg = a0.to_degrees();
            if !(0.0..=MAX_FREE_CONTACT_ANGLE_DEG).contains(&deg) {
                return Err(InvalidParameter::new(
                    "free_contact_angle",
                    format!("{deg} deg"),
                    format!("must lie in [0, {MAX_FREE_CONTACT_ANGLE_DEG}] deg"),
                ));
            }
            positive_finite("pitch_diameter", spec.pitch_diameter, "m")?;
            (spec.pitch_diameter, 0.0, a0)
        }
        Clearance::Diametral(pd) => {
            if !pd.is_finite() {
                return Err(InvalidParameter::new(
                    "diametral_clearance",
                    pd,
                    "must be a finite number",
                ));
            }
            positive_finite("pitch_diameter", spec.pitch_diameter, "m")?;
            (spec.pitch_diameter, pd, 0.0)
        }
        Clearance::RacewayDiameters { inner, outer } => {
            positive_finite("inner_raceway_diameter", inner, "m")?;
            positive_finite("outer_raceway_diameter", outer, "m")?;
            if outer <= inner {
                return Err(InvalidParameter::new(
                    "outer_raceway_diameter",
                    format!("{outer} m"),
                    format!(
                        "raceways cross: the outer raceway diameter must exceed the inner one ({inner} m)"
                    ),
                ));
            }
            ((inner + outer) / 2.0, outer - inner - 2.0 * d, 0.0)
        }
    })
}

/// The diametral clearance's limits: an interference only with the
/// explicit preload flag and at most a fraction of the ball diameter per
/// contact; a clearance below 2(f_i + f_o − 1)D.
fn clearance_limits(
    spec: &GeometrySpec,
    pd: f64,
    total_curvature: f64,
) -> Result<(), InvalidParameter> {
    let d = spec.ball_diameter;
    let pd_field = match spec.clearance {
        Clearance::RacewayDiameters { .. } => "outer_raceway_diameter",
        _ => "diametral_clearance",
    };
    if pd < 0.0 {
        if !spec.preload {
            return Err(InvalidParameter::new(
                pd_field,
                format!("diametral clearance {pd} m"),
                "negative clearance (interference) needs the explicit flag preload = true",
            ));
        }
        let per_contact = -pd / 4.0;
        if per_contact > MAX_PRELOAD_INTERFERENCE_FRACTION * d {
            return Err(InvalidParameter::new(
                pd_field,
                format!("diametral clearance {pd} m"),
                format!(
                    "raceways cross: the interference per contact ({per_contact} m) exceeds {}% of the ball diameter",
                    MAX_PRELOAD_INTERFERENCE_FRACTION * 100.0
                ),
            ));
        }
    }
    if pd >= total_curvature * d * 2.0 {
        return Err(InvalidParameter::new(
            pd_field,
            format!("diametral clearance {pd} m"),
            format!(
                "clearance reaches 2(f_i + f_o − 1)D = {} m: the ball could pass the raceway shoulders (free contact angle ≥ 90°)",
                2.0 * total_curvature * d
            ),
        ));
    }
    Ok(())
}

impl BearingGeometry {
    /// Validates a [`GeometrySpec`] against the rules of docs/model.md §2 and builds
    /// the groove-centre circles.
    pub fn new(spec: &GeometrySpec) -> Result<Self, InvalidParameter> {
        let d = spec.ball_diameter;
        positive_finite("ball_diameter", d, "m")?;
        let z = spec.ball_count;
        ball_count(z)?;
        groove_curvature("inner_groove_curvature", spec.inner_groove_curvature)?;
        groove_curvature("outer_groove_curvature", spec.outer_groove_curvature)?;
        let (fi, fo) = (spec.inner_groove_curvature, spec.outer_groove_curvature);
        let total_curvature = fi + fo - 1.0;

        let (pitch, pd, alpha0) = pitch_clearance_and_angle(spec)?;
        if pitch <= d {
            return Err(InvalidParameter::new(
                "pitch_diameter",
                format!("{pitch} m"),
                format!("must exceed the ball diameter ({d} m)"),
            ));
        }
        // Balls overlap when the chord between neighbouring centres is ≤ D
        // (exact form of Z·D < π d_m).
        let chord = pitch * (std::f64::consts::PI / z as f64).sin();
        if chord <= d {
            return Err(InvalidParameter::new(
                "ball_count",
                z,
                format!(
                    "balls overlap: {z} balls of {d} m on a {pitch} m pitch circle are {chord} m apart, less than one ball diameter"
                ),
            ));
        }
        clearance_limits(spec, pd, total_curvature)?;

        let (s0, c0) = alpha0.sin_cos();
        let inner_rc = pitch / 2.0 + (fi - 0.5) * d * c0 - pd / 4.0;
        let outer_rc = pitch / 2.0 - (fo - 0.5) * d * c0 + pd / 4.0;
        let inner = Raceway {
            kind: RingKind::Inner,
            groove_curvature: fi,
            groove_radius: fi * d,
            groove_centre_radius: inner_rc,
            groove_centre_axial: (fi - 0.5) * d * s0,
            groove_bottom_diameter: 2.0 * (inner_rc - fi * d),
        };
        let outer = Raceway {
            kind: RingKind::Outer,
            groove_curvature: fo,
            groove_radius: fo * d,
            groove_centre_radius: outer_rc,
            groove_centre_axial: -(fo - 0.5) * d * s0,
            groove_bottom_diameter: 2.0 * (outer_rc + fo * d),
        };
        if inner.groove_bottom_diameter <= 0.0 {
            return Err(InvalidParameter::new(
                "pitch_diameter",
                format!("{pitch} m"),
                "the inner raceway diameter would be negative",
            ));
        }
        Ok(Self {
            ball_diameter: d,
            ball_count: z,
            pitch_diameter: pitch,
            inner,
            outer,
            clearance: spec.clearance,
            diametral_clearance: pd,
            offset_contact_angle: alpha0,
        })
    }

    /// The raceway of one ring.
    pub fn raceway(&self, ring: RingKind) -> &Raceway {
        match ring {
            RingKind::Inner => &self.inner,
            RingKind::Outer => &self.outer,
        }
    }

    /// Total curvature B = f_i + f_o − 1.
    pub fn total_curvature(&self) -> f64 {
        self.inner.groove_curvature + self.outer.groove_curvature - 1.0
    }

    /// Distance between the two groove-centre circles at zero load, B D
    /// minus the clearance that is not taken up: the ball touches both
    /// raceways when the rings are displaced so that this equals B D.
    pub fn groove_centre_distance(&self) -> f64 {
        let dr = self.inner.groove_centre_radius - self.outer.groove_centre_radius;
        let dx = self.inner.groove_centre_axial - self.outer.groove_centre_axial;
        dr.hypot(dx)
    }

    /// Diametral clearance equivalent of the geometry,
    /// P_d,eq = 2 B D (1 − cos α_f): the given P_d for (b)/(c), the clearance
    /// α₀ encodes for (a) (Harris & Kotzalas ch. 2).
    pub fn equivalent_diametral_clearance(&self) -> f64 {
        2.0 * self.total_curvature() * self.ball_diameter * (1.0 - self.free_contact_angle().cos())
    }

    /// Free contact angle α_f: the contact angle when the rings are pushed
    /// axially until the clearance is taken up; cos α_f = 1 − P_d/(2 B D).
    /// Equals α₀ for parametrization (a). Negative clearance gives 0.
    pub fn free_contact_angle(&self) -> f64 {
        match self.clearance {
            Clearance::FreeContactAngle(a0) => a0,
            _ => {
                let c = 1.0
                    - self.diametral_clearance
                        / (2.0 * self.total_curvature() * self.ball_diameter);
                c.clamp(-1.0, 1.0).acos()
            }
        }
    }

    /// Axial play (end play) P_e = 2 B D sin α_f (Harris & Kotzalas ch. 2).
    pub fn axial_play(&self) -> f64 {
        2.0 * self.total_curvature() * self.ball_diameter * self.free_contact_angle().sin()
    }

    /// Nominal contact angle for kinematics and defect frequencies: α₀ for
    /// angular-contact (a), 0 for radial deep-groove specifications (b), (c).
    pub fn nominal_contact_angle(&self) -> f64 {
        self.offset_contact_angle
    }

    /// γ = D cos α / d_m.
    pub fn gamma(&self, contact_angle: f64) -> f64 {
        self.ball_diameter * contact_angle.cos() / self.pitch_diameter
    }

    /// Ball mass m = ρ π D³/6 \[kg\].
    pub fn ball_mass(&self, density: f64) -> f64 {
        density * std::f64::consts::PI * self.ball_diameter.powi(3) / 6.0
    }
}

/// A test bearing: the 7008C's ball and pitch diameters and free contact
/// angle (6.35 mm, 54 mm, 17.7°) with groove curvatures 0.55 / 0.52 and
/// `ball_count` balls.
#[cfg(test)]
pub(crate) fn test_bearing(ball_count: usize) -> BearingGeometry {
    BearingGeometry::new(&GeometrySpec {
        ball_diameter: 6.35e-3,
        ball_count,
        pitch_diameter: 54e-3,
        inner_groove_curvature: 0.55,
        outer_groove_curvature: 0.52,
        clearance: Clearance::FreeContactAngle(17.7f64.to_radians()),
        preload: false,
    })
    .expect("the test bearing is valid")
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::testing::spec_7008c;

    #[test]
    fn seed001_groove_bottom_diameters() {
        // Deng et al. 2022 Table 1: d_i = 47.62 mm, d_o = 60.36 mm (printed to 0.01 mm).
        let g = BearingGeometry::new(&spec_7008c()).unwrap();
        assert!((g.inner.groove_bottom_diameter - 47.62e-3).abs() < 0.006e-3);
        assert!((g.outer.groove_bottom_diameter - 60.36e-3).abs() < 0.006e-3);
        // The ball touches both raceways at α₀: groove centres B·D apart.
        let bd = g.total_curvature() * g.ball_diameter;
        assert!((g.groove_centre_distance() - bd).abs() < 1e-15);
    }

    #[test]
    fn parametrizations_agree() {
        // (b) with P_d and (c) with the implied raceway diameters are the same bearing.
        let mut b = spec_7008c();
        b.clearance = Clearance::Diametral(20e-6);
        let gb = BearingGeometry::new(&b).unwrap();
        let mut c = b;
        c.clearance = Clearance::RacewayDiameters {
            inner: gb.inner.groove_bottom_diameter,
            outer: gb.outer.groove_bottom_diameter,
        };
        let gc = BearingGeometry::new(&c).unwrap();
        assert!((gc.pitch_diameter - gb.pitch_diameter).abs() < 1e-15);
        assert!((gc.diametral_clearance - 20e-6).abs() < 1e-15);
        // (a) with the free angle of (b) encodes the same clearance.
        let mut a = b;
        a.clearance = Clearance::FreeContactAngle(gb.free_contact_angle());
        let ga = BearingGeometry::new(&a).unwrap();
        assert!((ga.equivalent_diametral_clearance() - 20e-6).abs() < 1e-15);
    }

    #[test]
    fn rules_are_enforced() {
        let bad = |f: &dyn Fn(&mut GeometrySpec)| {
            let mut s = spec_7008c();
            f(&mut s);
            BearingGeometry::new(&s).unwrap_err()
        };
        assert_eq!(
            bad(&|s| s.inner_groove_curvature = 0.5).field,
            "inner_groove_curvature"
        );
        assert_eq!(bad(&|s| s.ball_count = 2).field, "ball_count");
        assert_eq!(bad(&|s| s.ball_count = 30).field, "ball_count");
        assert_eq!(bad(&|s| s.ball_diameter = f64::NAN).field, "ball_diameter");
        assert_eq!(
            bad(&|s| s.clearance = Clearance::FreeContactAngle(61f64.to_radians())).field,
            "free_contact_angle"
        );
        assert_eq!(
            bad(&|s| s.clearance = Clearance::Diametral(-1e-6)).field,
            "diametral_clearance"
        );
        assert!(
            bad(&|s| s.clearance = Clearance::Diametral(-1e-6))
                .rule
                .contains("preload")
        );
        let e = bad(&|s| {
            s.clearance = Clearance::RacewayDiameters {
                inner: 0.06,
                outer: 0.05,
            }
        });
        assert!(e.rule.contains("raceways cross"));
        let mut s = spec_7008c();
        s.clearance = Clearance::Diametral(-1e-6);
        s.preload = true;
        assert!(BearingGeometry::new(&s).is_ok());
    }
}
