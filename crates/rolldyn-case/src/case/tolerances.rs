//! Fits by tolerance class: the interference of an ISO 286 shaft or
//! housing tolerance class on a bearing ring of ISO 492 normal tolerance
//! class (docs/quasistatic.md, "Fits").
//!
//! ISO 286-1 gives the standard tolerance grades IT5–IT8 and the
//! fundamental deviations of each letter by nominal diameter step; ISO
//! 286-2 tabulates the classes. Shafts: g (es), h (es = 0), js (± IT/2), j
//! (tabulated), k, m, n, p (ei). Housings: G (EI = −es of g), H (EI = 0),
//! JS, and K, M, N (grades ≤ 8) and P (grades ≤ 7) by ISO 286-1's rule
//! ES = −ei + Δ, Δ = IT_n − IT_(n−1). The ring's mean diameter of ISO 492
//! normal class lies between its nominal size and the tabulated lower
//! deviation. The diametral interference then ranges from
//! `shaft lower − ring upper` to `shaft upper − ring lower` (and for the
//! housing `ring lower − hole upper` to `ring upper − hole lower`); the
//! fit takes the middle of that range, the probable interference, and a
//! middle at or below zero as a loose fit (no interference).

/// Upper limits (inclusive) of the ISO 286 nominal diameter steps \[mm\]
/// from 3 mm.
const STEPS: [f64; 9] = [6.0, 10.0, 18.0, 30.0, 50.0, 80.0, 120.0, 180.0, 250.0];

/// Standard tolerance grades IT5, IT6, IT7, IT8 per step \[µm\].
const IT: [[f64; 9]; 4] = [
    [5.0, 6.0, 8.0, 9.0, 11.0, 13.0, 15.0, 18.0, 20.0],
    [8.0, 9.0, 11.0, 13.0, 16.0, 19.0, 22.0, 25.0, 29.0],
    [12.0, 15.0, 18.0, 21.0, 25.0, 30.0, 35.0, 40.0, 46.0],
    [18.0, 22.0, 27.0, 33.0, 39.0, 46.0, 54.0, 63.0, 72.0],
];

/// Fundamental deviations of shafts per step \[µm\]: g (upper), k, m, n, p
/// (lower; k for grades 4–7).
const G_UPPER: [f64; 9] = [-4.0, -5.0, -6.0, -7.0, -9.0, -10.0, -12.0, -14.0, -15.0];
const K_LOWER: [f64; 9] = [1.0, 1.0, 1.0, 2.0, 2.0, 2.0, 3.0, 3.0, 4.0];
const M_LOWER: [f64; 9] = [4.0, 6.0, 7.0, 8.0, 9.0, 11.0, 13.0, 15.0, 17.0];
const N_LOWER: [f64; 9] = [8.0, 10.0, 12.0, 15.0, 17.0, 20.0, 23.0, 27.0, 31.0];
const P_LOWER: [f64; 9] = [12.0, 15.0, 18.0, 22.0, 26.0, 32.0, 37.0, 43.0, 50.0];

/// j5 and j6 shafts (lower, upper) per step \[µm\] (ISO 286-2).
const J5: [(f64, f64); 9] = [
    (-2.0, 3.0),
    (-2.0, 4.0),
    (-3.0, 5.0),
    (-4.0, 5.0),
    (-5.0, 6.0),
    (-7.0, 6.0),
    (-9.0, 6.0),
    (-11.0, 7.0),
    (-13.0, 7.0),
];
const J6: [(f64, f64); 9] = [
    (-2.0, 6.0),
    (-2.0, 7.0),
    (-3.0, 8.0),
    (-4.0, 9.0),
    (-5.0, 11.0),
    (-7.0, 12.0),
    (-9.0, 13.0),
    (-11.0, 14.0),
    (-13.0, 16.0),
];

/// ISO 492 normal class: lower deviation of the inner ring's mean bore
/// (bore over, up to and including \[mm\], deviation \[µm\]; upper 0).
const BORE_LOWER: [(f64, f64, f64); 7] = [
    (2.5, 10.0, -8.0),
    (10.0, 18.0, -8.0),
    (18.0, 30.0, -10.0),
    (30.0, 50.0, -12.0),
    (50.0, 80.0, -15.0),
    (80.0, 120.0, -20.0),
    (120.0, 180.0, -25.0),
];

/// ISO 492 normal class: lower deviation of the outer ring's mean outside
/// diameter (upper 0).
const OUTSIDE_LOWER: [(f64, f64, f64); 8] = [
    (6.0, 18.0, -8.0),
    (18.0, 30.0, -9.0),
    (30.0, 50.0, -11.0),
    (50.0, 80.0, -13.0),
    (80.0, 120.0, -15.0),
    (120.0, 150.0, -18.0),
    (150.0, 180.0, -25.0),
    (180.0, 250.0, -30.0),
];

/// The interference of a fit by tolerance class \[m\], diametral.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ClassFit {
    /// The tolerance class, as given (e.g. "k5", "H7").
    pub class: String,
    /// Smallest interference (negative: a clearance) \[m\].
    pub interference_min_m: f64,
    /// Largest interference \[m\].
    pub interference_max_m: f64,
    /// The interference the model uses: the middle of the range, or 0
    /// when it is a clearance \[m\].
    pub interference_used_m: f64,
}

fn step(diameter_mm: f64) -> Result<usize, String> {
    if !(3.0..=250.0).contains(&diameter_mm) || diameter_mm == 3.0 {
        return Err(format!(
            "the {diameter_mm} mm diameter is outside the tabulated steps (over 3 up to 250 mm)"
        ));
    }
    Ok(STEPS
        .iter()
        .position(|&upto| diameter_mm <= upto)
        .unwrap_or(STEPS.len() - 1))
}

/// Splits "k5" into its letters and grade; the grade must be 5–8.
fn parse(class: &str) -> Result<(String, usize), String> {
    let letters: String = class
        .chars()
        .take_while(|c| c.is_ascii_alphabetic())
        .collect();
    let grade: usize = class[letters.len()..]
        .parse()
        .map_err(|_| "expected a letter and a grade, e.g. k5 or H7".to_string())?;
    if !(5..=8).contains(&grade) {
        return Err(format!("grade {grade}: the table holds IT5 to IT8"));
    }
    Ok((letters, grade))
}

/// Lower and upper deviation \[µm\] of shaft class `class` at diameter
/// `d_mm`.
pub fn shaft_deviations(class: &str, d_mm: f64) -> Result<(f64, f64), String> {
    let (letters, grade) = parse(class)?;
    let k = step(d_mm)?;
    let it = IT[grade - 5][k];
    let from_lower = |ei: f64| Ok((ei, ei + it));
    match (letters.as_str(), grade) {
        ("g", _) => Ok((G_UPPER[k] - it, G_UPPER[k])),
        ("h", _) => Ok((-it, 0.0)),
        ("js", _) => Ok((-0.5 * it, 0.5 * it)),
        ("j", 5) => Ok(J5[k]),
        ("j", 6) => Ok(J6[k]),
        ("k", 5..=7) => from_lower(K_LOWER[k]),
        ("m", _) => from_lower(M_LOWER[k]),
        ("n", _) => from_lower(N_LOWER[k]),
        ("p", _) => from_lower(P_LOWER[k]),
        _ => Err(
            "not a tabulated shaft class: g, h, js (5-8), j (5, 6), k (5-7), m, n, p (5-8), lower case"
                .into(),
        ),
    }
}

/// Lower and upper deviation \[µm\] of housing class `class` at diameter
/// `d_mm`.
pub fn housing_deviations(class: &str, d_mm: f64) -> Result<(f64, f64), String> {
    let (letters, grade) = parse(class)?;
    let k = step(d_mm)?;
    let it = IT[grade - 5][k];
    // Δ = IT_n − IT_(n−1) (ISO 286-1), for K, M, N, P.
    let delta = if grade > 5 {
        it - IT[grade - 6][k]
    } else {
        0.0
    };
    let from_upper = |es: f64| Ok((es - it, es));
    match (letters.as_str(), grade) {
        ("G", _) => Ok((-G_UPPER[k], -G_UPPER[k] + it)),
        ("H", _) => Ok((0.0, it)),
        ("JS", _) => Ok((-0.5 * it, 0.5 * it)),
        ("K", 6..=8) => from_upper(-K_LOWER[k] + delta),
        ("M", 6..=8) => from_upper(-M_LOWER[k] + delta),
        ("N", 6..=8) => from_upper(-N_LOWER[k] + delta),
        ("P", 6..=7) => from_upper(-P_LOWER[k] + delta),
        _ => Err(
            "not a tabulated housing class: G, H, JS (5-8), K, M, N (6-8), P (6, 7), upper case"
                .into(),
        ),
    }
}

fn ring_lower(table: &[(f64, f64, f64)], d_mm: f64, what: &str) -> Result<f64, String> {
    table
        .iter()
        .find(|(over, upto, _)| d_mm > *over && d_mm <= *upto)
        .map(|row| row.2)
        .ok_or_else(|| {
            format!(
                "the bearing's {d_mm} mm {what} is outside ISO 492's rows ({} to {} mm)",
                table[0].0,
                table[table.len() - 1].1
            )
        })
}

fn fit(class: &str, min_um: f64, max_um: f64) -> ClassFit {
    let middle = 0.5 * (min_um + max_um);
    ClassFit {
        class: class.to_string(),
        interference_min_m: min_um * 1e-6,
        interference_max_m: max_um * 1e-6,
        interference_used_m: middle.max(0.0) * 1e-6,
    }
}

/// The inner ring (bore `bore` \[m\]) on a shaft of class `class`.
pub fn shaft_fit(class: &str, bore: f64) -> Result<ClassFit, String> {
    let d = bore * 1e3;
    let (lower, upper) = shaft_deviations(class, d)?;
    let ring = ring_lower(&BORE_LOWER, d, "bore")?;
    Ok(fit(class, lower, upper - ring))
}

/// The outer ring (outside diameter `outside` \[m\]) in a housing of class
/// `class`.
pub fn housing_fit(class: &str, outside: f64) -> Result<ClassFit, String> {
    let d = outside * 1e3;
    let (lower, upper) = housing_deviations(class, d)?;
    let ring = ring_lower(&OUTSIDE_LOWER, d, "outside diameter")?;
    Ok(fit(class, ring - upper, -lower))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// ISO 286-2 table values for the classes bearing catalogues list.
    #[test]
    fn classes_match_iso_286_2() {
        for (class, d, expect) in [
            ("k5", 25.0, (2.0, 11.0)),
            ("k6", 40.0, (2.0, 18.0)),
            ("m5", 60.0, (11.0, 24.0)),
            ("m6", 100.0, (13.0, 35.0)),
            ("n6", 45.0, (17.0, 33.0)),
            ("p6", 70.0, (32.0, 51.0)),
            ("j5", 30.0, (-4.0, 5.0)),
            ("js6", 50.0, (-8.0, 8.0)),
            ("h6", 20.0, (-13.0, 0.0)),
            ("g6", 35.0, (-25.0, -9.0)),
        ] {
            assert_eq!(shaft_deviations(class, d).unwrap(), expect, "{class} {d}");
        }
        for (class, d, expect) in [
            ("H7", 52.0, (0.0, 30.0)),
            ("K7", 47.0, (-18.0, 7.0)),
            ("M7", 47.0, (-25.0, 0.0)),
            ("N7", 47.0, (-33.0, -8.0)),
            ("P7", 47.0, (-42.0, -17.0)),
            ("K6", 47.0, (-13.0, 3.0)),
            ("M7", 90.0, (-35.0, 0.0)),
            ("N7", 150.0, (-52.0, -12.0)),
            ("G7", 62.0, (10.0, 40.0)),
            ("JS7", 72.0, (-15.0, 15.0)),
        ] {
            assert_eq!(housing_deviations(class, d).unwrap(), expect, "{class} {d}");
        }
    }

    /// A 6205 (bore 25 mm, −10/0 µm; outside 52 mm, −13/0 µm) on k5 and in
    /// M7: 2 … 21 µm on the shaft, −13 … +30 µm in the housing.
    #[test]
    fn interference_ranges() {
        let s = shaft_fit("k5", 25e-3).unwrap();
        assert!((s.interference_min_m - 2e-6).abs() < 1e-12);
        assert!((s.interference_max_m - 21e-6).abs() < 1e-12);
        assert!((s.interference_used_m - 11.5e-6).abs() < 1e-12);
        let h = housing_fit("M7", 52e-3).unwrap();
        assert!((h.interference_min_m + 13e-6).abs() < 1e-12);
        assert!((h.interference_max_m - 30e-6).abs() < 1e-12);
        let loose = housing_fit("H7", 52e-3).unwrap();
        assert_eq!(loose.interference_used_m, 0.0);
        assert!(loose.interference_max_m <= 0.0);
    }

    #[test]
    fn bad_classes_name_the_rule() {
        assert!(
            shaft_deviations("K5", 25.0)
                .unwrap_err()
                .contains("shaft class")
        );
        assert!(
            shaft_deviations("k9", 25.0)
                .unwrap_err()
                .contains("IT5 to IT8")
        );
        assert!(
            housing_deviations("P8", 52.0)
                .unwrap_err()
                .contains("housing class")
        );
        assert!(shaft_fit("k5", 200e-3).unwrap_err().contains("ISO 492"));
        assert!(shaft_deviations("k5", 300.0).unwrap_err().contains("250"));
    }
}
