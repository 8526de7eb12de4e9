//! A2: the ellipticity solve satisfies its defining equation (1e-10 rel);
//! equal curvatures give κ = 1 and the sphere-on-sphere Hertz formulas.
//! A3: Hamrock–Brewe approximations vs the exact solve over
//! R_y/R_x ∈ [1, 100]. Hamrock & Brewe (1983) quote errors of a few
//! percent for κ and below 1 % for E and K; the maxima found here are
//! reported in docs/validation.md and asserted with a small margin.

use super::common::{bearing_7008c, rel};
use rolldyn::RingKind;
use rolldyn::contact::HertzModel;
use rolldyn::contact::hertz::{
    Curvature, HertzCoefficients, ellipticity_equation, solve_ellipticity,
};
use rolldyn::contact::table::RacewayContactModel;
use rolldyn::material::{Material, effective_modulus};

/// F(ρ) from 1e-5 (κ ≈ 1.000013) to 0.999 (κ ≈ 100). Below F ≈ 1e-5 the
/// check itself is ill-conditioned: κ − 1 ≈ 4F/3 and the rounding of κ
/// alone perturbs F by ~ε/(κ − 1); F = 0 → κ = 1 exactly is tested below.
#[test]
fn a2_defining_equation_over_bearing_range() {
    for i in 0..=1000 {
        let f = 1e-5 + 0.999 * i as f64 / 1000.0;
        let kappa = solve_ellipticity(f).unwrap();
        assert!(
            rel(ellipticity_equation(kappa), f) < 1e-10,
            "F = {f}: κ = {kappa}, F(κ) = {}",
            ellipticity_equation(kappa)
        );
    }
}

#[test]
fn a2_circular_limit() {
    // Ball D = 10 mm on a sphere of radius 20 mm: R_eff = 5·20/25 = 4 mm.
    let ep = effective_modulus(&Material::STEEL_52100, &Material::STEEL_52100);
    let h = HertzCoefficients::exact(&Curvature::circular(4e-3), ep).unwrap();
    assert_eq!(h.ellipticity, 1.0);
    let q = 250.0;
    let r = h.at_load(q);
    let e_star = ep / 2.0;
    let a = (3.0 * q * 4e-3 / (4.0 * e_star)).cbrt();
    assert!(rel(r.semi_major, a) < 1e-10 && rel(r.semi_minor, a) < 1e-10);
    assert!(rel(r.approach, a * a / 4e-3) < 1e-10);
    assert!(
        rel(
            r.max_pressure,
            3.0 * q / (2.0 * std::f64::consts::PI * a * a)
        ) < 1e-10
    );
    assert!(rel(h.stiffness, 4.0 / 3.0 * e_star * 4e-3f64.sqrt()) < 1e-10);
}

/// Max relative errors of Hamrock–Brewe (κ, E, K) on 1 ≤ R_y/R_x ≤ 100.
pub fn hamrock_brewe_max_errors() -> (f64, f64, f64) {
    let mut worst = (0.0f64, 0.0f64, 0.0f64);
    for i in 0..=2000 {
        let ratio = 100f64.powf(i as f64 / 2000.0);
        let c = Curvature {
            rolling_radius: 1e-3,
            transverse_radius: ratio * 1e-3,
        };
        let exact = HertzCoefficients::exact(&c, 2e11).unwrap();
        let hb = HertzCoefficients::hamrock_brewe(&c, 2e11);
        worst.0 = worst.0.max(rel(hb.ellipticity, exact.ellipticity));
        worst.1 = worst.1.max(rel(hb.elliptic_e, exact.elliptic_e));
        worst.2 = worst.2.max(rel(hb.elliptic_k, exact.elliptic_k));
        if i % 250 == 0 {
            eprintln!(
                "A3 Ry/Rx {ratio:7.2}: κ {:+.4}, E {:+.4}, K {:+.4}",
                hb.ellipticity / exact.ellipticity - 1.0,
                hb.elliptic_e / exact.elliptic_e - 1.0,
                hb.elliptic_k / exact.elliptic_k - 1.0
            );
        }
    }
    worst
}

#[test]
fn a3_hamrock_brewe_accuracy() {
    let (kappa, e, k) = hamrock_brewe_max_errors();
    eprintln!("A3 max rel. error on 1 ≤ Ry/Rx ≤ 100: κ {kappa:.4}, E {e:.4}, K {k:.4}");
    assert!(kappa < KAPPA_BOUND, "κ error {kappa}");
    assert!(e < E_BOUND, "E error {e}");
    assert!(k < K_BOUND, "K error {k}");
}

#[test]
fn a3_hamrock_brewe_on_a_real_bearing() {
    // On the 7008C raceways (Ry/Rx ≈ 10–30) the approximation's stiffness
    // is within 1 % of the exact one.
    let g = bearing_7008c();
    let ep = effective_modulus(&Material::STEEL_52100, &Material::STEEL_52100);
    for ring in RingKind::BOTH {
        let exact = RacewayContactModel::new(&g, ring, ep, HertzModel::Exact);
        let hb = RacewayContactModel::new(&g, ring, ep, HertzModel::HamrockBrewe);
        let a = 17.7f64.to_radians();
        let (ke, kh) = (
            exact.coefficients(a).unwrap().stiffness,
            hb.coefficients(a).unwrap().stiffness,
        );
        eprintln!(
            "A3 7008C {ring:?}: K_c exact {ke:.6e}, Hamrock–Brewe {kh:.6e}, rel {:.2e}",
            rel(kh, ke)
        );
        assert!(rel(kh, ke) < 0.01);
    }
}

// Found (docs/validation.md): κ 6.34 %, E 1.67 %, K 2.74 % over [1, 100];
// the bounds sit just above so that a change in either solver shows.
const KAPPA_BOUND: f64 = 0.065;
const E_BOUND: f64 = 0.017;
const K_BOUND: f64 = 0.028;
