//! The measurement chain of a vibration record: what an accelerometer on
//! the bearing housing reads, and what the acquisition makes of it
//! (docs/signal.md, "Sensor chain").
//!
//! * **Transfer path.** The force the bearing carries into the housing,
//!   F_h(t) in the radial plane (the outer ring's support force, or the
//!   balls' raceway forces on a fixed outer ring), drives the housing's
//!   structural modes. Each mode is a single-degree-of-freedom oscillator,
//!   isotropic in the radial plane, with its shape normalised to 1 at the
//!   bearing seat and at the sensor:
//!   m_k (q̈_k + 2ζ_k ω_k q̇_k + ω_k² q_k) = F_h(t),
//!   the sensor reading a(t) = e_s · Σ_k q̈_k along its direction e_s.
//!   This is the lumped housing of Sawalhi & Randall (2008), where a
//!   pedestal and a typical high-frequency bearing resonance carry the
//!   impacts to the transducer, taken one way: the housing's motion does
//!   not act back on the bearing (valid when the housing is much stiffer
//!   and heavier at the seat than the outer ring's own support).
//! * **Integration.** Between two accepted steps of the run F_h is taken
//!   linear in time (first-order hold), and each mode is advanced by its
//!   exact solution for that forcing (a damped oscillator's free response
//!   plus the particular solution of a ramp): no step of its own, exact for
//!   any mode frequency, no allocation.
//! * **Acquisition.** The acceleration is averaged over ticks of
//!   1/(R f_s) (R = [`OVERSAMPLING`]; the average is Δq̇/Δt, exact), the
//!   accelerometer's white noise is added, an anti-alias Butterworth
//!   low-pass filters it (the analog filter's bilinear-transform twin at
//!   R f_s, cutoff prewarped), every R-th tick is kept (the sample rate
//!   f_s) and an ADC of `adc_bits` over ±`full_scale` quantises it
//!   (values beyond the range clip and are counted).
//!
//! The chain is deterministic: the noise is SplitMix64 from the case's seed
//! through Box–Muller, drawn tick by tick in time order.

use crate::error::{InvalidParameter, require_non_negative, require_positive};
use crate::integrate::checkpoint::{CheckpointError, StateReader, StateWriter};
use crate::math::random::SplitMix64;
use std::collections::VecDeque;
use std::f64::consts::{PI, TAU};

/// Ticks of the acquisition's internal rate per output sample.
pub const OVERSAMPLING: u32 = 8;

/// One structural mode of the housing as seen from the bearing seat.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HousingMode {
    /// Natural frequency f_k \[Hz\].
    pub frequency: f64,
    /// Damping ratio ζ_k (0 < ζ < 1).
    pub damping_ratio: f64,
    /// Modal mass m_k at the seat \[kg\].
    pub mass: f64,
}

/// The sensor and its acquisition.
#[derive(Debug, Clone, PartialEq)]
pub struct SensorSpec {
    /// Direction of the accelerometer's axis in the radial plane, as a
    /// ball azimuth: e_s = cos(φ_s) e_y + sin(φ_s) e_z \[rad\].
    pub direction: f64,
    /// The housing's modes.
    pub modes: Vec<HousingMode>,
    /// The accelerometer's noise: RMS of its white noise between 0 and half
    /// the sample rate, before the anti-alias filter \[m/s²\].
    pub noise_rms: f64,
    /// Seed of the noise.
    pub seed: u64,
    /// Order of the anti-alias Butterworth low-pass (1–8).
    pub anti_alias_order: u32,
    /// Its −3 dB cutoff \[Hz\] (below half the sample rate).
    pub anti_alias_cutoff: f64,
    /// The ADC's range ± \[m/s²\].
    pub full_scale: f64,
    /// The ADC's resolution \[bits\] (1–32).
    pub adc_bits: u32,
    /// Samples per second f_s \[Hz\].
    pub sample_rate: f64,
}

impl SensorSpec {
    /// Checks every value; the error names the field (`sensor.…`).
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        if !self.direction.is_finite() {
            return Err(InvalidParameter::new(
                "sensor.direction",
                self.direction,
                "must be finite",
            ));
        }
        require_positive("sensor.sample_rate", self.sample_rate)?;
        if self.modes.is_empty() {
            return Err(InvalidParameter::new(
                "sensor.modes",
                0.0,
                "the housing needs at least one mode",
            ));
        }
        for mode in &self.modes {
            require_positive("sensor.modes.frequency", mode.frequency)?;
            require_positive("sensor.modes.mass", mode.mass)?;
            if !(mode.damping_ratio > 0.0 && mode.damping_ratio < 1.0) {
                return Err(InvalidParameter::new(
                    "sensor.modes.damping_ratio",
                    mode.damping_ratio,
                    "must lie between 0 and 1 (an underdamped mode)",
                ));
            }
        }
        require_non_negative("sensor.noise", self.noise_rms)?;
        require_count("sensor.anti_alias_order", self.anti_alias_order, 1..=8)?;
        if !(self.anti_alias_cutoff > 0.0 && self.anti_alias_cutoff < 0.5 * self.sample_rate) {
            return Err(InvalidParameter::new(
                "sensor.anti_alias_cutoff",
                self.anti_alias_cutoff,
                "must lie between 0 and half the sample rate (output.sample_rate)",
            ));
        }
        require_positive("sensor.full_scale", self.full_scale)?;
        require_count("sensor.adc_bits", self.adc_bits, 1..=32)
    }

    /// The unit vector of the sensor's axis (y, z).
    fn axis(&self) -> [f64; 2] {
        [self.direction.cos(), self.direction.sin()]
    }
}

/// `Ok` when the count `value` lies in `range`, else the error naming it.
fn require_count(
    field: &'static str,
    value: u32,
    range: std::ops::RangeInclusive<u32>,
) -> Result<(), InvalidParameter> {
    if range.contains(&value) {
        Ok(())
    } else {
        Err(InvalidParameter::new(
            field,
            value,
            format!("must be {} to {}", range.start(), range.end()),
        ))
    }
}

/// A mode's displacement and velocity in the radial plane (y, z).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
struct ModeState {
    q: [f64; 2],
    v: [f64; 2],
}

impl HousingMode {
    fn omega(&self) -> f64 {
        TAU * self.frequency
    }

    /// The mode advanced by `tau` under the force f₀ + f₁ s (s ∈ [0, τ],
    /// per axis): the exact solution (free damped response about the
    /// ramp's particular solution q_p = A + B s).
    fn advance(&self, state: &ModeState, tau: f64, f0: [f64; 2], f1: [f64; 2]) -> ModeState {
        let w = self.omega();
        let z = self.damping_ratio;
        let wd = w * (1.0 - z * z).sqrt();
        let decay = (-z * w * tau).exp();
        let (s, c) = (wd * tau).sin_cos();
        let mut out = ModeState::default();
        for axis in 0..2 {
            let slope = f1[axis] / (self.mass * w * w);
            let offset = f0[axis] / (self.mass * w * w) - 2.0 * z * slope / w;
            let e0 = state.q[axis] - offset;
            let de0 = state.v[axis] - slope;
            let e = decay * (e0 * c + (de0 + z * w * e0) / wd * s);
            let de = decay * (de0 * c - (w * w * e0 + z * w * de0) / wd * s);
            out.q[axis] = offset + slope * tau + e;
            out.v[axis] = slope + de;
        }
        out
    }

    /// The acceleration q̈ under force `f` (per axis).
    fn acceleration(&self, state: &ModeState, f: [f64; 2]) -> [f64; 2] {
        let w = self.omega();
        let z = self.damping_ratio;
        let a = |k: usize| f[k] / self.mass - 2.0 * z * w * state.v[k] - w * w * state.q[k];
        [a(0), a(1)]
    }
}

/// One second-order (or first-order: b₂ = a₂ = 0) section, transposed
/// direct form II.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
struct Biquad {
    b: [f64; 3],
    a: [f64; 2],
    state: [f64; 2],
}

impl Biquad {
    fn filter(&mut self, x: f64) -> f64 {
        let y = self.b[0] * x + self.state[0];
        self.state[0] = self.b[1] * x - self.a[0] * y + self.state[1];
        self.state[1] = self.b[2] * x - self.a[1] * y;
        y
    }
}

/// The Butterworth low-pass of `order` and −3 dB `cutoff` at `rate` as
/// cascaded sections (bilinear transform with the cutoff prewarped).
fn butterworth(order: u32, cutoff: f64, rate: f64) -> Vec<Biquad> {
    let k = (PI * cutoff / rate).tan();
    let mut sections = Vec::new();
    for i in 1..=order / 2 {
        let q = 1.0 / (2.0 * (PI * f64::from(2 * i - 1) / f64::from(2 * order)).sin());
        let norm = 1.0 / (1.0 + k / q + k * k);
        let b0 = k * k * norm;
        sections.push(Biquad {
            b: [b0, 2.0 * b0, b0],
            a: [2.0 * (k * k - 1.0) * norm, (1.0 - k / q + k * k) * norm],
            state: [0.0; 2],
        });
    }
    if order % 2 == 1 {
        let norm = 1.0 / (1.0 + k);
        sections.push(Biquad {
            b: [k * norm, k * norm, 0.0],
            a: [(k - 1.0) * norm, 0.0],
            state: [0.0; 2],
        });
    }
    sections
}

/// One output sample of the chain.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SensorSample {
    /// Index i of the sample, at t₀ + i/f_s.
    pub index: u64,
    /// The acquired acceleration: filtered, with noise, quantised \[m/s²\].
    pub acquired: f64,
    /// The housing's true acceleration at the sensor at that instant,
    /// noise-free and unfiltered \[m/s²\].
    pub housing: f64,
}

/// The chain running alongside a simulation; [`Self::advance`] at every
/// accepted step, [`Self::sample`] when the run records.
#[derive(Debug, Clone, PartialEq)]
pub struct SensorChain {
    spec: SensorSpec,
    axis: [f64; 2],
    t0: f64,
    /// Time and housing force of the last accepted step.
    t: f64,
    force: [f64; 2],
    modes: Vec<ModeState>,
    /// Next tick to produce (tick k at t₀ + k/(R f_s)).
    tick: u64,
    /// Σ_k e_s·q̇_k at the last tick (for the tick's mean acceleration).
    tick_velocity: f64,
    filter: Vec<Biquad>,
    rng: SplitMix64,
    clipped: u64,
    /// Samples produced and not yet superseded.
    samples: VecDeque<SensorSample>,
}

impl SensorChain {
    /// A chain starting at time `t0` with the housing force `force`
    /// (y, z) \[N\] carried statically: each mode at its static deflection,
    /// at rest.
    pub fn new(spec: SensorSpec, t0: f64, force: [f64; 2]) -> Result<Self, InvalidParameter> {
        spec.validate()?;
        if !force.iter().all(|f| f.is_finite()) {
            return Err(InvalidParameter::new(
                "sensor: the housing force at the start",
                format!("{force:?}"),
                "must be finite",
            ));
        }
        let modes = spec
            .modes
            .iter()
            .map(|m| {
                let k = m.mass * m.omega() * m.omega();
                ModeState {
                    q: [force[0] / k, force[1] / k],
                    v: [0.0; 2],
                }
            })
            .collect();
        let rate = spec.sample_rate * f64::from(OVERSAMPLING);
        let filter = butterworth(spec.anti_alias_order, spec.anti_alias_cutoff, rate);
        let mut chain = Self {
            axis: spec.axis(),
            rng: SplitMix64::new(spec.seed),
            spec,
            t0,
            t: t0,
            force,
            modes,
            tick: 1,
            tick_velocity: 0.0,
            filter,
            clipped: 0,
            samples: VecDeque::new(),
        };
        let first = SensorSample {
            index: 0,
            acquired: chain.quantise(0.0),
            housing: chain.housing_acceleration(force),
        };
        chain.samples.push_back(first);
        Ok(chain)
    }

    /// The sensor's description.
    pub fn spec(&self) -> &SensorSpec {
        &self.spec
    }

    /// Samples beyond the ADC's range so far.
    pub fn clipped(&self) -> u64 {
        self.clipped
    }

    fn tick_time(&self, tick: u64) -> f64 {
        let r = u64::from(OVERSAMPLING);
        let (sample, sub) = (tick / r, tick % r);
        self.t0 + (sample as f64 + sub as f64 / r as f64) / self.spec.sample_rate
    }

    fn housing_acceleration(&self, force: [f64; 2]) -> f64 {
        self.spec
            .modes
            .iter()
            .zip(&self.modes)
            .map(|(m, s)| {
                let a = m.acceleration(s, force);
                a[0] * self.axis[0] + a[1] * self.axis[1]
            })
            .sum()
    }

    fn sensor_velocity(&self) -> f64 {
        self.modes
            .iter()
            .map(|s| s.v[0] * self.axis[0] + s.v[1] * self.axis[1])
            .sum()
    }

    /// A standard normal draw (Box–Muller, one of the pair).
    fn normal(&mut self) -> f64 {
        let u = 1.0 - self.rng.unit();
        let v = self.rng.unit();
        (-2.0 * u.ln()).sqrt() * (TAU * v).cos()
    }

    fn quantise(&mut self, x: f64) -> f64 {
        let step = 2.0 * self.spec.full_scale / 2f64.powi(self.spec.adc_bits as i32);
        let q = (x / step).round() * step;
        let top = self.spec.full_scale - step;
        if q > top || q < -self.spec.full_scale {
            self.clipped += 1;
        }
        q.clamp(-self.spec.full_scale, top)
    }

    fn advance_modes(&mut self, tau: f64, f0: [f64; 2], slope: [f64; 2]) {
        for (m, s) in self.spec.modes.iter().zip(self.modes.iter_mut()) {
            *s = m.advance(s, tau, f0, slope);
        }
    }

    /// Advances the chain to the accepted step at time `t` where the
    /// housing carries `force` (y, z) \[N\], producing the ticks and
    /// samples up to `t` (and those within 1e-12 of it, which the run may
    /// record at its end).
    pub fn advance(&mut self, t: f64, force: [f64; 2]) {
        let interval = t - self.t;
        if interval <= 0.0 {
            return;
        }
        let slope = [
            (force[0] - self.force[0]) / interval,
            (force[1] - self.force[1]) / interval,
        ];
        let (start_time, start_force) = (self.t, self.force);
        let at = move |s: f64| [start_force[0] + slope[0] * s, start_force[1] + slope[1] * s];
        // Samples recorded before the previous step's end are done with.
        let done_before = self.t * (1.0 - 1e-9);
        while self
            .samples
            .front()
            .is_some_and(|s| self.tick_time(s.index * u64::from(OVERSAMPLING)) < done_before)
        {
            self.samples.pop_front();
        }
        let tick_length = 1.0 / (self.spec.sample_rate * f64::from(OVERSAMPLING));
        let noise = self.spec.noise_rms * f64::from(OVERSAMPLING).sqrt();
        let mut now = start_time;
        loop {
            let tick_time = self.tick_time(self.tick);
            if tick_time > t + 1e-12 * t.abs().max(tick_length) {
                break;
            }
            let f_now = at(now - start_time);
            self.advance_modes(tick_time - now, f_now, slope);
            now = tick_time;
            let velocity = self.sensor_velocity();
            let mean_acceleration = (velocity - self.tick_velocity) / tick_length;
            self.tick_velocity = velocity;
            let mut x = mean_acceleration;
            if noise > 0.0 {
                x += noise * self.normal();
            }
            for section in &mut self.filter {
                x = section.filter(x);
            }
            if self.tick % u64::from(OVERSAMPLING) == 0 {
                let sample = SensorSample {
                    index: self.tick / u64::from(OVERSAMPLING),
                    acquired: self.quantise(x),
                    housing: self.housing_acceleration(at(now - start_time)),
                };
                self.samples.push_back(sample);
            }
            self.tick += 1;
        }
        self.advance_modes(t - now, at(now - start_time), slope);
        self.t = t;
        self.force = force;
    }

    /// The sample at time `t` (a sample time of the run: t₀ + i/f_s), if
    /// it has been produced and not yet superseded.
    pub fn sample(&self, t: f64) -> Option<SensorSample> {
        let index = ((t - self.t0) * self.spec.sample_rate).round();
        if index < 0.0 {
            return None;
        }
        let index = index as u64;
        self.samples.iter().find(|s| s.index == index).copied()
    }

    /// Writes the chain's state (for a run's checkpoint).
    pub fn save(&self, out: &mut StateWriter) {
        out.tag("sensor");
        out.f64s(&[self.t, self.force[0], self.force[1], self.tick_velocity]);
        out.u64(self.tick);
        out.u64(self.rng.state());
        out.u64(self.clipped);
        for s in &self.modes {
            out.f64s(&[s.q[0], s.q[1], s.v[0], s.v[1]]);
        }
        for section in &self.filter {
            out.f64s(&section.state);
        }
        out.u64(self.samples.len() as u64);
        for s in &self.samples {
            out.u64(s.index);
            out.f64s(&[s.acquired, s.housing]);
        }
    }

    /// Restores the state [`Self::save`] wrote, into a chain built from
    /// the same spec.
    pub fn restore(&mut self, input: &mut StateReader) -> Result<(), CheckpointError> {
        input.tag("sensor")?;
        let mut head = [0.0; 4];
        input.f64s_into("sensor time and force", &mut head)?;
        [self.t, self.force[0], self.force[1], self.tick_velocity] = head;
        self.tick = input.u64()?;
        self.rng = SplitMix64::new(input.u64()?);
        self.clipped = input.u64()?;
        for s in &mut self.modes {
            let mut m = [0.0; 4];
            input.f64s_into("sensor mode", &mut m)?;
            *s = ModeState {
                q: [m[0], m[1]],
                v: [m[2], m[3]],
            };
        }
        for section in &mut self.filter {
            input.f64s_into("sensor filter", &mut section.state)?;
        }
        let count = input.u64()?;
        self.samples.clear();
        for _ in 0..count {
            let index = input.u64()?;
            let mut v = [0.0; 2];
            input.f64s_into("sensor sample", &mut v)?;
            self.samples.push_back(SensorSample {
                index,
                acquired: v[0],
                housing: v[1],
            });
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests;
