//! Ball–raceway contact (docs/model.md §2.1–§2.3).
//!
//! Data flow: [`torus`] finds where a ball touches a raceway for arbitrary
//! ring poses (penetration, normal, contact point, contact angle);
//! [`hertz`] turns a contact angle into Hertz constants (ellipticity,
//! semi-axes, stiffness) by the exact elliptic-integral solve or an
//! approximation; [`table`] precomputes those constants per raceway so no
//! elliptic integral is solved in a time loop; [`normal_law`] turns
//! penetration and its rate into a normal force.

pub mod hertz;
pub mod normal_law;
pub mod table;
pub mod torus;

pub use hertz::{Curvature, HertzCoefficients, HertzModel, HertzResult};
pub use normal_law::{ContactEpisode, NormalForceLaw, NormalLaw};
pub use table::{ContactTable, RacewayContactModel};
pub use torus::{GrooveCircle, RingPose, TorusContact};
