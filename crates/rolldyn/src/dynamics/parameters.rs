//! The dynamic model's parameters ([`DynamicsParameters`]): everything it
//! needs besides the bearing geometry and the materials, with
//! [`DynamicsParameters::new`] setting all but the inner ring's inertia and
//! the cage to documented defaults (docs/dynamics.md).

use super::supports::{OuterRing, SlidingRing, Support};
use crate::cage::CageParameters;
use crate::contact::NormalForceLaw;
use crate::error::InvalidParameter;
use crate::geometry::RingKind;
use crate::lubrication::drag::DragParameters;
use crate::operating::{LoadProfile, RingUnbalance, SpeedProfile, TorqueDrive};
use crate::seals::SealFriction;
use crate::surface::SurfaceModel;
use crate::traction::TractionModel;
use crate::traction::ellipse::TractionIntegration;
use crate::traction::mixed::MixedLubrication;

/// Everything the dynamic model needs besides geometry and materials.
#[derive(Debug, Clone, PartialEq)]
pub struct DynamicsParameters {
    /// Inner-ring (with shaft) mass m_i \[kg\].
    pub inner_ring_mass: f64,
    /// Inner-ring transverse moment of inertia I_t \[kg·m²\].
    pub inner_ring_tilt_inertia: f64,
    /// Cage.
    pub cage: CageParameters,
    /// Normal force law of the ball–raceway contacts.
    pub normal_law: NormalForceLaw,
    /// Impact-speed floor v_floor \[m/s\].
    pub impact_speed_floor: f64,
    /// Traction model of the ball–raceway contacts.
    pub traction: TractionModel,
    /// How traction is integrated over each contact ellipse.
    pub traction_integration: TractionIntegration,
    /// Inner-ring speed profile (with a `drive`, the speed at t = 0).
    pub speed: SpeedProfile,
    /// A torque driving the inner ring, whose speed is then a state of the
    /// run (None: the speed follows `speed`).
    pub drive: Option<TorqueDrive>,
    /// Loads on the inner ring (constant or tabulated in time).
    pub loads: LoadProfile,
    /// A rotating unbalance on the inner ring (None: none).
    pub unbalance: Option<RingUnbalance>,
    /// Spring–damper between the inner ring and ground (zero: free).
    pub inner_support: Support,
    /// Outer ring on a housing spring–damper (None: fixed).
    pub outer_ring: Option<OuterRing>,
    /// An outer ring sliding axially in its bore against friction (a
    /// floating bearing's; None: held axially).
    pub sliding_outer_ring: Option<SlidingRing>,
    /// Elastic-hysteresis coefficient α_h of the rolling resistance
    /// (0: off; ≈ 0.007 for steel, Lei et al. 2023 eq 21).
    pub rolling_hysteresis: f64,
    /// Gravitational acceleration along −z \[m/s²\] (0: off).
    pub gravity: f64,
    /// Planar mode (Shan et al. 2023): axial coordinates, tilts and the ball spin
    /// components other than ω_x frozen.
    pub planar: bool,
    /// The inner ring's tilts θ_y, θ_z held at zero: the ring sits on a
    /// shaft that its other bearing holds in tilt (`operating.fixed_tilt`;
    /// docs/dynamics.md, "Mounting").
    pub inner_ring_tilt_held: bool,
    /// Drag of the air–oil mixture.
    pub drag: DragParameters,
    /// Raceway and ball surfaces: waviness and spalls (default: smooth).
    pub surface: SurfaceModel,
    /// Oil supply of the inner and outer raceway contacts (starvation of
    /// the EHL film, docs/model.md §4; default: fully flooded).
    pub film_supply: [crate::lubrication::Supply; 2],
    /// The lubricant film in the normal approach (docs/model.md §4): δ_el = δ + h(Q)
    /// with the steady central film h (`dynamics::film`). Needs a film
    /// model (EHL traction) and a flooded or inlet-distance supply.
    pub film_in_approach: bool,
    /// Mixed lubrication (docs/model.md §3, model 5): boundary friction on the
    /// asperities' share of each contact's load, from the film parameter
    /// Λ = h_min/σ (`lubrication::mixed`). Needs a film model (EHL
    /// traction) and the raceways' and balls' roughness (`surface`).
    pub mixed_lubrication: Option<crate::traction::mixed::MixedLubrication>,
    /// Friction of contact seals on the inner ring (None: an open bearing).
    pub seals: Option<SealFriction>,
    /// EHL rolling resistance of the lubricated ball–raceway contacts
    /// (None: dry contacts; `lubrication::rolling_resistance`).
    pub rolling_resistance: Option<crate::lubrication::rolling_resistance::RollingResistance>,
    /// Churning of an oil bath or jet on the inner ring (None: neither;
    /// `lubrication::churning`).
    pub churning: Option<crate::lubrication::churning::Churning>,
}

impl DynamicsParameters {
    /// Whether the inner ring's state `k` (0–4: x, y, z, θ_y, θ_z; 5–9
    /// their rates) is frozen: the axial coordinate and the tilts in planar
    /// mode, the tilts when they are held.
    pub fn inner_ring_state_frozen(&self, k: usize) -> bool {
        (self.planar && matches!(k, 0 | 3 | 4 | 5 | 8 | 9))
            || (self.inner_ring_tilt_held && matches!(k, 3 | 4 | 8 | 9))
    }

    /// The parameters of a bearing whose inner ring (with what turns with
    /// it) has mass `inner_ring_mass` \[kg\] and transverse moment of
    /// inertia `inner_ring_tilt_inertia` \[kg·m²\], with `cage`; the rest at
    /// its default: Hertz contacts (impact-speed floor 1 mm/s), no traction
    /// (integrated on the default 12 × 6 grid when one is set), at rest
    /// (speed prescribed) without loads, a free inner ring and a fixed outer ring, no
    /// hysteresis, gravity or drag, 3-D, smooth surfaces, flooded films
    /// not in the normal approach, no mixed lubrication, no seals, no rolling
    /// resistance or churning. Change the rest
    /// with struct update syntax, so that a new parameter needs only its
    /// default here:
    /// `DynamicsParameters { traction, ..DynamicsParameters::new(0.5, 1e-4, cage) }`.
    pub fn new(inner_ring_mass: f64, inner_ring_tilt_inertia: f64, cage: CageParameters) -> Self {
        Self {
            inner_ring_mass,
            inner_ring_tilt_inertia,
            cage,
            normal_law: NormalForceLaw::Hertz,
            impact_speed_floor: crate::contact::normal_law::DEFAULT_IMPACT_SPEED_FLOOR,
            traction: TractionModel::None,
            traction_integration: TractionIntegration::default(),
            speed: SpeedProfile::Constant(0.0),
            drive: None,
            loads: LoadProfile::Constant(crate::operating::Loads::default()),
            unbalance: None,
            inner_support: Support::default(),
            outer_ring: None,
            sliding_outer_ring: None,
            rolling_hysteresis: 0.0,
            gravity: 0.0,
            planar: false,
            inner_ring_tilt_held: false,
            drag: DragParameters::default(),
            surface: SurfaceModel::default(),
            film_supply: Default::default(),
            film_in_approach: false,
            mixed_lubrication: None,
            seals: None,
            rolling_resistance: None,
            churning: None,
        }
    }
}

/// Checks that mixed lubrication has what it needs: its parameters, a film
/// model (EHL traction) and a roughness at both raceways' contacts.
pub(super) fn validate_mixed_lubrication(
    mixed: &MixedLubrication,
    params: &DynamicsParameters,
) -> Result<(), InvalidParameter> {
    mixed.validate()?;
    if !matches!(params.traction, TractionModel::Ehl(_)) {
        return Err(InvalidParameter::new(
            "mixed_lubrication",
            "given",
            "needs a film and a fluid traction law to blend with: traction law ehl (with a lubricant)",
        ));
    }
    for ring in [RingKind::Inner, RingKind::Outer] {
        if params.surface.composite_roughness(ring) <= 0.0 {
            return Err(InvalidParameter::new(
                "roughness",
                0.0,
                format!(
                    "mixed lubrication needs the film parameter Λ = h_min/σ: give the {} raceway's or the balls' RMS roughness",
                    match ring {
                        RingKind::Inner => "inner",
                        RingKind::Outer => "outer",
                    }
                ),
            ));
        }
    }
    Ok(())
}
