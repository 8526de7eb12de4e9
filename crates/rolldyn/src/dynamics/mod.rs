//! The dynamic bearing model (MODEL §1, §2.3, §3, §5, §8): balls with 6
//! degrees of freedom, an inner ring with 5 (its spin prescribed), and a
//! cage with planar whirl and rotation, as an [`crate::integrate::OdeSystem`].
//!
//! This release: exact torus contacts with any normal force law and
//! contact-episode memory, traction at the contact centre (modified
//! Coulomb), cylindrical cage pockets with a linear law and Coulomb
//! friction, ball and cage drag, gravity, planar mode, and the energy
//! bookkeeping of MODEL §10.
//! Traction integrated over the ellipse, EHL, guide lands, drag and output
//! recording are the next steps of issue 4 (docs/dynamics.md).

pub mod model;

pub use model::{
    BearingModel, CageParameters, ContactSample, DragParameters, DynamicsParameters, Energy,
    GuideLand, StateLayout,
};
