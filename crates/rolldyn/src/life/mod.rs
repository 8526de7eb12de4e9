//! Rating life of a bearing (issue 16).
//!
//! * [`iso281`] — basic dynamic load rating C_r from the ball set and the
//!   basic rating life L_10 = (C_r/P_r)³ by ISO 281:2007.
//!
//! Not yet: the modified life with a_ISO (contamination, viscosity ratio
//! κ, fatigue load limit) and ISO/TS 16281's reference rating life from the
//! actual load distribution (docs/quasistatic.md).

pub mod iso281;
