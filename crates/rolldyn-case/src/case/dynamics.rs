//! The dynamic model's parameters from a case (`rolldyn run`): inner-ring
//! inertia (estimated from the ring annulus when not given), cage, pocket
//! law, guide land, drag, supports and the film supply (docs/model.md §1, §5).

use super::{Case, Invalid, checked, non_negative, positive, positive_number};
use crate::raw::{CageGuidance, PocketLawChoice, RawDrag, RawSeals};
use rolldyn::RingKind;
use rolldyn::cage::pocket::hertz_pocket_stiffness;
use rolldyn::cage::{PocketLaw, PocketSqueeze};
use rolldyn::dynamics::{
    CageParameters, DragParameters, DynamicsParameters, GuideLand, SealFriction,
};
use rolldyn::operating::LoadProfile;
use rolldyn::traction::ModifiedCoulomb;

/// Film force at the pocket wall of the gupta_film law \[N\] (Deng et al. 2022
/// eq 28: K'_c = 11/C_p with C_p the per-side clearance).
pub const GUPTA_WALL_FORCE: f64 = 11.0;

/// Default least pocket film of the squeeze damping \[m\]: of the order
/// of the composite roughness of a ball (R_q ≈ 0.02 µm) and a machined
/// polymer pocket (R_a 0.4–1.6 µm). An assumption; only used with
/// `cage.pocket_squeeze_film`.
pub const DEFAULT_POCKET_MIN_FILM: f64 = 1e-6;

/// Default ball–pocket friction coefficient (lubricated steel on cage
/// material; Deng et al. 2022 and Zhang et al. 2025 use 0.01–0.1).
pub const DEFAULT_POCKET_FRICTION: f64 = 0.05;

/// Mass \[kg\] and transverse moment of inertia about a diameter through
/// its centre \[kg·m²\] of a ring as a uniform annulus of diameters
/// `inner` and `outer`, width `width` and density `density`.
fn annulus(inner: f64, outer: f64, width: f64, density: f64) -> (f64, f64) {
    let (ro, ri) = (outer / 2.0, inner / 2.0);
    let mass = density * std::f64::consts::PI * (ro * ro - ri * ri) * width;
    (
        mass,
        mass * (3.0 * (ro * ro + ri * ri) + width * width) / 12.0,
    )
}

impl Case {
    /// The outer ring's mass \[kg\]: `outer_ring.mass`, or the ring alone
    /// as an annulus from its groove bottom to the outside diameter (what
    /// slides in the housing under a floating bearing).
    pub fn outer_ring_mass(&self) -> Result<f64, Invalid> {
        if let Some(outer) = &self.outer_ring {
            return Ok(outer.mass);
        }
        let g = &self.bearing.geometry;
        match (self.bearing.outside_diameter, self.bearing.width) {
            (Some(od), Some(width)) => Ok(annulus(
                g.outer.groove_bottom_diameter,
                od,
                width,
                self.materials.rings.material.density,
            )
            .0),
            _ => Err(Invalid::missing(
                "outer_ring.mass",
                "a floating bearing in motion needs its outer ring's mass (or bearing.outside_diameter and bearing.width to estimate the ring)",
            )),
        }
    }

    /// The parameters of the dynamic model, with defaults applied. A value
    /// a dynamic run needs but the case lacks is an error naming its key.
    pub fn dynamics_parameters(&self) -> Result<DynamicsParameters, Invalid> {
        let g = &self.bearing.geometry;
        // Both tilts held at zero (`operating.fixed_tilt`): a shaft held in
        // tilt by its other bearing. Any other prescribed displacement is
        // quasi-static only.
        let tilt_held = self.prescribed_displacement[3..] == [Some(0.0), Some(0.0)];
        if let Some(k) = self
            .prescribed_displacement
            .iter()
            .enumerate()
            .position(|(k, p)| p.is_some() && !(tilt_held && k >= 3))
        {
            let key = [
                "displacement_x",
                "displacement_y",
                "displacement_z",
                "tilt_y",
                "tilt_z",
            ][k];
            return Err(Invalid::new(
                format!("operating.{key}"),
                None,
                "prescribed ring displacements are quasi-static only: a dynamic run moves the ring under its loads (it can hold both tilts at zero: operating.fixed_tilt)",
            ));
        }
        let speed = self.speed.clone().ok_or_else(|| {
            Invalid::missing(
                "operating.speed",
                "a dynamic run needs the inner-ring speed (or operating.speed_profile)",
            )
        })?;
        let need =
            |v: Option<f64>, key: &str, what: &str| v.ok_or_else(|| Invalid::missing(key, what));
        // Inner ring alone, as a steel annulus from bore to raceway, if not given.
        let ring_density = self.materials.rings.material.density;
        let annulus = match (self.bearing.bore, self.bearing.width) {
            (Some(bore), Some(width)) => Some(annulus(
                bore,
                g.inner.groove_bottom_diameter,
                width,
                ring_density,
            )),
            _ => None,
        };
        let inner_ring_mass = self.inner_ring_mass.or(annulus.map(|a| a.0)).ok_or_else(|| {
            Invalid::missing("inner_ring.mass", "a dynamic run needs the inner-ring mass (or bearing.bore and bearing.width to estimate the ring alone)")
        })?;
        let inner_ring_tilt_inertia = self
            .inner_ring_tilt_inertia
            .or(annulus.map(|a| a.1 * inner_ring_mass / a.0))
            .ok_or_else(|| {
                Invalid::missing(
                    "inner_ring.tilt_inertia",
                    "a dynamic run needs the inner-ring tilt inertia",
                )
            })?;
        let c = &self.cage;
        let cage = CageParameters {
            mass: need(c.mass, "cage.mass", "a dynamic run needs the cage mass")?,
            inertia: need(
                c.inertia,
                "cage.inertia",
                "a dynamic run needs the cage moment of inertia",
            )?,
            pitch_radius: g.pitch_diameter / 2.0,
            pocket_clearance: need(
                c.pocket_clearance,
                "cage.pocket_clearance",
                "a dynamic run needs the pocket clearance",
            )?,
            pocket_shape: c.pocket_shape,
            pocket_law: self.pocket_law()?,
            pocket_squeeze: self.pocket_squeeze()?,
            unbalance: c.unbalance,
            pocket_friction: ModifiedCoulomb {
                friction: c.pocket_friction,
                stick_speed: 0.0,
                full_speed: 1e-3,
            },
            whirl: c.whirl,
            guide: self.guide_land()?,
        };
        Ok(DynamicsParameters {
            inner_ring_mass,
            inner_ring_tilt_inertia,
            cage,
            normal_law: self.normal_law,
            impact_speed_floor: self.impact_speed_floor,
            traction: self.traction,
            traction_integration: self.traction_integration,
            speed,
            drive: self.drive.clone(),
            unbalance: self.unbalance,
            loads: self
                .load_profile
                .clone()
                .unwrap_or(LoadProfile::Constant(self.loads)),
            inner_support: self.inner_support_with_bearing_damping()?,
            outer_ring: self.outer_ring,
            sliding_outer_ring: None,
            rolling_hysteresis: self.rolling_hysteresis,
            gravity: if self.gravity { STANDARD_GRAVITY } else { 0.0 },
            planar: self.planar,
            inner_ring_tilt_held: tilt_held,
            drag: self.drag,
            seals: self.seals,
            rolling_resistance: self.rolling_resistance()?,
            churning: self.churning()?,
            surface: self.surface.clone(),
            film_supply: self
                .lubricant
                .as_ref()
                .map_or(Default::default(), |l| l.supply),
            film_in_approach: self.film_in_approach,
            mixed_lubrication: self.mixed_lubrication,
        })
    }
}

impl Case {
    /// The bearing's radial stiffness k_r \[N/m\] at the case's operating
    /// point (its loads and final speed, dry, the case's raceway control
    /// and held displacements): the quasi-static 5 × 5 stiffness along the
    /// radial load (along z without one). Err: why the quasi-static solve
    /// failed, or a stiffness that is not positive.
    pub fn radial_stiffness(&self) -> Result<f64, String> {
        let solver = rolldyn::quasistatic::QuasiStaticSolver::new(
            &self.bearing.geometry,
            &self.materials.ball.material,
            &self.materials.rings.material,
            self.contact_stiffness,
        )
        .map_err(|e| e.to_string())?;
        let conditions = rolldyn::quasistatic::Conditions {
            loads: self.loads,
            inner_speed: self.speed.as_ref().map_or(0.0, |s| s.final_speed()),
            control: self.raceway_control,
        };
        let k = solver
            .solve(&conditions, &self.solver_options())
            .map_err(|e| e.to_string())?
            .stiffness;
        let (fy, fz) = (self.loads.force[1], self.loads.force[2]);
        let norm = fy.hypot(fz);
        let (cy, cz) = if norm > 0.0 {
            (fy / norm, fz / norm)
        } else {
            (0.0, 1.0)
        };
        let radial = cy * cy * k[1][1] + cy * cz * (k[1][2] + k[2][1]) + cz * cz * k[2][2];
        if radial.is_finite() && radial > 0.0 {
            Ok(radial)
        } else {
            Err(format!("a radial stiffness of {radial} N/m"))
        }
    }

    /// `inner_ring`'s support with the bearing's damping between the rings
    /// (`model.bearing_damping` τ: c = τ k_r radially, on the inner ring
    /// against the fixed outer ring), added to any support damping the
    /// case gives.
    fn inner_support_with_bearing_damping(&self) -> Result<rolldyn::dynamics::Support, Invalid> {
        let mut support = self.inner_support;
        let Some(tau) = self.bearing_damping.filter(|&t| t > 0.0) else {
            return Ok(support);
        };
        let value = Some(format!("{tau:e} s"));
        if self.outer_ring.is_some() {
            return Err(Invalid::new(
                "model.bearing_damping",
                value,
                "acts between the rings with a fixed outer ring: with [outer_ring] set it to \"0 s\" and give the damping as inner_ring.support_radial_damping and outer_ring.housing_damping",
            ));
        }
        let k = self.radial_stiffness().map_err(|e| {
            Invalid::new(
                "model.bearing_damping",
                value,
                format!(
                    "needs the bearing's quasi-static radial stiffness at the operating point: {e}"
                ),
            )
        })?;
        support.damping[1] += tau * k;
        support.damping[2] += tau * k;
        Ok(support)
    }

    /// The ball–pocket law with its constants: K_bc of the hertz laws from
    /// the ball and pocket curvatures and the ball and cage materials.
    fn pocket_law(&self) -> Result<PocketLaw, Invalid> {
        let c = &self.cage;
        let damping = c.pocket_damping.unwrap_or(0.0);
        let hertz = || -> Result<f64, Invalid> {
            let cage = c.material.as_ref().ok_or_else(|| {
                Invalid::missing(
                    "cage.material",
                    "the hertz and gupta_film pocket laws need the cage material (e.g. a table with elastic_modulus, poisson_ratio, density)",
                )
            })?;
            let clearance = c.pocket_clearance.ok_or_else(|| {
                Invalid::missing(
                    "cage.pocket_clearance",
                    "a dynamic run needs the pocket clearance",
                )
            })?;
            let ep =
                rolldyn::material::effective_modulus(&self.materials.ball.material, &cage.material);
            hertz_pocket_stiffness(
                c.pocket_shape,
                self.bearing.geometry.ball_diameter,
                clearance,
                ep,
            )
            .map_err(|e| Invalid::new("cage.pocket_clearance", Some(e.value), e.rule))
        };
        Ok(match c.pocket_law {
            PocketLawChoice::Linear => PocketLaw::Linear {
                stiffness: c.pocket_stiffness.ok_or_else(|| {
                    Invalid::missing(
                        "cage.pocket_stiffness",
                        "the linear pocket law needs the ball–pocket contact stiffness, e.g. \"1e7 N/m\"",
                    )
                })?,
                damping,
            },
            PocketLawChoice::Hertz => PocketLaw::Hertz {
                stiffness: hertz()?,
                damping,
            },
            PocketLawChoice::GuptaFilm => PocketLaw::GuptaFilm {
                wall_force: c.pocket_wall_force,
                stiffness: hertz()?,
                damping,
            },
        })
    }

    /// The pocket film's squeeze damping, if asked for: η₀ from the
    /// lubricant, R = D/2.
    pub(crate) fn pocket_squeeze(&self) -> Result<Option<PocketSqueeze>, Invalid> {
        let c = &self.cage;
        if !c.pocket_squeeze_film {
            return Ok(None);
        }
        let lubricant = self.lubricant.as_ref().ok_or_else(|| {
            Invalid::new(
                "cage.pocket_squeeze_film",
                Some("true".into()),
                "the pocket squeeze film needs a [lubricant] section (its viscosity)",
            )
        })?;
        if let Some(clearance) = c.pocket_clearance
            && c.pocket_min_film >= 0.5 * clearance
        {
            return Err(Invalid::new(
                "cage.pocket_min_film",
                Some(format!("{} m", c.pocket_min_film)),
                format!(
                    "must be less than half of cage.pocket_clearance ({} m per side)",
                    0.5 * clearance
                ),
            ));
        }
        Ok(Some(PocketSqueeze {
            viscosity: lubricant.viscosity,
            ball_radius: 0.5 * self.bearing.geometry.ball_diameter,
            min_film: c.pocket_min_film,
            cavitation: c.pocket_squeeze_cavitation,
            tension: c.pocket_squeeze_tension,
        }))
    }

    /// The cage guide land, when the cage is ring-guided and whirls: land
    /// radius from the cage outer (outer-ring guidance) or inner diameter,
    /// width G, radial clearance C_g/2, η₀ from the lubricant.
    fn guide_land(&self) -> Result<Option<GuideLand>, Invalid> {
        self.guide_land_of(true)
    }

    /// The guide land of a ring-guided cage; with `whirl_only`, only when
    /// the cage whirls (the dynamic model's land acts on the whirl).
    pub(super) fn guide_land_of(&self, whirl_only: bool) -> Result<Option<GuideLand>, Invalid> {
        let c = &self.cage;
        let ring = match c.guidance {
            Some(CageGuidance::OuterRing) => RingKind::Outer,
            Some(CageGuidance::InnerRing) => RingKind::Inner,
            _ => return Ok(None),
        };
        if whirl_only && !c.whirl {
            return Ok(None);
        }
        let need =
            |v: Option<f64>, key: &str, what: &str| v.ok_or_else(|| Invalid::missing(key, what));
        let diameter = match ring {
            RingKind::Outer => need(
                c.outer_diameter,
                "cage.outer_diameter",
                "a ring-guided cage needs its guiding diameter",
            )?,
            RingKind::Inner => need(
                c.inner_diameter,
                "cage.inner_diameter",
                "a ring-guided cage needs its guiding diameter",
            )?,
        };
        let lubricant = self.lubricant.as_ref().ok_or_else(|| {
            Invalid::new(
                "cage.guidance",
                None,
                "a ring-guided cage needs a [lubricant] section (the guide land is hydrodynamic)",
            )
        })?;
        Ok(Some(GuideLand {
            ring,
            land_radius: diameter / 2.0,
            width: need(
                c.guide_land_width,
                "cage.guide_land_width",
                "a ring-guided cage needs the guide-land width",
            )?,
            radial_clearance: need(
                c.guide_clearance,
                "cage.guide_clearance",
                "a ring-guided cage needs the guide clearance",
            )? / 2.0,
            viscosity: lubricant.viscosity,
            max_eccentricity: GUIDE_MAX_ECCENTRICITY,
            stop_stiffness: GUIDE_STOP_STIFFNESS,
        }))
    }
}

/// Largest eccentricity ratio of the short-bearing guide-land law (docs/model.md §5).
pub const GUIDE_MAX_ECCENTRICITY: f64 = 0.95;
/// Stiffness of the guide-land stop beyond ε_max \[N/m\]: a stiff contact
/// (of the order of a cage-material line contact), not from a source.
pub const GUIDE_STOP_STIFFNESS: f64 = 1e8;

/// Standard gravity g₀ = 9.80665 m/s² (CGPM 1901).
pub const STANDARD_GRAVITY: f64 = 9.80665;

/// Checks `[drag]`: the oil–air mixture's effective density and the drag
/// coefficients (all 0, no drag, when not given).
pub(super) fn drag(d: &RawDrag) -> Result<DragParameters, Invalid> {
    let coefficient = |key: &str, v: Option<f64>| {
        positive_number(
            key,
            v,
            |x| (0.0..=1e4).contains(&x),
            "a drag coefficient must lie in [0, 1e4] (a sphere's C_D is below 1e3 down to Re = 0.03)",
        )
        .map(|v| v.unwrap_or(0.0))
    };
    Ok(DragParameters {
        effective_density: checked("drag.effective_density", &d.effective_density, non_negative)?
            .unwrap_or(0.0),
        ball_drag_coefficient: coefficient("drag.ball_drag_coefficient", d.ball_drag_coefficient)?,
        ball_spin_drag_coefficient: coefficient(
            "drag.ball_spin_drag_coefficient",
            d.ball_spin_drag_coefficient,
        )?,
        cage_viscous: checked("drag.cage_viscous", &d.cage_viscous, non_negative)?.unwrap_or(0.0),
        cage_windage: checked("drag.cage_windage", &d.cage_windage, non_negative)?.unwrap_or(0.0),
    })
}

/// Checks `[seals]`: the seals' friction moment (needed) and transition
/// speed (default 1 rpm).
pub(super) fn seals(raw: Option<&RawSeals>) -> Result<Option<SealFriction>, Invalid> {
    let Some(raw) = raw else {
        return Ok(None);
    };
    let torque =
        checked("seals.friction_torque", &raw.friction_torque, non_negative)?.ok_or_else(|| {
            Invalid::new(
                "seals.friction_torque",
                None,
                "[seals] needs the seals' friction moment, e.g. \"0.05 N.m\" (both seals together)",
            )
        })?;
    let mut seals = SealFriction::new(torque);
    if let Some(speed) = checked("seals.transition_speed", &raw.transition_speed, positive)? {
        seals.transition_speed = speed;
    }
    Ok(Some(seals))
}
