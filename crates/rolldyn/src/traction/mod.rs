//! Tangential (traction) stresses at a ball–raceway contact and their
//! integration over the Hertz ellipse (docs/model.md §3).
//!
//! Two kinds of traction model, variants of [`TractionModel`] chosen from
//! the case file, each in its own file:
//! - a **stress law** τ(p, slip, h) (behind [`TractionLaw`]): the shear
//!   stress on the ball at a point of the contact with Hertz pressure p,
//!   local sliding velocity `slip` (ball material relative to ring
//!   material) and film thickness h. [`ellipse`] integrates it over the
//!   contact ellipse on the deformed surface, or evaluates it once at the
//!   centre (Coulomb, traction curve, EHL);
//! - a **contact model** that integrates the ellipse itself: Kalker's
//!   FASTSIM ([`fastsim`], with the creep coefficients of [`kalker`]),
//!   whose tractions depend on the path of the material through the
//!   contact, not on the local slip alone; or Kalker's exact theory
//!   ([`exact`], a reference too slow for the time loop), tabulated over
//!   the normalised creepages for it ([`table`]).
//!
//! [`TractionModel::evaluate`] dispatches one contact to either.

pub mod coulomb;
pub mod curve;
pub mod ehl;
pub mod ellipse;
pub mod exact;
pub mod fastsim;
pub mod kalker;
pub mod mixed;
pub mod table;

pub use coulomb::ModifiedCoulomb;
pub use mixed::MixedLubrication;

/// Largest friction coefficient a case may give (Coulomb laws, FASTSIM,
/// pocket friction): clean metals in vacuum reach a few, lubricated
/// rolling contacts 0.001–0.2; beyond this a value is a slip.
pub const MAX_FRICTION: f64 = 5.0;

/// Checks a friction coefficient: finite, in [0, [`MAX_FRICTION`]].
pub fn require_friction(
    field: &'static str,
    value: f64,
) -> Result<(), crate::error::InvalidParameter> {
    if (0.0..=MAX_FRICTION).contains(&value) {
        Ok(())
    } else {
        Err(crate::error::InvalidParameter::new(
            field,
            value,
            format!("a friction coefficient must lie in [0, {MAX_FRICTION}]"),
        ))
    }
}
pub use curve::{SlipMeasure, TractionCurve};
pub use ehl::EhlRheology;
pub use ellipse::{
    ContactKinematics, ContactPatch, TractionGrid, TractionIntegration, TractionResult,
};
pub use fastsim::{Creep, Fastsim, TractionBound};
use nalgebra::Vector3;
use serde::{Deserialize, Serialize};
pub use table::ExactTable;

/// Contact-level conditions a stress law may need besides the local
/// pressure and slip (one value per contact).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactConditions {
    /// Central film thickness h \[m\] (0 when no film model is active).
    pub film: f64,
    /// Entrainment (rolling) speed |u| at the contact centre \[m/s\] (docs/model.md §3).
    pub entrainment_speed: f64,
    /// Rolling velocity u·e_roll along the patch's rolling direction
    /// \[m/s\], signed (FASTSIM's flow direction).
    pub rolling_velocity: f64,
}

/// A traction stress law whose stress opposes the local slip:
/// τ = −g(p, |v|) v with a ratio g ≥ 0 (every built-in law: Coulomb,
/// traction curve, EHL rheology, and their blend).
pub trait TractionLaw {
    /// What the law needs of a cell's pressure alone (the EHL rheology:
    /// the viscosity η(p)), computed once per distinct pressure of a grid.
    /// Default: nothing (0).
    #[inline]
    fn pressure_term(&self, _pressure: f64) -> f64 {
        0.0
    }

    /// [`Self::pressure_term`] of each of `values` (pressures on entry,
    /// terms on return). A law may override it with a loop the compiler
    /// vectorizes, with the same arithmetic per value. Default: one by one.
    #[inline(always)]
    fn pressure_terms(&self, values: &mut [f64]) {
        for value in values {
            *value = self.pressure_term(*value);
        }
    }

    /// The ratio g = |τ|/|v| ≥ 0 \[Pa·s/m\] at Hertz pressure `pressure`
    /// \[Pa\] (with its [`Self::pressure_term`] `term`) and slip speed
    /// `speed` = |v| \[m/s\], under the contact's `conditions`; 0 where the
    /// law gives no stress (no slip, no pressure, no film).
    fn stress_ratio(
        &self,
        pressure: f64,
        term: f64,
        speed: f64,
        conditions: &ContactConditions,
    ) -> f64;

    /// [`Self::stress_ratio`] of [`BATCH`] cells at once, into `ratios`
    /// (cells the caller leaves empty have pressure and speed 0, and get
    /// 0). A law may override it to evaluate the cells stage by stage
    /// (loops over the lanes that the compiler vectorizes), with the same
    /// arithmetic per cell. Default: cell by cell.
    #[inline(always)]
    fn stress_ratios(
        &self,
        pressures: &Cells,
        terms: &Cells,
        speeds: &Cells,
        conditions: &ContactConditions,
        ratios: &mut Cells,
    ) {
        for (k, out) in ratios.iter_mut().enumerate() {
            *out = self.stress_ratio(pressures[k], terms[k], speeds[k], conditions);
        }
    }

    /// Shear stress on the ball \[Pa\] (tangential vector) at Hertz pressure
    /// `pressure` \[Pa\] and local `slip` \[m/s\] (tangential), under the
    /// contact's `conditions`: −g v.
    #[inline]
    fn shear_stress(
        &self,
        pressure: f64,
        slip: &Vector3<f64>,
        conditions: &ContactConditions,
    ) -> Vector3<f64> {
        let term = self.pressure_term(pressure);
        -self.stress_ratio(pressure, term, slip.norm(), conditions) * slip
    }
}

/// Cells a traction law is handed at once ([`TractionLaw::stress_ratios`]; unused lanes empty).
pub const BATCH: usize = 24;

/// One value per cell of a batch.
pub type Cells = [f64; BATCH];

/// The built-in traction models (case file: `model.traction`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
#[serde(tag = "law", rename_all = "snake_case", deny_unknown_fields)]
pub enum TractionModel {
    /// No tangential stress (frictionless; energy tests).
    #[default]
    None,
    /// Shan et al. 2023 eqs 14–15: τ = −c_d(|v|) μ p v/|v|.
    ModifiedCoulomb(ModifiedCoulomb),
    /// Lei et al. 2023 eq 18: μ(S) = (A + B S) e^{−C S} + D.
    TractionCurve(TractionCurve),
    /// Deng et al. 2022 eqs 13–15: Eyring shear with limiting shear stress.
    Ehl(EhlRheology),
    /// Zhang et al. 2025 §2.2: Kalker's FASTSIM.
    Fastsim(Fastsim),
    /// Kalker's exact theory, tabulated ([`table`]).
    ExactTable(ExactTable),
}

impl TractionModel {
    /// Whether the model needs the film thickness (and so a lubricant).
    pub fn needs_film(&self) -> bool {
        matches!(self, Self::Ehl(_))
    }

    /// The lubricant of the models that use a film (EHL), else None.
    pub fn lubricant(&self) -> Option<&crate::lubrication::Lubricant> {
        match self {
            Self::Ehl(ehl) => Some(&ehl.lubricant),
            _ => None,
        }
    }

    /// Central film thickness h_c \[m\] of a contact for the models that
    /// use one (EHL: Hamrock–Dowson, docs/model.md §4), else 0: entrainment speed
    /// |u| \[m/s\], load Q \[N\], rolling radius R_x \[m\], effective
    /// modulus E' \[Pa\], ellipticity κ.
    pub fn central_film(
        &self,
        entrainment_speed: f64,
        load: f64,
        rolling_radius: f64,
        effective_modulus: f64,
        ellipticity: f64,
    ) -> f64 {
        match self {
            Self::Ehl(ehl) => {
                crate::lubrication::hamrock_dowson(
                    &ehl.lubricant,
                    entrainment_speed,
                    load,
                    rolling_radius,
                    effective_modulus,
                    ellipticity,
                )
                .central
            }
            _ => 0.0,
        }
    }

    /// Whether the stress law uses the entrainment speed.
    pub fn needs_entrainment(&self) -> bool {
        matches!(
            self,
            Self::Ehl(_) | Self::TractionCurve(_) | Self::Fastsim(_) | Self::ExactTable(_)
        )
    }

    /// Whether one contact's traction is integrated over many points
    /// (FASTSIM's own grid, or a stress law on the strip grid), i.e. costs
    /// microseconds rather than nanoseconds.
    pub fn integrates_over_a_grid(&self, integration: &ellipse::TractionIntegration) -> bool {
        match self {
            Self::None | Self::ExactTable(_) => false,
            Self::Fastsim(_) => true,
            _ => !matches!(integration, ellipse::TractionIntegration::Centre),
        }
    }

    /// Traction of one contact in motion `kinematics`: FASTSIM and the
    /// exact table take the ellipse whole, the stress laws are integrated
    /// over `grid` ([`ellipse::integrate`]). Allocation-free.
    pub fn evaluate(
        &self,
        grid: &ellipse::TractionGrid,
        kinematics: &ContactKinematics,
    ) -> TractionResult {
        match self {
            Self::None => TractionResult::default(),
            Self::ModifiedCoulomb(m) => ellipse::integrate(m, grid, kinematics),
            Self::TractionCurve(c) => ellipse::integrate(c, grid, kinematics),
            Self::Ehl(e) => ellipse::integrate(e, grid, kinematics),
            Self::Fastsim(f) => f.evaluate(kinematics),
            Self::ExactTable(t) => t.evaluate(kinematics),
        }
    }

    /// [`Self::evaluate`] in mixed lubrication: the EHL law blended with
    /// `boundary` friction at asperity share φ = `share` ([`mixed`]). The
    /// other models have no film to share the load with (the case refuses
    /// them); for them, and at φ = 0, this is [`Self::evaluate`].
    pub fn evaluate_blended(
        &self,
        boundary: &ModifiedCoulomb,
        share: f64,
        grid: &ellipse::TractionGrid,
        kinematics: &ContactKinematics,
    ) -> TractionResult {
        match self {
            Self::Ehl(fluid) if share > 0.0 => ellipse::integrate(
                &mixed::Blended {
                    fluid,
                    boundary,
                    share,
                },
                grid,
                kinematics,
            ),
            _ => self.evaluate(grid, kinematics),
        }
    }

    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), crate::InvalidParameter> {
        match self {
            Self::None => Ok(()),
            Self::ModifiedCoulomb(m) => m.validate(),
            Self::TractionCurve(c) => c.validate(),
            Self::Ehl(e) => e.validate(),
            Self::Fastsim(f) => f.validate(),
            Self::ExactTable(t) => t.validate(),
        }
    }
}

#[cfg(test)]
mod batch_tests {
    use super::*;

    /// Cells spread over slip speeds from 0 to 10 m/s and pressures from 0
    /// to 3 GPa, with the edge cases each law guards (zero slip, zero
    /// pressure).
    fn cells() -> (Vec<f64>, Vec<f64>) {
        let (mut p, mut v) = (Vec::new(), Vec::new());
        for k in 0..23 {
            let f = k as f64;
            p.push(if k % 7 == 3 {
                0.0
            } else {
                3e9 * (0.37 * f).sin().abs()
            });
            v.push(if k % 5 == 2 {
                0.0
            } else {
                10f64.powf(-6.0 + 0.33 * f)
            });
        }
        (p, v)
    }

    fn assert_batch_is_cell_by_cell(law: &impl TractionLaw, conditions: &ContactConditions) {
        let (p, v) = cells();
        for (pc, vc) in p.chunks(BATCH).zip(v.chunks(BATCH)) {
            let (mut pressures, mut speeds, mut terms) = ([0.0; BATCH], [0.0; BATCH], [0.0; BATCH]);
            pressures[..pc.len()].copy_from_slice(pc);
            speeds[..vc.len()].copy_from_slice(vc);
            for k in 0..BATCH {
                terms[k] = law.pressure_term(pressures[k]);
            }
            let mut in_one_loop = pressures;
            law.pressure_terms(&mut in_one_loop);
            for k in 0..BATCH {
                assert_eq!(in_one_loop[k].to_bits(), terms[k].to_bits(), "term {k}");
            }
            let mut batch = [0.0; BATCH];
            law.stress_ratios(&pressures, &terms, &speeds, conditions, &mut batch);
            for k in 0..BATCH {
                let single = law.stress_ratio(pressures[k], terms[k], speeds[k], conditions);
                assert_eq!(batch[k].to_bits(), single.to_bits(), "cell {k}");
                assert!(single >= 0.0 && single.is_finite(), "cell {k}: {single}");
            }
        }
    }

    #[test]
    fn batches_are_bit_identical_to_cell_by_cell() {
        let conditions = ContactConditions {
            film: 2e-7,
            entrainment_speed: 10.0,
            rolling_velocity: 10.0,
        };
        let ehl = ehl::tests::law();
        assert_batch_is_cell_by_cell(&ehl, &conditions);
        assert_batch_is_cell_by_cell(
            &ehl,
            &ContactConditions {
                film: 0.0,
                ..conditions
            },
        );
        for slip in [
            curve::SlipMeasure::SlideToRoll,
            curve::SlipMeasure::SlipSpeed,
        ] {
            let curve = TractionCurve {
                a: -0.06,
                b: 8.0,
                c: 60.0,
                d: 0.02,
                slip,
                full_speed: 1e-3,
            };
            assert_batch_is_cell_by_cell(&curve, &conditions);
        }
        let coulomb = ModifiedCoulomb {
            friction: 0.1,
            stick_speed: 1e-5,
            full_speed: 1e-3,
        };
        assert_batch_is_cell_by_cell(&coulomb, &conditions);
        let mut roelands = ehl;
        roelands.lubricant.pressure_model = crate::lubrication::PressureViscosity::Roelands;
        assert_batch_is_cell_by_cell(&roelands, &conditions);
        let blended = mixed::Blended {
            fluid: &ehl,
            boundary: &coulomb,
            share: 0.3,
        };
        assert_batch_is_cell_by_cell(&blended, &conditions);
    }
}
