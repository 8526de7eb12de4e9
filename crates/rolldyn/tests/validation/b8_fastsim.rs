//! B8: Kalker's FASTSIM (Kalker 1982; Zhang et al. 2025 §2.2; docs/model.md §3 model 4)
//! against the exact limits it must reproduce:
//! - linear theory (Kalker 1990, Table E.3 coefficients) at small
//!   creepage, one creepage at a time: F_x = −G c² C₁₁ ξ,
//!   F_y = −G c² C₂₂ η, F_y = +G c³ C₂₃ φ (this frame: x̂ along the flow,
//!   n from the ball into the ring; Kalker's frame flips the φ sign).
//!   FASTSIM's flexibilities are built so that this holds exactly in the
//!   continuum; the discretisation error is O(1/strips²) + O(1/elements²):
//!   below 1 % at the default 16 × 10 grid;
//! - full sliding: |F| = μQ (the bound is normalised to Q on the grid, so
//!   to rounding) and, for pure spin, the Coulomb spin moment
//!   μ ∫ p_n r dA of the parabolic pressure;
//! - symmetry of pure spin (no F_x), signs, monotone force in creepage,
//!   and dissipation ≥ 0 over a sweep of creepages and geometries;
//! - in the dynamic model, the explicit (DOPRI5) and stiff (ROS34PW2)
//!   integrators agree on a FASTSIM run (B2 with FASTSIM is in
//!   `b2_energy_balance`).

use super::common::{METHODS, bearing_7008c, dynamics_7008c, integrator, rel};
use nalgebra::Vector3;
use rolldyn::contact::HertzModel;
use rolldyn::dynamics::{BearingModel, DragParameters};
use rolldyn::integrate::Integrator;
use rolldyn::material::Material;
use rolldyn::traction::TractionModel;
use rolldyn::traction::fastsim::{DEFAULT_ELEMENTS, DEFAULT_STRIPS, combined_elastic_constants};
use rolldyn::traction::kalker::creep_coefficients;
use rolldyn::traction::{
    ContactConditions, ContactKinematics, ContactPatch, Fastsim, TractionResult,
};

/// An inner-race-like contact of the 7218B: 2.4 mm × 0.36 mm, 3 kN.
fn patch() -> ContactPatch {
    ContactPatch {
        point: Vector3::new(0.0, 0.0, -11e-3),
        normal: Vector3::new(0.0, 0.0, -1.0),
        rolling_direction: Vector3::new(0.0, 1.0, 0.0),
        semi_major: 2.4e-3,
        semi_minor: 0.36e-3,
        load: 3000.0,
        deformed_radius: f64::INFINITY,
    }
}

const SPEED: f64 = 10.0;

fn model(strips: usize, elements: usize) -> Fastsim {
    let (g, nu) = combined_elastic_constants(&Material::STEEL_52100, &Material::STEEL_52100);
    let mut m = Fastsim::new(0.1, g, nu);
    m.strips = strips;
    m.elements = elements;
    m
}

/// Tractions for creepages (ξ, η, φ) at rolling speed `SPEED` along +e_roll.
fn at(m: &Fastsim, p: &ContactPatch, xi: f64, eta: f64, phi: f64) -> TractionResult {
    let ex = p.rolling_direction;
    let ey = p.normal.cross(&ex);
    let v = SPEED.hypot(m.regularisation_speed);
    m.evaluate(&ContactKinematics {
        patch: *p,
        ball_centre: Vector3::zeros(),
        slip: (v * (xi * ex + eta * ey)),
        relative_spin: (v * phi * p.normal),
        conditions: ContactConditions {
            film: 0.0,
            entrainment_speed: SPEED,
            rolling_velocity: SPEED,
        },
    })
}

/// Linear-theory force components (x̂, ŷ) of one creepage.
fn linear(m: &Fastsim, p: &ContactPatch, xi: f64, eta: f64, phi: f64) -> (f64, f64) {
    let c = creep_coefficients(p.semi_minor, p.semi_major, m.poisson_ratio);
    let cc = p.semi_major * p.semi_minor;
    let g = m.shear_modulus;
    (
        -g * cc * c.longitudinal * xi,
        -g * cc * (c.lateral * eta - cc.sqrt() * c.spin_lateral * phi),
    )
}

fn components(p: &ContactPatch, r: &TractionResult) -> (f64, f64) {
    let ex = p.rolling_direction;
    (r.force.dot(&ex), r.force.dot(&p.normal.cross(&ex)))
}

#[test]
fn b8_linear_limit_one_creepage_at_a_time() {
    let p = patch();
    let m = model(DEFAULT_STRIPS, DEFAULT_ELEMENTS);
    for (name, xi, eta, phi, component) in [
        ("ξ", 1e-6, 0.0, 0.0, 0),
        ("η", 0.0, 1e-6, 0.0, 1),
        ("φ", 0.0, 0.0, 1e-3, 1),
    ] {
        let r = at(&m, &p, xi, eta, phi);
        let (fx, fy) = components(&p, &r);
        let (lx, ly) = linear(&m, &p, xi, eta, phi);
        let (f, l) = if component == 0 { (fx, lx) } else { (fy, ly) };
        let creep = r.creep.unwrap();
        eprintln!(
            "B8 linear {name}: FASTSIM {f:.6e} N, Kalker {l:.6e} N, rel {:.2e}, stick {:.3}",
            rel(f, l),
            creep.stick_fraction
        );
        assert_eq!(creep.stick_fraction, 1.0, "{name}: full stick");
        assert!(rel(f, l) < 0.01, "{name}: {f} vs {l}");
    }
}

#[test]
fn b8_discretisation_error_falls_with_the_grid() {
    let p = patch();
    let mut last = f64::INFINITY;
    for (strips, elements) in [(5, 3), (10, 6), (20, 12), (40, 24), (80, 48)] {
        let m = model(strips, elements);
        let (_, fy) = components(&p, &at(&m, &p, 0.0, 0.0, 1e-3));
        let (_, ly) = linear(&m, &p, 0.0, 0.0, 1e-3);
        let err = rel(fy, ly);
        eprintln!("B8 spin force {strips}×{elements}: rel error {err:.2e}");
        assert!(err < last, "{strips}×{elements}: {err} ≥ {last}");
        last = err;
    }
    assert!(last < 1e-3);
}

#[test]
fn b8_full_slip_gives_mu_q() {
    let p = patch();
    let m = model(DEFAULT_STRIPS, DEFAULT_ELEMENTS);
    let mu_q = m.friction * p.load;
    for (xi, eta) in [(1.0, 0.0), (0.0, -1.0), (0.6, 0.8), (-50.0, 20.0)] {
        let r = at(&m, &p, xi, eta, 0.0);
        let (fx, fy) = components(&p, &r);
        eprintln!(
            "B8 full slip ({xi}, {eta}): |F| = {:.6} N, μQ = {mu_q}",
            r.force.norm()
        );
        assert!(rel(r.force.norm(), mu_q) < 1e-9);
        // Against the creepage.
        assert!(fx * xi + fy * eta < 0.0);
        assert_eq!(r.creep.unwrap().stick_fraction, 0.0);
    }
}

#[test]
fn b8_pure_spin_symmetry_signs_and_sliding_moment() {
    let p = patch();
    let m = model(40, 40);
    // Partial slip: symmetric about the rolling axis, no F_x.
    for phi in [1.0, 30.0, -30.0] {
        let r = at(&m, &p, 0.0, 0.0, phi);
        let (fx, fy) = components(&p, &r);
        let spin_moment = r.couple.dot(&p.normal);
        eprintln!(
            "B8 spin φ = {phi} 1/m: F_x {fx:.2e} N, F_y {fy:.4e} N, M_n {spin_moment:.4e} N·m, stick {:.3}",
            r.creep.unwrap().stick_fraction
        );
        assert!(fx.abs() < 1e-9 * fy.abs());
        assert!(fy * phi > 0.0, "spin force sign as Kalker's C₂₃ term");
        assert!(spin_moment * phi < 0.0, "the spin moment opposes the spin");
    }
    // Very large spin: every element slides against the local rigid slip,
    // M_n → −μ ∫ p_n r dA (parabolic p_n), computed by fine quadrature.
    let (a, b) = (p.semi_minor, p.semi_major);
    let n = 800;
    let mut integral = 0.0;
    for i in 0..n {
        for k in 0..n {
            let x = a * (-1.0 + (i as f64 + 0.5) * 2.0 / n as f64);
            let y = b * (-1.0 + (k as f64 + 0.5) * 2.0 / n as f64);
            let s = 1.0 - (x / a).powi(2) - (y / b).powi(2);
            if s > 0.0 {
                integral += s * x.hypot(y) * (2.0 * a / n as f64) * (2.0 * b / n as f64);
            }
        }
    }
    let coulomb = m.friction * 2.0 * p.load / (std::f64::consts::PI * a * b) * integral;
    let r = at(&m, &p, 0.0, 0.0, 1e6);
    let spin_moment = -r.couple.dot(&p.normal);
    eprintln!("B8 sliding spin moment: FASTSIM {spin_moment:.5e}, Coulomb {coulomb:.5e} N·m");
    assert!(rel(spin_moment, coulomb) < 0.02);
}

#[test]
fn b8_force_grows_monotonically_to_saturation() {
    let p = patch();
    let m = model(DEFAULT_STRIPS, DEFAULT_ELEMENTS);
    let mut last = (0.0, 1.0);
    for k in 0..60 {
        let xi = 1e-6 * 10f64.powf(k as f64 / 10.0);
        let r = at(&m, &p, xi, 0.0, 0.0);
        let f = r.force.norm();
        let stick = r.creep.unwrap().stick_fraction;
        assert!(f >= last.0 * (1.0 - 1e-12), "ξ = {xi}: {f} < {}", last.0);
        assert!(stick <= last.1 + 1e-12, "stick area shrinks");
        assert!(f <= m.friction * p.load * (1.0 + 1e-12));
        last = (f, stick);
    }
}

#[test]
fn b8_dissipation_is_never_negative() {
    let m = model(DEFAULT_STRIPS, DEFAULT_ELEMENTS);
    let mut curved = patch();
    curved.deformed_radius = 12e-3;
    let mut worst: f64 = 0.0;
    let mut count = 0;
    for p in [patch(), curved] {
        for xi in [-1e-2, -1e-4, 0.0, 3e-5, 1e-3, 0.2] {
            for eta in [-1e-3, 0.0, 2e-4, 5e-2] {
                for phi in [-50.0, -1.0, 0.0, 0.3, 10.0, 300.0] {
                    let r = at(&m, &p, xi, eta, phi);
                    let scale =
                        m.friction * p.load * SPEED * (xi.abs() + eta.abs() + 1e-3 * phi.abs());
                    worst = worst.min(r.dissipation / scale.max(1e-30));
                    count += 1;
                }
            }
        }
    }
    eprintln!("B8 dissipation over {count} cases: worst relative {worst:.2e}");
    assert!(worst >= -1e-12);
}

/// The 7008C default configuration with FASTSIM (μ = 0.1) from the
/// Jones–Harris state, 3 ms: DOPRI5 and ROS34PW2 at rtol 1e-6 give the
/// same cage angle (to 1e-4 of its advance), drive work and dissipated
/// energy (to 1e-3) and closing energy balances.
#[test]
fn b8_integrators_agree_on_a_fastsim_run() {
    let g = bearing_7008c();
    let steel = Material::STEEL_52100;
    let (mut params, eq) = dynamics_7008c(DragParameters::default());
    let (shear, nu) = combined_elastic_constants(&steel, &steel);
    params.traction = TractionModel::Fastsim(Fastsim::new(0.1, shear, nu));
    let model = BearingModel::new(&g, &steel, &steel, HertzModel::Exact, params).unwrap();
    let y0 = model.state_from_equilibrium(&eq);
    let t_end = 3e-3;
    let c = model.layout().cage() + 2;
    let results: Vec<(f64, f64, f64, f64)> = METHODS
        .iter()
        .map(|&method| {
            let mut m = model.clone();
            let e0 = m.energy(0.0, &y0).total();
            let mut rk = integrator(method, &m, &y0, 1e-6, 1e-5);
            while rk.t() < t_end {
                rk.step(&mut m, t_end).unwrap();
            }
            let (drive, dissipated) = m.work(rk.y());
            let delta = m.energy(rk.t(), rk.y()).total() - e0;
            eprintln!(
                "B8 FASTSIM run ({method:?}): cage angle {:.6} rad, drive {drive:.5e} J, dissipated {dissipated:.5e} J, balance {:.1e}, {} steps",
                rk.y()[c] - y0[c],
                (drive - delta - dissipated) / drive,
                rk.stats().steps
            );
            (rk.y()[c] - y0[c], drive, dissipated, (drive - delta - dissipated) / drive)
        })
        .collect();
    let (a, b) = (results[0], results[1]);
    assert!(rel(a.0, b.0) < 1e-4, "cage angle {} vs {}", a.0, b.0);
    assert!(rel(a.1, b.1) < 1e-3, "drive work {} vs {}", a.1, b.1);
    assert!(rel(a.2, b.2) < 1e-3, "dissipation {} vs {}", a.2, b.2);
    assert!(a.3.abs() < 1e-3 && b.3.abs() < 1e-3);
    assert!(a.1 > 0.0 && a.2 > 0.0);
}

/// The stick/slip map of a contact in the dynamic model (Zhang et al. 2025 Fig. 11)
/// is the same evaluation as the run outputs: one cell per element, the
/// same contact output, and its stuck cells where the output reports a
/// stuck area.
#[test]
fn b8_traction_map_of_a_running_contact() {
    let g = bearing_7008c();
    let steel = Material::STEEL_52100;
    let (mut params, eq) = dynamics_7008c(DragParameters::default());
    let (shear, nu) = combined_elastic_constants(&steel, &steel);
    let fastsim = Fastsim::new(0.1, shear, nu);
    params.traction = TractionModel::Fastsim(fastsim);
    let model = BearingModel::new(&g, &steel, &steel, HertzModel::Exact, params).unwrap();
    let y = model.state_from_equilibrium(&eq);
    let mut samples = vec![rolldyn::dynamics::ContactSample::default(); g.ball_count];
    model.contact_samples(0.0, &y, &mut samples);
    for ring in [rolldyn::RingKind::Inner, rolldyn::RingKind::Outer] {
        let (mut cells, mut stuck) = (0, 0);
        let output = model
            .traction_map(0.0, &y, 0, ring, |c| {
                cells += 1;
                if c.stick {
                    stuck += 1;
                }
                assert!(c.traction.norm() <= c.bound * (1.0 + 1e-12));
            })
            .unwrap();
        let expected = match ring {
            rolldyn::RingKind::Inner => samples[0].inner,
            rolldyn::RingKind::Outer => samples[0].outer,
        };
        assert_eq!(output, expected);
        assert_eq!(cells, fastsim.strips * fastsim.elements);
        let stick = output.creep.unwrap().stick_fraction;
        eprintln!("B8 map ({ring:?}): {stuck}/{cells} cells stuck, stick fraction {stick:.3}");
        assert_eq!(stuck == 0, stick == 0.0);
    }
}
