//! `[inner_ring]` and `[outer_ring]`: the inner ring's mass, tilt inertia
//! and shaft support, and the outer ring's mass and housing.

use super::{Invalid, checked, non_negative, positive};
use crate::raw::RawCase;
use rolldyn::dynamics::{OuterRing, Support};

/// The checked ring sections.
pub(super) struct Rings {
    pub(super) inner_ring_mass: Option<f64>,
    pub(super) inner_ring_tilt_inertia: Option<f64>,
    pub(super) inner_support: Support,
    pub(super) outer_ring: Option<OuterRing>,
}

/// Checks `[inner_ring]` and `[outer_ring]`.
pub(super) fn rings(raw: &RawCase) -> Result<Rings, Invalid> {
    let inner_ring_mass = checked("inner_ring.mass", &raw.inner_ring.mass, positive)?;
    let inner_ring_tilt_inertia = checked(
        "inner_ring.tilt_inertia",
        &raw.inner_ring.tilt_inertia,
        positive,
    )?;
    let ir = &raw.inner_ring;
    let zero = |v: Option<f64>| v.unwrap_or(0.0);
    let radial_k = zero(checked(
        "inner_ring.support_radial_stiffness",
        &ir.support_radial_stiffness,
        non_negative,
    )?);
    let radial_c = zero(checked(
        "inner_ring.support_radial_damping",
        &ir.support_radial_damping,
        non_negative,
    )?);
    let inner_support = Support {
        stiffness: [
            zero(checked(
                "inner_ring.support_axial_stiffness",
                &ir.support_axial_stiffness,
                non_negative,
            )?),
            radial_k,
            radial_k,
        ],
        damping: [
            zero(checked(
                "inner_ring.support_axial_damping",
                &ir.support_axial_damping,
                non_negative,
            )?),
            radial_c,
            radial_c,
        ],
    };
    let outer_ring = match &raw.outer_ring {
        None => None,
        Some(o) => {
            let k = checked(
                "outer_ring.housing_stiffness",
                &Some(o.housing_stiffness.clone()),
                non_negative,
            )?
            .unwrap_or(0.0);
            let c = zero(checked(
                "outer_ring.housing_damping",
                &o.housing_damping,
                non_negative,
            )?);
            Some(OuterRing {
                mass: checked("outer_ring.mass", &Some(o.mass.clone()), positive)?.unwrap_or(0.0),
                housing: Support {
                    stiffness: [0.0, k, k],
                    damping: [0.0, c, c],
                },
            })
        }
    };
    Ok(Rings {
        inner_ring_mass,
        inner_ring_tilt_inertia,
        inner_support,
        outer_ring,
    })
}
