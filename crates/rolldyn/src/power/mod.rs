//! Power loss: where a bearing turns work into heat (docs/model.md §10).
//!
//! * [`dissipation`] — the dynamic model's exact dissipation split by force
//!   element and mechanism (the energy balance's dissipated power, per
//!   component).
//!
//! docs/power.md is the user guide.

pub mod dissipation;
pub mod harris;

pub use dissipation::{ContactLosses, Dissipation};
pub use harris::{LocalMethodInputs, LocalPowerLoss, RaceLosses, local_power_loss};
