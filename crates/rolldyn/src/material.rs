//! Elastic solids: Young's modulus, Poisson's ratio and density, and the
//! Hertz effective modulus of a pair of them.

use serde::{Deserialize, Serialize};

/// An isotropic elastic material.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Material {
    /// Young's modulus E \[Pa\], > 0.
    pub elastic_modulus: f64,
    /// Poisson's ratio ν \[-\], in (−1, 0.5).
    pub poisson_ratio: f64,
    /// Density ρ \[kg/m³\], > 0.
    pub density: f64,
}

impl Material {
    /// Through-hardened bearing steel AISI 52100 / GCr15 / 100Cr6:
    /// E = 208 GPa, ν = 0.3, ρ = 7830 kg/m³ (Harris & Kotzalas, *Essential
    /// Concepts of Bearing Technology*, 5th ed., Table 5.1 and App. Table).
    pub const STEEL_52100: Material = Material {
        elastic_modulus: 208.0e9,
        poisson_ratio: 0.3,
        density: 7830.0,
    };
    /// Hot-isostatically-pressed silicon nitride, bearing grade (ASTM F2094):
    /// E = 310 GPa, ν = 0.26, ρ = 3200 kg/m³ (Harris & Kotzalas, 5th ed.,
    /// Table 5.1; Zhang et al. 2020 uses Si₃N₄ balls).
    pub const SILICON_NITRIDE: Material = Material {
        elastic_modulus: 310.0e9,
        poisson_ratio: 0.26,
        density: 3200.0,
    };

    /// (1 − ν²)/E, the compliance one body contributes to a Hertz contact.
    pub fn contact_compliance(&self) -> f64 {
        (1.0 - self.poisson_ratio * self.poisson_ratio) / self.elastic_modulus
    }
}

/// Effective modulus E' = 2 / [(1 − ν₁²)/E₁ + (1 − ν₂²)/E₂] of docs/model.md §2.2
/// (Harris & Kotzalas, eq. 6.24 form; Lei et al. 2023 misprints (1 − ν)²).
/// For identical materials E' = E/(1 − ν²).
pub fn effective_modulus(a: &Material, b: &Material) -> f64 {
    2.0 / (a.contact_compliance() + b.contact_compliance())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_material_effective_modulus() {
        let s = Material::STEEL_52100;
        let e = effective_modulus(&s, &s);
        assert!((e - 208e9 / 0.91).abs() / e < 1e-15);
    }
}
