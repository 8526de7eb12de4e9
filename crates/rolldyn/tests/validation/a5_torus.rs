//! A5: the exact torus contact (docs/model.md §2.1)
//! * equals Shan et al. 2023 eqs 6–7 in planar mode (δ_i = R_i + r_b − R_rc,
//!   δ_o = R_rc + r_b − R_o, with R_rc the ball-centre distance from each
//!   ring's centre), for any in-plane inner-ring offset, to 1e-9 m
//!   (found: rounding level);
//! * agrees to first order with Deng et al. 2022 eqs 2–6 for small ring
//!   displacements: the difference shrinks as the square of the displacement.
//!   Deng et al. 2022's eq 5 is printed with its rows mixed; its T matrix (eq 3)
//!   gives, for groove-centre axial offset B = x_ci and radius R_i = ρ_ci:
//!   radial shift Δy cos φ + Δz sin φ − θ_y B sin φ + θ_z B cos φ,
//!   axial shift Δx + θ_y R_i sin φ − θ_z R_i cos φ.
//!   Deng et al. 2022 measures α from the global radial plane; rolldyn measures it
//!   from the tilted ring's radial plane (docs/model.md §2.1, sin α = |n·a|). The
//!   two differ by the tilt u_φ = −θ_y sin φ + θ_z cos φ at first order
//!   (Deng et al. 2022 eq 5, third row), which the test checks too.

use super::common::{bearing_6304, bearing_7008c};
use nalgebra::Vector3;
use rolldyn::contact::{GrooveCircle, RingPose};

#[test]
fn a5_planar_mode_equals_seed000() {
    let g = bearing_6304();
    let (ri, ro, rb) = (
        g.inner.groove_bottom_diameter / 2.0,
        g.outer.groove_bottom_diameter / 2.0,
        g.ball_diameter / 2.0,
    );
    let mut worst = 0.0f64;
    for k in 0..200 {
        let phi = 0.0314 * k as f64;
        let offset = Vector3::new(
            0.0,
            3e-6 * (0.7 * k as f64).cos(),
            -2e-6 * (1.3 * k as f64).sin(),
        );
        let r_ball = 18.005e-3 + 4e-6 * (0.37 * k as f64).sin();
        let q = Vector3::new(0.0, r_ball * phi.cos(), r_ball * phi.sin());
        let inner_pose = RingPose {
            translation: offset,
            ..Default::default()
        };
        let ci = GrooveCircle::of(&g.inner, &inner_pose)
            .contact(&q, g.ball_diameter, 0.0)
            .unwrap();
        let co = GrooveCircle::of(&g.outer, &RingPose::default())
            .contact(&q, g.ball_diameter, 0.0)
            .unwrap();
        let seed_i = ri + rb - (q - offset).norm();
        let seed_o = q.norm() + rb - ro;
        worst = worst
            .max((ci.penetration - seed_i).abs())
            .max((co.penetration - seed_o).abs());
        assert!(ci.contact_angle.abs() < 1e-12 && co.contact_angle.abs() < 1e-12);
    }
    eprintln!("A5 planar: worst |δ − δ_seed000| = {worst:.2e} m");
    assert!(worst < 1e-9);
}

/// (δ_i, α_i) from Deng et al. 2022's small-displacement formulas.
fn seed001(g: &rolldyn::BearingGeometry, u: [f64; 5], phi: f64) -> (f64, f64) {
    let [dx, dy, dz, ty, tz] = u;
    let b = g.inner.groove_centre_axial;
    let ri = g.inner.groove_centre_radius;
    let a0 = g.offset_contact_angle;
    let l = (g.inner.groove_curvature - 0.5) * g.ball_diameter;
    let radial = dy * phi.cos() + dz * phi.sin() - ty * b * phi.sin() + tz * b * phi.cos();
    let axial = dx + ty * ri * phi.sin() - tz * ri * phi.cos();
    let (num, den) = (l * a0.sin() + axial, l * a0.cos() + radial);
    (num.hypot(den) - l, num.atan2(den))
}

/// Worst differences over the balls between the exact contact and Deng et al. 2022:
/// (penetration, contact angle in the global radial plane, and the
/// ring-frame angle minus the global one against the tilt u_φ).
fn worst_difference(scale: f64) -> (f64, f64, f64) {
    let g = bearing_7008c();
    let u = [
        8e-6 * scale,
        -5e-6 * scale,
        6e-6 * scale,
        2e-4 * scale,
        -1.5e-4 * scale,
    ];
    let pose = RingPose {
        translation: Vector3::new(u[0], u[1], u[2]),
        tilt_y: u[3],
        tilt_z: u[4],
    };
    let circle = GrooveCircle::of(&g.inner, &pose);
    let (mut wd, mut wa, mut wt) = (0.0f64, 0.0f64, 0.0f64);
    for k in 0..g.ball_count {
        let phi = 2.0 * std::f64::consts::PI * k as f64 / g.ball_count as f64 + 0.1;
        let q = Vector3::new(
            0.0,
            g.pitch_diameter / 2.0 * phi.cos(),
            g.pitch_diameter / 2.0 * phi.sin(),
        );
        let c = circle.contact(&q, g.ball_diameter, 0.0).unwrap();
        let (d_seed, a_seed) = seed001(&g, u, phi);
        let global_angle = c.normal.x.abs().asin();
        let tilt = -u[3] * phi.sin() + u[4] * phi.cos();
        wd = wd.max((c.penetration - d_seed).abs());
        wa = wa.max((global_angle - a_seed).abs());
        wt = wt.max((c.contact_angle - global_angle - tilt).abs());
    }
    (wd, wa, wt)
}

#[test]
fn a5_small_displacements_match_seed001_to_first_order() {
    let (d1, a1, t1) = worst_difference(1.0);
    let (d2, a2, t2) = worst_difference(0.5);
    eprintln!(
        "A5 Deng et al. 2022: |Δδ| {d1:.2e} → {d2:.2e} m, |Δα| {a1:.2e} → {a2:.2e} rad, |Δα_ring − u_φ| {t1:.2e} → {t2:.2e} rad when displacements halve"
    );
    // Second-order remainder: halving the displacement quarters the gap.
    assert!((3.0..5.0).contains(&(d1 / d2)), "δ ratio {}", d1 / d2);
    assert!((3.0..5.0).contains(&(a1 / a2)), "α ratio {}", a1 / a2);
    assert!((3.0..5.0).contains(&(t1 / t2)), "tilt ratio {}", t1 / t2);
    // And it is small next to the first-order effect (displacements ~ 10 µm).
    assert!(d1 < 1e-7, "δ difference {d1}");
}
