//! Small systems with known solutions for the integrators' tests.

use super::OdeSystem;

/// y' = −y: y = y₀ e^(−t).
pub struct Decay;

impl OdeSystem for Decay {
    fn dimension(&self) -> usize {
        1
    }
    fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
        dy[0] = -y[0];
    }
}

/// x'' = −x as (x, x'): a unit circle in the phase plane, period 2π.
pub struct UnitOscillator;

impl OdeSystem for UnitOscillator {
    fn dimension(&self) -> usize {
        2
    }
    fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
        dy[0] = y[1];
        dy[1] = -y[0];
    }
}
