//! From a validated [`Case`] to the engine's objects: the one layer the
//! command-line tool, the Python package, the examples and the benchmarks
//! share, so that a new coupling or start is added in one place.
//!
//! * [`Simulation`]: the dynamic model of a case with its initial state
//!   (`solver.start`), the thermal network coupled when the case asks
//!   (`thermal.run_coupling`), the housing's accelerometer attached when
//!   it has one (`[sensor]`), and its integrator ([`SolverSettings`]);
//! * [`QuasiStatic`], [`power_loss`], [`thermal_steady_state`]: the
//!   quasi-static analyses of a case; [`BearingSet`]: a matched set of
//!   the case's bearing on one shaft (`[arrangement]`).
//!
//! A dynamic run of the default case, sampled at 2 kHz:
//! ```
//! use rolldyn_case::{load_default, simulation::Simulation};
//!
//! let case = load_default(&[])?;
//! let mut simulation = Simulation::from_case(&case)?;
//! let cage = simulation.model.layout().cage();
//! let mut cage_speeds = Vec::new();
//! let report = simulation.run(2e-3, 2000.0, |_, _, y| cage_speeds.push(y[cage + 5]))?;
//! assert_eq!(cage_speeds.len(), 5); // t = 0, 0.5, 1, 1.5, 2 ms
//! assert!(matches!(report.end, rolldyn::integrate::RunEnd::Completed));
//! // The cage turns at a little under half the shaft speed (10 000 rpm).
//! let shaft = 10_000.0 * std::f64::consts::TAU / 60.0;
//! assert!(cage_speeds.iter().all(|w| (0.4..0.5).contains(&(w / shaft))));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod integrator;
mod set_dynamics;
mod sets;
mod steady;

pub use integrator::{
    DEFAULT_MAX_STEP, DEFAULT_RELATIVE_TOLERANCE, DEFAULT_RK4_STEP, DEFAULT_STIFF_MAX_STEP,
    STEPS_PER_FILM_PERIOD, SolverSettings, stiff_max_step,
};
pub use set_dynamics::SetSimulation;
pub use sets::{BearingSet, SetThermal, ShaftBearingModel, ShaftModel};
pub use steady::{QuasiStatic, conditions, film_inputs, power_loss, thermal_steady_state};

use crate::Case;
use crate::case::Invalid;
use crate::raw::StartChoice;
use rolldyn::InvalidParameter;
use rolldyn::dynamics::{BearingModel, DynamicsParameters, ThermalCoupling};
use rolldyn::dynamics::{TractionSolveOptions, solve_traction_consistent};
use rolldyn::integrate::{IntegrationError, RunReport, Solver, run};
use rolldyn::quasistatic::QuasiStaticError;
use std::sync::atomic::AtomicBool;

/// Why a case cannot be simulated.
#[derive(Debug, thiserror::Error)]
pub enum SimulationError {
    /// A case key the model cannot use.
    #[error("{}: {}", .0.key, .0.rule)]
    Case(Invalid),
    /// A model parameter out of its range.
    #[error(transparent)]
    Parameter(#[from] InvalidParameter),
    /// The quasi-static solve failed.
    #[error(transparent)]
    QuasiStatic(#[from] QuasiStaticError),
    /// The thermal network's data.
    #[error("thermal: {0}")]
    Thermal(InvalidParameter),
    /// The thermal steady state's equilibrium at a warm pass (its
    /// temperatures and clearance named).
    #[error(transparent)]
    WarmEquilibrium(rolldyn::thermal::coupled::CoupledError),
    /// The initial state the case asks for cannot be found.
    #[error("solver.start = \"{start}\": {reason}")]
    Start {
        /// `solver.start` as the case writes it.
        start: &'static str,
        /// Why, with a hint.
        reason: String,
    },
    /// The integrator cannot start.
    #[error(transparent)]
    Integration(#[from] IntegrationError),
    /// A bearing set has no equilibrium or preload.
    #[error("arrangement: {0}")]
    Set(#[from] rolldyn::quasistatic::system::SystemError),
}

impl From<Invalid> for SimulationError {
    fn from(e: Invalid) -> Self {
        Self::Case(e)
    }
}

/// The dynamic model of a case, ready to integrate.
pub struct Simulation {
    /// The bearing model (parameters from the case).
    pub model: BearingModel,
    /// The initial state (`solver.start`).
    pub initial_state: Vec<f64>,
    /// The integrator and its tolerances.
    pub settings: SolverSettings,
}

impl Simulation {
    /// The case's model, started as `solver.start` says, with the thermal
    /// network coupled when `thermal.run_coupling` is set and the sensor
    /// attached when the case has `[sensor]` (it acquires at
    /// `output.sample_rate`: sample the run at that rate to read it).
    pub fn from_case(case: &Case) -> Result<Self, SimulationError> {
        Self::with_start(case, case.start)
    }

    /// As [`Self::from_case`] with another start.
    pub fn with_start(case: &Case, start: StartChoice) -> Result<Self, SimulationError> {
        single_bearing(case, "a dynamic run")?;
        let mut model = model(case, case.dynamics_parameters()?)?;
        let mut initial_state = match start {
            StartChoice::PureRolling => model.pure_rolling_state([0.0; 5]),
            StartChoice::JonesHarris => {
                jones_harris_state(case, &model, 0.0).map_err(|e| SimulationError::Start {
                    start: "jones_harris",
                    reason: format!("{e}; try start = \"pure_rolling\""),
                })?
            }
            StartChoice::QuasistaticTraction => {
                traction_state(case, &model, 0.0).map_err(|reason| SimulationError::Start {
                    start: "quasistatic_traction",
                    reason,
                })?
            }
        };
        model.seat_in_housing(&mut initial_state);
        if let Some(interval) = case.thermal.run_coupling {
            couple_thermal(case, &mut model, interval, &initial_state)?;
        }
        if let Some(sensor) = &case.sensor {
            model.attach_sensor(sensor.clone(), 0.0, &initial_state)?;
        }
        let settings = SolverSettings::of(
            case,
            &model.parameters().cage,
            case.bearing.geometry.ball_count,
        );
        Ok(Self {
            model,
            initial_state,
            settings,
        })
    }

    /// The case's integrator, at t = 0 on the initial state.
    pub fn solver(&self) -> Result<Solver, SimulationError> {
        Ok(self.settings.build(&self.model, &self.initial_state)?)
    }

    /// Integrates from t = 0 to `duration` \[s\], calling `on_sample` with
    /// the model, the time and the state at t = 0 and then every
    /// 1/`sample_rate` \[Hz\]. For files, checkpoints and progress use the
    /// command line (`rolldyn run`) or drive [`rolldyn::integrate::run_from`]
    /// with [`Self::solver`].
    pub fn run(
        &mut self,
        duration: f64,
        sample_rate: f64,
        on_sample: impl FnMut(&BearingModel, f64, &[f64]),
    ) -> Result<RunReport, SimulationError> {
        let mut solver = self.solver()?;
        let stop = AtomicBool::new(false);
        Ok(run(
            &mut self.model,
            &mut solver,
            duration,
            sample_rate,
            &stop,
            on_sample,
            |_| {},
        ))
    }
}

/// Refuses a case with a bearing set for an analysis that models one
/// bearing (`what`), naming the key.
pub fn single_bearing(case: &Case, what: &str) -> Result<(), SimulationError> {
    if case.shaft.is_some() {
        return Err(SimulationError::Case(Invalid {
            key: "shaft".into(),
            value: None,
            rule: format!(
                "{what} models one bearing; a shaft system has its quasi-static solution (`rolldyn quasistatic`), power loss (`rolldyn power`) and runs (`rolldyn run`, Python's rolldyn.run; docs/systems.md)"
            ),
        }));
    }
    match case.bearing_set() {
        Some(set) => Err(SimulationError::Case(Invalid {
            key: "arrangement.kind".into(),
            value: Some(crate::case::kind_name(set.kind).into()),
            rule: format!(
                "\"{}\": {what} models one bearing; a bearing set has its quasi-static solution (`rolldyn quasistatic`), power loss (`rolldyn power`), thermal steady state (`rolldyn thermal`) and runs (`rolldyn run`, Python's rolldyn.run; docs/systems.md)",
                crate::case::kind_name(set.kind)
            ),
        })),
        None => Ok(()),
    }
}

/// The bearing model of `case` with dynamics parameters `parameters`
/// (usually [`Case::dynamics_parameters`], possibly changed).
pub fn model(case: &Case, parameters: DynamicsParameters) -> Result<BearingModel, SimulationError> {
    Ok(BearingModel::new(
        &case.bearing.geometry,
        &case.materials.ball.material,
        &case.materials.rings.material,
        case.contact_stiffness,
        parameters,
    )?)
}

/// The Jones–Harris state of `model` at time `t` (that instant's speed and
/// loads with the inner ring's weight when gravity acts, the case's
/// raceway control; with the film in the approach when the case asks), so
/// that a heavy ring (a shaft share) does not start by dropping onto its
/// balls.
pub fn jones_harris_state(
    case: &Case,
    model: &BearingModel,
    t: f64,
) -> Result<Vec<f64>, SimulationError> {
    let p = model.parameters();
    let problem = QuasiStatic::from_case(case)?;
    let mut loads = p.loads.at(t);
    loads.force[2] -= p.inner_ring_mass * p.gravity;
    let conditions = rolldyn::quasistatic::Conditions {
        loads,
        inner_speed: p.speed.speed_at(t),
        control: case.raceway_control,
    };
    let equilibrium = problem.solve_at(&conditions)?;
    Ok(model.state_from_equilibrium(&equilibrium))
}

/// The traction-consistent state of `model` at time `t`, from the
/// Jones–Harris solution of the case at that instant's speed and loads;
/// the error says which step failed.
pub fn traction_state(case: &Case, model: &BearingModel, t: f64) -> Result<Vec<f64>, String> {
    let start = jones_harris_state(case, model, t)
        .map_err(|e| format!("the Jones–Harris start of the traction-consistent solve: {e}"))?;
    solve_traction_consistent(model, &start, t, &TractionSolveOptions::default())
        .map(|s| s.state)
        .map_err(|e| format!("{e}; the jones_harris start does not need one"))
}

/// Couples the thermal network to `model` with update interval `interval`
/// \[s\] from state `y0`: the network starts at the case's coupled
/// quasi-static thermal steady state, or with `thermal.run_start =
/// "ambient"` every part at the ambient temperature (the oil supply at its
/// own): a warm-up from cold.
pub fn couple_thermal(
    case: &Case,
    model: &mut BearingModel,
    interval: f64,
    y0: &[f64],
) -> Result<(), SimulationError> {
    let mut inputs = case.thermal_inputs()?;
    let temperatures = if case.thermal.run_from_ambient {
        let mut cold = [inputs.ambient_temperature; 10];
        if let Some(inlet) = rolldyn::thermal::bearing::node_index("oil_inlet") {
            cold[inlet] = inputs.oil_inlet_temperature;
        }
        cold
    } else {
        let steady = thermal_steady_state(case)?;
        inputs.oil_kinematic_viscosity = steady.oil_viscosity / inputs.oil_density;
        steady.thermal.temperatures
    };
    let coupling = ThermalCoupling::new(
        inputs,
        case.lubricant.as_ref().and_then(|l| l.viscosity_law),
        interval,
        temperatures,
    )
    .map_err(|e| {
        SimulationError::Case(Invalid {
            key: "thermal.update_interval".into(),
            value: None,
            rule: e.rule.to_string(),
        })
    })?;
    model.couple_thermal(coupling, 0.0, y0);
    Ok(())
}
