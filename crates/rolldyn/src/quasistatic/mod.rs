//! Quasi-static solvers (docs/model.md §7): the static load distribution of a
//! bearing under combined loads and the high-speed Jones–Harris
//! equilibrium, one set of equations ([`equilibrium`]). The
//! traction-consistent equilibrium of the dynamic model's force elements,
//! without raceway control, is [`crate::dynamics::traction_equilibrium`].
//!
//! Every ball contact comes from the exact torus geometry of docs/model.md §2.1
//! ([`ring_contact`]), with analytic derivatives, so Newton's method and
//! the stiffness matrix (implicit-function theorem) use an exact Jacobian.
//! [`sweep()`](sweep::sweep) solves lists and grids of operating points in parallel,
//! warm-started, deterministically. [`films`]: the lubricant films of a
//! solution (starved, Λ, K_oil), from the contact motion of
//! [`contact_motion`]; [`modes`]: natural frequencies and mode
//! shapes of the supported inner ring on the bearing stiffness;
//! [`stiffness`]: compliance and the conventional scalar stiffnesses.
//! [`system`]: bearing sets and several bearings on a rigid shaft, with
//! preload and lift-off; [`elastic_shaft`]: the same on an
//! Euler–Bernoulli shaft, whose bending misaligns the bearings
//! (docs/systems.md).

pub mod contact_motion;
pub mod elastic_shaft;
pub mod equilibrium;
pub mod error;
pub mod films;
pub mod modes;
pub mod ring_contact;
pub mod stiffness;
pub mod sweep;
pub mod system;

pub use equilibrium::{
    BallSolution, Conditions, ContactSolution, Equilibrium, QuasiStaticError, QuasiStaticSolver,
    RacewayControl, SolverOptions,
};
pub use sweep::sweep;
