//! Bearings on a shaft as one system of ordinary differential equations
//! for the integrators: the right-hand side (with the energy balance and
//! each bearing's acceptance records at a step's end), the error scales,
//! the states' names, the step limits and the energy balance (module doc
//! of `dynamics::shaft`).

use super::{SHAFT_LEN, SHAFT_STATES, ShaftDynamics, gather};
use crate::integrate::{BlockSplit, EnergyBalance, OdeSystem};

impl OdeSystem for ShaftDynamics {
    fn dimension(&self) -> usize {
        self.dimension
    }

    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        let (mut shaft_load, mut axial_moment) = ([0.0; 5], 0.0);
        let mut work = self.take();
        for b in &self.bearings {
            let l = b.model.layout();
            let (n, len) = (l.balls * self.ball_len, l.len());
            self.bearing_state_into(b, y, &mut work.y[..len]);
            b.model.rhs(t, &work.y[..len], &mut work.dy[..len]);
            dy[b.first_ball..b.first_ball + n].copy_from_slice(&work.dy[..n]);
            axial_moment += self.collect_border(b, &work.dy[..len], dy, &mut shaft_load);
        }
        self.give(work);
        let sh = self.first_shaft;
        self.shaft_rhs(t, &y[sh..], &shaft_load, axial_moment, &mut dy[sh..]);
    }

    /// Each bearing's `rhs_at_end` (one pass over its balls, its raceway
    /// records kept for its `accept_step` at the same point), assembled as
    /// [`Self::rhs`] and [`Self::energy_balance`] assemble theirs: the
    /// same operations in the same order, so the same bits.
    fn rhs_at_end(
        &mut self,
        t: f64,
        y: &[f64],
        dy: &mut [f64],
        balance: bool,
    ) -> Option<EnergyBalance> {
        let (mut shaft_load, mut axial_moment) = ([0.0; 5], 0.0);
        let (mut done, mut dissipated, mut mechanical) = (0.0, 0.0, 0.0);
        let mut work = self.take();
        let (ball_len, sh) = (self.ball_len, self.first_shaft);
        for i in 0..self.bearings.len() {
            let b = &mut self.bearings[i];
            let l = b.model.layout();
            let (n, len) = (l.balls * ball_len, l.len());
            gather(b, ball_len, sh, y, &mut work.y[..len]);
            let end = b
                .model
                .rhs_at_end(t, &work.y[..len], &mut work.dy[..len], balance);
            let b = &self.bearings[i];
            dy[b.first_ball..b.first_ball + n].copy_from_slice(&work.dy[..n]);
            axial_moment += self.collect_border(b, &work.dy[..len], dy, &mut shaft_load);
            if let Some(end) = end {
                // A shaft's bearings have no film work (checked at set-up).
                done += end.work;
                dissipated += end.dissipated;
                mechanical += self.without_shaft_parts(i, &work.y[..len], end.mechanical);
            }
        }
        self.give(work);
        self.shaft_rhs(t, &y[sh..], &shaft_load, axial_moment, &mut dy[sh..]);
        balance.then(|| EnergyBalance {
            work: done + y[sh + SHAFT_STATES],
            dissipated,
            mechanical: mechanical + self.shaft_energy(&y[sh..]),
        })
    }

    fn blocks(&self) -> Option<&dyn BlockSplit> {
        Some(self)
    }

    fn error_scale(&self, scale: &mut [f64]) {
        let mut own = Vec::new();
        for b in &self.bearings {
            own.resize(b.model.layout().len(), 0.0);
            b.model.error_scale(&mut own);
            for (local, v) in own.iter().enumerate() {
                if let Some(k) = self.system_index(b, local) {
                    scale[k] = *v;
                }
            }
            // The shaft's scales are the inner ring's (with its rotation).
            let l = b.model.layout();
            let (r, sh) = (l.ring(), self.first_shaft);
            scale[sh..sh + SHAFT_STATES].copy_from_slice(&own[r..r + 10]);
            // As a bearing's energy accumulators.
            scale[sh + SHAFT_STATES] = own[l.work()];
            if l.driven {
                scale[sh + SHAFT_LEN..sh + SHAFT_LEN + 2]
                    .copy_from_slice(&own[l.spin()..l.outer()]);
            }
        }
    }

    fn absolute_error(&self, absolute: &mut [bool]) {
        let mut own = Vec::new();
        for b in &self.bearings {
            own.clear();
            own.resize(b.model.layout().len(), false);
            b.model.absolute_error(&mut own);
            for (local, v) in own.iter().enumerate() {
                if let Some(k) = self.system_index(b, local) {
                    absolute[k] = *v;
                }
            }
        }
        if self.drive.is_some() {
            absolute[self.first_shaft + SHAFT_LEN] = true;
        }
    }

    fn state_name(&self, index: usize) -> String {
        if index >= self.first_shaft {
            const SHAFT: [&str; SHAFT_LEN + 2] = [
                "axial position x",
                "position y",
                "position z",
                "tilt θ_y",
                "tilt θ_z",
                "axial velocity ẋ",
                "velocity ẏ",
                "velocity ż",
                "tilt rate θ̇_y",
                "tilt rate θ̇_z",
                "work of the drive, unbalance and harmonic loads",
                "rotation angle",
                "speed",
            ];
            return format!("shaft {}", SHAFT[index - self.first_shaft]);
        }
        for (i, b) in self.bearings.iter().enumerate() {
            let l = b.model.layout();
            let local = if (b.first_ball..b.first_ball + l.balls * self.ball_len).contains(&index) {
                Some(index - b.first_ball)
            } else if (b.first_border..b.first_border + l.len() - l.outer()).contains(&index) {
                Some(index - b.first_border + l.outer())
            } else {
                None
            };
            if let Some(local) = local {
                return format!("bearing {i}: {}", b.model.state_name(local));
            }
        }
        format!("y[{index}]")
    }

    fn step_limit(&self, t: f64, y: &[f64]) -> f64 {
        let mut work = self.take();
        let limit = self
            .bearings
            .iter()
            .map(|b| {
                let len = b.model.layout().len();
                self.bearing_state_into(b, y, &mut work.y[..len]);
                b.model.step_limit(t, &work.y[..len])
            })
            .fold(f64::INFINITY, f64::min);
        self.give(work);
        limit
    }

    fn accept_step(&mut self, t: f64, y: &[f64]) -> bool {
        let mut work = self.take();
        let mut changed = false;
        let ball_len = self.ball_len;
        let shaft = self.first_shaft;
        for b in &mut self.bearings {
            let len = b.model.layout().len();
            gather(b, ball_len, shaft, y, &mut work.y[..len]);
            changed |= b.model.accept_step(t, &work.y[..len]);
        }
        self.give(work);
        changed
    }

    fn energy_balance(&self, t: f64, y: &[f64]) -> Option<EnergyBalance> {
        let mut work = self.take();
        let s = self.first_shaft;
        let (mut done, mut dissipated, mut mechanical) = (0.0, 0.0, 0.0);
        for (i, b) in self.bearings.iter().enumerate() {
            let len = b.model.layout().len();
            self.bearing_state_into(b, y, &mut work.y[..len]);
            let own = &work.y[..len];
            let (w, d) = b.model.work(own);
            done += w;
            dissipated += d;
            mechanical += self.bearing_energy(i, t, own);
        }
        self.give(work);
        done += y[s + SHAFT_STATES];
        mechanical += self.shaft_energy(&y[s..]);
        Some(EnergyBalance {
            work: done,
            dissipated,
            mechanical,
        })
    }
}
