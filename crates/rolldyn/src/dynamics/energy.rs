//! Energy bookkeeping of the dynamic model (docs/model.md §10).
//!
//! [`BearingModel::energy`] gives kinetic energy (balls, ring translation
//! and tilt, cage, a torque-driven rotor's ½ J ω²), elastic energy (Σ (2/5) K_c δ^{5/2} + ½ k δ_p²; with the
//! film in the approach each contact stores (2/5) K_c δ_el^{5/2} − Q h +
//! ∫₀^Q h dq, `dynamics::film`) and the potential of constant applied loads
//! and gravity; `BearingModel::rhs_with_end_records` gives the same sum
//! from the right-hand side's own pass over the balls at a step's end
//! (`dynamics::end_point`). With no dissipation and
//! a fixed contact angle (planar mode) their sum is conserved (VALIDATION
//! B1). Where α varies, K_c(α) δ^{3/2} is not the exact gradient of
//! (2/5) K_c δ^{5/2}; the K_c tables vary by ~1e-3 per degree.

use super::end_point::BallEnergy;
use super::model::BearingModel;
use super::motion::{BallMotion, RingMotion};
use crate::contact::ContactTable;
use crate::integrate::EnergyBalance;
use nalgebra::Vector3;

/// Energy of a state \[J\].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Energy {
    /// Kinetic energy (balls, ring translation and tilt, cage; a driven
    /// rotor's rotation).
    pub kinetic: f64,
    /// Elastic energy of the contacts.
    pub elastic: f64,
    /// Potential of constant applied loads and gravity.
    pub potential: f64,
}

impl Energy {
    /// Sum.
    pub fn total(&self) -> f64 {
        self.kinetic + self.elastic + self.potential
    }

    /// Adds a ball's share, term by term in a fixed order (the same sum
    /// however the share was evaluated).
    pub(super) fn add_ball(&mut self, ball: &BallEnergy) {
        self.kinetic += ball.kinetic;
        self.potential += ball.potential;
        for elastic in ball.elastic {
            self.elastic += elastic;
        }
    }
}

impl BearingModel {
    /// Work of the drive and the external forces (time-varying loads, cage
    /// unbalance), and the dissipated energy, accumulated in state `y` \[J\].
    pub fn work(&self, y: &[f64]) -> (f64, f64) {
        let w = self.elements.layout.work();
        (y[w], y[w + 1])
    }

    /// Work the films have done on the contacts, accumulated in state `y`
    /// \[J\] (0 without the film in the approach).
    pub fn film_work(&self, y: &[f64]) -> f64 {
        let l = self.elements.layout;
        if l.film_work { y[l.work() + 2] } else { 0.0 }
    }

    /// Mechanical energy of state `y` at time `t` (docs/model.md §10); its change
    /// equals the drive work minus the dissipated energy.
    pub fn energy(&self, t: f64, y: &[f64]) -> Energy {
        let (inner, outer) = self.elements.ring_motion(t, y);
        let mut e = Energy::default();
        for j in 0..self.elements.layout.balls {
            let (ball, _) = self.elements.ball_kinematics(j, y);
            let raceways = [
                self.raceway_energy(&inner, &self.elements.inner_table, &ball, None),
                self.raceway_energy(&outer, &self.elements.outer_table, &ball, None),
            ];
            e.add_ball(&self.ball_energy(j, y, &ball, raceways));
        }
        self.border_energy(t, y, &mut e);
        e
    }

    /// Ball j's share of the mechanical energy, its raceway contacts'
    /// elastic energies given.
    pub(super) fn ball_energy(
        &self,
        j: usize,
        y: &[f64],
        ball: &BallMotion,
        raceways: [f64; 2],
    ) -> BallEnergy {
        let (q, v, w) = (ball.centre, ball.velocity, ball.omega);
        let el = &self.elements;
        BallEnergy {
            kinetic: 0.5 * el.ball_mass * v.norm_squared()
                + 0.5 * el.ball_inertia * w.norm_squared(),
            potential: el.ball_mass * el.params.gravity * q.z,
            elastic: [raceways[0], raceways[1], el.pocket_energy(j, y, ball)],
        }
    }

    /// Elastic energy of a ball's contact with `ring` \[J\]: with the film
    /// in the approach its film's (`dynamics::film`), else (2/5) K_c(α)
    /// δ^{5/2} of its penetration δ and contact angle α, `known` where the
    /// caller has them (`Some(None)`: open), else from the geometry.
    pub(super) fn raceway_energy(
        &self,
        ring: &RingMotion,
        table: &ContactTable,
        ball: &BallMotion,
        known: Option<Option<(f64, f64)>>,
    ) -> f64 {
        if self.elements.layout.film_work {
            return self.elements.film_contact_energy(ring, table, ball);
        }
        let geometry = known.unwrap_or_else(|| {
            self.elements
                .race_geometry(ring, ball)
                .map(|(c, _)| (c.penetration, c.contact_angle))
        });
        geometry.map_or(0.0, |(delta, angle)| {
            0.4 * table.stiffness(angle) * delta * delta * delta.sqrt()
        })
    }

    /// Adds the rings', cage's, drive's and supports' energies and the
    /// applied loads' potential to `e`, which holds the balls'.
    pub(super) fn border_energy(&self, t: f64, y: &[f64], e: &mut Energy) {
        let l = self.elements.layout;
        let g = self.elements.params.gravity;
        let r = l.ring();
        let p = &self.elements.params;
        e.kinetic +=
            0.5 * p.inner_ring_mass * (y[r + 5].powi(2) + y[r + 6].powi(2) + y[r + 7].powi(2))
                + 0.5 * p.inner_ring_tilt_inertia * (y[r + 8].powi(2) + y[r + 9].powi(2));
        let loads = p.loads.at(t);
        e.potential -= loads.force[0] * y[r]
            + loads.force[1] * y[r + 1]
            + loads.force[2] * y[r + 2]
            + loads.moment[0] * y[r + 3]
            + loads.moment[1] * y[r + 4];
        e.potential += p.inner_ring_mass * g * y[r + 2];
        e.elastic += p
            .inner_support
            .energy(&Vector3::new(y[r], y[r + 1], y[r + 2]));
        if let Some(outer) = &p.outer_ring {
            let o = l.outer();
            e.kinetic += 0.5 * outer.mass * (y[o + 2].powi(2) + y[o + 3].powi(2));
            e.elastic += outer.housing.energy(&Vector3::new(0.0, y[o], y[o + 1]));
            e.potential += outer.mass * g * y[o + 1];
        }
        let c = l.cage();
        e.kinetic += 0.5 * p.cage.mass * (y[c + 3].powi(2) + y[c + 4].powi(2))
            + 0.5 * p.cage.inertia * y[c + 5].powi(2);
        e.potential += p.cage.mass * g * y[c + 1];
        if let Some(ring) = &p.sliding_outer_ring {
            e.kinetic += 0.5 * ring.mass * y[l.slide() + 1].powi(2);
        }
        if let Some(drive) = &p.drive {
            e.kinetic += 0.5 * drive.inertia * y[l.spin() + 1].powi(2);
        }
        if let Some(guide) = &p.cage.guide {
            // The stop beyond ε_max is a spring.
            let (centre, _, _) = self.elements.guide_ring(guide, t, y);
            let offset = (Vector3::new(0.0, y[c], y[c + 1]) - centre).norm();
            let stop = (offset - guide.max_eccentricity * guide.radial_clearance).max(0.0);
            e.elastic += 0.5 * guide.stop_stiffness * stop * stop;
        }
    }
}

impl BearingModel {
    /// [`crate::integrate::OdeSystem::rhs_at_end`]: one pass over the balls
    /// gives f, their energy shares and their raceway records, kept for
    /// `accept_step` at (t, y) (`dynamics::end_point`); with `balance`, the
    /// energy balance from the shares.
    pub(super) fn rhs_with_end_records(
        &mut self,
        t: f64,
        y: &[f64],
        dy: &mut [f64],
        balance: bool,
    ) -> Option<EnergyBalance> {
        let mut end = std::mem::take(&mut self.end_point);
        let balls = end.fill(t, y, balance);
        self.rhs_with(t, y, dy, None, None, Some(&mut *balls));
        let balance = balance.then(|| {
            let mut energy = Energy::default();
            for share in balls.iter().filter_map(|ball| ball.energy.as_ref()) {
                energy.add_ball(share);
            }
            self.border_energy(t, y, &mut energy);
            let (work, dissipated) = self.work(y);
            EnergyBalance {
                work: work + self.film_work(y),
                dissipated,
                mechanical: energy.total(),
            }
        });
        self.end_point = end;
        balance
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrate::{Integrator, OdeSystem};
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

    /// The 6304 preset's model (Shan et al. 2023) and its state `duration`
    /// after a pure-rolling start.
    fn the_6304_after(duration: f64) -> (BearingModel, Vec<f64>) {
        let (mut model, y0) = testing::model_6304();
        let y = advanced(&mut model, &y0, duration);
        (model, y)
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
        let balance = shared.rhs_at_end(t, y, &mut dy_shared, true);
        apart.rhs(t, y, &mut dy_apart);
        assert_eq!(bits(&dy_shared), bits(&dy_apart), "right-hand side");
        assert_eq!(balance, apart.energy_balance(t, y), "energy balance");
        let (inner, outer) = apart.elements.ring_motion(t, y);
        for (j, record) in shared.end_point.held().expect("held").iter().enumerate() {
            let evaluated =
                apart
                    .elements
                    .raceway_records(j, y, (&inner, &outer), &apart.episodes[j]);
            assert_eq!(record.raceways, evaluated, "ball {j}'s raceway records");
        }
        assert!(shared.end_point.held().is_some());
        assert_eq!(shared.accept_step(t, y), apart.accept_step(t, y));
        assert!(
            shared.end_point.held().is_none(),
            "the records are read once"
        );
        assert_eq!(shared.episodes, apart.episodes);
        assert_eq!(shared.peak_loads.peek(), apart.peak_loads.peek());
    }

    #[test]
    fn shared_pass_gives_the_separate_evaluations_bits() {
        // The 6304: serial pass, traction at the contact centre, pockets.
        let (model, y) = the_6304_after(2e-3);
        shared_pass_matches(&model, 2e-3, &y);
        // The default case's 7008C: EHL traction on the grid, the balls
        // across two threads.
        let (mut model, y0) = testing::model_7008c();
        let y = advanced(&mut model, &y0, 2e-4);
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .expect("two threads");
        pool.install(|| shared_pass_matches(&model, 2e-4, &y));
    }

    #[test]
    fn records_of_another_point_are_not_used() {
        let (model, y) = the_6304_after(1e-3);
        model.take_peak_loads();
        // Every ball moved outwards by 1 µm: the outer raceway's peak load
        // is another.
        let mut moved = y.clone();
        for j in 0..model.layout().balls {
            moved[model.layout().ball(j) + 1] += 1e-6;
        }
        let (mut shared, mut apart, mut unmoved) = (model.clone(), model.clone(), model.clone());
        let mut dy = vec![0.0; y.len()];
        shared.rhs_at_end(1e-3, &y, &mut dy, false);
        shared.accept_step(1e-3, &moved);
        apart.accept_step(1e-3, &moved);
        unmoved.accept_step(1e-3, &y);
        assert_eq!(shared.peak_loads.peek(), apart.peak_loads.peek());
        assert_ne!(shared.peak_loads.peek(), unmoved.peak_loads.peek());
        // Another time, the same state: evaluated anew as well.
        shared.rhs_at_end(1e-3, &y, &mut dy, false);
        assert!(shared.end_point.take_at(2e-3, &y).is_none());
        assert!(shared.end_point.take_at(1e-3, &y).is_none(), "forgotten");
    }
}
