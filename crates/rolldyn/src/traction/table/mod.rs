//! A traction law tabulated from Kalker's exact theory of steady rolling
//! ([`super::exact`]; J. J. Kalker, *Three-Dimensional Elastic Bodies in
//! Rolling Contact*, 1990), interpolated in the time loop
//! (docs/dynamics.md, "Traction tabulated from the exact theory").
//!
//! # What is tabulated
//! With Coulomb friction and the Hertz pressure, Kalker's steady problem
//! is self-similar: the forces over μQ depend only on the ellipse ratio
//! a/b (a along the rolling direction, b across it), Poisson's ratio and
//! the creepages normalised by the linear theory's saturation
//! ([`layout::Normalisation`]). Besides ξ, η and φ, a ball on a conforming
//! raceway rolls on a surface curved across the rolling direction: the
//! rigid slip along the flow gains the differential (Heathcote) term
//! −d(y) Ω·ŷ, with the surface's depth d(y) ≈ y²/(2R_d) and R_d the
//! deformed radius across the contact. It is the fourth creepage,
//! χ = Ω·ŷ/(2 R_d V) (slip −χ y²), and dominates the slip of ball-bearing
//! contacts at speed. So the slip is
//! ```text
//! w/V = (ξ − φ y − χ y²,  η + φ x)
//! ```
//! and the table holds, on a grid over log₂(a/b) ∈ [−5, 0] and the
//! normalised creepage's magnitude u = r/(1 + r) and direction (three
//! angles on a quarter of the unit sphere in four dimensions; the other
//! three quarters follow from the problem's symmetries), the outputs
//! F_x/(μQ), F_y/(μQ), M_n/(μQ b), Σ y² p_x dA/(μQ b²), Σ y² p_y dA/(μQ b²)
//! (each divided by u, so that the linear theory is exact as u → 0) and
//! the stick fraction. Each node is the exact theory on 32 × 32 cells
//! extrapolated to zero cell size with 16 × 16 ([`build`]), at ν = 0.28
//! (steel on steel 0.30, steel on silicon nitride ≈ 0.28, the creep
//! coefficients carry the rest of ν's effect).
//!
//! # The law
//! Per flow direction (blended like FASTSIM's within the regularisation
//! speed of rolling reversal), with V = √(|u|² + v_r²):
//! - ξ = s·x̂/V, φ = Ω·n/V, χ = Ω·ŷ/(2 R_d V), and η = (s·ŷ + d̄ Ω·x̂)/V
//!   with d̄ = b²/(10 R_d) the depth's mean over the Hertz pressure (the
//!   lateral Heathcote slip, small in a bearing, taken at its mean);
//! - multilinear interpolation over the five coordinates (32 corners);
//! - forces F = μQ(f_x x̂ + f_y ŷ), the couple about P
//!   M = μQ(b m_n n + b²/(2R_d) (q_y x̂ − q_x ŷ)) (the tractions act on the
//!   deformed surface, depth d(y)), and the dissipated power
//!   −(s·F + Ω·M), the work the tractions take from the rigid-body motion,
//!   which in steady rolling is the frictional power: the energy balance
//!   of a run closes exactly.
//!
//! # Accuracy and limits
//! Against fresh exact solutions of ball-bearing contacts the table is
//! off by 1.5 % of μQ on average and 8 % at worst, FASTSIM by 4.3 % and
//! 8–14 % (docs/validation.md, C8; tests bound both);
//! contacts with a/b outside [1/32, 1] take the nearest tabulated ratio.
//! Like FASTSIM it is a half-space, steady-state theory: the transient of
//! the material's passage (a few microseconds) is not modelled.

pub mod build;
pub mod layout;
#[cfg(test)]
mod tests;

use super::fastsim::{Creep, blend_flow_directions};
use super::{ContactKinematics, TractionResult};
use crate::error::{InvalidParameter, require_positive};
use layout::{Direction, Layout, Normalisation, OUTPUTS, SLOPES};
use nalgebra::Vector3;
use serde::{Deserialize, Serialize};
use std::f64::consts::{FRAC_PI_2, PI};
use std::sync::OnceLock;

/// The stored table: node layout and quantised outputs.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// Node grid.
    pub layout: Layout,
    /// Poisson ratio it was built at.
    pub poisson_ratio: f64,
    /// Cells per direction of the finer exact grid.
    pub cells: usize,
    /// Values per node, [`OUTPUTS`] each, quantised to i16 (unit 1/[`QUANTUM`]).
    values: Vec<i16>,
}

/// Quantisation: a stored value v means v/QUANTUM. The slopes lie within
/// ±8 (the linear theory's normalised slope is 3 along a single creepage)
/// and the stick fraction in [0, 1]; resolution 2.4e-4, so 2.4e-4 u of
/// μQ in a force.
pub const QUANTUM: f64 = 4096.0;

/// File signature of the stored table.
const MAGIC: &[u8; 8] = b"RDKTAB01";

/// Why a table file could not be read.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("exact traction table: {0}")]
pub struct TableError(String);

impl Table {
    /// A table from unquantised node outputs (storage order of `layout`).
    pub fn from_values(
        layout: Layout,
        poisson_ratio: f64,
        cells: usize,
        values: &[[f64; OUTPUTS]],
    ) -> Self {
        let values = values
            .iter()
            .flat_map(|v| {
                v.iter()
                    .map(|x| (x * QUANTUM).round().clamp(-32767.0, 32767.0) as i16)
            })
            .collect();
        Self {
            layout,
            poisson_ratio,
            cells,
            values,
        }
    }

    /// The values stored at a node (slopes and stick fraction).
    pub fn node(&self, index: usize) -> [f64; OUTPUTS] {
        std::array::from_fn(|k| f64::from(self.values[index * OUTPUTS + k]) / QUANTUM)
    }

    /// The table as bytes: signature, five node counts (u32), ν (f64), cells
    /// (u32), then the values (i16), all little-endian.
    pub fn to_bytes(&self) -> Vec<u8> {
        let l = &self.layout;
        let mut out = MAGIC.to_vec();
        for n in [l.ratios, l.alphas, l.betas, l.gammas, l.magnitudes] {
            out.extend_from_slice(&(n as u32).to_le_bytes());
        }
        out.extend_from_slice(&self.poisson_ratio.to_le_bytes());
        out.extend_from_slice(&(self.cells as u32).to_le_bytes());
        for v in &self.values {
            out.extend_from_slice(&v.to_le_bytes());
        }
        out
    }

    /// Reads [`Self::to_bytes`]'s format.
    pub fn from_bytes(bytes: &[u8]) -> Result<Self, TableError> {
        let header = MAGIC.len() + 5 * 4 + 8 + 4;
        if bytes.len() < header || &bytes[..MAGIC.len()] != MAGIC {
            return Err(TableError("not a table file (signature)".into()));
        }
        let u32_at = |at: usize| u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap_or([0; 4]));
        let count = |k: usize| u32_at(MAGIC.len() + 4 * k) as usize;
        let layout = Layout {
            ratios: count(0),
            alphas: count(1),
            betas: count(2),
            gammas: count(3),
            magnitudes: count(4),
        };
        if [
            layout.ratios,
            layout.alphas,
            layout.betas,
            layout.gammas,
            layout.magnitudes,
        ]
        .iter()
        .any(|&n| n < 2)
        {
            return Err(TableError(format!("too few nodes: {layout:?}")));
        }
        let at = MAGIC.len() + 20;
        let poisson_ratio = f64::from_le_bytes(bytes[at..at + 8].try_into().unwrap_or([0; 8]));
        let cells = u32_at(at + 8) as usize;
        let body = &bytes[header..];
        if body.len() != 2 * OUTPUTS * layout.nodes() {
            return Err(TableError(format!(
                "{} bytes of values for {} nodes",
                body.len(),
                layout.nodes()
            )));
        }
        let values = body
            .chunks_exact(2)
            .map(|b| i16::from_le_bytes([b[0], b[1]]))
            .collect();
        Ok(Self {
            layout,
            poisson_ratio,
            cells,
            values,
        })
    }

    /// The table embedded in the library (`data/exact_traction_table.bin`).
    pub fn embedded() -> &'static Table {
        static TABLE: OnceLock<Table> = OnceLock::new();
        TABLE.get_or_init(|| {
            // The file is part of the source and checked by a test; a
            // failure here is a build defect, not bad input.
            Table::from_bytes(include_bytes!("../../../data/exact_traction_table.bin"))
                .expect("the embedded exact traction table is valid")
        })
    }

    /// The normalised outputs at ellipse ratio a/b = `ratio` and grid
    /// coordinates `d` (symmetries not yet applied): the stored values
    /// multilinear in log₂(a/b), α, β, γ and u, the slopes then times u
    /// (so that the linear theory holds exactly as u → 0 and full slip at
    /// u = 1).
    pub fn interpolate(&self, ratio: f64, d: &Direction) -> [f64; OUTPUTS] {
        let l = &self.layout;
        // (lower node, weight of the upper) per coordinate.
        let locate = |position: f64, count: usize| {
            let p = position.clamp(0.0, (count - 1) as f64);
            let k = (p.floor() as usize).min(count - 2);
            (k, p - k as f64)
        };
        let log_ratio = ratio.log2();
        let g = locate(
            (log_ratio - Layout::LOG_RATIO_MIN) / -Layout::LOG_RATIO_MIN * (l.ratios - 1) as f64,
            l.ratios,
        );
        let a = locate(d.alpha / FRAC_PI_2 * (l.alphas - 1) as f64, l.alphas);
        let b = locate(d.beta / PI * (l.betas - 1) as f64, l.betas);
        let c = locate(d.gamma / PI * (l.gammas - 1) as f64, l.gammas);
        let u = locate(d.magnitude * (l.magnitudes - 1) as f64, l.magnitudes);
        // Node strides in storage order, and the lower node and the
        // weights of the lower and upper node per coordinate.
        let strides = [
            l.alphas * l.betas * l.gammas * l.magnitudes,
            l.betas * l.gammas * l.magnitudes,
            l.gammas * l.magnitudes,
            l.magnitudes,
            1,
        ];
        let cells = [g, a, b, c];
        let base: usize = cells
            .iter()
            .zip(strides)
            .map(|((k, _), s)| k * s)
            .sum::<usize>()
            + u.0;
        let (u_lower, u_upper) = (1.0 - u.1, u.1);
        let mut sum = [0.0; OUTPUTS];
        // The 16 corners in (ratio, α, β, γ); each reads its two magnitude
        // nodes, adjacent in storage.
        for corner in 0..16usize {
            let (mut w, mut node) = (1.0, base);
            for (dim, ((_, upper), stride)) in cells.iter().zip(strides).enumerate() {
                if (corner >> dim) & 1 == 1 {
                    w *= upper;
                    node += stride;
                } else {
                    w *= 1.0 - upper;
                }
            }
            if w == 0.0 {
                continue;
            }
            let pair = &self.values[node * OUTPUTS..(node + 2) * OUTPUTS];
            let (lower, upper) = pair.split_at(OUTPUTS);
            for k in 0..OUTPUTS {
                sum[k] += w * (u_lower * f64::from(lower[k]) + u_upper * f64::from(upper[k]));
            }
        }
        let mut out = sum.map(|v| v / QUANTUM);
        for v in &mut out[..SLOPES] {
            *v *= d.magnitude;
        }
        out
    }

    /// The normalised outputs at normalised creepages [ξ*, η*, φ*, χ*] of a
    /// contact of ratio a/b, symmetries applied.
    pub fn evaluate(&self, ratio: f64, normalised: [f64; 4]) -> [f64; OUTPUTS] {
        let d = Direction::of(normalised);
        let mut out = self.interpolate(ratio, &d);
        if d.reflected {
            for k in [1, 2, 4] {
                out[k] = -out[k];
            }
        }
        if d.negated {
            for v in &mut out[..5] {
                *v = -*v;
            }
        }
        out
    }
}

/// The tabulated exact-theory law (case file: `traction.law =
/// "exact_table"`): the same inputs as FASTSIM without its grid.
///
/// A 7218B inner-raceway contact (semi-axes 0.276 mm along and 2.26 mm
/// across the rolling direction, 2088 N, steel) rolling at 10 m/s: a
/// small longitudinal creepage gives Kalker's linear force, a large one
/// Coulomb sliding, and spin on the groove-curved surface a lateral force
/// and a spin moment against the spin:
/// ```
/// use nalgebra::Vector3;
/// use rolldyn::traction::{ContactConditions, ContactKinematics, ContactPatch, ExactTable};
///
/// let law = ExactTable::new(0.1, 76.9e9, 0.3);
/// let patch = ContactPatch {
///     point: Vector3::zeros(),
///     normal: Vector3::z(),
///     rolling_direction: Vector3::x(),
///     semi_major: 2.2609e-3,
///     semi_minor: 0.2761e-3,
///     load: 2088.0,
///     deformed_radius: 11e-3,
/// };
/// let speed = 10.0;
/// let rolling = ContactConditions { film: 0.0, entrainment_speed: speed, rolling_velocity: speed };
/// let at = |creepage: f64, spin: f64| {
///     let slip = Vector3::new(creepage * speed, 0.0, 0.0);
///     law.evaluate(&ContactKinematics {
///         patch,
///         ball_centre: Vector3::new(0.0, 0.0, -0.02),
///         slip,
///         relative_spin: Vector3::new(0.0, 0.0, spin * speed),
///         conditions: rolling,
///     })
/// };
/// // Linear theory: F_x = −G c² C₁₁ ξ with c² = a b.
/// let c11 = rolldyn::traction::kalker::creep_coefficients(patch.semi_minor, patch.semi_major, 0.3)
///     .longitudinal;
/// let linear = -76.9e9 * patch.semi_major * patch.semi_minor * c11 * 1e-7;
/// assert!((at(1e-7, 0.0).force.x / linear - 1.0).abs() < 0.03);
/// // Full slip: μQ against the slip.
/// assert!((at(0.1, 0.0).force.x + 0.1 * 2088.0).abs() < 0.01 * 208.8);
/// // Spin φ = 20 1/m: a spin moment against it, power dissipated.
/// let spinning = at(0.0, 20.0);
/// assert!(spinning.couple.z < 0.0 && spinning.dissipation > 0.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct ExactTable {
    /// Friction coefficient μ ≥ 0.
    pub friction: f64,
    /// Combined shear modulus G, 1/G = ½(1/G₁ + 1/G₂) \[Pa\].
    pub shear_modulus: f64,
    /// Combined Poisson ratio ν, in [0, 0.5] (the creep coefficients use
    /// it; the table's shape is that of ν = 0.28).
    pub poisson_ratio: f64,
    /// Regularisation speed v_r of the creepages \[m/s\].
    pub regularisation_speed: f64,
}

impl ExactTable {
    /// The law with the default regularisation speed (FASTSIM's).
    pub fn new(friction: f64, shear_modulus: f64, poisson_ratio: f64) -> Self {
        Self {
            friction,
            shear_modulus,
            poisson_ratio,
            regularisation_speed: super::fastsim::DEFAULT_REGULARISATION_SPEED,
        }
    }

    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        super::require_friction("friction", self.friction)?;
        require_positive("shear_modulus", self.shear_modulus)?;
        super::kalker::check_poisson_ratio(self.poisson_ratio)?;
        require_positive("regularisation_speed", self.regularisation_speed)
    }

    /// Tractions of one contact in motion `kinematics`, as
    /// [`super::Fastsim::evaluate`]. Allocation-free.
    pub fn evaluate(&self, kinematics: &ContactKinematics) -> TractionResult {
        let ContactKinematics {
            patch,
            ball_centre,
            conditions,
            ..
        } = kinematics;
        if patch.load <= 0.0 || self.friction <= 0.0 {
            return TractionResult::default();
        }
        let table = Table::embedded();
        let speed = conditions
            .entrainment_speed
            .hypot(self.regularisation_speed);
        let (along, across) = (patch.semi_minor, patch.semi_major);
        let normalisation = Normalisation::new(
            along,
            across,
            self.shear_modulus,
            self.poisson_ratio,
            patch.load,
            self.friction,
        );
        let mut out = blend_flow_directions(
            conditions.rolling_velocity,
            self.regularisation_speed,
            |direction, _| self.one_direction(table, &normalisation, kinematics, speed, direction),
        );
        out.moment = out.couple + (patch.point - ball_centre).cross(&out.force);
        out
    }

    /// The contact with the material flowing along `direction` · e_roll.
    fn one_direction(
        &self,
        table: &Table,
        normalisation: &Normalisation,
        kinematics: &ContactKinematics,
        speed: f64,
        direction: f64,
    ) -> (TractionResult, Creep) {
        let ContactKinematics {
            patch,
            slip,
            relative_spin: spin,
            ..
        } = kinematics;
        let n = patch.normal;
        let ex = direction * patch.rolling_direction;
        let ey = n.cross(&ex);
        let (along, across) = (patch.semi_minor, patch.semi_major);
        let (s_x, s_y) = (slip.dot(&ex), slip.dot(&ey));
        let (w_n, w_x, w_y) = (spin.dot(&n), spin.dot(&ex), spin.dot(&ey));
        let radius = patch.deformed_radius;
        let (chi, mean_depth, depth_scale) = if radius.is_finite() {
            (
                w_y / (2.0 * radius * speed),
                across * across / (10.0 * radius),
                across * across / (2.0 * radius),
            )
        } else {
            (0.0, 0.0, 0.0)
        };
        let creep = [
            s_x / speed,
            (s_y + mean_depth * w_x) / speed,
            w_n / speed,
            chi,
        ];
        let normalised = std::array::from_fn(|k| creep[k] * normalisation.scale[k]);
        let v = table.evaluate(along / across, normalised);
        let mu_q = self.friction * patch.load;
        let (fx, fy, mn) = (mu_q * v[0], mu_q * v[1], mu_q * across * v[2]);
        let (mx, my) = (mu_q * depth_scale * v[4], -mu_q * depth_scale * v[3]);
        let result = TractionResult {
            force: fx * ex + fy * ey,
            moment: Vector3::zeros(),
            couple: mx * ex + my * ey + mn * n,
            dissipation: -(s_x * fx + s_y * fy + w_n * mn + w_x * mx + w_y * my),
            creep: None,
        };
        let creep = Creep {
            longitudinal: creep[0],
            lateral: s_y / speed,
            spin: creep[2],
            stick_fraction: v[5].clamp(0.0, 1.0),
        };
        (result, creep)
    }
}
