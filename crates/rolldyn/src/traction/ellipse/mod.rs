//! Integration of a traction stress law over the Hertz contact ellipse
//! (docs/model.md §3, "Integration over the ellipse").
//!
//! The ellipse has semi-axes a (across the rolling direction) and b (along
//! it) and Hertz pressure p = p₀ √(1 − (ξ/a)² − (η/b)²). It is cut into
//! `across` equal strips in ξ and `along` cells per strip in η (the cells
//! of a strip span its chord, so the grid follows the ellipse outline):
//! equal cells on the uniform grid, or, on the graded grid, cells equal in
//! the angle θ of η = w b sin θ (w the strip's half-width in units of b),
//! along which the pressure is cos θ times the strip's, so that the cells
//! shrink where it falls steeply to the edge (`TractionGrid`; docs/dynamics.md,
//! "Traction grid"). Each cell is sampled at its middle (the graded one at
//! its angle's middle) and weighted by its area. Cell
//! pressures are scaled so that Σ p dA = Q exactly. The points X lie on the
//! **deformed** contact surface: across the rolling direction a circular
//! arc of radius R_d = 2 r_g (D/2)/(r_g + D/2) (Harris & Kotzalas,
//! *Advanced Concepts*, §5.2) curving back towards the ball, along it
//! straight:
//! ```text
//! X = P + ξ e_⊥ + η e_roll − (R_d − √(R_d² − ξ²)) n,    local normal n_X = cos θ n + sin θ e_⊥,  sin θ = ξ/R_d
//! ```
//! The sliding velocity of ball material relative to ring material is
//! linear in X: s(X) = s_P + Ω_rel × (X − P), with Ω_rel = ω_b − ω_ring, so
//! spin and Heathcote (differential) slip appear without special formulas.
//! Its part tangent to n_X drives the stress law. Forces and moments (about
//! the ball centre) are the sums over cells. The dissipated power is
//! −Σ dF·s. Along a strip X − P = r₀ + t r₁ and n_X is constant, so the
//! tangential slip is s₀ + t d. Every law's stress is τ = −g s_t with a
//! ratio g ≥ 0, and with r₀ = ξ e_⊥ − drop n the couple about P is
//! e_⊥ × Σ ξ dF − n × Σ drop dF + r₁ × Σ t dF. The cells are laid out
//! [`BATCH`] to a batch with each lane on one strip, so a cell costs its
//! ratio and four lane-wise sums (Σ dF, Σ t dF, Σ dF·s), and ξ and drop
//! multiply each lane's sum once (docs/performance.md).
//!
//! `centre` evaluates one point at P with the mean pressure Q/(πab) over the
//! area πab. It is exact for Coulomb friction at uniform slip; it ignores
//! spin and differential slip.

mod grid;

use super::{BATCH, Cells, ContactConditions, Creep, TractionLaw};
pub use grid::TractionGrid;
use grid::{CellBatch, MAX_LEVELS};
use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

/// How traction is integrated over a contact (case file: `model.traction_integration`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(tag = "method", rename_all = "snake_case", deny_unknown_fields)]
pub enum TractionIntegration {
    /// One point at the contact centre (Shan et al. 2023, cheap).
    Centre,
    /// Strip grid over the ellipse: equal strips, equal cells along each.
    Grid {
        /// Strips across the rolling direction (along a).
        across: usize,
        /// Cells per strip along the rolling direction (along b).
        along: usize,
    },
    /// Strip grid graded towards the ellipse's edge: equal strips, cells
    /// along each equal in the angle θ of t = w sin θ, so that they shrink
    /// where the Hertz pressure falls to the edge.
    Graded {
        /// Strips across the rolling direction (along a).
        across: usize,
        /// Cells per strip along the rolling direction (along b).
        along: usize,
    },
}

impl Default for TractionIntegration {
    /// The graded grid of 12 × 6 cells: on the default case's contacts
    /// its dissipated power is within about 1 % of a converged grid's, the
    /// uniform 12 × 6 grid's 7 % low (docs/dynamics.md).
    fn default() -> Self {
        Self::Graded {
            across: 12,
            along: 6,
        }
    }
}

impl TractionIntegration {
    /// The strips and cells per strip of a grid (`None` at the centre).
    pub fn cells(&self) -> Option<(usize, usize)> {
        match *self {
            Self::Centre => None,
            Self::Grid { across, along } | Self::Graded { across, along } => Some((across, along)),
        }
    }

    /// The case file's name of the method.
    pub fn method_name(&self) -> &'static str {
        match self {
            Self::Centre => "centre",
            Self::Grid { .. } => "grid",
            Self::Graded { .. } => "graded",
        }
    }
}

/// The motion at one contact that a traction law turns into forces: the
/// loaded ellipse and its frame, the ball centre (about which the moment is
/// taken), the slip and spin of ball material relative to ring material,
/// and the film's conditions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactKinematics {
    /// The contact's ellipse, frame and load.
    pub patch: ContactPatch,
    /// Ball centre \[m\].
    pub ball_centre: Vector3<f64>,
    /// Sliding velocity of ball material relative to ring material at the
    /// contact point P \[m/s\].
    pub slip: Vector3<f64>,
    /// Relative angular velocity ω_b − ω_ring \[rad/s\].
    pub relative_spin: Vector3<f64>,
    /// Film, entrainment speed |u| and rolling velocity u·e_roll.
    pub conditions: ContactConditions,
}

/// Geometry and load of one contact for traction integration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactPatch {
    /// Contact point P on the ball \[m\].
    pub point: Vector3<f64>,
    /// Unit normal at P, from the ball centre towards P.
    pub normal: Vector3<f64>,
    /// Unit rolling direction (⊥ normal).
    pub rolling_direction: Vector3<f64>,
    /// Semi-axis across the rolling direction a \[m\].
    pub semi_major: f64,
    /// Semi-axis along the rolling direction b \[m\].
    pub semi_minor: f64,
    /// Normal load Q \[N\].
    pub load: f64,
    /// Radius of the deformed surface across the rolling direction R_d \[m\]
    /// (`f64::INFINITY`: flat).
    pub deformed_radius: f64,
}

/// Traction resultants of one contact.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TractionResult {
    /// Tangential force on the ball \[N\].
    pub force: Vector3<f64>,
    /// Moment of the traction on the ball about its centre \[N·m\].
    pub moment: Vector3<f64>,
    /// Couple of the traction about the contact point, Σ (X − P) × dF
    /// \[N·m\] (spin friction): the other body takes −force at P and
    /// −couple.
    pub couple: Vector3<f64>,
    /// Dissipated power −Σ dF·s \[W\], ≥ 0 for dissipative laws.
    pub dissipation: f64,
    /// Creepages and stick fraction (FASTSIM only).
    pub creep: Option<Creep>,
}

/// Integrates `law` over the ellipse of a contact in motion `kinematics`
/// (the full slip vector at P, ball relative to ring, and the relative
/// angular velocity give each cell's slip). Allocation-free.
///
/// Compiled for AVX2 where the processor has it (detected at run time),
/// else for the target's baseline (SSE2 on x86-64). Both builds run the
/// same IEEE operations in the same order (the cells' loops four lanes to
/// an instruction instead of two; Rust never fuses a multiply and an add
/// on its own), so their results are bit-identical (test
/// `avx2_build_is_bit_identical_to_baseline`).
pub fn integrate<L: TractionLaw>(
    law: &L,
    grid: &TractionGrid,
    kinematics: &ContactKinematics,
) -> TractionResult {
    if let TractionIntegration::Centre = grid.method {
        return at_centre(law, kinematics);
    }
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: `integrate_avx2` requires AVX2 only, and the processor
        // has it (detected just above).
        #[allow(unsafe_code)]
        return unsafe { integrate_avx2(law, grid, kinematics) };
    }
    integrate_baseline(law, grid, kinematics)
}

/// One point at P with the mean pressure Q/(πab): no spin or
/// differential slip.
fn at_centre<L: TractionLaw>(law: &L, kinematics: &ContactKinematics) -> TractionResult {
    let ContactKinematics {
        patch,
        ball_centre,
        slip,
        ..
    } = kinematics;
    let mut out = TractionResult::default();
    if patch.load <= 0.0 {
        return out;
    }
    let n = patch.normal;
    let area = std::f64::consts::PI * patch.semi_major * patch.semi_minor;
    let s_t = slip - slip.dot(&n) * n;
    out.force = law.shear_stress(patch.load / area, &s_t, &kinematics.conditions) * area;
    out.dissipation = -out.force.dot(&s_t);
    out.moment = (patch.point - ball_centre).cross(&out.force);
    out
}

/// [`integrate_baseline`] compiled with AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn integrate_avx2<L: TractionLaw>(
    law: &L,
    grid: &TractionGrid,
    kinematics: &ContactKinematics,
) -> TractionResult {
    integrate_baseline(law, grid, kinematics)
}

/// The integration itself, inlined into both builds of [`integrate`].
#[inline(always)]
fn integrate_baseline<L: TractionLaw>(
    law: &L,
    grid: &TractionGrid,
    kinematics: &ContactKinematics,
) -> TractionResult {
    let ContactKinematics {
        patch,
        ball_centre,
        slip: slip_at_point,
        relative_spin,
        conditions,
    } = kinematics;
    let mut out = TractionResult::default();
    if patch.load <= 0.0 {
        return out;
    }
    let n = patch.normal;
    let e_roll = patch.rolling_direction;
    let e_across = n.cross(&e_roll);
    let (a, b) = (patch.semi_major, patch.semi_minor);
    match grid.method {
        TractionIntegration::Centre => return at_centre(law, kinematics),
        TractionIntegration::Grid { across, along }
        | TractionIntegration::Graded { across, along } => {
            let (across, along) = (across.max(1), along.max(1));
            let ds = 2.0 / across as f64;
            let cell = a * ds * b * 2.0 / along as f64;
            let p_scale = patch.load / (grid.shape_sum * cell);
            // The law's pressure term once per pressure level (per cell on
            // grids finer than MAX_LEVELS levels).
            let mut level_terms = [0.0; MAX_LEVELS];
            let shared = grid.levels.len() <= MAX_LEVELS;
            if shared {
                let terms = &mut level_terms[..grid.levels.len()];
                for (term, &shape) in terms.iter_mut().zip(&grid.levels) {
                    *term = p_scale * shape;
                }
                law.pressure_terms(terms);
            }
            let terms = if shared { Some(&level_terms) } else { None };
            // Σ dF, Σ ξ dF, Σ drop dF, Σ t dF (dF = −area g s_t).
            let mut totals = [Vector3::zeros(); 4];
            let mut power = 0.0;
            for group in &grid.groups {
                let mut lanes = StripLanes::default();
                for i in 0..group.len {
                    let (s, _) = grid.strips[group.first + i];
                    let xi = a * s;
                    let (sin_t, drop) = if patch.deformed_radius.is_finite() {
                        let r = patch.deformed_radius;
                        let st = (xi / r).clamp(-1.0, 1.0);
                        (st, r - (r * r - xi * xi).max(0.0).sqrt())
                    } else {
                        (0.0, 0.0)
                    };
                    let cos_t = (1.0 - sin_t * sin_t).sqrt();
                    let local_normal = cos_t * n + sin_t * e_across;
                    let tangential = |v: Vector3<f64>| v - v.dot(&local_normal) * local_normal;
                    // Along the strip X − P = r₀ + t r₁ (r₀ = ξ e_⊥ − drop n,
                    // r₁ = b e_roll), so the tangential slip is linear in t:
                    // s_t = s₀ + t d.
                    let r0 = xi * e_across - drop * n;
                    let s0 = tangential(slip_at_point + relative_spin.cross(&r0));
                    let d = tangential(relative_spin.cross(&(b * e_roll)));
                    for k in (i..BATCH).step_by(group.len) {
                        lanes.xi[k] = xi;
                        lanes.drop[k] = drop;
                        for c in 0..3 {
                            lanes.slip[c][k] = s0[c];
                            lanes.slope[c][k] = d[c];
                        }
                    }
                }
                let mut sums = Sums::default();
                for batch in &group.batches {
                    sums.add(law, batch, &lanes, (p_scale, cell), terms, conditions);
                }
                // The lanes' sums in lane order; ξ and drop are the lanes'.
                for k in 0..BATCH {
                    let force = Vector3::new(sums.force[0][k], sums.force[1][k], sums.force[2][k]);
                    totals[0] += force;
                    totals[1] += lanes.xi[k] * force;
                    totals[2] += lanes.drop[k] * force;
                    totals[3] += Vector3::new(sums.along[0][k], sums.along[1][k], sums.along[2][k]);
                    power += sums.power[k];
                }
            }
            // The couple about P is Σ (r₀ + t r₁) × dF
            // = e_⊥ × Σ ξ dF − n × Σ drop dF + r₁ × Σ t dF.
            let [force, across_moment, drop_moment, along_moment] = totals.map(|v| -v);
            out.force = force;
            out.couple = e_across.cross(&across_moment) - n.cross(&drop_moment)
                + (b * e_roll).cross(&along_moment);
            out.dissipation = power;
        }
    }
    // Σ (X − q) × dF = Σ (X − P) × dF + (P − q) × Σ dF.
    out.moment = out.couple + (patch.point - ball_centre).cross(&out.force);
    out
}

/// What a [`grid::StripGroup`]'s lanes take from their strips: ξ, drop, and
/// the tangential slip s₀ + t d along the strip.
#[derive(Default)]
struct StripLanes {
    xi: Cells,
    drop: Cells,
    slip: [Cells; 3],
    slope: [Cells; 3],
}

/// Lane-wise sums over a group's batches (each lane adds its cells in
/// column order; the lanes are added at the end in lane order: a fixed
/// order, so the same bits on every build): with w = area · g, Σ w s_t,
/// Σ t w s_t and Σ w |s_t|².
#[derive(Default)]
struct Sums {
    force: [Cells; 3],
    along: [Cells; 3],
    power: Cells,
}

impl Sums {
    /// The law's ratios for `batch`'s cells, added lane by lane. The cell
    /// pressure is `p_scale` times its shape and its area `cell` times its
    /// weight; the pressure terms per level from `terms`, or the law's own.
    #[inline(always)]
    #[allow(clippy::needless_range_loop)] // lanes of several arrays at once
    fn add<L: TractionLaw>(
        &mut self,
        law: &L,
        batch: &CellBatch,
        lanes: &StripLanes,
        (p_scale, cell): (f64, f64),
        terms: Option<&[f64; MAX_LEVELS]>,
        conditions: &ContactConditions,
    ) {
        let mut pressure = [0.0; BATCH];
        for (p, shape) in pressure.iter_mut().zip(&batch.shape) {
            *p = p_scale * shape;
        }
        let mut term = [0.0; BATCH];
        match terms {
            Some(levels) => {
                for (value, &level) in term.iter_mut().zip(&batch.level) {
                    *value = levels[level as usize];
                }
            }
            None => {
                for (value, &p) in term.iter_mut().zip(&pressure) {
                    *value = law.pressure_term(p);
                }
            }
        }
        let mut slip = [[0.0; BATCH]; 3];
        for (c, lane) in slip.iter_mut().enumerate() {
            for k in 0..BATCH {
                lane[k] = lanes.slip[c][k] + batch.t[k] * lanes.slope[c][k];
            }
        }
        let [x, y, z] = &slip;
        let mut speed = [0.0; BATCH];
        for (k, v) in speed.iter_mut().enumerate() {
            *v = (x[k] * x[k] + y[k] * y[k] + z[k] * z[k]).sqrt();
        }
        let mut ratio = [0.0; BATCH];
        law.stress_ratios(&pressure, &term, &speed, conditions, &mut ratio);
        for k in 0..BATCH {
            let w = (cell * batch.weight[k]) * ratio[k];
            for c in 0..3 {
                let f = w * slip[c][k];
                self.force[c][k] += f;
                self.along[c][k] += batch.t[k] * f;
            }
            self.power[k] += w * (speed[k] * speed[k]);
        }
    }
}

/// A test contact: 1 × 0.2 mm, 200 N, 3 mm below the ball centre at the
/// origin, rolling along +y, flat.
#[cfg(test)]
pub(crate) fn test_patch() -> ContactPatch {
    ContactPatch {
        point: Vector3::new(0.0, 0.0, -3e-3),
        normal: Vector3::new(0.0, 0.0, -1.0),
        rolling_direction: Vector3::new(0.0, 1.0, 0.0),
        semi_major: 1.0e-3,
        semi_minor: 0.2e-3,
        load: 200.0,
        deformed_radius: f64::INFINITY,
    }
}

#[cfg(test)]
mod tests;
