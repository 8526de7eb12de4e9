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
//! [`crate::integrate::OdeSystem::rhs_with_balance`] evaluates the
//! contacts once and keeps, per ball, its share of the energy and its
//! raceway contacts' penetration, rate and load; `accept_step` at the same
//! (t, y) reads them instead of evaluating the contacts again. Every
//! quantity is the same expression on the same operands as the separate
//! evaluations, so the results are the same bits.

use super::elements::Elements;
use super::energy::{BallEnergy, Energy};
use super::model::BearingModel;
use super::motion::RingMotion;
use super::race_contact::{RaceContact, Want};
use crate::contact::normal_law::ContactEpisode;
use crate::integrate::EnergyBalance;
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

/// One ball's part of an end-point evaluation.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(super) struct EndRecord {
    /// Its share of the mechanical energy.
    pub(super) energy: BallEnergy,
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

    /// The balls' records of an evaluation at exactly (t, y), once: the
    /// evaluation is forgotten either way.
    pub(super) fn take_at(&mut self, t: f64, y: &[f64]) -> Option<&[EndRecord]> {
        let hit = std::mem::replace(&mut self.valid, false) && self.t == t && self.y == y;
        hit.then_some(&self.balls[..])
    }
}

impl BearingModel {
    /// [`crate::integrate::OdeSystem::rhs_with_balance`]: one pass over the
    /// balls gives f, their energy shares and their raceway records, kept
    /// for `accept_step` at (t, y).
    pub(super) fn rhs_with_end_records(
        &mut self,
        t: f64,
        y: &[f64],
        dy: &mut [f64],
    ) -> EnergyBalance {
        let mut end = std::mem::take(&mut self.end_point);
        self.rhs_with(t, y, dy, None, None, Some(&mut end.balls));
        let mut energy = Energy::default();
        for ball in &end.balls {
            energy.add_ball(&ball.energy);
        }
        self.border_energy(t, y, &mut energy);
        end.t = t;
        end.y.clear();
        end.y.extend_from_slice(y);
        end.valid = true;
        self.end_point = end;
        let (work, dissipated) = self.work(y);
        EnergyBalance {
            work: work + self.film_work(y),
            dissipated,
            mechanical: energy.total(),
        }
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::HertzModel;
    use crate::integrate::{Integrator, OdeSystem};
    use crate::material::Material;
    use crate::testing::{self, Method};

    /// `model` integrated for `duration` from `y0` (ROS34PW2 at 1e-3):
    /// balls in and out of contact with their pockets and raceways.
    fn advanced(model: &mut BearingModel, y0: &[f64], duration: f64) -> Vec<f64> {
        let mut solver = testing::integrator(Method::Ros34pw2, model, y0, 1e-3, 1e-4);
        while solver.t() < duration {
            solver.step(model, duration).expect("step");
        }
        solver.y().to_vec()
    }

    fn bits(values: &[f64]) -> Vec<u64> {
        values.iter().map(|v| v.to_bits()).collect()
    }

    /// The shared pass against the separate evaluations at (t, y), and
    /// the acceptance from its records against one that evaluates the
    /// contacts itself: the same bits, the same episodes and peak loads.
    fn shared_pass_matches(model: &BearingModel, t: f64, y: &[f64]) {
        let (mut shared, mut apart) = (model.clone(), model.clone());
        let mut dy_shared = vec![0.0; y.len()];
        let mut dy_apart = vec![0.0; y.len()];
        let balance = shared.rhs_with_balance(t, y, &mut dy_shared);
        apart.rhs(t, y, &mut dy_apart);
        assert_eq!(bits(&dy_shared), bits(&dy_apart), "right-hand side");
        assert_eq!(balance, apart.energy_balance(t, y), "energy balance");
        let (inner, outer) = apart.elements.ring_motion(t, y);
        for (j, record) in shared.end_point.balls.iter().enumerate() {
            let evaluated =
                apart
                    .elements
                    .raceway_records(j, y, (&inner, &outer), &apart.episodes[j]);
            assert_eq!(record.raceways, evaluated, "ball {j}'s raceway records");
        }
        assert!(shared.end_point.valid);
        assert_eq!(shared.accept_step(t, y), apart.accept_step(t, y));
        assert!(!shared.end_point.valid, "the records are read once");
        assert_eq!(shared.episodes, apart.episodes);
        assert_eq!(shared.peak_loads.peek(), apart.peak_loads.peek());
    }

    #[test]
    fn shared_pass_gives_the_separate_evaluations_bits() {
        // The 6304: serial pass, traction at the contact centre, pockets.
        let steel = testing::steel_shan_2023();
        let mut model = BearingModel::new(
            &testing::bearing_6304(),
            &steel,
            &steel,
            HertzModel::HertzCircular,
            testing::dynamics_6304(100.0),
        )
        .expect("6304");
        let y0 = model.pure_rolling_state([0.0; 5]);
        let y = advanced(&mut model, &y0, 2e-3);
        shared_pass_matches(&model, 2e-3, &y);
        // The default case's 7008C: EHL traction on the grid, the balls
        // across two threads.
        let (params, equilibrium) = testing::dynamics_7008c(testing::drag_7008c());
        let steel = Material::STEEL_52100;
        let mut model = BearingModel::new(
            &testing::bearing_7008c(),
            &steel,
            &steel,
            HertzModel::Exact,
            params,
        )
        .expect("7008C");
        let y0 = model.state_from_equilibrium(&equilibrium);
        let y = advanced(&mut model, &y0, 2e-4);
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .expect("two threads");
        pool.install(|| shared_pass_matches(&model, 2e-4, &y));
    }

    #[test]
    fn records_of_another_point_are_not_used() {
        let steel = testing::steel_shan_2023();
        let mut model = BearingModel::new(
            &testing::bearing_6304(),
            &steel,
            &steel,
            HertzModel::HertzCircular,
            testing::dynamics_6304(100.0),
        )
        .expect("6304");
        let y0 = model.pure_rolling_state([0.0; 5]);
        let y = advanced(&mut model, &y0, 1e-3);
        model.take_peak_loads();
        // Every ball moved outwards by 1 µm: the outer raceway's peak load
        // is another.
        let mut moved = y.clone();
        for j in 0..model.layout().balls {
            moved[model.layout().ball(j) + 1] += 1e-6;
        }
        let (mut shared, mut apart, mut unmoved) = (model.clone(), model.clone(), model.clone());
        let mut dy = vec![0.0; y.len()];
        shared.rhs_with_balance(1e-3, &y, &mut dy);
        shared.accept_step(1e-3, &moved);
        apart.accept_step(1e-3, &moved);
        unmoved.accept_step(1e-3, &y);
        assert_eq!(shared.peak_loads.peek(), apart.peak_loads.peek());
        assert_ne!(shared.peak_loads.peek(), unmoved.peak_loads.peek());
        // Another time, the same state: evaluated anew as well.
        shared.rhs_with_balance(1e-3, &y, &mut dy);
        assert!(shared.end_point.take_at(2e-3, &y).is_none());
        assert!(shared.end_point.take_at(1e-3, &y).is_none(), "forgotten");
    }
}
