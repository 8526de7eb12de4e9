//! The dynamic bearing model (docs/model.md §1, §2.3, §3, §5, §8, §10): balls with
//! 6 degrees of freedom, an inner ring with 5 (its spin prescribed), an
//! outer ring fixed or on a housing spring–damper, and a cage with planar
//! whirl and rotation, as an [`crate::integrate::OdeSystem`].
//!
//! Contacts: exact torus geometry with any normal force law and
//! contact-episode memory; traction integrated over the Hertz ellipse
//! ([`crate::traction`]); rolling resistance by hysteresis; cage pockets,
//! guide land and unbalance ([`crate::cage`]); ball and cage drag; gravity;
//! planar mode; the energy bookkeeping of docs/model.md §10. docs/dynamics.md is
//! the user guide. One file per force element or concern:
//!
//! | file | what |
//! |---|---|
//! | `model` | the equations of motion: assembles the force elements' shares for the balls, rings and cage; the run's memory (contact episodes, thermal network) |
//! | `elements` | what the force elements evaluate: geometry, contact tables, masses, parameters |
//! | `motion` | state → the bodies' motion (ball and ring kinematics), which the force elements take |
//! | `layout` | offsets in the state vector |
//! | `ball_pass` | the balls' contacts evaluated serially or across threads, summed in ball order |
//! | `coupling` | what a ball's contacts pass to the rings, cage and energy accumulators |
//! | `race_contact` | ball–raceway normal force, traction, hysteresis |
//! | `film` | the contacts' steady films, and the film in the normal approach |
//! | `pocket` | ball–pocket contact |
//! | `supports` | ring spring–dampers |
//! | `surface_contact` | waviness and spalls in the contacts, spall step limit |
//! | `energy` | mechanical energy, work and dissipation; the balance at a step's end from the right-hand side's pass |
//! | `end_point` | what that pass keeps per ball for the step's acceptance (energy shares, raceway records) |
//! | `outputs` | per-contact output samples, pure-rolling reference |
//! | `thermal_coupling` | the thermal network advanced alongside a run, oil viscosity fed back |
//! | `traction_equilibrium` | the traction-consistent steady state the runs start from (no raceway control) |
//! | `checkpoint` | the model's memory (contact episodes, thermal network) in a run's checkpoint |
//! | `shaft` | several bearing models on one rigid shaft sharing its five degrees of freedom, with an unbalance (docs/systems.md, "Dynamics") |

mod ball_equations;
mod ball_pass;
mod block_split;
mod border;
pub mod checkpoint;
mod coupling;
pub mod elements;
mod end_point;
pub mod energy;
pub mod film;
pub mod layout;
mod mixed;
pub mod model;
pub mod motion;
pub mod outputs;
pub mod parameters;
pub mod peaks;
pub mod pocket;
pub mod race_contact;
mod sensor_coupling;
pub mod shaft;
pub mod spall_growth;
pub mod supports;
pub mod surface_contact;
pub mod thermal_coupling;
pub mod traction_equilibrium;

pub use crate::cage::{CageParameters, GuideLand, PocketLaw, PocketShape};
pub use crate::lubrication::drag::DragParameters;
pub use crate::seals::SealFriction;
pub use energy::Energy;
pub use layout::StateLayout;
pub use model::BearingModel;
pub use parameters::DynamicsParameters;
pub use race_contact::{ContactOutput, ContactSample, HYSTERESIS_RAMP_SPEED};
pub use supports::{OuterRing, SlidingRing, Support};
pub use thermal_coupling::ThermalCoupling;
pub use traction_equilibrium::{
    TractionEquilibrium, TractionSolveOptions, solve_traction_consistent,
};
