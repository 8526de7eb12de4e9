//! A1: complete elliptic integrals. K(0.5) = 1.8540746773013719,
//! E(0.5) = 1.3506438810476755 (A&S Table 17.1, 16 digits from mpmath),
//! both → π/2 as m → 0. Tolerance 1e-12 relative.

use super::common::rel;
use rolldyn::math::elliptic::complete;
use std::f64::consts::FRAC_PI_2;

#[test]
fn a1_reference_values_and_limit() {
    let c = complete(0.5);
    assert!(rel(c.k, 1.854_074_677_301_371_9) < 1e-12);
    assert!(rel(c.e, 1.350_643_881_047_675_5) < 1e-12);
    let z = complete(0.0);
    assert!(rel(z.k, FRAC_PI_2) < 1e-12 && rel(z.e, FRAC_PI_2) < 1e-12);
    let tiny = complete(1e-14);
    assert!(rel(tiny.k, FRAC_PI_2) < 1e-12 && rel(tiny.e, FRAC_PI_2) < 1e-12);
    // Extra points, mpmath ellipk/ellipe at 50 digits.
    let c9 = complete(0.9);
    assert!(
        rel(c9.k, 2.578_092_113_348_172_7) < 1e-12,
        "K(0.9) = {}",
        c9.k
    );
    assert!(
        rel(c9.e, 1.104_774_732_704_073_4) < 1e-12,
        "E(0.9) = {}",
        c9.e
    );
}
