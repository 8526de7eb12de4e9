//! A7: Shan et al. 2023 geometry. R_i = 13.24, R_o = 22.77, r_b = 4.76 mm give
//! c = 0.005 mm (eq 1: R_i + 2(r_b + c) = R_o) and R_m = 18.005 mm. In
//! rolldyn's parametrization (c) the diametral clearance is P_d = 4c and a
//! ball at the pitch radius has a gap of exactly c at both raceways
//! (this is the check that exposes the sign misprint in docs/model.md §2).

use super::common::bearing_6304;
use nalgebra::Vector3;
use rolldyn::contact::{GrooveCircle, RingPose};

#[test]
fn a7_clearance_and_pitch_radius() {
    let g = bearing_6304();
    let c = 0.005e-3;
    assert!((g.pitch_diameter / 2.0 - 18.005e-3).abs() < 1e-15);
    assert!((g.diametral_clearance - 4.0 * c).abs() < 1e-15);
    let q = Vector3::new(0.0, 0.0, g.pitch_diameter / 2.0);
    for race in [&g.inner, &g.outer] {
        let contact = GrooveCircle::of(race, &RingPose::default())
            .contact(&q, g.ball_diameter, 0.0)
            .unwrap();
        assert!(
            (contact.penetration + c).abs() < 1e-15,
            "gap {}",
            -contact.penetration
        );
    }
    assert!((g.inner.groove_bottom_diameter - 26.48e-3).abs() < 1e-15);
    assert!((g.outer.groove_bottom_diameter - 45.54e-3).abs() < 1e-15);
}
