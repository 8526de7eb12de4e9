//! A ball's equations of motion (docs/model.md §1, equations in [`super::model`])
//! from its contacts' shares, and the reuse of those shares by the
//! Jacobian's border columns.
//!
//! Each contact (inner raceway, outer raceway, pocket) contributes a
//! [`ContactShare`]: its force and moment on the ball and what it passes
//! to the border (ring or cage force and moment, dissipated power). The
//! ball's right-hand side sums the shares in a fixed order, then adds drag
//! and the frame's terms.
//!
//! A border state touches only some of a ball's contacts: the inner
//! ring's states the inner raceway contact, the outer ring's the outer
//! one, the cage's the pocket. When the finite-difference Jacobian
//! perturbs a border state, the other contacts see exactly the inputs of
//! the unperturbed evaluation, so their shares are taken from it (the
//! memo) instead of being evaluated again; the sums run in the same
//! order over the same values, so the column is the same bit for bit. For
//! the 7218B with FASTSIM this saves a third of the Jacobian's traction
//! evaluations (docs/performance.md).

use super::ball_pass::Extras;
use super::coupling::BallCoupling;
use super::end_point::{EndRecord, RacewayRecord};
use super::film::FilmWork;
use super::layout::StateLayout;
use super::model::BearingModel;
use super::motion::{BallMotion, RingMotion};
use super::race_contact::{ContactOutput, Want};
use crate::power::Dissipation;
use nalgebra::Vector3;

/// The contacts of a ball, in the order their shares are summed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum BallContact {
    Inner = 0,
    Outer = 1,
    Pocket = 2,
}

/// The closed contacts' shares (inner, outer, pocket, in that order)
/// added to the ball's `force` and `moment`; their reactions on the inner
/// ring, the outer ring and the cage, and their dissipation.
#[inline(always)]
fn add_shares(
    shares: &[ContactShare; 3],
    force: &mut Vector3<f64>,
    moment: &mut Vector3<f64>,
) -> BallCoupling {
    let mut out = BallCoupling::default();
    for (contact, share) in BallContact::ALL.iter().zip(shares) {
        if !share.closed {
            continue;
        }
        *force += share.force;
        *moment += share.moment;
        match contact {
            BallContact::Inner => {
                out.ring_force += share.body_force;
                out.ring_moment += share.body_moment;
            }
            BallContact::Outer => out.outer_force += share.body_force,
            BallContact::Pocket => {
                out.cage_force += share.body_force;
                out.cage_torque += share.body_moment.x;
            }
        }
        out.dissipation += share.dissipation;
    }
    out
}

impl BallContact {
    const ALL: [Self; 3] = [Self::Inner, Self::Outer, Self::Pocket];

    /// The contact a border state (index from the inner ring's first
    /// state) touches, if any: the accumulators touch none.
    pub(super) fn touched_by(layout: &StateLayout, border_state: usize) -> Option<Self> {
        let state = layout.ring() + border_state;
        if state < layout.outer() {
            Some(Self::Inner)
        } else if state < layout.cage() {
            Some(Self::Outer)
        } else if state < layout.work() {
            Some(Self::Pocket)
        } else {
            None
        }
    }
}

/// One contact's share of a ball's equations and of the border coupling.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(super) struct ContactShare {
    /// Whether the contact is closed (an open one adds nothing).
    closed: bool,
    /// Force and moment on the ball (about its centre).
    force: Vector3<f64>,
    moment: Vector3<f64>,
    /// Force and moment on the body at the contact's other side (the
    /// moment: the inner ring's about its centre; the cage's torque in x).
    body_force: Vector3<f64>,
    body_moment: Vector3<f64>,
    dissipation: f64,
}

impl ContactShare {
    /// f64s of a share in the memo.
    const LEN: usize = 14;
    /// f64s of a ball's memo: the three shares.
    pub(super) const MEMO_LEN: usize = 3 * Self::LEN;

    fn write(&self, out: &mut [f64]) {
        out[0] = if self.closed { 1.0 } else { 0.0 };
        out[1..4].copy_from_slice(self.force.as_slice());
        out[4..7].copy_from_slice(self.moment.as_slice());
        out[7..10].copy_from_slice(self.body_force.as_slice());
        out[10..13].copy_from_slice(self.body_moment.as_slice());
        out[13] = self.dissipation;
    }

    fn read(c: &[f64]) -> Self {
        Self {
            closed: c[0] != 0.0,
            force: Vector3::from_column_slice(&c[1..4]),
            moment: Vector3::from_column_slice(&c[4..7]),
            body_force: Vector3::from_column_slice(&c[7..10]),
            body_moment: Vector3::from_column_slice(&c[10..13]),
            dissipation: c[13],
        }
    }
}

/// Which of a ball's contacts a block evaluation includes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Part {
    /// All of them: the right-hand side.
    Whole,
    /// The pocket's terms alone: the split's fast part, whose Jacobian
    /// the implicit method refreshes at every step
    /// (`BlockSplit::with_fast_part`).
    Fast,
}

/// Where a ball's contact shares come from.
pub(super) enum Shares<'a> {
    /// All evaluated (and, with a memo, stored there).
    Evaluate(Option<&'a mut [f64]>),
    /// Only `contact` evaluated, the others read from the memo of the
    /// unperturbed point.
    Reuse {
        memo: &'a [f64],
        contact: Option<BallContact>,
    },
}

impl BearingModel {
    /// Ball j's state derivatives into `dy` and its coupling to the border,
    /// with the films' work (dynamics::film); `outputs`: the contacts'
    /// losses by mechanism, the raceway contacts' output quantities and
    /// the ball's end-point record (`dynamics::end_point`), where given.
    pub(super) fn ball_rhs(
        &self,
        t: f64,
        j: usize,
        y: &[f64],
        rings: (&RingMotion, &RingMotion),
        dy: &mut [f64],
        outputs: (Option<&mut Dissipation>, Extras<'_>),
    ) -> BallCoupling {
        self.ball_rhs_with(t, j, y, rings, dy, true, outputs, Shares::Evaluate(None))
    }

    /// A ball's block of the block split (`BlockSplit::block_rhs` and its
    /// memo variants): no films' work, no losses, the shares from `shares`,
    /// the contacts of `part` (the fast part needs no ring motion).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn block_rhs_from(
        &self,
        t: f64,
        y: &[f64],
        block: usize,
        dy_block: &mut [f64],
        coupling: &mut [f64],
        shares: Shares<'_>,
        part: Part,
    ) {
        let out = match part {
            Part::Whole => {
                let (inner, outer) = self.elements.ring_motion(t, y);
                self.ball_rhs_with(
                    t,
                    block,
                    y,
                    (&inner, &outer),
                    dy_block,
                    false,
                    (None, (None, None)),
                    shares,
                )
            }
            Part::Fast => self.pocket_terms(block, y, dy_block, shares),
        };
        out.write(coupling);
    }

    /// The fast part of ball j's block: its pocket contact's terms in the
    /// equations of motion and its coupling to the cage, nothing else (the
    /// raceway contacts, gravity, drag and the frame's terms belong to the
    /// slow rest); all zero while the pocket is open.
    fn pocket_terms(
        &self,
        j: usize,
        y: &[f64],
        dy: &mut [f64],
        shares: Shares<'_>,
    ) -> BallCoupling {
        let (ball, [ex, er, et]) = self.elements.ball_kinematics(j, y);
        let slot = BallContact::Pocket as usize * ContactShare::LEN;
        let share = match shares {
            Shares::Reuse { memo, contact } if contact != Some(BallContact::Pocket) => {
                ContactShare::read(&memo[slot..])
            }
            Shares::Reuse { .. } => self.pocket_share(j, y, &ball, None),
            Shares::Evaluate(memo) => {
                let share = self.pocket_share(j, y, &ball, None);
                if let Some(memo) = memo {
                    memo.fill(0.0);
                    share.write(&mut memo[slot..]);
                }
                share
            }
        };
        dy.fill(0.0);
        let mut out = BallCoupling::default();
        if !share.closed {
            return out;
        }
        let (m, inertia) = (self.elements.ball_mass, self.elements.ball_inertia);
        let r = y[self.elements.layout.ball(j) + 1];
        dy[3] = share.force.dot(&ex) / m;
        dy[4] = share.force.dot(&er) / m;
        dy[5] = share.force.dot(&et) / m / r;
        dy[6] = share.moment.dot(&ex) / inertia;
        dy[7] = share.moment.dot(&er) / inertia;
        dy[8] = share.moment.dot(&et) / inertia;
        if self.elements.params.planar {
            dy[3] = 0.0;
            dy[7] = 0.0;
            dy[8] = 0.0;
        }
        out.cage_force = share.body_force;
        out.cage_torque = share.body_moment.x;
        out.dissipation = share.dissipation;
        out
    }

    /// Whether ball j's pocket contact is open at y (no law's force, no
    /// squeeze film): the fast part's block is then zero.
    pub(super) fn pocket_open(&self, j: usize, y: &[f64]) -> bool {
        let (ball, _) = self.elements.ball_kinematics(j, y);
        !self.elements.pocket_acts(j, y, &ball)
    }

    /// [`Self::ball_rhs`] with the contact shares from `shares` (an end-point
    /// record only with all evaluated).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn ball_rhs_with(
        &self,
        t: f64,
        j: usize,
        y: &[f64],
        (inner, outer): (&RingMotion, &RingMotion),
        dy: &mut [f64],
        films_power: bool,
        (mut sink, (mut sample, end)): (Option<&mut Dissipation>, Extras<'_>),
        shares: Shares<'_>,
    ) -> BallCoupling {
        let l = self.elements.layout;
        let p = &self.elements.params;
        let (ball, [ex, er, et]) = self.elements.ball_kinematics(j, y);
        let w = ball.omega;
        // The film in the approach: each closed contact's share of the
        // films' work (dynamics::film).
        let mut film_work = [None; 2];
        let (memo, reused) = match shares {
            Shares::Evaluate(memo) => (memo, None),
            Shares::Reuse { memo, contact } => (None, Some((memo, contact))),
        };
        // The memo's share of a contact the perturbed state does not reach.
        let kept = |c: BallContact| match reused {
            Some((memo, touched)) if touched != Some(c) => {
                Some(ContactShare::read(&memo[c as usize * ContactShare::LEN..]))
            }
            _ => None,
        };
        let mut records = [None; 2];
        let inner_share = match kept(BallContact::Inner) {
            Some(share) => share,
            None => self.race_share(
                j,
                inner,
                &ball,
                0,
                (&mut film_work, &mut records),
                sink.as_deref_mut(),
                sample.as_deref_mut().map(|s| &mut s.inner),
            ),
        };
        let outer_share = match kept(BallContact::Outer) {
            Some(share) => share,
            None => self.race_share(
                j,
                outer,
                &ball,
                1,
                (&mut film_work, &mut records),
                sink.as_deref_mut(),
                sample.map(|s| &mut s.outer),
            ),
        };
        let pocket_share = match kept(BallContact::Pocket) {
            Some(share) => share,
            None => self.pocket_share(j, y, &ball, sink.as_deref_mut()),
        };
        let shares = [inner_share, outer_share, pocket_share];
        if let Some(end) = end {
            self.end_record(j, y, &ball, (inner, outer), records, end);
        }
        if let Some(memo) = memo {
            for (share, slot) in shares.iter().zip(memo.chunks_mut(ContactShare::LEN)) {
                share.write(slot);
            }
        }
        let mut force = Vector3::new(0.0, 0.0, -self.elements.ball_mass * p.gravity);
        let mut moment = Vector3::zeros();
        let mut out = add_shares(&shares, &mut force, &mut moment);
        let b = l.ball(j);
        let drag = &p.drag;
        if drag.effective_density > 0.0 {
            let v_t = y[b + 1] * y[b + 5];
            let w_rel = w - y[b + 5] * ex;
            let (f, m) = drag.ball(self.elements.geometry.ball_diameter, v_t, &w_rel);
            force += f * et;
            moment += m;
            out.dissipation -= f * v_t + m.dot(&w);
            if let Some(d) = sink {
                d.ball_drag -= f * v_t + m.dot(&w);
            }
        }
        let (r, phi_dot, vr) = (y[b + 1], y[b + 5], y[b + 4]);
        let (wr, wt) = (y[b + 7], y[b + 8]);
        let m = self.elements.ball_mass;
        let inertia = self.elements.ball_inertia;
        dy[0] = y[b + 3];
        dy[1] = vr;
        dy[2] = phi_dot;
        dy[3] = force.dot(&ex) / m;
        dy[4] = force.dot(&er) / m + r * phi_dot * phi_dot;
        dy[5] = (force.dot(&et) / m - 2.0 * vr * phi_dot) / r;
        dy[6] = moment.dot(&ex) / inertia;
        dy[7] = moment.dot(&er) / inertia + phi_dot * wt;
        dy[8] = moment.dot(&et) / inertia - phi_dot * wr;
        if l.ball_spin_angle {
            // ψ̇ = |ω_b − φ̇ e_x|: the ball's turning relative to the cage
            // frame carries its surface past the contacts (docs/model.md §1, §6).
            dy[StateLayout::SPIN_ANGLE] = (w - phi_dot * ex).norm();
        }
        if p.planar {
            dy[0] = 0.0;
            dy[3] = 0.0;
            dy[7] = 0.0;
            dy[8] = 0.0;
        }
        // Only the film-work accumulator needs this, and no Jacobian reads
        // it (`inert`): `block_rhs` leaves it out.
        if films_power {
            self.elements
                .add_film_work(t, y, j, dy, &film_work, inner, &mut out);
        }
        out
    }

    /// Ball j's part of an end-point evaluation: its raceway `records`,
    /// and its energy share only where the slot asks for it.
    #[inline(always)]
    fn end_record(
        &self,
        j: usize,
        y: &[f64],
        ball: &BallMotion,
        (inner, outer): (&RingMotion, &RingMotion),
        records: [Option<RacewayRecord>; 2],
        end: &mut EndRecord,
    ) {
        end.energy = end.energy.map(|_| {
            let known = |k: usize| Some(records[k].map(|r| (r.penetration, r.contact_angle)));
            let raceways = [
                self.raceway_energy(inner, &self.elements.inner_table, ball, known(0)),
                self.raceway_energy(outer, &self.elements.outer_table, ball, known(1)),
            ];
            self.ball_energy(j, y, ball, raceways)
        });
        end.raceways = records;
    }

    /// Ball j's share of its contact with `ring` (0: inner, whose moment
    /// about the ring centre the share carries; 1: outer); its film work
    /// goes to `film_work[k]`, its record for the step's acceptance to
    /// `records[k]`, its losses to `sink`, its output quantities to
    /// `output` (left as they are when the contact is open).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn race_share(
        &self,
        j: usize,
        ring: &RingMotion,
        ball: &BallMotion,
        k: usize,
        (film_work, records): (&mut [Option<FilmWork>; 2], &mut [Option<RacewayRecord>; 2]),
        sink: Option<&mut Dissipation>,
        output: Option<&mut ContactOutput>,
    ) -> ContactShare {
        let table = if k == 0 {
            &self.elements.inner_table
        } else {
            &self.elements.outer_table
        };
        // Read in place (a move of the whole contact costs a copy).
        let want = if output.is_some() {
            Want::Output
        } else {
            Want::Forces
        };
        let contact = self
            .elements
            .race_contact(ring, table, &self.episodes[j][k], ball, want);
        let Some(cn) = &contact else {
            return ContactShare::default();
        };
        if let Some(o) = output {
            *o = cn.output;
        }
        film_work[k] = cn.film_work;
        records[k] = Some(RacewayRecord::of(cn));
        if let Some(d) = sink {
            if k == 0 { &mut d.inner } else { &mut d.outer }.add(&cn.losses);
        }
        ContactShare {
            closed: true,
            force: cn.force + cn.surface.ball_force,
            moment: cn.moment + cn.surface.ball_moment,
            body_force: cn.surface.ring_force - cn.force,
            body_moment: if k == 0 {
                (cn.geometry.contact_point - ring.centre).cross(&(-cn.force)) - cn.couple
                    + (ball.centre - ring.centre).cross(&cn.surface.ring_force)
            } else {
                Vector3::zeros()
            },
            dissipation: cn.dissipation,
        }
    }

    /// Ball j's share of its pocket contact (the cage's torque in x).
    #[inline(always)]
    fn pocket_share(
        &self,
        j: usize,
        y: &[f64],
        ball: &BallMotion,
        sink: Option<&mut Dissipation>,
    ) -> ContactShare {
        let contact = self.elements.pocket_contact(j, y, ball);
        let Some(pc) = &contact else {
            return ContactShare::default();
        };
        if let Some(d) = sink {
            d.pocket_friction += pc.friction_power;
            d.pocket_damping += pc.dissipation - pc.friction_power;
        }
        let c = self.elements.layout.cage();
        let cage_centre = Vector3::new(0.0, y[c], y[c + 1]);
        ContactShare {
            closed: true,
            force: pc.force,
            moment: pc.moment,
            body_force: -pc.force,
            body_moment: Vector3::x() * (pc.point - cage_centre).cross(&(-pc.force)).x,
            dissipation: pc.dissipation,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_share_survives_the_memo_bit_for_bit() {
        let share = ContactShare {
            closed: true,
            force: Vector3::new(1.0 / 3.0, -0.0, 2e-300),
            moment: Vector3::new(-7.5, 1e10, 0.1),
            body_force: Vector3::new(-1.0 / 3.0, 0.0, -2e-300),
            body_moment: Vector3::new(3.0, -4.0, 5.0),
            dissipation: 12.5,
        };
        let mut memo = [0.0; ContactShare::LEN];
        share.write(&mut memo);
        let back = ContactShare::read(&memo);
        assert_eq!(back, share);
        assert_eq!(back.force.y.to_bits(), (-0.0f64).to_bits());
        ContactShare::default().write(&mut memo);
        assert!(!ContactShare::read(&memo).closed);
    }
}
