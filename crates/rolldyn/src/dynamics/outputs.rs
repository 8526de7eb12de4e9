//! Output quantities of a dynamic state: per-contact samples, FASTSIM
//! stick/slip maps, the pure-rolling cage-speed reference and ball
//! attitude (docs/model.md §9).

use super::model::BearingModel;
use super::race_contact::{ContactOutput, ContactSample, Want};
use crate::geometry::RingKind;
use crate::kinematics::cage_speed_ratio;
use crate::traction::fastsim::MapCell;
use rayon::prelude::*;

impl BearingModel {
    /// Contact loads and angles of every ball at state `y`, written into
    /// `out` (one entry per ball). The balls are evaluated on the threads
    /// of the current rayon pool when the right-hand side's ball pass is
    /// (each entry is one ball's alone: the same whatever the threads).
    pub fn contact_samples(&self, t: f64, y: &[f64], out: &mut [ContactSample]) {
        let (inner, outer) = self.elements.ring_motion(t, y);
        let sample = |j: usize| {
            let (ball, _) = self.elements.ball_kinematics(j, y);
            let episodes = &self.episodes[j];
            let mut sample = ContactSample::default();
            if let Some(c) = self.elements.race_contact(
                &inner,
                &self.elements.inner_table,
                &episodes[0],
                &ball,
                Want::Output,
            ) {
                sample.inner = c.output;
            }
            if let Some(c) = self.elements.race_contact(
                &outer,
                &self.elements.outer_table,
                &episodes[1],
                &ball,
                Want::Output,
            ) {
                sample.outer = c.output;
            }
            sample
        };
        let balls = self.elements.layout.balls.min(out.len());
        let out = &mut out[..balls];
        if self.ball_pass.is_parallel() {
            out.par_iter_mut()
                .enumerate()
                .for_each(|(j, entry)| *entry = sample(j));
        } else {
            for (j, entry) in out.iter_mut().enumerate() {
                *entry = sample(j);
            }
        }
    }

    /// The largest inner and outer contact loads \[N\] over all balls at
    /// the accepted steps since the last call (0 when none was loaded):
    /// the impacts' peaks that samples miss ([`super::peaks`]).
    pub fn take_peak_loads(&self) -> [f64; 2] {
        self.peak_loads.take()
    }

    /// The ball–pocket normal forces at state `y`: their sum over the
    /// balls and the largest \[N\] (the cage's impact history, docs/model.md §5).
    pub fn pocket_forces(&self, y: &[f64]) -> (f64, f64) {
        (0..self.elements.layout.balls)
            .filter_map(|j| {
                let (ball, _) = self.elements.ball_kinematics(j, y);
                self.elements.pocket_contact(j, y, &ball)
            })
            .fold((0.0, 0.0), |(sum, largest), c| {
                (sum + c.normal_force, f64::max(largest, c.normal_force))
            })
    }

    /// The FASTSIM stick/slip map of ball j's contact with `ring` at state
    /// `y`: `map` receives every element (Zhang et al. 2025 Fig. 11); returns the
    /// contact's output, or None when the contact is open. Other traction
    /// models call `map` never.
    pub fn traction_map(
        &self,
        t: f64,
        y: &[f64],
        j: usize,
        ring: RingKind,
        mut map: impl FnMut(&MapCell),
    ) -> Option<ContactOutput> {
        let (inner, outer) = self.elements.ring_motion(t, y);
        let (ball, _) = self.elements.ball_kinematics(j, y);
        let (motion, table, k) = match ring {
            RingKind::Inner => (&inner, &self.elements.inner_table, 0),
            RingKind::Outer => (&outer, &self.elements.outer_table, 1),
        };
        self.elements
            .race_contact(
                motion,
                table,
                &self.episodes[j][k],
                &ball,
                Want::Map(&mut map),
            )
            .map(|c| c.output)
    }

    /// Pure-rolling cage-speed ratio ω_c/ω_i of docs/model.md §7 for the current
    /// state: the mean contact angles of the loaded contacts and the mean
    /// ball attitude angle β (spin axis relative to the cage, as in Harris)
    /// in the formula with different inner and outer angles. The reference
    /// of the cage speed ratio (CSR) of Zhang et al. 2025 §4.2.
    pub fn pure_rolling_ratio(&self, samples: &[ContactSample], y: &[f64]) -> f64 {
        let l = self.elements.layout;
        let (mut ai, mut ao, mut beta, mut n) = (0.0, 0.0, 0.0, 0.0);
        for (j, s) in samples.iter().enumerate().take(l.balls) {
            if s.inner.load > 0.0 && s.outer.load > 0.0 {
                ai += s.inner.angle;
                ao += s.outer.angle;
                beta += self.ball_attitude(j, y).0;
                n += 1.0;
            }
        }
        let g = &self.elements.geometry;
        let gamma = g.ball_diameter / g.pitch_diameter;
        if n == 0.0 {
            let a = g.nominal_contact_angle();
            return cage_speed_ratio(gamma, a, a, a);
        }
        cage_speed_ratio(gamma, ai / n, ao / n, beta / n)
    }

    /// Attitude β and yaw β' of ball j \[rad\] (Zhang et al. 2025 §4.1; Harris): the
    /// direction of its spin relative to the cage frame, ω' = ω_b − φ̇ e_x,
    /// with ω'_x = −ω' cos β cos β', ω'_t = ω' cos β sin β', ω'_r = ω' sin β.
    /// A ball rolling on the contact line at angle α has β = α, β' = 0.
    pub fn ball_attitude(&self, j: usize, y: &[f64]) -> (f64, f64) {
        let b = self.elements.layout.ball(j);
        let axial = -(y[b + 6] - y[b + 5]);
        let (radial, tangential) = (y[b + 7], y[b + 8]);
        (
            radial.atan2(axial.hypot(tangential)),
            tangential.atan2(axial),
        )
    }
}
