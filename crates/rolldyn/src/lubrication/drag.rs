//! Drag of the air–oil mixture on balls and cage (Deng et al. 2022; docs/model.md §3, §5).

use nalgebra::Vector3;

/// Drag of the air–oil mixture on balls and cage (Deng et al. 2022 eqs 10–12, 24,
/// 36; docs/model.md §3, §5), with the paper's misprints corrected:
/// ```text
/// ball, orbit:  F = −½ ρ_e C_D (π D²/4) v_t |v_t| e_t             (v_t = r φ̇)
/// ball, spin:   M = −½ ρ_e C_n (D/2)⁵ |ω_rel| ω_rel              (ω_rel = ω_b − φ̇ e_x)
/// cage:         M = −(c₁ θ̇_c + c₂ θ̇_c |θ̇_c|)
/// ```
/// Deng et al. 2022 eqs 10–12 print M = ½ ρ ω (D/2)⁵ C_n, which is not a torque
/// (N·m·s); the quadratic form above is the rotating-sphere drag torque.
/// Deng et al. 2022 eq 24, F = C_D π ρ D² (d_m ω_m)^1.95/(32 g), is Gupta's
/// imperial-unit form (the g converts lbf); in SI with a constant C_D it is
/// the quadratic drag above. Deng et al. 2022 eq 36 mixes terms of inconsistent
/// dimensions; rolldyn uses a churning/windage torque with user
/// coefficients (docs/model.md §5), which c₁ (viscous) and c₂ (windage) are. The mixture is
/// taken at rest (outer ring fixed). All zero by default.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DragParameters {
    /// Effective density of the air–oil mixture ρ_e \[kg/m³\].
    pub effective_density: f64,
    /// Ball drag coefficient C_D \[-\].
    pub ball_drag_coefficient: f64,
    /// Ball spin drag coefficient C_n \[-\].
    pub ball_spin_drag_coefficient: f64,
    /// Cage viscous drag c₁ \[N·m·s\].
    pub cage_viscous: f64,
    /// Cage windage drag c₂ \[N·m·s²\].
    pub cage_windage: f64,
}

impl DragParameters {
    /// Orbital drag force along e_t \[N\] and spin drag moment \[N·m\] on a
    /// ball of diameter `diameter` with orbital speed `orbital_speed` (v_t)
    /// and spin `relative_spin` relative to the mixture (ω_b − φ̇ e_x).
    pub fn ball(
        &self,
        diameter: f64,
        orbital_speed: f64,
        relative_spin: &Vector3<f64>,
    ) -> (f64, Vector3<f64>) {
        let force = -0.5
            * self.effective_density
            * self.ball_drag_coefficient
            * std::f64::consts::FRAC_PI_4
            * diameter
            * diameter
            * orbital_speed
            * orbital_speed.abs();
        let moment = -0.5
            * self.effective_density
            * self.ball_spin_drag_coefficient
            * (0.5 * diameter).powi(5)
            * relative_spin.norm()
            * relative_spin;
        (force, moment)
    }
}
