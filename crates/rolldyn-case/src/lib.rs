//! # rolldyn-case — case files for rolldyn
//!
//! TOML case files with explicit units on every dimensional value, built-in
//! bearing presets, command-line overrides, and validation into a
//! [`Case`] in SI units. Errors name the file, line and column, the key,
//! the value and the rule broken ([`CaseError`]).
//!
//! * [`units`] — "6.35 mm"-style quantities;
//! * [`raw`] — the file's structure (and its JSON Schema);
//! * [`case`] — the validated case and its rules;
//! * [`presets`] — the papers' bearings and common catalogue bearings;
//! * [`catalogue`] — ISO 15 catalogue bearings (60/62/63, 70/72/73) with
//!   estimated internal geometry, as case text;
//! * [`load_case`] — the pipeline text → [`Case`];
//! * [`simulation`] — a case to the engine: dynamic model, start, integrator,
//!   quasi-static, power and thermal analyses.
//!
//! A case from text, with a command-line style override; values are SI
//! once validated, and bad input names the key, the value and the rule:
//! ```
//! use rolldyn_case::{Override, load_case, presets};
//!
//! let text = presets::find("6304").expect("a built-in preset").text;
//! let speed = Override::parse_set("operating.speed=\"3000 rpm\"")?;
//! let case = load_case("6304.toml", text, &[speed])?;
//! assert_eq!(case.bearing.geometry.ball_count, 7);
//! assert!((case.bearing.geometry.ball_diameter - 9.52e-3).abs() < 1e-12);
//! let rpm = case.speed.as_ref().map(|s| s.final_speed() * 60.0 / std::f64::consts::TAU);
//! assert!((rpm.unwrap() - 3000.0).abs() < 1e-9);
//!
//! let typo = Override::parse_set("bearing.ball_diameter=\"9.52 mmm\"")?;
//! let error = load_case("6304.toml", text, &[typo]).unwrap_err();
//! assert!(error.to_string().contains("bearing.ball_diameter"));
//! # Ok::<(), rolldyn_case::CaseError>(())
//! ```

pub mod case;
pub mod catalogue;
pub mod error;
mod load;
pub mod mounting;
pub mod presets;
pub mod raw;
pub mod simulation;
pub mod units;

pub use case::Case;
pub use error::{CaseError, Origin};
pub use load::{Override, OverrideSource, load_case, load_default};

/// The JSON Schema of the case format (for editor completion).
pub fn json_schema() -> serde_json::Value {
    serde_json::to_value(schemars::schema_for!(raw::RawCase)).unwrap_or_default()
}
