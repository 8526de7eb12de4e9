//! Quasi-static power loss by Harris's local method (Lei et al. 2023 §3; Harris &
//! Kotzalas, *Advanced Concepts of Bearing Technology*, 2006, ch. 6–7):
//! each mechanism evaluated on its own at every contact of a Jones–Harris
//! solution, under full sliding with a constant coefficient, and summed.
//!
//! Per ball–raceway contact (load Q, semi-axes a across and b along the
//! rolling direction, m = 1 − (b/a)², spin ω_s = Ω·n and rolling rate
//! ω_roll of the ball relative to the ring, from
//! [`crate::quasistatic::contact_motion`]):
//! ```text
//! hysteresis            H_E = (3/16) α_h b Q |ω_roll|                       (Johnson §9.2; Harris; Lei et al. 2023 eqs 20–27)
//! spin                  H_S = (3/8) f_s Q a E(m) |ω_s|                      (Harris & Kotzalas; Lei et al. 2023 eqs 34–35)
//! differential sliding  H_D = (3/4) I_H f_s Q a² |ω_roll| / R_d             (Heathcote slip, derived below)
//! ```
//! Heathcote slip: across the ellipse the deformed surface (radius
//! R_d = 2 r_g (D/2)/(r_g + D/2), as in [`crate::traction::ellipse`]) lies
//! ξ²/(2R_d) below the tangent plane, so rolling at ω_roll slides it at
//! s(ξ) = s₀ + ω_roll ξ²/(2R_d). With the strip load q(ξ) ∝ 1 − (ξ/a)²
//! and no net friction force (free rolling), the rolling lines sit at
//! ξ = ±c a with c³ − 3c + 1 = 0, c = 2 cos 80° = 0.3473 (Heathcote's
//! classical result), and the dissipated power is the line above with
//! I_H = 2/15 − (2/3)c² + (4/3)c³ − (4/15)c⁵. Lei et al. 2023's eqs 29–33 (a
//! fitted form of the same mechanism, with eq 32 printed twice) are not
//! used.
//!
//! Lei et al. 2023 eq 23 (with eq 27's E′ = 4(1 − ν²)/E corrected from (1 − ν)²),
//! read with Harris's a*, b*, δ* (eq 24 is δ*, eq 25 is b*), reduces to
//! φ = (3/16)(δ*/b*²) Σρ b Q: for a circular contact (δ* = b* = 1) on a
//! flat, (3/16) b Q/(D/4), the rolling-resistance form (3/16) α_h b Q/R
//! with half the ball radius for R and a factor δ*/b*² for ellipticity;
//! eq 21 then applies it with a bearing lever (d_m/4)(1 − γ²). We keep
//! the couple (3/16) α_h b Q about the rolling axis, the same law as the
//! dynamic model (see the test and docs/power.md).
//!
//! Cage and fluid (same laws as the dynamic model, at the solved speeds):
//! ```text
//! cage land     H_cl = T_land (ω_land − ω_c)              Petroff shear of the guide land, cage centred (crate::cage::GuideLand)
//! ball–pocket   H_cb = f_c Σ N_j (D/2) ω_R,j,  Σ N_j = (|T_land| + |T_cage drag|)/r_p + m_c g (no guide land)
//! drag          balls: −(F v_t + M·ω_b), cage: c₁ ω_c² + c₂ |ω_c|³ (crate::lubrication::drag::DragParameters)
//! seals         M_s ω_i² / √(ω_i² + ω₀²)                                  (crate::seals::SealFriction)
//! ```
//! The pocket forces are those that hold the cage against its drag (Harris
//! & Kotzalas ch. 7 take the cage weight, Lei et al. 2023 eq 37); they act where
//! the ball surface slides past the pocket at (D/2) ω_R, ω_R its spin
//! relative to the cage. Lei et al. 2023 eq 36 (an empirical land formula in
//! mixed units) and eq 38 (an inlet viscous loss, garbled) are not used.
//!
//! Lubricated contacts add the EHL rolling resistance 2 F_R u of
//! [`crate::lubrication::rolling_resistance`] (Houpert's fits or Biboulet &
//! Houpert 2010, with Aihara's inlet-heating factor and the film's or the
//! method's starvation), and an
//! oil bath or jet the churning M_drag ω_i of
//! [`crate::lubrication::churning`] (SKF 2013).
//!
//! The methods' sum counts every mechanism under full sliding, each alone:
//! an upper estimate. The dynamic model ([`super::dissipation`]) integrates
//! one traction law over each ellipse with all slips together; docs/power.md
//! compares the two.

use crate::cage::GuideLand;
use crate::contact::Curvature;
use crate::geometry::{BearingGeometry, RingKind};
use crate::lubrication::churning::Churning;
use crate::lubrication::drag::DragParameters;
use crate::lubrication::rolling_resistance::{RollingContact, RollingResistance};
use crate::lubrication::{FilmConditions, contact_film};
use crate::math::elliptic;
use crate::quasistatic::Equilibrium;
use crate::quasistatic::contact_motion::contact_motions;
use crate::quasistatic::films::FilmInputs;
use crate::seals::SealFriction;

/// Heathcote's rolling-line position c (ξ = ±c a): the root of
/// c³ − 3c + 1 = 0 in (0, 1), 2 cos 80°.
pub fn heathcote_rolling_line() -> f64 {
    2.0 * 80f64.to_radians().cos()
}

/// I_H = ∫₀¹ (1 − x²)|x² − c²| dx at Heathcote's c.
pub fn heathcote_integral() -> f64 {
    let c = heathcote_rolling_line();
    2.0 / 15.0 - 2.0 / 3.0 * c * c + 4.0 / 3.0 * c.powi(3) - 4.0 / 15.0 * c.powi(5)
}

/// Inputs of the local method besides the solution.
#[derive(Debug, Clone, PartialEq)]
pub struct LocalMethodInputs {
    /// Sliding friction coefficient f_s of the raceway contacts.
    pub sliding_friction: f64,
    /// Elastic-hysteresis coefficient α_h (≈ 0.007 for steel).
    pub hysteresis: f64,
    /// Ball–pocket friction coefficient f_c.
    pub pocket_friction: f64,
    /// Cage weight carried by the pockets when there is no guide land
    /// m_c g \[N\] (0 without gravity).
    pub cage_weight: f64,
    /// Pocket pitch radius r_p \[m\].
    pub pocket_radius: f64,
    /// Guide land, if the cage is ring-guided.
    pub guide: Option<GuideLand>,
    /// Drag of the air–oil mixture.
    pub drag: DragParameters,
    /// Contact seals, if the bearing has them.
    pub seals: Option<SealFriction>,
    /// EHL rolling resistance of the lubricated contacts (None: dry).
    pub rolling_resistance: Option<LubricatedContacts>,
    /// Churning of an oil bath or jet (None: neither).
    pub churning: Option<Churning>,
}

/// The lubricated contacts' rolling resistance and what their films need
/// (the starvation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LubricatedContacts {
    /// The rolling-resistance law.
    pub model: RollingResistance,
    /// The films' lubricant, supply and effective modulus.
    pub films: FilmInputs,
}

impl LubricatedContacts {
    /// Sets the viscosity η₀ at the contact inlets \[Pa·s\] and, if given,
    /// the temperature–viscosity coefficient β_T \[1/K\].
    pub fn set_viscosity(&mut self, viscosity: f64, temperature_viscosity: Option<f64>) {
        self.model.lubricant.viscosity = viscosity;
        self.films.lubricant.viscosity = viscosity;
        if let (Some(h), Some(beta)) = (&mut self.model.heating, temperature_viscosity) {
            h.temperature_viscosity = beta;
        }
    }

    /// Rolling force F_R of a contact \[N\] (`ring_speed` throws an
    /// oil-flow supply's film, `supply` the ring's index).
    pub fn force(&self, c: &RollingContact, supply: usize, ring_speed: f64) -> f64 {
        let film = contact_film(
            &self.films.lubricant,
            &self.films.supply[supply],
            0.0,
            &FilmConditions {
                entrainment_speed: c.entrainment_speed,
                load: c.load,
                rolling_radius: c.rolling_radius,
                effective_modulus: c.effective_modulus,
                ellipticity: c.semi_major / c.semi_minor,
                semi_minor: c.semi_minor,
                ring_speed,
            },
        );
        let starvation = match self.films.supply[supply] {
            crate::lubrication::Supply::Flooded => self.model.replenishment_factor(ring_speed),
            _ => film.starvation_factor,
        };
        self.model.force(c, starvation)
    }
}

/// Losses of the contacts with one raceway, summed over the balls \[W\].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RaceLosses {
    /// Elastic hysteresis H_E.
    pub hysteresis: f64,
    /// Differential (Heathcote) sliding H_D.
    pub differential_sliding: f64,
    /// Spin H_S.
    pub spin: f64,
    /// EHL rolling resistance 2 F_R u.
    pub rolling_resistance: f64,
}

impl RaceLosses {
    /// Sum \[W\].
    pub fn total(&self) -> f64 {
        self.hysteresis + self.differential_sliding + self.spin + self.rolling_resistance
    }
}

/// Power loss of a bearing by the local method \[W\].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LocalPowerLoss {
    /// Ball–inner-raceway contacts.
    pub inner: RaceLosses,
    /// Ball–outer-raceway contacts.
    pub outer: RaceLosses,
    /// Cage guide land.
    pub cage_land: f64,
    /// Ball–pocket friction.
    pub ball_pocket: f64,
    /// Drag on the balls.
    pub ball_drag: f64,
    /// Drag on the cage.
    pub cage_drag: f64,
    /// Friction of the contact seals.
    pub seals: f64,
    /// Churning of an oil bath or jet.
    pub churning: f64,
    /// Inner-ring speed ω_i \[rad/s\].
    pub inner_speed: f64,
}

impl LocalPowerLoss {
    /// Total H \[W\] (Lei et al. 2023 eq 39).
    pub fn total(&self) -> f64 {
        self.inner.total()
            + self.outer.total()
            + self.cage_land
            + self.ball_pocket
            + self.ball_drag
            + self.cage_drag
            + self.seals
            + self.churning
    }

    /// Friction torque H/ω_i \[N·m\] (0 at rest).
    pub fn friction_torque(&self) -> f64 {
        if self.inner_speed != 0.0 {
            self.total() / self.inner_speed.abs()
        } else {
            0.0
        }
    }
}

/// The local method's losses at the solution `eq` of the bearing `geometry`.
pub fn local_power_loss(
    geometry: &BearingGeometry,
    eq: &Equilibrium,
    inputs: &LocalMethodInputs,
) -> LocalPowerLoss {
    let mut out = LocalPowerLoss {
        inner_speed: eq.inner_speed,
        ..Default::default()
    };
    let rb = 0.5 * geometry.ball_diameter;
    let f_s = inputs.sliding_friction;
    let i_h = heathcote_integral();
    for contacts in contact_motions(geometry, eq) {
        for (k, motion) in contacts.iter().enumerate() {
            let Some(m) = motion else { continue };
            let q = m.solution.load;
            let (a, b) = (m.solution.hertz.semi_major, m.solution.hertz.semi_minor);
            let rg = m.raceway.groove_radius;
            let deformed_radius = 2.0 * rg * rb / (rg + rb);
            let e = elliptic::complete(1.0 - (b / a).powi(2)).e;
            let roll = m.rolling_rate().abs();
            let rolling_resistance = inputs.rolling_resistance.as_ref().map_or(0.0, |r| {
                let u = m.entrainment_speed();
                let curvature = Curvature::of_raceway(
                    m.raceway,
                    geometry.ball_diameter,
                    geometry.pitch_diameter,
                    m.solution.contact_angle,
                );
                let contact = RollingContact {
                    entrainment_speed: u,
                    load: q,
                    rolling_radius: curvature.rolling_radius,
                    transverse_radius: curvature.transverse_radius,
                    semi_major: a,
                    semi_minor: b,
                    effective_modulus: r.films.effective_modulus,
                };
                2.0 * r.force(&contact, k, eq.inner_speed) * u
            });
            let losses = RaceLosses {
                hysteresis: 0.1875 * inputs.hysteresis * b * q * roll,
                differential_sliding: 0.75 * i_h * f_s * q * a * a * roll / deformed_radius,
                spin: 0.375 * f_s * q * a * e * m.spin().abs(),
                rolling_resistance,
            };
            let ring = if k == 0 {
                &mut out.inner
            } else {
                &mut out.outer
            };
            ring.hysteresis += losses.hysteresis;
            ring.differential_sliding += losses.differential_sliding;
            ring.spin += losses.spin;
            ring.rolling_resistance += losses.rolling_resistance;
        }
    }
    let cage_speed = eq.cage_speed();
    let mut resisting_torque = 0.0;
    let mut pocket_load = 0.0;
    if let Some(guide) = &inputs.guide {
        let land_speed = match guide.ring {
            RingKind::Inner => eq.inner_speed,
            RingKind::Outer => 0.0,
        };
        let torque = guide
            .forces(&nalgebra::Vector3::zeros(), cage_speed, land_speed)
            .torque;
        out.cage_land = torque * (land_speed - cage_speed);
        resisting_torque += torque.abs();
    } else {
        pocket_load += inputs.cage_weight;
    }
    let drag = &inputs.drag;
    let cage_drag_torque =
        drag.cage_viscous * cage_speed + drag.cage_windage * cage_speed * cage_speed.abs();
    out.cage_drag = cage_drag_torque * cage_speed;
    resisting_torque += cage_drag_torque.abs();
    if inputs.pocket_radius > 0.0 {
        pocket_load += resisting_torque / inputs.pocket_radius;
    }
    let balls = eq.balls.len().max(1) as f64;
    let mean_spin = eq.balls.iter().map(|b| b.spin_speed.abs()).sum::<f64>() / balls;
    out.ball_pocket = inputs.pocket_friction * pocket_load * rb * mean_spin;
    if drag.effective_density > 0.0 {
        for ball in &eq.balls {
            let v_t = ball.radial_position * ball.orbital_speed;
            let w = nalgebra::Vector3::new(ball.spin_axial, ball.spin_radial, 0.0);
            let w_rel = w - ball.orbital_speed * nalgebra::Vector3::x();
            let (f, m) = drag.ball(geometry.ball_diameter, v_t, &w_rel);
            out.ball_drag -= f * v_t + m.dot(&w);
        }
    }
    out.seals = inputs.seals.map_or(0.0, |s| s.power(eq.inner_speed));
    out.churning = inputs.churning.map_or(0.0, |c| c.power(eq.inner_speed));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::{Curvature, HertzCoefficients};
    use crate::material::{Material, effective_modulus};
    use crate::math::roots::brent;
    use crate::traction::TractionGrid;
    use crate::traction::ellipse::{
        ContactKinematics, ContactPatch, TractionIntegration, integrate,
    };
    use crate::traction::{ContactConditions, ModifiedCoulomb};
    use nalgebra::Vector3;

    /// A 7008C-like inner contact: Q = 150 N.
    fn contact() -> (Curvature, HertzCoefficients, f64) {
        let g = crate::geometry::BearingGeometry::new(&crate::GeometrySpec {
            ball_diameter: 7.938e-3,
            ball_count: 15,
            pitch_diameter: 54e-3,
            inner_groove_curvature: 0.52,
            outer_groove_curvature: 0.53,
            clearance: crate::Clearance::FreeContactAngle(15f64.to_radians()),
            preload: false,
        })
        .unwrap();
        let c = Curvature::of_raceway(&g.inner, g.ball_diameter, g.pitch_diameter, 0.3);
        let steel = Material::STEEL_52100;
        let h = HertzCoefficients::exact(&c, effective_modulus(&steel, &steel)).unwrap();
        (c, h, g.inner.groove_radius)
    }

    fn coulomb(friction: f64) -> ModifiedCoulomb {
        ModifiedCoulomb {
            friction,
            stick_speed: 0.0,
            full_speed: 1e-6,
        }
    }

    fn patch(a: f64, b: f64, load: f64, deformed_radius: f64) -> ContactPatch {
        ContactPatch {
            point: Vector3::new(0.0, 0.0, -3e-3),
            normal: Vector3::new(0.0, 0.0, -1.0),
            rolling_direction: Vector3::new(0.0, 1.0, 0.0),
            semi_major: a,
            semi_minor: b,
            load,
            deformed_radius,
        }
    }

    #[test]
    fn heathcote_line_balances_the_friction_and_integral_matches_quadrature() {
        let c = heathcote_rolling_line();
        assert!((c.powi(3) - 3.0 * c + 1.0).abs() < 1e-14);
        // ∫₀^c (1 − x²) = ½ ∫₀¹ (1 − x²): the inner band's friction balances the outer.
        assert!(((c - c.powi(3) / 3.0) - 1.0 / 3.0).abs() < 1e-14);
        let n = 200_000;
        let quad: f64 = (0..n)
            .map(|i| {
                let x = (i as f64 + 0.5) / n as f64;
                (1.0 - x * x) * (x * x - c * c).abs() / n as f64
            })
            .sum();
        assert!((quad - heathcote_integral()).abs() < 1e-9, "{quad}");
    }

    /// The closed-form differential sliding against the engine's own
    /// traction integration over the curved ellipse (Coulomb, f_s = 0.1):
    /// pure rolling about the axis across the rolling direction, the rigid
    /// slip s₀ solved for zero net force; 1.5 % (the grid uses the exact
    /// circular drop, the formula its parabola: 0.8 % at a/R_d = 0.17).
    ///
    /// The patch is made slender (b = a/100): at the contact's own b the
    /// grid also sees the rolling's normal velocity ω_roll η tilted by the
    /// deformed surface, a transverse slip ±ω_roll η ξ/R_d that Heathcote's
    /// in-plane analysis leaves out (+4.7 % on this contact).
    #[test]
    fn differential_sliding_matches_the_ellipse_integral() {
        let (_, h, rg) = contact();
        let load = 150.0;
        let r = h.at_load(load);
        let rb = 0.5 * 7.938e-3;
        let rd = 2.0 * rg * rb / (rg + rb);
        let p = patch(r.semi_major, r.semi_major / 100.0, load, rd);
        let roll = 2000.0;
        let spin = Vector3::new(roll, 0.0, 0.0);
        let method = TractionIntegration::Grid {
            across: 64,
            along: 8,
        };
        let law = coulomb(0.1);
        let cond = ContactConditions::default();
        let grid = TractionGrid::new(method);
        let eval = |s0: f64| {
            integrate(
                &law,
                &grid,
                &ContactKinematics {
                    patch: p,
                    ball_centre: Vector3::zeros(),
                    slip: Vector3::new(0.0, s0, 0.0),
                    relative_spin: spin,
                    conditions: cond,
                },
            )
        };
        let top = roll * r.semi_major.powi(2) / rd;
        let s0 = brent(|s| eval(s).force.y, -top, top, 1e-15).unwrap();
        let grid = eval(s0).dissipation;
        let formula = 0.75 * heathcote_integral() * 0.1 * load * r.semi_major.powi(2) * roll / rd;
        assert!(
            (grid / formula - 1.0).abs() < 0.015,
            "grid {grid} W, formula {formula} W"
        );
    }

    /// Spin under full sliding: the ellipse integral's spin power against
    /// (3/8) f_s Q a E(m) ω_s (Harris & Kotzalas), 1 %.
    #[test]
    fn spin_power_matches_harris() {
        let (_, h, _) = contact();
        let load = 150.0;
        let r = h.at_load(load);
        let p = patch(r.semi_major, r.semi_minor, load, f64::INFINITY);
        let omega_s = 300.0;
        let res = integrate(
            &coulomb(0.1),
            &TractionGrid::new(TractionIntegration::Grid {
                across: 48,
                along: 24,
            }),
            &ContactKinematics {
                patch: p,
                ball_centre: Vector3::zeros(),
                slip: Vector3::zeros(),
                relative_spin: (omega_s * p.normal),
                conditions: ContactConditions::default(),
            },
        );
        let m = 1.0 - (r.semi_minor / r.semi_major).powi(2);
        let harris = 0.375 * 0.1 * load * r.semi_major * elliptic::complete(m).e * omega_s;
        assert!(
            (res.dissipation / harris - 1.0).abs() < 0.01,
            "{} vs {harris}",
            res.dissipation
        );
    }

    /// Lei et al. 2023 eq 23 (E′ of eq 27 corrected to 4(1 − ν²)/E), evaluated as
    /// printed with Harris's a*, b*, δ*, equals (3/16)(δ*/b*²) Σρ b Q with b
    /// from rolldyn's Hertz solution: the reduction docs/power.md states.
    #[test]
    fn seed004_eq23_reduces_to_the_rolling_resistance_form() {
        let (c, h, _) = contact();
        let steel = Material::STEEL_52100;
        let compliance = 2.0 * 4.0 * (1.0 - steel.poisson_ratio.powi(2)) / steel.elastic_modulus;
        let (kappa, k, e) = (h.ellipticity, h.elliptic_k, h.elliptic_e);
        let pi = std::f64::consts::PI;
        let delta_star = 2.0 * k / pi * (pi / (2.0 * kappa * kappa * e)).cbrt();
        let b_star = (2.0 * e / (pi * kappa)).cbrt();
        let sum_rho = c.sum();
        let load: f64 = 150.0;
        let phi = 9.0 / 128.0 * delta_star / b_star
            * (8.0 / 3.0 * sum_rho).powf(2.0 / 3.0)
            * compliance.cbrt()
            * load.powf(4.0 / 3.0);
        let b = h.at_load(load).semi_minor;
        let reduced = 3.0 / 16.0 * delta_star / (b_star * b_star) * sum_rho * b * load;
        assert!((phi / reduced - 1.0).abs() < 1e-9, "{phi} vs {reduced}");
    }
}
