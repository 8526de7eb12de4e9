//! Natural frequencies and mode shapes of the inner ring (with what turns
//! with it) on the bearing: the undamped eigenproblem K φ = ω² M φ with K
//! the 5×5 bearing stiffness of a quasi-static solution (docs/model.md §7) and
//! M = diag(m, m, m, I_t, I_t) over (x, y, z, θ_y, θ_z). Zhang et al. 2020 eqs
//! 41–46 reduce this to f = (1/2π)√(K/M) per direction (printed with 0.5π;
//! docs/model.md §4).
//!
//! K of a running bearing is not exactly symmetric (centrifugal and
//! gyroscopic ball terms); its symmetric part is used, and the size of the
//! skew part is reported. Ring gyroscopics are left out.

use nalgebra::{Matrix5, SymmetricEigen, Vector5};

/// One natural mode.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mode {
    /// Natural frequency f \[Hz\] (0 for a direction without stiffness).
    pub frequency: f64,
    /// Mode shape over (x, y, z \[m\], θ_y, θ_z \[rad\]), mass-normalised
    /// then scaled to unit largest component.
    pub shape: [f64; 5],
}

/// Modes of the ring, lowest first, and the relative size of K's skew part
/// ‖K − Kᵀ‖/‖K‖.
pub fn natural_modes(stiffness: &[[f64; 5]; 5], mass: f64, tilt_inertia: f64) -> (Vec<Mode>, f64) {
    let k = Matrix5::from_fn(|i, j| stiffness[i][j]);
    let symmetric = 0.5 * (k + k.transpose());
    let skew = (k - k.transpose()).norm() / k.norm().max(f64::MIN_POSITIVE);
    let inertia = Vector5::new(mass, mass, mass, tilt_inertia, tilt_inertia);
    let scale = inertia.map(|m| 1.0 / m.sqrt());
    // M^{-1/2} K M^{-1/2}: symmetric, eigenvalues ω².
    let a = Matrix5::from_fn(|i, j| scale[i] * symmetric[(i, j)] * scale[j]);
    let eigen = SymmetricEigen::new(a);
    let mut modes: Vec<Mode> = (0..5)
        .map(|i| {
            let omega2 = eigen.eigenvalues[i].max(0.0);
            let v = eigen.eigenvectors.column(i);
            let mut shape = [0.0; 5];
            for (s, (vi, si)) in shape.iter_mut().zip(v.iter().zip(scale.iter())) {
                *s = vi * si;
            }
            let largest = shape
                .iter()
                .copied()
                .fold(0.0f64, |m, x| if x.abs() > m.abs() { x } else { m });
            if largest != 0.0 {
                shape.iter_mut().for_each(|s| *s /= largest);
            }
            Mode {
                frequency: omega2.sqrt() / std::f64::consts::TAU,
                shape,
            }
        })
        .collect();
    modes.sort_by(|a, b| a.frequency.total_cmp(&b.frequency));
    (modes, skew)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn single_degree_modes_are_sqrt_k_over_m() {
        let mut k = [[0.0; 5]; 5];
        k[0][0] = 4e8; // axial
        k[1][1] = 1e8;
        k[2][2] = 1e8;
        k[3][3] = 2e4; // tilt, N·m/rad
        k[4][4] = 2e4;
        let (m, it) = (0.5, 1e-4);
        let (modes, skew) = natural_modes(&k, m, it);
        assert_eq!(skew, 0.0);
        let f = |kk: f64, mm: f64| (kk / mm).sqrt() / std::f64::consts::TAU;
        let mut expected = [f(4e8, m), f(1e8, m), f(1e8, m), f(2e4, it), f(2e4, it)];
        expected.sort_by(f64::total_cmp);
        for (mode, e) in modes.iter().zip(expected) {
            assert!(
                (mode.frequency / e - 1.0).abs() < 1e-12,
                "{} vs {e}",
                mode.frequency
            );
        }
        // The axial mode moves x only.
        let axial = modes
            .iter()
            .find(|mode| (mode.frequency / f(4e8, m) - 1.0).abs() < 1e-9)
            .unwrap();
        assert_eq!(axial.shape[0], 1.0);
        assert!(axial.shape[1..].iter().all(|s| s.abs() < 1e-12));
    }

    #[test]
    fn coupled_radial_tilt_mode_matches_the_two_by_two_solution() {
        // y and θ_z coupled: K = [[k, c], [c, kt]].
        let (k, c, kt, m, it) = (1e8, 2e5, 1e4, 0.4, 2e-4);
        let mut kk = [[0.0; 5]; 5];
        kk[1][1] = k;
        kk[1][4] = c;
        kk[4][1] = c;
        kk[4][4] = kt;
        let (modes, _) = natural_modes(&kk, m, it);
        // det(K − ω² M) = 0 for the 2×2 block.
        let (a, b, cc) = (m * it, -(k * it + kt * m), k * kt - c * c);
        let disc = (b * b - 4.0 * a * cc).sqrt();
        let w2 = [(-b - disc) / (2.0 * a), (-b + disc) / (2.0 * a)];
        let nonzero: Vec<f64> = modes
            .iter()
            .map(|m| m.frequency)
            .filter(|f| *f > 0.0)
            .collect();
        assert_eq!(nonzero.len(), 2);
        for (f, w) in nonzero.iter().zip(w2) {
            assert!((f / (w.sqrt() / std::f64::consts::TAU) - 1.0).abs() < 1e-9);
        }
    }
}
