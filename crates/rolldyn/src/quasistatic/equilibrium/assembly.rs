//! Assembly of the quasi-static equations (MODEL §7; the equations are
//! listed in the parent module's documentation): per ball the residual of
//! its force, rolling and spin equations and its Jacobian blocks, and the
//! ball's load on the inner ring with its derivatives; summed over the
//! balls into the bordered system Newton solves.

use super::{Assembly, Matrix5, QuasiStaticSolver, Row3, Row5, Setup, State, Vector5};
use crate::geometry::RingKind;
use crate::quasistatic::ring_contact::{Matrix3x5, RingContactEval, RingDisplacement};
use nalgebra::{Matrix3, SMatrix, Vector3};

/// One ball's share of the system: its residual (force e_x, e_r; rolling
/// at the inner and outer contact; spin at the controlling one), the
/// blocks A = ∂residual/∂ball, B = ∂residual/∂u, C = ∂(ring load)/∂ball,
/// D = ∂(ring load)/∂u, and its load on the inner ring.
pub(super) struct BallTerms {
    pub residual: Vector5,
    pub a: Matrix5,
    pub b: Matrix5,
    pub c: Matrix5,
    pub d: Matrix5,
    pub ring: Vector5,
    /// Larger of the ball's two contact loads \[N\].
    pub largest_load: f64,
}

fn cross_matrix(v: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -v.z, v.y, v.z, 0.0, -v.x, -v.y, v.x, 0.0)
}

/// The force of a contact on the ball, with the extension weighted.
fn weighted(eval: &RingContactEval, extension: f64) -> (Vector3<f64>, Matrix3<f64>, Matrix3x5) {
    let w = if eval.in_contact() { 1.0 } else { extension };
    (w * eval.force, w * eval.dforce_dball, w * eval.dforce_dring)
}

impl QuasiStaticSolver {
    /// The bordered system: every ball's terms, the applied loads on the
    /// ring.
    pub(super) fn assemble(
        &self,
        state: &State,
        controls: &[RingKind],
        setup: Setup<'_>,
    ) -> Assembly {
        let z = self.geometry.ball_count;
        let ring = RingDisplacement::from_array(state.ring.into());
        let mut asm = Assembly {
            ball: Vec::with_capacity(z),
            ring: Self::applied(&setup.conditions.loads),
            a: Vec::with_capacity(z),
            b: Vec::with_capacity(z),
            c: Vec::with_capacity(z),
            d: Matrix5::zeros(),
            largest_load: 0.0,
        };
        for (j, y) in state.balls.iter().enumerate() {
            let t = self.ball_terms(j, y, &ring, controls[j], setup);
            asm.ball.push(t.residual);
            asm.a.push(t.a);
            asm.b.push(t.b);
            asm.c.push(t.c);
            asm.d += t.d;
            asm.ring += t.ring;
            asm.largest_load = asm.largest_load.max(t.largest_load);
        }
        asm
    }

    /// Ball j's terms at ball unknowns `y` and ring displacement `ring`.
    pub(super) fn ball_terms(
        &self,
        j: usize,
        y: &Vector5,
        ring: &RingDisplacement,
        control: RingKind,
        setup: Setup<'_>,
    ) -> BallTerms {
        let d = self.geometry.ball_diameter;
        let half = 0.5 * d;
        let (m, inertia) = (self.ball_mass, self.ball_inertia);
        let omega_i = setup.conditions.inner_speed;
        let phi = self.azimuth(j, setup.options);
        let (ex, er) = Self::basis(phi);
        let e = SMatrix::<f64, 3, 2>::from_columns(&[ex, er]);
        let (q, inner, outer) = self.contacts(y, phi, ring);
        let largest_load = inner.load.max(outer.load);
        let (r, wm, wx, wr) = (y[1], y[2], y[3], y[4]);
        // Friction shares (λ_i, λ_o) of the gyroscopic moment and the
        // weights (t_i, t_o) of the no-spin conditions s_i, s_o: at the
        // controlling raceway; an inner-controlled ball's blended by
        // `inner_share` (t s_i − (1 − t) s_o: the minus keeps the blend
        // regular for a loaded ball, whose n_i ≈ −n_o).
        let t = setup.inner_share;
        let (lambda_i, lambda_o, spin_i_weight, spin_o_weight) = match control {
            RingKind::Outer => (0.0, 2.0, 0.0, 1.0),
            RingKind::Inner => (2.0 * t, 2.0 * (1.0 - t), t, t - 1.0),
        };

        // Normal components and their gradients.
        let nx = |c: &RingContactEval| c.normal.dot(&ex);
        let nr = |c: &RingContactEval| c.normal.dot(&er);
        let grad_q = |c: &RingContactEval, axis: &Vector3<f64>| -> Row3 {
            axis.transpose() * c.dnormal_dball
        };
        let grad_u = |c: &RingContactEval, axis: &Vector3<f64>| -> Row5 {
            axis.transpose() * c.dnormal_dring
        };

        // Gyroscopic friction f_k = c_k t_k, t_k = n_x e_r − n_r e_x.
        let mg = inertia * wm * wr;
        let tangent = |c: &RingContactEval| nx(c) * er - nr(c) * ex;
        let dtangent_dq = |c: &RingContactEval| er * grad_q(c, &ex) - ex * grad_q(c, &er);
        let dtangent_du = |c: &RingContactEval| er * grad_u(c, &ex) - ex * grad_u(c, &er);
        let (ci, co) = (lambda_i * mg / d, lambda_o * mg / d);
        let (fi, fo) = (ci * tangent(&inner), co * tangent(&outer));

        let (force_i, dfi_dq, dfi_du) = weighted(&inner, setup.extension);
        // An open outer contact keeps its full extension: it pulls the ball
        // to its raceway (at speed the centrifugal force closes it at the
        // solution; a weak pull would leave the ball's radial stiffness
        // negative, m ω_m², and Newton would drive it inwards).
        let (force_o, dfo_dq, _) = weighted(&outer, 1.0);

        let mut res = Vector5::zeros();
        let force = e.transpose() * (force_i + force_o + fi + fo);
        res[0] = force[0];
        res[1] = force[1] + m * r * wm * wm;
        let rolling = |c: &RingContactEval, omega: f64| {
            wm * r + half * (wx * nr(c) - wr * nx(c)) - omega * (r + half * nr(c))
        };
        res[2] = rolling(&inner, omega_i);
        res[3] = rolling(&outer, 0.0);
        let spin = |c: &RingContactEval, omega: f64| (wx - omega) * nx(c) + wr * nr(c);
        res[4] = spin_i_weight * spin(&inner, omega_i) + spin_o_weight * spin(&outer, 0.0);

        // A: ball rows × (x, r, ω_m, ω_x, ω_r).
        let mut a = Matrix5::zeros();
        let df_dq = dfi_dq + dfo_dq + ci * dtangent_dq(&inner) + co * dtangent_dq(&outer);
        let f_pos = e.transpose() * df_dq * e;
        let dforce_dwm = e.transpose()
            * (lambda_i * inertia * wr / d * tangent(&inner)
                + lambda_o * inertia * wr / d * tangent(&outer));
        let dforce_dwr = e.transpose()
            * (lambda_i * inertia * wm / d * tangent(&inner)
                + lambda_o * inertia * wm / d * tangent(&outer));
        for row in 0..2 {
            a[(row, 0)] = f_pos[(row, 0)];
            a[(row, 1)] = f_pos[(row, 1)];
            a[(row, 2)] = dforce_dwm[row];
            a[(row, 4)] = dforce_dwr[row];
        }
        a[(1, 1)] += m * wm * wm;
        a[(1, 2)] += 2.0 * m * r * wm;
        let rolling_dq = |c: &RingContactEval, omega: f64| -> Row3 {
            half * (wx - omega) * grad_q(c, &er) - half * wr * grad_q(c, &ex)
        };
        for (row, c, omega) in [(2, &inner, omega_i), (3, &outer, 0.0)] {
            let g = rolling_dq(c, omega) * e;
            a[(row, 0)] = g[0];
            a[(row, 1)] = g[1] + wm - omega;
            a[(row, 2)] = r;
            a[(row, 3)] = half * nr(c);
            a[(row, 4)] = -half * nx(c);
        }
        let spin_dq = |c: &RingContactEval, omega: f64| -> Row3 {
            (wx - omega) * grad_q(c, &ex) + wr * grad_q(c, &er)
        };
        let g =
            (spin_i_weight * spin_dq(&inner, omega_i) + spin_o_weight * spin_dq(&outer, 0.0)) * e;
        a[(4, 0)] = g[0];
        a[(4, 1)] = g[1];
        a[(4, 3)] = spin_i_weight * nx(&inner) + spin_o_weight * nx(&outer);
        a[(4, 4)] = spin_i_weight * nr(&inner) + spin_o_weight * nr(&outer);

        // B: ball rows × ring u (only the inner contact depends on u).
        let mut b = Matrix5::zeros();
        let fu = e.transpose() * (dfi_du + ci * dtangent_du(&inner));
        b.fixed_view_mut::<2, 5>(0, 0).copy_from(&fu);
        let roll_u: Row5 =
            half * (wx - omega_i) * grad_u(&inner, &er) - half * wr * grad_u(&inner, &ex);
        b.set_row(2, &roll_u);
        let spin_u: Row5 = (wx - omega_i) * grad_u(&inner, &ex) + wr * grad_u(&inner, &er);
        b.set_row(4, &(spin_i_weight * spin_u));

        // Ring: force and moment of this ball on the inner ring
        // (physical normal law plus the inner friction force).
        let (fn_phys, dfn_dq, dfn_du) = if inner.in_contact() {
            (inner.force, inner.dforce_dball, inner.dforce_dring)
        } else {
            (Vector3::zeros(), Matrix3::zeros(), Matrix3x5::zeros())
        };
        let f_ring = -(fn_phys + fi);
        let df_ring_dq = -(dfn_dq + ci * dtangent_dq(&inner));
        let df_ring_du = -(dfn_du + ci * dtangent_du(&inner));
        let df_ring_dwm = -(lambda_i * inertia * wr / d) * tangent(&inner);
        let df_ring_dwr = -(lambda_i * inertia * wm / d) * tangent(&inner);
        let arm = q - ring.translation;
        let arm_x = cross_matrix(&arm);
        let f_x = cross_matrix(&f_ring);
        let n_x = cross_matrix(&inner.normal);
        let fi_x = cross_matrix(&fi);
        // Friction acts at P = q + (D/2) n: extra couple −(D/2) n × f_i.
        let moment = arm.cross(&f_ring) - half * inner.normal.cross(&fi);
        let dm_dq = arm_x * df_ring_dq
            - f_x
            - half * (n_x * (ci * dtangent_dq(&inner)) - fi_x * inner.dnormal_dball);
        let mut dm_du = arm_x * df_ring_du
            - half * (n_x * (ci * dtangent_du(&inner)) - fi_x * inner.dnormal_dring);
        for k in 0..3 {
            let col = dm_du.column(k) + f_x.column(k);
            dm_du.set_column(k, &col);
        }
        let dm_dwm =
            arm_x * df_ring_dwm - half * n_x * (lambda_i * inertia * wr / d * tangent(&inner));
        let dm_dwr =
            arm_x * df_ring_dwr - half * n_x * (lambda_i * inertia * wm / d * tangent(&inner));
        let ring_load = Vector5::new(f_ring.x, f_ring.y, f_ring.z, moment.y, moment.z);

        let mut c = Matrix5::zeros();
        let fq = df_ring_dq * e;
        let mq = dm_dq * e;
        for col in 0..2 {
            for row in 0..3 {
                c[(row, col)] = fq[(row, col)];
            }
            c[(3, col)] = mq[(1, col)];
            c[(4, col)] = mq[(2, col)];
        }
        for row in 0..3 {
            c[(row, 2)] = df_ring_dwm[row];
            c[(row, 4)] = df_ring_dwr[row];
        }
        c[(3, 2)] = dm_dwm.y;
        c[(4, 2)] = dm_dwm.z;
        c[(3, 4)] = dm_dwr.y;
        c[(4, 4)] = dm_dwr.z;

        let mut dd = Matrix5::zeros();
        for col in 0..5 {
            for row in 0..3 {
                dd[(row, col)] = df_ring_du[(row, col)];
            }
            dd[(3, col)] = dm_du[(1, col)];
            dd[(4, col)] = dm_du[(2, col)];
        }
        BallTerms {
            residual: res,
            a,
            b,
            c,
            d: dd,
            ring: ring_load,
            largest_load,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Conditions, RacewayControl, SolverOptions};
    use super::*;
    use crate::contact::HertzModel;
    use crate::geometry::{BearingGeometry, Clearance, GeometrySpec};
    use crate::material::Material;
    use crate::operating::Loads;

    /// The assembled Jacobian blocks equal central differences of the
    /// residual, at speed, with friction on the inner ring: balls under
    /// inner and outer control, the inner control as stated (t = 1) and
    /// blended (t = 0.4, the outer-control homotopy).
    #[test]
    fn jacobian_matches_finite_differences() {
        let g = BearingGeometry::new(&GeometrySpec {
            ball_diameter: 6.35e-3,
            ball_count: 5,
            pitch_diameter: 54e-3,
            inner_groove_curvature: 0.55,
            outer_groove_curvature: 0.52,
            clearance: Clearance::FreeContactAngle(17.7f64.to_radians()),
            preload: false,
        })
        .unwrap();
        let solver = QuasiStaticSolver::new(
            &g,
            &Material::STEEL_52100,
            &Material::STEEL_52100,
            HertzModel::Exact,
        )
        .unwrap();
        let conditions = Conditions {
            loads: Loads {
                force: [300.0, 50.0, -80.0],
                moment: [1.0, -0.5],
            },
            inner_speed: 1000.0,
            control: RacewayControl::Inner,
        };
        let options = SolverOptions::default();
        let state = State {
            balls: (0..5)
                .map(|j| {
                    Vector5::new(
                        -3e-6 + 1e-7 * j as f64,
                        27.002e-3,
                        440.0 + j as f64,
                        180.0,
                        -2400.0,
                    )
                })
                .collect(),
            ring: Vector5::new(1.2e-5, 1e-6, -2e-6, 1e-4, -5e-5),
        };
        let controls: Vec<RingKind> = (0..5)
            .map(|j| {
                if j % 2 == 0 {
                    RingKind::Inner
                } else {
                    RingKind::Outer
                }
            })
            .collect();
        for inner_share in [1.0, 0.4] {
            let setup = Setup {
                conditions: &conditions,
                options: &options,
                extension: 1e-6,
                inner_share,
            };
            let asm = solver.assemble(&state, &controls, setup);
            let steps = [1e-9, 1e-9, 1e-3, 1e-3, 1e-3];
            for j in 0..5 {
                for (k, &step) in steps.iter().enumerate() {
                    let (mut plus, mut minus) = (state.clone(), state.clone());
                    plus.balls[j][k] += step;
                    minus.balls[j][k] -= step;
                    let (ap, am) = (
                        solver.assemble(&plus, &controls, setup),
                        solver.assemble(&minus, &controls, setup),
                    );
                    let fd_ball = (ap.ball[j] - am.ball[j]) / (2.0 * step);
                    let fd_ring = (ap.ring - am.ring) / (2.0 * step);
                    let (a, c) = (asm.a[j].column(k), asm.c[j].column(k));
                    assert!(
                        (fd_ball - a).norm() <= 1e-4 * fd_ball.norm().max(1e-3),
                        "A[{j}] col {k}: {fd_ball:?} vs {a:?}"
                    );
                    assert!(
                        (fd_ring - c).norm() <= 1e-4 * fd_ring.norm().max(1e-3),
                        "C[{j}] col {k}: {fd_ring:?} vs {c:?}"
                    );
                }
            }
            let ring_steps = [1e-9, 1e-9, 1e-9, 1e-8, 1e-8];
            for (k, &step) in ring_steps.iter().enumerate() {
                let (mut plus, mut minus) = (state.clone(), state.clone());
                plus.ring[k] += step;
                minus.ring[k] -= step;
                let (ap, am) = (
                    solver.assemble(&plus, &controls, setup),
                    solver.assemble(&minus, &controls, setup),
                );
                let fd_ring = (ap.ring - am.ring) / (2.0 * step);
                assert!(
                    (fd_ring - asm.d.column(k)).norm() <= 1e-4 * fd_ring.norm().max(1e-3),
                    "D col {k}: {fd_ring:?} vs {:?}",
                    asm.d.column(k)
                );
                for j in 0..5 {
                    let fd_ball = (ap.ball[j] - am.ball[j]) / (2.0 * step);
                    let b = asm.b[j].column(k);
                    assert!(
                        (fd_ball - b).norm() <= 1e-4 * fd_ball.norm().max(1e-3),
                        "B[{j}] col {k}: {fd_ball:?} vs {:?}",
                        b.transpose()
                    );
                }
            }
        }
    }
}
