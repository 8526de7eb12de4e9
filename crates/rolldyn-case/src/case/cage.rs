//! `[cage]`: pockets, guide land, inertia, pocket law and friction.

use super::{
    Cage, DEFAULT_POCKET_FRICTION, DEFAULT_POCKET_MIN_FILM, GUPTA_WALL_FORCE, Invalid, checked,
    material::material, non_negative, positive, positive_number, text,
};
use crate::raw::{PocketLawChoice, RawCage};

/// Checks `[cage]`.
pub(super) fn cage(c: &RawCage) -> Result<Cage, Invalid> {
    let cage = Cage {
        guidance: c.guidance,
        pocket_clearance: checked("cage.pocket_clearance", &c.pocket_clearance, positive)?,
        inner_diameter: checked("cage.inner_diameter", &c.inner_diameter, positive)?,
        outer_diameter: checked("cage.outer_diameter", &c.outer_diameter, positive)?,
        guide_land_width: checked("cage.guide_land_width", &c.guide_land_width, positive)?,
        guide_clearance: checked("cage.guide_clearance", &c.guide_clearance, positive)?,
        mass: checked("cage.mass", &c.mass, positive)?,
        inertia: checked("cage.inertia", &c.inertia, positive)?,
        pocket_stiffness: checked("cage.pocket_stiffness", &c.pocket_stiffness, positive)?,
        pocket_damping: checked("cage.pocket_damping", &c.pocket_damping, non_negative)?,
        pocket_friction: positive_number(
            "cage.pocket_friction",
            c.pocket_friction,
            |v| (0.0..=rolldyn::traction::MAX_FRICTION).contains(&v),
            "a friction coefficient must lie in [0, 5]",
        )?
        .unwrap_or(DEFAULT_POCKET_FRICTION),
        whirl: c.whirl.unwrap_or(true),
        pocket_shape: c.pocket_shape.unwrap_or_default(),
        pocket_law: c.pocket_law.unwrap_or(PocketLawChoice::Linear),
        pocket_wall_force: checked("cage.pocket_wall_force", &c.pocket_wall_force, non_negative)?
            .unwrap_or(GUPTA_WALL_FORCE),
        pocket_squeeze_film: c.pocket_squeeze_film.unwrap_or(false),
        pocket_min_film: checked("cage.pocket_min_film", &c.pocket_min_film, positive)?
            .unwrap_or(DEFAULT_POCKET_MIN_FILM),
        pocket_squeeze_cavitation: c.pocket_squeeze_cavitation.unwrap_or_default(),
        pocket_squeeze_tension: checked(
            "cage.pocket_squeeze_tension",
            &c.pocket_squeeze_tension,
            positive,
        )?
        .unwrap_or(rolldyn::cage::squeeze::DEFAULT_POCKET_TENSION),
        material: c
            .material
            .as_ref()
            .map(|m| material("cage.material", Some(m)))
            .transpose()?,
        unbalance: checked("cage.unbalance", &c.unbalance, non_negative)?.unwrap_or(0.0),
    };
    if let (Some(i), Some(o)) = (cage.inner_diameter, cage.outer_diameter) {
        if o <= i {
            return Err(Invalid::new(
                "cage.outer_diameter",
                text(&c.outer_diameter),
                format!(
                    "must exceed cage.inner_diameter ({})",
                    text(&c.inner_diameter).unwrap_or_default()
                ),
            ));
        }
    }
    Ok(cage)
}
