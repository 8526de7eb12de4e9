//! Integration of a traction stress law over the Hertz contact ellipse
//! (docs/model.md §3, "Integration over the ellipse").
//!
//! The ellipse has semi-axes a (across the rolling direction) and b (along
//! it) and Hertz pressure p = p₀ √(1 − (ξ/a)² − (η/b)²). It is cut into
//! `across` strips in ξ and `along` cells per strip in η (the cells of a
//! strip span its chord, so the grid follows the ellipse outline). Cell
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

use super::{BATCH, Cells, ContactConditions, Creep, TractionLaw};
use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

/// How traction is integrated over a contact (case file: `model.traction_integration`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(tag = "method", rename_all = "snake_case", deny_unknown_fields)]
pub enum TractionIntegration {
    /// One point at the contact centre (Shan et al. 2023, cheap).
    Centre,
    /// Strip grid over the ellipse.
    Grid {
        /// Strips across the rolling direction (along a).
        across: usize,
        /// Cells per strip along the rolling direction (along b).
        along: usize,
    },
}

impl Default for TractionIntegration {
    /// 12 × 6 cells (docs/model.md §3's example default).
    fn default() -> Self {
        Self::Grid {
            across: 12,
            along: 6,
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

/// The strip grid of a [`TractionIntegration`] over the unit ellipse,
/// prepared once (a model keeps one): per strip its position s and
/// half-width w = √(1 − s²), per cell its position t along the strip and
/// the unit Hertz shape √(1 − s² − t²), and Σ shape · w for the
/// normalisation. The grid is symmetric in s and in t (mirrored cells are
/// built from the same |s|, |t|), so each shape occurs up to four times:
/// the distinct shapes are the grid's pressure **levels**, at which
/// [`integrate`] evaluates a law's pressure term (the EHL viscosity) once.
/// These depend on the grid only; [`integrate`] scales them by the
/// contact's semi-axes and load.
///
/// The cells are laid out for the lanes (`StripGroup`): each lane stays
/// on one strip, so what is constant along a strip (its ξ, drop and
/// slip line) is set once per lane and the strip moments need no per-cell
/// product.
#[derive(Debug, Clone, PartialEq)]
pub struct TractionGrid {
    method: TractionIntegration,
    /// (s, w) per strip.
    strips: Vec<(f64, f64)>,
    /// The cells in lane order.
    groups: Vec<StripGroup>,
    /// The distinct unit shapes.
    levels: Vec<f64>,
    /// Σ shape · w over the cells.
    shape_sum: f64,
}

/// Consecutive strips `first..first + len` spread over the lanes: lane k
/// is on strip `first + k % len`, and a batch holds m = ⌊BATCH/len⌋ of
/// their cells' columns (lane k in column `c₀ + k / len`). Lanes beyond
/// `len · m`, and columns beyond the strip's cells, are empty (weight 0).
#[derive(Debug, Clone, PartialEq)]
struct StripGroup {
    first: usize,
    len: usize,
    batches: Vec<CellBatch>,
}

/// [`BATCH`] cells of a [`StripGroup`].
#[derive(Debug, Clone, PartialEq)]
struct CellBatch {
    /// Position along the strip, in units of b (0 where empty).
    t: Cells,
    /// Unit Hertz shape √(1 − s² − t²) (0 where empty).
    shape: Cells,
    /// The strip's half-width w (0 where empty): the cell's area is
    /// w times the contact's cell size.
    weight: Cells,
    /// Index of `shape` in the grid's levels.
    level: [u32; BATCH],
}

/// Most pressure levels [`integrate`] holds on the stack (12 × 6 has 18,
/// 24 × 12 has 72); finer grids evaluate the pressure term per cell.
const MAX_LEVELS: usize = 96;

/// Midpoints of n equal cells of [−1, 1], mirror-symmetric to the bit:
/// the upper half is the negated lower half.
fn symmetric_midpoints(n: usize) -> impl Iterator<Item = f64> {
    (0..n).map(move |k| {
        let lower = k.min(n - 1 - k);
        let u = -1.0 + (lower as f64 + 0.5) * 2.0 / n as f64;
        if k == lower { u } else { -u }
    })
}

/// Strips per [`StripGroup`] for a grid of `across` strips of `along`
/// cells: the fewest batches, and of those the fewest groups (12 × 6:
/// one group of 12 strips, 3 full batches).
fn group_len(across: usize, along: usize) -> usize {
    let batches = |len: usize| -> usize {
        (0..across)
            .step_by(len)
            .map(|first| along.div_ceil(BATCH / len.min(across - first)))
            .sum()
    };
    (1..=across.min(BATCH))
        .rev()
        .min_by_key(|&len| batches(len))
        .unwrap_or(1)
}

impl TractionGrid {
    /// Prepares the grid of `method` (nothing for the contact centre).
    pub fn new(method: TractionIntegration) -> Self {
        let mut grid = Self {
            method,
            strips: Vec::new(),
            groups: Vec::new(),
            levels: Vec::new(),
            shape_sum: 0.0,
        };
        let TractionIntegration::Grid { across, along } = method else {
            return grid;
        };
        let (across, along) = (across.max(1), along.max(1));
        let mut level_of = std::collections::HashMap::new();
        // Per cell, strip by strip: (t, shape, level).
        let mut cells = Vec::with_capacity(across * along);
        for s in symmetric_midpoints(across) {
            let w = (1.0 - s * s).sqrt();
            grid.strips.push((s, w));
            for u in symmetric_midpoints(along) {
                let t = w * u;
                let shape = (1.0 - s * s - t * t).max(0.0).sqrt();
                let next = grid.levels.len();
                let level = *level_of.entry(shape.to_bits()).or_insert(next);
                if level == next {
                    grid.levels.push(shape);
                }
                cells.push((t, shape, level));
                grid.shape_sum += shape * w;
            }
        }
        let group = group_len(across, along);
        for first in (0..across).step_by(group) {
            let len = group.min(across - first);
            let columns = BATCH / len;
            let batches = (0..along)
                .step_by(columns)
                .map(|first_column| {
                    let mut batch = CellBatch {
                        t: [0.0; BATCH],
                        shape: [0.0; BATCH],
                        weight: [0.0; BATCH],
                        level: [0; BATCH],
                    };
                    for k in 0..len * columns {
                        let (strip, column) = (first + k % len, first_column + k / len);
                        if column < along {
                            let (t, shape, level) = cells[strip * along + column];
                            batch.t[k] = t;
                            batch.shape[k] = shape;
                            batch.weight[k] = grid.strips[strip].1;
                            batch.level[k] = level as u32;
                        }
                    }
                    batch
                })
                .collect();
            grid.groups.push(StripGroup {
                first,
                len,
                batches,
            });
        }
        grid
    }
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
        TractionIntegration::Grid { across, along } => {
            let (across, along) = (across.max(1), along.max(1));
            let ds = 2.0 / across as f64;
            let cell = a * ds * b * 2.0 / along as f64;
            let p_scale = patch.load / (grid.shape_sum * cell);
            // The law's pressure term once per pressure level (per cell on
            // grids finer than MAX_LEVELS levels).
            let mut level_terms = [0.0; MAX_LEVELS];
            let shared = grid.levels.len() <= MAX_LEVELS;
            if shared {
                for (term, &shape) in level_terms.iter_mut().zip(&grid.levels) {
                    *term = law.pressure_term(p_scale * shape);
                }
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

/// What a [`StripGroup`]'s lanes take from their strips: ξ, drop, and
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::elliptic;
    use crate::traction::ModifiedCoulomb;

    fn patch() -> ContactPatch {
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

    fn coulomb() -> ModifiedCoulomb {
        ModifiedCoulomb {
            friction: 0.1,
            stick_speed: 0.0,
            full_speed: 1e-9,
        }
    }

    #[test]
    fn uniform_slip_gives_mu_q() {
        let p = patch();
        let q = Vector3::zeros();
        let slip = Vector3::new(0.0, 0.5, 0.0);
        for method in [
            TractionIntegration::Centre,
            TractionIntegration::Grid {
                across: 12,
                along: 6,
            },
        ] {
            let r = integrate(
                &coulomb(),
                &TractionGrid::new(method),
                &ContactKinematics {
                    patch: p,
                    ball_centre: q,
                    slip,
                    relative_spin: Vector3::zeros(),
                    conditions: ContactConditions::default(),
                },
            );
            assert!(
                (r.force - Vector3::new(0.0, -20.0, 0.0)).norm() < 1e-9,
                "{method:?}: {:?}",
                r.force
            );
            assert!((r.dissipation - 10.0).abs() < 1e-9);
        }
    }

    #[test]
    fn full_slip_spin_moment_is_harris() {
        // Pure spin about the normal with full Coulomb sliding:
        // M_s = (3/8) μ Q a E(m), m = 1 − (b/a)² (Harris & Kotzalas; docs/model.md §10).
        let p = patch();
        let spin = 1000.0 * p.normal;
        let m = 1.0 - (p.semi_minor / p.semi_major).powi(2);
        let exact = 0.375 * 0.1 * p.load * p.semi_major * elliptic::complete(m).e;
        let moment = |across, along| {
            let r = integrate(
                &coulomb(),
                &TractionGrid::new(TractionIntegration::Grid { across, along }),
                &ContactKinematics {
                    patch: p,
                    ball_centre: p.point,
                    slip: Vector3::zeros(),
                    relative_spin: spin,
                    conditions: ContactConditions::default(),
                },
            );
            assert!(r.force.norm() < 1e-9 * p.load, "symmetric: no net force");
            -r.moment.dot(&p.normal)
        };
        let coarse = moment(12, 6);
        let fine = moment(48, 24);
        eprintln!(
            "spin moment: 12×6 {:.4e}, 48×24 {:.4e}, exact {exact:.4e}",
            coarse, fine
        );
        assert!(
            (fine / exact - 1.0).abs() < 0.01,
            "48×24: {fine} vs {exact}"
        );
        assert!(
            (coarse / exact - 1.0).abs() < 0.03,
            "12×6: {coarse} vs {exact}"
        );
    }

    #[test]
    fn deformed_surface_curves_towards_the_ball() {
        // With spin about the rolling-direction-normal axis, points across the
        // ellipse move at different speeds only through the arc geometry.
        let mut p = patch();
        p.deformed_radius = 3e-3;
        let spin = Vector3::new(0.0, 500.0, 0.0);
        let flat = integrate(
            &coulomb(),
            &TractionGrid::new(TractionIntegration::Grid {
                across: 12,
                along: 6,
            }),
            &ContactKinematics {
                patch: patch(),
                ball_centre: Vector3::zeros(),
                slip: Vector3::zeros(),
                relative_spin: spin,
                conditions: ContactConditions::default(),
            },
        );
        let curved = integrate(
            &coulomb(),
            &TractionGrid::new(TractionIntegration::Grid {
                across: 12,
                along: 6,
            }),
            &ContactKinematics {
                patch: p,
                ball_centre: Vector3::zeros(),
                slip: Vector3::zeros(),
                relative_spin: spin,
                conditions: ContactConditions::default(),
            },
        );
        assert!(
            (flat.force - curved.force).norm() > 1e-6,
            "curvature changes the slip field"
        );
    }

    /// The AVX2 build of the integration gives the baseline build's bits
    /// for the EHL rheology (Newtonian to limiting shear), its blend with
    /// boundary friction and Coulomb friction, with slip and spin, on flat
    /// and curved patches, on grids that leave padding lanes and one finer
    /// than the shared pressure levels. Skipped without AVX2.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn avx2_build_is_bit_identical_to_baseline() {
        use crate::traction::mixed::Blended;
        if !std::arch::is_x86_feature_detected!("avx2") {
            return;
        }
        let bits = |r: &TractionResult| -> Vec<u64> {
            r.force
                .iter()
                .chain(r.couple.iter())
                .chain(r.moment.iter())
                .chain([r.dissipation].iter())
                .map(|x| x.to_bits())
                .collect()
        };
        let fluid = crate::traction::ehl::tests::law();
        let boundary = coulomb();
        let blend = Blended {
            fluid: &fluid,
            boundary: &boundary,
            share: 0.3,
        };
        let mut compared = 0;
        for (across, along, curved) in [(12, 6, true), (7, 5, false), (40, 20, true)] {
            let grid = TractionGrid::new(TractionIntegration::Grid { across, along });
            let mut p = patch();
            p.load = 400.0;
            if curved {
                p.deformed_radius = 3.3e-3;
            }
            for k in 0..30 {
                let f = k as f64;
                let kinematics = ContactKinematics {
                    patch: p,
                    ball_centre: Vector3::zeros(),
                    slip: Vector3::new(1e-7 * 10f64.powf(0.25 * f), 2e-4 * (0.7 * f).sin(), 0.0),
                    relative_spin: Vector3::new(0.0, 300.0 * f, -50.0 * (0.3 * f).cos()),
                    conditions: ContactConditions {
                        film: 2e-7,
                        entrainment_speed: 10.0,
                        rolling_velocity: 10.0,
                    },
                };
                let pairs = [
                    (
                        integrate_baseline(&fluid, &grid, &kinematics),
                        // SAFETY: AVX2 was detected above.
                        #[allow(unsafe_code)]
                        unsafe {
                            integrate_avx2(&fluid, &grid, &kinematics)
                        },
                    ),
                    (
                        integrate_baseline(&blend, &grid, &kinematics),
                        #[allow(unsafe_code)]
                        unsafe {
                            integrate_avx2(&blend, &grid, &kinematics)
                        },
                    ),
                    (
                        integrate_baseline(&boundary, &grid, &kinematics),
                        #[allow(unsafe_code)]
                        unsafe {
                            integrate_avx2(&boundary, &grid, &kinematics)
                        },
                    ),
                ];
                for (baseline, avx2) in &pairs {
                    assert!(baseline.force.norm() > 0.0);
                    assert_eq!(bits(baseline), bits(avx2), "{across} × {along}, case {k}");
                    compared += 1;
                }
            }
        }
        assert_eq!(compared, 270);
    }

    #[test]
    fn grid_levels_are_the_distinct_shapes() {
        // 12 × 6: mirror-symmetric in s and t, so 6 × 3 distinct shapes;
        // 7 × 5: 4 × 3.
        for (across, along, levels) in [(12, 6, 18), (7, 5, 12)] {
            let grid = TractionGrid::new(TractionIntegration::Grid { across, along });
            assert_eq!(grid.levels.len(), levels);
            for group in &grid.groups {
                for batch in &group.batches {
                    for k in 0..BATCH {
                        let level = grid.levels[batch.level[k] as usize];
                        if batch.weight[k] > 0.0 {
                            assert_eq!(level.to_bits(), batch.shape[k].to_bits());
                        }
                    }
                }
            }
        }
    }
}
