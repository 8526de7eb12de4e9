//! Churning of the oil by a bearing in an oil bath or under an oil jet:
//! SKF's drag-loss model for ball bearings (SKF, *Rolling bearings*,
//! catalogue 10000 EN, 2013, "Drag losses"; docs/lubrication.md,
//! "Lubrication method and churning"). In the catalogue's units (moment
//! N·mm, d_m, d, D, H mm, n r/min, ν mm²/s):
//! ```text
//! M_drag = 0.4 V_M K_ball d_m⁵ n² + 1.093e-7 n² d_m³ (n d_m² f_t/ν)^−1.379 R_s
//! K_ball = i_rw K_z (d + D)/(D − d) 1e-12
//! t = 2 arccos((0.6 d_m − H)/(0.6 d_m)),   H ≤ 1.2 d_m
//! f_t = sin(t/2) (t ≤ π), 1 (t > π)
//! R_s = 0.36 d_m² (t − sin t) f_A,   f_A = 0.05 K_z (D + d)/(D − d)
//! ```
//! H is the oil level above the lowest point of the outer ring's raceway,
//! K_z the bearing type's constant (3.1 deep-groove, 4.4 single-row
//! angular-contact), i_rw the rows of balls, and V_M(H/d_m) the drag
//! factor of the catalogue's diagram, here as digitised from it
//! ([`DRAG_FACTOR`], linear between points). The first term is the balls'
//! and cage's drag through the bath, the second the viscous drag of the
//! wetted ring faces. Under an oil jet the catalogue takes the oil-bath
//! value at a level of half a ball diameter, twice. Grease (after its
//! run-in) and air–oil leave no bath: no churning.
//!
//! The moment acts on the turning inner ring against its rotation
//! relative to the outer ring, M = −M_drag(|n|) sign(n), and dissipates
//! M_drag |ω| into the oil; how the bath's drag divides among balls, cage
//! and rings is not modelled, so it does not slow the cage.

use crate::error::{InvalidParameter, require_non_negative, require_positive};

/// V_M of ball bearings against H/d_m (×1e-4), digitised from SKF 2013's
/// diagram of the drag loss factor (catalogue 10000 EN, "Drag losses").
pub const DRAG_FACTOR: [(f64, f64); 17] = [
    (0.0, 0.0),
    (0.01, 0.016),
    (0.05, 0.19),
    (0.10, 0.72),
    (0.15, 1.58),
    (0.20, 2.47),
    (0.25, 3.16),
    (0.30, 3.85),
    (0.40, 4.8),
    (0.50, 5.66),
    (0.60, 6.38),
    (0.70, 7.05),
    (0.80, 7.8),
    (0.90, 8.7),
    (1.00, 9.5),
    (1.10, 10.5),
    (1.20, 12.4),
];

/// K_z of a deep-groove ball bearing (SKF 2013).
pub const DEEP_GROOVE_TYPE_CONSTANT: f64 = 3.1;
/// K_z of a single-row angular-contact ball bearing (SKF 2013).
pub const ANGULAR_CONTACT_TYPE_CONSTANT: f64 = 4.4;

/// How the oil churns.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bath {
    /// An oil bath of level H above the lowest point of the outer ring's
    /// raceway \[m\].
    Level(f64),
    /// An oil jet: the bath's drag at half a ball diameter, twice.
    Jet,
}

/// The churning of a bearing's oil.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Churning {
    /// Bore d \[m\].
    pub bore: f64,
    /// Outside diameter D \[m\].
    pub outside_diameter: f64,
    /// Ball diameter \[m\] (the jet's level).
    pub ball_diameter: f64,
    /// Bearing type constant K_z.
    pub type_constant: f64,
    /// The bath or jet.
    pub bath: Bath,
    /// Dynamic viscosity of the oil η \[Pa·s\] (a coupled thermal
    /// network updates it).
    pub viscosity: f64,
    /// Density of the oil ρ \[kg/m³\] (ν = η/ρ).
    pub density: f64,
}

impl Churning {
    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        require_positive("bore", self.bore)?;
        require_positive("ball_diameter", self.ball_diameter)?;
        if self.outside_diameter.is_nan() || self.outside_diameter <= self.bore {
            return Err(InvalidParameter::new(
                "outside_diameter",
                self.outside_diameter,
                "must exceed the bore",
            ));
        }
        require_positive("type_constant", self.type_constant)?;
        require_positive("viscosity", self.viscosity)?;
        require_positive("density", self.density)?;
        if let Bath::Level(h) = self.bath {
            require_non_negative("oil_level", h)?;
        }
        Ok(())
    }

    /// SKF's M_drag at speed |n| \[N·m\] (≥ 0), module doc.
    fn drag(&self, speed: f64, level: f64) -> f64 {
        let (d, big_d) = (self.bore * 1e3, self.outside_diameter * 1e3);
        let dm = 0.5 * (d + big_d);
        let n = speed.abs() * 60.0 / std::f64::consts::TAU;
        let nu = self.viscosity / self.density * 1e6;
        let h = (level * 1e3).min(1.2 * dm);
        if n <= 0.0 || h <= 0.0 {
            return 0.0;
        }
        let kz = self.type_constant;
        let k_ball = kz * (d + big_d) / (big_d - d) * 1e-12;
        let t = 2.0 * ((0.6 * dm - h) / (0.6 * dm)).clamp(-1.0, 1.0).acos();
        let f_t = if t <= std::f64::consts::PI {
            (0.5 * t).sin()
        } else {
            1.0
        };
        let f_a = 0.05 * kz * (big_d + d) / (big_d - d);
        let r_s = 0.36 * dm * dm * (t - t.sin()) * f_a;
        let v_m = drag_factor(h / dm) * 1e-4;
        let balls = 0.4 * v_m * k_ball * dm.powi(5) * n * n;
        let faces = 1.093e-7 * n * n * dm.powi(3) * (n * dm * dm * f_t / nu).powf(-1.379) * r_s;
        (balls + faces) * 1e-3
    }

    /// The churning moment on the inner ring turning at `speed` relative
    /// to the outer ring \[rad/s\], against the rotation \[N·m\].
    pub fn moment(&self, speed: f64) -> f64 {
        let m = match self.bath {
            Bath::Level(h) => self.drag(speed, h),
            Bath::Jet => 2.0 * self.drag(speed, 0.5 * self.ball_diameter),
        };
        -m * speed.signum()
    }

    /// Power the churning dissipates at `speed` \[W\] (≥ 0).
    pub fn power(&self, speed: f64) -> f64 {
        -self.moment(speed) * speed
    }
}

/// V_M × 1e4 at H/d_m, linear between the digitised points and held
/// beyond them.
pub fn drag_factor(level_ratio: f64) -> f64 {
    let last = DRAG_FACTOR[DRAG_FACTOR.len() - 1];
    if level_ratio >= last.0 {
        return last.1;
    }
    let x = level_ratio.max(0.0);
    let i = DRAG_FACTOR.partition_point(|p| p.0 <= x).max(1);
    let (a, b) = (DRAG_FACTOR[i - 1], DRAG_FACTOR[i]);
    a.1 + (b.1 - a.1) * (x - a.0) / (b.0 - a.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bearing_6205(bath: Bath) -> Churning {
        Churning {
            bore: 25e-3,
            outside_diameter: 52e-3,
            ball_diameter: 7.938e-3,
            type_constant: DEEP_GROOVE_TYPE_CONSTANT,
            bath,
            viscosity: 0.0172,
            density: 860.0,
        }
    }

    const RPM: f64 = std::f64::consts::TAU / 60.0;

    /// A 6205 at 3000 r/min in a 20 mm²/s bath at H = 0.3 d_m, computed by
    /// hand from the catalogue's formulas: t = 2π/3, f_t = sin 60°,
    /// f_A = 0.4420, R_s = 289.7 mm², K_ball = 8.84e-12, V_M = 3.85e-4:
    /// 1.036 + 0.839 = 1.876 N·mm.
    #[test]
    fn oil_bath_drag_of_a_6205_by_hand() {
        let dm = 38.5e-3;
        let c = bearing_6205(Bath::Level(0.3 * dm));
        let m = -c.moment(3000.0 * RPM);
        let t = 2.0 * std::f64::consts::FRAC_PI_3;
        let f_a = 0.05 * 3.1 * 77.0 / 27.0;
        let r_s = 0.36 * 38.5f64.powi(2) * (t - t.sin()) * f_a;
        let k_ball = 3.1 * 77.0 / 27.0 * 1e-12;
        let balls = 0.4 * 3.85e-4 * k_ball * 38.5f64.powi(5) * 9e6;
        let faces = 1.093e-7
            * 9e6
            * 38.5f64.powi(3)
            * (3000.0 * 38.5f64.powi(2) * (0.5 * t).sin() / 20.0).powf(-1.379)
            * r_s;
        assert!((r_s - 289.7).abs() < 0.1, "{r_s}");
        assert!((m * 1e3 - (balls + faces)).abs() < 1e-9, "{m}");
        assert!((m * 1e3 - 1.876).abs() < 0.001, "{m}");
        assert!(c.power(3000.0 * RPM) > 0.0 && c.power(-3000.0 * RPM) > 0.0);
        assert_eq!(c.moment(0.0), 0.0);
    }

    /// More oil, more speed: more drag; no bath, none; the jet is the
    /// bath at half a ball diameter, twice; the level caps at 1.2 d_m.
    #[test]
    fn trends_and_the_jet_rule() {
        let w = 3000.0 * RPM;
        let m = |h: f64| -bearing_6205(Bath::Level(h)).moment(w);
        assert_eq!(m(0.0), 0.0);
        assert!(m(5e-3) < m(10e-3) && m(10e-3) < m(30e-3));
        assert_eq!(m(1.2 * 38.5e-3), m(0.1));
        let bath = bearing_6205(Bath::Level(10e-3));
        assert!(-bath.moment(2.0 * w) > -bath.moment(w));
        let jet = -bearing_6205(Bath::Jet).moment(w);
        assert!((jet - 2.0 * m(0.5 * 7.938e-3)).abs() < 1e-15);
        assert!((drag_factor(0.3) - 3.85).abs() < 1e-12);
        assert!((drag_factor(0.35) - 0.5 * (3.85 + 4.8)).abs() < 1e-12);
        assert_eq!(drag_factor(2.0), 12.4);
        assert!(bearing_6205(Bath::Level(-1e-3)).validate().is_err());
    }
}
