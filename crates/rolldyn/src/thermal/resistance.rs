//! Thermal resistances of a bearing's parts \[K/W\] (Lei et al. 2023 §4.2;
//! docs/model.md §10).

use std::f64::consts::PI;

/// Radial conduction through a cylindrical shell (ring, housing), Lei et al. 2023
/// eq 40 (Incropera & DeWitt eq 3.28): R = ln(d_o/d_i)/(2π k l).
pub fn cylinder(inner_diameter: f64, outer_diameter: f64, conductivity: f64, length: f64) -> f64 {
    (outer_diameter / inner_diameter).ln() / (2.0 * PI * conductivity * length)
}

/// Convection from area `area` with coefficient `coefficient` \[W/(m²K)\],
/// Lei et al. 2023 eq 42: R = 1/(h S).
pub fn convection(coefficient: f64, area: f64) -> f64 {
    1.0 / (coefficient * area)
}

/// Resistance of one side of a Hertz contact to the heat generated in it,
/// the surface sliding through the ellipse at `speed` \[m/s\] (semi-axes
/// `semi_major` across and `semi_minor` along the motion; the body's
/// conductivity k and diffusivity κ = k/(ρc)).
///
/// High Péclet number (Pe = V b/κ ≫ 1): a surface point is heated for
/// t = ℓ/V while it crosses, and a semi-infinite body under a uniform flux q
/// warms by 2q√(κt/π)/k (Carslaw & Jaeger §2.9). Averaged over the crossing
/// and over the ellipse's mean chord ℓ = πb/2, the mean rise is
/// θ̄ = (4q/3k)√(κ ℓ/(πV)), so with q = H/(πab)
/// ```text
/// R_moving = (4/(3π k a b)) √(κ b/(2V))
/// ```
/// At rest the heat spreads in three dimensions: the mean rise of a uniform
/// flux on a circle of radius r = √(ab) is 32 q r/(3π² k) (Yovanovich),
/// R_static = 32/(3π³ k √(ab)). The two limits are joined as
/// R = (R_moving⁻² + R_static⁻²)^{−1/2}. Lei et al. 2023 eq 41 (after Neurouth et
/// al. 2014) has the same 1/(k√Pe) scaling at high Pe; its printed form
/// takes the Péclet number with the lubricant's heat capacity and is not
/// used.
pub fn moving_contact(
    semi_major: f64,
    semi_minor: f64,
    speed: f64,
    conductivity: f64,
    diffusivity: f64,
) -> f64 {
    let (a, b, k) = (semi_major, semi_minor, conductivity);
    let r_static = 32.0 / (3.0 * PI.powi(3) * k * (a * b).sqrt());
    let v = speed.abs();
    if v == 0.0 {
        return r_static;
    }
    let r_moving = 4.0 / (3.0 * PI * k * a * b) * (diffusivity * b / (2.0 * v)).sqrt();
    (r_moving.powi(-2) + r_static.powi(-2)).powf(-0.5)
}

/// Mean forced-convection coefficient of a surface of length `length`
/// swept by a fluid at `speed` (flat plate, Incropera & DeWitt eqs 7.30
/// and 7.38): laminar h = 0.664 (k/L) Re^{1/2} Pr^{1/3}, and above
/// Re = 5·10⁵ the mixed laminar–turbulent h = (k/L)(0.037 Re^{4/5} − 871)
/// Pr^{1/3}. Fluid conductivity k, kinematic viscosity ν, Prandtl number Pr.
pub fn flat_plate_coefficient(
    conductivity: f64,
    kinematic_viscosity: f64,
    prandtl: f64,
    speed: f64,
    length: f64,
) -> f64 {
    let re = speed.abs() * length / kinematic_viscosity;
    let nu = if re < 5e5 {
        0.664 * re.sqrt()
    } else {
        0.037 * re.powf(0.8) - 871.0
    };
    nu * prandtl.cbrt() * conductivity / length
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cylinder_and_convection() {
        // 1 m of a shell 10/20 mm in steel (k = 43): ln 2/(2π 43).
        let r = cylinder(10e-3, 20e-3, 43.0, 1.0);
        assert!((r - 2f64.ln() / (2.0 * PI * 43.0)).abs() < 1e-15);
        assert_eq!(convection(20.0, 0.5), 0.1);
    }

    /// The moving-source resistance falls as 1/√V at high speed and tends to
    /// the static one at rest; it is continuous and decreasing in V.
    #[test]
    fn moving_contact_limits() {
        let (a, b, k, kappa) = (1e-3, 0.15e-3, 43.0, 1.2e-5);
        let r0 = moving_contact(a, b, 0.0, k, kappa);
        assert!((r0 - 32.0 / (3.0 * PI.powi(3) * k * (a * b).sqrt())).abs() < 1e-12);
        let r_slow = moving_contact(a, b, 1e-6, k, kappa);
        assert!((r_slow / r0 - 1.0).abs() < 1e-3);
        let (r10, r40) = (
            moving_contact(a, b, 10.0, k, kappa),
            moving_contact(a, b, 40.0, k, kappa),
        );
        assert!((r10 / r40 - 2.0).abs() < 0.01, "{}", r10 / r40);
        let mut last = f64::INFINITY;
        for i in 0..60 {
            let r = moving_contact(a, b, 1e-4 * 1.3f64.powi(i), k, kappa);
            assert!(r < last);
            last = r;
        }
    }

    /// The laminar flat plate: Nu = 0.664 Re^{1/2} Pr^{1/3}.
    #[test]
    fn flat_plate() {
        let h = flat_plate_coefficient(0.14, 30e-6, 400.0, 10.0, 0.1);
        let re: f64 = 10.0 * 0.1 / 30e-6;
        assert!((h - 0.664 * re.sqrt() * 400f64.cbrt() * 0.14 / 0.1).abs() < 1e-9);
    }
}
