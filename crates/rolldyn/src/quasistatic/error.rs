//! Why a quasi-static solve failed (Jones–Harris and traction-consistent).

/// Why a quasi-static solve failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum QuasiStaticError {
    /// Newton did not reach the tolerance.
    #[error(
        "no equilibrium found at {speed_rpm:.0} rpm: Newton stopped after {iterations} iterations with a relative residual of {residual:.3e} (from the static solution, by continuation in load and speed); try another raceway control, or reach this point by a sweep from a nearby solved one"
    )]
    NoConvergence {
        /// Iterations done.
        iterations: usize,
        /// Largest relative residual at the end.
        residual: f64,
        /// Speed at which the failure happened \[rpm\].
        speed_rpm: f64,
    },
    /// The traction-consistent solve ([`super::traction_control`]) did not
    /// converge.
    #[error(
        "no traction-consistent equilibrium at {speed_rpm:.0} rpm: Newton stopped after {iterations} iterations with a residual force of {residual:.3e} of the largest contact load (with little friction the balls may have no rolling equilibrium: the gyroscopic moment exceeds what the traction can hold, and the balls pivot)"
    )]
    NoTractionEquilibrium {
        /// Iterations done.
        iterations: usize,
        /// Largest residual force over the largest contact load.
        residual: f64,
        /// Inner-ring speed \[rpm\].
        speed_rpm: f64,
    },
    /// The ring is not held in the load direction.
    #[error("the bearing cannot carry this load: {reason}")]
    Unsupported {
        /// What is missing.
        reason: String,
    },
}
