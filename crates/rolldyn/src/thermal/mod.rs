//! Temperatures of a running bearing (Lei et al. 2023 §4; docs/model.md §10).
//!
//! * [`network`] — a lumped thermal network: nodes, conductances, heat
//!   sources, fixed temperatures; steady state by a direct solve, transient
//!   by the trapezoidal rule;
//! * [`resistance`] — the thermal resistances of a bearing: conduction
//!   through rings as cylinders, the moving-heat-source resistance of a
//!   Hertz contact, convection (correlations with user overrides), oil
//!   advection;
//! * [`bearing`] — Lei et al. 2023's network of a bearing (ball, inner- and
//!   outer-race contacts, rings, shaft, housing, oil, ambient, oil inlet);
//! * [`viscosity`] — the Walther (ASTM D341) viscosity–temperature law;
//! * [`coupled`] — temperatures fed back (viscosity, thermal expansion of
//!   the clearance) in a quasi-static iteration to thermal steady state;
//! * [`set`] — the same for the bearings of a shaft system, with the
//!   shaft's axial growth against the housing's: thermal preload growth.
//!
//! docs/thermal.md is the user guide.

pub mod bearing;
pub mod coupled;
pub mod network;
pub mod resistance;
pub mod set;
pub mod viscosity;

pub use bearing::{BearingThermal, HeatSources, ThermalInputs, ThermalSolution};
pub use network::{NodeId, ThermalNetwork};
pub use viscosity::Walther;
