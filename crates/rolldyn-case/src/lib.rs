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
//! * [`load_case`] — the pipeline text → [`Case`].

pub mod case;
pub mod error;
mod load;
pub mod presets;
pub mod raw;
pub mod units;

pub use case::Case;
pub use error::{CaseError, Origin};
pub use load::{Override, OverrideSource, load_case, load_default};

/// The JSON Schema of the case format (for editor completion).
pub fn json_schema() -> serde_json::Value {
    serde_json::to_value(schemars::schema_for!(raw::RawCase)).unwrap_or_default()
}
