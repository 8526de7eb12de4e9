//! A step's candidate end point evaluated once: the right-hand side, the
//! energy balance and what the step's acceptance records of the raceway
//! contacts, from one pass over the balls.
//!
//! The integrators' energy control needs the mechanical energy at the
//! candidate y₁, an accepted step needs f(y₁) for its next step, and the
//! acceptance records each raceway contact's episode, peak load and the
//! outer raceway's force on the sensor (`BearingModel::accept_step`). All
//! three start from the same contact geometry, which on a dry bearing is
//! most of a right-hand side's cost (docs/performance.md). The pass of
//! [`crate::integrate::OdeSystem::rhs_at_end`] evaluates the
//! contacts once and keeps, per ball, its share of the energy and its
//! raceway contacts' penetration, rate and load; `accept_step` at the same
//! (t, y) reads them instead of evaluating the contacts again. Every
//! quantity is the same expression on the same operands as the separate
//! evaluations, so the results are the same bits. This file holds the
//! records; the pass is `BearingModel::rhs_with_end_records`
//! (`dynamics::energy`), the acceptance `BearingModel::accept_step`.

use super::elements::Elements;
use super::motion::RingMotion;
use super::race_contact::{RaceContact, Want};
use crate::contact::normal_law::ContactEpisode;
use nalgebra::Vector3;

/// What the acceptance needs of one raceway contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct RacewayRecord {
    /// Penetration δ \[m\] (the elastic approach with the film in it).
    pub(super) penetration: f64,
    /// Its rate δ̇ \[m/s\].
    pub(super) penetration_rate: f64,
    /// Contact angle α \[rad\].
    pub(super) contact_angle: f64,
    /// Normal load Q \[N\].
    pub(super) load: f64,
    /// Force on the ring of the normal load and the surfaces' effect \[N\]
    /// (no traction: what the sensor chain reads of the outer raceway).
    pub(super) ring_force: Vector3<f64>,
}

impl RacewayRecord {
    /// The record of an evaluated contact.
    pub(super) fn of(contact: &RaceContact) -> Self {
        Self {
            penetration: contact.geometry.penetration,
            penetration_rate: contact.penetration_rate,
            contact_angle: contact.geometry.contact_angle,
            load: contact.load,
            ring_force: contact.surface.ring_force + contact.load * contact.geometry.normal,
        }
    }
}

/// One ball's share of the mechanical energy \[J\] (`dynamics::energy`).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(super) struct BallEnergy {
    /// ½ m v² + ½ I ω².
    pub(super) kinetic: f64,
    /// m g z.
    pub(super) potential: f64,
    /// Its inner raceway, outer raceway and pocket contacts.
    pub(super) elastic: [f64; 3],
}

/// One ball's part of an end-point evaluation.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(super) struct EndRecord {
    /// Its share of the mechanical energy: computed by the pass where
    /// [`EndPoint::fill`] asked for it (Some), else left out (None).
    pub(super) energy: Option<BallEnergy>,
    /// Its inner and outer raceway contacts (None: open).
    pub(super) raceways: [Option<RacewayRecord>; 2],
}

/// The last end point evaluated, until an acceptance at it reads it.
#[derive(Debug, Clone, Default)]
pub(super) struct EndPoint {
    /// Whether `t`, `y` and `balls` hold an unread evaluation.
    valid: bool,
    t: f64,
    y: Vec<f64>,
    /// Per ball.
    balls: Vec<EndRecord>,
}

impl EndPoint {
    /// Room for `balls` balls and `states` states.
    pub(super) fn new(balls: usize, states: usize) -> Self {
        Self {
            valid: false,
            t: 0.0,
            y: Vec::with_capacity(states),
            balls: vec![EndRecord::default(); balls],
        }
    }

    /// The balls' slots for an evaluation at (t, y), which they then hold;
    /// with `energy` the pass computes each ball's energy share.
    pub(super) fn fill(&mut self, t: f64, y: &[f64], energy: bool) -> &mut [EndRecord] {
        self.t = t;
        self.y.clear();
        self.y.extend_from_slice(y);
        self.valid = true;
        let share = energy.then(BallEnergy::default);
        for ball in &mut self.balls {
            ball.energy = share;
        }
        &mut self.balls
    }

    /// The balls' records of an evaluation at exactly (t, y), once: the
    /// evaluation is forgotten either way.
    pub(super) fn take_at(&mut self, t: f64, y: &[f64]) -> Option<&[EndRecord]> {
        let hit = std::mem::replace(&mut self.valid, false) && self.t == t && self.y == y;
        hit.then_some(&self.balls[..])
    }

    /// The records held, if not yet read.
    #[cfg(test)]
    pub(super) fn held(&self) -> Option<&[EndRecord]> {
        self.valid.then_some(&self.balls[..])
    }
}

impl Elements {
    /// Ball j's raceway records at y (inner, outer; None where open), its
    /// contacts evaluated for their normal forces alone with the
    /// `episodes` in force.
    pub(super) fn raceway_records(
        &self,
        j: usize,
        y: &[f64],
        (inner, outer): (&RingMotion, &RingMotion),
        episodes: &[ContactEpisode; 2],
    ) -> [Option<RacewayRecord>; 2] {
        let (ball, _) = self.ball_kinematics(j, y);
        let record = |ring, table, episode| {
            self.race_contact(ring, table, episode, &ball, Want::Penetration)
                .map(|contact| RacewayRecord::of(&contact))
        };
        [
            record(inner, &self.inner_table, &episodes[0]),
            record(outer, &self.outer_table, &episodes[1]),
        ]
    }
}
