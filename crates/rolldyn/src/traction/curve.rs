//! Traction curve (Lei et al. 2023 eq 18; docs/model.md §3, model 2), Gupta's
//! four-parameter form:
//! ```text
//! μ(S) = (A + B S) e^{−C S} + D,     τ = −c_r(|v|) max(μ(S), 0) p v/|v|
//! ```
//! S is the slide-to-roll ratio |v|/|u| (v: local slip, u: entrainment
//! speed of the contact) or the slip speed |v| in m/s, as the user states;
//! A..D are per lubricant (user coefficients; with S in m/s, B and C are
//! in s/m). The ramp c_r = min(|v|/v₁, 1) (v₁ = `full_speed`) makes the
//! stress continuous at zero slip when μ(0) = A + D ≠ 0, as stiff
//! integrators need; μ is floored at 0 so the law cannot drive a contact.
//! Below an entrainment speed of v₁ the slide-to-roll ratio is taken
//! against v₁ (S stays finite at rest).
//!
//! Lei et al. 2023 eq 19 fits A..D for FVA-M oil as power laws of a
//! dimensionless load, speed and temperature that the paper does not
//! define; rolldyn ships no preset from it (docs/model.md §3).

use super::{ContactConditions, TractionLaw};
use crate::error::{InvalidParameter, require_positive};

use serde::{Deserialize, Serialize};

/// What the traction curve's S is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum SlipMeasure {
    /// Slide-to-roll ratio |v|/|u| \[-\].
    #[default]
    SlideToRoll,
    /// Slip speed |v| \[m/s\].
    SlipSpeed,
}

/// Parameters of the traction curve μ(S) = (A + B S) e^{−C S} + D.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TractionCurve {
    /// A \[-\].
    pub a: f64,
    /// B \[1/unit of S\].
    pub b: f64,
    /// C \[1/unit of S\], ≥ 0.
    pub c: f64,
    /// D \[-\] (the high-slip asymptote).
    pub d: f64,
    /// What S is.
    pub slip: SlipMeasure,
    /// Slip speed of full traction v₁ \[m/s\] (regularisation; default 1 mm/s).
    pub full_speed: f64,
}

/// Largest traction coefficient the curve may reach (as the friction of
/// the other laws).
const MAX_COEFFICIENT: f64 = 5.0;

impl TractionCurve {
    /// Checks the parameters: finite, C ≥ 0, and μ(S) ≤ 5 for every S ≥ 0.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        for (field, v) in [("a", self.a), ("b", self.b), ("d", self.d)] {
            if !v.is_finite() {
                return Err(InvalidParameter::new(field, v, "must be finite"));
            }
        }
        if !(self.c.is_finite() && self.c >= 0.0) {
            return Err(InvalidParameter::new(
                "c",
                self.c,
                "must not be negative (the curve must stay bounded)",
            ));
        }
        require_positive("full_speed", self.full_speed)?;
        let (largest, field) = self.largest_coefficient();
        if largest > MAX_COEFFICIENT {
            let value = match field {
                "a" => self.a,
                "b" => self.b,
                _ => self.d,
            };
            return Err(InvalidParameter::new(
                field,
                value,
                format!(
                    "the curve reaches mu = {largest:.3e}; a traction coefficient above {MAX_COEFFICIENT} is not a physical friction (the other laws bound mu to [0, 5])"
                ),
            ));
        }
        Ok(())
    }

    /// The supremum of μ(S) over S ≥ 0 and the parameter that sets it:
    /// μ(0) = A + D, the stationary point S* = 1/C − A/B of (A + BS)e^{−CS}
    /// when it lies at S* > 0, and the asymptote D (C > 0) or a line
    /// growing without bound (C = 0, B > 0).
    fn largest_coefficient(&self) -> (f64, &'static str) {
        let Self { a, b, c, d, .. } = *self;
        if c == 0.0 {
            return if b > 0.0 {
                (f64::INFINITY, "b")
            } else {
                (a + d, "a")
            };
        }
        let mut largest = if a + d >= d { (a + d, "a") } else { (d, "d") };
        if b != 0.0 {
            let stationary = 1.0 / c - a / b;
            if stationary > 0.0 {
                let peak = (a + b * stationary) * (-c * stationary).exp() + d;
                if peak > largest.0 {
                    largest = (peak, "b");
                }
            }
        }
        if d > MAX_COEFFICIENT {
            largest.1 = "d";
        }
        largest
    }

    /// Traction coefficient μ(S), floored at 0.
    #[inline]
    pub fn coefficient(&self, s: f64) -> f64 {
        ((self.a + self.b * s) * (-self.c * s).exp() + self.d).max(0.0)
    }
}

impl TractionLaw for TractionCurve {
    /// g = ramp(|v|) μ(S) p / |v|.
    #[inline]
    fn stress_ratio(
        &self,
        pressure: f64,
        _term: f64,
        speed: f64,
        conditions: &ContactConditions,
    ) -> f64 {
        if speed == 0.0 || pressure <= 0.0 {
            return 0.0;
        }
        let s = match self.slip {
            SlipMeasure::SlideToRoll => speed / conditions.entrainment_speed.max(self.full_speed),
            SlipMeasure::SlipSpeed => speed,
        };
        let ramp = (speed / self.full_speed).min(1.0);
        ramp * self.coefficient(s) * pressure / speed
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    fn curve() -> TractionCurve {
        // A rising-then-falling curve: peak μ near S = 1/C − A/B.
        TractionCurve {
            a: -0.06,
            b: 8.0,
            c: 60.0,
            d: 0.06,
            slip: SlipMeasure::SlideToRoll,
            full_speed: 1e-3,
        }
    }

    #[test]
    fn the_largest_coefficient_is_found_and_bounded() {
        // Seed curve: peak at S* = 1/60 + 0.06/8, checked against a scan.
        let c = curve();
        let scanned = (0..200_000)
            .map(|k| c.coefficient(k as f64 * 1e-5))
            .fold(0.0, f64::max);
        let (peak, field) = c.largest_coefficient();
        assert!((peak - scanned).abs() < 1e-9, "{peak} {scanned}");
        assert_eq!(field, "b");
        assert!(c.validate().is_ok());
        // d = 1e9 was accepted once, and the run never left t = 0.
        for (bad, field) in [
            (TractionCurve { d: 1e9, ..c }, "d"),
            (TractionCurve { b: 1e6, ..c }, "b"),
            (TractionCurve { a: 6.0, ..c }, "a"),
            (TractionCurve { c: 0.0, ..c }, "b"),
        ] {
            let e = bad.validate().unwrap_err();
            assert_eq!(e.field, field, "{bad:?}: {e}");
        }
        // A falling line (C = 0, B < 0) is bounded by A + D.
        assert!(
            TractionCurve {
                c: 0.0,
                b: -1.0,
                ..c
            }
            .validate()
            .is_ok()
        );
    }

    #[test]
    fn stress_is_mu_of_slide_to_roll_times_pressure() {
        let c = curve();
        let cond = ContactConditions {
            film: 0.0,
            entrainment_speed: 10.0,
            ..Default::default()
        };
        // S = 0.2/10 = 0.02: μ = (−0.06 + 0.16) e^{−1.2} + 0.06.
        let tau = c.shear_stress(1e9, &Vector3::new(0.2, 0.0, 0.0), &cond);
        let mu = 0.1 * (-1.2f64).exp() + 0.06;
        assert!((-tau.x / 1e9 - mu).abs() < 1e-12);
        // Zero at zero slip (A + D = 0), D at large slip.
        assert!(c.coefficient(0.0).abs() < 1e-15);
        assert!((c.coefficient(10.0) - 0.06).abs() < 1e-12);
    }

    #[test]
    fn continuous_at_zero_slip_and_floored() {
        let mut c = curve();
        c.a = 0.0; // μ(0) = D ≠ 0: the ramp takes over.
        let cond = ContactConditions::default();
        let tiny = c.shear_stress(1e9, &Vector3::new(1e-9, 0.0, 0.0), &cond);
        assert!(tiny.norm() < 1e-4 * 1e9 * 0.06);
        c.d = -1.0;
        assert_eq!(c.coefficient(5.0), 0.0);
        assert!(c.validate().is_ok());
        c.c = -1.0;
        assert!(c.validate().is_err());
    }
}
