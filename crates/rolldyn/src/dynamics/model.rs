//! State, equations of motion and contact forces of the dynamic model.
//!
//! # State (MODEL §1)
//! Two more states integrate the drive work and the dissipated energy
//! (MODEL §10 bookkeeping). Ball j (9 states): axial x, radial r, azimuth φ, their rates, and the
//! angular velocity (ω_x, ω_r, ω_t) in the ball's azimuth frame
//! (e_x, e_r, e_t), e_r = cos φ e_y + sin φ e_z, e_t = e_x × e_r. Inner ring
//! (10): translation (x, y, z), tilts (θ_y, θ_z) and their rates; its spin
//! ω_i(t) is prescribed (MODEL §8). Cage (6): whirl (y_c, z_c), rotation θ_c
//! and their rates. The outer ring is fixed.
//!
//! # Equations
//! ```text
//! m ẍ = F_x,   m (r̈ − r φ̇²) = F_r,   m (r φ̈ + 2 ṙ φ̇) = F_t
//! ω̇_x = M_x/I,  ω̇_r = M_r/I + φ̇ ω_t,  ω̇_t = M_t/I − φ̇ ω_r,      I = m D²/10
//! inner ring: m_i ẗ = ΣF + F_applied,  I_t θ̈ = ΣM + M_applied      (ring gyroscopics neglected)
//! cage: m_c (ÿ_c, z̈_c) = ΣF,  I_c θ̈_c = ΣM_x                     (seed 001 eq 39)
//! ```
//! Centrifugal and Coriolis terms come from the rotating azimuth frame.
//!
//! # Contacts
//! Ball–raceway: the exact torus contact of MODEL §2.1 (δ, n, contact
//! point P, α). The normal law gives Q from δ, δ̇ = (q̇ − ṗ)·n (p: the
//! groove-centre point, moving with the ring) and the episode's impact
//! speed. Traction acts at P on the tangential slip of ball material
//! relative to ring material, v_b = q̇ + ω_b × (P − q) and
//! v_g = ṫ + ω_ring × (P − t), with ω_ring = ω_i a + the tilt rates. Force
//! on the ball: −Q n + F_T; the ring takes the reaction at P.
//!
//! Ball–pocket (MODEL §5, `linear`, seed 002 eq 6): cylindrical pockets
//! with radial axes at the cage pitch radius. The gap is measured
//! perpendicular to the pocket axis; beyond C_p/2 the force is k δ + c δ̇
//! (≥ 0), with modified-Coulomb friction on the slip at the contact point.
//!
//! Gravity (optional) acts along −z.
//!
//! # Energy (MODEL §10)
//! [`BearingModel::energy`] gives kinetic energy (balls, ring translation
//! and tilt, cage), elastic energy (Σ (2/5) K_c δ^{5/2} + ½ k δ_p²) and the
//! potential of constant applied loads and gravity. With no dissipation and
//! a fixed contact angle (planar mode) their sum is conserved (VALIDATION
//! B1). Where α varies, K_c(α) δ^{3/2} is not the exact gradient of
//! (2/5) K_c δ^{5/2}; the K_c tables vary by ~1e-3 per degree.

use crate::contact::Curvature;
use crate::contact::normal_law::{ContactEpisode, ContactState, NormalLaw};
use crate::contact::{
    ContactTable, GrooveCircle, HertzModel, NormalForceLaw, RacewayContactModel, RingPose,
    TorusContact,
};
use crate::error::InvalidParameter;
use crate::geometry::Raceway;
use crate::geometry::{BearingGeometry, RingKind};
use crate::integrate::OdeSystem;
use crate::kinematics::cage_speed_ratio;
use crate::lubrication::hamrock_dowson;
use crate::material::{Material, effective_modulus};
use crate::operating::{Loads, SpeedProfile};
use crate::quasistatic::Equilibrium;
use crate::traction::ellipse::{self, ContactPatch, TractionIntegration};
use crate::traction::{ModifiedCoulomb, TractionModel};
use nalgebra::{Rotation3, Vector3};

/// Cage data of the dynamic model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CageParameters {
    /// Mass m_c \[kg\].
    pub mass: f64,
    /// Polar moment of inertia I_c \[kg·m²\].
    pub inertia: f64,
    /// Pocket-centre radius r_cp \[m\] (usually d_m/2).
    pub pitch_radius: f64,
    /// Diametral pocket clearance C_p \[m\].
    pub pocket_clearance: f64,
    /// Pocket contact stiffness k \[N/m\].
    pub pocket_stiffness: f64,
    /// Pocket contact damping c \[N·s/m\].
    pub pocket_damping: f64,
    /// Pocket friction.
    pub pocket_friction: ModifiedCoulomb,
    /// Whether the cage centre may whirl (false: rotation only, seed 002).
    pub whirl: bool,
    /// Guide land, if the cage is ring-guided.
    pub guide: Option<GuideLand>,
}

/// A cage guide land (MODEL §5; seed 001 eqs 30–35, short-bearing theory):
/// with eccentricity e of the cage centre from the guiding ring's centre,
/// ε = e/c, land radius R_d, width G, u₁ = R_d (ω_land + ω_c):
/// ```text
/// F_ζ = −η₀ |u₁| G³ ε² / (c² (1 − ε²)²)           along the eccentricity (restoring)
/// F_φ =  π η₀ u₁ G³ ε / (4 c² (1 − ε²)^{3/2})      perpendicular, with the rotation
/// M   =  2π η₀ R_d³ G (ω_land − ω_c) / (c √(1 − ε²))   drag torque on the cage
/// ```
/// Seed 001 eq 32 prints R_d to the first power; R_d³ makes it a torque
/// (MODEL §5). ε is capped at ε_max in these formulas; beyond ε_max c a
/// stiff stop k_s (e − ε_max c) acts (MODEL: "a stiff contact beyond
/// ε_max"). The guiding ring takes the reactions. c is the **radial**
/// clearance, half of the diametral guide clearance C_g of the case file.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GuideLand {
    /// Guiding ring (outer: fixed land; inner: land turning with ω_i).
    pub ring: RingKind,
    /// Land radius R_d \[m\].
    pub land_radius: f64,
    /// Land width G \[m\].
    pub width: f64,
    /// Radial clearance c \[m\].
    pub radial_clearance: f64,
    /// Lubricant viscosity η₀ \[Pa·s\].
    pub viscosity: f64,
    /// Largest eccentricity ratio of the hydrodynamic law ε_max (e.g. 0.95).
    pub max_eccentricity: f64,
    /// Stop stiffness beyond ε_max c \[N/m\].
    pub stop_stiffness: f64,
}

/// Forces of a guide land on the cage.
struct GuideForces {
    /// Force on the cage (radial plane) \[N\].
    force: Vector3<f64>,
    /// Torque on the cage about x \[N·m\].
    torque: f64,
    /// Penetration of the stop \[m\] (for the elastic energy).
    stop: f64,
}

impl GuideLand {
    /// Forces for cage centre offset `rel` from the ring centre (radial plane),
    /// cage speed ω_c and land speed ω_land.
    fn forces(&self, rel: &Vector3<f64>, cage_speed: f64, land_speed: f64) -> GuideForces {
        let c = self.radial_clearance;
        let e = rel.norm();
        let (g, eta, rd) = (self.width, self.viscosity, self.land_radius);
        let eps = (e / c).min(self.max_eccentricity);
        let u1 = rd * (land_speed + cage_speed);
        let torque = 2.0 * std::f64::consts::PI * eta * rd.powi(3) * g * (land_speed - cage_speed)
            / (c * (1.0 - eps * eps).sqrt());
        if e == 0.0 {
            return GuideForces {
                force: Vector3::zeros(),
                torque,
                stop: 0.0,
            };
        }
        let zeta = rel / e;
        let phi = Vector3::x().cross(&zeta);
        let one = 1.0 - eps * eps;
        let f_zeta = -eta * u1.abs() * g.powi(3) * eps * eps / (c * c * one * one);
        let f_phi =
            std::f64::consts::PI * eta * u1 * g.powi(3) * eps / (4.0 * c * c * one.powf(1.5));
        let stop = (e - self.max_eccentricity * c).max(0.0);
        GuideForces {
            force: (f_zeta - self.stop_stiffness * stop) * zeta + f_phi * phi,
            torque,
            stop,
        }
    }
}

/// Drag of the air–oil mixture on balls and cage (seed 001 eqs 10–12, 24,
/// 36; MODEL §3, §5), with the seed's misprints corrected:
/// ```text
/// ball, orbit:  F = −½ ρ_e C_D (π D²/4) v_t |v_t| e_t             (v_t = r φ̇)
/// ball, spin:   M = −½ ρ_e C_n (D/2)⁵ |ω_rel| ω_rel              (ω_rel = ω_b − φ̇ e_x)
/// cage:         M = −(c₁ θ̇_c + c₂ θ̇_c |θ̇_c|)
/// ```
/// Seed 001 eqs 10–12 print M = ½ ρ ω (D/2)⁵ C_n, which is not a torque
/// (N·m·s); the quadratic form above is the rotating-sphere drag torque.
/// Seed 001 eq 24, F = C_D π ρ D² (d_m ω_m)^1.95/(32 g), is Gupta's
/// imperial-unit form (the g converts lbf); in SI with a constant C_D it is
/// the quadratic drag above. Seed 001 eq 36 mixes terms of inconsistent
/// dimensions; MODEL §5 asks for a churning/windage torque with user
/// coefficients, which c₁ (viscous) and c₂ (windage) are. The mixture is
/// taken at rest (outer ring fixed). All zero by default.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DragParameters {
    /// Effective density of the air–oil mixture ρ_e \[kg/m³\].
    pub effective_density: f64,
    /// Ball drag coefficient C_D \[-\].
    pub ball_drag_coefficient: f64,
    /// Ball spin drag coefficient C_n \[-\].
    pub ball_spin_drag_coefficient: f64,
    /// Cage viscous drag c₁ \[N·m·s\].
    pub cage_viscous: f64,
    /// Cage windage drag c₂ \[N·m·s²\].
    pub cage_windage: f64,
}

/// Everything the dynamic model needs besides geometry and materials.
#[derive(Debug, Clone, PartialEq)]
pub struct DynamicsParameters {
    /// Inner-ring (with shaft) mass m_i \[kg\].
    pub inner_ring_mass: f64,
    /// Inner-ring transverse moment of inertia I_t \[kg·m²\].
    pub inner_ring_tilt_inertia: f64,
    /// Cage.
    pub cage: CageParameters,
    /// Normal force law of the ball–raceway contacts.
    pub normal_law: NormalForceLaw,
    /// Impact-speed floor v_floor \[m/s\].
    pub impact_speed_floor: f64,
    /// Traction model of the ball–raceway contacts.
    pub traction: TractionModel,
    /// How traction is integrated over each contact ellipse.
    pub traction_integration: TractionIntegration,
    /// Inner-ring speed profile.
    pub speed: SpeedProfile,
    /// Constant loads on the inner ring.
    pub loads: Loads,
    /// Gravitational acceleration along −z \[m/s²\] (0: off).
    pub gravity: f64,
    /// Planar mode (seed 000): axial coordinates, tilts and the ball spin
    /// components other than ω_x frozen.
    pub planar: bool,
    /// Drag of the air–oil mixture.
    pub drag: DragParameters,
}

/// Offsets of the parts of the state vector.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StateLayout {
    /// Number of balls.
    pub balls: usize,
}

impl StateLayout {
    /// States per ball.
    pub const BALL: usize = 9;
    /// Inner-ring states.
    pub const RING: usize = 10;
    /// Cage states.
    pub const CAGE: usize = 6;
    /// First state of ball j.
    pub fn ball(&self, j: usize) -> usize {
        Self::BALL * j
    }
    /// First inner-ring state.
    pub fn ring(&self) -> usize {
        Self::BALL * self.balls
    }
    /// First cage state.
    pub fn cage(&self) -> usize {
        self.ring() + Self::RING
    }
    /// The two energy accumulators: drive work and dissipated energy \[J\].
    pub fn work(&self) -> usize {
        self.cage() + Self::CAGE
    }
    /// Total number of states.
    pub fn len(&self) -> usize {
        self.work() + 2
    }
    /// Whether there are no states (never, for a valid bearing).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// Contact state of one ball for output.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactSample {
    /// Inner normal load Q_i \[N\].
    pub load_inner: f64,
    /// Outer normal load Q_o \[N\].
    pub load_outer: f64,
    /// Inner contact angle α_i \[rad\] (0 when open).
    pub angle_inner: f64,
    /// Outer contact angle α_o \[rad\] (0 when open).
    pub angle_outer: f64,
}

/// Energy of a state \[J\].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Energy {
    /// Kinetic energy (balls, ring translation and tilt, cage).
    pub kinetic: f64,
    /// Elastic energy of the contacts.
    pub elastic: f64,
    /// Potential of constant applied loads and gravity.
    pub potential: f64,
}

impl Energy {
    /// Sum.
    pub fn total(&self) -> f64 {
        self.kinetic + self.elastic + self.potential
    }
}

/// One evaluated ball–raceway contact.
struct RaceContact {
    geometry: TorusContact,
    penetration_rate: f64,
    /// Dissipated power: normal damping and traction \[W\].
    dissipation: f64,
    /// Force on the ball (normal and traction) \[N\].
    force: Vector3<f64>,
    /// Moment on the ball about its centre \[N·m\].
    moment: Vector3<f64>,
    /// Traction couple about the contact point \[N·m\]; the ring takes
    /// −force at P and −couple.
    couple: Vector3<f64>,
}

/// One evaluated ball–pocket contact.
struct PocketContact {
    /// Force on the ball \[N\].
    force: Vector3<f64>,
    /// Moment on the ball about its centre \[N·m\].
    moment: Vector3<f64>,
    /// Contact point on the ball \[m\].
    point: Vector3<f64>,
    /// Penetration beyond the clearance \[m\].
    penetration: f64,
    /// Dissipated power: damping and friction \[W\].
    dissipation: f64,
}

/// Kinematic state of a ring for contact evaluation.
struct RingMotion {
    raceway: Raceway,
    circle: GrooveCircle,
    centre: Vector3<f64>,
    velocity: Vector3<f64>,
    /// Angular velocity of the ring material (spin + tilt rates).
    omega: Vector3<f64>,
    /// Angular velocity of the ring's frame (tilt rates only).
    omega_frame: Vector3<f64>,
}

/// The dynamic bearing model.
#[derive(Debug, Clone)]
pub struct BearingModel {
    geometry: BearingGeometry,
    inner_table: ContactTable,
    outer_table: ContactTable,
    ball_mass: f64,
    ball_inertia: f64,
    effective_modulus: f64,
    params: DynamicsParameters,
    layout: StateLayout,
    /// Episode memory: inner and outer contact of each ball.
    episodes: Vec<[ContactEpisode; 2]>,
}

fn positive(field: &'static str, v: f64) -> Result<(), InvalidParameter> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(InvalidParameter::new(field, v, "must be positive"))
    }
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
        positive("inner_ring_mass", params.inner_ring_mass)?;
        positive("inner_ring_tilt_inertia", params.inner_ring_tilt_inertia)?;
        positive("cage_mass", params.cage.mass)?;
        positive("cage_inertia", params.cage.inertia)?;
        positive("cage_pitch_radius", params.cage.pitch_radius)?;
        positive("pocket_clearance", params.cage.pocket_clearance)?;
        positive("pocket_stiffness", params.cage.pocket_stiffness)?;
        params.cage.pocket_friction.validate()?;
        params.normal_law.validate()?;
        positive("impact_speed_floor", params.impact_speed_floor)?;
        match params.traction {
            TractionModel::ModifiedCoulomb(m) => m.validate()?,
            TractionModel::Ehl(e) => e.validate()?,
            TractionModel::None => {}
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
            },
            episodes: vec![[ContactEpisode::default(); 2]; geometry.ball_count],
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

    /// Start from a quasi-static (Jones–Harris) solution (seed 002 §3.1):
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

    fn ring_motion(&self, t: f64, y: &[f64]) -> (RingMotion, RingMotion) {
        let r = self.layout.ring();
        let pose = RingPose {
            translation: Vector3::new(y[r], y[r + 1], y[r + 2]),
            tilt_y: y[r + 3],
            tilt_z: y[r + 4],
        };
        let rz = Rotation3::from_axis_angle(&Vector3::z_axis(), pose.tilt_z);
        let omega_frame = y[r + 9] * Vector3::z() + y[r + 8] * (rz * Vector3::y());
        let axis = pose.rotation() * Vector3::x();
        let inner = RingMotion {
            raceway: self.geometry.inner,
            circle: GrooveCircle::of(&self.geometry.inner, &pose),
            centre: pose.translation,
            velocity: Vector3::new(y[r + 5], y[r + 6], y[r + 7]),
            omega: self.params.speed.speed_at(t) * axis + omega_frame,
            omega_frame,
        };
        let outer = RingMotion {
            raceway: self.geometry.outer,
            circle: GrooveCircle::of(&self.geometry.outer, &RingPose::default()),
            centre: Vector3::zeros(),
            velocity: Vector3::zeros(),
            omega: Vector3::zeros(),
            omega_frame: Vector3::zeros(),
        };
        (inner, outer)
    }

    /// Ball centre, velocity and angular velocity (global), and its frame.
    #[allow(clippy::type_complexity)]
    fn ball_kinematics(
        &self,
        j: usize,
        y: &[f64],
    ) -> (Vector3<f64>, Vector3<f64>, Vector3<f64>, [Vector3<f64>; 3]) {
        let b = self.layout.ball(j);
        let (s, c) = y[b + 2].sin_cos();
        let ex = Vector3::x();
        let er = Vector3::new(0.0, c, s);
        let et = Vector3::new(0.0, -s, c);
        let q = y[b] * ex + y[b + 1] * er;
        let v = y[b + 3] * ex + y[b + 4] * er + y[b + 1] * y[b + 5] * et;
        let w = y[b + 6] * ex + y[b + 7] * er + y[b + 8] * et;
        (q, v, w, [ex, er, et])
    }

    fn race_contact(
        &self,
        ring: &RingMotion,
        table: &ContactTable,
        episode: &ContactEpisode,
        q: &Vector3<f64>,
        v: &Vector3<f64>,
        w: &Vector3<f64>,
    ) -> Option<RaceContact> {
        let d = self.geometry.ball_diameter;
        let geometry = ring.circle.contact(q, d, 0.0)?;
        if geometry.penetration <= 0.0 {
            return None;
        }
        let n = geometry.normal;
        let groove_velocity = ring.velocity
            + ring
                .omega_frame
                .cross(&(geometry.groove_centre - ring.centre));
        let penetration_rate = (v - groove_velocity).dot(&n);
        let hertz = table.at(geometry.contact_angle);
        let stiffness = hertz.stiffness;
        let state = ContactState {
            stiffness,
            penetration: geometry.penetration,
            penetration_rate,
            impact_speed: episode.impact_speed(penetration_rate, self.params.impact_speed_floor),
            effective_mass: self.ball_mass,
        };
        let load = self.params.normal_law.force(&state);
        let point = geometry.contact_point;
        let ball_surface = v + w.cross(&(point - q));
        let ring_surface = ring.velocity + ring.omega.cross(&(point - ring.centre));
        let slip = ball_surface - ring_surface;
        let ellipse = hertz.at_load(load);
        // Rolling direction: the azimuthal direction at P, tangent to the contact.
        let azimuthal = Vector3::new(0.0, -point.z, point.y);
        let along = azimuthal - azimuthal.dot(&n) * n;
        let rolling_direction = if along.norm() > 0.0 {
            along.normalize()
        } else {
            n.cross(&Vector3::x()).normalize()
        };
        let film = match &self.params.traction {
            TractionModel::Ehl(ehl) => {
                let entrainment = 0.5 * ((ball_surface - v) + (ring_surface - v));
                let u = (entrainment - entrainment.dot(&n) * n).norm();
                let curvature = Curvature::of_raceway(
                    &ring.raceway,
                    self.geometry.ball_diameter,
                    self.geometry.pitch_diameter,
                    geometry.contact_angle,
                );
                hamrock_dowson(
                    &ehl.lubricant,
                    u,
                    load,
                    curvature.rolling_radius,
                    self.effective_modulus,
                    hertz.ellipticity,
                )
                .central
            }
            _ => 0.0,
        };
        let rg = ring.raceway.groove_radius;
        let rb = 0.5 * self.geometry.ball_diameter;
        let patch = ContactPatch {
            point,
            normal: n,
            rolling_direction,
            semi_major: ellipse.semi_major,
            semi_minor: ellipse.semi_minor,
            load,
            deformed_radius: 2.0 * rg * rb / (rg + rb),
        };
        let traction = ellipse::integrate(
            &self.params.traction,
            self.params.traction_integration,
            &patch,
            q,
            &slip,
            &(w - ring.omega),
            film,
        );
        let elastic = stiffness * geometry.penetration * geometry.penetration.sqrt();
        let dissipation = (load - elastic) * penetration_rate + traction.dissipation;
        Some(RaceContact {
            geometry,
            penetration_rate,
            dissipation,
            force: -load * n + traction.force,
            moment: traction.moment,
            couple: traction.couple,
        })
    }

    /// Pocket contact of ball j, if closed.
    fn pocket_contact(
        &self,
        j: usize,
        y: &[f64],
        q: &Vector3<f64>,
        v: &Vector3<f64>,
        w: &Vector3<f64>,
    ) -> Option<PocketContact> {
        let cage = &self.params.cage;
        let c = self.layout.cage();
        let centre = Vector3::new(0.0, y[c], y[c + 1]);
        let velocity = Vector3::new(0.0, y[c + 3], y[c + 4]);
        let spin = y[c + 5] * Vector3::x();
        let angle = y[c + 2] + std::f64::consts::TAU * j as f64 / self.layout.balls as f64;
        let axis = Vector3::new(0.0, angle.cos(), angle.sin());
        let pocket = centre + cage.pitch_radius * axis;
        let rel = q - pocket;
        let perp = rel - rel.dot(&axis) * axis;
        let dist = perp.norm();
        let penetration = dist - 0.5 * cage.pocket_clearance;
        if penetration <= 0.0 || dist == 0.0 {
            return None;
        }
        let n = perp / dist;
        let point = q + 0.5 * self.geometry.ball_diameter * n;
        let pocket_point_velocity = velocity + spin.cross(&(q - centre));
        let rate = (v - pocket_point_velocity).dot(&n);
        let normal = (cage.pocket_stiffness * penetration + cage.pocket_damping * rate).max(0.0);
        let arm = point - q;
        let slip = (v + w.cross(&arm)) - (velocity + spin.cross(&(point - centre)));
        let slip_t = slip - slip.dot(&n) * n;
        let friction = cage.pocket_friction.force(normal, &slip_t);
        Some(PocketContact {
            force: -normal * n + friction,
            moment: arm.cross(&friction),
            point,
            penetration,
            dissipation: (normal - cage.pocket_stiffness * penetration) * rate
                - friction.dot(&slip_t),
        })
    }

    /// Contact loads and angles of every ball at state `y`, written into
    /// `out` (one entry per ball).
    pub fn contact_samples(&self, t: f64, y: &[f64], out: &mut [ContactSample]) {
        let (inner, outer) = self.ring_motion(t, y);
        for (j, sample) in out.iter_mut().enumerate().take(self.layout.balls) {
            let (q, v, w, _) = self.ball_kinematics(j, y);
            let episodes = &self.episodes[j];
            *sample = ContactSample::default();
            if let Some(c) = self.race_contact(&inner, &self.inner_table, &episodes[0], &q, &v, &w)
            {
                sample.load_inner = (-c.force).dot(&c.geometry.normal);
                sample.angle_inner = c.geometry.contact_angle;
            }
            if let Some(c) = self.race_contact(&outer, &self.outer_table, &episodes[1], &q, &v, &w)
            {
                sample.load_outer = (-c.force).dot(&c.geometry.normal);
                sample.angle_outer = c.geometry.contact_angle;
            }
        }
    }

    /// Pure-rolling cage-speed ratio ω_c/ω_i of MODEL §7 for the current
    /// state: the mean contact angles of the loaded contacts and the mean
    /// ball attitude angle β (spin axis relative to the cage, as in Harris)
    /// in the formula with different inner and outer angles. The reference
    /// of the cage speed ratio (CSR) of seed 002 §4.2.
    pub fn pure_rolling_ratio(&self, samples: &[ContactSample], y: &[f64]) -> f64 {
        let l = self.layout;
        let (mut ai, mut ao, mut beta, mut n) = (0.0, 0.0, 0.0, 0.0);
        for (j, s) in samples.iter().enumerate().take(l.balls) {
            if s.load_inner > 0.0 && s.load_outer > 0.0 {
                let b = l.ball(j);
                ai += s.angle_inner;
                ao += s.angle_outer;
                beta += y[b + 7].atan2(-(y[b + 6] - y[b + 5]));
                n += 1.0;
            }
        }
        let g = &self.geometry;
        let gamma = g.ball_diameter / g.pitch_diameter;
        if n == 0.0 {
            let a = g.nominal_contact_angle();
            return cage_speed_ratio(gamma, a, a, a);
        }
        cage_speed_ratio(gamma, ai / n, ao / n, beta / n)
    }

    /// Centre (radial plane), centre velocity and land speed of the guiding ring.
    fn guide_ring(
        &self,
        guide: &GuideLand,
        t: f64,
        y: &[f64],
    ) -> (Vector3<f64>, Vector3<f64>, f64) {
        match guide.ring {
            RingKind::Outer => (Vector3::zeros(), Vector3::zeros(), 0.0),
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

    /// Drive work and dissipated energy accumulated in state `y` \[J\].
    pub fn work(&self, y: &[f64]) -> (f64, f64) {
        let w = self.layout.work();
        (y[w], y[w + 1])
    }

    /// Mechanical energy of state `y` at time `t` (MODEL §10); its change
    /// equals the drive work minus the dissipated energy.
    pub fn energy(&self, t: f64, y: &[f64]) -> Energy {
        let l = self.layout;
        let (inner, outer) = self.ring_motion(t, y);
        let g = self.params.gravity;
        let mut e = Energy::default();
        for j in 0..l.balls {
            let (q, v, w, _) = self.ball_kinematics(j, y);
            e.kinetic += 0.5 * self.ball_mass * v.norm_squared()
                + 0.5 * self.ball_inertia * w.norm_squared();
            e.potential += self.ball_mass * g * q.z;
            for (ring, table) in [(&inner, &self.inner_table), (&outer, &self.outer_table)] {
                if let Some(c) = ring.circle.contact(&q, self.geometry.ball_diameter, 0.0) {
                    if c.penetration > 0.0 {
                        e.elastic +=
                            0.4 * table.stiffness(c.contact_angle) * c.penetration.powf(2.5);
                    }
                }
            }
            if let Some(pc) = self.pocket_contact(j, y, &q, &v, &w) {
                e.elastic += 0.5 * self.params.cage.pocket_stiffness * pc.penetration.powi(2);
            }
        }
        let r = l.ring();
        let p = &self.params;
        e.kinetic +=
            0.5 * p.inner_ring_mass * (y[r + 5].powi(2) + y[r + 6].powi(2) + y[r + 7].powi(2))
                + 0.5 * p.inner_ring_tilt_inertia * (y[r + 8].powi(2) + y[r + 9].powi(2));
        e.potential -= p.loads.force[0] * y[r]
            + p.loads.force[1] * y[r + 1]
            + p.loads.force[2] * y[r + 2]
            + p.loads.moment[0] * y[r + 3]
            + p.loads.moment[1] * y[r + 4];
        e.potential += p.inner_ring_mass * g * y[r + 2];
        let c = l.cage();
        e.kinetic += 0.5 * p.cage.mass * (y[c + 3].powi(2) + y[c + 4].powi(2))
            + 0.5 * p.cage.inertia * y[c + 5].powi(2);
        e.potential += p.cage.mass * g * y[c + 1];
        e
    }
}

impl OdeSystem for BearingModel {
    fn dimension(&self) -> usize {
        self.layout.len()
    }

    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        let l = self.layout;
        let p = &self.params;
        let (inner, outer) = self.ring_motion(t, y);
        let g = p.gravity;
        let mut ring_force = Vector3::zeros();
        let mut ring_moment = Vector3::zeros();
        let mut cage_force = Vector3::zeros();
        let mut cage_torque = 0.0;
        let mut dissipation = 0.0;
        let c = l.cage();
        let cage_centre = Vector3::new(0.0, y[c], y[c + 1]);
        for j in 0..l.balls {
            let (q, v, w, [ex, er, et]) = self.ball_kinematics(j, y);
            let mut force = Vector3::new(0.0, 0.0, -self.ball_mass * g);
            let mut moment = Vector3::zeros();
            let episodes = &self.episodes[j];
            if let Some(cn) = self.race_contact(&inner, &self.inner_table, &episodes[0], &q, &v, &w)
            {
                force += cn.force;
                moment += cn.moment;
                ring_force -= cn.force;
                ring_moment +=
                    (cn.geometry.contact_point - inner.centre).cross(&(-cn.force)) - cn.couple;
                dissipation += cn.dissipation;
            }
            if let Some(cn) = self.race_contact(&outer, &self.outer_table, &episodes[1], &q, &v, &w)
            {
                force += cn.force;
                moment += cn.moment;
                dissipation += cn.dissipation;
            }
            if let Some(pc) = self.pocket_contact(j, y, &q, &v, &w) {
                force += pc.force;
                moment += pc.moment;
                cage_force -= pc.force;
                cage_torque += (pc.point - cage_centre).cross(&(-pc.force)).x;
                dissipation += pc.dissipation;
            }
            let b = l.ball(j);
            let drag = &p.drag;
            if drag.effective_density > 0.0 {
                let d = self.geometry.ball_diameter;
                let v_t = y[b + 1] * y[b + 5];
                let f = -0.5
                    * drag.effective_density
                    * drag.ball_drag_coefficient
                    * std::f64::consts::FRAC_PI_4
                    * d
                    * d
                    * v_t
                    * v_t.abs();
                force += f * et;
                let w_rel = w - y[b + 5] * ex;
                let m = -0.5
                    * drag.effective_density
                    * drag.ball_spin_drag_coefficient
                    * (0.5 * d).powi(5)
                    * w_rel.norm()
                    * w_rel;
                moment += m;
                dissipation -= f * v_t + m.dot(&w);
            }
            let (r, phi_dot, vr) = (y[b + 1], y[b + 5], y[b + 4]);
            let (wr, wt) = (y[b + 7], y[b + 8]);
            let m = self.ball_mass;
            let inertia = self.ball_inertia;
            dy[b] = y[b + 3];
            dy[b + 1] = vr;
            dy[b + 2] = phi_dot;
            dy[b + 3] = force.dot(&ex) / m;
            dy[b + 4] = force.dot(&er) / m + r * phi_dot * phi_dot;
            dy[b + 5] = (force.dot(&et) / m - 2.0 * vr * phi_dot) / r;
            dy[b + 6] = moment.dot(&ex) / inertia;
            dy[b + 7] = moment.dot(&er) / inertia + phi_dot * wt;
            dy[b + 8] = moment.dot(&et) / inertia - phi_dot * wr;
            if p.planar {
                dy[b] = 0.0;
                dy[b + 3] = 0.0;
                dy[b + 7] = 0.0;
                dy[b + 8] = 0.0;
            }
        }
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
            dissipation -=
                fluid.dot(&(cage_velocity - centre_velocity)) + gf.torque * (y[c + 5] - land_speed);
            if guide.ring == RingKind::Inner {
                ring_force -= gf.force;
                ring_moment -= gf.torque * Vector3::x();
            }
        }
        let r = l.ring();
        dy[r..r + 5].copy_from_slice(&y[r + 5..r + 10]);
        let mi = p.inner_ring_mass;
        dy[r + 5] = (ring_force.x + p.loads.force[0]) / mi;
        dy[r + 6] = (ring_force.y + p.loads.force[1]) / mi;
        dy[r + 7] = (ring_force.z + p.loads.force[2]) / mi - g;
        dy[r + 8] = (ring_moment.y + p.loads.moment[0]) / p.inner_ring_tilt_inertia;
        dy[r + 9] = (ring_moment.z + p.loads.moment[1]) / p.inner_ring_tilt_inertia;
        if p.planar {
            for k in [0, 3, 4, 5, 8, 9] {
                dy[r + k] = 0.0;
            }
        }
        dy[c..c + 3].copy_from_slice(&y[c + 3..c + 6]);
        if p.cage.whirl {
            dy[c + 3] = cage_force.y / p.cage.mass;
            dy[c + 4] = cage_force.z / p.cage.mass - g;
        } else {
            dy[c] = 0.0;
            dy[c + 1] = 0.0;
            dy[c + 3] = 0.0;
            dy[c + 4] = 0.0;
        }
        let cage_speed = y[c + 5];
        let cage_drag = -(p.drag.cage_viscous * cage_speed
            + p.drag.cage_windage * cage_speed * cage_speed.abs());
        dissipation -= cage_drag * cage_speed;
        dy[c + 5] = (cage_torque + cage_drag) / p.cage.inertia;
        // Drive power: the prescribed spin must supply −ω_i (moment of the
        // contact forces on the ring about its spin axis).
        let spin_axis = inner.omega - inner.omega_frame;
        let w = l.work();
        dy[w] = -ring_moment.dot(&spin_axis);
        dy[w + 1] = dissipation;
    }

    /// Characteristic scales: positions 1 µm (contact deflections), speeds
    /// 1 mm/s (contact vibration), angles 1 µrad, angular speeds 1 rad/s.
    fn error_scale(&self, scale: &mut [f64]) {
        let l = self.layout;
        for j in 0..l.balls {
            let b = l.ball(j);
            scale[b..b + 3].fill(1e-6);
            scale[b + 3..b + 5].fill(1e-3);
            scale[b + 5..b + 9].fill(1.0);
        }
        let r = l.ring();
        scale[r..r + 5].fill(1e-6);
        scale[r + 5..r + 10].fill(1e-3);
        let c = l.cage();
        scale[c..c + 3].fill(1e-6);
        scale[c + 3..c + 5].fill(1e-3);
        scale[c + 5] = 1.0;
        let w = l.work();
        scale[w..w + 2].fill(1e-6);
    }

    fn accept_step(&mut self, t: f64, y: &[f64]) -> bool {
        let (inner, outer) = self.ring_motion(t, y);
        let floor = self.params.impact_speed_floor;
        let mut changed = false;
        for j in 0..self.layout.balls {
            let (q, v, w, _) = self.ball_kinematics(j, y);
            for (k, (ring, table)) in [(&inner, &self.inner_table), (&outer, &self.outer_table)]
                .into_iter()
                .enumerate()
            {
                let before = self.episodes[j][k];
                let contact = self.race_contact(ring, table, &before, &q, &v, &w);
                let mut episode = before;
                match contact {
                    Some(cn) => episode.accept(cn.geometry.penetration, cn.penetration_rate, floor),
                    None => episode.accept(-1.0, 0.0, floor),
                }
                if episode != before {
                    changed = true;
                    self.episodes[j][k] = episode;
                }
            }
        }
        changed && self.params.normal_law.hysteresis_factor().is_some()
    }
}
