//! Basic dynamic load rating and basic rating life of radial ball
//! bearings by ISO 281:2007 (§6.1, Tables 2 and 3):
//!
//! ```text
//! C_r = b_m f_c (i cos α)^0.7 Z^(2/3) D_w^1.8              D_w ≤ 25.4 mm
//! C_r = 3.647 b_m f_c (i cos α)^0.7 Z^(2/3) D_w^1.4        D_w > 25.4 mm      (N, mm)
//! P_r = X F_r + Y F_a,    L_10 = (C_r/P_r)^3  [10⁶ revolutions]
//! ```
//! b_m = 1.3 (radial ball bearings); f_c from Table 2 (single-row radial
//! contact groove ball bearings and angular-contact groove ball bearings),
//! linear between its rows, over D_w cos α/D_pw; X, Y, e from Table 3 for
//! single-row bearings: deep-groove (α = 0) and 15° angular-contact bearings
//! by the relative axial load f_0 F_a/C_0r = F_a/(i Z D_w² cos α) (N, mm;
//! ISO 76's C_0r = f_0 i Z D_w² cos α, so f_0 itself is not needed), linear
//! between its rows and held at the end rows outside them; 20°, 25°, 30°,
//! 35° and 40° bearings by their fixed rows; X = 1, Y = 0 under a purely
//! radial load for any bearing. Between the tabulated angles of 15° … 40°
//! e, X and Y are linear in α between the neighbouring rows (ISO 281's note
//! on intermediate values; e.g. the 7008C's 17.7°). Other nominal angles
//! (5°, 10°, above 40°) under axial load are not covered: the equivalent
//! load is then None.
//!
//! Check: C_r of the CWRU 6205 and 6203 geometries and of the 6206 and 6304
//! presets against manufacturers' catalogue values computed by the same
//! standard (tests).

use crate::error::InvalidParameter;
use crate::geometry::BearingGeometry;

/// b_m of radial ball bearings (ISO 281 Table 1).
pub const B_M: f64 = 1.3;

/// ISO 281:2007 Table 2, first column: (D_w cos α/D_pw, f_c).
const F_C: [(f64, f64); 25] = [
    (0.01, 29.1),
    (0.02, 35.8),
    (0.03, 40.3),
    (0.04, 43.8),
    (0.05, 46.7),
    (0.06, 49.1),
    (0.07, 51.1),
    (0.08, 52.8),
    (0.09, 54.3),
    (0.10, 55.5),
    (0.12, 57.5),
    (0.14, 58.8),
    (0.16, 59.6),
    (0.18, 59.9),
    (0.20, 59.9),
    (0.22, 59.6),
    (0.24, 59.0),
    (0.26, 58.2),
    (0.28, 57.1),
    (0.30, 56.0),
    (0.32, 54.6),
    (0.34, 53.2),
    (0.36, 51.7),
    (0.38, 50.0),
    (0.40, 48.4),
];

/// f_c at γ = D_w cos α/D_pw (linear between the table's rows), or None
/// outside [0.01, 0.40].
pub fn geometry_factor(gamma: f64) -> Option<f64> {
    F_C.windows(2).find_map(|w| {
        let ((g0, f0), (g1, f1)) = (w[0], w[1]);
        (g0..=g1)
            .contains(&gamma)
            .then(|| f0 + (f1 - f0) * (gamma - g0) / (g1 - g0))
    })
}

/// Basic dynamic radial load rating C_r \[N\] of a single-row radial ball
/// bearing: ball diameter D_w, pitch diameter D_pw \[m\], Z balls,
/// nominal contact angle α \[rad\].
pub fn dynamic_load_rating(
    ball_diameter: f64,
    pitch_diameter: f64,
    ball_count: usize,
    contact_angle: f64,
) -> Result<f64, InvalidParameter> {
    let gamma = ball_diameter * contact_angle.cos() / pitch_diameter;
    let f_c = geometry_factor(gamma).ok_or_else(|| {
        InvalidParameter::new(
            "D_w cos α / D_pw",
            gamma,
            "ISO 281 Table 2 covers 0.01 to 0.40",
        )
    })?;
    let d_mm = ball_diameter * 1e3;
    let z = ball_count as f64;
    let common = B_M * f_c * contact_angle.cos().powf(0.7) * z.powf(2.0 / 3.0);
    Ok(if d_mm <= 25.4 {
        common * d_mm.powf(1.8)
    } else {
        3.647 * common * d_mm.powf(1.4)
    })
}

/// ISO 281 Table 3, single-row angular-contact ball bearings of fixed
/// rows: (α \[deg\], e, X, Y) for F_a/F_r > e (X = 1, Y = 0 at or below e).
const ANGULAR: [(f64, f64, f64, f64); 5] = [
    (20.0, 0.57, 0.43, 1.00),
    (25.0, 0.68, 0.41, 0.87),
    (30.0, 0.80, 0.39, 0.76),
    (35.0, 0.95, 0.37, 0.66),
    (40.0, 1.14, 0.35, 0.57),
];

/// ISO 281 Table 3, relative axial load f_0 F_a/C_0r of the rows of
/// deep-groove and 15° single-row bearings.
const RELATIVE_AXIAL_LOAD: [f64; 9] = [0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89];

/// A bearing type of Table 3 whose e and Y follow the relative axial load:
/// (α \[deg\], X, e per row, Y per row).
struct AxialLoadRows {
    angle_deg: f64,
    x: f64,
    e: [f64; 9],
    y: [f64; 9],
}

const LOAD_DEPENDENT: [AxialLoadRows; 2] = [
    // Single-row deep-groove ball bearings.
    AxialLoadRows {
        angle_deg: 0.0,
        x: 0.56,
        e: [0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44],
        y: [2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00],
    },
    // Single-row angular-contact ball bearings, α = 15°.
    AxialLoadRows {
        angle_deg: 15.0,
        x: 0.44,
        e: [0.38, 0.40, 0.43, 0.46, 0.47, 0.50, 0.55, 0.56, 0.56],
        y: [1.47, 1.40, 1.30, 1.23, 1.19, 1.12, 1.02, 1.00, 1.00],
    },
];

/// Linear interpolation of `values` over [`RELATIVE_AXIAL_LOAD`], held at
/// the end rows.
fn by_relative_axial_load(values: &[f64; 9], relative: f64) -> f64 {
    let xs = &RELATIVE_AXIAL_LOAD;
    if relative <= xs[0] {
        return values[0];
    }
    for i in 1..xs.len() {
        if relative <= xs[i] {
            let t = (relative - xs[i - 1]) / (xs[i] - xs[i - 1]);
            return values[i - 1] + t * (values[i] - values[i - 1]);
        }
    }
    values[xs.len() - 1]
}

/// The ball set of a single-row radial ball bearing, as ISO 281 rates it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallSet {
    /// Ball diameter D_w \[m\].
    pub ball_diameter: f64,
    /// Pitch diameter D_pw \[m\].
    pub pitch_diameter: f64,
    /// Number of balls Z.
    pub ball_count: usize,
    /// Nominal contact angle α \[rad\] (0 for deep-groove bearings).
    pub contact_angle: f64,
}

impl BallSet {
    /// The ball set of `geometry` at its nominal contact angle.
    pub fn of(geometry: &BearingGeometry) -> Self {
        Self {
            ball_diameter: geometry.ball_diameter,
            pitch_diameter: geometry.pitch_diameter,
            ball_count: geometry.ball_count,
            contact_angle: geometry.nominal_contact_angle(),
        }
    }

    /// Basic dynamic radial load rating C_r \[N\].
    pub fn dynamic_load_rating(&self) -> Result<f64, InvalidParameter> {
        dynamic_load_rating(
            self.ball_diameter,
            self.pitch_diameter,
            self.ball_count,
            self.contact_angle,
        )
    }

    /// Relative axial load f_0 F_a/C_0r = F_a/(Z D_w² cos α) \[N/mm², as
    /// Table 3 tabulates it\] for the axial load F_a \[N\].
    pub fn relative_axial_load(&self, axial: f64) -> f64 {
        let d_mm = self.ball_diameter * 1e3;
        axial.abs() / (self.ball_count as f64 * d_mm * d_mm * self.contact_angle.cos())
    }

    /// Dynamic equivalent radial load P_r \[N\] for radial load F_r and
    /// axial load F_a \[N\]: F_r when F_a = 0; by Table 3 for deep-groove
    /// bearings and angular-contact bearings of 15°, 20°, 25°, 30°, 35° and
    /// 40° (nominal angle within 0.5°), linear in α between those rows;
    /// otherwise (0.5° … 14.5°, above 40.5°) None (not covered).
    pub fn equivalent_load(&self, radial: f64, axial: f64) -> Option<f64> {
        let (fr, fa) = (radial.abs(), axial.abs());
        if fa == 0.0 {
            return Some(fr);
        }
        let deg = self.contact_angle.to_degrees();
        let (e, x, y) = match self.row(deg, fa) {
            Some(row) => row,
            // Between the tabulated angles of 15° … 40°: linear in α
            // between the neighbouring rows (ISO 281's note on
            // intermediate values).
            None => {
                let angles = [15.0, 20.0, 25.0, 30.0, 35.0, 40.0];
                let k = angles.windows(2).position(|w| w[0] < deg && deg < w[1])?;
                let (a0, a1) = (angles[k], angles[k + 1]);
                let (r0, r1) = (self.row(a0, fa)?, self.row(a1, fa)?);
                let w = (deg - a0) / (a1 - a0);
                let mix = |p: f64, q: f64| p + w * (q - p);
                (mix(r0.0, r1.0), mix(r0.1, r1.1), mix(r0.2, r1.2))
            }
        };
        Some(if fr > 0.0 && fa / fr <= e {
            fr
        } else {
            x * fr + y * fa
        })
    }
}

impl BallSet {
    /// (e, X, Y) of the Table 3 row within 0.5° of `deg` \[°\] at axial
    /// load `fa` \[N\], if there is one.
    fn row(&self, deg: f64, fa: f64) -> Option<(f64, f64, f64)> {
        let near = |a: f64| (a - deg).abs() <= 0.5;
        if let Some(rows) = LOAD_DEPENDENT.iter().find(|r| near(r.angle_deg)) {
            let relative = self.relative_axial_load(fa);
            return Some((
                by_relative_axial_load(&rows.e, relative),
                rows.x,
                by_relative_axial_load(&rows.y, relative),
            ));
        }
        ANGULAR
            .iter()
            .find(|row| near(row.0))
            .map(|&(_, e, x, y)| (e, x, y))
    }
}

/// Basic rating life L_10 = (C_r/P_r)³ \[10⁶ revolutions\] (ball bearings).
pub fn basic_rating_life(rating: f64, equivalent_load: f64) -> f64 {
    (rating / equivalent_load).powi(3)
}

#[cfg(test)]
mod tests {
    use super::*;

    const IN: f64 = 0.0254;

    /// C_r of catalogue bearings, computed from their ball sets, against
    /// the values NSK lists (computed by ISO 281 from the same ball sets):
    /// 6205 14.0 kN, 6203 9.55 kN, 6206 19.5 kN, 6304 15.9 kN; 0.5 % (the
    /// catalogue rounds to three figures; the 6206 and 6304 ball sets are
    /// the presets', the usual ones).
    #[test]
    fn dynamic_rating_matches_catalogue_values() {
        for (name, d, dm, z, catalogue) in [
            ("6205", 0.3126 * IN, 1.537 * IN, 9, 14_000.0),
            ("6203", 0.2656 * IN, 1.122 * IN, 8, 9_550.0),
            ("6206", 9.525e-3, 46e-3, 9, 19_500.0),
            ("6304", 9.52e-3, 36e-3, 7, 15_900.0),
        ] {
            let c = dynamic_load_rating(d, dm, z, 0.0).unwrap();
            assert!(
                (c / catalogue - 1.0).abs() < 5e-3,
                "{name}: {c} N vs {catalogue} N"
            );
        }
    }

    #[test]
    fn factors() {
        assert_eq!(geometry_factor(0.20), Some(59.9));
        assert!((geometry_factor(0.21).unwrap() - 59.75).abs() < 1e-12);
        assert!(geometry_factor(0.5).is_none());
        let set = |deg: f64| BallSet {
            ball_diameter: 7.94e-3,
            pitch_diameter: 39e-3,
            ball_count: 9,
            contact_angle: deg.to_radians(),
        };
        assert_eq!(set(0.0).equivalent_load(1000.0, 0.0), Some(1000.0));
        let a30 = set(30.0);
        assert_eq!(a30.equivalent_load(1000.0, 700.0), Some(1000.0));
        assert!(
            (a30.equivalent_load(780.0, 3000.0).unwrap() - (0.39 * 780.0 + 0.76 * 3000.0)).abs()
                < 1e-9
        );
        assert!(set(10.0).equivalent_load(780.0, 3000.0).is_none());
        assert!(set(45.0).equivalent_load(780.0, 3000.0).is_none());
        // Between rows: linear in α. 27.5° is the mean of the fixed 25° and
        // 30° rows (both above e here, so P is linear in X and Y too); at
        // 17.5° the load-dependent 15° row is read at this set's own
        // relative axial load, so P lies between its neighbours'.
        let p = set(27.5).equivalent_load(780.0, 3000.0).unwrap();
        let (p0, p1) = (
            set(25.0).equivalent_load(780.0, 3000.0).unwrap(),
            set(30.0).equivalent_load(780.0, 3000.0).unwrap(),
        );
        assert!((p - 0.5 * (p0 + p1)).abs() < 1e-9 * p, "{p} vs {p0}, {p1}");
        for (fr, fa) in [(780.0, 3000.0), (0.0, 500.0)] {
            let p = set(17.5).equivalent_load(fr, fa).unwrap();
            let (p0, p1) = (
                set(15.0).equivalent_load(fr, fa).unwrap(),
                set(20.0).equivalent_load(fr, fa).unwrap(),
            );
            assert!(p < p0.max(p1) && p > p0.min(p1), "17.5°: {p} vs {p0}, {p1}");
        }
    }

    /// Deep-groove 6205 ball set (Z = 9, D_w = 7.94 mm), F_a = 1000 N:
    /// f_0 F_a/C_0r = 1000/(9 · 7.94²) = 1.7625, between Table 3's rows
    /// 1.38 (e 0.30, Y 1.45) and 2.07 (e 0.34, Y 1.31); by hand
    /// e = 0.3222, Y = 1.3724, so F_r = 2000 N (F_a/F_r = 0.5 > e) gives
    /// P = 0.56 · 2000 + 1.3724 · 1000, and F_r = 4000 N (0.25 < e) P = F_r.
    #[test]
    fn deep_groove_axial_factors_interpolate_table_3() {
        let set = BallSet {
            ball_diameter: 7.94e-3,
            pitch_diameter: 39e-3,
            ball_count: 9,
            contact_angle: 0.0,
        };
        let relative = 1000.0 / (9.0 * 7.94 * 7.94);
        assert!((set.relative_axial_load(1000.0) - relative).abs() < 1e-12);
        let t = (relative - 1.38) / (2.07 - 1.38);
        let y = 1.45 + t * (1.31 - 1.45);
        let p = set.equivalent_load(2000.0, 1000.0).unwrap();
        assert!((p - (0.56 * 2000.0 + y * 1000.0)).abs() < 1e-9, "{p}");
        assert!((y - 1.3724).abs() < 1e-4);
        assert_eq!(set.equivalent_load(4000.0, 1000.0), Some(4000.0));
        // Pure axial load beyond the last row: Y = 1.00.
        assert_eq!(set.equivalent_load(0.0, 50_000.0), Some(50_000.0));
        // 15°: the same column, X = 0.44; below the first row, its values.
        let set15 = BallSet {
            contact_angle: 15f64.to_radians(),
            ..set
        };
        assert_eq!(set15.equivalent_load(0.0, 10.0), Some(1.47 * 10.0));
    }

    #[test]
    fn life() {
        assert_eq!(basic_rating_life(2000.0, 1000.0), 8.0);
        // Large balls use the D_w^1.4 branch: continuous within 1 % at 25.4 mm.
        let below = dynamic_load_rating(25.39e-3, 150e-3, 12, 0.0).unwrap();
        let above = dynamic_load_rating(25.41e-3, 150e-3, 12, 0.0).unwrap();
        assert!((above / below - 1.0).abs() < 0.01, "{below} {above}");
    }
}
