//! State, equations of motion and contact forces of the dynamic model.
//!
//! # State (docs/model.md §1)
//! Two more states integrate the drive work and the dissipated energy
//! (docs/model.md §10 bookkeeping). Ball j (9 states): axial x, radial r, azimuth φ, their rates, and the
//! angular velocity (ω_x, ω_r, ω_t) in the ball's azimuth frame
//! (e_x, e_r, e_t), e_r = cos φ e_y + sin φ e_z, e_t = e_x × e_r. Inner ring
//! (10): translation (x, y, z), tilts (θ_y, θ_z) and their rates; its spin
//! ω_i(t) is prescribed (docs/model.md §8). Outer ring (4): radial translation
//! (y_o, z_o) and rates, frozen at zero unless the ring sits on a housing
//! spring–damper (Zhang et al. 2025 eqs 14–15). Cage (6): whirl (y_c, z_c),
//! rotation θ_c and their rates.
//!
//! # Equations
//! ```text
//! m ẍ = F_x,   m (r̈ − r φ̇²) = F_r,   m (r φ̈ + 2 ṙ φ̇) = F_t
//! ω̇_x = M_x/I,  ω̇_r = M_r/I + φ̇ ω_t,  ω̇_t = M_t/I − φ̇ ω_r,      I = m D²/10
//! inner ring: m_i ẗ = ΣF + F_applied(t) − k t − c ṫ,  I_t θ̈ = ΣM + M_applied(t)   (ring gyroscopics neglected)
//! outer ring: m_o (ÿ_o, z̈_o) = ΣF − k_h (y_o, z_o) − c_h (ẏ_o, ż_o)             (Zhang et al. 2025 eqs 14–15)
//! cage: m_c (ÿ_c, z̈_c) = ΣF + m_u e ω_c² (cos θ_c, sin θ_c),  I_c θ̈_c = ΣM_x    (Deng et al. 2022 eqs 37–39)
//! ```
//! Centrifugal and Coriolis terms come from the rotating azimuth frame.
//!
//!
//! # Force elements
//! Each lives in its own file: ball–raceway contact and rolling resistance
//! ([`super::race_contact`]), ball–pocket ([`super::pocket`]), drag
//! ([`crate::lubrication::drag`]), ring supports ([`super::supports`]); the energy
//! bookkeeping is in [`super::energy`], output quantities in
//! [`super::outputs`]; a ball's equations sum its contacts' shares in
//! `dynamics::ball_equations`, and the block structure the implicit
//! integrators use is in `dynamics::block_split`. Gravity (optional) acts
//! along −z.

use super::ball_pass::BallPass;
use super::coupling::BallCoupling;
use super::layout::StateLayout;
use super::parameters::DynamicsParameters;
use super::race_contact::{ContactSample, Want};
use crate::cage::GuideLand;
use crate::contact::normal_law::ContactEpisode;
use crate::contact::{ContactTable, GrooveCircle, HertzModel, RacewayContactModel, RingPose};
use crate::error::{InvalidParameter, require_non_negative, require_positive};
use crate::geometry::Raceway;
use crate::geometry::{BearingGeometry, RingKind};
use crate::integrate::{BlockSplit, EnergyBalance, OdeSystem};
use crate::kinematics::cage_speed_ratio;
use crate::lubrication::Supply;
use crate::material::{Material, effective_modulus};
use crate::power::Dissipation;
use crate::quasistatic::Equilibrium;
use crate::traction::TractionGrid;
use nalgebra::{Rotation3, Vector3};

/// Kinematic state of a ball (global frame).
pub(super) struct BallMotion {
    /// Ball index j.
    pub(super) index: usize,
    /// Spin angle ψ \[rad\] (0 when the balls carry no surface).
    pub(super) spin_angle: f64,
    pub(super) centre: Vector3<f64>,
    pub(super) velocity: Vector3<f64>,
    pub(super) omega: Vector3<f64>,
    /// Orbital rate φ̇ of its azimuth frame \[rad/s\].
    pub(super) orbital_rate: f64,
}

/// Kinematic state of a ring for contact evaluation.
pub(super) struct RingMotion {
    pub(super) raceway: Raceway,
    pub(super) circle: GrooveCircle,
    pub(super) centre: Vector3<f64>,
    pub(super) velocity: Vector3<f64>,
    /// Angular velocity of the ring material (spin + tilt rates).
    pub(super) omega: Vector3<f64>,
    /// Angular velocity of the ring's frame (tilt rates only).
    pub(super) omega_frame: Vector3<f64>,
    /// Angle the ring has turned about its axis θ_ring \[rad\].
    pub(super) spin_angle: f64,
    /// Spin speed of the ring about its axis \[rad/s\].
    pub(super) spin_speed: f64,
    /// Inner-ring (shaft) speed \[rad/s\] (the oil-flow supply, docs/model.md §4).
    pub(super) shaft_speed: f64,
}

/// The dynamic bearing model.
#[derive(Debug, Clone)]
pub struct BearingModel {
    pub(super) geometry: BearingGeometry,
    pub(super) inner_table: ContactTable,
    pub(super) outer_table: ContactTable,
    pub(super) ball_mass: f64,
    pub(super) ball_inertia: f64,
    pub(super) effective_modulus: f64,
    pub(super) params: DynamicsParameters,
    pub(super) layout: StateLayout,
    /// Episode memory: inner and outer contact of each ball.
    pub(super) episodes: Vec<[ContactEpisode; 2]>,
    /// Largest contact loads at the accepted steps since the sampler took
    /// them ([`super::peaks`]).
    pub(super) peak_loads: super::peaks::PeakLoads,
    /// Thermal network advanced alongside a run, if coupled.
    pub(super) thermal: Option<Box<super::thermal_coupling::ThermalCoupling>>,
    /// The balls' contact evaluations, serial or across threads.
    pub(super) ball_pass: BallPass,
    /// The traction grid of `params.traction_integration`, prepared.
    pub(super) traction_grid: TractionGrid,
}

impl BearingModel {
    /// Builds the model: contact tables, ball mass and inertia, checks.
    pub fn new(
        geometry: &BearingGeometry,
        ball: &Material,
        rings: &Material,
        hertz: HertzModel,
        params: DynamicsParameters,
    ) -> Result<Self, InvalidParameter> {
        require_positive("inner_ring_mass", params.inner_ring_mass)?;
        require_positive("inner_ring_tilt_inertia", params.inner_ring_tilt_inertia)?;
        params.cage.validate()?;
        if params.cage.pocket_squeeze.is_some() {
            // Built here, not at the first force evaluation in the time loop.
            crate::cage::squeeze::build_tables();
        }
        params.normal_law.validate()?;
        require_positive("impact_speed_floor", params.impact_speed_floor)?;
        params.traction.validate()?;
        params.inner_support.validate("inner_ring_support")?;
        if let Some(outer) = &params.outer_ring {
            require_positive("outer_ring_mass", outer.mass)?;
            outer.housing.validate("outer_ring_housing")?;
        }
        require_non_negative("rolling_hysteresis", params.rolling_hysteresis)?;
        params.surface.validate(geometry.ball_count)?;
        for supply in &params.film_supply {
            supply.validate()?;
        }
        if params.film_in_approach {
            if params.traction.lubricant().is_none() {
                return Err(InvalidParameter::new(
                    "film_in_approach",
                    "true",
                    "needs a film model: a traction law with a lubricant (ehl)",
                ));
            }
            for supply in &params.film_supply {
                if let Supply::Flow { flow, .. } = supply {
                    return Err(InvalidParameter::new(
                        "oil_flow",
                        *flow,
                        "the film in the normal approach needs a flooded supply or an inlet distance ratio",
                    ));
                }
            }
        }
        if let Some(mixed) = &params.mixed_lubrication {
            crate::dynamics::mixed::validate(mixed, &params)?;
        }
        let ep = effective_modulus(ball, rings);
        let ball_mass = geometry.ball_mass(ball.density);
        Ok(Self {
            inner_table: ContactTable::new(RacewayContactModel::new(
                geometry,
                RingKind::Inner,
                ep,
                hertz,
            ))?,
            outer_table: ContactTable::new(RacewayContactModel::new(
                geometry,
                RingKind::Outer,
                ep,
                hertz,
            ))?,
            ball_mass,
            ball_inertia: ball_mass * geometry.ball_diameter.powi(2) / 10.0,
            effective_modulus: ep,
            layout: StateLayout {
                balls: geometry.ball_count,
                ball_spin_angle: params.surface.has_ball_surfaces(),
                film_work: params.film_in_approach,
            },
            episodes: vec![[ContactEpisode::default(); 2]; geometry.ball_count],
            peak_loads: Default::default(),
            thermal: None,
            traction_grid: TractionGrid::new(params.traction_integration),
            ball_pass: BallPass::new(
                geometry.ball_count,
                params
                    .traction
                    .integrates_over_a_grid(&params.traction_integration),
            ),
            geometry: geometry.clone(),
            params,
        })
    }

    /// State layout.
    pub fn layout(&self) -> StateLayout {
        self.layout
    }

    /// Parameters.
    pub fn parameters(&self) -> &DynamicsParameters {
        &self.params
    }

    /// Bearing geometry.
    pub fn geometry(&self) -> &BearingGeometry {
        &self.geometry
    }

    /// Ball mass \[kg\].
    pub fn ball_mass(&self) -> f64 {
        self.ball_mass
    }

    /// Pure-rolling start: balls at the pitch circle with the pure-rolling
    /// orbital and spin speeds at the nominal contact angle, the cage turning
    /// with them, the inner ring at `ring_displacement` and at rest.
    pub fn pure_rolling_state(&self, ring_displacement: [f64; 5]) -> Vec<f64> {
        let g = &self.geometry;
        let l = self.layout;
        let mut y = vec![0.0; l.len()];
        let omega_i = self.params.speed.speed_at(0.0);
        let alpha = g.nominal_contact_angle();
        let gamma = g.ball_diameter / g.pitch_diameter;
        let omega_c = cage_speed_ratio(gamma, alpha, alpha, alpha) * omega_i;
        // Spin relative to the cage about the axis at β = α: no slip at the
        // outer contact gives ω_R = ω_c (d_m/D)(1 + γ cos α), directed along
        // (−cos α, +sin α) in (e_x, e_r).
        let spin_rel = -omega_c * g.pitch_diameter * (1.0 + gamma * alpha.cos()) / g.ball_diameter;
        for j in 0..l.balls {
            let b = l.ball(j);
            y[b + 1] = g.pitch_diameter / 2.0;
            y[b + 2] = std::f64::consts::TAU * j as f64 / l.balls as f64;
            y[b + 5] = omega_c;
            y[b + 6] = omega_c + spin_rel * alpha.cos();
            if !self.params.planar {
                y[b + 7] = -spin_rel * alpha.sin();
            }
        }
        let r = l.ring();
        y[r..r + 5].copy_from_slice(&ring_displacement);
        let c = l.cage();
        y[c + 5] = omega_c;
        y
    }

    /// Start from a quasi-static (Jones–Harris) solution (Zhang et al. 2025 §3.1):
    /// ball positions and speeds, ring displacement; cage at the mean ball
    /// orbital speed.
    pub fn state_from_equilibrium(&self, eq: &Equilibrium) -> Vec<f64> {
        let l = self.layout;
        let mut y = vec![0.0; l.len()];
        for (j, b) in eq.balls.iter().enumerate().take(l.balls) {
            let o = l.ball(j);
            y[o] = b.axial_position;
            y[o + 1] = b.radial_position;
            y[o + 2] = b.azimuth;
            y[o + 5] = b.orbital_speed;
            y[o + 6] = b.spin_axial;
            y[o + 7] = b.spin_radial;
        }
        let r = l.ring();
        y[r..r + 5].copy_from_slice(&eq.displacement);
        let c = l.cage();
        y[c + 5] = eq.cage_speed();
        y
    }

    pub(super) fn ring_motion(&self, t: f64, y: &[f64]) -> (RingMotion, RingMotion) {
        let (r, o) = (self.layout.ring(), self.layout.outer());
        self.ring_motion_of(
            t,
            &y[r..r + StateLayout::RING],
            &y[o..o + StateLayout::OUTER],
        )
    }

    /// [`Self::ring_motion`] from the inner ring's 10 states and the outer
    /// ring's 4.
    pub(super) fn ring_motion_of(
        &self,
        t: f64,
        ring: &[f64],
        outer: &[f64],
    ) -> (RingMotion, RingMotion) {
        let y = ring;
        let r = 0;
        let pose = RingPose {
            translation: Vector3::new(y[r], y[r + 1], y[r + 2]),
            tilt_y: y[r + 3],
            tilt_z: y[r + 4],
        };
        let omega_frame = y[r + 9] * Vector3::z() + y[r + 8] * tilt_axis_y(pose.tilt_z);
        let unit_axis = pose.axis();
        let axis = unit_axis.into_inner();
        let spin_speed = self.params.speed.speed_at(t);
        let inner = RingMotion {
            raceway: self.geometry.inner,
            circle: GrooveCircle::with_axis(&self.geometry.inner, &pose.translation, unit_axis),
            centre: pose.translation,
            velocity: Vector3::new(y[r + 5], y[r + 6], y[r + 7]),
            omega: spin_speed * axis + omega_frame,
            omega_frame,
            spin_angle: if self.params.surface.inner.is_smooth() {
                0.0
            } else {
                self.params.speed.angle_at(t)
            },
            spin_speed,
            shaft_speed: spin_speed,
        };
        let (y, o) = (outer, 0);
        let outer_pose = RingPose {
            translation: Vector3::new(0.0, y[o], y[o + 1]),
            ..RingPose::default()
        };
        let outer = RingMotion {
            raceway: self.geometry.outer,
            circle: GrooveCircle::of(&self.geometry.outer, &outer_pose),
            centre: outer_pose.translation,
            velocity: Vector3::new(0.0, y[o + 2], y[o + 3]),
            omega: Vector3::zeros(),
            omega_frame: Vector3::zeros(),
            spin_angle: 0.0,
            spin_speed: 0.0,
            shaft_speed: spin_speed,
        };
        (inner, outer)
    }

    /// Ball centre, velocity and angular velocity (global), and its frame.
    #[allow(clippy::type_complexity)]
    pub(super) fn ball_kinematics(&self, j: usize, y: &[f64]) -> (BallMotion, [Vector3<f64>; 3]) {
        let b = self.layout.ball(j);
        self.ball_motion_of(j, &y[b..b + self.layout.ball_len()])
    }

    /// [`Self::ball_kinematics`] from ball j's block of states.
    #[allow(clippy::type_complexity)]
    pub(super) fn ball_motion_of(
        &self,
        j: usize,
        block: &[f64],
    ) -> (BallMotion, [Vector3<f64>; 3]) {
        let (y, b) = (block, 0);
        let (s, c) = y[b + 2].sin_cos();
        let ex = Vector3::x();
        let er = Vector3::new(0.0, c, s);
        let et = Vector3::new(0.0, -s, c);
        let q = y[b] * ex + y[b + 1] * er;
        let v = y[b + 3] * ex + y[b + 4] * er + y[b + 1] * y[b + 5] * et;
        let w = y[b + 6] * ex + y[b + 7] * er + y[b + 8] * et;
        (
            BallMotion {
                index: j,
                spin_angle: if self.layout.ball_spin_angle {
                    y[b + StateLayout::SPIN_ANGLE]
                } else {
                    0.0
                },
                centre: q,
                velocity: v,
                omega: w,
                orbital_rate: y[b + 5],
            },
            [ex, er, et],
        )
    }

    /// Centre (radial plane), centre velocity and land speed of the guiding ring.
    pub(super) fn guide_ring(
        &self,
        guide: &GuideLand,
        t: f64,
        y: &[f64],
    ) -> (Vector3<f64>, Vector3<f64>, f64) {
        match guide.ring {
            RingKind::Outer => {
                let o = self.layout.outer();
                (
                    Vector3::new(0.0, y[o], y[o + 1]),
                    Vector3::new(0.0, y[o + 2], y[o + 3]),
                    0.0,
                )
            }
            RingKind::Inner => {
                let r = self.layout.ring();
                (
                    Vector3::new(0.0, y[r + 1], y[r + 2]),
                    Vector3::new(0.0, y[r + 6], y[r + 7]),
                    self.params.speed.speed_at(t),
                )
            }
        }
    }
}

impl BearingModel {
    /// Derivatives of the border states (rings, cage, energy accumulators;
    /// into `dy`, which starts at the inner ring's first state) for the
    /// summed ball couplings.
    pub(super) fn border_rhs_with(
        &self,
        t: f64,
        y: &[f64],
        inner: &RingMotion,
        balls: &BallCoupling,
        dy: &mut [f64],
        mut sink: Option<&mut Dissipation>,
    ) {
        let l = self.layout;
        let p = &self.params;
        let g = p.gravity;
        let c = l.cage();
        let cage_centre = Vector3::new(0.0, y[c], y[c + 1]);
        let BallCoupling {
            mut ring_force,
            mut ring_moment,
            mut outer_force,
            mut cage_force,
            mut cage_torque,
            mut dissipation,
            film_power,
            ring_velocity_gradient,
            outer_velocity_gradient,
        } = *balls;
        let mut external_power = 0.0;
        // `dy` starts at the inner ring: ring, outer ring, cage and work
        // offsets within it.
        let (dr, dob, dc, dw) = (
            0,
            l.outer() - l.ring(),
            l.cage() - l.ring(),
            l.work() - l.ring(),
        );
        if let Some(guide) = &p.cage.guide {
            let (centre, centre_velocity, land_speed) = self.guide_ring(guide, t, y);
            let cage_velocity = Vector3::new(0.0, y[c + 3], y[c + 4]);
            let gf = guide.forces(&(cage_centre - centre), y[c + 5], land_speed);
            cage_force += gf.force;
            cage_torque += gf.torque;
            // Fluid power is dissipation; the stop spring is conservative.
            let stop_force = -guide.stop_stiffness * gf.stop * (cage_centre - centre).normalize();
            let fluid = gf.force
                - if gf.stop > 0.0 {
                    stop_force
                } else {
                    Vector3::zeros()
                };
            let fluid_power = -(fluid.dot(&(cage_velocity - centre_velocity))
                + gf.torque * (y[c + 5] - land_speed));
            dissipation += fluid_power;
            if let Some(d) = sink.as_deref_mut() {
                d.guide_land = fluid_power;
            }
            match guide.ring {
                RingKind::Inner => {
                    ring_force -= gf.force;
                    ring_moment -= gf.torque * Vector3::x();
                }
                RingKind::Outer => outer_force -= gf.force,
            }
        }
        let r = l.ring();
        dy[dr..dr + 5].copy_from_slice(&y[r + 5..r + 10]);
        let mi = p.inner_ring_mass;
        let loads = p.loads.at(t);
        let (ring_position, ring_velocity) = (
            Vector3::new(y[r], y[r + 1], y[r + 2]),
            Vector3::new(y[r + 5], y[r + 6], y[r + 7]),
        );
        ring_force += p.inner_support.force(&ring_position, &ring_velocity);
        dissipation += p.inner_support.dissipation(&ring_velocity);
        if let Some(d) = sink.as_deref_mut() {
            d.support_damping = p.inner_support.dissipation(&ring_velocity);
        }
        dy[dr + 5] = (ring_force.x + loads.force[0]) / mi;
        dy[dr + 6] = (ring_force.y + loads.force[1]) / mi;
        dy[dr + 7] = (ring_force.z + loads.force[2]) / mi - g;
        dy[dr + 8] = (ring_moment.y + loads.moment[0]) / p.inner_ring_tilt_inertia;
        dy[dr + 9] = (ring_moment.z + loads.moment[1]) / p.inner_ring_tilt_inertia;
        if p.planar {
            for k in [0, 3, 4, 5, 8, 9] {
                dy[dr + k] = 0.0;
            }
        }
        // Tabulated loads: the load potential −F(t)·x changes explicitly
        // with time; that change is work of the external loads.
        let load_rate = p.loads.rate(t);
        external_power -= load_rate.force[0] * y[r]
            + load_rate.force[1] * y[r + 1]
            + load_rate.force[2] * y[r + 2]
            + load_rate.moment[0] * y[r + 3]
            + load_rate.moment[1] * y[r + 4];
        let o = l.outer();
        dy[dob..dob + 4].fill(0.0);
        if let Some(ring) = &p.outer_ring {
            let position = Vector3::new(0.0, y[o], y[o + 1]);
            let velocity = Vector3::new(0.0, y[o + 2], y[o + 3]);
            outer_force += ring.housing.force(&position, &velocity);
            dissipation += ring.housing.dissipation(&velocity);
            if let Some(d) = sink.as_deref_mut() {
                d.support_damping += ring.housing.dissipation(&velocity);
            }
            dy[dob] = y[o + 2];
            dy[dob + 1] = y[o + 3];
            dy[dob + 2] = outer_force.y / ring.mass;
            dy[dob + 3] = outer_force.z / ring.mass - g;
        }
        dy[dc..dc + 3].copy_from_slice(&y[c + 3..c + 6]);
        if p.cage.whirl {
            let [fy, fz] = p.cage.unbalance_force(y[c + 2], y[c + 5]);
            external_power += fy * y[c + 3] + fz * y[c + 4];
            dy[dc + 3] = (cage_force.y + fy) / p.cage.mass;
            dy[dc + 4] = (cage_force.z + fz) / p.cage.mass - g;
        } else {
            dy[dc] = 0.0;
            dy[dc + 1] = 0.0;
            dy[dc + 3] = 0.0;
            dy[dc + 4] = 0.0;
        }
        let cage_speed = y[c + 5];
        let cage_drag = -(p.drag.cage_viscous * cage_speed
            + p.drag.cage_windage * cage_speed * cage_speed.abs());
        dissipation -= cage_drag * cage_speed;
        if let Some(d) = sink {
            d.cage_drag = -cage_drag * cage_speed;
            // Torque the drive supplies: minus the moment of the bearing's
            // forces on the inner ring about its (tilted) axis.
            let speed = p.speed.speed_at(t);
            let axis = if speed != 0.0 {
                (inner.omega - inner.omega_frame) / speed
            } else {
                Vector3::x()
            };
            d.drive_torque = -ring_moment.dot(&axis);
        }
        dy[dc + 5] = (cage_torque + cage_drag) / p.cage.inertia;
        // Drive power: the prescribed spin must supply −ω_i (moment of the
        // contact forces on the ring about its spin axis).
        let spin_axis = inner.omega - inner.omega_frame;
        dy[dw] = -ring_moment.dot(&spin_axis) + external_power;
        dy[dw + 1] = dissipation;
        if l.film_work {
            // The rings' accelerations complete the films' power.
            let dot = |g: &[f64], a: &[f64]| g.iter().zip(a).map(|(g, a)| g * a).sum::<f64>();
            dy[dw + 2] = film_power
                + dot(&ring_velocity_gradient, &dy[dr + 5..dr + 10])
                + dot(&outer_velocity_gradient, &dy[dob + 2..dob + 4]);
        }
    }
}

impl BearingModel {
    /// The equations of motion; with `sink`, also the dissipated power by
    /// component and the drive torque.
    fn rhs_with(
        &self,
        t: f64,
        y: &[f64],
        dy: &mut [f64],
        mut sink: Option<&mut Dissipation>,
        samples: Option<&mut [ContactSample]>,
    ) {
        let l = self.layout;
        let (inner, outer) = self.ring_motion(t, y);
        let (dy_balls, border) = dy.split_at_mut(l.ring());
        let balls = self.ball_pass.sum(
            dy_balls,
            l.ball_len(),
            sink.as_deref_mut(),
            samples,
            |j, dy_ball, sink, sample| {
                self.ball_rhs(t, j, y, &inner, &outer, dy_ball, true, sink, sample)
            },
        );
        self.border_rhs_with(t, y, &inner, &balls, border, sink);
    }

    /// Derivatives `dy` of state `y` at time `t` (as [`OdeSystem::rhs`]) and
    /// the dissipated power by component with the drive torque (docs/model.md §10,
    /// [`crate::power::dissipation`]). Its total equals the rate of the
    /// dissipated-energy accumulator, `dy[layout().work() + 1]`.
    pub fn rhs_with_power(&self, t: f64, y: &[f64], dy: &mut [f64]) -> Dissipation {
        let mut power = Dissipation::default();
        self.rhs_with(t, y, dy, Some(&mut power), None);
        power
    }

    /// [`Self::rhs_with_power`] and every ball's contacts into `samples`
    /// (one entry per ball, as [`Self::contact_samples`]) from the same
    /// evaluation: what an output sample needs, in one pass over the balls
    /// (with fewer entries than balls, two passes).
    pub fn rhs_with_samples(
        &self,
        t: f64,
        y: &[f64],
        dy: &mut [f64],
        samples: &mut [ContactSample],
    ) -> Dissipation {
        let balls = self.layout.balls;
        if samples.len() < balls {
            let power = self.rhs_with_power(t, y, dy);
            self.contact_samples(t, y, samples);
            return power;
        }
        let mut power = Dissipation::default();
        self.rhs_with(t, y, dy, Some(&mut power), Some(&mut samples[..balls]));
        power
    }
}

impl OdeSystem for BearingModel {
    fn dimension(&self) -> usize {
        self.layout.len()
    }

    fn state_name(&self, index: usize) -> String {
        self.layout.state_name(index)
    }

    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        self.rhs_with(t, y, dy, None, None);
    }

    fn blocks(&self) -> Option<&dyn BlockSplit> {
        Some(self)
    }

    /// Characteristic scales: positions 1 µm (contact deflections), speeds
    /// 1 mm/s (contact vibration), tilts 1 µrad, angular speeds 1 rad/s.
    /// The angles that turn without bound (ball azimuths φ, the cage angle,
    /// the balls' spin angles ψ) have the scale of 1 µm along their
    /// circle and no relative part ([`Self::absolute_error`]). The energy
    /// accumulators keep their relative part: held absolutely, to rtol ×
    /// 100 µJ, the balance of the default case did not improve over 1 s
    /// while the Zhang et al. 2025 ramp (hundreds of joules) ran more than three
    /// times as long (docs/performance.md).
    fn error_scale(&self, scale: &mut [f64]) {
        let l = self.layout;
        let micron = 1e-6;
        let ball_orbit = micron / (0.5 * self.geometry.pitch_diameter);
        let ball_surface = micron / (0.5 * self.geometry.ball_diameter);
        for j in 0..l.balls {
            let b = l.ball(j);
            scale[b..b + 2].fill(micron);
            scale[b + 2] = ball_orbit;
            scale[b + 3..b + 5].fill(1e-3);
            scale[b + 5..b + 9].fill(1.0);
            if l.ball_spin_angle {
                scale[b + StateLayout::SPIN_ANGLE] = ball_surface;
            }
        }
        let r = l.ring();
        scale[r..r + 5].fill(micron);
        scale[r + 5..r + 10].fill(1e-3);
        let o = l.outer();
        scale[o..o + 2].fill(micron);
        scale[o + 2..o + 4].fill(1e-3);
        let c = l.cage();
        scale[c..c + 2].fill(micron);
        scale[c + 2] = micron / self.params.cage.pitch_radius;
        scale[c + 3..c + 5].fill(1e-3);
        scale[c + 5] = 1.0;
        let w = l.work();
        scale[w..w + 2].fill(micron);
    }

    /// The ball azimuths, the cage angle and the spin angles grow by 2π a
    /// turn: judged relative to their size, a ball's position along its
    /// orbit would be allowed an error of rtol × 2π per turn made (after
    /// 1 s of the default case, 4.6 rad for a step).
    fn absolute_error(&self, absolute: &mut [bool]) {
        let l = self.layout;
        for j in 0..l.balls {
            let b = l.ball(j);
            absolute[b + 2] = true;
            if l.ball_spin_angle {
                absolute[b + StateLayout::SPIN_ANGLE] = true;
            }
        }
        absolute[l.cage() + 2] = true;
    }

    /// Drive and external work (with the films' work), dissipated energy
    /// and mechanical energy: the balance `rolldyn run` reports, for the
    /// integrators' energy error control.
    fn energy_balance(&self, t: f64, y: &[f64]) -> Option<EnergyBalance> {
        let (work, dissipated) = self.work(y);
        Some(EnergyBalance {
            work: work + self.film_work(y),
            dissipated,
            mechanical: self.energy(t, y).total(),
        })
    }

    /// Spalls: the step may not carry a contact across one unseen.
    fn step_limit(&self, t: f64, y: &[f64]) -> f64 {
        self.spall_step_limit(t, y)
    }

    fn accept_step(&mut self, t: f64, y: &[f64]) -> bool {
        let (inner, outer) = self.ring_motion(t, y);
        let floor = self.params.impact_speed_floor;
        let mut changed = false;
        for j in 0..self.layout.balls {
            let (ball, _) = self.ball_kinematics(j, y);
            for (k, (ring, table)) in [(&inner, &self.inner_table), (&outer, &self.outer_table)]
                .into_iter()
                .enumerate()
            {
                let before = self.episodes[j][k];
                // Only the penetration matters here: no traction.
                let contact = self.race_contact(ring, table, &before, &ball, Want::Penetration);
                let mut episode = before;
                match contact {
                    Some(cn) => {
                        episode.accept(cn.geometry.penetration, cn.penetration_rate, floor);
                        self.peak_loads.raise(k, cn.load);
                    }
                    None => episode.accept(-1.0, 0.0, floor),
                }
                if episode != before {
                    changed = true;
                    self.episodes[j][k] = episode;
                }
            }
        }
        let thermal = self.thermal_update(t, y);
        (changed && self.params.normal_law.hysteresis_factor().is_some()) || thermal
    }
}

/// The inner ring's tilted y axis R_z(θ_z) e_y, about which the tilt rate
/// θ̇_y turns it (docs/model.md §1).
pub(super) fn tilt_axis_y(tilt_z: f64) -> Vector3<f64> {
    if tilt_z == 0.0 {
        return Vector3::y();
    }
    Rotation3::from_axis_angle(&Vector3::z_axis(), tilt_z) * Vector3::y()
}
