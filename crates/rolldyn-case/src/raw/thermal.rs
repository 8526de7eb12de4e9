//! `[power]` and `[thermal]`: friction power loss and the thermal network
//! (Lei et al. 2023; docs/model.md §10) as written.

use crate::units::*;
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Harris's local power-loss method (`rolldyn power`, `rolldyn thermal`).
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawPower {
    /// Sliding friction coefficient f_s of the raceway contacts under full
    /// sliding (spin, differential sliding). Default: the traction model's
    /// full-sliding value (Coulomb μ, EHL limiting shear coefficient,
    /// traction-curve asymptote D, FASTSIM μ).
    pub sliding_friction: Option<f64>,
}

/// Thermal network of the bearing (`rolldyn thermal`); every key has a
/// documented default (docs/thermal.md).
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RawThermal {
    /// Ambient air temperature (default 20 °C).
    pub ambient_temperature: Option<Quantity<Temperature>>,
    /// Oil inlet temperature (default: `lubricant.temperature`, else ambient).
    pub oil_inlet_temperature: Option<Quantity<Temperature>>,
    /// Oil supply flow (default: `lubricant.oil_flow`, else none).
    pub oil_flow: Option<Quantity<VolumeFlow>>,
    /// Housing outside diameter (default 1.6 × the bearing's outside diameter).
    pub housing_diameter: Option<Quantity<Length>>,
    /// Housing width (default 2 × the bearing width).
    pub housing_width: Option<Quantity<Length>>,
    /// Shaft length in air on each side of the bearing (default the bearing width).
    pub shaft_length: Option<Quantity<Length>>,
    /// Housing-to-air convection coefficient (default 15 W/(m²K)).
    pub housing_convection: Option<Quantity<HeatTransferCoefficient>>,
    /// Shaft-to-air convection coefficient (default 15 W/(m²K)).
    pub shaft_convection: Option<Quantity<HeatTransferCoefficient>>,
    /// Balls and rings to oil (default: flat-plate correlation at the cage's surface speed).
    pub oil_convection: Option<Quantity<HeatTransferCoefficient>>,
    /// Ring and shaft conductivity (default 43 W/(m·K), bearing steel).
    pub ring_conductivity: Option<Quantity<ThermalConductivity>>,
    /// Ball conductivity (default 43 W/(m·K); 30 for silicon nitride balls).
    pub ball_conductivity: Option<Quantity<ThermalConductivity>>,
    /// Housing conductivity (default 43 W/(m·K)).
    pub housing_conductivity: Option<Quantity<ThermalConductivity>>,
    /// Ring specific heat (default 458 J/(kg·K)).
    pub ring_specific_heat: Option<Quantity<SpecificHeat>>,
    /// Ball specific heat (default 458 J/(kg·K); 690 for silicon nitride).
    pub ball_specific_heat: Option<Quantity<SpecificHeat>>,
    /// Ring expansion coefficient (default 11.9e-6 1/K, AISI 52100).
    pub ring_expansion: Option<Quantity<ThermalExpansion>>,
    /// Ball expansion coefficient (default 11.9e-6 1/K; 3.2e-6 for silicon nitride).
    pub ball_expansion: Option<Quantity<ThermalExpansion>>,
    /// Shaft expansion coefficient of a bearing set's thermal preload
    /// (default: the ring's).
    pub shaft_expansion: Option<Quantity<ThermalExpansion>>,
    /// Housing expansion coefficient of a bearing set's thermal preload
    /// (default: the ring's; cast iron ~10.5e-6, aluminium ~23e-6 1/K).
    pub housing_expansion: Option<Quantity<ThermalExpansion>>,
    /// Temperature at which the geometry is given (default 20 °C).
    pub reference_temperature: Option<Quantity<Temperature>>,
    /// Couple the network to `rolldyn run` (default false): it starts at
    /// the quasi-static thermal steady state and is advanced every
    /// `update_interval`, feeding the oil viscosity back.
    pub run_coupling: Option<bool>,
    /// Update interval of the run coupling (default 1 ms).
    pub update_interval: Option<Quantity<Time>>,
    /// Where the coupled network starts: "steady_state" (default: the
    /// quasi-static coupled steady state) or "ambient" (every part at the
    /// ambient temperature: a warm-up from cold).
    pub run_start: Option<RawThermalStart>,
}

/// Initial temperatures of a coupled run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum RawThermalStart {
    /// The quasi-static coupled steady state (`rolldyn thermal`).
    SteadyState,
    /// Every part at the ambient temperature, the oil supply at its own.
    Ambient,
}
