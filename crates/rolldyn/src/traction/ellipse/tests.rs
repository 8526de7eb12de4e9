//! Tests of the integration over the ellipse.

use super::*;
use crate::math::elliptic;
use crate::traction::ModifiedCoulomb;

fn patch() -> ContactPatch {
    test_patch()
}

fn coulomb() -> ModifiedCoulomb {
    ModifiedCoulomb {
        friction: 0.1,
        stick_speed: 0.0,
        full_speed: 1e-9,
    }
}

#[test]
fn uniform_slip_gives_mu_q() {
    let p = patch();
    let q = Vector3::zeros();
    let slip = Vector3::new(0.0, 0.5, 0.0);
    for method in [
        TractionIntegration::Centre,
        TractionIntegration::Grid {
            across: 12,
            along: 6,
        },
        TractionIntegration::Graded {
            across: 12,
            along: 6,
        },
    ] {
        let r = integrate(
            &coulomb(),
            &TractionGrid::new(method),
            &ContactKinematics {
                patch: p,
                ball_centre: q,
                slip,
                relative_spin: Vector3::zeros(),
                conditions: ContactConditions::default(),
            },
        );
        assert!(
            (r.force - Vector3::new(0.0, -20.0, 0.0)).norm() < 1e-9,
            "{method:?}: {:?}",
            r.force
        );
        assert!((r.dissipation - 10.0).abs() < 1e-9);
    }
}

#[test]
fn full_slip_spin_moment_is_harris() {
    // Pure spin about the normal with full Coulomb sliding:
    // M_s = (3/8) μ Q a E(m), m = 1 − (b/a)² (Harris & Kotzalas; docs/model.md §10).
    let p = patch();
    let spin = 1000.0 * p.normal;
    let m = 1.0 - (p.semi_minor / p.semi_major).powi(2);
    let exact = 0.375 * 0.1 * p.load * p.semi_major * elliptic::complete(m).e;
    let moment = |method: TractionIntegration| {
        let r = integrate(
            &coulomb(),
            &TractionGrid::new(method),
            &ContactKinematics {
                patch: p,
                ball_centre: p.point,
                slip: Vector3::zeros(),
                relative_spin: spin,
                conditions: ContactConditions::default(),
            },
        );
        assert!(r.force.norm() < 1e-9 * p.load, "symmetric: no net force");
        -r.moment.dot(&p.normal) / exact - 1.0
    };
    let uniform = |across, along| moment(TractionIntegration::Grid { across, along });
    let graded = |across, along| moment(TractionIntegration::Graded { across, along });
    eprintln!(
        "spin moment error: uniform 12×6 {:+.2e}, 48×24 {:+.2e}; graded 12×6 {:+.2e}, 48×24 {:+.2e}",
        uniform(12, 6),
        uniform(48, 24),
        graded(12, 6),
        graded(48, 24)
    );
    assert!(uniform(48, 24).abs() < 0.01, "uniform 48×24");
    assert!(uniform(12, 6).abs() < 0.03, "uniform 12×6");
    // Cells graded towards the edge take the square-root edge of the
    // pressure along the strips; what is left is the strips' midpoint rule
    // across them, which sets this long ellipse's spin moment.
    assert!(graded(12, 6).abs() < uniform(12, 6).abs(), "graded 12×6");
    assert!(
        graded(48, 24).abs() < 0.6 * uniform(48, 24).abs(),
        "graded 48×24"
    );
}

/// Contacts of the default case, sampled from runs (default_case_contacts.txt).
fn default_case_contacts() -> Vec<ContactKinematics> {
    include_str!("default_case_contacts.txt")
        .lines()
        .filter(|line| !line.starts_with('#'))
        .map(|line| {
            let v: Vec<f64> = line
                .split_whitespace()
                .map(|x| x.parse().unwrap())
                .collect();
            let v3 = |i: usize| Vector3::new(v[i], v[i + 1], v[i + 2]);
            ContactKinematics {
                patch: ContactPatch {
                    point: v3(0),
                    normal: v3(3),
                    rolling_direction: v3(6),
                    semi_major: v[9],
                    semi_minor: v[10],
                    load: v[11],
                    deformed_radius: v[12],
                },
                ball_centre: v3(13),
                slip: v3(16),
                relative_spin: v3(19),
                conditions: ContactConditions {
                    film: v[22],
                    entrainment_speed: v[23],
                    rolling_velocity: v[24],
                },
            }
        })
        .collect()
}

/// On the default case's own contacts (EHL rheology, at 10 000 and
/// 100 rpm) the graded 12 × 6 grid is closer than the uniform one to a
/// 96 × 48 reference in the force, the spin moment and the dissipated
/// power; the uniform grid's power and spin moment are several per cent
/// low (its midpoint rule on the pressure's square-root edge).
#[test]
fn graded_grid_is_closer_on_bearing_contacts() {
    let law = crate::traction::ehl::tests::law();
    let contacts = default_case_contacts();
    assert_eq!(contacts.len(), 8);
    let reference = TractionGrid::new(TractionIntegration::Graded {
        across: 96,
        along: 48,
    });
    let check = TractionGrid::new(TractionIntegration::Grid {
        across: 192,
        along: 96,
    });
    // (force / (Λ_L Q), spin moment, power): mean relative errors.
    let errors = |grid: &TractionGrid| {
        let mut sums = [0.0; 3];
        for k in &contacts {
            let (r, x) = (integrate(&law, &reference, k), integrate(&law, grid, k));
            let spin = |r: &TractionResult| r.couple.dot(&k.patch.normal);
            sums[0] += (x.force - r.force).norm() / (0.08 * k.patch.load);
            sums[1] += (spin(&x) / spin(&r) - 1.0).abs();
            sums[2] += (x.dissipation / r.dissipation - 1.0).abs();
        }
        sums.map(|s| s / contacts.len() as f64)
    };
    let [f_ref, m_ref, p_ref] = errors(&check);
    assert!(
        f_ref < 1e-3 && m_ref < 2e-3 && p_ref < 2e-3,
        "references agree: {f_ref:.1e} {m_ref:.1e} {p_ref:.1e}"
    );
    let [f_uniform, m_uniform, p_uniform] = errors(&TractionGrid::new(TractionIntegration::Grid {
        across: 12,
        along: 6,
    }));
    let [f_graded, m_graded, p_graded] = errors(&TractionGrid::new(TractionIntegration::Graded {
        across: 12,
        along: 6,
    }));
    eprintln!(
        "12×6 mean errors, uniform / graded: force {f_uniform:.2e} / {f_graded:.2e} of Λ_L Q, \
         spin moment {m_uniform:.2e} / {m_graded:.2e}, power {p_uniform:.2e} / {p_graded:.2e}"
    );
    assert!(
        p_uniform > 0.03 && m_uniform > 0.03,
        "the uniform grid's known error"
    );
    assert!(
        p_graded < 0.02 && p_graded < 0.25 * p_uniform,
        "graded power"
    );
    assert!(
        m_graded < 0.03 && m_graded < 0.35 * m_uniform,
        "graded spin moment"
    );
    assert!(f_graded < f_uniform, "graded force");
}

#[test]
fn deformed_surface_curves_towards_the_ball() {
    // With spin about the rolling-direction-normal axis, points across the
    // ellipse move at different speeds only through the arc geometry.
    let mut p = patch();
    p.deformed_radius = 3e-3;
    let spin = Vector3::new(0.0, 500.0, 0.0);
    let flat = integrate(
        &coulomb(),
        &TractionGrid::new(TractionIntegration::Grid {
            across: 12,
            along: 6,
        }),
        &ContactKinematics {
            patch: patch(),
            ball_centre: Vector3::zeros(),
            slip: Vector3::zeros(),
            relative_spin: spin,
            conditions: ContactConditions::default(),
        },
    );
    let curved = integrate(
        &coulomb(),
        &TractionGrid::new(TractionIntegration::Grid {
            across: 12,
            along: 6,
        }),
        &ContactKinematics {
            patch: p,
            ball_centre: Vector3::zeros(),
            slip: Vector3::zeros(),
            relative_spin: spin,
            conditions: ContactConditions::default(),
        },
    );
    assert!(
        (flat.force - curved.force).norm() > 1e-6,
        "curvature changes the slip field"
    );
}

/// The AVX2 build of the integration gives the baseline build's bits
/// for the EHL rheology (Newtonian to limiting shear), its blend with
/// boundary friction and Coulomb friction, with slip and spin, on flat
/// and curved patches, on grids that leave padding lanes and one finer
/// than the shared pressure levels. Skipped without AVX2.
#[cfg(target_arch = "x86_64")]
#[test]
fn avx2_build_is_bit_identical_to_baseline() {
    use crate::traction::mixed::Blended;
    if !std::arch::is_x86_feature_detected!("avx2") {
        return;
    }
    let bits = |r: &TractionResult| -> Vec<u64> {
        r.force
            .iter()
            .chain(r.couple.iter())
            .chain(r.moment.iter())
            .chain([r.dissipation].iter())
            .map(|x| x.to_bits())
            .collect()
    };
    let fluid = crate::traction::ehl::tests::law();
    let boundary = coulomb();
    let blend = Blended {
        fluid: &fluid,
        boundary: &boundary,
        share: 0.3,
    };
    let mut compared = 0;
    for (across, along, curved) in [(12, 6, true), (7, 5, false), (40, 20, true), (10, 6, true)] {
        let grid = TractionGrid::new(if across == 10 {
            TractionIntegration::Graded { across, along }
        } else {
            TractionIntegration::Grid { across, along }
        });
        let mut p = patch();
        p.load = 400.0;
        if curved {
            p.deformed_radius = 3.3e-3;
        }
        for k in 0..30 {
            let f = k as f64;
            let kinematics = ContactKinematics {
                patch: p,
                ball_centre: Vector3::zeros(),
                slip: Vector3::new(1e-7 * 10f64.powf(0.25 * f), 2e-4 * (0.7 * f).sin(), 0.0),
                relative_spin: Vector3::new(0.0, 300.0 * f, -50.0 * (0.3 * f).cos()),
                conditions: ContactConditions {
                    film: 2e-7,
                    entrainment_speed: 10.0,
                    rolling_velocity: 10.0,
                },
            };
            let pairs = [
                (
                    integrate_baseline(&fluid, &grid, &kinematics),
                    // SAFETY: AVX2 was detected above.
                    #[allow(unsafe_code)]
                    unsafe {
                        integrate_avx2(&fluid, &grid, &kinematics)
                    },
                ),
                (
                    integrate_baseline(&blend, &grid, &kinematics),
                    #[allow(unsafe_code)]
                    unsafe {
                        integrate_avx2(&blend, &grid, &kinematics)
                    },
                ),
                (
                    integrate_baseline(&boundary, &grid, &kinematics),
                    #[allow(unsafe_code)]
                    unsafe {
                        integrate_avx2(&boundary, &grid, &kinematics)
                    },
                ),
            ];
            for (baseline, avx2) in &pairs {
                assert!(baseline.force.norm() > 0.0);
                assert_eq!(bits(baseline), bits(avx2), "{across} × {along}, case {k}");
                compared += 1;
            }
        }
    }
    assert_eq!(compared, 360);
}

#[test]
fn grid_levels_are_the_distinct_shapes() {
    // 12 × 6: mirror-symmetric in s and t, so 6 × 3 distinct shapes;
    // 7 × 5: 4 × 3; the graded 12 × 6 too.
    for (method, levels) in [
        (
            TractionIntegration::Grid {
                across: 12,
                along: 6,
            },
            18,
        ),
        (
            TractionIntegration::Grid {
                across: 7,
                along: 5,
            },
            12,
        ),
        (
            TractionIntegration::Graded {
                across: 12,
                along: 6,
            },
            18,
        ),
    ] {
        let grid = TractionGrid::new(method);
        assert_eq!(grid.levels.len(), levels);
        for group in &grid.groups {
            for batch in &group.batches {
                for k in 0..BATCH {
                    let level = grid.levels[batch.level[k] as usize];
                    if batch.weight[k] > 0.0 {
                        assert_eq!(level.to_bits(), batch.shape[k].to_bits());
                    }
                }
            }
        }
    }
}
