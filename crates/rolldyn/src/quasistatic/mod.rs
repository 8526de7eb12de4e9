//! Quasi-static solvers (MODEL §7): the static load distribution of a
//! bearing under combined loads and, built on the same contact evaluation,
//! the high-speed Jones–Harris equilibrium.
//!
//! Every ball contact comes from the exact torus geometry of MODEL §2.1
//! ([`ring_contact`]), with analytic derivatives, so Newton's method and
//! the stiffness matrix (by the implicit-function theorem) use an exact
//! Jacobian.

pub mod ring_contact;
pub mod static_load;

pub use static_load::{BallLoad, StaticOptions, StaticSolution, StaticSolveError, StaticSolver};
