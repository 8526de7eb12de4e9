//! Bearings of the source papers (`rolldyn::testing`) and the references
//! the validation cases share.

pub use rolldyn::testing::*;

use rolldyn::BearingGeometry;
use rolldyn::contact::HertzModel;
use rolldyn::material::Material;

/// Relative difference |a − b|/|b|.
pub fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// The textbook thrust curve of an angular-contact bearing at rest,
/// (δ_a, F_a) at contact angle α, steel on steel, exact Hertz:
/// F_a = Z K_n (BD)^1.5 sin α (cos α₀/cos α − 1)^1.5 with K_n the series
/// stiffness of the two contacts at α, δ_a = BD cos α₀ (tan α − tan α₀)
/// (Harris & Kotzalas, *Essential Concepts*, eq. 7.30 form).
pub fn thrust_curve(g: &BearingGeometry, alpha: f64) -> (f64, f64) {
    let kn = series_stiffness(g, alpha);
    let bd = g.total_curvature() * g.ball_diameter;
    let a0 = g.offset_contact_angle;
    let force = g.ball_count as f64
        * kn
        * bd.powf(1.5)
        * alpha.sin()
        * (a0.cos() / alpha.cos() - 1.0).powf(1.5);
    (bd * a0.cos() * (alpha.tan() - a0.tan()), force)
}

/// K_n of a ball's two contacts in series at contact angle α, steel on
/// steel, exact Hertz: (K_i^(−2/3) + K_o^(−2/3))^(−3/2) (Harris &
/// Kotzalas, *Essential Concepts*, eq. 7.9).
pub fn series_stiffness(g: &BearingGeometry, alpha: f64) -> f64 {
    let ep = rolldyn::material::effective_modulus(&Material::STEEL_52100, &Material::STEEL_52100);
    let k = |ring| {
        rolldyn::contact::RacewayContactModel::new(g, ring, ep, HertzModel::Exact)
            .coefficients(alpha)
            .unwrap()
            .stiffness
    };
    ((1.0 / k(rolldyn::RingKind::Inner)).powf(2.0 / 3.0)
        + (1.0 / k(rolldyn::RingKind::Outer)).powf(2.0 / 3.0))
    .powf(-1.5)
}

/// The quasi-static solver of bearing `g`, steel on steel, exact Hertz.
pub fn steel_solver(g: &BearingGeometry) -> rolldyn::quasistatic::QuasiStaticSolver {
    rolldyn::quasistatic::QuasiStaticSolver::new(
        g,
        &Material::STEEL_52100,
        &Material::STEEL_52100,
        HertzModel::Exact,
    )
    .unwrap()
}

/// The EHL rolling resistance of the 7008C cases: Biboulet & Houpert's
/// fully flooded fit with `lubricant`, inlet heating with β_T = 0.04 1/K
/// and k_f = 0.13 W/(m·K) (mineral-oil values, assumed).
pub fn rolling_resistance_7008c(
    lubricant: rolldyn::lubrication::Lubricant,
) -> rolldyn::lubrication::rolling_resistance::RollingResistance {
    use rolldyn::lubrication::rolling_resistance::{
        InletHeating, RollingForceLaw, RollingResistance,
    };
    RollingResistance {
        law: RollingForceLaw::BibouletHoupert,
        lubricant,
        heating: Some(InletHeating {
            temperature_viscosity: 0.04,
            conductivity: 0.13,
        }),
        replenishment: None,
    }
}
