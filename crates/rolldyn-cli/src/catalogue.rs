//! `rolldyn catalogue` and `rolldyn new --bearing`: catalogue bearings
//! with estimated internal geometry (docs/catalogue.md), their case text
//! and a table of their ball sets and ratings.

use crate::Failure;
use rolldyn_case::catalogue::{BearingKind, CatalogueBearing, CatalogueError};
use serde::Serialize;

/// One row of `rolldyn catalogue --json` (units in the key names).
#[derive(Debug, Clone, Serialize)]
pub struct CatalogueEntry {
    /// Designation, e.g. "6205" or "7210B".
    pub designation: String,
    /// "deep_groove" or "angular_contact".
    pub kind: BearingKind,
    /// Bore d (ISO 15).
    pub bore_mm: f64,
    /// Outside diameter D (ISO 15).
    pub outside_diameter_mm: f64,
    /// Width B (ISO 15).
    pub width_mm: f64,
    /// Estimated ball diameter D_w.
    pub ball_diameter_mm: f64,
    /// Estimated number of balls Z.
    pub ball_count: usize,
    /// Estimated pitch diameter d_m.
    pub pitch_diameter_mm: f64,
    /// Free contact angle of an angular-contact bearing (null for
    /// deep-groove bearings).
    pub contact_angle_deg: Option<f64>,
    /// ISO 5753-1 group CN range [min, max] of a deep-groove bearing.
    pub clearance_cn_um: Option<[f64; 2]>,
    /// ISO 281 C_r of the estimated ball set.
    pub dynamic_load_rating_n: f64,
    /// ISO 76 C_0r of the estimated geometry.
    pub static_load_rating_n: f64,
    /// C_r a manufacturer lists for its own ball set, where known.
    pub published_dynamic_load_rating_n: Option<f64>,
    /// C_0r a manufacturer lists, where known.
    pub published_static_load_rating_n: Option<f64>,
}

fn failure(e: CatalogueError) -> Failure {
    let flag = match e {
        CatalogueError::Designation { .. } => "--bearing",
        CatalogueError::Clearance { .. } => "--clearance",
    };
    Failure::BadInput(format!("argument {flag}: {e}"))
}

/// The case text of `rolldyn new --bearing DESIGNATION [--clearance GROUP]`.
pub fn case_text(designation: &str, clearance: Option<&str>) -> Result<String, Failure> {
    let bearing = CatalogueBearing::lookup(designation, clearance).map_err(failure)?;
    bearing
        .case_text()
        .map_err(|e| Failure::Model(format!("{}: {e}", bearing.designation)))
}

/// Catalogue rows, all or of one series ("62", "72", …).
pub fn entries(series: Option<&str>) -> Result<Vec<CatalogueEntry>, Failure> {
    const SERIES: [&str; 6] = ["60", "62", "63", "70", "72", "73"];
    if let Some(s) = series
        && !SERIES.contains(&s)
    {
        return Err(Failure::BadInput(format!(
            "series {s:?}: not a catalogue series: 60, 62, 63, 70, 72 or 73"
        )));
    }
    CatalogueBearing::all()
        .into_iter()
        .filter(|b| series.is_none_or(|s| b.designation.starts_with(s)))
        .map(|b| {
            // Millimetres to six decimals: the tables' values, not their
            // binary neighbours.
            let mm = |x: f64| (x * 1e9).round() * 1e-6;
            let r = b
                .ratings()
                .map_err(|e| Failure::Model(format!("{}: {e}", b.designation)))?;
            Ok(CatalogueEntry {
                designation: b.designation.clone(),
                kind: b.kind,
                bore_mm: mm(b.bore),
                outside_diameter_mm: mm(b.outside_diameter),
                width_mm: mm(b.width),
                ball_diameter_mm: mm(b.ball_diameter),
                ball_count: b.ball_count,
                pitch_diameter_mm: mm(b.pitch_diameter),
                contact_angle_deg: b.contact_angle.map(f64::to_degrees),
                clearance_cn_um: b.clearance_range.map(|(lo, hi)| [lo * 1e6, hi * 1e6]),
                dynamic_load_rating_n: r.dynamic,
                static_load_rating_n: r.r#static,
                published_dynamic_load_rating_n: r.published_dynamic,
                published_static_load_rating_n: r.published_static,
            })
        })
        .collect()
}

/// The text table of `rolldyn catalogue`.
pub fn table(list: &[CatalogueEntry]) -> String {
    let mut t = String::from(
        "catalogue bearings: ISO 15 boundary dimensions; ball set estimated (docs/catalogue.md)\n\
         designation  d x D x B [mm]        balls  D_w [mm]  d_m [mm]  angle  C_r [kN]  C_0r [kN]  listed C_r, C_0r [kN]\n",
    );
    for e in list {
        let size = format!("{} x {} x {}", e.bore_mm, e.outside_diameter_mm, e.width_mm);
        let angle = e
            .contact_angle_deg
            .map_or("0".to_string(), |a| format!("{a:.0}"));
        let listed = match (
            e.published_dynamic_load_rating_n,
            e.published_static_load_rating_n,
        ) {
            (Some(c), Some(c0)) => format!("{:.2}, {:.2}", c * 1e-3, c0 * 1e-3),
            _ => String::new(),
        };
        t.push_str(&format!(
            "{:<12} {:<21} {:>5}  {:>8.3}  {:>8.2}  {:>5}  {:>8.2}  {:>9.2}  {}\n",
            e.designation,
            size,
            e.ball_count,
            e.ball_diameter_mm,
            e.pitch_diameter_mm,
            angle,
            e.dynamic_load_rating_n * 1e-3,
            e.static_load_rating_n * 1e-3,
            listed
        ));
    }
    t
}
