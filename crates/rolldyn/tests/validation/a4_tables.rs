//! A4: contact tables (docs/model.md §2.2) vs the exact solve on 10 000 random
//! contact angles per raceway, for three bearings of the papers, with
//! different ball and ring materials. Tolerance 1e-6 relative on K_c
//! (docs/model.md §2.2) and, beyond the requirement, on a*, b*, δ*, κ.

use super::common::{bearing_6304, bearing_7008c, bearing_7218b, rel};
use rolldyn::RingKind;
use rolldyn::contact::HertzModel;
use rolldyn::contact::table::{ContactTable, RacewayContactModel};
use rolldyn::material::{Material, effective_modulus};

/// xorshift64* — a fixed, dependency-free pseudo-random sequence.
struct Rng(u64);
impl Rng {
    fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[test]
fn a4_tables_match_exact_solve() {
    let hybrid = effective_modulus(&Material::SILICON_NITRIDE, &Material::STEEL_52100);
    let steel = effective_modulus(&Material::STEEL_52100, &Material::STEEL_52100);
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    for (name, g, ep) in [
        ("7008C", bearing_7008c(), steel),
        ("6304", bearing_6304(), hybrid),
        ("7218B", bearing_7218b(), steel),
    ] {
        for ring in RingKind::BOTH {
            let model = RacewayContactModel::new(&g, ring, ep, HertzModel::Exact);
            let table = ContactTable::new(model).unwrap();
            let mut worst = 0.0f64;
            for _ in 0..10_000 {
                let alpha = rng.uniform() * std::f64::consts::FRAC_PI_2;
                let exact = model.coefficients(alpha).unwrap();
                let t = table.at(alpha);
                let err = rel(t.stiffness, exact.stiffness)
                    .max(rel(t.semi_major_coefficient, exact.semi_major_coefficient))
                    .max(rel(t.semi_minor_coefficient, exact.semi_minor_coefficient))
                    .max(rel(t.approach_coefficient, exact.approach_coefficient))
                    .max(rel(t.ellipticity, exact.ellipticity));
                worst = worst.max(err);
            }
            eprintln!("A4 {name} {ring:?}: worst table error {worst:.2e}");
            assert!(worst < 1e-6, "{name} {ring:?}: {worst}");
        }
    }
}
