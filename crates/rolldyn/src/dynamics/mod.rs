//! The dynamic bearing model (MODEL §1, §2.3, §3, §5, §8, §10): balls with
//! 6 degrees of freedom, an inner ring with 5 (its spin prescribed), an
//! outer ring fixed or on a housing spring–damper, and a cage with planar
//! whirl and rotation, as an [`crate::integrate::OdeSystem`].
//!
//! Contacts: exact torus geometry with any normal force law and
//! contact-episode memory; traction integrated over the Hertz ellipse
//! ([`crate::traction`]); rolling resistance by hysteresis; cage pockets,
//! guide land and unbalance ([`crate::cage`]); ball and cage drag; gravity;
//! planar mode; the energy bookkeeping of MODEL §10. docs/dynamics.md is
//! the user guide.

pub mod model;

pub use crate::cage::{CageParameters, GuideLand, PocketLaw, PocketShape};
pub use model::{
    BearingModel, ContactOutput, ContactSample, DragParameters, DynamicsParameters, Energy,
    OuterRing, StateLayout, Support,
};
