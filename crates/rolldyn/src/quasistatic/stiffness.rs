//! Stiffness and compliance of a quasi-static solution (docs/model.md §7; issue
//! 16). The solver returns the full 5×5 bearing stiffness K = −∂F/∂u over
//! the ring displacements u = (x, y, z, θ_y, θ_z) (implicit-function
//! theorem on the converged equations, so the balls' positions and speeds
//! follow). Designers quote two different scalars:
//!
//! * the **diagonal** K_ii: load per displacement along i with every other
//!   displacement held at zero (what the ring sees from a rigid fixture);
//! * the **conventional** stiffness 1/C_ii from the compliance C = K⁻¹:
//!   displacement along i per load along i with every other load held
//!   (the other displacements free), what a load–deflection test measures
//!   and what bearing catalogues and tools such as MESYS and BEARINX report.
//!
//! Under combined load the coupling terms (axial–radial, radial–tilt) make
//! them differ, by about 2× on the 7218B at F_x = F_z.

use super::Equilibrium;
use nalgebra::SMatrix;

type Matrix5 = SMatrix<f64, 5, 5>;

impl Equilibrium {
    /// Compliance C = K⁻¹ \[m/N, rad/(N·m), …\], or None where K is singular
    /// (a direction no loaded ball resists, e.g. clearance under a load
    /// along one axis).
    pub fn compliance(&self) -> Option<[[f64; 5]; 5]> {
        let k = Matrix5::from_fn(|i, j| self.stiffness[i][j]);
        let scale = k.amax();
        if scale.is_nan() || scale <= 0.0 {
            return None;
        }
        let c = k.try_inverse()?;
        // Reject numerically singular stiffness: ‖C K − I‖ must be small.
        let residual = (c * k - Matrix5::identity()).amax();
        (residual < 1e-6 && c.iter().all(|v| v.is_finite()))
            .then(|| std::array::from_fn(|i| std::array::from_fn(|j| c[(i, j)])))
    }

    /// Conventional stiffnesses 1/C_ii (axial, radial y, radial z \[N/m\];
    /// tilt y, tilt z \[N·m/rad\]), None where K is singular.
    pub fn conventional_stiffness(&self) -> Option<[f64; 5]> {
        let c = self.compliance()?;
        Some(std::array::from_fn(|i| 1.0 / c[i][i]))
    }
}
