//! Viscosity–temperature law of a mineral or synthetic oil (docs/model.md §10):
//! Walther's equation as standardised in ASTM D341,
//! ```text
//! log₁₀ log₁₀(ν + 0.7) = A − B log₁₀ T          (ν in mm²/s, T in K)
//! ```
//! fitted through two points (T₁, ν₁), (T₂, ν₂). Dynamic viscosity
//! η = ρ ν with a constant density (its change with temperature, ~0.06 %/K,
//! is neglected).

use crate::error::InvalidParameter;

/// Walther (ASTM D341) law through two points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Walther {
    a: f64,
    b: f64,
    density: f64,
}

impl Walther {
    /// Through dynamic viscosities `eta1` at `t1` and `eta2` at `t2`
    /// \[Pa·s, K\], with `density` \[kg/m³\].
    pub fn through(
        (t1, eta1): (f64, f64),
        (t2, eta2): (f64, f64),
        density: f64,
    ) -> Result<Self, InvalidParameter> {
        if !(t1 > 0.0 && t2 > 0.0 && t1 != t2) {
            return Err(InvalidParameter::new(
                "temperature",
                t2,
                "the two viscosity points need different temperatures above 0 K",
            ));
        }
        if !(eta1 > 0.0 && eta2 > 0.0 && density > 0.0) {
            return Err(InvalidParameter::new(
                "viscosity",
                eta2,
                "viscosities and density must be positive",
            ));
        }
        let w = |eta: f64| (eta / density * 1e6 + 0.7).log10().log10();
        let (w1, w2) = (w(eta1), w(eta2));
        if ((w1 - w2) * (t1 - t2)) >= 0.0 {
            return Err(InvalidParameter::new(
                "viscosity",
                eta2,
                "viscosity must fall as temperature rises",
            ));
        }
        let b = (w1 - w2) / (t2.log10() - t1.log10());
        Ok(Self {
            a: w1 + b * t1.log10(),
            b,
            density,
        })
    }

    /// Kinematic viscosity at temperature `t` \[m²/s\].
    pub fn kinematic(&self, t: f64) -> f64 {
        (10f64.powf(10f64.powf(self.a - self.b * t.log10())) - 0.7) * 1e-6
    }

    /// Dynamic viscosity at temperature `t` \[Pa·s\].
    pub fn dynamic(&self, t: f64) -> f64 {
        self.density * self.kinematic(t)
    }

    /// Temperature–viscosity coefficient β_T = −d ln η/dT at `t` \[1/K\]:
    /// with Y = log₁₀(ν + 0.7) (ν in mm²/s), β_T = B Y (ν + 0.7) ln 10 / (T ν).
    pub fn temperature_coefficient(&self, t: f64) -> f64 {
        let nu = self.kinematic(t) * 1e6;
        let y = (nu + 0.7).log10();
        self.b * y * (nu + 0.7) * std::f64::consts::LN_10 / (t * nu)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An ISO VG 32 oil (32 and 5.4 mm²/s at 40 and 100 °C, 860 kg/m³):
    /// the law passes through both points, falls with temperature, and its
    /// 70 °C value lies between them and below their geometric mean (the
    /// log-log law is convex in T).
    #[test]
    fn walther_through_two_points() {
        let rho = 860.0;
        let w = Walther::through((313.15, 32e-6 * rho), (373.15, 5.4e-6 * rho), rho).unwrap();
        assert!((w.kinematic(313.15) / 32e-6 - 1.0).abs() < 1e-12);
        assert!((w.kinematic(373.15) / 5.4e-6 - 1.0).abs() < 1e-12);
        let mid = w.kinematic(343.15);
        assert!(mid < (32e-6f64 * 5.4e-6).sqrt() && mid > 5.4e-6, "{mid}");
        assert!(Walther::through((313.15, 1e-3), (373.15, 2e-3), rho).is_err());
        assert!(Walther::through((313.15, 1e-3), (313.15, 2e-3), rho).is_err());
        // β_T against the logarithmic derivative.
        let dt = 1e-3;
        let slope = -(w.dynamic(343.15 + dt) / w.dynamic(343.15 - dt)).ln() / (2.0 * dt);
        assert!((w.temperature_coefficient(343.15) / slope - 1.0).abs() < 1e-6);
    }
}
