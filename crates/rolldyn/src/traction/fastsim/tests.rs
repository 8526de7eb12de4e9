use super::*;
use crate::traction::ContactConditions;

fn patch() -> ContactPatch {
    crate::traction::ellipse::test_patch()
}

fn rolling(speed: f64) -> ContactConditions {
    ContactConditions {
        film: 0.0,
        entrainment_speed: speed.abs(),
        rolling_velocity: speed,
    }
}

#[test]
fn rolling_reversal_is_continuous() {
    let m = Fastsim::new(0.1, 80e9, 0.3);
    let p = patch();
    let slip = Vector3::new(0.3e-3, 0.0, 0.0);
    let at = |u: f64| {
        m.evaluate(&ContactKinematics {
            patch: p,
            ball_centre: Vector3::zeros(),
            slip,
            relative_spin: Vector3::zeros(),
            conditions: rolling(u),
        })
    };
    let mut last = at(-2e-3);
    for k in 1..=400 {
        let u = -2e-3 + k as f64 * 1e-5;
        let r = at(u);
        assert!(
            (r.force - last.force).norm() < 0.02 * 20.0,
            "jump at u = {u}"
        );
        assert!(r.dissipation >= -1e-12);
        last = r;
    }
}

/// Under spin the lateral force comes from the slip direction's lag
/// behind the rigid slip, which turns across each element. The slip
/// step takes the rigid slip at the element centre (backward Euler,
/// exact lag in deep slip): on the default 16 × 10 grid the forces of
/// a 7218B inner-raceway contact stay within 2.5 % of μQ of a
/// 400 × 800 grid, and the lateral force within 5 % at φ = 20 1/m
/// (the midpoint step was 4.4 % of μQ and 17 % off).
#[test]
fn default_grid_follows_spin() {
    let p = ContactPatch {
        point: Vector3::new(0.0, 0.0, -3e-3),
        normal: Vector3::new(0.0, 0.0, -1.0),
        rolling_direction: Vector3::new(1.0, 0.0, 0.0),
        semi_major: 2.2609e-3,
        semi_minor: 0.2761e-3,
        load: 2088.0,
        deformed_radius: f64::INFINITY,
    };
    let force = |m: &Fastsim, xi: f64, eta: f64, phi: f64| {
        let ex = p.rolling_direction;
        let ey = p.normal.cross(&ex);
        let slip = (xi * ex + eta * ey) * 10.0;
        let spin = p.normal * phi * 10.0;
        let r = m.evaluate(&ContactKinematics {
            patch: p,
            ball_centre: Vector3::zeros(),
            slip,
            relative_spin: spin,
            conditions: rolling(10.0),
        });
        Vector2::new(r.force.dot(&ex), r.force.dot(&ey))
    };
    let coarse = Fastsim::new(0.1, 76.923e9, 0.3);
    let mut fine = coarse;
    fine.strips = 400;
    fine.elements = 800;
    let mu_q = 0.1 * p.load;
    for &(xi, eta, phi) in &[
        (0.0, 0.0, 5.0),
        (0.0, 0.0, 20.0),
        (0.0, 0.0, 50.0),
        (1e-3, 0.0, 20.0),
        (3e-4, 1e-3, 10.0),
        (3e-3, 3e-4, 20.0),
    ] {
        let (c, f) = (force(&coarse, xi, eta, phi), force(&fine, xi, eta, phi));
        assert!(
            (c - f).norm() < 0.025 * mu_q,
            "{xi},{eta},{phi}: {c} vs {f}"
        );
    }
    let (c, f) = (force(&coarse, 0.0, 0.0, 20.0), force(&fine, 0.0, 0.0, 20.0));
    assert!((c.y / f.y - 1.0).abs() < 0.05, "{} vs {}", c.y, f.y);
}

#[test]
fn no_load_no_traction() {
    let mut p = patch();
    p.load = 0.0;
    let r = Fastsim::new(0.1, 80e9, 0.3).evaluate(&ContactKinematics {
        patch: p,
        ball_centre: Vector3::zeros(),
        slip: Vector3::new(1.0, 0.0, 0.0),
        relative_spin: Vector3::zeros(),
        conditions: rolling(1.0),
    });
    assert_eq!(r.force, Vector3::zeros());
}

#[test]
fn combined_constants_of_equal_bodies_are_theirs() {
    let steel = crate::material::Material::STEEL_52100;
    let (g, nu) = combined_elastic_constants(&steel, &steel);
    assert!((g - steel.elastic_modulus / (2.0 * 1.3)).abs() < 1e-3);
    assert!((nu - 0.3).abs() < 1e-12);
}

/// The AVX2 build of the march gives the baseline build's bits, over
/// creepages from full stick to full slide, with spin, on flat and
/// curved patches, both bounds, and strip counts that leave padding
/// lanes. Skipped on a processor without AVX2.
#[cfg(target_arch = "x86_64")]
#[test]
fn avx2_march_is_bit_identical_to_baseline() {
    if !std::arch::is_x86_feature_detected!("avx2") {
        return;
    }
    let bits = |r: &(TractionResult, Creep)| {
        let (t, c) = r;
        let mut v: Vec<u64> = t
            .force
            .iter()
            .chain(t.couple.iter())
            .map(|x| x.to_bits())
            .collect();
        v.extend([t.dissipation, c.stick_fraction].map(f64::to_bits));
        v
    };
    let mut compared = 0;
    let (mut least_stick, mut most_stick) = (1.0f64, 0.0f64);
    for (strips, elements, bound, curved) in [
        (16, 10, TractionBound::Parabolic, false),
        (13, 7, TractionBound::Elliptic, true),
        (3, 25, TractionBound::Parabolic, true),
    ] {
        let mut m = Fastsim::new(0.1, 80e9, 0.3);
        m.strips = strips;
        m.elements = elements;
        m.bound = bound;
        let mut p = patch();
        if curved {
            p.deformed_radius = 4e-3;
        }
        let c = m.coefficients(&p);
        for k in 0..40 {
            let f = k as f64;
            let slip = Vector3::new(1e-8 * 10f64.powf(0.15 * f), 3e-8 * (0.7 * f).sin(), 0.0);
            let spin = Vector3::new(0.0, 0.0, 1e-3 * 10f64.powf(0.1 * f) * (0.3 * f).cos());
            let kinematics = ContactKinematics {
                patch: p,
                ball_centre: Vector3::zeros(),
                slip,
                relative_spin: spin,
                conditions: ContactConditions::default(),
            };
            for direction in [1.0, -1.0] {
                let baseline = m.march_baseline(&kinematics, 2.0, direction, &c, &mut |_| {});
                // SAFETY: AVX2 was detected above.
                #[allow(unsafe_code)]
                let avx2 = unsafe { m.march_avx2(&kinematics, 2.0, direction, &c, &mut |_| {}) };
                assert_eq!(bits(&baseline), bits(&avx2), "strips {strips}, case {k}");
                compared += 1;
                least_stick = least_stick.min(baseline.1.stick_fraction);
                most_stick = most_stick.max(baseline.1.stick_fraction);
            }
        }
    }
    assert_eq!(compared, 240);
    // Both branches of the march (stick and slide) were compared.
    assert!(
        least_stick < 0.05 && most_stick > 0.95,
        "{least_stick} … {most_stick}"
    );
}

#[test]
fn bad_parameters_are_refused() {
    let mut m = Fastsim::new(0.1, 80e9, 0.3);
    m.strips = 0;
    assert_eq!(m.validate().unwrap_err().field, "strips");
    let m = Fastsim::new(0.1, 80e9, 0.7);
    assert_eq!(m.validate().unwrap_err().field, "poisson_ratio");
    let m = Fastsim::new(-0.1, 80e9, 0.3);
    assert_eq!(m.validate().unwrap_err().field, "friction");
}
