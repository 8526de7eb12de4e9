//! Normal force laws of a ball–raceway (or ball–pocket) contact, docs/model.md §2.3.
//!
//! With penetration δ > 0, its rate δ̇ (positive while approaching) and K_c
//! from the Hertz tables:
//!
//! | law | force | source |
//! |---|---|---|
//! | `hertz` | K_c δ^{3/2} | Hertz (1882) |
//! | `lankarani_nikravesh` | K_c δ^{3/2} [1 + 3(1 − e²)/4 · δ̇/δ̇⁻] | Lankarani & Nikravesh, J. Mech. Des. 112 (1990) 369; Shan et al. 2023 eqs 11/13 (which print D δ without K_c) |
//! | `hunt_crossley` | K_c δ^{3/2} [1 + 3(1 − e)/2 · δ̇/δ̇⁻] | Hunt & Crossley, J. Appl. Mech. 42 (1975) 440 |
//! | `flores` | K_c δ^{3/2} [1 + 8(1 − e)/(5e) · δ̇/δ̇⁻] | Flores et al., Nonlinear Dyn. 65 (2011) 383 |
//! | `viscous` | K_c δ^{3/2} + c_n δ̇ | c_n given, or 2ζ√(k_lin m) with k_lin = 1.5 K_c δ^{1/2} |
//! | `material` | K_c δ^{3/2} [1 + (3/2) d δ̇] | Hunt & Crossley, J. Appl. Mech. 42 (1975) 440, with the material's constant d |
//!
//! **The material law** is Hunt & Crossley's own form: the damping factor d
//! \[s/m\] is a property of the material, not of an impact, and the
//! restitution of an impact at speed v is e ≈ 1 − d v (small d v). Hunt &
//! Crossley report d = 0.08–0.32 s/m for steel, bronze and ivory from
//! Goldsmith's (1960) impact measurements; the default
//! [`DEFAULT_STEEL_DISSIPATION`] takes the low end for hardened bearing
//! steel, the most elastic of the three (an assumption, docs/model.md §2.3).
//! It needs no episode memory, so a ball that stays in contact is damped by
//! its material alone: the contact's linearised damping is
//! c = (3/2) d Q, a damping ratio ζ = (3/4) d Q/√(k m) of the ball on the
//! contact (a few per cent for a 6205 at 100 N), where the episode laws with
//! the impact-speed floor give a persistent contact tens of times its
//! critical damping.
//!
//! δ̇⁻ is the approach speed at the start of the current contact episode,
//! kept by [`ContactEpisode`]: recorded when a contact closes, only at
//! accepted integrator steps, and clamped below by `v_floor` (a persistent
//! rolling contact has no impact speed; without the floor the damping term
//! diverges). Until an accepted step records it, the current |δ̇| (floored)
//! stands in. The force is clamped at ≥ 0: contacts never pull.

use crate::error::InvalidParameter;
use serde::{Deserialize, Serialize};

/// Default lower bound of the recorded impact speed δ̇⁻ \[m/s\]. Ball radial
/// speeds inside a 10 µm clearance at cage frequencies of 50–100 Hz are of
/// order 2π·f·c ≈ 3–6 mm/s (Shan et al. 2023's 6304), so 1 mm/s sits below real
/// impacts and only bounds the persistent rolling contacts.
pub const DEFAULT_IMPACT_SPEED_FLOOR: f64 = 1.0e-3;

/// Hunt & Crossley's damping factor d of hardened bearing steel \[s/m\]:
/// the low end of their 0.08–0.32 s/m for steel, bronze and ivory (module
/// doc); restitution 0.992 at 0.1 m/s, 0.96 at 0.5 m/s.
pub const DEFAULT_STEEL_DISSIPATION: f64 = 0.08;

/// State of one contact as the force law sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactState {
    /// Hertz constant K_c \[N/m^{1.5}\].
    pub stiffness: f64,
    /// Penetration δ \[m\].
    pub penetration: f64,
    /// Penetration rate δ̇ \[m/s\], positive while approaching.
    pub penetration_rate: f64,
    /// Impact speed of the episode δ̇⁻ \[m/s\], already floored (> 0).
    pub impact_speed: f64,
    /// Effective mass of the contact \[kg\] (ball mass for a ball on a ring).
    pub effective_mass: f64,
}

/// A normal force law: the trait behind which built-in and research laws sit.
pub trait NormalLaw {
    /// Normal force Q ≥ 0 \[N\]; 0 when δ ≤ 0.
    fn force(&self, contact: &ContactState) -> f64;
}

/// The built-in normal force laws (case file: `model.normal_law`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(tag = "law", rename_all = "snake_case", deny_unknown_fields)]
pub enum NormalForceLaw {
    /// Elastic Hertz law.
    #[default]
    Hertz,
    /// Lankarani–Nikravesh hysteresis damping; coefficient of restitution e.
    LankaraniNikravesh {
        /// Coefficient of restitution e in (0, 1].
        restitution: f64,
    },
    /// Hunt–Crossley hysteresis damping.
    HuntCrossley {
        /// Coefficient of restitution e in (0, 1].
        restitution: f64,
    },
    /// Flores et al. hysteresis damping (valid down to low e).
    Flores {
        /// Coefficient of restitution e in (0, 1].
        restitution: f64,
    },
    /// Hertz spring plus linear viscous damper; give exactly one of
    /// `damping` and `damping_ratio`.
    Viscous {
        /// Damping coefficient c_n \[N·s/m\], ≥ 0.
        #[serde(default)]
        damping: Option<f64>,
        /// Damping ratio ζ ≥ 0 of the contact linearised at its current δ:
        /// c_n = 2ζ√(1.5 K_c δ^{1/2} m).
        #[serde(default)]
        damping_ratio: Option<f64>,
    },
    /// Hunt–Crossley damping with the material's constant factor d
    /// (no episode memory).
    Material {
        /// Damping factor d \[s/m\] ≥ 0 (restitution e ≈ 1 − d v).
        #[serde(default = "default_dissipation")]
        dissipation: f64,
    },
}

fn default_dissipation() -> f64 {
    DEFAULT_STEEL_DISSIPATION
}

impl NormalForceLaw {
    /// Case-file names of the laws.
    pub const NAMES: [&'static str; 6] = [
        "hertz",
        "lankarani_nikravesh",
        "hunt_crossley",
        "flores",
        "viscous",
        "material",
    ];

    /// The default law of a case: the material's damping with
    /// [`DEFAULT_STEEL_DISSIPATION`].
    pub const MATERIAL: Self = Self::Material {
        dissipation: DEFAULT_STEEL_DISSIPATION,
    };

    /// The case-file name of this law.
    pub fn name(&self) -> &'static str {
        match self {
            Self::Hertz => "hertz",
            Self::LankaraniNikravesh { .. } => "lankarani_nikravesh",
            Self::HuntCrossley { .. } => "hunt_crossley",
            Self::Flores { .. } => "flores",
            Self::Viscous { .. } => "viscous",
            Self::Material { .. } => "material",
        }
    }

    /// Checks the law's parameters; the error names the field.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        let restitution = |e: f64| {
            if e.is_finite() && e > 0.0 && e <= 1.0 {
                Ok(())
            } else {
                Err(InvalidParameter::new(
                    "restitution",
                    e,
                    "coefficient of restitution must lie in (0, 1]",
                ))
            }
        };
        match *self {
            Self::Hertz => Ok(()),
            Self::Material { dissipation } => {
                if dissipation.is_finite() && (0.0..=10.0).contains(&dissipation) {
                    Ok(())
                } else {
                    Err(InvalidParameter::new(
                        "dissipation",
                        dissipation,
                        "Hunt–Crossley damping factor must lie in [0, 10] s/m (steel: 0.08–0.32)",
                    ))
                }
            }
            Self::LankaraniNikravesh { restitution: e }
            | Self::HuntCrossley { restitution: e }
            | Self::Flores { restitution: e } => restitution(e),
            Self::Viscous {
                damping,
                damping_ratio,
            } => match (damping, damping_ratio) {
                (Some(c), None) if c.is_finite() && c >= 0.0 => Ok(()),
                (Some(c), None) => Err(InvalidParameter::new(
                    "damping",
                    c,
                    "damping coefficient must be ≥ 0",
                )),
                (None, Some(z)) if z.is_finite() && z >= 0.0 => Ok(()),
                (None, Some(z)) => Err(InvalidParameter::new(
                    "damping_ratio",
                    z,
                    "damping ratio must be ≥ 0",
                )),
                (Some(_), Some(_)) => Err(InvalidParameter::new(
                    "damping_ratio",
                    "given",
                    "give either damping or damping_ratio, not both",
                )),
                (None, None) => Err(InvalidParameter::new(
                    "damping",
                    "missing",
                    "the viscous law needs damping (N·s/m) or damping_ratio",
                )),
            },
        }
    }

    /// The hysteresis factor χ of the `K_c δ^{3/2}(1 + χ δ̇/δ̇⁻)` laws.
    pub fn hysteresis_factor(&self) -> Option<f64> {
        match *self {
            Self::LankaraniNikravesh { restitution: e } => Some(0.75 * (1.0 - e * e)),
            Self::HuntCrossley { restitution: e } => Some(1.5 * (1.0 - e)),
            Self::Flores { restitution: e } => Some(1.6 * (1.0 - e) / e),
            _ => None,
        }
    }
}

impl NormalLaw for NormalForceLaw {
    #[inline]
    fn force(&self, c: &ContactState) -> f64 {
        if c.penetration <= 0.0 {
            return 0.0;
        }
        let sqrt_delta = c.penetration.sqrt();
        let elastic = c.stiffness * c.penetration * sqrt_delta;
        let q = match *self {
            Self::Hertz => elastic,
            Self::Material { dissipation } => {
                elastic * (1.0 + 1.5 * dissipation * c.penetration_rate)
            }
            Self::Viscous {
                damping,
                damping_ratio,
            } => {
                let coefficient = match (damping, damping_ratio) {
                    (Some(cn), _) => cn,
                    (None, Some(zeta)) => {
                        2.0 * zeta * (1.5 * c.stiffness * sqrt_delta * c.effective_mass).sqrt()
                    }
                    (None, None) => 0.0,
                };
                elastic + coefficient * c.penetration_rate
            }
            _ => {
                let chi = self.hysteresis_factor().unwrap_or(0.0);
                elastic * (1.0 + chi * c.penetration_rate / c.impact_speed)
            }
        };
        q.max(0.0)
    }
}

/// Memory of one contact episode: the approach speed δ̇⁻ at closing.
/// Update it only at accepted integrator steps (never inside RK stages).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactEpisode {
    impact_speed: Option<f64>,
}

impl ContactEpisode {
    /// The impact speed to use now: the recorded one, or (before an accepted
    /// step has recorded it) the current |δ̇|; never below `floor`.
    #[inline]
    pub fn impact_speed(&self, penetration_rate: f64, floor: f64) -> f64 {
        self.impact_speed
            .unwrap_or(penetration_rate.abs())
            .max(floor)
    }

    /// Records the episode state after an accepted step: a contact that is
    /// closed (δ > 0) and has no record gets δ̇⁻ = max(δ̇, floor); an open
    /// contact forgets its record.
    pub fn accept(&mut self, penetration: f64, penetration_rate: f64, floor: f64) {
        if penetration > 0.0 {
            if self.impact_speed.is_none() {
                self.impact_speed = Some(penetration_rate.max(floor));
            }
        } else {
            self.impact_speed = None;
        }
    }

    /// The recorded impact speed, if the contact is in an episode.
    pub fn recorded(&self) -> Option<f64> {
        self.impact_speed
    }

    /// An episode with this record (a restored checkpoint).
    pub fn with_record(impact_speed: Option<f64>) -> Self {
        Self { impact_speed }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn state(delta: f64, rate: f64) -> ContactState {
        ContactState {
            stiffness: 1e10,
            penetration: delta,
            penetration_rate: rate,
            impact_speed: 0.1,
            effective_mass: 1e-3,
        }
    }

    #[test]
    fn never_pulls_and_zero_when_open() {
        let laws = [
            NormalForceLaw::Hertz,
            NormalForceLaw::LankaraniNikravesh { restitution: 0.5 },
            NormalForceLaw::HuntCrossley { restitution: 0.5 },
            NormalForceLaw::Flores { restitution: 0.5 },
            NormalForceLaw::MATERIAL,
            NormalForceLaw::Viscous {
                damping: Some(1e5),
                damping_ratio: None,
            },
        ];
        for law in laws {
            assert_eq!(law.force(&state(-1e-6, 1.0)), 0.0);
            assert!(law.force(&state(1e-6, -100.0)) >= 0.0);
        }
    }

    #[test]
    fn hysteresis_laws_reduce_to_hertz_at_rest() {
        let h = NormalForceLaw::Hertz.force(&state(1e-6, 0.0));
        let ln = NormalForceLaw::LankaraniNikravesh { restitution: 0.7 }.force(&state(1e-6, 0.0));
        assert_eq!(h, ln);
        assert!((h - 1e10 * 1e-9).abs() < 1e-9);
    }

    #[test]
    fn episode_records_only_on_accept_and_floors() {
        let mut ep = ContactEpisode::default();
        assert_eq!(ep.impact_speed(0.05, 1e-3), 0.05);
        ep.accept(1e-7, 1e-5, 1e-3);
        assert_eq!(ep.recorded(), Some(1e-3));
        ep.accept(2e-7, 0.5, 1e-3);
        assert_eq!(
            ep.recorded(),
            Some(1e-3),
            "record is kept during the episode"
        );
        ep.accept(-1e-9, -0.1, 1e-3);
        assert_eq!(ep.recorded(), None);
    }

    /// Hunt & Crossley's restitution: a ball of mass m dropped at v on a
    /// Hertz contact with the material law bounces back at e v, with
    /// 1 − e ≈ d v for small d v (their eq. 12, to first order).
    #[test]
    fn material_law_restitution_follows_hunt_crossley() {
        let d = DEFAULT_STEEL_DISSIPATION;
        let law = NormalForceLaw::Material { dissipation: d };
        for v in [0.05, 0.2, 0.5] {
            // Semi-implicit Euler on m ẍ = −Q(x, ẋ), x the penetration.
            let (m, k) = (1e-3, 1e10);
            let (mut x, mut u) = (0.0f64, v);
            let dt = 1e-10;
            loop {
                let q = law.force(&ContactState {
                    stiffness: k,
                    penetration: x,
                    penetration_rate: u,
                    impact_speed: 1.0,
                    effective_mass: m,
                });
                u -= q / m * dt;
                x += u * dt;
                if x < 0.0 {
                    break;
                }
            }
            let e = -u / v;
            let expected = 1.0 - d * v;
            assert!(
                (e - expected).abs() < 0.1 * d * v,
                "v {v}: e {e} against 1 − d v = {expected}"
            );
        }
    }

    #[test]
    fn validation_names_the_field() {
        let e = NormalForceLaw::LankaraniNikravesh { restitution: 1.5 }
            .validate()
            .unwrap_err();
        assert_eq!(e.field, "restitution");
    }
}
