//! Kalker's linear-theory creep coefficients C₁₁, C₂₂, C₂₃ of an elliptic
//! contact (J. J. Kalker, *Three-dimensional elastic bodies in rolling
//! contact*, Kluwer 1990, Table E.3; the same table is in E. A. H.
//! Vollebregt's open CONTACT code, `linrol` in `m_hertz.f90`). The values
//! are `data/kalker_creep_coefficients.csv` (a unit test checks the copy
//! below against it).
//!
//! a is the semi-axis **along** the rolling direction, b the lateral one,
//! g = min(a/b, b/a). Linear theory (Kalker's frame):
//! ```text
//! F_x = −G c² C₁₁ ξ,   F_y = −G c² (C₂₂ η + c C₂₃ φ),   c = √(ab)
//! ```
//! Interpolation, as CONTACT does: linear in g at each tabulated ν, then a
//! parabola in ν through 1/C at ν = 0, 0.25, 0.5 (1/C is nearly linear in
//! ν). For a ≤ b and g < 0.1, Kalker's asymptotes
//! ```text
//! C₁₁ = π²/(4(1 − ν)),  C₂₂ = π²/4,  C₂₃ = π √g /(3(1 − ν)) [1 + ν (ln(16/g) − 5)]
//! ```
//! joined continuously to the table: C = C_asym(g) + (g/0.1)(C_table(0.1) −
//! C_asym(0.1)). For a > b the table stops at g = 0.1 (a contact 10 times
//! longer in the rolling direction than wide, which a ball bearing never
//! has): [`check_axes`] refuses it, [`creep_coefficients`] holds g at 0.1.
//! ν must lie in [0, 0.5] (the table's range).

use crate::error::InvalidParameter;
use std::f64::consts::PI;

/// Tabulated g = 0.1, 0.2, …, 1.0; per g the rows ν = 0, 0.25, 0.5 of
/// (C₁₁, C₂₂, C₂₃). Case a ≤ b (short axis along the rolling direction).
// Kalker's printed values (3.14 is a table entry, not π).
#[allow(clippy::approx_constant)]
const SHORT_ALONG: [[[f64; 3]; 3]; 10] = [
    [
        [2.51, 2.51, 0.334],
        [3.31, 2.52, 0.473],
        [4.85, 2.53, 0.731],
    ],
    [
        [2.59, 2.59, 0.483],
        [3.37, 2.63, 0.603],
        [4.81, 2.66, 0.809],
    ],
    [[2.68, 2.68, 0.607], [3.44, 2.75, 0.715], [4.8, 2.81, 0.889]],
    [[2.78, 2.78, 0.72], [3.53, 2.88, 0.823], [4.82, 2.98, 0.977]],
    [[2.88, 2.88, 0.827], [3.62, 3.01, 0.929], [4.83, 3.14, 1.07]],
    [[2.98, 2.98, 0.93], [3.72, 3.14, 1.03], [4.91, 3.31, 1.18]],
    [[3.09, 3.09, 1.03], [3.81, 3.28, 1.14], [4.97, 3.48, 1.29]],
    [[3.19, 3.19, 1.13], [3.91, 3.41, 1.25], [5.05, 3.65, 1.4]],
    [[3.29, 3.29, 1.23], [4.01, 3.54, 1.36], [5.12, 3.82, 1.51]],
    [[3.4, 3.4, 1.33], [4.12, 3.67, 1.47], [5.2, 3.98, 1.63]],
];

/// As [`SHORT_ALONG`], case a > b (long axis along the rolling direction).
const LONG_ALONG: [[[f64; 3]; 3]; 10] = [
    [[10.7, 10.7, 12.2], [11.7, 12.8, 14.6], [12.9, 16.0, 18.0]],
    [[6.96, 6.96, 5.72], [7.78, 8.14, 6.63], [8.82, 9.79, 7.89]],
    [[5.57, 5.57, 3.79], [6.34, 6.4, 4.32], [7.34, 7.51, 5.01]],
    [[4.84, 4.84, 2.88], [5.57, 5.48, 3.24], [6.57, 6.31, 3.7]],
    [[4.37, 4.37, 2.35], [5.1, 4.9, 2.62], [6.11, 5.56, 2.96]],
    [[4.06, 4.06, 2.01], [4.78, 4.5, 2.23], [5.8, 5.04, 2.5]],
    [[3.82, 3.82, 1.76], [4.54, 4.21, 1.95], [5.58, 4.67, 2.18]],
    [[3.65, 3.65, 1.58], [4.36, 3.99, 1.75], [5.42, 4.39, 1.94]],
    [[3.51, 3.51, 1.44], [4.22, 3.81, 1.59], [5.3, 4.16, 1.77]],
    [[3.4, 3.4, 1.33], [4.12, 3.67, 1.47], [5.2, 3.98, 1.63]],
];

/// Kalker's creep coefficients of one contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CreepCoefficients {
    /// Longitudinal C₁₁.
    pub longitudinal: f64,
    /// Lateral C₂₂.
    pub lateral: f64,
    /// Lateral force from spin C₂₃.
    pub spin_lateral: f64,
}

/// Checks that Kalker's table covers a contact with semi-axis `along` the
/// rolling direction and `across` it \[m\], and Poisson's ratio ν.
pub fn check_axes(along: f64, across: f64, poisson_ratio: f64) -> Result<(), InvalidParameter> {
    crate::error::require_positive("semi_axis_along", along)?;
    crate::error::require_positive("semi_axis_across", across)?;
    check_poisson_ratio(poisson_ratio)?;
    if along > across && across / along < 0.1 {
        return Err(InvalidParameter::new(
            "semi_axis_along",
            along,
            format!(
                "Kalker's table needs the semi-axis along the rolling direction ≤ 10 × the lateral one ({across})"
            ),
        ));
    }
    Ok(())
}

/// Checks 0 ≤ ν ≤ 0.5, the range of Kalker's table.
pub fn check_poisson_ratio(poisson_ratio: f64) -> Result<(), InvalidParameter> {
    if (0.0..=0.5).contains(&poisson_ratio) {
        Ok(())
    } else {
        Err(InvalidParameter::new(
            "poisson_ratio",
            poisson_ratio,
            "Kalker's creep coefficients are tabulated for 0 ≤ ν ≤ 0.5",
        ))
    }
}

/// C₁₁, C₂₂, C₂₃ for semi-axes `along` and `across` the rolling direction
/// \[m\] and Poisson's ratio ν (module doc: interpolation and off-table
/// rules; ν is clamped to [0, 0.5]). Continuous in its inputs.
pub fn creep_coefficients(along: f64, across: f64, poisson_ratio: f64) -> CreepCoefficients {
    let nu = poisson_ratio.clamp(0.0, 0.5);
    let c = if along <= across {
        let g = along / across;
        if g >= 0.1 {
            table(&SHORT_ALONG, g, nu)
        } else {
            let asym = |g: f64| asymptote(g, nu);
            let at = table(&SHORT_ALONG, 0.1, nu);
            let edge = asym(0.1);
            let low = asym(g.max(0.0));
            let w = g / 0.1;
            [
                low[0] + w * (at[0] - edge[0]),
                low[1] + w * (at[1] - edge[1]),
                low[2] + w * (at[2] - edge[2]),
            ]
        }
    } else {
        table(&LONG_ALONG, (across / along).max(0.1), nu)
    };
    CreepCoefficients {
        longitudinal: c[0],
        lateral: c[1],
        spin_lateral: c[2],
    }
}

/// Kalker's asymptotes for a ≪ b.
fn asymptote(g: f64, nu: f64) -> [f64; 3] {
    let c23 = if g > 0.0 {
        PI * g.sqrt() / (3.0 * (1.0 - nu)) * (1.0 + nu * ((16.0 / g).ln() - 5.0))
    } else {
        0.0
    };
    [PI * PI / (4.0 * (1.0 - nu)), PI * PI / 4.0, c23]
}

/// Linear in g (0.1 ≤ g ≤ 1), parabola in ν on 1/C.
fn table(t: &[[[f64; 3]; 3]; 10], g: f64, nu: f64) -> [f64; 3] {
    let s = ((g - 0.1) / 0.1).clamp(0.0, 9.0);
    let i = (s.floor() as usize).min(8);
    let w = s - i as f64;
    // Lagrange weights through ν = 0, 0.25, 0.5.
    let (n0, n1, n2) = (0.0, 0.25, 0.5);
    let l = [
        (nu - n1) * (nu - n2) / ((n0 - n1) * (n0 - n2)),
        (nu - n0) * (nu - n2) / ((n1 - n0) * (n1 - n2)),
        (nu - n0) * (nu - n1) / ((n2 - n0) * (n2 - n1)),
    ];
    let mut out = [0.0; 3];
    for (k, o) in out.iter_mut().enumerate() {
        let mut inv = 0.0;
        for (row, lr) in l.iter().enumerate() {
            let c = (1.0 - w) * t[i][row][k] + w * t[i + 1][row][k];
            inv += lr / c;
        }
        *o = 1.0 / inv;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn embedded_table_matches_the_data_file() {
        let csv = include_str!("../../data/kalker_creep_coefficients.csv");
        let mut n = 0;
        for line in csv
            .lines()
            .filter(|l| !l.starts_with('#') && !l.starts_with("case"))
        {
            let f: Vec<&str> = line.split(',').collect();
            let g: f64 = f[1].parse().unwrap();
            let nu: f64 = f[2].parse().unwrap();
            let t = if f[0] == "a<=b" {
                &SHORT_ALONG
            } else {
                &LONG_ALONG
            };
            let gi = (g * 10.0).round() as usize - 1;
            let ni = (nu * 4.0).round() as usize;
            for k in 0..3 {
                let v: f64 = f[3 + k].parse().unwrap();
                assert_eq!(t[gi][ni][k], v, "{line}");
            }
            n += 1;
        }
        assert_eq!(n, 60);
    }

    #[test]
    fn reproduces_table_nodes_and_is_continuous() {
        // At nodes the interpolation returns the table.
        let c = creep_coefficients(0.3, 1.0, 0.25);
        assert!((c.longitudinal - 3.44).abs() < 1e-12);
        assert!((c.spin_lateral - 0.715).abs() < 1e-12);
        let c = creep_coefficients(1.0, 0.5, 0.5);
        assert!((c.lateral - 5.56).abs() < 1e-12);
        // Continuous across g = 0.1 and across a = b.
        for nu in [0.0, 0.3, 0.5] {
            let below = creep_coefficients(0.1 - 1e-9, 1.0, nu);
            let above = creep_coefficients(0.1 + 1e-9, 1.0, nu);
            assert!((below.spin_lateral - above.spin_lateral).abs() < 1e-6);
            let short = creep_coefficients(1.0 - 1e-9, 1.0, nu);
            let long = creep_coefficients(1.0, 1.0 - 1e-9, nu);
            assert!((short.lateral - long.lateral).abs() < 1e-6);
        }
    }

    #[test]
    fn slender_limit_is_kalkers_asymptote() {
        // g → 0: C₁₁ → π²/(4(1−ν)), C₂₂ → π²/4, C₂₃ → 0.
        let nu = 0.3;
        let c = creep_coefficients(1e-6, 1.0, nu);
        assert!((c.longitudinal / (PI * PI / (4.0 * (1.0 - nu))) - 1.0).abs() < 1e-4);
        assert!((c.lateral / (PI * PI / 4.0) - 1.0).abs() < 1e-4);
        assert!(c.spin_lateral < 0.01);
        // At g = 0.1 the asymptote is already within ~10 % of the table.
        let a = asymptote(0.1, 0.25);
        assert!((a[0] / 3.31 - 1.0).abs() < 0.01, "{a:?}");
    }

    #[test]
    fn off_table_axes_and_poisson_ratio_are_refused() {
        assert!(check_axes(1.0, 0.05, 0.3).is_err());
        assert!(check_axes(0.05, 1.0, 0.3).is_ok());
        let e = check_axes(0.5, 1.0, 0.6).unwrap_err();
        assert_eq!(e.field, "poisson_ratio");
        assert!(check_poisson_ratio(-0.1).is_err());
    }
}
