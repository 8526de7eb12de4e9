//! State and equations of motion of the dynamic model: the assembly of
//! the force elements' shares into the balls', rings' and cage's
//! accelerations, and the memory a run carries.
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
//! Each lives in its own file below this one (ARCHITECTURE.md, "Layers"):
//! methods of [`super::elements::Elements`] or laws that take the bodies'
//! motion ([`super::motion`]) and return their share: ball–raceway contact
//! and rolling resistance ([`super::race_contact`]), ball–pocket
//! ([`super::pocket`]), drag ([`crate::lubrication::drag`]), ring supports
//! ([`super::supports`]), seals ([`crate::seals`]); the energy
//! bookkeeping is in [`super::energy`], output quantities in
//! [`super::outputs`]; a ball's equations sum its contacts' shares in
//! `dynamics::ball_equations`, and the block structure the implicit
//! integrators use is in `dynamics::block_split`. Gravity (optional) acts
//! along −z.

use super::ball_pass::BallPass;
use super::elements::Elements;
use super::end_point::{EndPoint, EndRecord};
use super::layout::StateLayout;
use super::motion::RingMotion;
use super::parameters::DynamicsParameters;
use super::peaks::PeakLoads;
use super::race_contact::{ContactSample, Want};
use super::thermal_coupling::ThermalCoupling;
use crate::contact::HertzModel;
use crate::contact::normal_law::ContactEpisode;
use crate::error::InvalidParameter;
use crate::geometry::BearingGeometry;
use crate::integrate::{BlockSplit, EnergyBalance, OdeSystem};
use crate::kinematics::cage_speed_ratio;
use crate::material::Material;
use crate::power::Dissipation;
use crate::quasistatic::Equilibrium;
use crate::signal::sensor::SensorChain;
use crate::thermal::bearing::HeatSources;
use nalgebra::Vector3;

/// The dynamic bearing model: its force elements and the memory a run
/// carries (contact episodes, peak loads, the thermal network, the
/// sensor chain, the growing spalls' lengths).
#[derive(Debug, Clone)]
pub struct BearingModel {
    /// Geometry, contact tables, masses and parameters: what the force
    /// elements evaluate.
    pub(super) elements: Elements,
    /// Episode memory: inner and outer contact of each ball.
    pub(super) episodes: Vec<[ContactEpisode; 2]>,
    /// Largest contact loads at the accepted steps since the sampler took
    /// them ([`super::peaks`]).
    pub(super) peak_loads: PeakLoads,
    /// Thermal network advanced alongside a run, if coupled.
    pub(super) thermal: Option<Box<ThermalCoupling>>,
    /// Sensor chain advanced alongside a run, if attached.
    pub(super) sensor: Option<Box<SensorChain>>,
    /// The spalls that grow over the run ([`super::spall_growth`]).
    pub(super) growth: Vec<crate::surface::GrowingSpall>,
    /// The balls' contact evaluations, serial or across threads.
    pub(super) ball_pass: BallPass,
    /// The last step's candidate end, evaluated with its energy and
    /// raceway records (`dynamics::end_point`).
    pub(super) end_point: EndPoint,
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
        let ball_pass = BallPass::new(
            geometry.ball_count,
            params
                .traction
                .integrates_over_a_grid(&params.traction_integration),
        );
        let elements = Elements::new(geometry, ball, rings, hertz, params)?;
        let end_point = EndPoint::new(geometry.ball_count, elements.layout.len());
        let mut model = Self {
            elements,
            episodes: vec![[ContactEpisode::default(); 2]; geometry.ball_count],
            peak_loads: PeakLoads::default(),
            thermal: None,
            sensor: None,
            growth: Vec::new(),
            ball_pass,
            end_point,
        };
        model.growth = model.elements.params.surface.growing_spalls();
        Ok(model)
    }

    /// State layout.
    pub fn layout(&self) -> StateLayout {
        self.elements.layout
    }

    /// Parameters.
    pub fn parameters(&self) -> &DynamicsParameters {
        &self.elements.params
    }

    /// Bearing geometry.
    pub fn geometry(&self) -> &BearingGeometry {
        &self.elements.geometry
    }

    /// The inner ring's speed \[rad/s\] at (t, y): a torque-driven ring's
    /// state, else the prescribed profile's.
    pub fn inner_speed(&self, t: f64, y: &[f64]) -> f64 {
        self.elements.spin(t, y).speed
    }

    /// Ball mass \[kg\].
    pub fn ball_mass(&self) -> f64 {
        self.elements.ball_mass
    }

    /// Pure-rolling start: balls at the pitch circle with the pure-rolling
    /// orbital and spin speeds at the nominal contact angle, the cage turning
    /// with them, the inner ring at `ring_displacement` and at rest.
    pub fn pure_rolling_state(&self, ring_displacement: [f64; 5]) -> Vec<f64> {
        let g = &self.elements.geometry;
        let l = self.elements.layout;
        let mut y = vec![0.0; l.len()];
        let omega_i = self.elements.params.speed.speed_at(0.0);
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
            if !self.elements.params.planar {
                y[b + 7] = -spin_rel * alpha.sin();
            }
        }
        let r = l.ring();
        y[r..r + 5].copy_from_slice(&ring_displacement);
        let c = l.cage();
        y[c + 5] = omega_c;
        self.start_rotation(&mut y);
        y
    }

    /// Seats a start state `y` in its housing: with the outer ring on a
    /// housing spring, the whole bearing is moved by the spring's static
    /// deflection under the loads at t = 0 and every body's weight
    /// (outer ring, balls, cage, inner ring), so that a run does not start
    /// by dropping into its housing. The bearing's own deflection (the
    /// start's inner-ring displacement relative to the outer ring) is kept.
    /// No change with a fixed outer ring or without radial stiffness.
    pub fn seat_in_housing(&self, y: &mut [f64]) {
        let p = &self.elements.params;
        let Some(ring) = p.outer_ring.as_ref() else {
            return;
        };
        let l = self.elements.layout;
        let loads = p.loads.at(0.0);
        let weight = p.gravity
            * (ring.mass
                + p.inner_ring_mass
                + p.cage.mass
                + self.elements.ball_mass * l.balls as f64);
        let force = [loads.force[1], loads.force[2] - weight];
        let shift: [f64; 2] = std::array::from_fn(|k| {
            let k_h = ring.housing.stiffness[k + 1];
            if k_h > 0.0 { force[k] / k_h } else { 0.0 }
        });
        if shift == [0.0, 0.0] {
            return;
        }
        let o = l.outer();
        y[o] += shift[0];
        y[o + 1] += shift[1];
        let r = l.ring();
        y[r + 1] += shift[0];
        y[r + 2] += shift[1];
        for j in 0..l.balls {
            let b = l.ball(j);
            let (radius, azimuth) = (y[b + 1], y[b + 2]);
            let yy = radius * azimuth.cos() + shift[0];
            let zz = radius * azimuth.sin() + shift[1];
            y[b + 1] = yy.hypot(zz);
            // Keep the azimuth's turn count: move it by the small change.
            let moved = zz.atan2(yy);
            let change = (moved - azimuth).rem_euclid(std::f64::consts::TAU);
            y[b + 2] = azimuth
                + if change > std::f64::consts::PI {
                    change - std::f64::consts::TAU
                } else {
                    change
                };
        }
    }

    /// A driven ring starts at the profile's speed, at angle 0.
    fn start_rotation(&self, y: &mut [f64]) {
        let l = self.elements.layout;
        if l.driven {
            y[l.spin() + 1] = self.elements.params.speed.speed_at(0.0);
        }
    }

    /// Start from a quasi-static (Jones–Harris) solution (Zhang et al. 2025 §3.1):
    /// ball positions and speeds, ring displacement; cage at the mean ball
    /// orbital speed.
    pub fn state_from_equilibrium(&self, eq: &Equilibrium) -> Vec<f64> {
        let l = self.elements.layout;
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
        self.start_rotation(&mut y);
        y
    }
}

impl BearingModel {
    /// The equations of motion; with `sink`, also the dissipated power by
    /// component and the drive torque; with `samples`, the raceway
    /// contacts' outputs; with `ends`, each ball's end-point record
    /// (`dynamics::end_point`).
    pub(super) fn rhs_with(
        &self,
        t: f64,
        y: &[f64],
        dy: &mut [f64],
        mut sink: Option<&mut Dissipation>,
        samples: Option<&mut [ContactSample]>,
        ends: Option<&mut [EndRecord]>,
    ) {
        let l = self.elements.layout;
        let (inner, outer) = self.elements.ring_motion(t, y);
        let (dy_balls, border) = dy.split_at_mut(l.ring());
        let balls = self.ball_pass.sum(
            dy_balls,
            l.ball_len(),
            sink.as_deref_mut(),
            (samples, ends),
            |j, dy_ball, sink, extras| {
                self.ball_rhs(t, j, y, (&inner, &outer), dy_ball, (sink, extras))
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
        self.rhs_with(t, y, dy, Some(&mut power), None, None);
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
        let balls = self.elements.layout.balls;
        if samples.len() < balls {
            let power = self.rhs_with_power(t, y, dy);
            self.contact_samples(t, y, samples);
            return power;
        }
        let mut power = Dissipation::default();
        self.rhs_with(
            t,
            y,
            dy,
            Some(&mut power),
            Some(&mut samples[..balls]),
            None,
        );
        power
    }
}

impl OdeSystem for BearingModel {
    fn dimension(&self) -> usize {
        self.elements.layout.len()
    }

    fn state_name(&self, index: usize) -> String {
        self.elements.layout.state_name(index)
    }

    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        self.rhs_with(t, y, dy, None, None, None);
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
        let l = self.elements.layout;
        let micron = 1e-6;
        let ball_orbit = micron / (0.5 * self.elements.geometry.pitch_diameter);
        let ball_surface = micron / (0.5 * self.elements.geometry.ball_diameter);
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
        scale[c + 2] = micron / self.elements.params.cage.pitch_radius;
        scale[c + 3..c + 5].fill(1e-3);
        scale[c + 5] = 1.0;
        if l.sliding {
            scale[l.slide()] = micron;
            scale[l.slide() + 1] = 1e-3;
        }
        if l.driven {
            scale[l.spin()] = micron / (0.5 * self.elements.geometry.pitch_diameter);
            scale[l.spin() + 1] = 1.0;
        }
        let w = l.work();
        scale[w..w + 2].fill(micron);
    }

    /// The ball azimuths, the cage angle and the spin angles grow by 2π a
    /// turn: judged relative to their size, a ball's position along its
    /// orbit would be allowed an error of rtol × 2π per turn made (after
    /// 1 s of the default case, 4.6 rad for a step).
    fn absolute_error(&self, absolute: &mut [bool]) {
        let l = self.elements.layout;
        for j in 0..l.balls {
            let b = l.ball(j);
            absolute[b + 2] = true;
            if l.ball_spin_angle {
                absolute[b + StateLayout::SPIN_ANGLE] = true;
            }
        }
        absolute[l.cage() + 2] = true;
        if l.driven {
            absolute[l.spin()] = true;
        }
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
        self.elements.spall_step_limit(t, y)
    }

    /// The candidate end's right-hand side and balance from one pass over
    /// the balls, its raceway records kept for `accept_step`
    /// (`dynamics::end_point`).
    fn rhs_at_end(
        &mut self,
        t: f64,
        y: &[f64],
        dy: &mut [f64],
        balance: bool,
    ) -> Option<EnergyBalance> {
        self.rhs_with_end_records(t, y, dy, balance)
    }

    /// Records each raceway contact's episode and peak load and advances
    /// the sensor chain, the growing spalls and the thermal network; the
    /// contacts come from the `rhs_at_end` evaluation at (t, y) if
    /// that was the last, else are evaluated here (normal forces only).
    fn accept_step(&mut self, t: f64, y: &[f64]) -> bool {
        let floor = self.elements.params.impact_speed_floor;
        let mut changed = false;
        let mut outer_raceway = Vector3::zeros();
        let source = match self.end_point.take_at(t, y) {
            Some(balls) => Records::Kept(balls),
            None => {
                let (inner, outer) = self.elements.ring_motion(t, y);
                Records::Evaluate(inner, outer)
            }
        };
        for j in 0..self.elements.layout.balls {
            let raceways = match &source {
                Records::Kept(balls) => balls[j].raceways,
                Records::Evaluate(inner, outer) => {
                    self.elements
                        .raceway_records(j, y, (inner, outer), &self.episodes[j])
                }
            };
            for (k, record) in raceways.into_iter().enumerate() {
                let before = self.episodes[j][k];
                let mut episode = before;
                match record {
                    Some(r) => {
                        episode.accept(r.penetration, r.penetration_rate, floor);
                        self.peak_loads.raise(k, r.load);
                        if k == 1 {
                            outer_raceway += r.ring_force;
                        }
                    }
                    None => episode.accept(-1.0, 0.0, floor),
                }
                if episode != before {
                    changed = true;
                    self.episodes[j][k] = episode;
                }
            }
        }
        self.sensor_update(t, y, outer_raceway);
        let grown = !self.growth.is_empty() && self.grow_spalls(t, y);
        let thermal = self.thermal_update(t, y);
        grown
            || (changed
                && self
                    .elements
                    .params
                    .normal_law
                    .hysteresis_factor()
                    .is_some())
            || thermal
    }
}

/// Where an acceptance takes its raceway records from (one on the stack
/// per acceptance: its size does not matter).
#[allow(clippy::large_enum_variant)]
enum Records<'a> {
    /// The `rhs_at_end` evaluation at the accepted point.
    Kept(&'a [EndRecord]),
    /// Evaluated anew with these ring motions (inner, outer).
    Evaluate(RingMotion, RingMotion),
}

/// The thermal network advanced alongside a run (`thermal_coupling`).
impl BearingModel {
    /// Couples the thermal network to this model's run from time `t0` and
    /// state `y0` (the dissipated energy counts from there) and applies the
    /// starting viscosities.
    pub fn couple_thermal(&mut self, mut coupling: ThermalCoupling, t0: f64, y0: &[f64]) {
        let viscosities = coupling.start(t0, self.work(y0).1, self.dimension());
        self.elements.apply_viscosities(viscosities);
        self.thermal = Some(Box::new(coupling));
    }

    /// The thermal coupling, if the run has one.
    pub fn thermal(&self) -> Option<&ThermalCoupling> {
        self.thermal.as_deref()
    }

    /// Whether its passes over the balls run across the current pool's
    /// threads (traction over a grid, enough balls, more than one thread).
    pub fn runs_in_parallel(&self) -> bool {
        self.ball_pass.is_parallel()
    }

    /// The coupling's update at an accepted step; true when the right-hand
    /// side changed (the viscosity).
    fn thermal_update(&mut self, t: f64, y: &[f64]) -> bool {
        let Some(mut c) = self.thermal.take() else {
            return false;
        };
        if !c.due(t) {
            self.thermal = Some(c);
            return false;
        }
        let dissipated = self.work(y).1;
        let mut scratch = std::mem::take(&mut c.scratch);
        let power = self.rhs_with_power(t, y, &mut scratch);
        c.scratch = scratch;
        let cage_speed = y[self.elements.layout.cage() + 5];
        let viscosities = c.advance(t, dissipated, &power, cage_speed, |heat| {
            self.contact_means(t, y, heat)
        });
        self.thermal = Some(c);
        self.elements.apply_viscosities(viscosities);
        viscosities.is_some()
    }

    /// Mean semi-axes, entrainment speeds and counts of the loaded contacts.
    fn contact_means(&self, t: f64, y: &[f64], heat: &mut HeatSources) {
        let e = &self.elements;
        let (inner, outer) = e.ring_motion(t, y);
        let rings = [(&inner, &e.inner_table), (&outer, &e.outer_table)];
        heat.set_contact_means((0..e.layout.balls).flat_map(|j| {
            let (ball, _) = e.ball_kinematics(j, y);
            rings
                .into_iter()
                .enumerate()
                .filter_map(move |(k, (ring, table))| {
                    let cn =
                        e.race_contact(ring, table, &self.episodes[j][k], &ball, Want::Output)?;
                    let o = cn.output;
                    (o.load > 0.0).then(|| {
                        let e = table.at(o.angle).at_load(o.load);
                        (k, e.semi_major, e.semi_minor, o.entrainment_speed)
                    })
                })
        }));
    }
}
