//! Hydrodynamic (EHL) rolling resistance of a lubricated ball–raceway
//! contact: the Poiseuille flow of the inlet drags both surfaces against
//! their rolling (docs/lubrication.md, "Rolling resistance").
//!
//! **Force** (N. Biboulet & L. Houpert, "Hydrodynamic force and moment in
//! pure rolling lubricated contacts. Part 2: point contacts", Proc. IMechE
//! J 224, 2010, eq 32; fully flooded, isothermal, Newtonian, pure
//! rolling, from the isoviscous-rigid to the EHL regime):
//! ```text
//! U = 2 η₀ u / (E' R_x),   W = Q / (E' R_x²),   κ = b/a ≤ 1
//! β = b E' / (π p_h R_x) = 2 a b² E' / (3 Q R_x),   M = β^¼ κ W / U^¾
//! T = (2a/R_x) [ (0.77 β^−⅓ κ^0.12 U^−1/12 − 1.8 β^−¼) / (1 + M/6.6) + 1.8 β^−¼ ] U^¾
//! F_R = T E' R_x²
//! ```
//! u is the entrainment (mean surface) speed relative to the contact, b
//! the Hertz semi-axis along the rolling direction, a across it, E'
//! Hamrock's effective modulus (the engine's, docs/model.md §2.2). The
//! paper fits U from 6e-13 to 1.6e-10 and p_h from 60 MPa to 4 GPa; the
//! law is used outside that range as it extrapolates (∝ U^⅔ at low speed,
//! U^¾ at high). Biboulet & Houpert state that their fully flooded forces
//! are 1.4× (EHL) and 1.6× (isoviscous) Houpert's earlier fits, and
//! that published line-contact fits differ by up to a factor of 5 in the
//! EHL regime.
//!
//! **Houpert's fits** (the default; as Biboulet & Houpert 2010 Part 2,
//! eqs 28–29 quote them, the same U, W, β, κ), joined across the regimes
//! as eq 32 joins its asymptotes (Bălan et al. 2015, eq 3):
//! ```text
//! F_IVR = 0.835 (R_x/R_y)^−0.358 U^0.636 W^0.364 E' R_x²
//! F_EHL = 1.544 β^⅓ κ^−0.577 U^0.656 W^0.466 G^0.022 E' R_x²,   G = α_p E'
//! F_R   = (F_IVR − F_EHL)/(1 + M/6.6) + F_EHL
//! ```
//! Biboulet & Houpert put these at about 0.6–0.7× their fully flooded
//! forces at usual conditions (joined, 0.80–1.37× on a 6206-like contact
//! here, unit test): they correspond to a moderately starved inlet
//! (meniscus at about 3b in EHL), which is how ball bearings run; Bălan et
//! al. 2015 found the rolling torque they measured with 7.938 mm balls and
//! a few drops of oil closest to them (with smaller balls, which leave the
//! oil more room, closer to the fully flooded eq 32). Their load exponent is close to that of SKF's
//! rolling moment (0.54 on the bearing load); eq 32's is about ⅓ (through
//! 2a). [`RollingForceLaw`] chooses; docs/validation.md compares both with
//! SKF's model.
//!
//! **What F_R is, and the forces it leaves on the bodies.** F_R is the
//! Poiseuille shear on each surface, against its motion relative to the
//! contact; the pressure's component along the rolling direction, 2 F_R
//! in all (Biboulet & Houpert 2010 Part 1, eq 32), acts on each body
//! through its centre of curvature in proportion to its curvature, 2 F_R
//! R_x/R_i (the surfaces' slopes x/R_i weight the same pressure). So body i
//! carries a force F_R (2 R_x/R_i − 1) along the entrainment direction and
//! a moment F_R R_i against its rolling; forces and moments of the two
//! bodies cancel, and in pure rolling the pair dissipates
//! ```text
//! P = F_R (u₁ + u₂) = 2 F_R u
//! ```
//! (Biboulet & Houpert 2010 Part 1, eq 45; Part 2, eq 37). On the ball
//! (R₁ = D/2) and its raceway the same system is a force
//! F_R (2 R_x/(D/2) − 1) û at the contact point and a couple −2 F_R R_x e_a
//! about it (e_a = n × û the rolling axis), the ring taking the opposite
//! ([`RollingResistance::ball_load`]).
//!
//! **Inlet shear heating** (Aihara 1987, J. Tribol. 109, 471, the factor
//! fitted to measured rolling torques):
//! ```text
//! L = η₀ β_T u² / k_f,   φ_T = 1 / (1 + 0.29 L^0.78)
//! ```
//! with β_T = −d ln η/dT and k_f the oil's conductivity. Murch & Wilson's
//! film factor 3.94/(3.94 + L^0.62) gives 0.80 instead of 0.78 at L = 1
//! and 0.59 instead of 0.50 at L = 5.
//!
//! **Starvation**: F_R is scaled by the film's reduction factor h_s/h
//! (`lubrication::starvation`). Biboulet & Houpert (Part 1, eq 44) find
//! the rolling force more sensitive to starvation than the film, so this
//! is an upper estimate of a starved contact's force. Where the supply is
//! not stated (flooded) but the lubrication method is, the track's
//! kinematic replenishment starves it instead by SKF's factor (SKF 2013,
//! "kinematic replenishment/starvation reduction factor"):
//! ```text
//! φ_rs = exp(−K_rs ν n (d + D) √(K_z / (2 (D − d))))      (ν mm²/s, n r/min, d, D mm)
//! ```
//! K_rs = 3e-8 for an oil bath or jet, 6e-8 for grease and air–oil.

use super::Lubricant;
use crate::error::{InvalidParameter, require_positive};
use nalgebra::Vector3;

/// Aihara's thermal-loading coefficient and exponent (φ_T = 1/(1 + 0.29 L^0.78)).
const AIHARA: (f64, f64) = (0.29, 0.78);

/// Temperature–viscosity coefficient β_T = −d ln η/dT of an ISO VG 32
/// mineral oil of viscosity index 100 (32 and 5.4 mm²/s at 40 and 100 °C)
/// at 40 °C by ASTM D341 \[1/K\]: the default when a case gives no second
/// viscosity point (test `default_temperature_coefficient_is_the_vg32_slope`).
pub const DEFAULT_TEMPERATURE_VISCOSITY: f64 = 0.0426;

/// The inlet's shear heating: the oil's temperature–viscosity coefficient
/// and thermal conductivity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InletHeating {
    /// β_T = −d ln η/dT \[1/K\], > 0.
    pub temperature_viscosity: f64,
    /// Thermal conductivity of the oil k_f \[W/(m·K)\], > 0.
    pub conductivity: f64,
}

/// The rolling-force fit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RollingForceLaw {
    /// Houpert's fits (Biboulet & Houpert 2010, Part 2 eqs 28–29, joined
    /// as eq 32): a moderately starved inlet.
    #[default]
    Houpert,
    /// Biboulet & Houpert 2010, Part 2 eq 32 (fully flooded, IVR to EHL).
    BibouletHoupert,
}

/// The rolling resistance of the lubricated contacts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollingResistance {
    /// The rolling-force fit.
    pub law: RollingForceLaw,
    /// The lubricant (η₀ at the inlet; a coupled thermal network updates it).
    pub lubricant: Lubricant,
    /// Inlet shear heating (None: isothermal).
    pub heating: Option<InletHeating>,
    /// Kinematic starvation of a flooded supply (None: fully flooded).
    pub replenishment: Option<Replenishment>,
}

/// SKF's kinematic replenishment of the track (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Replenishment {
    /// K_rs: 3e-8 oil bath or jet, 6e-8 grease and air–oil.
    pub constant: f64,
    /// Bore d \[m\].
    pub bore: f64,
    /// Outside diameter D \[m\].
    pub outside_diameter: f64,
    /// Bearing type constant K_z (3.1 deep-groove, 4.4 angular-contact).
    pub type_constant: f64,
    /// Oil density ρ \[kg/m³\] (ν = η₀/ρ).
    pub density: f64,
}

/// K_rs of an oil bath or jet (SKF 2013).
pub const REPLENISHMENT_OIL: f64 = 3e-8;
/// K_rs of grease and air–oil (SKF 2013).
pub const REPLENISHMENT_GREASE: f64 = 6e-8;

/// A contact as the rolling resistance needs it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollingContact {
    /// Entrainment speed u (mean surface speed relative to the contact) \[m/s\].
    pub entrainment_speed: f64,
    /// Normal load Q \[N\].
    pub load: f64,
    /// Rolling-direction radius R_x \[m\].
    pub rolling_radius: f64,
    /// Transverse radius R_y \[m\].
    pub transverse_radius: f64,
    /// Hertz semi-axis across the rolling direction a \[m\].
    pub semi_major: f64,
    /// Hertz semi-axis along the rolling direction b \[m\].
    pub semi_minor: f64,
    /// Effective modulus E' \[Pa\].
    pub effective_modulus: f64,
}

impl RollingResistance {
    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        self.lubricant.validate()?;
        if let Some(h) = &self.heating {
            require_positive("temperature_viscosity", h.temperature_viscosity)?;
            require_positive("oil_thermal_conductivity", h.conductivity)?;
        }
        Ok(())
    }

    /// Isothermal rolling force F_R \[N\] by the chosen fit (module doc); 0
    /// without speed or load.
    pub fn isothermal_force(&self, c: &RollingContact) -> f64 {
        let u = c.entrainment_speed.abs();
        let (a, b) = (c.semi_major, c.semi_minor);
        if !(u > 0.0 && c.load > 0.0 && a > 0.0 && b > 0.0) {
            return 0.0;
        }
        let (ep, rx) = (c.effective_modulus, c.rolling_radius);
        // κ ≤ 1: the semi-axis along the rolling direction over the other.
        let kappa = (b / a).min(a / b);
        let speed = 2.0 * self.lubricant.viscosity * u / (ep * rx);
        let load = c.load / (ep * rx * rx);
        let beta = 2.0 * a * b * b * ep / (3.0 * c.load * rx);
        // The powers as exponentials of the groups' logarithms (evaluated
        // at every loaded contact of every right-hand side).
        let (ln_u, ln_w, ln_beta, ln_kappa) = (speed.ln(), load.ln(), beta.ln(), kappa.ln());
        let moes = (0.25 * ln_beta + ln_kappa + ln_w - 0.75 * ln_u).exp();
        let blend = |rigid: f64, ehl: f64| (rigid - ehl) / (1.0 + moes / 6.6) + ehl;
        let scale = ep * rx * rx;
        if self.law == RollingForceLaw::Houpert {
            let ln_g = (self.lubricant.pressure_viscosity * ep).ln();
            let rigid = 0.835
                * (-0.358 * (rx / c.transverse_radius).ln() + 0.636 * ln_u + 0.364 * ln_w).exp();
            let ehl = 1.544
                * (ln_beta / 3.0 - 0.577 * ln_kappa + 0.656 * ln_u + 0.466 * ln_w + 0.022 * ln_g)
                    .exp();
            return blend(rigid, ehl) * scale;
        }
        let ehl = 1.8 * (0.75 * ln_u - 0.25 * ln_beta).exp();
        let rigid = 0.77 * (-ln_beta / 3.0 + 0.12 * ln_kappa + (2.0 / 3.0) * ln_u).exp();
        (2.0 * a / rx) * blend(rigid, ehl) * scale
    }

    /// Inlet shear heating's reduction φ_T at entrainment speed u \[m/s\]
    /// (Aihara 1987; 1 when isothermal).
    pub fn thermal_factor(&self, entrainment_speed: f64) -> f64 {
        match &self.heating {
            None => 1.0,
            Some(h) => {
                let loading = self.lubricant.viscosity
                    * h.temperature_viscosity
                    * entrainment_speed
                    * entrainment_speed
                    / h.conductivity;
                1.0 / (1.0 + AIHARA.0 * loading.powf(AIHARA.1))
            }
        }
    }

    /// SKF's φ_rs at inner-ring speed `ring_speed` \[rad/s\] (1 without a
    /// replenishment model).
    pub fn replenishment_factor(&self, ring_speed: f64) -> f64 {
        match &self.replenishment {
            None => 1.0,
            Some(r) => {
                let nu = self.lubricant.viscosity / r.density * 1e6;
                let n = ring_speed.abs() * 60.0 / std::f64::consts::TAU;
                let (d, big_d) = (r.bore * 1e3, r.outside_diameter * 1e3);
                let root = (r.type_constant / (2.0 * (big_d - d))).sqrt();
                (-r.constant * nu * n * (d + big_d) * root).exp()
            }
        }
    }

    /// The rolling force F_R \[N\] of contact `c` whose film is starved by
    /// `starvation_factor` (h_s/h in [0, 1]; 1 flooded).
    pub fn force(&self, c: &RollingContact, starvation_factor: f64) -> f64 {
        self.isothermal_force(c) * self.thermal_factor(c.entrainment_speed) * starvation_factor
    }

    /// Power of the rolling force in pure rolling, 2 F_R u \[W\].
    pub fn power(&self, c: &RollingContact, starvation_factor: f64) -> f64 {
        2.0 * self.force(c, starvation_factor) * c.entrainment_speed.abs()
    }

    /// The load on the ball of a contact with rolling force F_R, ball
    /// radius D/2 and rolling-direction radius R_x, entrainment direction
    /// û (unit) and rolling axis e_a = n × û: a force at the contact point
    /// and a couple about it (module doc); the ring takes the opposite.
    pub fn ball_load(
        force: f64,
        ball_radius: f64,
        rolling_radius: f64,
        direction: &Vector3<f64>,
        rolling_axis: &Vector3<f64>,
    ) -> (Vector3<f64>, Vector3<f64>) {
        (
            force * (2.0 * rolling_radius / ball_radius - 1.0) * direction,
            -2.0 * force * rolling_radius * rolling_axis,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::{Curvature, HertzCoefficients};
    use crate::lubrication::PressureViscosity;

    fn model(viscosity: f64) -> RollingResistance {
        RollingResistance {
            law: RollingForceLaw::BibouletHoupert,
            lubricant: Lubricant {
                viscosity,
                pressure_viscosity: 2e-8,
                pressure_model: PressureViscosity::Barus,
            },
            heating: None,
            replenishment: None,
        }
    }

    /// A 6206-like inner contact (D = 9.525 mm, d_m = 46 mm, f = 0.52,
    /// α = 0, steel E = 208 GPa, ν = 0.3) at load Q, by the engine's Hertz
    /// solution.
    fn contact(u: f64, q: f64) -> (RollingContact, f64) {
        let (d, dm, f) = (9.525e-3, 46e-3, 0.52);
        let ep = 2.08e11 / (1.0 - 0.09);
        let rx = 0.5 * d * (1.0 - d / dm);
        let ry = f * d / (2.0 * f - 1.0);
        let curvature = Curvature {
            rolling_radius: rx,
            transverse_radius: ry,
        };
        let h = HertzCoefficients::exact(&curvature, ep).unwrap();
        let e = h.at_load(q);
        (
            RollingContact {
                entrainment_speed: u,
                load: q,
                rolling_radius: rx,
                transverse_radius: ry,
                semi_major: e.semi_major,
                semi_minor: e.semi_minor,
                effective_modulus: ep,
            },
            ry,
        )
    }

    /// Bălan, Houpert, Tufescu & Olaru 2015 (Lubricants 3, 222, eqs 1–4):
    /// the same fit written with the radii ratio k = R_y/R_x and the Hertz
    /// relations substituted, an independent form of eq 32.
    fn balan(c: &RollingContact, ry: f64, viscosity: f64) -> f64 {
        let (ep, rx) = (c.effective_modulus, c.rolling_radius);
        let k = ry / rx;
        let u = viscosity * c.entrainment_speed / (ep * rx);
        let w = c.load / (ep * rx * rx);
        let rigid = 2.9766 * ep * rx * rx * k.powf(0.3316) * w.cbrt() * u.powf(2.0 / 3.0);
        let ehl = 7.5826 * ep * rx * rx * k.powf(0.4055) * w.cbrt() * u.powf(0.75);
        let m = 0.5549 * k.powf(-0.6029) * w * u.powf(-0.75);
        (rigid - ehl) / (1.0 + m / 6.6) + ehl
    }

    /// Eq 32 against Bălan et al.'s closed form over loads 50–1000 N and
    /// speeds 1–10 m/s (1.5 %: the two are fits of the same numerical
    /// results, stated to agree within 1 %); and the worked point of
    /// η₀ = 20 mPa·s, u = 5 m/s, Q = 500 N: about 0.2 N.
    #[test]
    fn eq32_agrees_with_balans_closed_form() {
        for (eta, u, q) in [
            (0.02, 5.0, 500.0),
            (0.02, 5.0, 50.0),
            (0.05, 1.0, 1000.0),
            (0.01, 10.0, 200.0),
        ] {
            let (c, ry) = contact(u, q);
            let f = model(eta).isothermal_force(&c);
            let g = balan(&c, ry, eta);
            assert!((f / g - 1.0).abs() < 0.015, "{eta} {u} {q}: {f} vs {g}");
        }
        let (c, _) = contact(5.0, 500.0);
        let f = model(0.02).isothermal_force(&c);
        assert!((f - 0.198).abs() < 0.01, "{f}");
    }

    /// The asymptotes: F_R ∝ U^⅔ where the contact is isoviscous-rigid
    /// (light load, M → 0), U^¾ in the EHL limit (M → ∞), and the power
    /// 2 F_R u; no force without speed or load.
    #[test]
    fn regimes_and_power() {
        let slope = |q: f64, u: f64| {
            let (c, _) = contact(u, q);
            let (c2, _) = contact(1.01 * u, q);
            let m = model(0.02);
            (m.isothermal_force(&c2) / m.isothermal_force(&c)).ln() / 1.01f64.ln()
        };
        assert!(
            (slope(1e-3, 1e3) - 2.0 / 3.0).abs() < 0.02,
            "{}",
            slope(1e-3, 1e3)
        );
        assert!(
            (slope(5000.0, 0.05) - 0.75).abs() < 0.02,
            "{}",
            slope(5000.0, 0.05)
        );
        let (c, _) = contact(5.0, 500.0);
        let m = model(0.02);
        assert_eq!(m.power(&c, 1.0), 2.0 * m.force(&c, 1.0) * 5.0);
        assert_eq!(m.force(&c, 0.5), 0.5 * m.force(&c, 1.0));
        let (still, _) = contact(0.0, 500.0);
        assert_eq!(m.isothermal_force(&still), 0.0);
    }

    /// Houpert's fits against eq 32 (a 6206-like contact, 20 mPa·s,
    /// α_p 2e-8): Biboulet & Houpert put the older fits at 0.6–0.7× theirs
    /// at usual conditions; joined across the regimes the two differ by
    /// less than a factor of 2 here (0.97 at 5 m/s and 500 N, 1.17 at
    /// 2 m/s and 1 kN: the older fit grows faster with load).
    #[test]
    fn houperts_fits_and_the_flooded_force_differ_by_less_than_two() {
        for (u, q) in [(5.0, 500.0), (2.0, 1000.0), (10.0, 200.0), (1.0, 2000.0)] {
            let (c, _) = contact(u, q);
            let flooded = model(0.02).isothermal_force(&c);
            let older = RollingResistance {
                law: RollingForceLaw::Houpert,
                ..model(0.02)
            }
            .isothermal_force(&c);
            let ratio = older / flooded;
            eprintln!("{u} m/s {q} N: Houpert / eq 32 = {ratio:.3}");
            assert!((0.5..2.0).contains(&ratio), "{u} {q}: {ratio}");
        }
    }

    /// Aihara's factor: 1 isothermal, 1/(1 + 0.29) at L = 1, falling with
    /// speed and viscosity.
    #[test]
    fn thermal_factor_follows_aihara() {
        let mut m = model(0.02);
        assert_eq!(m.thermal_factor(10.0), 1.0);
        m.heating = Some(InletHeating {
            temperature_viscosity: 0.04,
            conductivity: 0.13,
        });
        // L = η β u²/k = 1 at u² = k/(η β).
        let u = (0.13f64 / (0.02 * 0.04)).sqrt();
        assert!((m.thermal_factor(u) - 1.0 / 1.29).abs() < 1e-12);
        assert!(m.thermal_factor(2.0 * u) < m.thermal_factor(u));
        assert!(m.validate().is_ok());
    }

    /// SKF's φ_rs: a 6205 (25 × 52 mm, K_z 3.1) at 3000 r/min in a
    /// 20 mm²/s oil bath: exp(−3e-8 · 20 · 3000 · 77 · √(3.1/54)) = 0.9673.
    #[test]
    fn replenishment_factor_of_a_6205() {
        let mut m = model(0.0172);
        assert_eq!(m.replenishment_factor(314.0), 1.0);
        m.replenishment = Some(Replenishment {
            constant: REPLENISHMENT_OIL,
            bore: 25e-3,
            outside_diameter: 52e-3,
            type_constant: 3.1,
            density: 860.0,
        });
        let w = 3000.0 * std::f64::consts::TAU / 60.0;
        let expected = (-3e-8f64 * 20.0 * 3000.0 * 77.0 * (3.1f64 / 54.0).sqrt()).exp();
        assert!((m.replenishment_factor(w) - expected).abs() < 1e-12);
        assert!((expected - 0.9673).abs() < 1e-4, "{expected}");
    }

    /// The ball's share and the ring's (the opposite) conserve momentum;
    /// with the ball's centre at q = P − (D/2) n the force at P and the
    /// couple are a force F_R (2R_x/(D/2) − 1) through the centre and a
    /// moment F_R D/2 against the rolling; in pure rolling (the ball
    /// turning at u/(D/2) about e_a, the ring at −u/R₂ with
    /// 1/R_x = 2/D + 1/R₂) the pair dissipates 2 F_R u.
    #[test]
    fn ball_load_dissipates_twice_force_times_speed_in_pure_rolling() {
        let (rb, r2) = (4e-3, 12e-3);
        let rx = 1.0 / (1.0 / rb + 1.0 / r2);
        let n = Vector3::new(0.0, 0.0, -1.0);
        let u_hat = Vector3::new(1.0, 0.0, 0.0);
        let e_a = n.cross(&u_hat);
        let (f, u) = (0.3, 5.0);
        let (force, couple) = RollingResistance::ball_load(f, rb, rx, &u_hat, &e_a);
        // Moment about the ball centre q = P − rb n: couple + (P − q) × force.
        let about_centre = couple + (rb * n).cross(&force);
        let ball_spin = (u / rb) * e_a;
        assert!((about_centre.dot(&ball_spin) + f * u).abs() < 1e-12);
        let ring_spin = -(u / r2) * e_a;
        // Relative rolling u/R_x; the pair's power −C·(ω_b − ω_r) (no slip).
        let power = -couple.dot(&(ball_spin - ring_spin));
        assert!((power - 2.0 * f * u).abs() < 1e-12, "{power}");
        assert!((force.norm() - f * (2.0 * rx / rb - 1.0)).abs() < 1e-15);
    }

    /// β_T of the ISO VG 32 oil at 40 °C by Walther's law (ASTM D341,
    /// log₁₀ log₁₀(ν + 0.7) = A − B log₁₀ T): −d ln ν/dT = B Y (ν + 0.7)
    /// ln 10 / (T ν), Y = log₁₀(ν + 0.7), the density held constant.
    #[test]
    fn default_temperature_coefficient_is_the_vg32_slope() {
        let walther = |nu: f64| (nu + 0.7f64).log10().log10();
        let (t1, t2) = (313.15f64, 373.15f64);
        let b = (walther(32.0) - walther(5.4)) / (t2.log10() - t1.log10());
        let slope = b * (32.7f64).log10() * 32.7 * std::f64::consts::LN_10 / (t1 * 32.0);
        assert!(
            (slope / DEFAULT_TEMPERATURE_VISCOSITY - 1.0).abs() < 0.005,
            "{slope}"
        );
    }
}
