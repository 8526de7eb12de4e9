//! Assembly of the quasi-static equations (docs/model.md §7; the equations are
//! listed in the parent module's documentation): per ball the residual of
//! its force, rolling and spin equations and its Jacobian blocks, and the
//! ball's load on the inner ring with its derivatives; summed over the
//! balls into the bordered system Newton solves.

use super::race_drive::{RaceDrive, kinematic_inner, race_drive};
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
    /// ∂residual/∂ω_i at fixed unknowns (the rolling equation at the inner
    /// contact and an inner-controlled ball's spin condition).
    pub speed_derivative: Vector5,
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

/// The frame of a ball's azimuth, e_x (axial) and e_r (radial), and the
/// contact normals' components in it with their gradients by the ball's
/// position q and the ring's displacement u.
struct Frame {
    ex: Vector3<f64>,
    er: Vector3<f64>,
    e: SMatrix<f64, 3, 2>,
}

impl Frame {
    fn at(phi: f64) -> Self {
        let (ex, er) = QuasiStaticSolver::basis(phi);
        Self {
            ex,
            er,
            e: SMatrix::<f64, 3, 2>::from_columns(&[ex, er]),
        }
    }

    fn nx(&self, c: &RingContactEval) -> f64 {
        c.normal.dot(&self.ex)
    }

    fn nr(&self, c: &RingContactEval) -> f64 {
        c.normal.dot(&self.er)
    }

    fn grad_q_x(&self, c: &RingContactEval) -> Row3 {
        self.ex.transpose() * c.dnormal_dball
    }

    fn grad_q_r(&self, c: &RingContactEval) -> Row3 {
        self.er.transpose() * c.dnormal_dball
    }

    fn grad_u_x(&self, c: &RingContactEval) -> Row5 {
        self.ex.transpose() * c.dnormal_dring
    }

    fn grad_u_r(&self, c: &RingContactEval) -> Row5 {
        self.er.transpose() * c.dnormal_dring
    }

    /// The gyroscopic friction's direction t = n_x e_r − n_r e_x.
    fn tangent(&self, c: &RingContactEval) -> Vector3<f64> {
        self.nx(c) * self.er - self.nr(c) * self.ex
    }

    fn dtangent_dq(&self, c: &RingContactEval) -> Matrix3<f64> {
        self.er * self.grad_q_x(c) - self.ex * self.grad_q_r(c)
    }

    fn dtangent_du(&self, c: &RingContactEval) -> Matrix3x5 {
        self.er * self.grad_u_x(c) - self.ex * self.grad_u_r(c)
    }
}

/// A ball's orbit radius r and speeds ω_m, ω_x, ω_r (its unknowns 1–4),
/// with its half diameter: the rolling and no-spin conditions at a
/// contact and their gradients by the ball's position.
struct BallSpeeds {
    r: f64,
    wm: f64,
    wx: f64,
    wr: f64,
    half: f64,
}

impl BallSpeeds {
    fn of(y: &Vector5, half: f64) -> Self {
        Self {
            r: y[1],
            wm: y[2],
            wx: y[3],
            wr: y[4],
            half,
        }
    }

    /// Rolling at contact c against a raceway turning at `omega`.
    fn rolling(&self, f: &Frame, c: &RingContactEval, omega: f64) -> f64 {
        let (r, half) = (self.r, self.half);
        self.wm * r + half * (self.wx * f.nr(c) - self.wr * f.nx(c)) - omega * (r + half * f.nr(c))
    }

    fn rolling_dq(&self, f: &Frame, c: &RingContactEval, omega: f64) -> Row3 {
        self.half * (self.wx - omega) * f.grad_q_r(c) - self.half * self.wr * f.grad_q_x(c)
    }

    fn rolling_du(&self, f: &Frame, c: &RingContactEval, omega: f64) -> Row5 {
        self.half * (self.wx - omega) * f.grad_u_r(c) - self.half * self.wr * f.grad_u_x(c)
    }

    /// Spin at contact c against a raceway turning at `omega`.
    fn spin(&self, f: &Frame, c: &RingContactEval, omega: f64) -> f64 {
        (self.wx - omega) * f.nx(c) + self.wr * f.nr(c)
    }

    fn spin_dq(&self, f: &Frame, c: &RingContactEval, omega: f64) -> Row3 {
        (self.wx - omega) * f.grad_q_x(c) + self.wr * f.grad_q_r(c)
    }

    fn spin_du(&self, f: &Frame, c: &RingContactEval, omega: f64) -> Row5 {
        (self.wx - omega) * f.grad_u_x(c) + self.wr * f.grad_u_r(c)
    }
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
            speed_derivative: Vec::with_capacity(z),
            ring: Self::applied(&setup.conditions.loads),
            a: Vec::with_capacity(z),
            b: Vec::with_capacity(z),
            c: Vec::with_capacity(z),
            d: Matrix5::zeros(),
            largest_load: 0.0,
            free: Vec::with_capacity(z),
        };
        for (j, y) in state.balls.iter().enumerate() {
            let t = self.ball_terms(j, y, &ring, controls[j], setup);
            asm.ball.push(t.residual);
            asm.speed_derivative.push(t.speed_derivative);
            asm.a.push(t.a);
            asm.b.push(t.b);
            asm.free
                .push(t.c == Matrix5::zeros() && t.ring == Vector5::zeros());
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
        let f = Frame::at(phi);
        let e = f.e;
        let (q, inner, outer) = self.contacts(j, y, phi, ring);
        let largest_load = inner.load.max(outer.load);
        let s = BallSpeeds::of(y, half);
        let (r, wm) = (s.r, s.wm);
        // How far the inner raceway drives the ball (`race_drive`): 1 while
        // its contact is closed, → 0 as it opens.
        let drive = race_drive(&inner, self.drive_reference(), setup.options.race_drive);
        let inner_k = kinematic_inner(&inner, &outer, &drive);
        let shares = ControlShares::new(control, setup.inner_share, &drive);
        let ControlShares {
            spin_i_weight,
            spin_o_weight,
            dshare_dq,
            dshare_du,
            ..
        } = shares;
        let gyro = Gyroscopic::new(&f, &s, &shares, (&inner, &outer), inertia, d);
        let (fi, fo, dfric_i_dq, dfric_i_du) = (gyro.fi, gyro.fo, gyro.dfi_dq, gyro.dfi_du);

        let (force_i, dfi_dq, dfi_du) = weighted(&inner, setup.extension);
        // An open outer contact keeps its full extension: it pulls the ball
        // to its raceway (at speed the centrifugal force closes it at the
        // solution; with a weak pull the ball's radial stiffness would be
        // the destabilising centrifugal m ω_m² alone, and Newton would
        // drive the ball inwards).
        let (force_o, dfo_dq, _) = weighted(&outer, 1.0);

        let mut res = Vector5::zeros();
        let force = e.transpose() * (force_i + force_o + fi + fo);
        res[0] = force[0];
        res[1] = force[1] + m * r * wm * wm;
        res[2] = s.rolling(&f, &inner_k, omega_i);
        res[3] = s.rolling(&f, &outer, 0.0);
        let (spin_i, spin_o) = (s.spin(&f, &inner, omega_i), s.spin(&f, &outer, 0.0));
        res[4] = spin_i_weight * spin_i + spin_o_weight * spin_o;

        // A: ball rows × (x, r, ω_m, ω_x, ω_r).
        let mut a = Matrix5::zeros();
        let df_dq = dfi_dq + dfo_dq + dfric_i_dq + gyro.co * f.dtangent_dq(&outer);
        let f_pos = e.transpose() * df_dq * e;
        let dforce_dwm = e.transpose() * (gyro.dfi_dwm + gyro.dfo_dwm);
        let dforce_dwr = e.transpose() * (gyro.dfi_dwr + gyro.dfo_dwr);
        for row in 0..2 {
            a[(row, 0)] = f_pos[(row, 0)];
            a[(row, 1)] = f_pos[(row, 1)];
            a[(row, 2)] = dforce_dwm[row];
            a[(row, 4)] = dforce_dwr[row];
        }
        a[(1, 1)] += m * wm * wm;
        a[(1, 2)] += 2.0 * m * r * wm;
        for (row, c, omega) in [(2, &inner_k, omega_i), (3, &outer, 0.0)] {
            let g = s.rolling_dq(&f, c, omega) * e;
            a[(row, 0)] = g[0];
            a[(row, 1)] = g[1] + wm - omega;
            a[(row, 2)] = r;
            a[(row, 3)] = half * f.nr(c);
            a[(row, 4)] = -half * f.nx(c);
        }
        let g = (spin_i_weight * s.spin_dq(&f, &inner, omega_i)
            + spin_o_weight * s.spin_dq(&f, &outer, 0.0)
            + (spin_i + spin_o) * dshare_dq)
            * e;
        a[(4, 0)] = g[0];
        a[(4, 1)] = g[1];
        a[(4, 3)] = spin_i_weight * f.nx(&inner) + spin_o_weight * f.nx(&outer);
        a[(4, 4)] = spin_i_weight * f.nr(&inner) + spin_o_weight * f.nr(&outer);

        // B: ball rows × ring u (only the inner contact depends on u).
        let mut b = Matrix5::zeros();
        let fu = e.transpose() * (dfi_du + dfric_i_du);
        b.fixed_view_mut::<2, 5>(0, 0).copy_from(&fu);
        b.set_row(2, &s.rolling_du(&f, &inner_k, omega_i));
        let spin_u = s.spin_du(&f, &inner, omega_i);
        b.set_row(4, &(spin_i_weight * spin_u + (spin_i + spin_o) * dshare_du));

        // Ring: force and moment of this ball on the inner ring.
        let friction = InnerFriction {
            force: fi,
            dq: dfric_i_dq,
            du: dfric_i_du,
            dwm: gyro.dfi_dwm,
            dwr: gyro.dfi_dwr,
        };
        let (ring_load, c, dd) = ring_terms(&inner, &friction, q - ring.translation, half, &e);
        BallTerms {
            speed_derivative: Vector5::new(
                0.0,
                0.0,
                -(r + half * f.nr(&inner_k)),
                0.0,
                -spin_i_weight * f.nx(&inner),
            ),
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

/// The gyroscopic friction f_k = c_k t_k at the inner and outer contact
/// (t_k = n_x e_r − n_r e_x, c_k = λ_k I ω_m ω_r / D), and its derivatives
/// by ω_m, ω_r and, at the inner contact, by q and u with the share's own
/// dependence (λ_i = 2s).
struct Gyroscopic {
    fi: Vector3<f64>,
    fo: Vector3<f64>,
    co: f64,
    dfi_dq: Matrix3<f64>,
    dfi_du: Matrix3x5,
    dfi_dwm: Vector3<f64>,
    dfo_dwm: Vector3<f64>,
    dfi_dwr: Vector3<f64>,
    dfo_dwr: Vector3<f64>,
}

impl Gyroscopic {
    fn new(
        f: &Frame,
        s: &BallSpeeds,
        shares: &ControlShares,
        (inner, outer): (&RingContactEval, &RingContactEval),
        inertia: f64,
        d: f64,
    ) -> Self {
        let (lambda_i, lambda_o, wm, wr) = (shares.lambda_i, shares.lambda_o, s.wm, s.wr);
        let mg = inertia * wm * wr;
        let (ci, co) = (lambda_i * mg / d, lambda_o * mg / d);
        let (ti, to) = (f.tangent(inner), f.tangent(outer));
        Self {
            fi: ci * ti,
            fo: co * to,
            co,
            dfi_dq: ci * f.dtangent_dq(inner) + ti * (2.0 * mg / d * shares.dshare_dq),
            dfi_du: ci * f.dtangent_du(inner) + ti * (2.0 * mg / d * shares.dshare_du),
            dfi_dwm: lambda_i * inertia * wr / d * ti,
            dfo_dwm: lambda_o * inertia * wr / d * to,
            dfi_dwr: lambda_i * inertia * wm / d * ti,
            dfo_dwr: lambda_o * inertia * wm / d * to,
        }
    }
}

/// Friction shares (λ_i, λ_o) of the gyroscopic moment and the weights of
/// the no-spin conditions s_i, s_o: at the controlling raceway. An
/// inner-controlled ball's share s = t w: faded by the drive weight w, and
/// blended by `inner_share` t on the way from outer control
/// (s s_i − (1 − s) s_o: the minus keeps the blend regular for a loaded
/// ball, whose n_i ≈ −n_o); with the gradients of s = t w.
struct ControlShares {
    lambda_i: f64,
    lambda_o: f64,
    spin_i_weight: f64,
    spin_o_weight: f64,
    dshare_dq: Row3,
    dshare_du: Row5,
}

impl ControlShares {
    fn new(control: RingKind, t: f64, drive: &RaceDrive) -> Self {
        if control == RingKind::Inner {
            let share = t * drive.weight;
            Self {
                lambda_i: 2.0 * share,
                lambda_o: 2.0 * (1.0 - t),
                spin_i_weight: share,
                spin_o_weight: share - 1.0,
                dshare_dq: t * drive.dq,
                dshare_du: t * drive.du,
            }
        } else {
            Self {
                lambda_i: 0.0,
                lambda_o: 2.0,
                spin_i_weight: 0.0,
                spin_o_weight: 1.0,
                dshare_dq: Row3::zeros(),
                dshare_du: Row5::zeros(),
            }
        }
    }
}

/// The inner raceway's gyroscopic friction force f_i on the ball and its
/// derivatives by the ball's position q, the ring's displacement u and
/// the ball's ω_m, ω_r.
struct InnerFriction {
    force: Vector3<f64>,
    dq: Matrix3<f64>,
    du: Matrix3x5,
    dwm: Vector3<f64>,
    dwr: Vector3<f64>,
}

/// Force and moment of one ball on the inner ring (the physical normal
/// law plus the inner friction force, acting at P = q + (D/2) n: an extra
/// couple −(D/2) n × f_i) at arm `arm` = q − the ring's translation, and
/// their derivatives: the load (F_x, F_y, F_z, M_y, M_z), C (by the ball's
/// x, r, ω_m, ω_x, ω_r through the basis `e`) and D (by the ring's u).
fn ring_terms(
    inner: &RingContactEval,
    friction: &InnerFriction,
    arm: Vector3<f64>,
    half: f64,
    e: &SMatrix<f64, 3, 2>,
) -> (Vector5, Matrix5, Matrix5) {
    let (fn_phys, dfn_dq, dfn_du) = if inner.in_contact() {
        (inner.force, inner.dforce_dball, inner.dforce_dring)
    } else {
        (Vector3::zeros(), Matrix3::zeros(), Matrix3x5::zeros())
    };
    let fi = friction.force;
    let f_ring = -(fn_phys + fi);
    let df_ring_dq = -(dfn_dq + friction.dq);
    let df_ring_du = -(dfn_du + friction.du);
    let df_ring_dwm = -friction.dwm;
    let df_ring_dwr = -friction.dwr;
    let arm_x = cross_matrix(&arm);
    let f_x = cross_matrix(&f_ring);
    let n_x = cross_matrix(&inner.normal);
    let fi_x = cross_matrix(&fi);
    let moment = arm.cross(&f_ring) - half * inner.normal.cross(&fi);
    let dm_dq = arm_x * df_ring_dq - f_x - half * (n_x * friction.dq - fi_x * inner.dnormal_dball);
    let mut dm_du = arm_x * df_ring_du - half * (n_x * friction.du - fi_x * inner.dnormal_dring);
    for k in 0..3 {
        let col = dm_du.column(k) + f_x.column(k);
        dm_du.set_column(k, &col);
    }
    let dm_dwm = arm_x * df_ring_dwm - half * n_x * friction.dwm;
    let dm_dwr = arm_x * df_ring_dwr - half * n_x * friction.dwr;
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
    (ring_load, c, dd)
}

#[cfg(test)]
mod tests {
    use super::super::{Conditions, RacewayControl, SolverOptions};
    use super::*;
    use crate::contact::HertzModel;
    use crate::geometry::{BearingGeometry, test_bearing};
    use crate::material::Material;
    use crate::operating::Loads;
    use crate::quasistatic::equilibrium::race_drive::GAP_FRACTION;
    use crate::quasistatic::ring_contact::RingDisplacement;

    /// A state of five balls at speed with the ring displaced: balls 3
    /// (outer control) and 4 (inner control) in the race drive's band,
    /// their inner gap at g_ref (w = 1/2); ball 2's inner contact open wide
    /// (w ≈ 0.008).
    fn drive_band_state(
        g: &BearingGeometry,
        solver: &QuasiStaticSolver,
        options: &SolverOptions,
    ) -> State {
        let mut state = State {
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
        let ring = RingDisplacement::from_array(state.ring.into());
        let g_ref = GAP_FRACTION * g.ball_diameter;
        for (j, gap) in [(2, 5.0 * g_ref), (3, g_ref), (4, g_ref)] {
            let phi = solver.azimuth(j, options);
            let (mut outside, mut inside) = (26.9e-3, 27.1e-3);
            for _ in 0..200 {
                let mut y = state.balls[j];
                y[1] = 0.5 * (outside + inside);
                if solver.contacts(j, &y, phi, &ring).1.penetration > -gap {
                    outside = y[1];
                } else {
                    inside = y[1];
                }
            }
            state.balls[j][1] = 0.5 * (outside + inside);
            let (_, inner, outer) = solver.contacts(j, &state.balls[j], phi, &ring);
            assert!((inner.penetration + gap).abs() < 1e-3 * gap, "ball {j}");
            assert!(outer.in_contact(), "ball {j}: outer contact open");
        }
        state
    }

    /// Fourth-order central differences of the balls' residuals and the
    /// ring load under `perturbed` (the drive band is steep).
    fn fourth_order(perturbed: &dyn Fn(f64) -> Assembly, h: f64) -> (Vec<Vector5>, Vector5) {
        let (p1, m1, p2, m2) = (
            perturbed(h),
            perturbed(-h),
            perturbed(2.0 * h),
            perturbed(-2.0 * h),
        );
        let combine = |f: &dyn Fn(&Assembly) -> Vector5| {
            (8.0 * (f(&p1) - f(&m1)) - (f(&p2) - f(&m2))) / (12.0 * h)
        };
        let balls: Vec<Vector5> = (0..p1.ball.len())
            .map(|j| combine(&|a: &Assembly| a.ball[j]))
            .collect();
        (balls, combine(&|a: &Assembly| a.ring))
    }

    fn close(fd: &Vector5, exact: Vector5) -> bool {
        (fd - exact).norm() <= 1e-4 * fd.norm().max(1e-3)
    }

    /// The blocks A, C (ball columns), B, D (ring columns) and the speed
    /// derivative of one assembly against [`fourth_order`] differences.
    fn check_blocks(
        solver: &QuasiStaticSolver,
        state: &State,
        controls: &[RingKind],
        setup: Setup,
    ) {
        let inner_share = setup.inner_share;
        let conditions = setup.conditions;
        let asm = solver.assemble(state, controls, setup);
        let steps = [1e-9, 1e-9, 1e-3, 1e-3, 1e-3];
        for j in 0..5 {
            for (k, &step) in steps.iter().enumerate() {
                let (fd_balls, fd_ring) = fourth_order(
                    &|h| {
                        let mut moved = state.clone();
                        moved.balls[j][k] += h;
                        solver.assemble(&moved, controls, setup)
                    },
                    step,
                );
                let (a, c) = (
                    asm.a[j].column(k).into_owned(),
                    asm.c[j].column(k).into_owned(),
                );
                assert!(
                    close(&fd_balls[j], a),
                    "A[{j}] col {k} (t {inner_share}): {:?} vs {a:?}",
                    fd_balls[j]
                );
                assert!(
                    close(&fd_ring, c),
                    "C[{j}] col {k} (t {inner_share}): {fd_ring:?} vs {c:?}"
                );
            }
        }
        let ring_steps = [1e-9, 1e-9, 1e-9, 1e-8, 1e-8];
        for (k, &step) in ring_steps.iter().enumerate() {
            let (fd_balls, fd_ring) = fourth_order(
                &|h| {
                    let mut moved = state.clone();
                    moved.ring[k] += h;
                    solver.assemble(&moved, controls, setup)
                },
                step,
            );
            let d = asm.d.column(k).into_owned();
            assert!(
                close(&fd_ring, d),
                "D col {k} (t {inner_share}): {fd_ring:?} vs {d:?}"
            );
            for (j, fd_ball) in fd_balls.iter().enumerate() {
                let b = asm.b[j].column(k).into_owned();
                assert!(
                    close(fd_ball, b),
                    "B[{j}] col {k} (t {inner_share}): {fd_ball:?} vs {b:?}"
                );
            }
        }
        // ∂residual/∂ω_i: the residual is linear in ω_i.
        let faster = Conditions {
            inner_speed: conditions.inner_speed + 1.0,
            ..*conditions
        };
        let moved = solver.assemble(
            state,
            controls,
            Setup {
                conditions: &faster,
                ..setup
            },
        );
        for j in 0..5 {
            let fd = moved.ball[j] - asm.ball[j];
            assert!(
                close(&fd, asm.speed_derivative[j]),
                "speed derivative of ball {j}: {fd:?} vs {:?}",
                asm.speed_derivative[j]
            );
        }
    }

    /// The assembled Jacobian blocks equal central differences of the
    /// residual, at speed, with friction on the inner ring: balls under
    /// inner and outer control, the inner control as stated (t = 1) and
    /// blended (t = 0.4, the outer-control homotopy).
    #[test]
    fn jacobian_matches_finite_differences() {
        let g = test_bearing(5);
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
        let state = drive_band_state(&g, &solver, &options);
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
            check_blocks(&solver, &state, &controls, setup);
        }
    }
}
