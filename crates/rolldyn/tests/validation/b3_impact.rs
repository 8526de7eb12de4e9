//! B3: a single ball impact with the Lankarani–Nikravesh law (docs/model.md §2.3).
//! A 6304 ball (D 9.52 mm, steel) hits the inner raceway of Shan et al. 2023's
//! bearing at 0.1 m/s; integrated with RK4 at 1/2000 of the Hertz contact
//! time; the episode's impact speed is recorded at the first accepted step
//! in contact. L–N is derived for e near 1 (Lankarani & Nikravesh 1990):
//! the rebound/impact ratio is expected close to e. Found values are
//! reported in docs/validation.md; tolerance below: 2 % of e.

use super::common::bearing_6304;
use rolldyn::RingKind;
use rolldyn::contact::HertzModel;
use rolldyn::contact::normal_law::{ContactEpisode, ContactState, NormalForceLaw, NormalLaw};
use rolldyn::contact::table::RacewayContactModel;
use rolldyn::material::{Material, effective_modulus};

/// Rebound speed / impact speed of one impact.
pub fn restitution_found(law: NormalForceLaw, impact_speed: f64) -> f64 {
    let g = bearing_6304();
    let steel = Material {
        elastic_modulus: 210e9,
        poisson_ratio: 0.3,
        density: 7800.0,
    };
    let ep = effective_modulus(&steel, &steel);
    let k = RacewayContactModel::new(&g, RingKind::Inner, ep, HertzModel::Exact)
        .coefficients(0.0)
        .unwrap()
        .stiffness;
    let m = g.ball_mass(steel.density);
    // Hertz contact duration ≈ 3.21 (m/k)^{2/5} v^{−1/5} (Johnson, Contact Mechanics, eq. 11.24).
    let duration = 3.21 * (m / k).powf(0.4) * impact_speed.powf(-0.2);
    let dt = duration / 2000.0;
    let floor = 1e-6;
    let mut episode = ContactEpisode::default();
    let accel = |d: f64, v: f64, ep: &ContactEpisode| {
        let state = ContactState {
            stiffness: k,
            penetration: d,
            penetration_rate: v,
            impact_speed: ep.impact_speed(v, floor),
            effective_mass: m,
        };
        -law.force(&state) / m
    };
    let (mut d, mut v) = (0.0f64, impact_speed);
    for _ in 0..100_000 {
        let (k1d, k1v) = (v, accel(d, v, &episode));
        let (k2d, k2v) = (
            v + 0.5 * dt * k1v,
            accel(d + 0.5 * dt * k1d, v + 0.5 * dt * k1v, &episode),
        );
        let (k3d, k3v) = (
            v + 0.5 * dt * k2v,
            accel(d + 0.5 * dt * k2d, v + 0.5 * dt * k2v, &episode),
        );
        let (k4d, k4v) = (v + dt * k3v, accel(d + dt * k3d, v + dt * k3v, &episode));
        d += dt / 6.0 * (k1d + 2.0 * k2d + 2.0 * k3d + k4d);
        v += dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        episode.accept(d, v, floor);
        if d <= 0.0 && v < 0.0 {
            return -v / impact_speed;
        }
    }
    f64::NAN
}

#[test]
fn b3_lankarani_nikravesh_rebound() {
    for e in [0.9, 0.95] {
        let found = restitution_found(NormalForceLaw::LankaraniNikravesh { restitution: e }, 0.1);
        eprintln!(
            "B3 L–N e = {e}: rebound/impact = {found:.4} (error {:+.2} %)",
            100.0 * (found - e) / e
        );
        assert!(((found - e) / e).abs() < 0.02, "e = {e}: found {found}");
    }
}

#[test]
fn b3_hertz_is_elastic() {
    let found = restitution_found(NormalForceLaw::Hertz, 0.1);
    assert!((found - 1.0).abs() < 1e-6, "{found}");
}
