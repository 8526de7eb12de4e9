//! The exact torus contact (docs/model.md §2.1) of one ball with one ring, with the
//! analytic derivatives of the contact force that Newton's method and the
//! implicit-function stiffness need.
//!
//! The contact is evaluated in the ring's own frame. With R = R_z(θ_z) R_y(θ_y)
//! and ring translation t, the ball centre in the ring frame is
//! s = Rᵀ(q − t). Relative to the groove-centre circle (axial position x_c,
//! radius ρ, axis e_x) the contact depends on two scalars only:
//! ```text
//! a = s_x − x_c (axial offset),  b = |s_yz| − ρ (radial offset),  d = √(a² + b²)
//! δ = d − (r_g − D/2),  n = (a, b ŝ_yz)/d,  α = atan2(|a|, |b|)
//! ```
//! which is docs/model.md §2.1's construction written out. The force of the ring on
//! the ball is F = −Q n (towards the groove centre) with Q = K_c(α) δ^{3/2}
//! from the contact table. Derivatives (rotated back to the global frame):
//! ```text
//! ∂a/∂s = e_x,  ∂b/∂s = (0, ŝ_yz),  ∂n/∂s = (I − n nᵀ) G / d,
//! G = e_x e_xᵀ + ŝ ŝᵀ + (b/|s_yz|)(I_yz − ŝ ŝᵀ)
//! ∂Q/∂s = (dQ/dδ) n + (dQ/dα) ∇α,   ∇α = (|b| sgn(a) e_x − |a| sgn(b) (0, ŝ))/d²
//! ```
//! plus the derivative of R for the tilts (∂R/∂θ_y = R_z [e_y×] R_y,
//! ∂R/∂θ_z = [e_z×] R).
//!
//! **Film in the approach** (docs/model.md §4; `lubrication::approach`). With a
//! film law the bodies are compressed by δ_el = δ + h(Q): Q = K_c δ_el^{3/2}
//! by Newton, and `penetration` is δ_el. Then
//! dQ/dδ = K_H/(1 − K_H dh/dQ) (Hertz and film in series) and
//! dQ/dα = K_c' δ_el^{3/2}/(1 − K_H dh/dQ). The law itself (entrainment
//! speed, curvature at α) is held: the solver sets it from the previous
//! solution (`QuasiStaticSolver::solve_with_films`).
//!
//! **Signed extension.** With `extend` the force law continues to δ < 0 as
//! Q = K_c δ|δ|^{1/2} (a pull). The static solver uses it only in the ball
//! equations at zero speed, where a ball that carries no load has no
//! physical position; it then stays where both gaps balance. Forces on the
//! rings always use the physical, clipped law.

use crate::contact::ContactTable;
use crate::geometry::Raceway;
use crate::lubrication::approach::FilmLaw;
use nalgebra::{Matrix3, Rotation3, SMatrix, Vector3};

/// 3 × 5 matrix: derivative of a 3-vector with respect to the ring DOFs
/// (t_x, t_y, t_z, θ_y, θ_z).
pub type Matrix3x5 = SMatrix<f64, 3, 5>;

/// Pose of a ring as the quasi-static solver sees it: translation and tilts.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RingDisplacement {
    /// (x, y, z) \[m\].
    pub translation: Vector3<f64>,
    /// Tilt about y \[rad\].
    pub tilt_y: f64,
    /// Tilt about z \[rad\].
    pub tilt_z: f64,
}

impl RingDisplacement {
    /// From the solver's 5-vector (x, y, z, θ_y, θ_z).
    pub fn from_array(u: [f64; 5]) -> Self {
        Self {
            translation: Vector3::new(u[0], u[1], u[2]),
            tilt_y: u[3],
            tilt_z: u[4],
        }
    }
}

/// One evaluated contact with derivatives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RingContactEval {
    /// Penetration δ \[m\].
    pub penetration: f64,
    /// Contact angle α \[rad\] from the ring's radial plane.
    pub contact_angle: f64,
    /// Physical normal load Q ≥ 0 \[N\].
    pub load: f64,
    /// Unit normal (global), from the groove centre towards the ball centre.
    pub normal: Vector3<f64>,
    /// Force of the ring on the ball (global) \[N\]; with `extend`, the signed
    /// extension for δ < 0.
    pub force: Vector3<f64>,
    /// ∂force/∂q (ball centre) \[N/m\].
    pub dforce_dball: Matrix3<f64>,
    /// ∂force/∂(t, θ) of the ring.
    pub dforce_dring: Matrix3x5,
    /// ∂normal/∂q \[1/m\].
    pub dnormal_dball: Matrix3<f64>,
    /// ∂normal/∂(t, θ) of the ring.
    pub dnormal_dring: Matrix3x5,
}

impl RingContactEval {
    /// Whether the contact is closed (physical load > 0).
    pub fn in_contact(&self) -> bool {
        self.penetration > 0.0
    }
}

fn cross_matrix(v: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -v.z, v.y, v.z, 0.0, -v.x, -v.y, v.x, 0.0)
}

/// Evaluates the contact of a ball (diameter D, centre q) with `raceway` on
/// a ring displaced by `ring`, using `table` for K_c(α), with the film
/// `film` in the approach if given.
pub fn evaluate(
    raceway: &Raceway,
    table: &ContactTable,
    ball_diameter: f64,
    ball_centre: &Vector3<f64>,
    ring: &RingDisplacement,
    extend: bool,
    film: Option<&FilmLaw>,
) -> RingContactEval {
    let rz = Rotation3::from_axis_angle(&Vector3::z_axis(), ring.tilt_z);
    let ry = Rotation3::from_axis_angle(&Vector3::y_axis(), ring.tilt_y);
    let rot = (rz * ry).into_inner();
    let rel = ball_centre - ring.translation;
    let s = rot.transpose() * rel;

    let r_yz = s.y.hypot(s.z);
    let s_hat = if r_yz > 0.0 {
        Vector3::new(0.0, s.y / r_yz, s.z / r_yz)
    } else {
        Vector3::new(0.0, 1.0, 0.0)
    };
    let a = s.x - raceway.groove_centre_axial;
    let b = r_yz - raceway.groove_centre_radius;
    let d = a.hypot(b);
    let overlap = d - (raceway.groove_radius - 0.5 * ball_diameter);
    let n = Vector3::new(a / d, b / d * s_hat.y, b / d * s_hat.z);
    let alpha = a.abs().atan2(b.abs());

    let (k, dk) = table.stiffness_with_derivative(alpha);
    // The elastic approach, and the film's series factor 1/(1 − K_H h').
    let (delta, series) = match film.map(|law| (law, law.elastic_approach(k, overlap))) {
        Some((_, Some(a))) => (a.approach, a.series_factor),
        Some((law, None)) => (overlap + law.film(0.0), 1.0),
        None => (overlap, 1.0),
    };
    let active = delta > 0.0 || extend;
    let root = delta.abs().sqrt();
    let (q_signed, dq_ddelta, dq_dalpha) = if active {
        (
            k * delta * root,
            series * 1.5 * k * root,
            series * dk * delta * root,
        )
    } else {
        (0.0, 0.0, 0.0)
    };

    let ex = Vector3::x();
    let grad_alpha = (b.abs() * a.signum() * ex - a.abs() * b.signum() * s_hat) / (d * d);
    let grad_q = dq_ddelta * n + dq_dalpha * grad_alpha;
    let i_yz = Matrix3::from_diagonal(&Vector3::new(0.0, 1.0, 1.0));
    let ss = s_hat * s_hat.transpose();
    let g = ex * ex.transpose() + ss + (b / r_yz.max(f64::MIN_POSITIVE)) * (i_yz - ss);
    let dn_ds = (Matrix3::identity() - n * n.transpose()) * g / d;
    let force_ring_frame = -q_signed * n;
    let j_s = -(n * grad_q.transpose()) - q_signed * dn_ds;

    let rt = rot.transpose();
    let dforce_dball = rot * j_s * rt;
    let drot_dty = rz.into_inner() * cross_matrix(&Vector3::y()) * ry.into_inner();
    let drot_dtz = cross_matrix(&Vector3::z()) * rot;
    let dnormal_dball = rot * dn_ds * rt;
    let mut dforce_dring = Matrix3x5::zeros();
    let mut dnormal_dring = Matrix3x5::zeros();
    dforce_dring
        .fixed_view_mut::<3, 3>(0, 0)
        .copy_from(&(-dforce_dball));
    dnormal_dring
        .fixed_view_mut::<3, 3>(0, 0)
        .copy_from(&(-dnormal_dball));
    for (col, drot) in [(3, drot_dty), (4, drot_dtz)] {
        let ds = drot.transpose() * rel;
        dforce_dring.set_column(col, &(drot * force_ring_frame + rot * j_s * ds));
        dnormal_dring.set_column(col, &(drot * n + rot * dn_ds * ds));
    }
    RingContactEval {
        penetration: delta,
        contact_angle: alpha,
        load: if delta > 0.0 { k * delta * root } else { 0.0 },
        normal: rot * n,
        force: rot * force_ring_frame,
        dforce_dball,
        dforce_dring,
        dnormal_dball,
        dnormal_dring,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::{HertzModel, RacewayContactModel};
    use crate::geometry::{RingKind, test_bearing};
    use crate::material::{Material, effective_modulus};

    #[test]
    fn derivatives_match_central_differences() {
        let g = test_bearing(22);
        let ep = effective_modulus(&Material::STEEL_52100, &Material::STEEL_52100);
        let model = RacewayContactModel::new(&g, RingKind::Inner, ep, HertzModel::Exact);
        let table = ContactTable::new(model).unwrap();
        let phi: f64 = 0.7;
        let q0 = Vector3::new(-4e-6, 27.003e-3 * phi.cos(), 27.003e-3 * phi.sin());
        let u0 = [3e-6, -2e-6, 1.5e-6, 2e-4, -1e-4];
        for extend in [false, true] {
            let eval = |q: &Vector3<f64>, u: [f64; 5]| {
                evaluate(
                    &g.inner,
                    &table,
                    g.ball_diameter,
                    q,
                    &RingDisplacement::from_array(u),
                    extend,
                    None,
                )
            };
            let base = eval(&q0, u0);
            assert!(base.penetration > 0.0);
            // Central difference of (force, normal) along one input.
            let check = |name: &str,
                         h: f64,
                         plus: RingContactEval,
                         minus: RingContactEval,
                         df: Vector3<f64>,
                         dn: Vector3<f64>| {
                let fd_f = (plus.force - minus.force) / (2.0 * h);
                let fd_n = (plus.normal - minus.normal) / (2.0 * h);
                let f_scale = fd_f.norm().max(1e-3 * base.force.norm() / g.ball_diameter);
                assert!(
                    (fd_f - df).norm() < 1e-5 * f_scale,
                    "dF/d{name}: {fd_f:?} vs {df:?}"
                );
                let n_scale = fd_n.norm().max(1e-3 / g.ball_diameter);
                assert!(
                    (fd_n - dn).norm() < 1e-5 * n_scale,
                    "dn/d{name}: {fd_n:?} vs {dn:?}"
                );
            };
            for k in 0..3 {
                let h = 1e-9;
                let (mut qp, mut qm) = (q0, q0);
                qp[k] += h;
                qm[k] -= h;
                let (df, dn) = (
                    base.dforce_dball.column(k).into(),
                    base.dnormal_dball.column(k).into(),
                );
                check(&format!("q{k}"), h, eval(&qp, u0), eval(&qm, u0), df, dn);
            }
            for k in 0..5 {
                let h = if k < 3 { 1e-9 } else { 1e-8 };
                let (mut up, mut um) = (u0, u0);
                up[k] += h;
                um[k] -= h;
                let (df, dn) = (
                    base.dforce_dring.column(k).into(),
                    base.dnormal_dring.column(k).into(),
                );
                check(&format!("u{k}"), h, eval(&q0, up), eval(&q0, um), df, dn);
            }
        }
    }
}
