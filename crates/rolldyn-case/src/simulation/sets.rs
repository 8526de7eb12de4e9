//! A case's matched bearing set on one rigid shaft (`[arrangement]`;
//! docs/systems.md): the set built from the case's bearing, its preload
//! offset, its equilibrium under the case's loads, the preload at the
//! operating speed and the lift-off load at rest.

use super::{QuasiStatic, SimulationError};
use crate::Case;
use crate::case::{Arrangement, Invalid, Preload};
use rolldyn::operating::Loads;
use rolldyn::quasistatic::SolverOptions;
use rolldyn::quasistatic::system::{
    MountedBearing, ShaftSystem, SystemConditions, SystemEquilibrium,
};

/// The case's bearing set, preloaded, at the case's operating point.
#[derive(Debug, Clone)]
pub struct BearingSet {
    /// The bearings on the shaft, with their preload offset.
    pub system: ShaftSystem,
    /// The case's `[arrangement]`.
    pub arrangement: Arrangement,
    /// The axial offset of each inner ring that sets the preload \[m\].
    pub offset: f64,
    /// The case's loads on the shaft (at the middle between the
    /// bearings), speed and raceway control.
    pub conditions: SystemConditions,
    /// Quasi-static solver options.
    pub options: SolverOptions,
}

impl BearingSet {
    /// The set of `case`, or None when the case has one bearing. A preload
    /// force sets the offset at rest (the mounting preload).
    pub fn from_case(case: &Case) -> Result<Option<Self>, SimulationError> {
        let Some(arrangement) = case.bearing_set().copied() else {
            return Ok(None);
        };
        if let Some(k) = case
            .prescribed_displacement
            .iter()
            .position(Option::is_some)
        {
            let key = ["x", "y", "z"].get(k).map_or(
                ["operating.tilt_y", "operating.tilt_z"][k - 3].to_string(),
                |a| format!("operating.displacement_{a}"),
            );
            return Err(SimulationError::Case(Invalid {
                key,
                value: None,
                rule: "a prescribed ring displacement is not supported with [arrangement]: the shaft's displacement follows from the loads".into(),
            }));
        }
        let problem = QuasiStatic::from_case(case)?;
        let control = problem.conditions.control;
        let options = problem.options;
        let system = ShaftSystem::matched(&problem.solver, arrangement.kind, arrangement.spacing);
        let offset = match arrangement.preload {
            Preload::None => 0.0,
            Preload::Displacement(d) => d,
            Preload::Force(f) => system.offset_for_preload(f, 0.0, control, &options)?,
        };
        Ok(Some(Self {
            system: system.with_axial_offset(offset),
            arrangement,
            offset,
            conditions: SystemConditions {
                loads: case.loads,
                inner_speed: problem.conditions.inner_speed,
                control,
            },
            options,
        }))
    }

    /// The set's equilibrium under the case's loads.
    pub fn solve(&self) -> Result<SystemEquilibrium, SimulationError> {
        Ok(self.system.solve(&self.conditions, &self.options)?)
    }

    /// The preload at the operating speed: bearing 0's axial load without
    /// external load \[N\] (None without a preload: the set is then not
    /// determined without load).
    pub fn preload_at_speed(&self) -> Result<Option<f64>, SimulationError> {
        if self.offset == 0.0 {
            return Ok(None);
        }
        let unloaded = SystemConditions {
            loads: Loads::default(),
            ..self.conditions
        };
        let eq = self.system.solve(&unloaded, &self.options)?;
        Ok(Some(
            eq.bearings[0]
                .as_ref()
                .map_or(0.0, MountedBearing::axial_load),
        ))
    }

    /// The lift-off load: the external axial load that unloads the
    /// opposed bearing, at rest \[N\] (None for a tandem set, or without
    /// preload). At speed the balls' centrifugal force lets the opposed
    /// bearing's balls follow its inner ring along the outer groove, so
    /// its axial load decays slowly instead of vanishing at a definite load
    /// (docs/systems.md): the lift-off load is a mounting quantity.
    pub fn lift_off_load(&self) -> Result<Option<f64>, SimulationError> {
        if self.offset == 0.0 {
            return Ok(None);
        }
        Ok(self
            .system
            .lift_off_load(0.0, self.conditions.control, &self.options)?)
    }
}
