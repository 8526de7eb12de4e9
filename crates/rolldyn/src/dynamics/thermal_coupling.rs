//! Temperatures during a dynamic run (docs/model.md §10): the bearing's
//! thermal network ([`crate::thermal::bearing`]) advanced on its own,
//! slower time scale alongside the integration, feeding the oil viscosity
//! back into the EHL traction and the guide land.
//!
//! Every `interval` of simulated time (at the first accepted step past
//! it), the coupling
//! 1. takes the dissipated energy over the interval from the energy
//!    balance's accumulator (exact) and splits it like the dissipation by
//!    component at that instant ([`super::BearingModel::rhs_with_power`]): race
//!    contacts to the contact nodes, pocket losses to the balls, guide
//!    land, drag and support dampers to the oil;
//! 2. takes the loaded contacts' mean Hertz semi-axes and entrainment
//!    speeds from the current state;
//! 3. advances the network by one trapezoidal step of the interval (the
//!    parts' time constants are seconds to minutes, the interval
//!    milliseconds);
//! 4. sets η₀ of the EHL traction to the Walther viscosity at the contact
//!    inlet, taken as the mean of the ball and mean-ring temperatures, and
//!    the guide land's and the pocket squeeze film's to the viscosity at
//!    the oil node.
//!
//! The step that changes the viscosity tells the integrator
//! (`accept_step` returns true), which re-evaluates the right-hand side.

use crate::error::InvalidParameter;
use crate::integrate::checkpoint::{CheckpointError, StateReader, StateWriter};
use crate::power::Dissipation;
use crate::thermal::bearing::{BearingThermal, HeatSources, ThermalInputs, node_index};
use crate::thermal::viscosity::Walther;

/// The thermal state carried by a coupled run.
#[derive(Debug, Clone, PartialEq)]
pub struct ThermalCoupling {
    inputs: ThermalInputs,
    viscosity: Option<Walther>,
    interval: f64,
    next_update: f64,
    last_time: f64,
    last_dissipated: f64,
    temperatures: [f64; 10],
    initial: [f64; 10],
    updates: usize,
    largest_rate: f64,
    heat_supplied: f64,
    /// The right-hand side's buffer for the update's dissipation by
    /// component.
    pub(super) scratch: Vec<f64>,
}

/// The nodes with a heat capacity (the others follow quasi-statically).
const MASSIVE: [usize; 5] = [0, 2, 3, 5, 6];

impl ThermalCoupling {
    /// A coupling for `inputs`, the viscosity law (None: constant
    /// viscosity, temperatures only), update `interval` \[s\], starting
    /// from `temperatures` (per node of [`NODES`](crate::thermal::bearing::NODES), K).
    pub fn new(
        inputs: ThermalInputs,
        viscosity: Option<Walther>,
        interval: f64,
        temperatures: [f64; 10],
    ) -> Result<Self, InvalidParameter> {
        if !(interval.is_finite() && interval > 0.0) {
            return Err(InvalidParameter::new(
                "update_interval",
                interval,
                "must be a positive time",
            ));
        }
        Ok(Self {
            inputs,
            viscosity,
            interval,
            next_update: interval,
            last_time: 0.0,
            last_dissipated: 0.0,
            temperatures,
            initial: temperatures,
            updates: 0,
            largest_rate: 0.0,
            heat_supplied: 0.0,
            scratch: Vec::new(),
        })
    }

    /// Node temperatures now \[K\] (order of [`NODES`](crate::thermal::bearing::NODES)).
    pub fn temperatures(&self) -> &[f64; 10] {
        &self.temperatures
    }

    /// Node temperatures at the start \[K\].
    pub fn initial_temperatures(&self) -> &[f64; 10] {
        &self.initial
    }

    /// Updates done.
    pub fn updates(&self) -> usize {
        self.updates
    }

    /// Largest temperature rate of the parts with a heat capacity (balls,
    /// rings, shaft, housing) at the last update \[K/s\]: how far from
    /// thermal steady state the run is.
    pub fn largest_rate(&self) -> f64 {
        self.largest_rate
    }

    /// Heat given to the network so far \[J\]: the dissipated energy from
    /// the coupling's start to its last update.
    pub fn heat_supplied(&self) -> f64 {
        self.heat_supplied
    }

    /// Update interval \[s\].
    pub fn interval(&self) -> f64 {
        self.interval
    }

    /// Temperature of a node \[K\].
    pub fn temperature(&self, node: &str) -> Option<f64> {
        node_index(node).map(|i| self.temperatures[i])
    }

    /// Viscosities at the contact inlets and at the oil node \[Pa·s\]
    /// (None without a viscosity law).
    fn viscosities(&self) -> Option<(f64, f64)> {
        let w = self.viscosity?;
        let t = |n| {
            self.temperature(n)
                .unwrap_or(self.inputs.ambient_temperature)
        };
        let rings = 0.5 * (t("inner_ring") + t("outer_ring"));
        Some((w.dynamic(0.5 * (t("ball") + rings)), w.dynamic(t("oil"))))
    }
}

impl ThermalCoupling {
    /// Appends the network's evolving state to a checkpoint.
    pub(super) fn save(&self, out: &mut StateWriter) {
        out.tag("thermal");
        for v in [
            self.next_update,
            self.last_time,
            self.last_dissipated,
            self.largest_rate,
            self.heat_supplied,
        ] {
            out.f64(v);
        }
        out.u64(self.updates as u64);
        out.f64s(&self.temperatures);
    }

    /// Restores what [`ThermalCoupling::save`] wrote; returns the
    /// viscosities to apply.
    pub(super) fn restore(
        &mut self,
        input: &mut StateReader,
    ) -> Result<Option<(f64, f64)>, CheckpointError> {
        input.tag("thermal")?;
        self.next_update = input.f64()?;
        self.last_time = input.f64()?;
        self.last_dissipated = input.f64()?;
        self.largest_rate = input.f64()?;
        self.heat_supplied = input.f64()?;
        self.updates = input.u64()? as usize;
        input.f64s_into("thermal node temperatures", &mut self.temperatures)?;
        Ok(self.viscosities())
    }
}

impl ThermalCoupling {
    /// Prepares the coupling for a run from time `t0`, where the dissipated
    /// energy is `dissipated` \[J\], with a right-hand-side buffer of
    /// `dimension` states; returns the starting viscosities.
    pub(super) fn start(
        &mut self,
        t0: f64,
        dissipated: f64,
        dimension: usize,
    ) -> Option<(f64, f64)> {
        self.last_time = t0;
        self.next_update = t0 + self.interval;
        self.last_dissipated = dissipated;
        self.scratch = vec![0.0; dimension];
        self.viscosities()
    }

    /// Whether an accepted step at `t` updates the network.
    pub(super) fn due(&self, t: f64) -> bool {
        t >= self.next_update
    }

    /// The update at an accepted step at `t` (module doc): `dissipated`,
    /// the energy dissipated so far \[J\]; `power`, the dissipation by
    /// component at `t` (from [`super::BearingModel::rhs_with_power`] into
    /// [`Self::scratch`]); `cage_speed` \[rad/s\]; `contact_means` sets the
    /// loaded contacts' mean semi-axes and entrainment speeds. Returns the
    /// viscosities to apply.
    pub(super) fn advance(
        &mut self,
        t: f64,
        dissipated: f64,
        power: &Dissipation,
        cage_speed: f64,
        contact_means: impl FnOnce(&mut HeatSources),
    ) -> Option<(f64, f64)> {
        let span = t - self.last_time;
        let mean_power = (dissipated - self.last_dissipated) / span;
        let p = power;
        let scale = if p.total() > 0.0 {
            mean_power / p.total()
        } else {
            0.0
        };
        let mut heat = HeatSources {
            inner_contacts: scale * p.inner.total(),
            outer_contacts: scale * p.outer.total(),
            balls: scale * (p.pocket_friction + p.pocket_damping),
            oil: scale
                * (p.guide_land
                    + p.ball_drag
                    + p.cage_drag
                    + p.support_damping
                    + p.seals
                    + p.churning),
            cage_speed,
            ..HeatSources::default()
        };
        contact_means(&mut heat);
        let mut inputs = self.inputs.clone();
        if let Some((_, land)) = self.viscosities() {
            inputs.oil_kinematic_viscosity = land / inputs.oil_density;
        }
        let before = self.temperatures;
        if let Ok(s) = BearingThermal::new(&inputs, &heat)
            .and_then(|n| n.transient(&self.temperatures, span, 1))
        {
            self.temperatures = s.temperatures;
        }
        self.largest_rate = MASSIVE
            .iter()
            .map(|&i| (self.temperatures[i] - before[i]).abs() / span)
            .fold(0.0, f64::max);
        self.heat_supplied +=
            span * (heat.inner_contacts + heat.outer_contacts + heat.balls + heat.oil);
        self.updates += 1;
        self.last_time = t;
        self.last_dissipated = dissipated;
        self.next_update = t + self.interval;
        self.viscosities()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::HertzModel;
    use crate::dynamics::BearingModel;
    use crate::dynamics::{CageParameters, DynamicsParameters, PocketLaw};
    use crate::integrate::tableau::DOPRI5;
    use crate::integrate::{ExplicitRk, Integrator, StepControl};
    use crate::material::Material;
    use crate::operating::{LoadProfile, Loads, SpeedProfile};
    use crate::quasistatic::{Conditions, QuasiStaticSolver, RacewayControl, SolverOptions};
    use crate::traction::EhlRheology;
    use crate::traction::TractionModel;
    use crate::traction::ellipse::TractionIntegration;

    /// A 30×62×16-like bearing with EHL traction, coupled every 0.1 ms over
    /// 0.45 ms: the heat handed to the network equals the dissipated energy
    /// of the energy balance over the coupled span (to rounding), and the
    /// EHL η₀ follows Walther at the inlet temperature.
    /// The 30×62×16-like bearing with EHL traction, coupled every 0.1 ms,
    /// from its Jones–Harris state; with the viscosity law.
    fn coupled_model() -> (BearingModel, Vec<f64>, Walther) {
        let g = crate::testing::bearing_30x62();
        let steel = Material::STEEL_52100;
        let speed = 9000.0 * std::f64::consts::TAU / 60.0;
        let loads = Loads {
            force: [3000.0, 0.0, 780.0],
            moment: [0.0; 2],
        };
        let eq = QuasiStaticSolver::new(&g, &steel, &steel, HertzModel::Exact)
            .unwrap()
            .solve(
                &Conditions {
                    loads,
                    inner_speed: speed,
                    control: RacewayControl::Outer,
                },
                &SolverOptions::default(),
            )
            .unwrap();
        let lubricant = crate::lubrication::Lubricant {
            viscosity: 0.0275,
            pressure_viscosity: 2e-8,
            pressure_model: Default::default(),
        };
        let cage = CageParameters {
            whirl: false,
            ..CageParameters::new(
                6e-3,
                2.8e-6,
                23e-3,
                0.3e-3,
                PocketLaw::Linear {
                    stiffness: 1e7,
                    damping: 20.0,
                },
            )
        };
        let params = DynamicsParameters {
            traction: TractionModel::Ehl(EhlRheology {
                eyring_stress: 5e6,
                limiting_shear_coefficient: 0.08,
                lubricant,
            }),
            traction_integration: TractionIntegration::Grid {
                across: 8,
                along: 4,
            },
            speed: SpeedProfile::Constant(speed),
            loads: LoadProfile::Constant(loads),
            rolling_hysteresis: 0.007,
            ..DynamicsParameters::new(0.3, 1e-4, cage)
        };
        let mut model = BearingModel::new(&g, &steel, &steel, HertzModel::Exact, params).unwrap();
        let y0 = model.state_from_equilibrium(&eq);
        let (inputs, walther) = crate::testing::thermal_30x62();
        let start = [333.15; 10];
        let coupling = ThermalCoupling::new(inputs, Some(walther), 1e-4, start).unwrap();
        model.couple_thermal(coupling, 0.0, &y0);
        (model, y0, walther)
    }

    #[test]
    fn coupling_hands_over_the_dissipated_energy_and_sets_the_viscosity() {
        let (mut model, y0, walther) = coupled_model();
        let eta = |m: &BearingModel| match &m.parameters().traction {
            TractionModel::Ehl(e) => e.lubricant.viscosity,
            _ => f64::NAN,
        };
        assert!((eta(&model) - walther.dynamic(333.15)).abs() < 1e-15);
        let control = StepControl::Adaptive {
            relative_tolerance: 1e-6,
            max_step: 1e-5,
            initial_step: None,
        };
        let mut rk = ExplicitRk::builder(&DOPRI5)
            .control(control)
            .build(&model, &y0)
            .unwrap();
        let mut at_update = (0, 0.0);
        while rk.t() < 4.5e-4 {
            rk.step(&mut model, 4.5e-4).unwrap();
            let c = model.thermal().unwrap();
            if c.updates() != at_update.0 {
                at_update = (c.updates(), model.work(rk.y()).1);
            }
        }
        let c = model.thermal().unwrap();
        assert_eq!(
            c.updates(),
            4,
            "updates at 0.2, 0.4, 0.6, 0.8 ms (and the one at 1 ms if reached)"
        );
        let supplied = c.heat_supplied();
        assert!(
            supplied > 0.0 && (supplied - at_update.1).abs() < 1e-12 * at_update.1,
            "{supplied} J vs {} J",
            at_update.1
        );
        let t = |n| c.temperature(n).unwrap();
        let inlet = 0.5 * (t("ball") + 0.5 * (t("inner_ring") + t("outer_ring")));
        assert!((eta(&model) - walther.dynamic(inlet)).abs() < 1e-15);
    }

    /// A coupled run checkpointed between two network updates and restored
    /// into a freshly coupled model continues bit for bit:
    /// temperatures, heat, update times and the viscosities fed back.
    #[test]
    fn coupled_run_resumes_bit_identically() {
        use crate::integrate::{Checkpoint, StateReader, StateWriter};
        let control = StepControl::Adaptive {
            relative_tolerance: 1e-6,
            max_step: 1e-5,
            initial_step: None,
        };
        let (mut model, y0, _) = coupled_model();
        let mut rk = ExplicitRk::builder(&DOPRI5)
            .control(control)
            .build(&model, &y0)
            .unwrap();
        while rk.t() < 2.5e-4 {
            rk.step(&mut model, 5e-4).unwrap();
        }
        assert!(model.thermal().unwrap().updates() >= 1);
        let mut w = StateWriter::new();
        rk.save(&mut w);
        model.save(&mut w);
        let bytes = w.into_bytes();
        while rk.t() < 5e-4 {
            rk.step(&mut model, 5e-4).unwrap();
        }
        let (mut again, _, _) = coupled_model();
        let mut rk2 = ExplicitRk::builder(&DOPRI5)
            .control(control)
            .build(&again, &y0)
            .unwrap();
        let mut r = StateReader::new(&bytes);
        rk2.restore(&mut r).unwrap();
        again.restore(&mut r).unwrap();
        assert!(r.is_done());
        while rk2.t() < 5e-4 {
            rk2.step(&mut again, 5e-4).unwrap();
        }
        assert!(
            rk.y()
                .iter()
                .zip(rk2.y())
                .all(|(a, b)| a.to_bits() == b.to_bits())
        );
        let (c, c2) = (model.thermal().unwrap(), again.thermal().unwrap());
        assert_eq!(c, c2);
        assert!(c.updates() >= 3);
        assert_eq!(model.parameters().traction, again.parameters().traction);
    }
}
