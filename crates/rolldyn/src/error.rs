//! Errors of the core library. Each names the field, the value and the
//! rule, so the case-file layer can point at the offending key.

/// A parameter that violates a physical or geometric rule.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{field} = {value}: {rule}")]
pub struct InvalidParameter {
    /// Name of the parameter as it appears in case files (snake_case).
    pub field: &'static str,
    /// The offending value, formatted in SI units.
    pub value: String,
    /// The rule that was broken, as a sentence fragment.
    pub rule: String,
}

impl InvalidParameter {
    /// Builds the error from a field name, a displayable value and a rule.
    pub fn new(
        field: &'static str,
        value: impl std::fmt::Display,
        rule: impl Into<String>,
    ) -> Self {
        Self {
            field,
            value: value.to_string(),
            rule: rule.into(),
        }
    }
}

/// `Ok` when `value` is finite and > 0, else the error "must be positive".
pub fn require_positive(field: &'static str, value: f64) -> Result<(), InvalidParameter> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(InvalidParameter::new(field, value, "must be positive"))
    }
}

/// `Ok` when `value` is finite and ≥ 0, else the error "must not be negative".
pub fn require_non_negative(field: &'static str, value: f64) -> Result<(), InvalidParameter> {
    if value.is_finite() && value >= 0.0 {
        Ok(())
    } else {
        Err(InvalidParameter::new(field, value, "must not be negative"))
    }
}
