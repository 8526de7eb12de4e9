//! A case's bearings on one rigid shaft (docs/systems.md): the matched set
//! of `[arrangement]` built from the case's bearing, its preload offset,
//! its equilibrium under the case's loads, the preload at the operating
//! speed and the lift-off load at rest; and the general system of
//! `[shaft]`, built-in bearings at positions.

use super::{QuasiStatic, SimulationError};
use crate::Case;
use crate::case::{Arrangement, Invalid, Preload};
use rolldyn::operating::Loads;
use rolldyn::quasistatic::SolverOptions;
use rolldyn::quasistatic::elastic_shaft::{ElasticEquilibrium, ElasticShaft};
use rolldyn::quasistatic::system::{
    MountedBearing, ShaftSystem, SystemConditions, SystemEquilibrium,
};
use rolldyn::thermal::coupled::CoupledOptions;
use rolldyn::thermal::set::{
    AxialExpansion, SetThermalError, SetThermalProblem, SetThermalSolution, set_steady,
};

/// A set's thermal steady state (docs/systems.md, "Temperature").
#[derive(Debug, Clone)]
pub struct SetThermal {
    /// The set's equilibrium at the reference temperature.
    pub cold: SystemEquilibrium,
    /// At operating temperature.
    pub hot: SetThermalSolution,
    /// The preload at speed without external load, at the reference and
    /// at the operating temperatures: bearing 0's axial load \[N\] (None
    /// without a preload).
    pub preload_at_speed: Option<[f64; 2]>,
}

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
            let tilt_held = case.prescribed_displacement[3..] == [Some(0.0), Some(0.0)];
            if k >= 3 && tilt_held {
                return Err(SimulationError::Case(Invalid {
                    key: "operating.fixed_tilt".into(),
                    value: Some("true".into()),
                    rule: "a set's shaft holds its own tilt: not with [arrangement] (a single bearing's mounting; docs/dynamics.md, \"Mounting\")".into(),
                }));
            }
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

    /// The preload at the operating speed: the axial force through the set
    /// without external load \[N\] (`ShaftSystem::preload_of`; None without
    /// a preload: the set is then not determined without load).
    pub fn preload_at_speed(&self) -> Result<Option<f64>, SimulationError> {
        if self.offset == 0.0 {
            return Ok(None);
        }
        let unloaded = SystemConditions {
            loads: Loads::default(),
            ..self.conditions
        };
        let eq = self.system.solve(&unloaded, &self.options)?;
        Ok(Some(self.system.preload_of(&eq)))
    }

    /// The set's coupled thermal steady state under the case's loads
    /// (`case` is the set's own case: its bearing, lubricant and
    /// `[thermal]` are every bearing's).
    pub fn thermal_steady_state(&self, case: &Case) -> Result<SetThermal, SimulationError> {
        let cold = self.solve()?;
        let hot = system_thermal(
            &vec![case.clone(); self.system.bearings.len()],
            case,
            &self.system,
            &self.conditions,
            &self.options,
            &cold,
            "arrangement",
        )?;
        let preload_at_speed = match self.preload_at_speed()? {
            None => None,
            Some(cold_preload) => {
                let unloaded = SystemConditions {
                    loads: Loads::default(),
                    ..self.conditions
                };
                let eq = hot.system.solve(&unloaded, &self.options)?;
                Some([cold_preload, hot.system.preload_of(&eq)])
            }
        };
        Ok(SetThermal {
            cold,
            hot,
            preload_at_speed,
        })
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

/// The coupled thermal steady state of bearings on a shaft: bearing i
/// with `cases[i]`'s geometry, materials and lubricant under `system_case`'s
/// `[thermal]` (one machine: one ambient, one oil supply, one shaft and
/// housing), from their equilibrium `cold`; an unloaded bearing is
/// refused under `key`.
fn system_thermal(
    cases: &[Case],
    system_case: &Case,
    system: &ShaftSystem,
    conditions: &SystemConditions,
    options: &SolverOptions,
    cold: &SystemEquilibrium,
    key: &str,
) -> Result<SetThermalSolution, SimulationError> {
    let cases: Vec<Case> = cases
        .iter()
        .map(|c| Case {
            thermal: system_case.thermal.clone(),
            ..c.clone()
        })
        .collect();
    let bearings = cases
        .iter()
        .map(super::steady::coupled_problem)
        .collect::<Result<Vec<_>, _>>()?;
    let [shaft, housing] = system_case.thermal.shaft_housing_expansion;
    let problem = SetThermalProblem {
        bearings,
        system,
        conditions: *conditions,
        options: *options,
        axial: AxialExpansion { shaft, housing },
    };
    set_steady(&problem, cold, &CoupledOptions::default()).map_err(|e| match e {
        SetThermalError::Coupled(c) => super::steady::coupled_failure(c),
        SetThermalError::System(s) => SimulationError::Set(s),
        unloaded @ SetThermalError::Unloaded { .. } => SimulationError::Case(Invalid {
            key: key.into(),
            value: None,
            rule: unloaded.to_string(),
        }),
    })
}

/// One bearing of a `[shaft]` system: its preset's case at the system's
/// speed and raceway control, and its mounting.
#[derive(Debug, Clone)]
pub struct ShaftBearingModel {
    /// The preset's case (its geometry, materials, lubricant, life
    /// settings) with the system case's speed.
    pub case: Case,
    /// On the shaft.
    pub mounted: MountedBearing,
}

/// The `[shaft]` system of a case at its operating point.
#[derive(Debug, Clone)]
pub struct ShaftModel {
    /// Its bearings, in the case's order.
    pub bearings: Vec<ShaftBearingModel>,
    /// The shaft with them.
    pub system: ShaftSystem,
    /// The `[operating]` loads and the `[[shaft.loads]]` about the
    /// reference point, the speed and the raceway control.
    pub conditions: SystemConditions,
    /// Quasi-static solver options (the first bearing's).
    pub options: SolverOptions,
    /// The elastic shaft with its bearings and point loads (None: rigid).
    pub elastic: Option<ElasticShaft>,
    /// The `[operating]` loads alone (at the reference point; the elastic
    /// shaft takes the `[[shaft.loads]]` at their nodes).
    pub reference_loads: Loads,
}

impl ShaftModel {
    /// The system of `case`, or None without `[shaft]`.
    pub fn from_case(case: &Case) -> Result<Option<Self>, SimulationError> {
        let Some(shaft) = &case.shaft else {
            return Ok(None);
        };
        let at = super::conditions(case, None);
        let speed =
            crate::Override::parse_set(&format!("operating.speed=\"{} rad/s\"", at.inner_speed))
                .map_err(|e| {
                    SimulationError::Case(Invalid {
                        key: "operating.speed".into(),
                        value: None,
                        rule: e.to_string(),
                    })
                })?;
        let mut bearings = Vec::with_capacity(shaft.bearings.len());
        let mut options = None;
        for (i, b) in shaft.bearings.iter().enumerate() {
            let invalid = |rule: String| {
                SimulationError::Case(Invalid {
                    key: format!("shaft.bearings[{i}].{}", b.source.key()),
                    value: Some(b.source.name().into()),
                    rule,
                })
            };
            let text = b.case_text().map_err(invalid)?;
            let bearing_case =
                crate::load_case(b.source.name(), &text, std::slice::from_ref(&speed)).map_err(
                    |e| {
                        let rule = e.to_string();
                        // Its fits' errors name its fits.
                        if b.fits.is_some() && rule.contains("fits.") {
                            SimulationError::Case(Invalid {
                                key: format!("shaft.bearings[{i}].fits"),
                                value: None,
                                rule,
                            })
                        } else {
                            invalid(rule)
                        }
                    },
                )?;
            let problem = QuasiStatic::from_case(&bearing_case)?;
            options.get_or_insert(problem.options);
            bearings.push(ShaftBearingModel {
                mounted: MountedBearing {
                    solver: problem.solver,
                    position: b.position,
                    orientation: b.orientation,
                    axial_offset: b.preload_offset,
                    floating: b.floating,
                },
                case: bearing_case,
            });
        }
        let options = options.ok_or_else(|| {
            SimulationError::Case(Invalid {
                key: "shaft.bearings".into(),
                value: None,
                rule: "[shaft] needs at least one bearing".into(),
            })
        })?;
        let loads = Loads {
            force: std::array::from_fn(|k| case.loads.force[k] + shaft.loads.force[k]),
            moment: std::array::from_fn(|k| case.loads.moment[k] + shaft.loads.moment[k]),
        };
        let system = ShaftSystem {
            bearings: bearings.iter().map(|b| b.mounted.clone()).collect(),
        };
        let elastic = shaft
            .section
            .map(|section| ElasticShaft::new(section, system.clone(), shaft.point_loads.clone()))
            .transpose()?;
        Ok(Some(Self {
            system,
            elastic,
            reference_loads: case.loads,
            bearings,
            conditions: SystemConditions {
                loads,
                inner_speed: at.inner_speed,
                control: at.control,
            },
            options,
        }))
    }

    /// The system's equilibrium (on the elastic shaft's, its reference
    /// node's displacement and stiffness).
    pub fn solve(&self) -> Result<SystemEquilibrium, SimulationError> {
        match self.solve_elastic()? {
            Some(eq) => Ok(eq.system),
            None => Ok(self.system.solve_general(&self.conditions, &self.options)?),
        }
    }

    /// The system's coupled thermal steady state (every bearing's network
    /// with `case`'s `[thermal]`; a rigid shaft's), with no preload to
    /// report.
    pub fn thermal_steady_state(&self, case: &Case) -> Result<SetThermal, SimulationError> {
        if self.elastic.is_some() {
            return Err(SimulationError::Case(Invalid {
                key: "shaft.diameter".into(),
                value: None,
                rule: "the thermal steady state is solved on a rigid shaft; drop shaft.diameter for it".into(),
            }));
        }
        let cold = self.system.solve_general(&self.conditions, &self.options)?;
        let cases: Vec<Case> = self.bearings.iter().map(|b| b.case.clone()).collect();
        let hot = system_thermal(
            &cases,
            case,
            &self.system,
            &self.conditions,
            &self.options,
            &cold,
            "shaft",
        )?;
        Ok(SetThermal {
            cold,
            hot,
            preload_at_speed: None,
        })
    }

    /// The elastic shaft's equilibrium (None for a rigid shaft).
    pub fn solve_elastic(&self) -> Result<Option<ElasticEquilibrium>, SimulationError> {
        let Some(elastic) = &self.elastic else {
            return Ok(None);
        };
        let conditions = SystemConditions {
            loads: self.reference_loads,
            ..self.conditions
        };
        Ok(Some(elastic.solve(&conditions, &self.options)?))
    }
}
