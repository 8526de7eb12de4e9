//! `[arrangement]` in SI: a matched set of the case's bearing on one
//! rigid shaft, checked.

use super::{Case, Invalid, checked, positive};
use crate::raw::{ArrangementKind, RawArrangement};
use rolldyn::quasistatic::system::SetKind;

/// Largest preload force accepted \[N\] (a matched set of the largest
/// ball bearings takes tens of kilonewtons).
pub const MAX_PRELOAD: f64 = 1e6;
/// Largest preload displacement accepted \[m\].
pub const MAX_PRELOAD_DISPLACEMENT: f64 = 1e-3;

/// How the set is preloaded.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Preload {
    /// No preload (the rings just touch the balls at rest).
    None,
    /// The axial force through the set at rest without external load
    /// \[N\] (each bearing's of a pair; a triple's single bearing's).
    Force(f64),
    /// The axial offset of each inner ring towards its loaded side \[m\].
    Displacement(f64),
}

/// `[arrangement]`, checked.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Arrangement {
    /// The set.
    pub kind: SetKind,
    /// Its preload.
    pub preload: Preload,
    /// Distance between neighbouring pitch planes \[m\].
    pub spacing: f64,
    /// A rotating unbalance on the shaft: mass × radius \[kg·m\] and its
    /// position from the middle between the bearings \[m\] (dynamics only).
    pub unbalance: Option<(f64, f64)>,
}

/// The raw kind as the engine's.
fn set_kind(kind: ArrangementKind) -> SetKind {
    match kind {
        ArrangementKind::Single => SetKind::Single,
        ArrangementKind::BackToBack => SetKind::BackToBack,
        ArrangementKind::FaceToFace => SetKind::FaceToFace,
        ArrangementKind::Tandem => SetKind::Tandem,
        ArrangementKind::TandemBackToBack => SetKind::TandemBackToBack,
        ArrangementKind::TandemFaceToFace => SetKind::TandemFaceToFace,
    }
}

/// The kind as the case writes it.
pub fn kind_name(kind: SetKind) -> &'static str {
    match kind {
        SetKind::Single => "single",
        SetKind::BackToBack => "back_to_back",
        SetKind::FaceToFace => "face_to_face",
        SetKind::Tandem => "tandem",
        SetKind::TandemBackToBack => "tandem_back_to_back",
        SetKind::TandemFaceToFace => "tandem_face_to_face",
    }
}

/// Largest unbalance accepted \[kg·m\]: 10 kg·mm, far beyond any balance
/// grade of a bearing-sized rotor (a typo guard).
pub const MAX_UNBALANCE: f64 = 1e-2;

pub(super) fn arrangement(
    raw: &Option<RawArrangement>,
    width: Option<f64>,
) -> Result<Option<Arrangement>, Invalid> {
    let Some(raw) = raw else { return Ok(None) };
    let kind = set_kind(raw.kind);
    let force = checked("arrangement.preload", &raw.preload, |v| {
        if v > 0.0 && v <= MAX_PRELOAD {
            Ok(())
        } else {
            Err(format!("must be positive and at most {MAX_PRELOAD:e} N"))
        }
    })?;
    let displacement = checked(
        "arrangement.preload_displacement",
        &raw.preload_displacement,
        |v| {
            if v > 0.0 && v <= MAX_PRELOAD_DISPLACEMENT {
                Ok(())
            } else {
                Err("must be positive and at most 1 mm".into())
            }
        },
    )?;
    let preload = match (force, displacement) {
        (Some(_), Some(_)) => {
            return Err(Invalid::new(
                "arrangement.preload_displacement",
                raw.preload_displacement.as_ref().map(|q| q.to_string()),
                "give the preload either as a force (arrangement.preload) or as a displacement, not both",
            ));
        }
        (Some(f), None) => Preload::Force(f),
        (None, Some(d)) => Preload::Displacement(d),
        (None, None) => Preload::None,
    };
    if preload != Preload::None && !kind.opposed() {
        let key = if force.is_some() {
            "arrangement.preload"
        } else {
            "arrangement.preload_displacement"
        };
        return Err(Invalid::new(
            key,
            None,
            format!(
                "a {} arrangement takes no preload by itself (only opposed sets do: back_to_back, face_to_face, tandem_back_to_back, tandem_face_to_face); apply the axial load with operating.force_x",
                kind_name(kind)
            ),
        ));
    }
    let spacing = match checked("arrangement.spacing", &raw.spacing, positive)? {
        Some(s) => s,
        None => match width {
            Some(w) if kind != SetKind::Single => w,
            _ if kind == SetKind::Single => 0.0,
            _ => {
                return Err(Invalid::new(
                    "arrangement.spacing",
                    None,
                    "missing: give the distance between the bearings' pitch planes (the bearing has no bearing.width to place them side by side)",
                ));
            }
        },
    };
    let amount = checked("arrangement.unbalance", &raw.unbalance, |v| {
        if (0.0..=MAX_UNBALANCE).contains(&v) {
            Ok(())
        } else {
            Err(format!("must lie in [0, {MAX_UNBALANCE}] kg·m"))
        }
    })?;
    let position = checked(
        "arrangement.unbalance_position",
        &raw.unbalance_position,
        |v| {
            if v.abs() <= super::MAX_SHAFT_POSITION {
                Ok(())
            } else {
                Err(format!(
                    "must lie within ±{} m of the middle between the bearings",
                    super::MAX_SHAFT_POSITION
                ))
            }
        },
    )?;
    if position.is_some() && amount.is_none() {
        return Err(Invalid::new(
            "arrangement.unbalance_position",
            raw.unbalance_position.as_ref().map(|q| q.to_string()),
            "places arrangement.unbalance, which is not given",
        ));
    }
    Ok(Some(Arrangement {
        kind,
        preload,
        spacing,
        unbalance: amount.map(|a| (a, position.unwrap_or(0.0))),
    }))
}

impl Case {
    /// The matched set the case describes, if it has more than one bearing.
    pub fn bearing_set(&self) -> Option<&Arrangement> {
        self.arrangement
            .as_ref()
            .filter(|a| a.kind != SetKind::Single)
    }
}
