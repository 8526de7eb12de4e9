//! The case's traction model (`[model] traction = …`, docs/model.md §3): the
//! stress laws and Kalker's FASTSIM, whose elastic constants are combined
//! from the ball and ring materials.

use super::{Invalid, Lubricant, Materials};
use crate::raw::{RawMixedLubrication, RawTraction, TractionChoice};
use rolldyn::RingKind;
use rolldyn::traction::fastsim::combined_elastic_constants;
use rolldyn::traction::mixed::MixedLubrication;
use rolldyn::traction::{
    EhlRheology, ExactTable, Fastsim, ModifiedCoulomb, TractionCurve, TractionIntegration,
    TractionModel,
};

pub(super) fn traction(
    choice: Option<&TractionChoice>,
    lubricant: Option<&Lubricant>,
    materials: &Materials,
) -> Result<TractionModel, Invalid> {
    let key = "model.traction";
    Ok(match choice {
        None | Some(TractionChoice::Named(_)) | Some(TractionChoice::Table(RawTraction::None)) => {
            TractionModel::None
        }
        Some(TractionChoice::Table(RawTraction::ModifiedCoulomb {
            friction,
            stick_speed,
            full_speed,
        })) => {
            let law = ModifiedCoulomb {
                friction: *friction,
                stick_speed: stick_speed.as_ref().map_or(0.0, |q| q.si),
                full_speed: full_speed.as_ref().map_or(1e-3, |q| q.si),
            };
            law.validate()
                .map_err(|e| Invalid::new(format!("{key}.{}", e.field), Some(e.value), e.rule))?;
            TractionModel::ModifiedCoulomb(law)
        }
        Some(TractionChoice::Table(RawTraction::TractionCurve {
            a,
            b,
            c,
            d,
            slip,
            full_speed,
        })) => {
            let law = TractionCurve {
                a: *a,
                b: *b,
                c: *c,
                d: *d,
                slip: slip.unwrap_or_default(),
                full_speed: full_speed.as_ref().map_or(1e-3, |q| q.si),
            };
            law.validate()
                .map_err(|e| Invalid::new(format!("{key}.{}", e.field), Some(e.value), e.rule))?;
            TractionModel::TractionCurve(law)
        }
        Some(TractionChoice::Table(RawTraction::Ehl {
            eyring_stress,
            limiting_shear_coefficient,
        })) => {
            let lub = lubricant.ok_or_else(|| {
                Invalid::new(key, None, "the ehl traction law needs a [lubricant] section (viscosity, pressure_viscosity)")
            })?;
            let law = EhlRheology {
                eyring_stress: eyring_stress.si,
                limiting_shear_coefficient: *limiting_shear_coefficient,
                lubricant: rolldyn::lubrication::Lubricant {
                    viscosity: lub.viscosity,
                    pressure_viscosity: lub.pressure_viscosity,
                    pressure_model: lub.pressure_viscosity_model,
                },
            };
            law.validate()
                .map_err(|e| Invalid::new(format!("{key}.{}", e.field), Some(e.value), e.rule))?;
            TractionModel::Ehl(law)
        }
        Some(TractionChoice::Table(RawTraction::Fastsim {
            friction,
            strips,
            elements,
            bound,
            regularisation_speed,
        })) => {
            let (shear_modulus, poisson_ratio) =
                combined_elastic_constants(&materials.ball.material, &materials.rings.material);
            let mut law = Fastsim::new(*friction, shear_modulus, poisson_ratio);
            law.strips = strips.unwrap_or(law.strips);
            law.elements = elements.unwrap_or(law.elements);
            law.bound = bound.unwrap_or_default();
            if let Some(v) = regularisation_speed {
                law.regularisation_speed = v.si;
            }
            law.validate().map_err(|e| material_error(e, key))?;
            TractionModel::Fastsim(law)
        }
        Some(TractionChoice::Table(RawTraction::ExactTable {
            friction,
            regularisation_speed,
        })) => {
            let (shear_modulus, poisson_ratio) =
                combined_elastic_constants(&materials.ball.material, &materials.rings.material);
            let mut law = ExactTable::new(*friction, shear_modulus, poisson_ratio);
            if let Some(v) = regularisation_speed {
                law.regularisation_speed = v.si;
            }
            law.validate().map_err(|e| material_error(e, key))?;
            TractionModel::ExactTable(law)
        }
    })
}

/// A FASTSIM or exact-table parameter error, naming the materials for the
/// elastic constants combined from them.
fn material_error(e: rolldyn::InvalidParameter, key: &str) -> Invalid {
    let field = if e.field == "poisson_ratio" || e.field == "shear_modulus" {
        format!(
            "materials (combined {} of ball and rings for {key})",
            e.field
        )
    } else {
        format!("{key}.{}", e.field)
    };
    Invalid::new(field, Some(e.value), e.rule)
}

/// Checks `model.film_in_approach`: the film needs a film model (EHL with
/// a lubricant) and a flooded or inlet-distance supply.
pub(super) fn film_in_approach(
    requested: Option<bool>,
    traction: &TractionModel,
    lubricant: Option<&Lubricant>,
) -> Result<bool, Invalid> {
    if requested != Some(true) {
        return Ok(false);
    }
    if traction.lubricant().is_none() {
        return Err(Invalid::new(
            "model.film_in_approach",
            Some("true".into()),
            "the film needs a film model: model.traction = \"ehl\" with a [lubricant] section",
        ));
    }
    let flow = lubricant.is_some_and(|l| {
        l.supply
            .iter()
            .any(|s| matches!(s, rolldyn::lubrication::Supply::Flow { .. }))
    });
    if flow {
        return Err(Invalid::new(
            "model.film_in_approach",
            Some("true".into()),
            "the film in the approach needs a flooded supply or lubricant.inlet_distance_ratio, not lubricant.oil_flow (docs/lubrication.md)",
        ));
    }
    Ok(true)
}

/// Checks the traction grid of `model.traction_integration`: 1 to 10 000 cells.
pub(super) fn integration(
    integration: Option<TractionIntegration>,
) -> Result<TractionIntegration, Invalid> {
    if let Some((across, along)) = integration.as_ref().and_then(TractionIntegration::cells) {
        if across.saturating_mul(along) > 10_000 || across == 0 || along == 0 {
            return Err(Invalid::new(
                "model.traction_integration",
                Some(format!("{across} × {along}")),
                "the grid needs 1 to 10 000 cells (across × along)",
            ));
        }
    }
    Ok(integration.unwrap_or_default())
}

/// `[model.mixed_lubrication]` (docs/model.md §3, model 5): needs the EHL traction
/// law (the fluid it blends with, and the film) and a roughness at both
/// raceways' contacts (the film parameter Λ = h_min/σ).
pub(super) fn mixed_lubrication(
    raw: Option<&RawMixedLubrication>,
    traction: &TractionModel,
    surface: &rolldyn::surface::SurfaceModel,
) -> Result<Option<MixedLubrication>, Invalid> {
    let Some(raw) = raw else {
        return Ok(None);
    };
    let key = "model.mixed_lubrication";
    let mixed = MixedLubrication {
        boundary: ModifiedCoulomb {
            friction: raw.boundary_friction,
            stick_speed: 0.0,
            full_speed: raw.full_speed.as_ref().map_or(1e-3, |q| q.si),
        },
        sigma_beta_eta: raw.sigma_beta_eta,
        sigma_over_beta: raw.sigma_over_beta,
    };
    mixed.validate().map_err(|e| {
        let field = match e.field {
            "friction" => "boundary_friction",
            other => other,
        };
        Invalid::new(format!("{key}.{field}"), Some(e.value), e.rule)
    })?;
    if !matches!(traction, TractionModel::Ehl(_)) {
        return Err(Invalid::new(
            key,
            None,
            "mixed lubrication blends boundary friction with the fluid's traction: it needs model.traction law \"ehl\" with a [lubricant] section (the film h_min)",
        ));
    }
    for (ring, name) in [(RingKind::Inner, "inner"), (RingKind::Outer, "outer")] {
        if surface.composite_roughness(ring) <= 0.0 {
            return Err(Invalid::new(
                key,
                None,
                format!(
                    "mixed lubrication needs the film parameter Λ = h_min/σ at every contact: give surface.{name}.roughness or surface.balls.roughness"
                ),
            ));
        }
    }
    Ok(Some(mixed))
}
