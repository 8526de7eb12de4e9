//! `[materials]`: a built-in material by name or the elastic constants
//! and density of a custom one.

use super::{Invalid, MATERIALS, NamedMaterial, checked, positive_number};
use crate::raw::MaterialChoice;
use rolldyn::Material;

/// Checks one material choice (`key` names it in errors); none: steel 52100.
pub(super) fn material(
    key: &str,
    choice: Option<&MaterialChoice>,
) -> Result<NamedMaterial, Invalid> {
    match choice {
        None => Ok(NamedMaterial {
            name: "steel_52100".into(),
            material: Material::STEEL_52100,
        }),
        Some(MaterialChoice::Named(name)) => MATERIALS
            .iter()
            .find(|(n, _)| n == name)
            .map(|(n, m)| NamedMaterial {
                name: n.to_string(),
                material: *m,
            })
            .ok_or_else(|| {
                Invalid::new(
                    key,
                    Some(format!("\"{name}\"")),
                    format!(
                        "unknown material; built-in: {} (or give a table with elastic_modulus, poisson_ratio, density)",
                        MATERIALS.map(|m| m.0).join(", ")
                    ),
                )
            }),
        Some(MaterialChoice::Custom(m)) => {
            checked(&format!("{key}.elastic_modulus"), &Some(m.elastic_modulus.clone()), |v| {
                if (1e6..=1e13).contains(&v) {
                    Ok(())
                } else {
                    Err("must lie in [1 MPa, 10 TPa] (engineering solids)".into())
                }
            })?;
            checked(&format!("{key}.density"), &Some(m.density.clone()), |v| {
                if (1.0..=1e5).contains(&v) {
                    Ok(())
                } else {
                    Err("must lie in [1, 100 000] kg/m^3".into())
                }
            })?;
            positive_number(
                &format!("{key}.poisson_ratio"),
                Some(m.poisson_ratio),
                |v| v > -1.0 && v < 0.5,
                "Poisson's ratio must lie in (-1, 0.5)",
            )?;
            Ok(NamedMaterial {
                name: m.name.clone().unwrap_or_else(|| "custom".into()),
                material: Material {
                    elastic_modulus: m.elastic_modulus.si,
                    poisson_ratio: m.poisson_ratio,
                    density: m.density.si,
                },
            })
        }
    }
}
