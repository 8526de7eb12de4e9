//! Thermal preload of a bearing set (`thermal::set`, docs/systems.md,
//! "Temperature"), against the rigid-ring geometry of a preloaded
//! angular-contact bearing at rest (Harris & Kotzalas, *Essential
//! Concepts*, ch. 2 and eq. 7.30 form):
//!
//! ```text
//! R = BD cos α₀ − ΔP_d/2,   X = BD sin α₀ + s,   L = √(R² + X²)
//! δ = L − BD,   sin α = X/L,   F_a = Z K_n(α) δ^1.5 sin α
//! ```
//!
//! with R, X the radial and axial distances of the groove centres (the
//! rings held where they were mounted; the inner groove centre lies
//! outside the outer one, so less clearance is a longer R), ΔP_d the thermal change of the
//! diametral clearance, s the preload offset plus the shaft's axial growth
//! against the housing's at the bearing, and K_n the series stiffness of
//! the two contacts at α. The set's model reaches the same through its own
//! parametrization (free contact angle of the operating clearance, offset
//! from the new touching position); this checks that bookkeeping, the
//! signs of both growths and the arrangement's role.

use super::common::{bearing_7008c, rel, series_stiffness};
use rolldyn::BearingGeometry;
use rolldyn::contact::HertzModel;
use rolldyn::material::Material;
use rolldyn::operating::Loads;
use rolldyn::quasistatic::system::{MountedBearing, SetKind, ShaftSystem, SystemConditions};
use rolldyn::quasistatic::{QuasiStaticSolver, RacewayControl, SolverOptions};
use rolldyn::thermal::bearing::node_index;
use rolldyn::thermal::coupled::Expansion;
use rolldyn::thermal::set::{AxialExpansion, axial_strain, mounted_at};

const SPACING: f64 = 15e-3;
const STEEL: f64 = 11.9e-6;
const REFERENCE: f64 = 293.15;

/// F_a of the rigid-ring geometry (module doc) at groove-centre distances
/// (R, X).
fn rigid_ring_thrust(g: &BearingGeometry, radial: f64, axial: f64) -> f64 {
    let length = radial.hypot(axial);
    let alpha = axial.atan2(radial);
    let kn = series_stiffness(g, alpha);
    let delta = length - g.total_curvature() * g.ball_diameter;
    g.ball_count as f64 * kn * delta.powf(1.5) * alpha.sin()
}

/// Node temperatures: the given rises above the reference, the rest at it.
fn temperatures(rises: &[(&str, f64)]) -> [f64; 10] {
    let mut t = [REFERENCE; 10];
    for (name, rise) in rises {
        t[node_index(name).unwrap()] += rise;
    }
    t
}

/// A spindle's gradient: inner ring, balls and shaft warmer than the outer
/// ring and housing.
const SPINDLE: [(&str, f64); 5] = [
    ("inner_ring", 15.0),
    ("ball", 12.0),
    ("shaft", 15.0),
    ("outer_ring", 6.0),
    ("housing", 5.0),
];

#[test]
fn hot_preload_follows_the_rigid_ring_geometry() {
    let g = bearing_7008c();
    let options = SolverOptions::default();
    let expansion = Expansion {
        ring: STEEL,
        ball: STEEL,
        reference_temperature: REFERENCE,
    };
    let axial = AxialExpansion {
        shaft: STEEL,
        housing: 23e-6, // an aluminium housing
    };
    let rest = SystemConditions {
        loads: Loads::default(),
        inner_speed: 0.0,
        control: RacewayControl::Outer,
    };
    let solver = QuasiStaticSolver::new(
        &g,
        &Material::STEEL_52100,
        &Material::STEEL_52100,
        HertzModel::Exact,
    )
    .unwrap();
    let t = [temperatures(&SPINDLE); 2];
    let strain = axial_strain(&axial, &[REFERENCE; 2], &t);
    assert!(rel(strain, STEEL * 15.0 - 23e-6 * 5.0) < 1e-12);
    let bd = g.total_curvature() * g.ball_diameter;
    let a0 = g.free_contact_angle();
    // ΔP_d = α[(d_m + D)ΔT_o − (d_m − D)ΔT_i] − 2α D ΔT_b.
    let clearance_change = STEEL
        * ((g.pitch_diameter + g.ball_diameter) * 6.0
            - (g.pitch_diameter - g.ball_diameter) * 15.0
            - 2.0 * g.ball_diameter * 12.0);
    let mut hot = [0.0; 2];
    for (k, kind) in [SetKind::BackToBack, SetKind::FaceToFace]
        .into_iter()
        .enumerate()
    {
        let set = ShaftSystem::matched(&solver, kind, SPACING);
        let offset = set
            .offset_for_preload(200.0, 0.0, RacewayControl::Outer, &options)
            .unwrap();
        let set = set.with_axial_offset(offset);
        let (warm, geometries) =
            mounted_at(&set, &[(&g, expansion), (&g, expansion)], strain, &t).unwrap();
        assert!(
            rel(
                geometries[0].equivalent_diametral_clearance(),
                g.equivalent_diametral_clearance() + clearance_change
            ) < 1e-9
        );
        let eq = warm.solve(&rest, &options).unwrap();
        for (i, b) in set.bearings.iter().enumerate() {
            // The shaft grows from the middle: bearing i's inner ring
            // moves by strain × x_i against its outer ring, towards its
            // loaded side when that is +x for a forward bearing.
            let sign = if i == 0 { 1.0 } else { -1.0 };
            let s = offset + sign * b.position * strain;
            let expected = rigid_ring_thrust(
                &g,
                bd * a0.cos() - 0.5 * clearance_change,
                bd * a0.sin() + s,
            );
            let got = eq.bearings[i]
                .as_ref()
                .map_or(0.0, MountedBearing::axial_load);
            eprintln!(
                "{kind:?}: bearing {i} at {:+.1} mm: 200 N mounted, {got:.2} N at the spindle's temperatures (rigid rings {expected:.2} N)",
                b.position * 1e3
            );
            assert!(
                rel(got, expected) < 1e-5,
                "{kind:?} bearing {i}: {got} vs {expected}"
            );
        }
        hot[k] = eq.bearings[0]
            .as_ref()
            .map_or(0.0, MountedBearing::axial_load);
    }
    // The radial growth loads both; the shaft's axial growth relieves the
    // back-to-back pair and loads the face-to-face one.
    assert!(200.0 < hot[0] && hot[0] < hot[1], "{hot:?}");
}

#[test]
fn uniform_warming_keeps_the_preload() {
    // Every part of a steel set warmer by the same 30 K: the clearance
    // and the spacers grow alike, so the preload does not change.
    let g = bearing_7008c();
    let options = SolverOptions::default();
    let expansion = Expansion {
        ring: STEEL,
        ball: STEEL,
        reference_temperature: REFERENCE,
    };
    let axial = AxialExpansion {
        shaft: STEEL,
        housing: STEEL,
    };
    let solver = QuasiStaticSolver::new(
        &g,
        &Material::STEEL_52100,
        &Material::STEEL_52100,
        HertzModel::Exact,
    )
    .unwrap();
    let set = ShaftSystem::matched(&solver, SetKind::BackToBack, SPACING);
    let offset = set
        .offset_for_preload(200.0, 0.0, RacewayControl::Outer, &options)
        .unwrap();
    let set = set.with_axial_offset(offset);
    let t = [[REFERENCE + 30.0; 10]; 2];
    let strain = axial_strain(&axial, &[REFERENCE; 2], &t);
    assert!(strain.abs() < 1e-18);
    let (warm, geometries) =
        mounted_at(&set, &[(&g, expansion), (&g, expansion)], strain, &t).unwrap();
    assert!(
        (geometries[0].equivalent_diametral_clearance() - g.equivalent_diametral_clearance()).abs()
            < 1e-15
    );
    let eq = warm
        .solve(
            &SystemConditions {
                loads: Loads::default(),
                inner_speed: 0.0,
                control: RacewayControl::Outer,
            },
            &options,
        )
        .unwrap();
    let preload = eq.bearings[0]
        .as_ref()
        .map_or(0.0, MountedBearing::axial_load);
    assert!(rel(preload, 200.0) < 1e-8, "{preload}");
}
