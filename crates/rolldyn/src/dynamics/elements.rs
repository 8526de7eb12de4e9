//! What the force elements evaluate: the bearing's geometry, the contact
//! tables of both raceways, the ball's mass and inertia and the model's
//! parameters (docs/model.md §1, §2). Fixed during a run, except the oil
//! viscosities a coupled thermal network sets. The force elements
//! (`race_contact`, `film`, `mixed`, `surface_contact`, `pocket`) are
//! methods of [`Elements`] taking the bodies' motion (`motion`) and
//! returning their share; `model` assembles them into the equations of
//! motion.

use super::layout::StateLayout;
use super::parameters::DynamicsParameters;
use crate::contact::{ContactTable, HertzModel, RacewayContactModel};
use crate::error::{InvalidParameter, require_non_negative, require_positive};
use crate::geometry::{BearingGeometry, RingKind};
use crate::lubrication::Supply;
use crate::material::{Material, effective_modulus};
use crate::traction::{TractionGrid, TractionModel};

/// The bearing as the force elements see it.
#[derive(Debug, Clone)]
pub struct Elements {
    pub(super) geometry: BearingGeometry,
    pub(super) inner_table: ContactTable,
    pub(super) outer_table: ContactTable,
    pub(super) ball_mass: f64,
    pub(super) ball_inertia: f64,
    pub(super) effective_modulus: f64,
    pub(super) params: DynamicsParameters,
    pub(super) layout: StateLayout,
    /// The traction grid of `params.traction_integration`, prepared.
    pub(super) traction_grid: TractionGrid,
}

impl Elements {
    /// Checks the parameters and builds the contact tables, ball mass and
    /// inertia.
    pub fn new(
        geometry: &BearingGeometry,
        ball: &Material,
        rings: &Material,
        hertz: HertzModel,
        params: DynamicsParameters,
    ) -> Result<Self, InvalidParameter> {
        require_positive("inner_ring_mass", params.inner_ring_mass)?;
        require_positive("inner_ring_tilt_inertia", params.inner_ring_tilt_inertia)?;
        params.cage.validate()?;
        if let Some(squeeze) = &params.cage.pocket_squeeze {
            // Built here, not at the first force evaluation in the time loop.
            squeeze.build_tables(params.cage.pocket_shape);
        }
        params.normal_law.validate()?;
        require_positive("impact_speed_floor", params.impact_speed_floor)?;
        params.traction.validate()?;
        params.inner_support.validate("inner_ring_support")?;
        if let Some(seals) = &params.seals {
            seals.validate()?;
        }
        if let Some(rolling) = &params.rolling_resistance {
            rolling.validate()?;
        }
        if let Some(churning) = &params.churning {
            churning.validate()?;
        }
        if let Some(outer) = &params.outer_ring {
            require_positive("outer_ring_mass", outer.mass)?;
            outer.housing.validate("outer_ring_housing")?;
        }
        require_non_negative("rolling_hysteresis", params.rolling_hysteresis)?;
        params.surface.validate(geometry.ball_count)?;
        for supply in &params.film_supply {
            supply.validate()?;
        }
        if params.film_in_approach {
            if params.traction.lubricant().is_none() {
                return Err(InvalidParameter::new(
                    "film_in_approach",
                    "true",
                    "needs a film model: a traction law with a lubricant (ehl)",
                ));
            }
            for supply in &params.film_supply {
                if let Supply::Flow { flow, .. } = supply {
                    return Err(InvalidParameter::new(
                        "oil_flow",
                        *flow,
                        "the film in the normal approach needs a flooded supply or an inlet distance ratio",
                    ));
                }
            }
        }
        if let Some(unbalance) = &params.unbalance {
            unbalance.validate()?;
        }
        if let Some(ring) = &params.sliding_outer_ring {
            ring.validate()?;
            if params.film_in_approach {
                return Err(InvalidParameter::new(
                    "film_in_approach",
                    "true",
                    "is not available with a sliding outer ring yet",
                ));
            }
        }
        if let Some(drive) = &params.drive {
            drive.validate()?;
            if params.film_in_approach {
                return Err(InvalidParameter::new(
                    "film_in_approach",
                    "true",
                    "is not available with a torque-driven ring yet (the films' power would miss the ring's speed change)",
                ));
            }
            if let crate::operating::SpeedProfile::PiecewiseLinear(_) = params.speed {
                return Err(InvalidParameter::new(
                    "speed_profile",
                    "given",
                    "a torque-driven ring's speed is the run's outcome: give its speed at the start as a constant speed",
                ));
            }
        }
        if let Some(mixed) = &params.mixed_lubrication {
            super::parameters::validate_mixed_lubrication(mixed, &params)?;
        }
        let ep = effective_modulus(ball, rings);
        let ball_mass = geometry.ball_mass(ball.density);
        Ok(Self {
            inner_table: ContactTable::new(RacewayContactModel::new(
                geometry,
                RingKind::Inner,
                ep,
                hertz,
            ))?,
            outer_table: ContactTable::new(RacewayContactModel::new(
                geometry,
                RingKind::Outer,
                ep,
                hertz,
            ))?,
            ball_mass,
            ball_inertia: ball_mass * geometry.ball_diameter.powi(2) / 10.0,
            effective_modulus: ep,
            layout: StateLayout {
                balls: geometry.ball_count,
                ball_spin_angle: params.surface.has_ball_surfaces(),
                film_work: params.film_in_approach,
                driven: params.drive.is_some(),
                sliding: params.sliding_outer_ring.is_some(),
            },
            traction_grid: TractionGrid::new(params.traction_integration),
            geometry: geometry.clone(),
            params,
        })
    }

    /// η₀ of the EHL traction and the rolling resistance, and of the guide
    /// land, the pocket squeeze film and the churning (the oil node's), if
    /// `viscosities` (contact inlet, oil) \[Pa·s\].
    pub(super) fn apply_viscosities(&mut self, viscosities: Option<(f64, f64)>) {
        let Some((contact, land)) = viscosities else {
            return;
        };
        if let TractionModel::Ehl(ehl) = &mut self.params.traction {
            ehl.lubricant.viscosity = contact;
        }
        if let Some(guide) = &mut self.params.cage.guide {
            guide.viscosity = land;
        }
        if let Some(squeeze) = &mut self.params.cage.pocket_squeeze {
            squeeze.viscosity = land;
        }
        if let Some(rolling) = &mut self.params.rolling_resistance {
            rolling.lubricant.viscosity = contact;
        }
        if let Some(churning) = &mut self.params.churning {
            churning.viscosity = land;
        }
    }
}
