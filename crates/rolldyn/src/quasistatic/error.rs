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
    /// The traction-consistent solve ([`crate::dynamics::traction_equilibrium`]) did not
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
    /// Along the branch the solver follows, the balls cannot carry the
    /// axial load on their loaded flank at this radial load and speed (with
    /// the tilt free under combined load, or at speed under inner control):
    /// the axial reaction has a minimum short of zero. Another branch may
    /// still exist (inner control of the 7218B has two near 6 600 rpm). The
    /// axial load
    /// the bearing needs is at least `least_axial_load`
    /// ([`super::equilibrium`]'s axial-displacement search found the
    /// smallest reaction at a minimum that does not reach zero).
    #[error(
        "no equilibrium found at {speed_rpm:.0} rpm: along the solution branch this load needs an axial load of at least {} N at this radial load and speed (F_x = {axial_load} N given; below it the balls run over towards the groove's other flank); raise the axial load, under combined load hold the tilt (--fix-tilt), or reach the point by a sweep (another branch may exist)",
        significant(*.least_axial_load)
    )]
    AxialLoadTooSmall {
        /// The axial load given \[N\].
        axial_load: f64,
        /// The smallest axial load with an equilibrium on the loaded
        /// flank (the minimum of the reaction found; an estimate) \[N\].
        least_axial_load: f64,
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

/// `value` to four significant digits, fixed-point from 0.01 up (a
/// least axial load of 3e-5 N printed as "0.0000" reads as none).
fn significant(value: f64) -> String {
    if value == 0.0 || value.abs() >= 0.01 {
        format!("{value:.4}")
    } else {
        format!("{value:.3e}")
    }
}
