//! Kalker's simplified theory of rolling contact, FASTSIM (J. J. Kalker,
//! "A fast algorithm for the simplified theory of rolling contact",
//! *Vehicle System Dynamics* 11 (1982) 1–13; Zhang et al. 2025 §2.2; docs/model.md §3,
//! model 4).
//!
//! # Frame and creepages
//! At a contact with normal n (ball centre → P), material flows through
//! the ellipse along x̂ = ±e_roll, the sign of the rolling velocity
//! u·e_roll (u: entrainment, the mean surface velocity relative to the
//! contact point); ŷ = n × x̂. With the sliding velocity s_P of ball
//! material relative to ring material at P and the relative angular
//! velocity Ω = ω_b − ω_ring,
//! ```text
//! ξ = s_P·x̂ / V,   η = s_P·ŷ / V,   φ = Ω·n / V  [1/m],    V = √(|u|² + v_r²)
//! ```
//! v_r (`regularisation_speed`, default 1 mm/s) keeps the creepages finite
//! as the rolling stops: at V → 0 every creepage is large and FASTSIM gives
//! Coulomb sliding, μQ against the slip (the pure-sliding limit). Within
//! |u·e_roll| < v_r the tractions of both flow directions are blended with
//! weights ½(1 ± u·e_roll/v_r), so they stay continuous when the rolling
//! reverses.
//!
//! # Algorithm
//! The rolling-direction semi-axis a_r is the Hertz minor semi-axis b (the
//! short axis lies along the rolling direction in a ball bearing), the
//! lateral b_r the major a (docs/model.md §3). Flexibilities (Kalker 1982)
//! ```text
//! L₁ = 8a_r/(3 G C₁₁),  L₂ = 8a_r/(3 G C₂₂),  L₃ = π a_r √(a_r/b_r)/(4 G C₂₃)
//! L  = (L₁|ξ| + L₂|η| + L₃ c|φ|) / √(ξ² + η² + c²φ²),   c = √(a_r b_r)
//! ```
//! (weights smoothed by [`WEIGHT_SMOOTHING`] so that L is differentiable)
//! with Kalker's C_ij ([`super::kalker`]) and the combined shear modulus G
//! and Poisson ratio ν of the two bodies. The ellipse is cut into `strips`
//! across the rolling direction (midpoints y_i), each into `elements` of
//! length Δx from the leading edge x = −a_i to the trailing edge x = +a_i.
//! On each strip the traction (on the ball, Pa) is zero at the leading
//! edge and marches from element centre to element centre x_k:
//! ```text
//! p_k = p_{k−1} − (1/(L V)) ∫_{x_{k−1}}^{x_k} w dx,   then |p_k| ≤ g(x_k) = μ p_n(x_k)  (slip: scaled onto the bound)
//! ```
//! (the first step integrates from the leading edge; w is linear in x, so
//! the integral is exact at its midpoint).
//! where w is the rigid slip in the contact plane. In slip the step is
//! FASTSIM's backward-Euler form of the slip condition p = −g s/|s|:
//! p_k = g (p_{k−1} − Δx w(x_k)/(L V))/|…| with the rigid slip at the
//! element centre itself, which gives the traction direction the exact
//! lag behind a turning slip direction in deep slip; the midpoint slip
//! would lag by half an element and, under spin, overstate the lateral
//! force (by 17 % at φ = 20 1/m and 47 % at 50 1/m on a 7218B inner
//! contact with 10 elements, against a fine grid). The two are blended by the overshoot
//! 1 − g/|p_tentative| (0 at the bound, so p stays continuous where a
//! cell starts to slip; 1 deep in slip).
//! On a flat contact
//! w = V(ξ − φy, η + φx). The engine also places each strip on the deformed
//! surface across the rolling direction (depth d_i = R_d − √(R_d² − y_i²),
//! as the stress-law integration does, [`super::ellipse`]), which adds the
//! differential (Heathcote) slip of a conforming groove:
//! w_x = s_P·x̂ − Ω_n y − d_i Ω·ŷ, w_y = s_P·ŷ + Ω_n x + d_i Ω·x̂ (exact for
//! the strip's points; d_i = 0 on a flat contact). L is weighted per strip
//! with the strip's creepages (ξ_i, η_i, φ); on a flat contact this is
//! Kalker's L.
//!
//! The traction bound μ p_n uses Kalker's parabolic pressure
//! p_n = 2Q/(π a_r b_r)(1 − x²/a_r² − y²/b_r²) (`bound = "parabolic"`, the
//! default, with which FASTSIM's linear limit is exact) or the Hertz
//! ellipsoid (`"elliptic"`); either is scaled so that its discrete integral
//! is Q, so full sliding gives exactly μQ. Element forces are p_k Δx Δy
//! (midpoint rule), applied at the element centres X; the couple about P, the moment about the ball centre and
//! the dissipated power −Σ dF·w(X) follow from the same points, so the
//! power is exactly what the traction takes from the rigid-body motion
//! (the energy balance closes). The stick fraction is the stuck area over the discretised area.
//!
//! # Accuracy and limits
//! In full stick the march integrates the linear theory exactly at the
//! element centres, which all stick as the creepages → 0: with a single
//! creepage FASTSIM returns Kalker's linear forces
//! F_x = −G c² C₁₁ ξ, F_y = −G c² C₂₂ η, and the spin force
//! F_y = +G c³ C₂₃ φ (in this frame; Kalker's frame has x against the flow
//! and the normal into the lower body, which flips the sign of the φ term),
//! up to the midpoint-rule errors over strips and along them,
//! O(1/strips²) + O(1/elements²) (tests). With several creepages the
//! single weighted L is FASTSIM's known approximation (Kalker 1982 reports
//! ~5–15 % against the exact theory in combined creep and spin).
//! FASTSIM is a half-space theory: the tractions lie in the contact plane
//! and the normal pressure does not change with them.

use super::kalker::{self, CreepCoefficients};
use super::{ContactKinematics, ContactPatch, TractionResult};
use crate::error::{InvalidParameter, require_positive};
use nalgebra::{Vector2, Vector3};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Relative smoothing of the weights of Kalker's L: |ξ| → √(ξ² + ε²)
/// (η and cφ alike) with ε = 1e-4 √(ξ² + η² + c²φ²), so that the
/// tractions are differentiable where one creepage changes sign while
/// others do not (the stiff integrator's and the quasi-static solver's
/// Jacobians; a kink there stalls Newton). It changes L by < 0.03 %.
pub const WEIGHT_SMOOTHING: f64 = 1e-4;

/// Strips marched together (instruction-level parallelism).
const LANES: usize = 8;

/// One strip's constants during the march.
#[derive(Debug, Clone, Copy, Default)]
struct Strip {
    /// A real strip (padding lanes are not).
    active: bool,
    /// Strip centre y \[m\].
    y: f64,
    /// Half chord a_i \[m\].
    half: f64,
    /// Element length Δx \[m\] (0 for padding).
    dx: f64,
    /// Depth of the deformed surface d_i \[m\].
    depth: f64,
    /// Δx/(L V) \[Pa·s/m\]: traction per unit rigid slip.
    gain: f64,
    /// Rigid slip along x̂, w_x \[m/s\] (constant along the strip).
    rate_x: f64,
    /// Translational rigid slip along ŷ \[m/s\] (spin part apart).
    slip_y: f64,
    /// μ p_n scale of the strip \[Pa\] (times the element shape).
    limit: f64,
}

/// What a lane group's strip set-up reads from the contact.
struct SetUp<'a, Y: Fn(usize) -> f64> {
    strip_y: &'a Y,
    across: f64,
    along: f64,
    dt: f64,
    curved: bool,
    deformed_radius: f64,
    /// Rigid slip at P along x̂ and ŷ \[m/s\].
    slip: (f64, f64),
    /// Relative spin about n, x̂, ŷ \[rad/s\].
    spin: (f64, f64, f64),
    speed: f64,
    /// c = √(ab) and the spin creepage φ of Kalker's weight.
    cc: f64,
    phi: f64,
    /// L₁, L₂, L₃.
    flexibilities: (f64, f64, f64),
    bound_scale: f64,
}

/// Largest accepted number of strips or elements per strip.
pub const MAX_DIVISIONS: usize = 1000;

/// The normal pressure that bounds the traction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum TractionBound {
    /// Kalker's parabolic p = 2Q/(πab)(1 − x²/a² − y²/b²) (FASTSIM's own).
    #[default]
    Parabolic,
    /// The Hertz ellipsoid p = 3Q/(2πab) √(1 − x²/a² − y²/b²).
    Elliptic,
}

/// FASTSIM parameters (case file: `traction.law = "fastsim"`).
///
/// One flat contact (semi-axes 2.26 mm across and 0.276 mm along the
/// rolling direction, 2088 N, steel) rolling at 10 m/s with a small
/// longitudinal slip: the force is Kalker's linear law, and at large slip
/// it saturates at μQ:
/// ```
/// use nalgebra::Vector3;
/// use rolldyn::traction::{ContactConditions, ContactKinematics, ContactPatch, Fastsim};
///
/// let law = Fastsim::new(0.1, 76.9e9, 0.3);
/// let patch = ContactPatch {
///     point: Vector3::zeros(),
///     normal: Vector3::z(),
///     rolling_direction: Vector3::x(),
///     semi_major: 2.2609e-3,
///     semi_minor: 0.2761e-3,
///     load: 2088.0,
///     deformed_radius: f64::INFINITY,
/// };
/// let speed = 10.0;
/// let rolling = ContactConditions { film: 0.0, entrainment_speed: speed, rolling_velocity: speed };
/// let force = |creepage: f64| {
///     let slip = Vector3::new(creepage * speed, 0.0, 0.0);
///     let kinematics = ContactKinematics {
///         patch,
///         ball_centre: Vector3::new(0.0, 0.0, -0.02),
///         slip,
///         relative_spin: Vector3::zeros(),
///         conditions: rolling,
///     };
///     law.evaluate(&kinematics).force
/// };
/// // Linear theory: F_x = −G c² C₁₁ ξ with c² = a b.
/// let creepage = 1e-6;
/// let c11 = law.coefficients(&patch).longitudinal;
/// let linear = -76.9e9 * patch.semi_major * patch.semi_minor * c11 * creepage;
/// assert!((force(creepage).x / linear - 1.0).abs() < 0.02);
/// // Full slip: μQ against the slip.
/// assert!((force(0.1).x + 0.1 * 2088.0).abs() < 1e-6 * 2088.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Fastsim {
    /// Friction coefficient μ ≥ 0.
    pub friction: f64,
    /// Strips across the rolling direction.
    pub strips: usize,
    /// Elements per strip along the rolling direction.
    pub elements: usize,
    /// Traction bound.
    pub bound: TractionBound,
    /// Combined shear modulus G, 1/G = ½(1/G₁ + 1/G₂) \[Pa\].
    pub shear_modulus: f64,
    /// Combined Poisson ratio ν = ½ G (ν₁/G₁ + ν₂/G₂), in [0, 0.5].
    pub poisson_ratio: f64,
    /// Regularisation speed v_r of the creepages \[m/s\].
    pub regularisation_speed: f64,
}

/// Default strips across the ellipse.
pub const DEFAULT_STRIPS: usize = 16;
/// Default elements per strip.
pub const DEFAULT_ELEMENTS: usize = 10;
/// Default regularisation speed v_r \[m/s\].
pub const DEFAULT_REGULARISATION_SPEED: f64 = 1e-3;

/// Kalker's combined elastic constants of two bodies (E, ν each):
/// 1/G = ½(1/G₁ + 1/G₂), ν = ½ G (ν₁/G₁ + ν₂/G₂), G_i = E_i/(2(1 + ν_i)).
pub fn combined_elastic_constants(
    first: &crate::material::Material,
    second: &crate::material::Material,
) -> (f64, f64) {
    let g1 = first.elastic_modulus / (2.0 * (1.0 + first.poisson_ratio));
    let g2 = second.elastic_modulus / (2.0 * (1.0 + second.poisson_ratio));
    let g = 2.0 / (1.0 / g1 + 1.0 / g2);
    let nu = 0.5 * g * (first.poisson_ratio / g1 + second.poisson_ratio / g2);
    (g, nu)
}

/// One element of the stick/slip map (`rolldyn traction --map`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapCell {
    /// Element centre along the flow direction x̂, from the contact centre \[m\].
    pub x: f64,
    /// Strip centre along ŷ = n × x̂ \[m\].
    pub y: f64,
    /// Traction on the ball at the element centre (x̂, ŷ components) \[Pa\].
    pub traction: Vector2<f64>,
    /// Traction bound μ p_n there \[Pa\].
    pub bound: f64,
    /// Whether the element sticks.
    pub stick: bool,
}

impl MapCell {
    /// Header of the stick/slip map CSV (`rolldyn traction --map`).
    pub const CSV_HEADER: &'static str = "x_m,y_m,traction_x_pa,traction_y_pa,bound_pa,state";

    /// This cell as a CSV row (no newline), columns as [`Self::CSV_HEADER`].
    pub fn csv_row(&self) -> String {
        format!(
            "{:e},{:e},{:e},{:e},{:e},{}",
            self.x,
            self.y,
            self.traction.x,
            self.traction.y,
            self.bound,
            if self.stick { "stick" } else { "slip" }
        )
    }
}

/// Creepages and stick fraction of a FASTSIM contact.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Creep {
    /// Longitudinal creepage ξ \[-\].
    pub longitudinal: f64,
    /// Lateral creepage η \[-\].
    pub lateral: f64,
    /// Spin creepage φ \[1/m\].
    pub spin: f64,
    /// Stuck fraction of the contact area \[-\].
    pub stick_fraction: f64,
}

/// The flow-direction rule of the contact models that integrate the
/// ellipse along the flow (FASTSIM, [`super::table`]): `one_direction(d,
/// dominant)` solves the contact with the material flowing along d · e_roll
/// (d = ±1). Within |u·e_roll| < v_r (`regularisation_speed`) both
/// directions are solved and blended with weights ½(1 ± u·e_roll/v_r), so
/// the tractions stay continuous when the rolling reverses; elsewhere only
/// the flow direction of the rolling is. The result carries the dominant
/// direction's creepages and the blended stick fraction; its `moment` is
/// left to the caller.
pub(crate) fn blend_flow_directions(
    rolling: f64,
    regularisation_speed: f64,
    mut one_direction: impl FnMut(f64, bool) -> (TractionResult, Creep),
) -> TractionResult {
    let v_r = regularisation_speed;
    let forward = if rolling >= 0.0 { 1.0 } else { -1.0 };
    let weight = if rolling.abs() < v_r {
        0.5 * (1.0 + rolling / v_r)
    } else if rolling > 0.0 {
        1.0
    } else {
        0.0
    };
    let dominant = one_direction(forward, true);
    let (mut out, creep) = if weight == 0.0 || weight == 1.0 {
        dominant
    } else {
        let other = one_direction(-forward, false);
        let w = if forward > 0.0 { weight } else { 1.0 - weight };
        let (a, ca) = dominant;
        let (b, cb) = other;
        let mix = |x: f64, y: f64| w * x + (1.0 - w) * y;
        (
            TractionResult {
                force: a.force * w + b.force * (1.0 - w),
                moment: Vector3::zeros(),
                couple: a.couple * w + b.couple * (1.0 - w),
                dissipation: mix(a.dissipation, b.dissipation),
                creep: None,
            },
            Creep {
                stick_fraction: mix(ca.stick_fraction, cb.stick_fraction),
                ..ca
            },
        )
    };
    out.creep = Some(creep);
    out
}

impl Fastsim {
    /// A FASTSIM model with the default discretisation and bound.
    pub fn new(friction: f64, shear_modulus: f64, poisson_ratio: f64) -> Self {
        Self {
            friction,
            strips: DEFAULT_STRIPS,
            elements: DEFAULT_ELEMENTS,
            bound: TractionBound::Parabolic,
            shear_modulus,
            poisson_ratio,
            regularisation_speed: DEFAULT_REGULARISATION_SPEED,
        }
    }

    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), InvalidParameter> {
        super::require_friction("friction", self.friction)?;
        for (field, n) in [("strips", self.strips), ("elements", self.elements)] {
            if !(1..=MAX_DIVISIONS).contains(&n) {
                return Err(InvalidParameter::new(
                    field,
                    n,
                    format!("must be between 1 and {MAX_DIVISIONS}"),
                ));
            }
        }
        require_positive("shear_modulus", self.shear_modulus)?;
        kalker::check_poisson_ratio(self.poisson_ratio)?;
        require_positive("regularisation_speed", self.regularisation_speed)
    }

    /// Kalker's creep coefficients of `patch`.
    pub fn coefficients(&self, patch: &ContactPatch) -> CreepCoefficients {
        kalker::creep_coefficients(patch.semi_minor, patch.semi_major, self.poisson_ratio)
    }

    /// Tractions of one contact in motion `kinematics` (`conditions`
    /// carries |u| and u·e_roll). Allocation-free.
    pub fn evaluate(&self, kinematics: &ContactKinematics) -> TractionResult {
        self.evaluate_mapped(kinematics, |_| {})
    }

    /// As [`Self::evaluate`], calling `map` for every element of the
    /// dominant flow direction (the stick/slip map).
    pub fn evaluate_mapped(
        &self,
        kinematics: &ContactKinematics,
        mut map: impl FnMut(&MapCell),
    ) -> TractionResult {
        let ContactKinematics {
            patch,
            ball_centre,
            conditions,
            ..
        } = kinematics;
        if patch.load <= 0.0 {
            return TractionResult::default();
        }
        let speed = conditions
            .entrainment_speed
            .hypot(self.regularisation_speed);
        let coefficients = self.coefficients(patch);
        let mut out = blend_flow_directions(
            conditions.rolling_velocity,
            self.regularisation_speed,
            |direction, dominant| {
                // The map shows the dominant flow direction only.
                self.march(
                    kinematics,
                    speed,
                    direction,
                    &coefficients,
                    &mut |cell: &MapCell| {
                        if dominant {
                            map(cell)
                        }
                    },
                )
            },
        );
        out.moment = out.couple + (patch.point - ball_centre).cross(&out.force);
        out
    }

    /// The strips `first`.. of one lane group, stage by stage across the
    /// lanes so that their square roots and divisions overlap (one strip's
    /// chain of six runs at the latency of the divide unit). Each lane
    /// computes exactly what a strip on its own would; lanes past the last
    /// strip are zero-width padding.
    #[inline(always)]
    fn set_up_strips<Y: Fn(usize) -> f64>(
        &self,
        first: usize,
        strips: usize,
        c: SetUp<'_, Y>,
        separable: &impl Fn(f64) -> f64,
    ) -> [Strip; LANES] {
        let (s_x, s_y) = c.slip;
        let (w_n, w_x, w_y) = c.spin;
        let (l1, l2, l3) = c.flexibilities;
        let mut y = [0.0; LANES];
        let mut k = [0.0; LANES];
        let mut depth = [0.0; LANES];
        for l in 0..LANES {
            y[l] = (c.strip_y)((first + l).min(strips - 1));
            k[l] = (1.0 - (y[l] / c.across).powi(2)).max(0.0);
        }
        if c.curved {
            let r = c.deformed_radius;
            for l in 0..LANES {
                depth[l] = r - (r * r - y[l] * y[l]).max(0.0).sqrt();
            }
        }
        let mut half = [0.0; LANES];
        let mut slip_x = [0.0; LANES];
        let mut slip_y = [0.0; LANES];
        let mut norm = [0.0; LANES];
        let mut weights = [[0.0; 3]; LANES];
        for l in 0..LANES {
            half[l] = c.along * k[l].sqrt();
            // The strip's translational slip (spin terms apart).
            slip_x[l] = s_x - depth[l] * w_y;
            slip_y[l] = s_y + depth[l] * w_x;
            let (xi, eta) = (slip_x[l] / c.speed, slip_y[l] / c.speed);
            // Kalker's weights |ξ|, |η|, c|φ|, smoothed over
            // WEIGHT_SMOOTHING of their norm so that L is differentiable
            // where one creepage changes sign.
            norm[l] = (xi * xi + eta * eta + c.cc * c.cc * c.phi * c.phi).sqrt();
            let eps = WEIGHT_SMOOTHING * norm[l];
            // √(v² + ε²) directly: creepages are O(1), far from overflow,
            // and libm's `hypot` (careful scaling) cost 18 % of the
            // Zhang et al. 2025 ramp.
            let smooth = |v: f64| (v * v + eps * eps).sqrt();
            weights[l] = [smooth(xi), smooth(eta), smooth(c.cc * c.phi)];
        }
        let mut lane = [Strip::default(); LANES];
        for l in 0..LANES {
            let [wx, wy, ws] = weights[l];
            let flexibility = if norm[l] > 0.0 {
                (l1 * wx + l2 * wy + l3 * ws) / (wx * wx + wy * wy + ws * ws).sqrt()
            } else {
                l1
            };
            if first + l < strips {
                lane[l] = Strip {
                    active: true,
                    y: y[l],
                    half: half[l],
                    dx: half[l] * c.dt,
                    depth: depth[l],
                    gain: half[l] * c.dt / (flexibility * c.speed),
                    rate_x: slip_x[l] - w_n * y[l],
                    slip_y: slip_y[l],
                    limit: c.bound_scale * separable(k[l]),
                };
            }
        }
        lane
    }

    /// One FASTSIM pass with the flow along `direction` · e_roll: the
    /// march compiled for AVX2 where the processor has it (detected at run
    /// time), else for the target's baseline (SSE2 on x86-64).
    ///
    /// Both builds run the same IEEE operations in the same order
    /// (additions, multiplications, divisions and square roots, each
    /// correctly rounded; Rust never fuses a multiply and an add on its
    /// own), four lanes to an instruction instead of two, so their results
    /// are bit-identical (test `avx2_march_is_bit_identical_to_baseline`).
    /// Measured on the Zhang et al. 2025 ramp: −20 % wall (docs/performance.md).
    fn march(
        &self,
        kinematics: &ContactKinematics,
        speed: f64,
        direction: f64,
        c: &CreepCoefficients,
        map: &mut impl FnMut(&MapCell),
    ) -> (TractionResult, Creep) {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: `march_avx2` requires AVX2 only, and the processor
            // has it (detected just above).
            #[allow(unsafe_code)]
            return unsafe { self.march_avx2(kinematics, speed, direction, c, map) };
        }
        self.march_baseline(kinematics, speed, direction, c, map)
    }

    /// [`Self::march_baseline`] compiled with AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn march_avx2(
        &self,
        kinematics: &ContactKinematics,
        speed: f64,
        direction: f64,
        c: &CreepCoefficients,
        map: &mut impl FnMut(&MapCell),
    ) -> (TractionResult, Creep) {
        self.march_baseline(kinematics, speed, direction, c, map)
    }

    /// The march itself, inlined into both builds of [`Self::march`].
    #[inline(always)]
    fn march_baseline(
        &self,
        kinematics: &ContactKinematics,
        speed: f64,
        direction: f64,
        c: &CreepCoefficients,
        map: &mut impl FnMut(&MapCell),
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
        let g = self.shear_modulus;
        let l1 = 8.0 * along / (3.0 * g * c.longitudinal);
        let l2 = 8.0 * along / (3.0 * g * c.lateral);
        let l3 = PI * along * (along / across).sqrt() / (4.0 * g * c.spin_lateral);
        let cc = (along * across).sqrt();
        let (s_x, s_y) = (slip.dot(&ex), slip.dot(&ey));
        let (w_n, w_x, w_y) = (spin.dot(&n), spin.dot(&ex), spin.dot(&ey));
        let phi = w_n / speed;
        let (strips, elements) = (self.strips.max(1), self.elements.max(1));
        let dy = 2.0 * across / strips as f64;
        let dt = 2.0 / elements as f64;
        let strip_y = |i: usize| -across + (i as f64 + 0.5) * dy;
        // The bound's shape separates: (1 − x²/a_r² − y²/b_r²) = k (1 − t²)
        // with k = 1 − y²/b_r² and t = x/a_i; elliptic takes the root.
        let separable = |v: f64| match self.bound {
            TractionBound::Parabolic => v.max(0.0),
            TractionBound::Elliptic => v.max(0.0).sqrt(),
        };
        let element_shape = |e: usize| {
            let t = -1.0 + (e as f64 + 0.5) * dt;
            separable(1.0 - t * t)
        };
        // Discrete Σ shape·dA with unit peak, to scale the bound to Q.
        let along_sum: f64 = (0..elements).map(element_shape).sum();
        let (mut raw, mut area) = (0.0, 0.0);
        for i in 0..strips {
            let k = (1.0 - (strip_y(i) / across).powi(2)).max(0.0);
            let half = along * k.sqrt();
            raw += separable(k) * along_sum * half * dt * dy;
            area += 2.0 * half * dy;
        }
        let bound_scale = if raw > 0.0 {
            self.friction * patch.load / raw
        } else {
            0.0
        };
        let curved = patch.deformed_radius.is_finite();
        let (mut fx, mut fy, mut mx, mut my, mut mn) = (0.0, 0.0, 0.0, 0.0, 0.0);
        let (mut power, mut stuck) = (0.0, 0.0);
        // Strips are independent: march LANES of them together so that their
        // (sequential) element recurrences overlap in the pipeline. Lanes
        // past the last strip have zero width and contribute nothing.
        for first in (0..strips).step_by(LANES) {
            let lane = self.set_up_strips(
                first,
                strips,
                SetUp {
                    strip_y: &strip_y,
                    across,
                    along,
                    dt,
                    curved,
                    deformed_radius: patch.deformed_radius,
                    slip: (s_x, s_y),
                    spin: (w_n, w_x, w_y),
                    speed,
                    cc,
                    phi,
                    flexibilities: (l1, l2, l3),
                    bound_scale,
                },
                &separable,
            );
            let sums = march_lanes(&lane, elements, (dt, dy), w_n, &element_shape, map);
            for (l, st) in lane.iter().enumerate() {
                fx += sums.fx[l];
                fy += sums.fy[l];
                mn += sums.mn[l];
                power += sums.power[l];
                stuck += sums.stuck[l];
                // (x x̂ + y ŷ − d n) × (f_x x̂ + f_y ŷ): the −d n part.
                mx += st.depth * sums.fy[l];
                my -= st.depth * sums.fx[l];
            }
        }
        let result = TractionResult {
            force: fx * ex + fy * ey,
            moment: Vector3::zeros(),
            couple: mx * ex + my * ey + mn * n,
            dissipation: power,
            creep: None,
        };
        let creep = Creep {
            longitudinal: s_x / speed,
            lateral: s_y / speed,
            spin: phi,
            stick_fraction: if area > 0.0 {
                (stuck / area).min(1.0)
            } else {
                0.0
            },
        };
        (result, creep)
    }
}

/// One group of [`LANES`] strips' sums over their elements: the forces
/// along x̂ and ŷ, the moment about n, the power and the stuck area, one
/// entry per lane (kept apart so that the additions do not form one serial
/// chain).
struct LaneSums {
    fx: [f64; LANES],
    fy: [f64; LANES],
    mn: [f64; LANES],
    power: [f64; LANES],
    stuck: [f64; LANES],
}

/// Marches a group of strips through their `elements` elements together
/// (cell sizes `(dt, dy)`, spin w_n about the normal), so that the strips'
/// sequential element recurrences overlap in the pipeline; `map` receives
/// every cell of the active strips. Inlined into both builds of the march
/// (`Fastsim::march`), the AVX2 one and the baseline.
#[inline(always)]
fn march_lanes(
    lane: &[Strip; LANES],
    elements: usize,
    (dt, dy): (f64, f64),
    w_n: f64,
    element_shape: &impl Fn(usize) -> f64,
    map: &mut impl FnMut(&MapCell),
) -> LaneSums {
    let mut px = [0.0; LANES];
    let mut py = [0.0; LANES];
    let mut sums = LaneSums {
        fx: [0.0; LANES],
        fy: [0.0; LANES],
        mn: [0.0; LANES],
        power: [0.0; LANES],
        stuck: [0.0; LANES],
    };
    for e in 0..elements {
        let t = -1.0 + (e as f64 + 0.5) * dt;
        let shape = element_shape(e);
        // Rigid slip integrated exactly (it is linear in x) from the
        // previous element centre, or from the leading edge.
        let (step, back) = if e == 0 { (0.5, 0.25) } else { (1.0, 0.5) };
        for l in 0..LANES {
            let st = &lane[l];
            let x = st.half * t;
            let x_between = x - back * st.dx;
            let gain = step * st.gain;
            let tx = px[l] - gain * st.rate_x;
            let ty = py[l] - gain * (st.slip_y + w_n * x_between);
            let limit = st.limit * shape;
            let size2 = tx * tx + ty * ty;
            let stick = size2 <= limit * limit;
            if stick {
                px[l] = tx;
                py[l] = ty;
            } else {
                // The slip step: the rigid slip at x_k rather than
                // between the centres, blended in by the overshoot.
                let excess = 1.0 - limit / size2.sqrt();
                let ty = ty - excess * gain * w_n * back * st.dx;
                let scale = limit / (tx * tx + ty * ty).sqrt();
                px[l] = tx * scale;
                py[l] = ty * scale;
            }
            let cell = st.dx * dy;
            let (dfx, dfy) = (px[l] * cell, py[l] * cell);
            sums.fx[l] += dfx;
            sums.fy[l] += dfy;
            sums.mn[l] += x * dfy - st.y * dfx;
            sums.power[l] -= dfx * st.rate_x + dfy * (st.slip_y + w_n * x);
            if stick {
                sums.stuck[l] += cell;
            }
            if st.active {
                map(&MapCell {
                    x,
                    y: st.y,
                    traction: Vector2::new(px[l], py[l]),
                    bound: limit,
                    stick,
                });
            }
        }
    }
    sums
}

#[cfg(test)]
mod tests;
