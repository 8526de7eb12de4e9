//! The preload and lift-off of a matched set (docs/systems.md, "The
//! model"): the axial offset that gives a preload force at rest, and the
//! external axial load that unloads the opposed bearing.

use super::{
    MountedBearing, Orientation, ShaftSystem, SystemConditions, SystemEquilibrium, SystemError,
};
use crate::geometry::RingKind;
use crate::operating::Loads;
use crate::quasistatic::{Equilibrium, RacewayControl, SolverOptions};

/// Each ball's contact approach at the least preload force a set takes
/// \[m\]: 5 nm. Closer to the contacts' onset the round-off of the
/// ball's coordinates (ε d_m ≈ 1e-17 m against an approach of 1e-9 m)
/// is more than the quasi-static solve's 1e-8 of the load, its solves
/// fail, and the preload search cannot close (a 7008C pair found no
/// equilibrium below 3.7 mN, ~1.3 nm).
pub const LEAST_APPROACH: f64 = 5e-9;

impl ShaftSystem {
    /// The axial force through the set at `equilibrium` \[N\]: the sum of
    /// the +x-thrust bearings' axial loads (a pair's: bearing 0's; a
    /// triple's: its tandem pair's, which its single opposed bearing
    /// carries back without external load). A matched set's preload.
    pub fn preload_of(&self, equilibrium: &SystemEquilibrium) -> f64 {
        self.bearings
            .iter()
            .zip(&equilibrium.bearings)
            .filter(|(b, _)| b.orientation == Orientation::Forward)
            .filter_map(|(_, eq)| eq.as_ref().map(MountedBearing::axial_load))
            .sum()
    }

    /// The same axial offset s on every bearing (a matched set's preload
    /// displacement).
    pub fn with_axial_offset(&self, offset: f64) -> Self {
        let mut set = self.clone();
        for b in &mut set.bearings {
            b.axial_offset = offset;
        }
        set
    }

    /// The axial offset s at which, with no external load, the set carries
    /// the axial force `preload` \[N\] ([`Self::preload_of`]) at speed
    /// `inner_speed` (regula falsi on the load's 2/3 power, to 1e-9 of the preload or
    /// 1 nN).
    pub fn offset_for_preload(
        &self,
        preload: f64,
        inner_speed: f64,
        control: RacewayControl,
        options: &SolverOptions,
    ) -> Result<f64, SystemError> {
        if preload.is_nan() || preload <= 0.0 {
            return Err(SystemError::Preload {
                reason: format!("{preload} N: a preload force must be positive"),
            });
        }
        let least = self.least_preload();
        if preload < least {
            return Err(SystemError::Preload {
                reason: format!(
                    "{preload} N is below the least preload the solver resolves for this set, {least:.3} N: each ball's contact approach would be under {} nm, where the round-off of the ball's coordinates is more than 1e-8 of its load; give at least {least:.3} N or no preload",
                    LEAST_APPROACH * 1e9
                ),
            });
        }
        let unloaded = SystemConditions {
            loads: Loads::default(),
            inner_speed,
            control,
        };
        // Axial load of bearing 0 minus the preload at offset s. Near the
        // contacts' onset (at rest the balls just touch without offset; at
        // speed the centrifugal force lifts them off the inner raceway) the
        // inner ring carries nothing and the balls' equilibrium is not
        // determined: a failed solve there counts as no load, and the last
        // failure is reported if no offset up to 1 mm carries the preload.
        let mut failure = None;
        let mut near: Option<SystemEquilibrium> = None;
        let mut carried = |s: f64| -> f64 {
            let set = self.with_axial_offset(s);
            let solved = match &near {
                Some(n) => set.solve_near(n, &unloaded, options),
                None => set.solve(&unloaded, options),
            };
            match solved {
                Ok(eq) => {
                    let load = set.preload_of(&eq);
                    near = Some(eq);
                    load
                }
                Err(e) => {
                    failure = Some(e);
                    0.0
                }
            }
        };
        // The search is on L^{2/3} − P^{2/3}: with Hertz contacts the
        // load grows as (s − s₀)^{3/2} beyond the onset s₀, so its 2/3
        // power is nearly linear in s and regula falsi converges in a few
        // steps where it crawls on L itself (1 mN: 30 solves).
        let linear = |load: f64| load.signum() * load.abs().powf(2.0 / 3.0);
        let target = linear(preload);
        // Bracket: without offset the inner rings carry nothing; doubling
        // from a micrometre.
        let (mut lo, mut f_lo) = (0.0, -target);
        let mut hi = 1e-6;
        let mut load = carried(hi);
        let mut f_hi = linear(load) - target;
        while f_hi < 0.0 {
            if hi > 1e-3 {
                return Err(failure.unwrap_or_else(|| SystemError::Preload {
                    reason: format!("{preload} N needs an axial offset beyond 1 mm"),
                }));
            }
            (lo, f_lo) = (hi, f_hi);
            hi *= 2.0;
            load = carried(hi);
            f_hi = linear(load) - target;
        }
        // To 1e-9 of the preload, but not below the shaft solve's own
        // accuracy (1e-10 of a load scale of at least 1 N): a millinewton
        // preload otherwise chases round-off.
        let close = |load: f64| (load - preload).abs() <= 1e-9 * preload.max(1.0);
        if close(load) {
            return Ok(hi);
        }
        // Regula falsi (Illinois: the end kept twice has its value halved),
        // kept inside the bracket's middle 98 %.
        let mut kept = 0i8;
        for _ in 0..100 {
            let w = (f_lo / (f_lo - f_hi)).clamp(0.01, 0.99);
            let mid = lo + w * (hi - lo);
            let load = carried(mid);
            let f = linear(load) - target;
            if close(load) || hi - lo <= 1e-15 {
                return Ok(mid);
            }
            if f < 0.0 {
                (lo, f_lo) = (mid, f);
                if kept == 1 {
                    f_hi *= 0.5;
                }
                kept = 1;
            } else {
                (hi, f_hi) = (mid, f);
                if kept == -1 {
                    f_lo *= 0.5;
                }
                kept = -1;
            }
        }
        Ok(0.5 * (lo + hi))
    }

    /// The axial load \[N\] of bearing 0 (the one whose load is the
    /// preload) when each of its balls is compressed by 5 nm (`LEAST_APPROACH`)
    /// in series at its free contact angle α₀: Z sin α₀ K δ^{3/2} with
    /// K = (K_i^{-2/3} + K_o^{-2/3})^{-3/2} (Hertz; Harris & Kotzalas,
    /// *Essential Concepts*, §7.2). Zero without a free contact angle.
    pub fn least_preload(&self) -> f64 {
        let Some(bearing) = self.bearings.first() else {
            return 0.0;
        };
        let geometry = bearing.solver.geometry();
        let angle = geometry.free_contact_angle();
        let stiffness = |ring| bearing.solver.table(ring).stiffness(angle).powf(-2.0 / 3.0);
        let series = (stiffness(RingKind::Inner) + stiffness(RingKind::Outer)).powf(-1.5);
        geometry.ball_count as f64 * angle.sin() * series * LEAST_APPROACH.powf(1.5)
    }

    /// The external axial load \[N\] (along +x) at which every bearing
    /// facing −x carries no axial load: the lift-off load of an opposed
    /// set under pure axial load. None when no bearing faces −x or none
    /// faces +x.
    pub fn lift_off_load(
        &self,
        inner_speed: f64,
        control: RacewayControl,
        options: &SolverOptions,
    ) -> Result<Option<f64>, SystemError> {
        let faces = |o| self.bearings.iter().any(|b| b.orientation == o);
        if !faces(Orientation::Forward) || !faces(Orientation::Reversed) {
            return Ok(None);
        }
        // Sum of the reversed bearings' axial loads at shaft axial
        // displacement x (the shaft otherwise held: pure axial load), each
        // bearing solved from its last loaded state.
        let mut warm: Vec<Option<Equilibrium>> = vec![None; self.bearings.len()];
        let mut opposed = |x: f64| -> Result<(f64, f64), SystemError> {
            let u = [x, 0.0, 0.0, 0.0, 0.0];
            let mut reversed = 0.0;
            let mut total = 0.0;
            for (index, b) in self.bearings.iter().enumerate() {
                if b.open_at_rest(&u, inner_speed) {
                    continue;
                }
                let eq = match b.solve(&u, inner_speed, control, options, warm[index].as_ref()) {
                    Ok(eq) => eq,
                    // Once its inner contacts open, the opposed bearing's
                    // balls have no equilibrium on the inner raceway: it
                    // carries nothing.
                    Err(_) if b.unloaded_by(&u) => continue,
                    Err(source) => return Err(SystemError::Bearing { index, source }),
                };
                total += b.shaft_load(&eq.reaction)[0];
                if b.orientation == Orientation::Reversed {
                    reversed += MountedBearing::axial_load(&eq);
                }
                warm[index] = Some(eq);
            }
            Ok((reversed, total))
        };
        let (mut lo, mut hi) = (0.0, 1e-6);
        let (r0, _) = opposed(lo)?;
        if r0 <= 0.0 {
            return Ok(Some(0.0));
        }
        while opposed(hi)?.0 > 0.0 {
            if hi > 1e-3 {
                return Err(SystemError::Preload {
                    reason: "the opposed bearing stays loaded beyond 1 mm of axial displacement"
                        .into(),
                });
            }
            lo = hi;
            hi *= 2.0;
        }
        // Near the onset the opposed bearing's load goes as (x_on − x)^{3/2}
        // (Hertz), so R^{2/3} is nearly linear in x: the onset is where the
        // line through the last two loaded points meets zero. Step 90 % of
        // the way there and repeat until the prediction settles or the
        // balls find no equilibrium (within nanometres of the onset, at
        // millinewtons, they do not converge); the lift-off load is what
        // the other bearings carry at the predicted onset (3e-7 of F(2s)
        // on the 7008C pair, the test against the thrust curve).
        let c = |r: f64| r.max(0.0).powf(2.0 / 3.0);
        let (mut b, mut c_b) = (lo, c(opposed(lo)?.0));
        let a0 = lo - 0.02 * (hi - lo);
        let (mut a, mut c_a) = (a0, c(opposed(a0)?.0));
        let mut onset = hi;
        let mut previous = f64::NAN;
        for _ in 0..60 {
            if c_a <= c_b {
                break;
            }
            onset = b + c_b * (b - a) / (c_a - c_b);
            if (onset - previous).abs() <= 1e-12 * onset.abs().max(1e-9) {
                break;
            }
            previous = onset;
            let trial = b + 0.9 * (onset - b);
            let r = opposed(trial)?.0;
            if r <= 0.0 {
                // The balls found no equilibrium this close (millinewtons):
                // the line through the last loaded points is the estimate.
                break;
            }
            (a, c_a, b, c_b) = (b, c_b, trial, c(r));
        }
        let forward: Result<f64, SystemError> = self
            .bearings
            .iter()
            .enumerate()
            .filter(|(_, b)| b.orientation == Orientation::Forward)
            .map(|(index, b)| {
                let near = warm[index].as_ref();
                b.solve(
                    &[onset, 0.0, 0.0, 0.0, 0.0],
                    inner_speed,
                    control,
                    options,
                    near,
                )
                .map(|eq| b.shaft_load(&eq.reaction)[0])
                .map_err(|source| SystemError::Bearing { index, source })
            })
            .sum();
        Ok(Some(forward?))
    }
}
