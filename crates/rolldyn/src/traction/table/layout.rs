//! The table's coordinates: normalised creepages, their magnitude and
//! direction, and the node grid over them (shared by the builder and the
//! interpolation, so that both read the same numbers).

use crate::traction::kalker;

/// Outputs per node: F_x/(μQ), F_y/(μQ), M_n/(μQ b), Σy²p_x dA/(μQ b²),
/// Σy²p_y dA/(μQ b²), stick fraction. The table stores the first five
/// divided by u (their secant slope, finite at u = 0, where it is the
/// linear theory's), the stick fraction as is.
pub const OUTPUTS: usize = 6;

/// How many outputs are stored as secant slopes (divided by u).
pub const SLOPES: usize = 5;

/// u at which the u = 0 node's slope is evaluated (the linear theory:
/// the whole contact but its trailing edge adheres).
pub const LINEAR_MAGNITUDE: f64 = 1e-4;

/// Dimensions of the node grid, in the order of storage (the last runs
/// fastest): ellipse ratio, α, β, γ, magnitude.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout {
    /// Nodes over log₂(a/b) from [`Self::LOG_RATIO_MIN`] to 0 (a/b = 1).
    pub ratios: usize,
    /// Nodes over α ∈ [0, π/2] (angle of the direction from the Heathcote axis).
    pub alphas: usize,
    /// Nodes over β ∈ [0, π] (angle from the spin axis).
    pub betas: usize,
    /// Nodes over γ ∈ [0, π] (azimuth from ξ towards η).
    pub gammas: usize,
    /// Nodes over u = r/(1 + r) ∈ [0, 1], evenly spaced.
    pub magnitudes: usize,
}

impl Layout {
    /// log₂ of the slenderest tabulated ratio a/b (1/32).
    pub const LOG_RATIO_MIN: f64 = -5.0;

    /// The embedded table's grid (docs/dynamics.md): 11 ratios, α at
    /// 11.25°, β at 11.25°, γ at 22.5°, 11 magnitudes.
    pub const EMBEDDED: Layout = Layout {
        ratios: 11,
        alphas: 9,
        betas: 17,
        gammas: 9,
        magnitudes: 11,
    };

    /// Number of nodes.
    pub fn nodes(&self) -> usize {
        self.ratios * self.alphas * self.betas * self.gammas * self.magnitudes
    }

    /// Index of node (ratio, α, β, γ, magnitude) in storage order.
    #[inline(always)]
    pub fn index(&self, g: usize, a: usize, b: usize, c: usize, u: usize) -> usize {
        (((g * self.alphas + a) * self.betas + b) * self.gammas + c) * self.magnitudes + u
    }

    /// Ellipse ratio a/b of node `g`.
    pub fn ratio(&self, g: usize) -> f64 {
        let t = g as f64 / (self.ratios - 1) as f64;
        (Self::LOG_RATIO_MIN * (1.0 - t)).exp2()
    }

    /// The angle of node `k` of `count` over [0, `range`].
    pub fn angle(k: usize, count: usize, range: f64) -> f64 {
        range * k as f64 / (count - 1) as f64
    }

    /// u of magnitude node `k`.
    pub fn magnitude(&self, k: usize) -> f64 {
        k as f64 / (self.magnitudes - 1) as f64
    }
}

/// Scale factors from creepages to the normalised ones of a contact with
/// semi-axes a (along the rolling direction) and b (across), combined
/// shear modulus G, Poisson ratio ν, load Q and friction μ:
/// ```text
/// ξ* = k C₁₁ ξ,  η* = k C₂₂ η,  φ* = k C₁₁ φ b/√5,  χ* = k C₁₁ χ b²/5,
/// k = G c²/(3μQ),  c = √(ab)
/// ```
/// with Kalker's C_ij. A normalised creepage of 1 alone is about where the
/// contact slides fully. Spin and the Heathcote creepage χ (slip −χy²
/// along the flow) are measured by the longitudinal slip they cause at the
/// pressure-weighted root mean square of y, b/√5, so that the four are
/// alike in how much of the contact they make slide: the linear theory's
/// spin normalisation (by C₂₃, the lateral force) would compress the range
/// where spin takes over the slip into a few degrees of direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Normalisation {
    /// [ξ, η, φ, χ] → [ξ*, η*, φ*, χ*].
    pub scale: [f64; 4],
}

impl Normalisation {
    /// The factors of a contact.
    pub fn new(
        along: f64,
        across: f64,
        shear_modulus: f64,
        poisson_ratio: f64,
        load: f64,
        friction: f64,
    ) -> Self {
        let c = kalker::creep_coefficients(along, across, poisson_ratio);
        let cc = (along * across).sqrt();
        let base = shear_modulus * cc * cc / (3.0 * friction * load);
        let longitudinal = base * c.longitudinal;
        Self {
            scale: [
                longitudinal,
                base * c.lateral,
                longitudinal * across / 5f64.sqrt(),
                longitudinal * across * across / 5.0,
            ],
        }
    }
}

/// Where a normalised creepage lies on the grid: its magnitude u and
/// direction angles (α, β, γ), and the symmetry that brought it to the
/// tabulated quarter (χ* ≥ 0, η* ≥ 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Direction {
    /// u = r/(1 + r), r = |(ξ*, η*, φ*, χ*)|.
    pub magnitude: f64,
    /// α = acos(χ*/r) ∈ [0, π/2].
    pub alpha: f64,
    /// β = angle of (ξ*, η*, φ*) from the φ* axis ∈ [0, π].
    pub beta: f64,
    /// γ = atan2(η*, ξ*) ∈ [0, π].
    pub gamma: f64,
    /// All signs reversed (the outputs change sign).
    pub negated: bool,
    /// y reflected (η*, φ* reversed; F_y, M_n, Σy²p_y change sign).
    pub reflected: bool,
}

impl Direction {
    /// The grid coordinates of normalised creepages [ξ*, η*, φ*, χ*].
    ///
    /// Kalker's problem is odd in the creepages (all reversed, all
    /// tractions reverse) and symmetric in y (η and φ reversed: F_x and
    /// the even moments stay, F_y and M_n reverse).
    pub fn of(normalised: [f64; 4]) -> Self {
        let [mut xi, mut eta, mut phi, mut chi] = normalised;
        let negated = chi < 0.0;
        if negated {
            (xi, eta, phi, chi) = (-xi, -eta, -phi, -chi);
        }
        let reflected = eta < 0.0;
        if reflected {
            (eta, phi) = (-eta, -phi);
        }
        let in_plane = (xi * xi + eta * eta).sqrt();
        let creep = (in_plane * in_plane + phi * phi).sqrt();
        let r = (creep * creep + chi * chi).sqrt();
        Self {
            magnitude: r / (1.0 + r),
            alpha: creep.atan2(chi),
            beta: in_plane.atan2(phi),
            gamma: eta.atan2(xi),
            negated,
            reflected,
        }
    }

    /// The normalised creepages of grid coordinates (u < 1), in the
    /// tabulated quarter.
    pub fn creepages(magnitude: f64, alpha: f64, beta: f64, gamma: f64) -> [f64; 4] {
        let r = magnitude / (1.0 - magnitude);
        Self::unit(alpha, beta, gamma).map(|v| r * v)
    }

    /// The unit direction [ξ*, η*, φ*, χ*] of angles (α, β, γ).
    pub fn unit(alpha: f64, beta: f64, gamma: f64) -> [f64; 4] {
        let (sa, ca) = alpha.sin_cos();
        let (sb, cb) = beta.sin_cos();
        let (sg, cg) = gamma.sin_cos();
        [sa * sb * cg, sa * sb * sg, sa * cb, ca]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn directions_round_trip_and_fold_by_symmetry() {
        for &(alpha, beta, gamma) in &[(0.3, 1.1, 2.0), (1.2, 0.2, 0.4), (0.9, 2.9, 3.0)] {
            let v = Direction::creepages(0.6, alpha, beta, gamma);
            let d = Direction::of(v);
            assert!((d.magnitude - 0.6).abs() < 1e-14);
            assert!((d.alpha - alpha).abs() < 1e-12);
            assert!((d.beta - beta).abs() < 1e-12);
            assert!((d.gamma - gamma).abs() < 1e-12);
            assert!(!d.negated && !d.reflected);
            let all = Direction::of(v.map(|x| -x));
            assert!(all.negated && !all.reflected && (all.beta - beta).abs() < 1e-12);
            let y = Direction::of([v[0], -v[1], -v[2], v[3]]);
            assert!(y.reflected && !y.negated && (y.gamma - gamma).abs() < 1e-12);
        }
    }

    #[test]
    fn node_layout_spans_its_ranges() {
        let l = Layout {
            ratios: 11,
            alphas: 5,
            betas: 9,
            gammas: 9,
            magnitudes: 11,
        };
        assert!((l.ratio(0) - 1.0 / 32.0).abs() < 1e-15);
        assert_eq!(l.ratio(10), 1.0);
        assert_eq!((l.magnitude(0), l.magnitude(10)), (0.0, 1.0));
        assert_eq!(l.index(10, 4, 8, 8, 10), l.nodes() - 1);
    }
}
