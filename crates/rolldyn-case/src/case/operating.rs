//! `[operating]`: the shaft speed (constant or a table over time), the
//! loads on the inner ring (components, a radial load at an angle, or a
//! table over time) and the prescribed ring displacements.

use super::{Invalid, check_force, check_speed};
use crate::raw::RawOperating;
use crate::units::Quantity;
use rolldyn::operating::{LoadProfile, Loads, RingUnbalance, SpeedProfile, TorqueDrive};

/// The checked `[operating]` section.
pub(super) struct Operating {
    pub(super) speed: Option<SpeedProfile>,
    /// The loads at t = 0 (what the quasi-static solvers and a run's start see).
    pub(super) loads: Loads,
    pub(super) load_profile: Option<LoadProfile>,
    pub(super) first_ball_azimuth: f64,
    pub(super) prescribed_displacement: [Option<f64>; 5],
    pub(super) drive: Option<TorqueDrive>,
    pub(super) unbalance: Option<RingUnbalance>,
}

/// Checks `[operating]`.
pub(super) fn operating(op: &RawOperating) -> Result<Operating, Invalid> {
    if let Some(s) = &op.speed {
        check_speed("operating.speed", s.si)?;
    }
    for (i, p) in op.speed_profile.iter().flatten().enumerate() {
        check_speed(&format!("operating.speed_profile[{i}].speed"), p.speed.si)?;
    }
    for (key, q) in [
        ("operating.force_x", &op.force_x),
        ("operating.force_y", &op.force_y),
        ("operating.force_z", &op.force_z),
        ("operating.radial_load", &op.radial_load),
    ] {
        if let Some(q) = q {
            check_force(key, q.si)?;
        }
    }
    let speed = speed(op)?;
    let force = |q: &Option<Quantity<crate::units::Force>>| q.as_ref().map_or(0.0, |q| q.si);
    let moment = |q: &Option<Quantity<crate::units::Moment>>| q.as_ref().map_or(0.0, |q| q.si);
    let mut loads = Loads {
        force: [force(&op.force_x), force(&op.force_y), force(&op.force_z)],
        moment: [moment(&op.moment_y), moment(&op.moment_z)],
    };
    if let Some(q) = &op.radial_load {
        if op.force_y.is_some() || op.force_z.is_some() {
            return Err(Invalid::new(
                "operating.radial_load",
                Some(q.to_string()),
                "give the radial load either as radial_load (with radial_load_angle) or as force_y/force_z, not both",
            ));
        }
        let angle = op
            .radial_load_angle
            .as_ref()
            .map_or(std::f64::consts::FRAC_PI_2, |a| a.si);
        // Exact zeros along the axes (cos 90° is 6e-17 in floating point).
        let snap = |v: f64| if v.abs() < 1e-12 * q.si.abs() { 0.0 } else { v };
        loads.force[1] = snap(q.si * angle.cos());
        loads.force[2] = snap(q.si * angle.sin());
    } else if let Some(a) = &op.radial_load_angle {
        return Err(Invalid::new(
            "operating.radial_load_angle",
            Some(a.to_string()),
            "needs operating.radial_load",
        ));
    }
    let load_profile = match &op.load_profile {
        None => None,
        Some(points) => {
            if let Some(key) = [
                ("force_x", &op.force_x),
                ("force_y", &op.force_y),
                ("force_z", &op.force_z),
                ("radial_load", &op.radial_load),
            ]
            .iter()
            .find(|(_, q)| q.is_some())
            .map(|(k, _)| *k)
            .or_else(|| {
                [("moment_y", &op.moment_y), ("moment_z", &op.moment_z)]
                    .iter()
                    .find(|(_, q)| q.is_some())
                    .map(|(k, _)| *k)
            }) {
                return Err(Invalid::new(
                    "operating.load_profile",
                    None,
                    format!(
                        "give either constant loads (operating.{key}, ...) or operating.load_profile, not both"
                    ),
                ));
            }
            let table = points
                .iter()
                .map(|p| {
                    (
                        p.time.si,
                        Loads {
                            force: [force(&p.force_x), force(&p.force_y), force(&p.force_z)],
                            moment: [moment(&p.moment_y), moment(&p.moment_z)],
                        },
                    )
                })
                .collect();
            Some(LoadProfile::piecewise_linear(table).map_err(|(i, e)| {
                let v = points.get(i).map(|p| p.time.to_string());
                Invalid::new(format!("operating.load_profile[{i}].time"), v, e.rule)
            })?)
        }
    };
    // The quasi-static solvers (and a dynamic run's start) see the loads at t = 0.
    let loads = load_profile.as_ref().map_or(loads, |p| p.at(0.0));
    Ok(Operating {
        speed,
        loads,
        load_profile,
        first_ball_azimuth: op.first_ball_azimuth.as_ref().map_or(0.0, |a| a.si),
        prescribed_displacement: prescribed(op)?,
        drive: drive(op)?,
        unbalance: unbalance(op)?,
    })
}

/// The inner-ring speed of `[operating]`: constant, a profile or none.
fn speed(op: &RawOperating) -> Result<Option<SpeedProfile>, Invalid> {
    Ok(match (&op.speed, &op.speed_profile) {
        (Some(_), Some(_)) => {
            return Err(Invalid::new(
                "operating.speed_profile",
                None,
                "give either operating.speed (constant) or operating.speed_profile, not both",
            ));
        }
        (Some(s), None) => Some(SpeedProfile::Constant(s.si)),
        (None, Some(points)) => Some(
            SpeedProfile::piecewise_linear(
                points.iter().map(|p| (p.time.si, p.speed.si)).collect(),
            )
            .map_err(|(i, e)| {
                let v = points.get(i).map(|p| p.time.to_string());
                Invalid::new(format!("operating.speed_profile[{i}].time"), v, e.rule)
            })?,
        ),
        (None, None) => None,
    })
}

/// The rotating unbalance of `[operating]`, if any.
fn unbalance(op: &RawOperating) -> Result<Option<RingUnbalance>, Invalid> {
    let Some(amount) = &op.unbalance else {
        if let Some(phase) = &op.unbalance_phase {
            return Err(Invalid::new(
                "operating.unbalance_phase",
                Some(phase.to_string()),
                "needs operating.unbalance",
            ));
        }
        return Ok(None);
    };
    if !(0.0..=super::arrangement::MAX_UNBALANCE).contains(&amount.si) {
        return Err(Invalid::new(
            "operating.unbalance",
            Some(amount.to_string()),
            format!(
                "must lie in [0, {}] kg·m",
                super::arrangement::MAX_UNBALANCE
            ),
        ));
    }
    Ok(Some(RingUnbalance {
        amount: amount.si,
        phase: op.unbalance_phase.as_ref().map_or(0.0, |a| a.si),
    }))
}

/// The torque drive of `[operating]`, if any: a constant torque or a
/// table, on a rotor of the given inertia, from the constant `speed`.
fn drive(op: &RawOperating) -> Result<Option<TorqueDrive>, Invalid> {
    let torque = match (&op.drive_torque, &op.drive_torque_profile) {
        (None, None) => {
            if let Some(j) = &op.rotor_inertia {
                return Err(Invalid::new(
                    "operating.rotor_inertia",
                    Some(j.to_string()),
                    "is the inertia a drive torque turns: give operating.drive_torque (or drive_torque_profile), or leave it out for a prescribed speed",
                ));
            }
            return Ok(None);
        }
        (Some(_), Some(_)) => {
            return Err(Invalid::new(
                "operating.drive_torque_profile",
                None,
                "give either operating.drive_torque (constant) or operating.drive_torque_profile, not both",
            ));
        }
        (Some(t), None) => vec![(0.0, t.si)],
        (None, Some(points)) => points.iter().map(|p| (p.time.si, p.torque.si)).collect(),
    };
    for (i, &(time, value)) in torque.iter().enumerate() {
        if !(value.is_finite() && value.abs() <= 1e6) {
            let key = if op.drive_torque.is_some() {
                "operating.drive_torque".to_string()
            } else {
                format!("operating.drive_torque_profile[{i}].torque")
            };
            return Err(Invalid::new(
                key,
                Some(format!("{value} N·m")),
                "must be finite, within ±1 MN·m",
            ));
        }
        if i > 0 && time <= torque[i - 1].0 {
            return Err(Invalid::new(
                format!("operating.drive_torque_profile[{i}].time"),
                Some(format!("{time} s")),
                format!(
                    "times must increase strictly (previous point: {} s)",
                    torque[i - 1].0
                ),
            ));
        }
    }
    if op.drive_torque_profile.as_ref().is_some_and(Vec::is_empty) {
        return Err(Invalid::new(
            "operating.drive_torque_profile",
            Some("[]".into()),
            "needs at least one point",
        ));
    }
    let inertia = op.rotor_inertia.as_ref().ok_or_else(|| {
        Invalid::missing(
            "operating.rotor_inertia",
            "a drive torque needs the polar moment of inertia of what it turns (ring, shaft, rotor), e.g. rotor_inertia = \"2e-3 kg.m^2\"",
        )
    })?;
    if !(inertia.si.is_finite() && inertia.si > 0.0) {
        return Err(Invalid::new(
            "operating.rotor_inertia",
            Some(inertia.to_string()),
            "must be positive",
        ));
    }
    if op.speed_profile.is_some() {
        return Err(Invalid::new(
            "operating.speed_profile",
            None,
            "a driven ring's speed is the run's outcome: give its speed at the start as operating.speed",
        ));
    }
    if op.speed.is_none() {
        return Err(Invalid::missing(
            "operating.speed",
            "a drive torque needs the speed at the start (0 rpm: from rest)",
        ));
    }
    Ok(Some(TorqueDrive {
        inertia: inertia.si,
        torque,
    }))
}

/// The prescribed displacements of `[operating]`: each instead of its load.
fn prescribed(op: &RawOperating) -> Result<[Option<f64>; 5], Invalid> {
    let fixed = op.fixed_tilt.unwrap_or(false);
    let length = |q: &Option<Quantity<crate::units::Length>>| q.as_ref().map(|q| q.si);
    let angle = |q: &Option<Quantity<crate::units::Angle>>| q.as_ref().map(|q| q.si);
    let out = [
        length(&op.displacement_x),
        length(&op.displacement_y),
        length(&op.displacement_z),
        angle(&op.tilt_y).or(fixed.then_some(0.0)),
        angle(&op.tilt_z).or(fixed.then_some(0.0)),
    ];
    let loads = [
        ("force_x", op.force_x.is_some()),
        ("force_y", op.force_y.is_some() || op.radial_load.is_some()),
        ("force_z", op.force_z.is_some() || op.radial_load.is_some()),
        ("moment_y", op.moment_y.is_some()),
        ("moment_z", op.moment_z.is_some()),
    ];
    let names = [
        "displacement_x",
        "displacement_y",
        "displacement_z",
        "tilt_y",
        "tilt_z",
    ];
    let given = [
        op.displacement_x.is_some(),
        op.displacement_y.is_some(),
        op.displacement_z.is_some(),
        op.tilt_y.is_some(),
        op.tilt_z.is_some(),
    ];
    for k in 0..5 {
        if out[k].is_some() && loads[k].1 {
            let key = if given[k] { names[k] } else { "fixed_tilt" };
            return Err(Invalid::new(
                format!("operating.{key}"),
                None,
                format!(
                    "a ring displacement is either prescribed or follows its load: not with operating.{}",
                    loads[k].0
                ),
            ));
        }
    }
    if out.iter().any(Option::is_some) && op.load_profile.is_some() {
        return Err(Invalid::new(
            "operating.load_profile",
            None,
            "prescribed ring displacements are quasi-static: not with a load table",
        ));
    }
    Ok(out)
}
