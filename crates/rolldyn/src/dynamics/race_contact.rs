//! Ball–raceway contact: normal force, traction and rolling resistance
//! (docs/model.md §2.1, §3).
//!
//! Ball–raceway: the exact torus contact of docs/model.md §2.1 (δ, n, contact
//! point P, α). The normal law gives Q from δ, δ̇ = (q̇ − ṗ)·n (p: the
//! groove-centre point, moving with the ring) and the episode's impact
//! speed. With the film in the normal approach δ is the elastic approach
//! δ + h(Q) (`dynamics::film`). Traction acts at P on the tangential slip of ball material
//! relative to ring material, v_b = q̇ + ω_b × (P − q) and
//! v_g = ṫ + ω_ring × (P − t), with ω_ring = ω_i a + the tilt rates. Force
//! on the ball: −Q n + F_T; the ring takes the reaction at P.
//!
//! Rolling resistance by elastic hysteresis (docs/model.md §3; Lei et al. 2023 eq 21,
//! Harris): F_h = α_h (3/16)(b/(D/2)) Q opposing the rolling, applied as
//! the equivalent couple M_h = (D/2) F_h = (3/16) α_h b Q about the rolling
//! axis e_a = n × û on the ball, the reaction couple on the ring; its power
//! M_h |ω_roll| is dissipated. A ramp over 1 mm/s of rolling speed makes it
//! continuous at rest.
//!
//! EHL rolling resistance of a lubricated contact
//! (`lubrication::rolling_resistance`; Houpert, Biboulet & Houpert 2010): the
//! rolling force F_R of the inlet's Poiseuille flow at the contact's
//! entrainment speed, load and ellipse, reduced by inlet heating and the
//! film's starvation, acting on the ball as a force F_R (2R_x/(D/2) − 1) û
//! at P and a couple −2 F_R R_x e_a about it, the ring taking the
//! opposite; 2 F_R u in pure rolling is dissipated.

use super::elements::Elements;
use super::film::{FilmApproach, FilmWork};
use super::motion::{BallMotion, RingMotion};
use super::surface_contact::SurfaceEffect;
use crate::contact::normal_law::{ContactEpisode, ContactState, NormalLaw};
use crate::contact::{ContactTable, HertzCoefficients, HertzResult, TorusContact};
use crate::lubrication::rolling_resistance::{RollingContact, RollingResistance};
use crate::lubrication::{ContactFilm, FilmConditions, Supply, contact_film};
use crate::power::ContactLosses;
use crate::traction::fastsim::MapCell;
use crate::traction::{
    ContactConditions, ContactKinematics, ContactPatch, Creep, TractionModel, TractionResult,
};
use nalgebra::Vector3;

/// Rolling speed over which the hysteresis couple ramps up from zero
/// (regularisation, docs/model.md §3) \[m/s\].
pub const HYSTERESIS_RAMP_SPEED: f64 = 1e-3;

/// State of one ball–raceway contact for output (docs/model.md §9); all zero
/// when the contact is open.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactOutput {
    /// Normal load Q \[N\].
    pub load: f64,
    /// Contact angle α \[rad\].
    pub angle: f64,
    /// Sliding speed |Δv| at the contact centre \[m/s\].
    pub slip_speed: f64,
    /// Entrainment (rolling) speed |u| \[m/s\].
    pub entrainment_speed: f64,
    /// Slide-to-roll ratio |Δv|/|u| at the contact centre \[-\].
    pub slide_to_roll: f64,
    /// Spin-to-roll ratio ω_s/|ω_roll| \[-\] (Harris).
    pub spin_to_roll: f64,
    /// Central film thickness h_c \[m\] (0 without a film model).
    pub film: f64,
    /// Asperities' share φ of the load (0 without mixed lubrication).
    pub asperity_share: f64,
    /// FASTSIM creepages (ξ, η \[-\], φ \[1/m\]) and stick fraction
    /// (None with the stress-law traction models).
    pub creep: Option<Creep>,
    /// Dissipated power by mechanism \[W\] (docs/power.md).
    pub losses: ContactLosses,
}

/// Contact state of one ball for output.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactSample {
    /// Inner contact.
    pub inner: ContactOutput,
    /// Outer contact.
    pub outer: ContactOutput,
}

/// What a contact evaluation must deliver.
pub(super) enum Want<'a> {
    /// Only the penetration and its rate (episode bookkeeping): no traction.
    Penetration,
    /// Forces and moments for the equations of motion.
    Forces,
    /// Forces and the output quantities.
    Output,
    /// Output, and the FASTSIM stick/slip map into the callback.
    Map(&'a mut dyn FnMut(&MapCell)),
}

/// One evaluated ball–raceway contact.
pub(super) struct RaceContact {
    /// Geometry; the penetration includes the surfaces' Δδ.
    pub(super) geometry: TorusContact,
    /// The surfaces' forces (scaled by the load; zero when smooth).
    pub(super) surface: SurfaceEffect,
    pub(super) penetration_rate: f64,
    /// Normal load Q \[N\] (the normal law's force).
    pub(super) load: f64,
    /// Dissipated power: normal damping and traction \[W\].
    pub(super) dissipation: f64,
    /// What the film in the approach passes to the films' power (None
    /// without it).
    pub(super) film_work: Option<FilmWork>,
    /// The same by mechanism (sums to `dissipation` to rounding).
    pub(super) losses: ContactLosses,
    /// Force on the ball (normal and traction) \[N\].
    pub(super) force: Vector3<f64>,
    /// Moment on the ball about its centre \[N·m\].
    pub(super) moment: Vector3<f64>,
    /// Traction couple about the contact point \[N·m\]; the ring takes
    /// −force at P and −couple.
    pub(super) couple: Vector3<f64>,
    /// Output quantities.
    pub(super) output: ContactOutput,
}

/// The normal part of one ball–raceway contact (`Elements::race_normal`).
struct NormalContact {
    /// Geometry; the penetration includes the surfaces' Δδ (with the film
    /// in the approach, the elastic approach).
    geometry: TorusContact,
    /// The surfaces' effect per unit load.
    surface: SurfaceEffect,
    penetration_rate: f64,
    /// Hertz constants at the contact angle.
    hertz: HertzCoefficients,
    /// Entrainment velocity u and its magnitude (zero where not needed).
    entrainment: Vector3<f64>,
    entrainment_speed: f64,
    /// The film in the approach (None without it).
    approach: Option<FilmApproach>,
    /// Normal load Q \[N\].
    load: f64,
}

impl NormalContact {
    /// The normal force alone (episode bookkeeping): no ellipse, film or
    /// traction.
    fn alone(self) -> RaceContact {
        RaceContact {
            surface: self.surface.scaled(self.load),
            penetration_rate: self.penetration_rate,
            load: self.load,
            dissipation: 0.0,
            film_work: None,
            losses: ContactLosses::default(),
            force: -self.load * self.geometry.normal,
            moment: Vector3::zeros(),
            couple: Vector3::zeros(),
            output: ContactOutput::default(),
            geometry: self.geometry,
        }
    }
}

impl ContactOutput {
    /// The output of a contact of `geometry` in motion `kinematics` at
    /// rolling rate `rolling_rate` about the rolling axis.
    fn of(
        geometry: &TorusContact,
        kinematics: &ContactKinematics,
        rolling_rate: f64,
        asperity_share: f64,
        creep: Option<Creep>,
        losses: ContactLosses,
    ) -> Self {
        let (slip, n) = (kinematics.slip, kinematics.patch.normal);
        let u = kinematics.conditions.entrainment_speed;
        let slip_speed = (slip - slip.dot(&n) * n).norm();
        Self {
            load: kinematics.patch.load,
            angle: geometry.contact_angle,
            slip_speed,
            entrainment_speed: u,
            slide_to_roll: if u > 0.0 { slip_speed / u } else { 0.0 },
            spin_to_roll: if rolling_rate != 0.0 {
                kinematics.relative_spin.dot(&n) / rolling_rate.abs()
            } else {
                0.0
            },
            film: kinematics.conditions.film,
            asperity_share,
            creep,
            losses,
        }
    }
}

impl Elements {
    /// Contact geometry of a ball with a ring, the penetration including the
    /// surfaces (docs/model.md §2.1, §6), and the surfaces' effect per unit load;
    /// None when the bodies do not overlap.
    pub(super) fn race_geometry(
        &self,
        ring: &RingMotion,
        ball: &BallMotion,
    ) -> Option<(TorusContact, SurfaceEffect)> {
        self.race_geometry_any(ring, ball)
            .filter(|(geometry, _)| geometry.penetration > 0.0)
    }

    /// [`Self::race_geometry`], overlapping or not (penetration ≤ 0: the
    /// gap); None only where the torus geometry is degenerate.
    pub(super) fn race_geometry_any(
        &self,
        ring: &RingMotion,
        ball: &BallMotion,
    ) -> Option<(TorusContact, SurfaceEffect)> {
        let mut geometry = ring
            .circle
            .contact(&ball.centre, self.geometry.ball_diameter, 0.0)?;
        let surface = self
            .surface_effect(ring, ball, &geometry)
            .unwrap_or_default();
        geometry.penetration += surface.approach;
        Some((geometry, surface))
    }

    /// The normal part of a ball–raceway contact: its geometry with the
    /// surfaces, the film in the approach and the normal law's load; None
    /// when open. The entrainment is computed only where it is used
    /// (`with_output`, the film, the traction curve, the resistances).
    fn race_normal(
        &self,
        ring: &RingMotion,
        table: &ContactTable,
        episode: &ContactEpisode,
        ball: &BallMotion,
        with_output: bool,
    ) -> Option<NormalContact> {
        let films = self.layout.film_work;
        let (mut geometry, surface) = if films {
            self.race_geometry_any(ring, ball)?
        } else {
            self.race_geometry(ring, ball)?
        };
        let n = geometry.normal;
        let groove_velocity = ring.velocity
            + ring
                .omega_frame
                .cross(&(geometry.groove_centre - ring.centre));
        let penetration_rate = (ball.velocity - groove_velocity).dot(&n) + surface.approach_rate;
        let hertz = table.at(geometry.contact_angle);
        let (entrainment, entrainment_speed) = if with_output
            || self.params.rolling_hysteresis > 0.0
            || films
            || self.params.rolling_resistance.is_some()
            || self.params.traction.needs_entrainment()
        {
            let e = Self::entrainment(ring, ball, &geometry.contact_point, &n);
            (e, e.norm())
        } else {
            (Vector3::zeros(), 0.0)
        };
        // Film in the approach (dynamics::film): the contact is closed while
        // δ + h > 0 and its elastic approach is δ_el = δ + h(Q).
        let approach = if films {
            let a = self.film_approach(ring, &hertz, &geometry, entrainment_speed)?;
            geometry.penetration = a.elastic_approach;
            Some(a)
        } else {
            None
        };
        let state = ContactState {
            stiffness: hertz.stiffness,
            penetration: geometry.penetration,
            penetration_rate,
            impact_speed: episode.impact_speed(penetration_rate, self.params.impact_speed_floor),
            effective_mass: self.ball_mass,
        };
        let load = self.params.normal_law.force(&state);
        Some(NormalContact {
            geometry,
            surface,
            penetration_rate,
            hertz,
            entrainment,
            entrainment_speed,
            approach,
            load,
        })
    }

    pub(super) fn race_contact(
        &self,
        ring: &RingMotion,
        table: &ContactTable,
        episode: &ContactEpisode,
        ball: &BallMotion,
        want: Want,
    ) -> Option<RaceContact> {
        let with_output = matches!(want, Want::Output | Want::Map(_));
        let normal = self.race_normal(ring, table, episode, ball, with_output)?;
        if let Want::Penetration = want {
            return Some(normal.alone());
        }
        let NormalContact {
            geometry,
            surface,
            penetration_rate,
            hertz,
            entrainment,
            entrainment_speed: u,
            approach,
            load,
        } = normal;
        let n = geometry.normal;
        let q = &ball.centre;
        let point = geometry.contact_point;
        let ellipse = hertz.at_load(load);
        let (steady, film, asperity_share) = self.race_film(
            ring,
            &hertz,
            &geometry,
            (u, load),
            &ellipse,
            approach.as_ref(),
        );
        // The entrainment's direction û (zero at rest).
        let direction = if u > 0.0 {
            entrainment / u
        } else {
            Vector3::zeros()
        };
        let film_work = approach.map(|a| FilmWork {
            law: a.law,
            load: a.load,
            speed: u,
            direction,
            point,
        });
        let kinematics = self.race_kinematics(
            ring,
            ball,
            &geometry,
            &ellipse,
            load,
            (&entrainment, u),
            film,
        );
        let traction = self.race_traction(want, &kinematics, asperity_share);
        // Rolling axis e_a = n × û and the rolling rate about it.
        let rolling_axis = if u > 0.0 {
            n.cross(&direction)
        } else {
            Vector3::zeros()
        };
        let rolling_rate = kinematics.relative_spin.dot(&rolling_axis);
        let mut loads = BallLoads {
            force: -load * n + traction.force,
            moment: traction.moment,
            couple: traction.couple,
            dissipation: traction.dissipation,
            losses: traction_losses(&traction, &kinematics),
        };
        self.add_rolling_losses(
            &mut loads,
            &Rolling {
                ring,
                hertz: &hertz,
                geometry: &geometry,
                ellipse: &ellipse,
                load,
                entrainment: &entrainment,
                axis: rolling_axis,
                rate: rolling_rate,
                steady: steady.as_ref(),
                lever: point - q,
                slip: kinematics.slip,
                relative_spin: kinematics.relative_spin,
            },
        );
        let elastic = hertz.stiffness * geometry.penetration * geometry.penetration.sqrt();
        loads.dissipation += (load - elastic) * penetration_rate;
        loads.losses.damping = (load - elastic) * penetration_rate;
        let output = if with_output {
            ContactOutput::of(
                &geometry,
                &kinematics,
                rolling_rate,
                asperity_share,
                traction.creep,
                loads.losses,
            )
        } else {
            ContactOutput::default()
        };
        Some(RaceContact {
            geometry,
            surface: surface.scaled(load),
            penetration_rate,
            load,
            dissipation: loads.dissipation,
            film_work,
            losses: loads.losses,
            force: loads.force,
            moment: loads.moment,
            couple: loads.couple,
            output,
        })
    }

    /// The contact's film (docs/model.md §4) at entrainment speed u and
    /// load Q: h(Q) of the elastic load with the film in the approach
    /// (`approach`), else the steady Hamrock–Dowson film at the load
    /// (returned too, for the rolling resistance), both starved by the
    /// ring's supply; and the asperities' share of the load
    /// (dynamics::mixed).
    fn race_film(
        &self,
        ring: &RingMotion,
        hertz: &HertzCoefficients,
        geometry: &TorusContact,
        (entrainment_speed, load): (f64, f64),
        ellipse: &HertzResult,
        approach: Option<&FilmApproach>,
    ) -> (Option<ContactFilm>, f64, f64) {
        let contact_angle = geometry.contact_angle;
        let steady = match approach {
            Some(_) => None,
            None => self.steady_film(
                ring,
                hertz,
                contact_angle,
                entrainment_speed,
                load,
                ellipse.semi_minor,
            ),
        };
        let film = match approach {
            Some(a) => a.film,
            None => steady.map_or(0.0, |f| f.central),
        };
        let asperity_share = self.asperity_share(
            ring,
            hertz,
            contact_angle,
            entrainment_speed,
            load,
            ellipse,
            steady.as_ref(),
        );
        (steady, film, asperity_share)
    }

    /// The contact's kinematics for the traction (docs/model.md §3): the
    /// slip of ball material over ring material at P, the relative spin,
    /// the rolling direction (the azimuthal direction at P, tangent to
    /// the contact) and the patch at load Q.
    #[allow(clippy::too_many_arguments)]
    fn race_kinematics(
        &self,
        ring: &RingMotion,
        ball: &BallMotion,
        geometry: &TorusContact,
        ellipse: &HertzResult,
        load: f64,
        (entrainment, entrainment_speed): (&Vector3<f64>, f64),
        film: f64,
    ) -> ContactKinematics {
        let (q, v, w) = (&ball.centre, &ball.velocity, &ball.omega);
        let (point, n) = (geometry.contact_point, geometry.normal);
        let ball_surface = v + w.cross(&(point - q));
        let ring_surface = ring.velocity + ring.omega.cross(&(point - ring.centre));
        let slip = ball_surface - ring_surface;
        let azimuthal = Vector3::new(0.0, -point.z, point.y);
        let along = azimuthal - azimuthal.dot(&n) * n;
        let rolling_direction = if along.norm() > 0.0 {
            along.normalize()
        } else {
            n.cross(&Vector3::x()).normalize()
        };
        let rg = ring.raceway.groove_radius;
        let rb = 0.5 * self.geometry.ball_diameter;
        ContactKinematics {
            patch: ContactPatch {
                point,
                normal: n,
                rolling_direction,
                semi_major: ellipse.semi_major,
                semi_minor: ellipse.semi_minor,
                load,
                deformed_radius: 2.0 * rg * rb / (rg + rb),
            },
            ball_centre: *q,
            slip,
            relative_spin: w - ring.omega,
            conditions: ContactConditions {
                film,
                entrainment_speed,
                rolling_velocity: entrainment.dot(&rolling_direction),
            },
        }
    }

    /// The traction model's forces (blended with the boundary friction by
    /// the asperities' share under mixed lubrication), or FASTSIM's with
    /// its stick/slip map for [`Want::Map`].
    fn race_traction(
        &self,
        want: Want,
        kinematics: &ContactKinematics,
        asperity_share: f64,
    ) -> TractionResult {
        let model = &self.params.traction;
        match (want, model) {
            (Want::Map(map), TractionModel::Fastsim(f)) => f.evaluate_mapped(kinematics, map),
            _ => match &self.params.mixed_lubrication {
                Some(mixed) => model.evaluate_blended(
                    &mixed.boundary,
                    asperity_share,
                    &self.traction_grid,
                    kinematics,
                ),
                None => model.evaluate(&self.traction_grid, kinematics),
            },
        }
    }

    /// The hysteresis couple on the ball, M_h = −(3/16) α_h b Q e_a, ramped
    /// over [`HYSTERESIS_RAMP_SPEED`] of rolling speed (module doc).
    fn hysteresis_couple(
        &self,
        rolling_rate: f64,
        rolling_axis: &Vector3<f64>,
        semi_minor: f64,
        load: f64,
    ) -> Vector3<f64> {
        let rolling_speed = 0.5 * self.geometry.ball_diameter * rolling_rate;
        let ramp = (rolling_speed / HYSTERESIS_RAMP_SPEED).clamp(-1.0, 1.0);
        -(0.1875 * self.params.rolling_hysteresis * semi_minor * load * ramp) * rolling_axis
    }

    /// The rolling losses (module doc) added to a contact's loads on the
    /// ball: the hysteresis couple, and the EHL rolling resistance's force
    /// at the contact point and its couple, with their powers.
    fn add_rolling_losses(&self, loads: &mut BallLoads, at: &Rolling) {
        if self.params.rolling_hysteresis > 0.0 {
            let m_h = self.hysteresis_couple(at.rate, &at.axis, at.ellipse.semi_minor, at.load);
            loads.moment += m_h;
            loads.couple += m_h;
            loads.dissipation -= m_h.dot(&at.relative_spin);
            loads.losses.hysteresis = -m_h.dot(&at.relative_spin);
        }
        let u = at.entrainment.norm();
        if let Some(rolling) = self.params.rolling_resistance.as_ref().filter(|_| u > 0.0) {
            let (f_r, c_r) = self.rolling_resistance(rolling, at);
            loads.force += f_r;
            loads.moment += at.lever.cross(&f_r) + c_r;
            loads.couple += c_r;
            let power = -(f_r.dot(&at.slip) + c_r.dot(&at.relative_spin));
            loads.dissipation += power;
            loads.losses.rolling_resistance = power;
        }
    }

    /// The EHL rolling resistance's force at the contact point and couple
    /// about it on the ball (module doc) at entrainment velocity
    /// `at.entrainment` (|u| > 0) and rolling axis e_a; starved by the
    /// film's supply (`at.steady`, the steady film, when computed), or with
    /// a flooded supply by the method's kinematic replenishment.
    fn rolling_resistance(
        &self,
        rolling: &RollingResistance,
        at: &Rolling,
    ) -> (Vector3<f64>, Vector3<f64>) {
        let Rolling {
            ring,
            hertz,
            geometry,
            ellipse,
            load,
            entrainment,
            axis: rolling_axis,
            steady,
            ..
        } = *at;
        let u = entrainment.norm();
        let curvature = self.curvature(ring, geometry.contact_angle);
        let rolling_radius = curvature.rolling_radius;
        let contact = RollingContact {
            entrainment_speed: u,
            load,
            rolling_radius,
            transverse_radius: curvature.transverse_radius,
            semi_major: ellipse.semi_major,
            semi_minor: ellipse.semi_minor,
            effective_modulus: self.effective_modulus,
        };
        let supply = &self.params.film_supply[super::film::contact_index(ring)];
        let starvation = match (supply, steady) {
            (Supply::Flooded, _) => rolling.replenishment_factor(ring.shaft_speed),
            (_, Some(film)) => film.starvation_factor,
            (_, None) => {
                contact_film(
                    &rolling.lubricant,
                    supply,
                    0.0,
                    &FilmConditions {
                        entrainment_speed: u,
                        load,
                        rolling_radius,
                        effective_modulus: self.effective_modulus,
                        ellipticity: hertz.ellipticity,
                        semi_minor: ellipse.semi_minor,
                        ring_speed: ring.shaft_speed,
                    },
                )
                .starvation_factor
            }
        };
        RollingResistance::ball_load(
            rolling.force(&contact, starvation),
            0.5 * self.geometry.ball_diameter,
            rolling_radius,
            &(entrainment / u),
            &rolling_axis,
        )
    }
}

/// A contact's loads on the ball and their power, summed as the contact
/// is evaluated: the normal load and the traction, then the rolling losses.
struct BallLoads {
    force: Vector3<f64>,
    moment: Vector3<f64>,
    couple: Vector3<f64>,
    dissipation: f64,
    losses: ContactLosses,
}

/// What the rolling losses read of a contact: its ring, Hertz
/// coefficients, geometry and ellipse at load Q, the entrainment velocity
/// u, the rolling axis e_a = n × û and the rolling rate about it, the steady
/// film (when computed), the lever P − q from the ball's centre, and the
/// ball's slip and spin relative to the ring.
#[derive(Clone, Copy)]
struct Rolling<'a> {
    ring: &'a RingMotion,
    hertz: &'a HertzCoefficients,
    geometry: &'a TorusContact,
    ellipse: &'a HertzResult,
    load: f64,
    entrainment: &'a Vector3<f64>,
    axis: Vector3<f64>,
    rate: f64,
    steady: Option<&'a ContactFilm>,
    lever: Vector3<f64>,
    slip: Vector3<f64>,
    relative_spin: Vector3<f64>,
}

/// The traction's power by mechanism (crate::power::dissipation): rigid
/// sliding along and across the rolling direction, spin about n, and the
/// rest of the traction's power (differential sliding).
fn traction_losses(traction: &TractionResult, kinematics: &ContactKinematics) -> ContactLosses {
    let (n, rolling_direction) = (
        &kinematics.patch.normal,
        &kinematics.patch.rolling_direction,
    );
    let (slip, relative_spin) = (&kinematics.slip, &kinematics.relative_spin);
    let across = n.cross(rolling_direction);
    let mut losses = ContactLosses {
        rolling_sliding: -traction.force.dot(rolling_direction) * slip.dot(rolling_direction),
        transverse_sliding: -traction.force.dot(&across) * slip.dot(&across),
        spin: -traction.couple.dot(n) * relative_spin.dot(n),
        ..ContactLosses::default()
    };
    losses.differential_sliding =
        traction.dissipation - losses.rolling_sliding - losses.transverse_sliding - losses.spin;
    losses
}
