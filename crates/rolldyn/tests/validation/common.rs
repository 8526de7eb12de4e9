//! Bearings of the seed papers, built from their printed tables.

use rolldyn::{BearingGeometry, Clearance, GeometrySpec};

/// Relative difference |a − b|/|b|.
pub fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// 7008C, seed 001 Table 1: d_m 54, D 6.35 mm, Z 22, α₀ 17.7°,
/// r_i 3.493, r_o 3.302 mm.
pub fn bearing_7008c() -> BearingGeometry {
    BearingGeometry::new(&GeometrySpec {
        ball_diameter: 6.35e-3,
        ball_count: 22,
        pitch_diameter: 54e-3,
        inner_groove_curvature: 3.493 / 6.35,
        outer_groove_curvature: 3.302 / 6.35,
        clearance: Clearance::FreeContactAngle(17.7f64.to_radians()),
        preload: false,
    })
    .expect("seed 001 geometry is valid")
}

/// 6304, seed 000 Table 1: R_i 13.24, R_o 22.77, r_b 4.76 mm, 7 balls.
/// Groove curvatures are not printed: 0.52 assumed (as the preset).
pub fn bearing_6304() -> BearingGeometry {
    BearingGeometry::new(&GeometrySpec {
        ball_diameter: 9.52e-3,
        ball_count: 7,
        pitch_diameter: 0.0,
        inner_groove_curvature: 0.52,
        outer_groove_curvature: 0.52,
        clearance: Clearance::RacewayDiameters {
            inner: 26.48e-3,
            outer: 45.54e-3,
        },
        preload: false,
    })
    .expect("seed 000 geometry is valid")
}

/// 7218B as Harris's 218 angular-contact example: D 22.23 mm, Z 16,
/// d_m 125.26 mm, f = 0.5232, α₀ 40° (seed 002 Table 2 gives D, Z, α₀, d_i).
pub fn bearing_7218b() -> BearingGeometry {
    BearingGeometry::new(&GeometrySpec {
        ball_diameter: 22.23e-3,
        ball_count: 16,
        pitch_diameter: 125.26e-3,
        inner_groove_curvature: 0.5232,
        outer_groove_curvature: 0.5232,
        clearance: Clearance::FreeContactAngle(40f64.to_radians()),
        preload: false,
    })
    .expect("7218B geometry is valid")
}
