//! Several bearings on one rigid shaft, each with its full ball and cage
//! dynamics, the shaft's five rigid-body degrees of freedom shared
//! (docs/systems.md, "Dynamics").
//!
//! Each bearing is a [`BearingModel`] whose inner ring does not move by
//! itself: its states are those of the shaft seen from the bearing,
//! q_i = M_i P_i u + s_i e_x and q̇_i = M_i P_i u̇, with P_i the rigid
//! shaft's small-rotation map to the bearing's pitch plane at x_i, M_i the
//! reflection of a mirrored bearing and s_i its preload offset (the
//! kinematics of the quasi-static set, `quasistatic::system`). The balls'
//! forces and moments on each inner ring, F_i, act on the shaft:
//!
//! ```text
//! m_s ü = Σ_i (M_i P_i)ᵀ F_i + F_applied − m_s g e_z     (x, y, z)
//! I_t θ̈ = Σ_i (M_i P_i)ᵀ F_i + M_applied                 (θ_y, θ_z)
//! ```
//!
//! the rotation about the axis prescribed (every bearing's inner-ring
//! speed, constant) or driven by a torque T(t): J ω̇ = T + Σ_i M_x,i with
//! J the rotor's polar inertia and M_x,i bearing i's moment about the
//! axis, the shaft's angle and speed then two more states after its work
//! (each bearing's model turns a unit inertia without torque, so that its
//! computed ring acceleration is M_x,i). A floating bearing's inner ring
//! follows the shaft axially as any other's while its outer ring slides in
//! its bore (`dynamics::SlidingRing`, states of its own model). A rotating
//! unbalance U = m_u e at x_u adds
//! U ω² (cos ωt, sin ωt) along (y, z) at x_u, with the moments of that
//! force about the reference point (θ_y: −x_u F_z, θ_z: x_u F_y); its work
//! is accumulated in one more shaft state for the energy balance, as is
//! that of harmonic loads F sin(k θ + φ) at their positions (a gear mesh's
//! fluctuation, k the tooth count). A mirrored bearing's own frame is the reflection x → −x of the
//! shaft's: positions and forces along x change sign, and so do the tilts
//! and moments about y and z (pseudovectors); the spin about x does not,
//! so every bearing turns with the shaft's speed in its own frame.
//!
//! The state: every bearing's balls (the implicit integrators' blocks),
//! then each bearing's outer ring, cage and energy accumulators, then the
//! shaft's displacement and velocity. A bearing's right-hand side is its
//! own, evaluated on its state gathered from the system's with the inner
//! ring's slots set from the shaft, its inner ring of unit mass and
//! inertia without load or support so that its computed ring
//! accelerations are F_i (+g along z). The energy: each bearing's balls,
//! outer ring, cage and contacts, the shaft's kinetic energy and the
//! potential of the applied loads and gravity; work and dissipation are
//! the bearings' accumulators.

use super::coupling::BallCoupling;
use super::model::BearingModel;
use crate::error::InvalidParameter;
use crate::integrate::BlockSplit;

mod block_split;
mod checkpoint;
mod ode;
mod rotating;
use crate::operating::{LoadProfile, Loads, TorqueDrive};
use crate::quasistatic::system::{MountedBearing, Orientation, SystemEquilibrium};
pub use rotating::{HarmonicLoad, Unbalance};
use std::sync::Mutex;

/// Shaft states: displacement (x, y, z, θ_y, θ_z) and velocity.
pub const SHAFT_STATES: usize = 10;
/// The shaft's states with the work of its rotating loads and drive; a
/// torque-driven shaft's rotation angle and speed follow.
const SHAFT_LEN: usize = SHAFT_STATES + 1;

/// The rigid shaft's inertia.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShaftBody {
    /// Mass with everything that moves with it (inner rings, hubs) \[kg\].
    pub mass: f64,
    /// Moment of inertia about a diameter through the reference point
    /// \[kg·m²\].
    pub tilt_inertia: f64,
}

/// One bearing of the system: its model and where it sits.
#[derive(Debug, Clone)]
struct Mounted {
    model: BearingModel,
    /// M_i P_i, row-major (ring displacement of unit shaft displacements).
    transform: [[f64; 5]; 5],
    /// Preload offset s_i \[m\].
    offset: f64,
    /// First state of its balls and of its border in the system's state.
    first_ball: usize,
    first_border: usize,
    /// Its first block.
    first_block: usize,
}

impl Mounted {
    /// Its own states set from the shaft's: the inner ring's 10 and a
    /// driven ring's rotation (angle, speed), from its inner ring's first.
    fn slaved(&self) -> usize {
        let l = self.model.layout();
        l.outer() - l.ring()
    }

    fn ring(&self, u: &[f64]) -> [f64; 5] {
        std::array::from_fn(|r| (0..5).map(|k| self.transform[r][k] * u[k]).sum())
    }

    /// (M_i P_i)ᵀ f: a ring load on the shaft.
    fn to_shaft(&self, f: &[f64; 5]) -> [f64; 5] {
        std::array::from_fn(|k| (0..5).map(|r| self.transform[r][k] * f[r]).sum())
    }
}

/// Work buffers: a bearing's state and derivative in its own layout.
#[derive(Debug, Clone, Default)]
struct Buffers {
    y: Vec<f64>,
    dy: Vec<f64>,
}

/// Bearings on one rigid shaft (module doc).
#[derive(Debug)]
pub struct ShaftDynamics {
    bearings: Vec<Mounted>,
    body: ShaftBody,
    loads: Loads,
    unbalance: Option<Unbalance>,
    harmonic_loads: Vec<HarmonicLoad>,
    /// The torque driving the shaft (None: its speed prescribed).
    drive: Option<TorqueDrive>,
    gravity: f64,
    ball_len: usize,
    first_shaft: usize,
    dimension: usize,
    /// A pool of buffers (taken and returned around each bearing's
    /// evaluation; allocated once per concurrent evaluation).
    pool: Mutex<Vec<Buffers>>,
}

impl Clone for ShaftDynamics {
    fn clone(&self) -> Self {
        Self {
            bearings: self.bearings.clone(),
            body: self.body,
            loads: self.loads,
            unbalance: self.unbalance,
            harmonic_loads: self.harmonic_loads.clone(),
            drive: self.drive.clone(),
            gravity: self.gravity,
            ball_len: self.ball_len,
            first_shaft: self.first_shaft,
            dimension: self.dimension,
            pool: Mutex::new(Vec::new()),
        }
    }
}

impl ShaftDynamics {
    /// The system of `bearings` (each model with its mounting on the
    /// shaft: position, orientation, preload offset), the shaft `body` and
    /// the constant `loads` on it at its reference point. The models'
    /// inner-ring mass, loads and support are replaced (the shaft carries
    /// them); their speeds should agree (the shaft's), and so should their
    /// drives: a torque drive turns the shaft (its inertia the rotor's).
    pub fn new(
        bearings: Vec<(BearingModel, &MountedBearing)>,
        body: ShaftBody,
        loads: Loads,
    ) -> Result<Self, InvalidParameter> {
        let Some((first, _)) = bearings.first() else {
            return Err(InvalidParameter::new(
                "bearings",
                0.0,
                "needs at least one bearing",
            ));
        };
        let ball_len = first.layout().ball_len();
        let gravity = first.parameters().gravity;
        let drive = first.parameters().drive.clone();
        for (field, value) in [("mass", body.mass), ("tilt_inertia", body.tilt_inertia)] {
            if !(value.is_finite() && value > 0.0) {
                return Err(InvalidParameter::new(field, value, "must be positive"));
            }
        }
        let balls: usize = bearings.iter().map(|(m, _)| m.layout().balls).sum();
        let mut first_ball = 0;
        let mut first_border = balls * ball_len;
        let mut first_block = 0;
        let mut mounted = Vec::with_capacity(bearings.len());
        for (mut model, mount) in bearings {
            let l = model.layout();
            if l.ball_len() != ball_len {
                return Err(InvalidParameter::new(
                    "bearings",
                    l.ball_len() as f64,
                    "every bearing needs the same ball states (all with surfaces or none)",
                ));
            }
            if l.film_work || model.parameters().planar {
                return Err(InvalidParameter::new(
                    "bearings",
                    0.0,
                    "a shaft system's bearings run without the film in the approach, in 3-D",
                ));
            }
            if mount.floating != l.sliding {
                return Err(InvalidParameter::new(
                    "sliding_outer_ring",
                    if l.sliding { "given" } else { "none" },
                    "a floating bearing's model needs its sliding outer ring, a located one none",
                ));
            }
            if model.parameters().gravity != gravity {
                return Err(InvalidParameter::new(
                    "gravity",
                    model.parameters().gravity,
                    "every bearing needs the same gravity",
                ));
            }
            if model.parameters().drive != drive {
                return Err(InvalidParameter::new(
                    "drive",
                    "differs",
                    "every bearing turns with the shaft: the same drive for all",
                ));
            }
            let p = &mut model.elements.params;
            p.inner_ring_mass = 1.0;
            p.inner_ring_tilt_inertia = 1.0;
            if p.drive.is_some() {
                // Its axial moment then comes out as its ring's
                // acceleration: the shaft sums them.
                p.drive = Some(TorqueDrive::constant(1.0, 0.0));
            }
            p.loads = LoadProfile::Constant(Loads::default());
            // The shaft carries the loads, a rotating unbalance among them.
            p.unbalance = None;
            p.inner_support = super::Support::default();
            let zero = mount.ring_displacement(&[0.0; 5]);
            let mut transform: [[f64; 5]; 5] = std::array::from_fn(|r| {
                std::array::from_fn(|k| {
                    let mut e = [0.0; 5];
                    e[k] = 1.0;
                    mount.ring_displacement(&e)[r] - zero[r]
                })
            });
            if mount.floating {
                // The shaft moves a floating bearing's inner ring axially as
                // any other's; its outer ring slides in its bore (a state of
                // its model) instead of the quasi-static solve's free ring.
                transform[0][0] = match mount.orientation {
                    Orientation::Forward => 1.0,
                    Orientation::Reversed => -1.0,
                };
            }
            let border = l.len() - l.outer();
            mounted.push(Mounted {
                transform,
                offset: mount.axial_offset,
                first_ball,
                first_border,
                first_block,
                model,
            });
            first_ball += l.balls * ball_len;
            first_border += border;
            first_block += l.balls;
        }
        Ok(Self {
            bearings: mounted,
            body,
            loads,
            unbalance: None,
            harmonic_loads: Vec::new(),
            dimension: first_border + SHAFT_LEN + 2 * usize::from(drive.is_some()),
            drive,
            gravity,
            ball_len,
            first_shaft: first_border,
            pool: Mutex::new(Vec::new()),
        })
    }

    /// Number of bearings.
    pub fn bearing_count(&self) -> usize {
        self.bearings.len()
    }

    /// Bearing `i`'s model (its inner ring slaved to the shaft).
    pub fn bearing(&self, i: usize) -> &BearingModel {
        &self.bearings[i].model
    }

    /// First shaft state.
    pub fn shaft(&self) -> usize {
        self.first_shaft
    }

    /// Bearing `i`'s state in its own layout (as a [`BearingModel`]'s)
    /// from the system's state `y`, into `out`.
    pub fn bearing_state(&self, i: usize, y: &[f64], out: &mut [f64]) {
        gather(&self.bearings[i], self.ball_len, self.first_shaft, y, out);
    }

    /// `v` (a shaft displacement, velocity or acceleration: x, y, z, θ_y,
    /// θ_z) as bearing `i`'s inner ring sees it, M_i P_i v.
    pub fn at_bearing(&self, i: usize, v: &[f64; 5]) -> [f64; 5] {
        self.bearings[i].ring(v)
    }

    /// The load on bearing `i`'s inner ring from its balls (and an inner
    /// guide land), in its own frame, from its derivative `dy` as its
    /// right-hand side computes it on its gathered state \[N, N·m\].
    pub fn ring_load(&self, i: usize, dy: &[f64]) -> [f64; 5] {
        let r = self.bearings[i].model.layout().ring();
        self.ring_load_from(&dy[r + 5..r + 10])
    }

    /// The shaft's acceleration (x, y, z, θ_y, θ_z) at time `t` and
    /// system state `y` under the bearings' ring loads `loads` (each in its
    /// own frame, [`Self::ring_load`]), the applied loads and the rotating
    /// ones.
    pub fn shaft_acceleration(&self, t: f64, y: &[f64], loads: &[[f64; 5]]) -> [f64; 5] {
        let mut total = [0.0; 5];
        for (b, f) in self.bearings.iter().zip(loads) {
            total
                .iter_mut()
                .zip(b.to_shaft(f))
                .for_each(|(sum, v)| *sum += v);
        }
        let mut out = [0.0; SHAFT_LEN + 2];
        let state = &y[self.first_shaft..];
        self.shaft_rhs(t, state, &total, 0.0, &mut out[..state.len()]);
        std::array::from_fn(|k| out[5 + k])
    }

    /// Bearing `i`'s mechanical energy without its inner ring's (the
    /// shaft's) at time `t`, from its own-layout state `own` \[J\]: balls,
    /// outer ring, cage, contacts, pockets, gravity.
    pub fn bearing_energy(&self, i: usize, t: f64, own: &[f64]) -> f64 {
        let total = self.bearings[i].model.energy(t, own).total();
        self.without_shaft_parts(i, own, total)
    }

    /// Bearing `i`'s mechanical energy `total` (its model's, at its
    /// own-layout state `own`) less its inner ring's kinetic energy and
    /// gravity's potential, which the shaft carries \[J\].
    fn without_shaft_parts(&self, i: usize, own: &[f64], total: f64) -> f64 {
        let l = self.bearings[i].model.layout();
        let r = l.ring();
        // Its inner ring has unit mass and inertia (module doc), and so has
        // a driven ring about its axis.
        let ring_kinetic = 0.5 * own[r + 5..r + 10].iter().map(|v| v * v).sum::<f64>()
            + if l.driven {
                0.5 * own[l.spin() + 1].powi(2)
            } else {
                0.0
            };
        total - ring_kinetic - self.gravity * own[r + 2]
    }

    /// The shaft's mechanical energy at system state `y` (kinetic, applied
    /// loads' and gravity's potential) \[J\].
    pub fn shaft_mechanical_energy(&self, y: &[f64]) -> f64 {
        self.shaft_energy(&y[self.first_shaft..])
    }

    /// The system's state at a quasi-static equilibrium of the same set
    /// (balls, cages, shaft displacement; velocities of rings zero).
    pub fn initial_state(&self, eq: &SystemEquilibrium) -> Result<Vec<f64>, InvalidParameter> {
        let mut y = vec![0.0; self.dimension];
        for (i, b) in self.bearings.iter().enumerate() {
            let Some(state) = eq.bearings.get(i).and_then(Option::as_ref) else {
                return Err(InvalidParameter::new(
                    "equilibrium",
                    i as f64,
                    "every bearing needs its equilibrium (none may be lifted off)",
                ));
            };
            let mut own = b.model.state_from_equilibrium(state);
            let l = b.model.layout();
            if l.sliding {
                // Its outer ring where the quasi-static solve's free inner
                // ring puts it against the shaft's, the balls with it.
                let ring_x = b.ring(&eq.displacement)[0] + b.offset;
                let slide = ring_x - own[l.ring()];
                own[l.slide()] = slide;
                own[l.ring()] = ring_x;
                for j in 0..l.balls {
                    own[l.ball(j)] += slide;
                }
            }
            let n = l.balls * self.ball_len;
            y[b.first_ball..b.first_ball + n].copy_from_slice(&own[..n]);
            let border = l.len() - l.outer();
            y[b.first_border..b.first_border + border].copy_from_slice(&own[l.outer()..]);
            if l.driven {
                y[self.first_shaft + SHAFT_LEN + 1] = own[l.spin() + 1];
            }
        }
        y[self.first_shaft..self.first_shaft + 5].copy_from_slice(&eq.displacement);
        Ok(y)
    }

    /// Writes bearing `b`'s inner ring (from the shaft) and its border
    /// states into its own-layout `out`.
    fn gather_border(&self, b: &Mounted, y: &[f64], out: &mut [f64]) {
        gather_border(b, self.first_shaft, y, out);
    }

    fn take(&self) -> Buffers {
        let mut buffers = self
            .pool
            .lock()
            .map_or_else(|_| Buffers::default(), |mut p| p.pop().unwrap_or_default());
        let n = self
            .bearings
            .iter()
            .map(|b| b.model.layout().len())
            .max()
            .unwrap_or(0);
        if buffers.y.len() < n {
            buffers.y.resize(n, 0.0);
            buffers.dy.resize(n, 0.0);
        }
        buffers
    }

    fn give(&self, buffers: Buffers) {
        if let Ok(mut p) = self.pool.lock() {
            p.push(buffers);
        }
    }

    /// The ring load F_i from a bearing's computed inner-ring
    /// accelerations (unit mass and inertia, gravity along −z).
    fn ring_load_from(&self, acceleration: &[f64]) -> [f64; 5] {
        let mut f: [f64; 5] = std::array::from_fn(|k| acceleration[k]);
        f[2] += self.gravity;
        f
    }

    /// The shaft's derivatives `out` (its states with the rotating loads'
    /// and the drive's work) from its `state`, the summed bearing loads on
    /// it and, for a driven shaft, the bearings' summed moment about its
    /// axis `axial_moment`, at `t`.
    fn shaft_rhs(
        &self,
        t: f64,
        state: &[f64],
        load: &[f64; 5],
        axial_moment: f64,
        out: &mut [f64],
    ) {
        out[..5].copy_from_slice(&state[5..SHAFT_STATES]);
        let applied = [
            self.loads.force[0],
            self.loads.force[1],
            self.loads.force[2],
            self.loads.moment[0],
            self.loads.moment[1],
        ];
        let rotating = self.rotating_load(t, state);
        for k in 0..5 {
            let inertia = if k < 3 {
                self.body.mass
            } else {
                self.body.tilt_inertia
            };
            out[5 + k] = (load[k] + applied[k] + rotating[k]) / inertia;
        }
        out[7] -= self.gravity;
        out[SHAFT_STATES] = (0..5).map(|k| rotating[k] * state[5 + k]).sum();
        if let Some(drive) = &self.drive {
            let (speed, torque) = (state[SHAFT_LEN + 1], drive.torque_at(t));
            out[SHAFT_LEN] = speed;
            out[SHAFT_LEN + 1] = (torque + axial_moment) / drive.inertia;
            out[SHAFT_STATES] += torque * speed;
        }
    }

    /// The applied loads' potential and gravity's at shaft `state` plus
    /// the shaft's kinetic energy \[J\].
    fn shaft_energy(&self, state: &[f64]) -> f64 {
        let v = &state[5..SHAFT_STATES];
        let applied = [
            self.loads.force[0],
            self.loads.force[1],
            self.loads.force[2],
            self.loads.moment[0],
            self.loads.moment[1],
        ];
        let spin = self
            .drive
            .as_ref()
            .map_or(0.0, |d| 0.5 * d.inertia * state[SHAFT_LEN + 1].powi(2));
        spin + 0.5 * self.body.mass * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
            + 0.5 * self.body.tilt_inertia * (v[3] * v[3] + v[4] * v[4])
            - (0..5).map(|k| applied[k] * state[k]).sum::<f64>()
            + self.body.mass * self.gravity * state[2]
    }

    /// Which bearing and which of its balls system block `block` is.
    fn block_owner(&self, block: usize) -> (usize, usize) {
        let i = self
            .bearings
            .iter()
            .rposition(|b| b.first_block <= block)
            .unwrap_or(0);
        (i, block - self.bearings[i].first_block)
    }

    /// Which bearing a system border state (counted from the first border
    /// state) belongs to and its index counted from that bearing's inner
    /// ring; None for the shaft's.
    fn border_owner(&self, column: usize) -> Option<(usize, usize)> {
        let state = self.bearings[0].first_border + column;
        if state >= self.first_shaft {
            return None;
        }
        let i = self
            .bearings
            .iter()
            .rposition(|b| b.first_border <= state)
            .unwrap_or(0);
        let b = &self.bearings[i];
        Some((i, b.slaved() + state - b.first_border))
    }

    /// The system state index of bearing `b`'s own state `local`, None for
    /// its inner ring's (slaved).
    fn system_index(&self, b: &Mounted, local: usize) -> Option<usize> {
        let l = b.model.layout();
        if local < l.ring() {
            Some(b.first_ball + local)
        } else if local >= l.outer() {
            Some(b.first_border + local - l.outer())
        } else {
            None
        }
    }

    fn memo_parts(&self) -> (usize, usize) {
        let own = self.bearings[0].model.memo_len();
        (own, own + self.ball_len + BallCoupling::LEN)
    }
}

/// Bearing `b`'s inner ring from the shaft states at `shaft` and its
/// border states, from the system's `y` into its own-layout `out`.
fn gather_border(b: &Mounted, shaft: usize, y: &[f64], out: &mut [f64]) {
    let l = b.model.layout();
    let r = l.ring();
    let mut ring = b.ring(&y[shaft..shaft + 5]);
    ring[0] += b.offset;
    out[r..r + 5].copy_from_slice(&ring);
    out[r + 5..r + 10].copy_from_slice(&b.ring(&y[shaft + 5..shaft + 10]));
    if l.driven {
        out[l.spin()..l.outer()].copy_from_slice(&y[shaft + SHAFT_LEN..shaft + SHAFT_LEN + 2]);
    }
    let border = l.len() - l.outer();
    out[l.outer()..l.len()].copy_from_slice(&y[b.first_border..b.first_border + border]);
}

/// Bearing `b`'s full own-layout state from the system's `y` (a free
/// function for the mutable pass of `accept_step`).
fn gather(b: &Mounted, ball_len: usize, shaft: usize, y: &[f64], out: &mut [f64]) {
    let n = b.model.layout().balls * ball_len;
    out[..n].copy_from_slice(&y[b.first_ball..b.first_ball + n]);
    gather_border(b, shaft, y, out);
}

impl ShaftDynamics {
    fn bearing_state_into(&self, b: &Mounted, y: &[f64], out: &mut [f64]) {
        gather(b, self.ball_len, self.first_shaft, y, out);
    }

    /// Bearing `b`'s border derivatives from its own-layout `own` into
    /// `dy` (the system's derivative, or its tail from the first border
    /// state), its ring load added to `shaft_load`; returns its moment
    /// about a driven shaft's axis (0 when prescribed).
    fn collect_border(
        &self,
        b: &Mounted,
        own: &[f64],
        dy: &mut [f64],
        shaft_load: &mut [f64; 5],
    ) -> f64 {
        let l = b.model.layout();
        let border = l.len() - l.outer();
        let at = b.first_border + dy.len() - self.dimension;
        dy[at..at + border].copy_from_slice(&own[l.outer()..]);
        let r = l.ring();
        let load = b.to_shaft(&self.ring_load_from(&own[r + 5..r + 10]));
        shaft_load.iter_mut().zip(load).for_each(|(s, f)| *s += f);
        // Unit inertia, no torque: its ring's acceleration is the moment.
        if l.driven { own[l.spin() + 1] } else { 0.0 }
    }
}
