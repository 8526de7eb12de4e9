//! A case's bearings on one shaft in motion (docs/systems.md, "Dynamics"):
//! the matched set of `[arrangement]` or the bearings of a `[shaft]`, each
//! with its ball and cage dynamics ([`rolldyn::dynamics::shaft`]), started
//! from the system's quasi-static equilibrium at the case's speed and loads.

use super::{BearingSet, ShaftModel, SimulationError, SolverSettings};
use crate::Case;
use crate::case::{Invalid, Preload};
use rolldyn::dynamics::SlidingRing;
use rolldyn::dynamics::shaft::{ShaftBody, ShaftDynamics, Unbalance};
use rolldyn::quasistatic::system::{MountedBearing, SetKind, SystemEquilibrium};

/// The dynamic model of a case's bearings on their shaft.
pub struct SetSimulation {
    /// The matched set's kind (None: a `[shaft]`).
    pub kind: Option<SetKind>,
    /// The matched set's mounting preload \[N\] (None: none, a
    /// displacement, or a `[shaft]`).
    pub mounting_preload: Option<f64>,
    /// The bearings as mounted (positions, orientations, offsets).
    pub mounted: Vec<MountedBearing>,
    /// The quasi-static equilibrium the run starts from.
    pub quasistatic: SystemEquilibrium,
    /// The bearings on the shaft.
    pub system: ShaftDynamics,
    /// The initial state.
    pub initial_state: Vec<f64>,
    /// The integrator and its tolerances.
    pub settings: SolverSettings,
}

/// A refusal of what a system in motion does not do, naming the key.
fn refuse<T>(key: &str, rule: &str) -> Result<T, SimulationError> {
    Err(SimulationError::Case(Invalid {
        key: key.into(),
        value: None,
        rule: format!("{rule}: not available for bearings on a shaft in motion (docs/systems.md)"),
    }))
}

/// Refuses what bearings on a shaft in motion do not do, naming the key.
fn refuse_unsupported(case: &Case) -> Result<(), SimulationError> {
    if case.load_profile.is_some() {
        return refuse("operating.load_profile", "time-varying loads");
    }
    if case.thermal.run_coupling.is_some() {
        return refuse(
            "thermal.run_coupling",
            "the thermal network coupled to the run",
        );
    }
    if case.sensor.is_some() {
        return refuse("sensor", "the sensor chain");
    }
    if case.bearing_damping.is_some() {
        return refuse(
            "model.bearing_damping",
            "a damping between one bearing's rings (a shaft's bearings damp through their contacts and supports)",
        );
    }
    if case.unbalance.is_some() {
        return refuse(
            "operating.unbalance",
            "an unbalance on one bearing's ring (a set's shaft takes arrangement.unbalance)",
        );
    }
    if case.start != crate::raw::StartChoice::JonesHarris {
        return refuse(
            "solver.start",
            "the bearings start from their quasi-static equilibrium (\"jones_harris\"); other starts",
        );
    }
    Ok(())
}

/// Each mounted bearing's model from its case (`on_shaft`: a `[shaft]`'s
/// bearing, whose errors name it), the shaft's drive turning its inner
/// ring, and the shaft body the inner rings make up.
fn bearing_models(
    case: &Case,
    mounted: &[MountedBearing],
    bearing_cases: &[Case],
    on_shaft: bool,
    inner_speed: f64,
) -> Result<(Vec<rolldyn::dynamics::BearingModel>, ShaftBody), SimulationError> {
    let mut models = Vec::with_capacity(mounted.len());
    let mut body = ShaftBody {
        mass: 0.0,
        tilt_inertia: 0.0,
    };
    for (i, (b, bearing_case)) in mounted.iter().zip(bearing_cases).enumerate() {
        // A shaft bearing's own case: its errors name it.
        let name = |mut invalid: Invalid| {
            if on_shaft {
                invalid.key = format!("shaft.bearings[{i}].{}", invalid.key);
            }
            invalid
        };
        let named = |e: SimulationError| match e {
            SimulationError::Case(invalid) => SimulationError::Case(name(invalid)),
            e => e,
        };
        let mut parameters = bearing_case
            .dynamics_parameters()
            .map_err(|e| named(e.into()))?;
        // The shaft's drive turns every bearing's inner ring.
        parameters.drive = case.drive.clone();
        if b.floating {
            // Its outer ring slides in its bore.
            parameters.sliding_outer_ring = Some(SlidingRing {
                mass: bearing_case
                    .outer_ring_mass()
                    .map_err(|e| named(e.into()))?,
                friction: case
                    .shaft
                    .as_ref()
                    .map_or(0.0, |s| s.bearings[i].housing_friction),
            });
        }
        if parameters.speed.speed_at(0.0) != inner_speed {
            return refuse("operating.speed", "a speed that changes over the run");
        }
        body.mass += parameters.inner_ring_mass;
        body.tilt_inertia += parameters.inner_ring_tilt_inertia
            + parameters.inner_ring_mass * b.position * b.position;
        models.push(super::model(bearing_case, parameters).map_err(named)?);
    }
    Ok((models, body))
}

impl SetSimulation {
    /// The case's bearings on their shaft in motion, or None when the
    /// case has one bearing. The shaft carries each bearing's inner ring
    /// (its case's `inner_ring.mass` and tilt inertia, at the bearing's
    /// pitch plane); the case's loads (with a `[shaft]`'s loads at their
    /// positions) act on it at the reference point, constant, and
    /// `arrangement.unbalance` turns with it.
    pub fn from_case(case: &Case) -> Result<Option<Self>, SimulationError> {
        refuse_unsupported(case)?;
        let harmonic_loads = case
            .shaft
            .as_ref()
            .map_or(Vec::new(), |s| s.harmonic_loads.clone());
        let (kind, mounting_preload, unbalance, bearing_cases, mounted, quasistatic, conditions) =
            if let Some(set) = BearingSet::from_case(case)? {
                let equilibrium = set.solve().map_err(|e| SimulationError::Start {
                    start: "jones_harris",
                    reason: format!("the set's quasi-static equilibrium: {e}"),
                })?;
                (
                    Some(set.arrangement.kind),
                    match set.arrangement.preload {
                        Preload::Force(f) => Some(f),
                        _ => None,
                    },
                    set.arrangement.unbalance,
                    vec![case.clone(); set.system.bearings.len()],
                    set.system.bearings,
                    equilibrium,
                    set.conditions,
                )
            } else if let Some(shaft) = ShaftModel::from_case(case)? {
                if shaft.elastic.is_some() {
                    return refuse("shaft.diameter", "an elastic shaft (quasi-static only)");
                }
                let equilibrium = shaft.solve().map_err(|e| SimulationError::Start {
                    start: "jones_harris",
                    reason: format!("the shaft's quasi-static equilibrium: {e}"),
                })?;
                (
                    None,
                    None,
                    None,
                    shaft.bearings.into_iter().map(|b| b.case).collect(),
                    shaft.system.bearings,
                    equilibrium,
                    shaft.conditions,
                )
            } else {
                return Ok(None);
            };
        let (models, body) = bearing_models(
            case,
            &mounted,
            &bearing_cases,
            kind.is_none(),
            conditions.inner_speed,
        )?;
        let settings = SolverSettings::of(
            case,
            &models[0].parameters().cage,
            models[0].geometry().ball_count,
        );
        let mut system = ShaftDynamics::new(
            models.into_iter().zip(&mounted).collect(),
            body,
            conditions.loads,
        )?;
        if let Some((amount, position)) = unbalance {
            system = system.with_unbalance(Unbalance { amount, position })?;
        }
        if !harmonic_loads.is_empty() {
            system = system.with_harmonic_loads(harmonic_loads)?;
        }
        let initial_state = system.initial_state(&quasistatic)?;
        Ok(Some(Self {
            kind,
            mounting_preload,
            mounted,
            quasistatic,
            system,
            initial_state,
            settings,
        }))
    }
}
