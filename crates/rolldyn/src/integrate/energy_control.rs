//! Step control by the energy balance: a second error estimate, of the
//! quantity a mechanical system's accuracy is judged by.
//!
//! A system that keeps an energy balance (drive work W, dissipated energy
//! D and mechanical energy E, [`super::OdeSystem::energy_balance`]) has
//! the invariant R = W − D − E: constant along every exact solution.
//! The usual error norm weighs each state against its own tolerance, and
//! three failures pass it on bearing models (measured in
//! docs/dynamics.md, "Accuracy at default settings"):
//!
//! * an L-stable method damps a lightly damped vibration (a ring ringing
//!   after a ball leaves a spall) by a little every step, each step within
//!   tolerance; the energy of the vibration disappears from the balance;
//! * at loose tolerances a Rosenbrock–W step can feed a stiff slip mode
//!   that the traction then dissipates: energy is made and destroyed, the
//!   states stay within their tolerances;
//! * an RMS norm over hundreds of states dilutes the error of the few that
//!   carry the energy (a ring, the accumulators).
//!
//! The estimate is the change of R between the solution y₁ and the
//! embedded solution ŷ₁ of the same step, |R(y₁) − R(ŷ₁)|: the local error
//! of the lower-order solution, measured in joules. Where the model's own
//! bookkeeping is not exact (the contact stiffness varying with the contact
//! angle, docs/dynamics.md), both solutions carry the same defect to
//! higher order, so the estimate sees integration error only and the
//! control cannot stall on a modelling approximation.
//!
//! The allowance is per unit of energy turned over in the step ("error per
//! unit step", Hairer, Nørsett & Wanner I §II.4): ε (s |ΔW| + |ΔD|), at
//! least ε h P₀ with P₀ = 1 µW for systems with neither drive nor
//! dissipation, plus what rounding alone can put between the two
//! residuals (n ε (|W| + |D| + |E|) for n states, Higham 2002, §4.2): an
//! estimate at the energies' last bits is not integration error, and
//! without this floor a quiet start (no work, no dissipation yet, ε h P₀
//! below the last bit of the balls' kinetic energy) rejected every step
//! whose two solutions differed there. The drive's turnover counts with
//! s = |W − W₀| / Σ|ΔW|, the net share of the drive work turned over so
//! far: a drive that
//! exchanges energy back and forth with a vibration (a ring ringing on its
//! contacts after a spall impact modulates the traction torque: ±30 W
//! about a 14 mW mean) would otherwise earn an allowance from work it
//! takes back. The estimates' sum over a run is then bounded by
//! ε (|W − W₀| + D), the scale the balance is judged on, whatever the number
//! of steps (the error kept came within 3.4 ε of it on a drive exchanging
//! 100 times its net work; unit test).
//!
//! The states' scaled error ‖e‖ of a method of error order q goes as h^q,
//! and the PI controller's exponents assume it. The energy's ratio
//! |ΔR̂| / allowance goes as h^(q−1) (an error per unit step, HNW I §II.4),
//! so it enters the controller as (|ΔR̂| / allowance)^(q/(q−1)): the same
//! steps pass (the ratio ≤ 1 either way), and a step the energy decides is
//! resized by the exponent its error follows (unit test in
//! `rosenbrock`). The larger of the two goes to the step-size controller,
//! so the same PI control rejects and shrinks steps for either reason.

use super::OdeSystem;
use super::checkpoint::{CheckpointError, StateReader, StateWriter};

/// The energy balance of a mechanical system at one state \[J\]; see
/// [`super::OdeSystem::energy_balance`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EnergyBalance {
    /// Work of the drive and the external forces since the start.
    pub work: f64,
    /// Energy dissipated since the start.
    pub dissipated: f64,
    /// Mechanical energy (kinetic, elastic, potential).
    pub mechanical: f64,
}

impl EnergyBalance {
    /// W − D − E: constant along an exact solution.
    pub fn residual(&self) -> f64 {
        self.work - self.dissipated - self.mechanical
    }

    /// The balance's error since `start`, ΔW − ΔD − ΔE, relative to the
    /// larger of the drive work and the dissipated energy (as `rolldyn
    /// run` reports it; 0 when both are 0).
    pub fn relative_error_since(&self, start: &EnergyBalance) -> f64 {
        let (work, dissipated) = (self.work - start.work, self.dissipated - start.dissipated);
        let scale = work.abs().max(dissipated.abs());
        if scale > 0.0 {
            (self.residual() - start.residual()) / scale
        } else {
            0.0
        }
    }
}

/// Power below which a step's allowance does not shrink: a system with
/// neither drive nor dissipation is held to ε × 1 µW × h \[W\].
pub const POWER_FLOOR: f64 = 1e-6;

/// Share of the energy turned over so far that one step may add to the
/// balance's error beyond its per-unit-step allowance (times ε). Where the
/// right-hand side jumps (the ball's path over a spall has kinks), the
/// local error is O(h) and the per-unit-step allowance, also O(h), would
/// never pass; this floor lets the step shrink until the jump's share is
/// negligible: a million such steps add at most ε × the turnover. Where a
/// tight ε and little energy turned over yet put that below the time
/// resolution, the step loop takes the step the states pass at the
/// resolution (`step_control::take_step`).
pub const EVENT_SHARE: f64 = 1e-6;

/// Default ε of `solver.energy_tolerance`: the largest error in the energy
/// balance per unit of energy turned over in a step, as estimated by the
/// embedded solution. Measured on the accuracy regimes (docs/performance.md):
/// 1e-3 left the power loss of starts at 1 and 100 rpm 480 % and 2.6 %
/// off a tighter run; 1e-4 holds them to 0.1 % and closes every regime's
/// balance but the deep spall's, at up to 8× the cost of no control.
pub const DEFAULT_ENERGY_TOLERANCE: f64 = 1e-4;

/// The energy-balance error control of one integrator.
#[derive(Debug, Clone)]
pub(crate) struct EnergyControl {
    tolerance: f64,
    /// q / (q − 1) for a method whose error scales as h^q (see
    /// [`Self::scaled_error`]).
    exponent: f64,
    /// Balance at the current accepted point (saved with a checkpoint).
    current: Option<EnergyBalance>,
    /// Drive work at the start of the control \[J\].
    origin_work: f64,
    /// Drive work turned over so far, Σ |ΔW| over the accepted steps \[J\].
    gross_work: f64,
    /// Balance at the last attempt's solution y₁.
    candidate: EnergyBalance,
    /// |ΔW| of the last attempt \[J\].
    candidate_drive: f64,
    /// Work space for the embedded solution.
    embedded: Vec<f64>,
}

impl EnergyControl {
    /// Control with tolerance ε for `system` from (t, y) under a method
    /// whose error scales as h^`order`, or None when the system keeps no
    /// energy balance.
    pub(crate) fn new(
        system: &impl OdeSystem,
        tolerance: f64,
        order: f64,
        t: f64,
        y: &[f64],
    ) -> Option<Self> {
        let current = system.energy_balance(t, y)?;
        Some(Self {
            tolerance,
            exponent: order / (order - 1.0),
            current: Some(current),
            origin_work: current.work,
            gross_work: 0.0,
            candidate: current,
            candidate_drive: 0.0,
            embedded: vec![0.0; y.len()],
        })
    }

    /// Scaled energy error of a step of size h from (t, y) to (t + h, y₁),
    /// whose balance is `end` (the integrator has it from the system's
    /// [`OdeSystem::rhs_at_end`]) and whose embedded solution is
    /// y₁ − `error`: ≤ 1 passes; raised to q/(q − 1) so that it scales as
    /// h^q like the states' error.
    pub(crate) fn scaled_error(
        &mut self,
        system: &impl OdeSystem,
        t: f64,
        y: &[f64],
        h: f64,
        (y_new, end): (&[f64], Option<EnergyBalance>),
        error: impl Fn(usize) -> f64,
    ) -> f64 {
        let start = match self.current {
            Some(b) => b,
            None => {
                let Some(b) = system.energy_balance(t, y) else {
                    return 0.0;
                };
                self.current = Some(b);
                b
            }
        };
        let Some(end) = end else {
            return 0.0;
        };
        for (k, e) in self.embedded.iter_mut().enumerate() {
            *e = y_new[k] - error(k);
        }
        let Some(embedded) = system.energy_balance(t + h, &self.embedded) else {
            return 0.0;
        };
        self.candidate = end;
        self.candidate_drive = (end.work - start.work).abs();
        let estimate = (end.residual() - embedded.residual()).abs();
        let turnover = self.candidate_drive * self.net_share(start)
            + (end.dissipated - start.dissipated).abs();
        let allowed = self.tolerance
            * (turnover.max(h * POWER_FLOOR)
                + EVENT_SHARE * (end.work.abs() + end.dissipated.abs()))
            + self.rounding(&end);
        let scaled = (estimate / allowed).powf(self.exponent);
        if scaled.is_finite() {
            scaled
        } else {
            f64::INFINITY
        }
    }

    /// What rounding alone can put between the residuals of two nearby
    /// states: each of W, D and E sums at most one term per state, and a
    /// sum of n terms carries an error of at most n u Σ|terms| (u = ε/2,
    /// Higham 2002, §4.2); two residuals differ by up to twice that, taken
    /// on |W| + |D| + |E|. An estimate below it is not integration error.
    fn rounding(&self, at: &EnergyBalance) -> f64 {
        let terms = self.embedded.len() as f64;
        terms * f64::EPSILON * (at.work.abs() + at.dissipated.abs() + at.mechanical.abs())
    }

    /// The net share of the drive work turned over so far, |W − W₀| / Σ |ΔW|
    /// (1 before the first step): a drive that exchanges energy back and
    /// forth with a vibration counts only with what it supplies net.
    fn net_share(&self, current: EnergyBalance) -> f64 {
        let net = (current.work - self.origin_work).abs();
        if self.gross_work > 0.0 {
            (net / self.gross_work).min(1.0)
        } else {
            1.0
        }
    }

    /// Takes over the bookkeeping of `other`, which integrated the same
    /// system up to the current point (a switch of method).
    pub(crate) fn continue_from(&mut self, other: &EnergyControl) {
        self.current = other.current;
        self.origin_work = other.origin_work;
        self.gross_work = other.gross_work;
    }

    /// The last attempt was accepted: its end is the new current point.
    pub(crate) fn accepted(&mut self) {
        self.current = Some(self.candidate);
        self.gross_work += self.candidate_drive;
    }

    /// Saves the balance at the current point: evaluated again after a
    /// restore it could differ in the last bits (the model's memory, e.g.
    /// a coupled thermal state, changes after the step it was taken at).
    pub(crate) fn save(&self, out: &mut StateWriter) {
        out.tag("energy balance");
        out.f64(self.origin_work);
        out.f64(self.gross_work);
        let b = self.current;
        out.opt_f64(b.map(|b| b.work));
        out.opt_f64(b.map(|b| b.dissipated));
        out.opt_f64(b.map(|b| b.mechanical));
    }

    /// Restores what [`Self::save`] wrote.
    pub(crate) fn restore(&mut self, input: &mut StateReader) -> Result<(), CheckpointError> {
        input.tag("energy balance")?;
        self.origin_work = input.f64()?;
        self.gross_work = input.f64()?;
        let (work, dissipated, mechanical) = (input.opt_f64()?, input.opt_f64()?, input.opt_f64()?);
        self.current = match (work, dissipated, mechanical) {
            (Some(work), Some(dissipated), Some(mechanical)) => Some(EnergyBalance {
                work,
                dissipated,
                mechanical,
            }),
            _ => None,
        };
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// x'' = −ω² x with its energy as the balance (no drive, no loss).
    struct Oscillator;
    impl OdeSystem for Oscillator {
        fn dimension(&self) -> usize {
            2
        }
        fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
            dy[0] = y[1];
            dy[1] = -1e6 * y[0];
        }
        fn energy_balance(&self, _t: f64, y: &[f64]) -> Option<EnergyBalance> {
            Some(EnergyBalance {
                work: 0.0,
                dissipated: 0.0,
                mechanical: 0.5 * y[1] * y[1] + 0.5e6 * y[0] * y[0],
            })
        }
    }

    #[test]
    fn estimate_is_the_residual_change_between_the_solutions() {
        let mut control = EnergyControl::new(&Oscillator, 1e-3, 3.0, 0.0, &[1e-3, 0.0]).unwrap();
        let y = [1e-3, 0.0];
        let y_new = [1e-3, 1e-3];
        // Embedded solution y_new − e = (1e-3, 0): residual change 0.5e-6 J.
        let end = (&y_new[..], Oscillator.energy_balance(1e-6, &y_new));
        let scaled = control.scaled_error(&Oscillator, 0.0, &y, 1e-6, end, |k| {
            if k == 1 { 1e-3 } else { 0.0 }
        });
        // Raised to q/(q − 1) = 3/2 for a method of error order 3.
        // The allowance ε h P₀, and the rounding of E = 0.5 J over 2 states.
        let allowed = 1e-3 * 1e-6 * POWER_FLOOR + 2.0 * f64::EPSILON * (0.5 + 0.5e-6);
        let expected = (0.5e-6 / allowed).powf(1.5);
        assert!((scaled - expected).abs() < 1e-9 * expected);
        // Equal solutions: no energy error.
        let scaled = control.scaled_error(&Oscillator, 0.0, &y, 1e-6, end, |_| 0.0);
        assert_eq!(scaled, 0.0);
    }

    /// A mass driven by F(t) = F₀ sin ωt through a viscous damper to
    /// ground and a spring: m v' = F − c v − k x, with W' = F v and
    /// D' = c v² as states, E = ½ m v² + ½ k x².
    struct Driven;
    impl Driven {
        const M: f64 = 1e-3;
        const C: f64 = 0.05;
        const K: f64 = 1e5;
        fn force(t: f64) -> f64 {
            10.0 * (3000.0 * t).sin()
        }
    }
    impl OdeSystem for Driven {
        fn dimension(&self) -> usize {
            4
        }
        fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
            let (x, v) = (y[0], y[1]);
            let f = Self::force(t);
            dy[0] = v;
            dy[1] = (f - Self::C * v - Self::K * x) / Self::M;
            dy[2] = f * v;
            dy[3] = Self::C * v * v;
        }
        fn error_scale(&self, scale: &mut [f64]) {
            scale.copy_from_slice(&[1e-6, 1e-3, 1e-6, 1e-6]);
        }
        fn energy_balance(&self, _t: f64, y: &[f64]) -> Option<EnergyBalance> {
            Some(EnergyBalance {
                work: y[2],
                dissipated: y[3],
                mechanical: 0.5 * Self::M * y[1] * y[1] + 0.5 * Self::K * y[0] * y[0],
            })
        }
    }

    /// The balance error of a run of `Driven` over 20 ms at rtol 1e-2,
    /// relative to the energy turned over, and the steps taken.
    fn driven_balance(energy_tolerance: Option<f64>) -> (f64, u64) {
        use crate::integrate::{Integrator, ROS34PW2, Rosenbrock};
        let y0 = [0.0; 4];
        let mut r = Rosenbrock::builder(&ROS34PW2)
            .relative_tolerance(1e-2)
            .max_step(1e-3)
            .energy_tolerance(energy_tolerance)
            .build(&Driven, &y0)
            .unwrap();
        // Turnover: Σ |ΔW| + ΔD over the accepted steps.
        let (mut turnover, mut last) = (0.0, Driven.energy_balance(0.0, &y0).unwrap());
        while r.t() < 0.02 {
            r.step(&mut Driven, 0.02).unwrap();
            let b = Driven.energy_balance(r.t(), r.y()).unwrap();
            turnover += (b.work - last.work).abs() + (b.dissipated - last.dissipated).abs();
            last = b;
        }
        (last.residual().abs() / turnover, r.stats().steps)
    }

    #[test]
    fn the_control_holds_the_balance_to_its_tolerance() {
        let (loose, loose_steps) = driven_balance(None);
        for eps in [1e-3, 1e-4] {
            let (held, steps) = driven_balance(Some(eps));
            // The sum of the per-step allowances bounds the error; the
            // estimate is the lower-order solution's, so the error of the
            // solution kept is smaller still.
            assert!(held <= eps, "ε {eps}: balance {held:e} of the turnover");
            assert!(steps > loose_steps, "ε {eps}: {steps} steps");
        }
        // Without the control the state tolerance alone leaves the balance
        // far looser (the test can fail).
        assert!(loose > 1e-2, "without control: {loose:e}");
    }

    /// `Driven` off resonance exchanges far more work back and forth than
    /// it supplies net; the control holds the balance to the scale of the
    /// net work and the dissipation, which `rolldyn run` judges it on.
    #[test]
    fn the_balance_is_held_to_the_net_work() {
        use crate::integrate::{Integrator, ROS34PW2, Rosenbrock};
        let y0 = [0.0; 4];
        for eps in [1e-3, 1e-4] {
            let mut r = Rosenbrock::builder(&ROS34PW2)
                .relative_tolerance(1e-2)
                .max_step(1e-3)
                .energy_tolerance(Some(eps))
                .build(&Driven, &y0)
                .unwrap();
            let (mut gross, mut last) = (0.0, Driven.energy_balance(0.0, &y0).unwrap());
            while r.t() < 0.02 {
                r.step(&mut Driven, 0.02).unwrap();
                let b = Driven.energy_balance(r.t(), r.y()).unwrap();
                gross += (b.work - last.work).abs();
                last = b;
            }
            let net = last.work.abs() + last.dissipated;
            assert!(gross > 5.0 * net, "gross {gross:e} against net {net:e}");
            let held = last.residual().abs() / net;
            // The allowances sum to ε of the net work; the error kept is
            // within a few times that (3.4 ε and 2.3 ε), where allowances
            // per unit of gross turnover (100× the net work here) would
            // let it reach 100 ε.
            assert!(
                held <= 5.0 * eps,
                "ε {eps}: balance {held:e} of the net work"
            );
        }
    }

    /// An estimate at the last bits of the energies is rounding and
    /// passes however small the step's allowance; one well above it does
    /// not. (At the 6304 preset's start, with neither work nor dissipation
    /// yet, ε h P₀ was below the last bit of the balls' 0.57 J, and steps
    /// whose two solutions differed there were rejected: 3886 attempts for
    /// the first 0.1 ms, 311 now.)
    #[test]
    fn rounding_in_the_energies_passes() {
        // `Driven` at rest with 0.05 J in its spring, W = D = 0, a step of
        // 1 ns: ε h P₀ = 1e-18 J; the 4 states' rounding 4.4e-17 J.
        let (t, h, y) = (0.0, 1e-9, [1e-3, 0.0, 0.0, 0.0]);
        let ulp = 1e-3f64.next_up() - 1e-3;
        let scaled = |bits: f64| {
            let mut control = EnergyControl::new(&Driven, 1e-3, 3.0, t, &y).unwrap();
            // The embedded solution `bits` last bits of x lower: E lower
            // by K x × bits × ulp (2.2e-17 J a bit).
            let at = |k: usize| if k == 0 { bits * ulp } else { 0.0 };
            let end = (&y[..], Driven.energy_balance(t + h, &y));
            control.scaled_error(&Driven, t, &y, h, end, at)
        };
        assert!(scaled(1.0) <= 1.0, "one bit: {}", scaled(1.0));
        assert!(scaled(20.0) > 1.0, "20 bits: {}", scaled(20.0));
    }

    /// A mass in a V-shaped potential E = ½ m v² + F |x| (a ball's
    /// contact over a spall's kink: the force jumps where the path
    /// kinks): m v' = −F sign x, no work, no loss. Exact: from x = −x₀,
    /// v = 1 m/s, x = −x₀ + t + ½ a t² (a = F/m) to the kink at t_c, then
    /// x = v_c (t − t_c) − ½ a (t − t_c)².
    struct Vee;
    impl Vee {
        const M: f64 = 1e-3;
        const ACCELERATION: f64 = 100.0;
        const X0: f64 = 1e-3;
        /// (x, v) at time t while the mass has crossed the kink once.
        fn exact(t: f64) -> (f64, f64) {
            let a = Self::ACCELERATION;
            // −x₀ + t + ½ a t² = 0.
            let crossing = ((1.0 + 2.0 * a * Self::X0).sqrt() - 1.0) / a;
            if t < crossing {
                return (-Self::X0 + t + 0.5 * a * t * t, 1.0 + a * t);
            }
            let (v_c, s) = (1.0 + a * crossing, t - crossing);
            (v_c * s - 0.5 * a * s * s, v_c - a * s)
        }
    }
    impl OdeSystem for Vee {
        fn dimension(&self) -> usize {
            2
        }
        fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
            dy[0] = y[1];
            dy[1] = -Self::ACCELERATION * y[0].signum();
        }
        fn error_scale(&self, scale: &mut [f64]) {
            scale.copy_from_slice(&[1e-6, 1e-3]);
        }
        fn energy_balance(&self, _t: f64, y: &[f64]) -> Option<EnergyBalance> {
            Some(EnergyBalance {
                work: 0.0,
                dissipated: 0.0,
                mechanical: 0.5 * Self::M * y[1] * y[1] + Self::M * Self::ACCELERATION * y[0].abs(),
            })
        }
    }

    /// A step across the kink leaves its two solutions Δa h apart in
    /// velocity, an energy estimate m v Δa h (0.2 h W) against an
    /// allowance of ε h P₀ (1e-13 h W at ε = 1e-7): only the rounding of
    /// E passes it, at steps below the time resolution. The step the
    /// states pass at the resolution is taken (before, the run failed
    /// with "step size … fell below"); both methods reach the exact
    /// state and keep the energy.
    #[test]
    fn a_kink_passes_at_the_time_resolution() {
        use crate::integrate::tableau::DOPRI5;
        use crate::integrate::{Builder, ExplicitRk, Integrator, ROS34PW2, Rosenbrock};
        fn check(name: &str, mut method: impl Integrator) {
            let end = 5e-3;
            while method.t() < end {
                method
                    .step(&mut Vee, end)
                    .unwrap_or_else(|e| panic!("{name}: {e}"));
            }
            let (x, v) = Vee::exact(end);
            let y = method.y();
            assert!(
                (y[0] / x - 1.0).abs() < 1e-6,
                "{name}: x {} against {x}",
                y[0]
            );
            assert!(
                (y[1] / v - 1.0).abs() < 1e-6,
                "{name}: v {} against {v}",
                y[1]
            );
            let energy = |y: &[f64]| Vee.energy_balance(0.0, y).unwrap().mechanical;
            let start = energy(&[-Vee::X0, 1.0]);
            let drift = (energy(y) / start - 1.0).abs();
            assert!(drift < 1e-9, "{name}: energy drift {drift:e}");
        }
        fn tight<T>(builder: Builder<T>) -> Builder<T> {
            builder
                .relative_tolerance(1e-6)
                .max_step(1e-4)
                .energy_tolerance(Some(1e-7))
        }
        let y0 = [-Vee::X0, 1.0];
        let stiff = tight(Rosenbrock::builder(&ROS34PW2)).build(&Vee, &y0);
        check("ROS34PW2", stiff.unwrap());
        let explicit = tight(ExplicitRk::builder(&DOPRI5)).build(&Vee, &y0);
        check("DOPRI5", explicit.unwrap());
    }

    #[test]
    fn relative_error_is_over_the_larger_of_work_and_dissipation() {
        let start = EnergyBalance {
            work: 1.0,
            dissipated: 0.5,
            mechanical: 2.0,
        };
        let end = EnergyBalance {
            work: 3.0,
            dissipated: 1.4,
            mechanical: 3.0,
        };
        // ΔW 2, ΔD 0.9, ΔE 1: error 0.1 of 2.
        assert!((end.relative_error_since(&start) - 0.05).abs() < 1e-12);
        assert_eq!(start.relative_error_since(&start), 0.0);
    }

    #[test]
    fn systems_without_a_balance_have_no_control() {
        struct Plain;
        impl OdeSystem for Plain {
            fn dimension(&self) -> usize {
                1
            }
            fn rhs(&self, _t: f64, _y: &[f64], dy: &mut [f64]) {
                dy[0] = 0.0;
            }
        }
        assert!(EnergyControl::new(&Plain, 1e-3, 3.0, 0.0, &[0.0]).is_none());
    }
}
