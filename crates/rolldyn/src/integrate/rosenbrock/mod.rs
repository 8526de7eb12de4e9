//! Linearly implicit Rosenbrock–W integration for stiff systems (Hairer &
//! Wanner, *Solving ODEs II*, 2nd ed., §IV.7 Rosenbrock methods and
//! W-methods; Rang & Angermann, *BIT Numer. Math.* 45 (2005) 761–787,
//! method ROS34PW2).
//!
//! One step with s stages solves, for i = 1…s, with the same matrix
//!
//! (I/(hγ) − A) Uᵢ = f(t + αᵢh, y + Σⱼ aᵢⱼUⱼ) + Σⱼ (cᵢⱼ/h) Uⱼ,
//!
//! y₁ = y + Σ mᵢUᵢ, error estimate Σ (mᵢ − m̂ᵢ)Uᵢ, in the transformed
//! variables Uᵢ = Σⱼ γᵢⱼkⱼ (HW IV.7.3: a = αΓ⁻¹, c = diag(1/γ) − Γ⁻¹,
//! m = bΓ⁻¹). A is **any** approximation of ∂f/∂y: a W-method keeps its
//! order with it, so A is re-evaluated only when a step is rejected with
//! an A at least [`MIN_AGE_FOR_REFRESH`] steps old or A has served
//! [`MAX_JACOBIAN_AGE`] steps (longer while the fast part is refreshed,
//! [`MAX_JACOBIAN_AGE_WITH_FAST_PART`]), and the time
//! derivative ∂f/∂t is left out (allowed for a W-method; it is the
//! autonomized system's Jacobian with one column approximated by zero).
//! Each new step size needs a new factorization of I/(hγ) − A, which the
//! bordered block structure makes cheap ([`super::linear`]).
//!
//! A system whose block split has a fast part refreshes that part's
//! Jacobian at every step while it lengthens the steps ([`fast_part`]).
//!
//! ROS34PW2: 4 stages, order 3 with an embedded order-2 estimate,
//! L-stable, stiffly accurate, W-order 3. The first stage reuses f at the
//! start of the step, which an accepted step evaluates anyway for the
//! dense output (cubic Hermite, order 3), so a step costs 4 right-hand
//! sides and one factorization. That f(y₁) is evaluated in every attempt
//! the states' error passes, with the balance at y₁ under the energy
//! control ([`OdeSystem::rhs_at_end`], one pass over the contacts that
//! also serves the step's acceptance), and kept if the step is accepted;
//! an attempt the energy then rejects has spent it.

use super::checkpoint::{Checkpoint, CheckpointError, StateReader, StateWriter};
use super::energy_control::EnergyControl;
use super::jacobian::{JacobianWork, finite_difference};
use super::linear::{BlockJacobian, BlockLayout, BlockLu};
use super::point::StepPoint;
use super::step_control::{IntegrationError, IntegrationStats, PiControl, StepMethod, take_step};
use super::{Integrator, OdeSystem, Tolerances};
use fast_part::FastRefresh;

pub mod fast_part;

/// Largest number of stages of a Rosenbrock tableau.
const MAX_STAGES: usize = 6;

/// Accepted steps one Jacobian may serve before it is re-evaluated.
pub const MAX_JACOBIAN_AGE: u32 = 20;

/// A rejected step re-evaluates the Jacobian only if it has served at
/// least this many steps; a rejection with a younger one is a matter of
/// accuracy, answered by a smaller step. Both constants were chosen on the
/// three bearing benchmarks (docs/performance.md, Jacobian reuse).
pub const MIN_AGE_FOR_REFRESH: u32 = 10;

/// [`MAX_JACOBIAN_AGE`] and [`MIN_AGE_FOR_REFRESH`] while the fast part is
/// refreshed at every step ([`fast_part`]): the rest of the Jacobian then
/// ages slowly (default case, 0.3 s: 8 050 steps with 173 Jacobians
/// against 7 961 with 580 at 20 and 10; docs/performance.md).
pub const MAX_JACOBIAN_AGE_WITH_FAST_PART: u32 = 80;
/// See [`MAX_JACOBIAN_AGE_WITH_FAST_PART`].
pub const MIN_AGE_FOR_REFRESH_WITH_FAST_PART: u32 = 40;

/// A Rosenbrock tableau in the original form of HW IV.7 (stage
/// coefficients αᵢⱼ, γᵢⱼ with common diagonal γ, weights b and b̂).
#[derive(Debug, Clone, PartialEq)]
pub struct RosenbrockTableau {
    /// Name for statistics and case files.
    pub name: &'static str,
    /// Order of the solution.
    pub order: u32,
    /// Diagonal γ.
    pub gamma: f64,
    /// αᵢⱼ, row i has i entries.
    pub alpha: &'static [&'static [f64]],
    /// γᵢⱼ below the diagonal, row i has i entries.
    pub gamma_below: &'static [&'static [f64]],
    /// Weights b.
    pub b: &'static [f64],
    /// Embedded weights b̂ (one order lower).
    pub b_embedded: &'static [f64],
}

/// ROS34PW2 of Rang & Angermann (2005), Table 4 (the digits as printed).
#[allow(clippy::excessive_precision)]
pub const ROS34PW2: RosenbrockTableau = RosenbrockTableau {
    name: "ros34pw2",
    order: 3,
    gamma: 4.358_665_215_084_590e-1,
    alpha: &[
        &[],
        &[8.717_330_430_169_180e-1],
        &[8.445_706_001_536_942e-1, -1.129_906_423_648_418e-1],
        &[0.0, 0.0, 1.0],
    ],
    gamma_below: &[
        &[],
        &[-8.717_330_430_169_180e-1],
        &[-9.033_805_701_304_408e-1, 5.418_067_238_809_533e-2],
        &[
            2.421_238_070_609_535e-1,
            -1.223_250_583_904_515,
            5.452_602_553_351_021e-1,
        ],
    ],
    b: &[
        2.421_238_070_609_535e-1,
        -1.223_250_583_904_515,
        1.545_260_255_335_102,
        4.358_665_215_084_590e-1,
    ],
    b_embedded: &[
        3.781_090_314_581_937e-1,
        -9.604_229_221_242_318e-2,
        0.5,
        2.179_332_607_542_295e-1,
    ],
};

/// The tableau in transformed variables.
#[derive(Debug, Clone, Copy)]
struct Transformed {
    stages: usize,
    gamma: f64,
    /// Stage time fractions αᵢ = Σⱼ αᵢⱼ.
    node: [f64; MAX_STAGES],
    a: [[f64; MAX_STAGES]; MAX_STAGES],
    c: [[f64; MAX_STAGES]; MAX_STAGES],
    m: [f64; MAX_STAGES],
    error: [f64; MAX_STAGES],
}

impl Transformed {
    // Triangular-matrix index arithmetic reads clearest with indices.
    #[allow(clippy::needless_range_loop)]
    fn of(tab: &RosenbrockTableau) -> Self {
        let s = tab.b.len();
        assert!(s <= MAX_STAGES && tab.alpha.len() == s && tab.gamma_below.len() == s);
        // Γ (lower triangular, diagonal γ) and its inverse by substitution.
        let mut g = [[0.0; MAX_STAGES]; MAX_STAGES];
        for i in 0..s {
            g[i][..i].copy_from_slice(tab.gamma_below[i]);
            g[i][i] = tab.gamma;
        }
        let mut inv = [[0.0; MAX_STAGES]; MAX_STAGES];
        for col in 0..s {
            for i in col..s {
                let rhs = if i == col { 1.0 } else { 0.0 };
                let sum: f64 = (col..i).map(|k| g[i][k] * inv[k][col]).sum();
                inv[i][col] = (rhs - sum) / g[i][i];
            }
        }
        let mut me = Self {
            stages: s,
            gamma: tab.gamma,
            node: [0.0; MAX_STAGES],
            a: [[0.0; MAX_STAGES]; MAX_STAGES],
            c: [[0.0; MAX_STAGES]; MAX_STAGES],
            m: [0.0; MAX_STAGES],
            error: [0.0; MAX_STAGES],
        };
        for i in 0..s {
            me.node[i] = tab.alpha[i].iter().sum();
            for j in 0..i {
                me.a[i][j] = (0..i).map(|k| tab.alpha[i][k] * inv[k][j]).sum();
                me.c[i][j] = -inv[i][j];
            }
        }
        for j in 0..s {
            let m: f64 = (0..s).map(|i| tab.b[i] * inv[i][j]).sum();
            let m_hat: f64 = (0..s).map(|i| tab.b_embedded[i] * inv[i][j]).sum();
            me.m[j] = m;
            me.error[j] = m - m_hat;
        }
        me
    }
}

/// A Rosenbrock–W integrator with its work space.
#[derive(Debug, Clone)]
pub struct Rosenbrock {
    tableau: &'static RosenbrockTableau,
    coefficients: Transformed,
    max_step: f64,
    /// The current point, the last accepted step, the controller, the
    /// energy control and the counters.
    point: StepPoint,
    stages: Vec<Vec<f64>>,
    stage_y: Vec<f64>,
    y_new: Vec<f64>,
    /// f at y_new, when the last attempt evaluated it with the energy
    /// balance there ([`OdeSystem::rhs_at_end`]; `end_evaluated`):
    /// the next step's first stage if the step is accepted.
    f_new: Vec<f64>,
    end_evaluated: bool,
    error: Vec<f64>,
    tolerances: Tolerances,
    jacobian: BlockJacobian,
    /// The fast part's refresh, for a system that has one.
    fast: Option<FastRefresh>,
    lu: BlockLu,
    work: JacobianWork,
    /// Accepted steps since the Jacobian was evaluated; None: none yet.
    jacobian_age: Option<u32>,
    /// Step size of the current factorization.
    factored_step: Option<f64>,
    /// Whether the factorization has gathered the current Jacobian (a new
    /// step size then only refactors, [`BlockLu::refactor`]).
    gathered: bool,
}

impl Rosenbrock {
    /// The builder of an integrator with this tableau ([`super::Builder`]:
    /// defaults, changed by name).
    pub fn builder(tableau: &'static RosenbrockTableau) -> super::Builder<RosenbrockTableau> {
        super::Builder::new(tableau)
    }

    /// Sets up an integration of `system` from (t0, y0) with error control.
    pub(crate) fn start(
        tableau: &'static RosenbrockTableau,
        relative_tolerance: f64,
        max_step: f64,
        initial_step: Option<f64>,
        system: &impl OdeSystem,
        t0: f64,
        y0: &[f64],
    ) -> Result<Self, IntegrationError> {
        StepPoint::check_adaptive(relative_tolerance, max_step)?;
        let point = StepPoint::start(system, t0, y0)?;
        let n = y0.len();
        let layout = system
            .blocks()
            .map(|s| s.block_layout())
            .unwrap_or(BlockLayout::dense(n));
        if layout.dimension() != n {
            return Err(IntegrationError::Setting(format!(
                "block layout covers {} states, the system has {n}",
                layout.dimension()
            )));
        }
        let tolerances = Tolerances::new(system, relative_tolerance);
        let coefficients = Transformed::of(tableau);
        let mut me = Self {
            tableau,
            coefficients,
            max_step,
            point,
            stages: vec![vec![0.0; n]; coefficients.stages],
            stage_y: vec![0.0; n],
            y_new: vec![0.0; n],
            f_new: vec![0.0; n],
            end_evaluated: false,
            error: vec![0.0; n],
            tolerances,
            jacobian: BlockJacobian::zeros(layout),
            fast: FastRefresh::of(system, &BlockJacobian::zeros(layout)),
            lu: match system.blocks() {
                Some(split) => {
                    let mut lu = BlockLu::with_structure(
                        layout,
                        |state| split.inert(state),
                        |state| split.rate_of(state),
                    );
                    lu.set_parallel(split.parallel());
                    lu
                }
                None => BlockLu::new(layout),
            },
            work: JacobianWork::new(system),
            jacobian_age: None,
            factored_step: None,
            gathered: false,
        };
        me.point.h = initial_step
            .unwrap_or_else(|| me.starting_step())
            .min(max_step);
        Ok(me)
    }

    /// A first step from the size of f relative to the tolerance: the
    /// explicit estimate of HW I §II.4 without its second evaluation
    /// (stiff components make that one meaningless); the controller
    /// corrects it within a few steps.
    fn starting_step(&self) -> f64 {
        let mut sum = 0.0;
        for i in 0..self.point.y.len() {
            sum += (self.point.f[i] / (self.tolerances.scale(i, self.point.y[i].abs()))).powi(2);
        }
        let d1 = (sum / self.point.y.len() as f64).sqrt();
        if d1 < 1e-5 {
            1e-6
        } else {
            (0.01 / d1).clamp(1e-12, 1e-3)
        }
    }

    /// Also controls the error of the system's energy balance to
    /// `tolerance` per unit of energy turned over in a step
    /// ([`super::energy_control`]); no effect for a system that keeps no
    /// balance. Call before the first step.
    pub(crate) fn with_energy_control(mut self, system: &impl OdeSystem, tolerance: f64) -> Self {
        self.point
            .control_energy(system, tolerance, self.tableau.order);
        self
    }

    /// Step size the next step will try.
    pub fn step_size(&self) -> f64 {
        self.point.h
    }

    /// Continues from (t, y) with a first step h, as after a hand-over from
    /// another integrator: f evaluated afresh, a new Jacobian before the
    /// next step, the controller's memory cleared, the energy control
    /// continued from `energy`.
    pub(crate) fn restart(
        &mut self,
        system: &impl OdeSystem,
        t: f64,
        y: &[f64],
        h: f64,
        energy: Option<&EnergyControl>,
    ) {
        self.point
            .restart(system, t, y, h.min(self.max_step), energy);
        self.jacobian_age = None;
        self.factored_step = None;
        self.gathered = false;
        if let Some(fast) = &mut self.fast {
            fast.restart();
        }
    }

    /// The energy-balance control, if any.
    pub(crate) fn energy_control(&self) -> Option<&EnergyControl> {
        self.point.energy.as_ref()
    }

    /// The tableau's name.
    pub fn name(&self) -> &'static str {
        self.tableau.name
    }

    fn evaluate_jacobian(&mut self, system: &impl OdeSystem) {
        let cost = finite_difference(
            system,
            self.point.t,
            &self.point.y,
            &self.point.f,
            &mut self.jacobian,
            &mut self.work,
        );
        self.point.stats.jacobian_evaluations += 1;
        self.point.stats.jacobian_rhs_evaluations += cost;
        self.jacobian_age = Some(0);
        self.factored_step = None;
        self.gathered = false;
        if let Some(fast) = &mut self.fast
            && fast.split(
                system,
                (self.point.t, &self.point.y),
                &self.jacobian,
                &mut self.work,
            )
        {
            self.point.stats.fast_part_jacobians += 1;
        }
    }

    /// Stages and candidate for step h; the scaled error norm (∞ when the
    /// matrix is singular or the stages are not finite).
    fn try_step(&mut self, system: &mut impl OdeSystem, h: f64) -> f64 {
        let co = self.coefficients;
        let n = self.point.y.len();
        self.end_evaluated = false;
        self.point.states_error = f64::INFINITY;
        if self.factored_step != Some(h) {
            self.point.stats.factorizations += 1;
            let sigma = 1.0 / (h * co.gamma);
            let factored = if self.gathered {
                self.lu.refactor(&self.jacobian, sigma)
            } else {
                self.gathered = true;
                self.lu.factor(&self.jacobian, sigma)
            };
            if factored.is_err() {
                self.factored_step = None;
                return f64::INFINITY;
            }
            self.factored_step = Some(h);
        }
        for i in 0..co.stages {
            let (done, rest) = self.stages.split_at_mut(i);
            let u = &mut rest[0];
            if i == 0 {
                u.copy_from_slice(&self.point.f);
            } else {
                for k in 0..n {
                    let mut acc = self.point.y[k];
                    for (j, d) in done.iter().enumerate() {
                        acc += co.a[i][j] * d[k];
                    }
                    self.stage_y[k] = acc;
                }
                system.rhs(self.point.t + co.node[i] * h, &self.stage_y, u);
                self.point.stats.rhs_evaluations += 1;
                for k in 0..n {
                    let mut acc = 0.0;
                    for (j, d) in done.iter().enumerate() {
                        acc += co.c[i][j] * d[k];
                    }
                    u[k] += acc / h;
                }
            }
            self.lu.solve(u);
        }
        let (mut sum, mut largest) = (0.0, (0, 0.0));
        for k in 0..n {
            let (mut step, mut err) = (0.0, 0.0);
            for i in 0..co.stages {
                step += co.m[i] * self.stages[i][k];
                err += co.error[i] * self.stages[i][k];
            }
            self.y_new[k] = self.point.y[k] + step;
            self.error[k] = err;
            let scale = self
                .tolerances
                .scale(k, self.point.y[k].abs().max(self.y_new[k].abs()));
            let term = (err / scale).powi(2);
            sum += term;
            if term > largest.1 {
                largest = (k, term);
            }
        }
        // The refresh starts from a full Jacobian (its slow rest).
        if let Some(fast) = &mut self.fast {
            let led = system.blocks().is_some_and(|s| s.fast_state(largest.0));
            if fast.attempted(led) {
                self.jacobian_age = None;
            }
        }
        let err = (sum / n as f64).sqrt();
        self.point.states_error = err;
        if !err.is_finite() {
            return f64::INFINITY;
        }
        if err > 1.0 {
            return err;
        }
        // The states pass: f(y₁), which an accepted step needs next, and
        // the balance there for the energy's verdict, from one evaluation.
        let balance = self.point.energy.is_some();
        let end = system.rhs_at_end(self.point.t + h, &self.y_new, &mut self.f_new, balance);
        self.point.stats.rhs_evaluations += 1;
        self.end_evaluated = true;
        match &mut self.point.energy {
            Some(energy) => {
                let e = &self.error;
                let candidate = (&self.y_new[..], end);
                err.max(energy.scaled_error(
                    system,
                    self.point.t,
                    &self.point.y,
                    h,
                    candidate,
                    |k| e[k],
                ))
            }
            None => err,
        }
    }

    fn finish_step(&mut self, system: &mut impl OdeSystem, h: f64) {
        self.point.advance(h, &self.y_new);
        let changed = system.accept_step(self.point.t, &self.point.y);
        if self.end_evaluated && !changed {
            std::mem::swap(&mut self.point.f, &mut self.f_new);
        } else {
            system.rhs(self.point.t, &self.point.y, &mut self.point.f);
            self.point.stats.rhs_evaluations += 1;
        }
        self.point.accepted();
        if let Some(age) = &mut self.jacobian_age {
            *age += 1;
        }
        if let Some(fast) = &mut self.fast {
            fast.accepted();
        }
    }
}

impl StepMethod for Rosenbrock {
    fn point(&self) -> (f64, &[f64]) {
        (self.point.t, &self.point.y)
    }

    fn max_step(&self) -> f64 {
        self.max_step
    }

    /// The embedded solution has order q − 1: the error scales as h^q.
    fn error_order(&self) -> Option<f64> {
        Some(self.tableau.order as f64)
    }

    fn step_size(&mut self) -> (&mut f64, &mut PiControl) {
        (&mut self.point.h, &mut self.point.control)
    }

    fn prepare<S: OdeSystem>(&mut self, system: &S) {
        let refreshing = self.fast.as_ref().is_some_and(FastRefresh::refreshing);
        let max_age = if refreshing {
            MAX_JACOBIAN_AGE_WITH_FAST_PART
        } else {
            MAX_JACOBIAN_AGE
        };
        if self.jacobian_age.is_none_or(|age| age >= max_age) {
            self.evaluate_jacobian(system);
        } else if let Some(fast) = &mut self.fast
            && fast.refresh(
                system,
                (self.point.t, &self.point.y),
                &mut self.jacobian,
                &mut self.work,
            )
        {
            self.point.stats.fast_part_jacobians += 1;
            self.factored_step = None;
            self.gathered = false;
        }
    }

    fn attempt<S: OdeSystem>(&mut self, system: &mut S, h: f64) -> f64 {
        self.try_step(system, h)
    }

    fn finish<S: OdeSystem>(&mut self, system: &mut S, h: f64) {
        self.finish_step(system, h);
    }

    fn states_error(&self) -> f64 {
        self.point.states_error
    }

    /// A rejection with an old Jacobian refreshes it first.
    fn reject(&mut self) {
        self.point.stats.rejected_steps += 1;
        let min_age = if self.fast.as_ref().is_some_and(FastRefresh::refreshing) {
            MIN_AGE_FOR_REFRESH_WITH_FAST_PART
        } else {
            MIN_AGE_FOR_REFRESH
        };
        if self.jacobian_age.is_some_and(|age| age >= min_age) {
            self.jacobian_age = None;
        }
    }

    fn too_small<S: OdeSystem>(
        &self,
        system: &S,
        step: f64,
        _tried: f64,
        err: f64,
    ) -> IntegrationError {
        let terms = (0..self.point.y.len()).map(|k| {
            let scale = self
                .tolerances
                .scale(k, self.point.y[k].abs().max(self.y_new[k].abs()));
            if self.y_new[k].is_finite() {
                (self.error[k] / scale).abs()
            } else {
                f64::INFINITY
            }
        });
        PiControl::too_small(
            self.point.t,
            step,
            err,
            system,
            terms,
            &self.point.y,
            &self.point.f,
            &self.tolerances,
        )
    }
}

impl Checkpoint for Rosenbrock {
    fn save(&self, out: &mut StateWriter) {
        out.tag(self.tableau.name);
        self.point.save(out);
        out.f64(self.point.control.err_prev);
        // Age + 1, 0 for "no Jacobian yet".
        out.u64(self.jacobian_age.map_or(0, |a| u64::from(a) + 1));
        out.opt_f64(self.factored_step);
        let j = &self.jacobian;
        for part in [&j.diag, &j.upper, &j.lower, &j.border] {
            out.f64s(part);
        }
        self.point.save_energy(out);
        if let Some(fast) = &self.fast {
            fast.save(out);
        }
        self.point.stats.save(out);
    }

    /// Restores the state; the iteration matrix is factored again from the
    /// saved Jacobian and step (the same operations, so the same bits).
    fn restore(&mut self, input: &mut StateReader) -> Result<(), CheckpointError> {
        input.tag(self.tableau.name)?;
        self.point.restore(input)?;
        self.point.control.err_prev = input.f64()?;
        self.jacobian_age = match input.u64()? {
            0 => None,
            a => Some(u32::try_from(a - 1).map_err(|_| {
                CheckpointError::Mismatch(format!("Jacobian age {a} out of range"))
            })?),
        };
        self.factored_step = input.opt_f64()?;
        self.gathered = false;
        let j = &mut self.jacobian;
        input.f64s_into("jacobian diagonal blocks", &mut j.diag)?;
        input.f64s_into("jacobian upper border", &mut j.upper)?;
        input.f64s_into("jacobian lower border", &mut j.lower)?;
        input.f64s_into("jacobian corner", &mut j.border)?;
        self.point.restore_energy(input)?;
        if let Some(fast) = &mut self.fast {
            fast.restore(input)?;
        }
        self.point.stats.restore(input)?;
        if let Some(h) = self.factored_step {
            self.gathered = true;
            if self
                .lu
                .factor(&self.jacobian, 1.0 / (h * self.coefficients.gamma))
                .is_err()
            {
                self.factored_step = None;
            }
        }
        Ok(())
    }
}

impl Integrator for Rosenbrock {
    /// Current time.
    fn t(&self) -> f64 {
        self.point.t
    }

    /// Current state.
    fn y(&self) -> &[f64] {
        &self.point.y
    }

    /// Takes one accepted step, not beyond `t_limit` (`step_control::take_step`).
    /// Calls the system's `accept_step` hook once, after acceptance.
    fn step<S: OdeSystem>(&mut self, system: &mut S, t_limit: f64) -> Result<(), IntegrationError> {
        take_step(self, system, t_limit)
    }

    /// Dense output: cubic Hermite interpolation in the last accepted step
    /// (clamped to it), order 3 like the method.
    fn interpolate(&self, t: f64, out: &mut [f64]) {
        super::explicit::hermite(
            self.point.t_prev,
            self.point.h_prev,
            &self.point.y_prev,
            &self.point.f_prev,
            &self.point.y,
            &self.point.f,
            t,
            out,
        );
    }

    /// Counters so far.
    fn stats(&self) -> IntegrationStats {
        self.point.stats
    }
}

#[cfg(test)]
mod tests;
