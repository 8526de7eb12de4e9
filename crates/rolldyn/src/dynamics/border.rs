//! The border's equations of the dynamic bearing model (docs/model.md §1,
//! §5, §8): the inner ring under the balls' sums, its support, the
//! applied and tabulated loads and an unbalance; the outer ring (housed or
//! sliding in its bore); the cage (whirl, unbalance, drag, guide land);
//! the seals' and churning's moments, the drive, and the energy
//! accumulators (work, dissipation, the films' power).

use super::coupling::BallCoupling;
use super::model::BearingModel;
use super::motion::RingMotion;
use crate::cage::GuideLand;
use crate::geometry::RingKind;
use crate::power::Dissipation;
use nalgebra::Vector3;

impl BearingModel {
    /// Derivatives of the border states (rings, cage, energy accumulators;
    /// into `dy`, which starts at the inner ring's first state) for the
    /// summed ball couplings.
    pub(super) fn border_rhs_with(
        &self,
        t: f64,
        y: &[f64],
        inner: &RingMotion,
        balls: &BallCoupling,
        dy: &mut [f64],
        mut sink: Option<&mut Dissipation>,
    ) {
        let l = self.elements.layout;
        let p = &self.elements.params;
        let g = p.gravity;
        // The balls' sums, to which the border's own terms are added.
        let mut sums = *balls;
        let mut external_power = 0.0;
        // `dy` starts at the inner ring: ring, outer ring, cage and work
        // offsets within it.
        let (dr, dob, dc, dw) = (
            0,
            l.outer() - l.ring(),
            l.cage() - l.ring(),
            l.work() - l.ring(),
        );
        if let Some(guide) = &p.cage.guide {
            self.add_guide_land(guide, t, y, &mut sums, sink.as_deref_mut());
        }
        let r = l.ring();
        dy[dr..dr + 5].copy_from_slice(&y[r + 5..r + 10]);
        let mi = p.inner_ring_mass;
        let loads = p.loads.at(t);
        let (ring_position, ring_velocity) = (
            Vector3::new(y[r], y[r + 1], y[r + 2]),
            Vector3::new(y[r + 5], y[r + 6], y[r + 7]),
        );
        sums.ring_force += p.inner_support.force(&ring_position, &ring_velocity);
        sums.dissipation += p.inner_support.dissipation(&ring_velocity);
        if let Some(d) = sink.as_deref_mut() {
            d.support_damping = p.inner_support.dissipation(&ring_velocity);
        }
        // A rotating unbalance: not a potential (it turns), its work
        // accumulated.
        let [fy, fz] = p.unbalance.map_or([0.0; 2], |u| {
            let spin = self.elements.spin(t, y);
            u.force(spin.speed, spin.angle)
        });
        external_power += fy * y[r + 6] + fz * y[r + 7];
        dy[dr + 5] = (sums.ring_force.x + loads.force[0]) / mi;
        dy[dr + 6] = (sums.ring_force.y + loads.force[1] + fy) / mi;
        dy[dr + 7] = (sums.ring_force.z + loads.force[2] + fz) / mi - g;
        dy[dr + 8] = (sums.ring_moment.y + loads.moment[0]) / p.inner_ring_tilt_inertia;
        dy[dr + 9] = (sums.ring_moment.z + loads.moment[1]) / p.inner_ring_tilt_inertia;
        for k in (0..10).filter(|&k| p.inner_ring_state_frozen(k)) {
            dy[dr + k] = 0.0;
        }
        // Tabulated loads: the load potential −F(t)·x changes explicitly
        // with time; that change is work of the external loads.
        let load_rate = p.loads.rate(t);
        external_power -= load_rate.force[0] * y[r]
            + load_rate.force[1] * y[r + 1]
            + load_rate.force[2] * y[r + 2]
            + load_rate.moment[0] * y[r + 3]
            + load_rate.moment[1] * y[r + 4];
        self.outer_ring_rhs(y, &mut sums, &mut dy[dob..], sink.as_deref_mut());
        let (cage_speed, cage_drag, unbalance_power) = self.cage_rhs(y, &mut sums, &mut dy[dc..]);
        if let Some(power) = unbalance_power {
            external_power += power;
        }
        // The moment about the ring's (tilted) axis of the bearing's forces
        // on the inner ring (contacts, an inner guide land) and its seals' and
        // churning's.
        let mut axial_moment = sums.ring_moment.dot(&inner.axis);
        // The seals' and the churning's moments and powers on the ring.
        let w = inner.spin_speed;
        let seals = p.seals.as_ref().map(|s| (s.moment(w), s.power(w)));
        let churning = p.churning.as_ref().map(|c| (c.moment(w), c.power(w)));
        for (moment, power) in [seals, churning].into_iter().flatten() {
            sums.dissipation += power;
            axial_moment += moment;
        }
        if let Some(d) = sink.as_deref_mut() {
            d.seals = seals.map_or(0.0, |(_, power)| power);
            d.churning = churning.map_or(0.0, |(_, power)| power);
        }
        // Drive power: a prescribed spin supplies −M_x ω (the torque that
        // holds the speed); a torque drive T ω, the rotor's speed then
        // following J ω̇ = T + M_x.
        let drive_torque = match &p.drive {
            None => -axial_moment,
            Some(drive) => {
                let s = l.spin() - l.ring();
                dy[s] = inner.spin_speed;
                dy[s + 1] = (drive.torque_at(t) + axial_moment) / drive.inertia;
                drive.torque_at(t)
            }
        };
        if let Some(d) = sink {
            d.cage_drag = -cage_drag * cage_speed;
            d.drive_torque = drive_torque;
            d.friction_torque = -axial_moment;
        }
        dy[dw] = drive_torque * inner.spin_speed + external_power;
        dy[dw + 1] = sums.dissipation;
        if l.film_work {
            // The rings' accelerations complete the films' power.
            let dot = |g: &[f64], a: &[f64]| g.iter().zip(a).map(|(g, a)| g * a).sum::<f64>();
            dy[dw + 2] = sums.film_power
                + dot(&sums.ring_velocity_gradient, &dy[dr + 5..dr + 10])
                + dot(&sums.outer_velocity_gradient, &dy[dob + 2..dob + 4]);
        }
    }

    /// The cage's equations (`dy` starts at its first state): its centre's
    /// motion when it whirls (with its unbalance, whose power it returns),
    /// else held; its rotation under the contacts' torque and its drag.
    /// Returns the cage's speed, its drag torque and the unbalance's power.
    #[inline(always)]
    fn cage_rhs(
        &self,
        y: &[f64],
        sums: &mut BallCoupling,
        dy: &mut [f64],
    ) -> (f64, f64, Option<f64>) {
        let p = &self.elements.params;
        let c = self.elements.layout.cage();
        let mut unbalance_power = None;
        dy[..3].copy_from_slice(&y[c + 3..c + 6]);
        if p.cage.whirl {
            let [fy, fz] = p.cage.unbalance_force(y[c + 2], y[c + 5]);
            unbalance_power = Some(fy * y[c + 3] + fz * y[c + 4]);
            dy[3] = (sums.cage_force.y + fy) / p.cage.mass;
            dy[4] = (sums.cage_force.z + fz) / p.cage.mass - p.gravity;
        } else {
            dy[0] = 0.0;
            dy[1] = 0.0;
            dy[3] = 0.0;
            dy[4] = 0.0;
        }
        let cage_speed = y[c + 5];
        let cage_drag = -(p.drag.cage_viscous * cage_speed
            + p.drag.cage_windage * cage_speed * cage_speed.abs());
        sums.dissipation -= cage_drag * cage_speed;
        dy[5] = (sums.cage_torque + cage_drag) / p.cage.inertia;
        (cage_speed, cage_drag, unbalance_power)
    }

    /// The guide land's forces on the cage and their reaction on the ring
    /// that guides it, added to `sums` with the fluid's dissipated power
    /// (the stop spring is conservative).
    #[inline(always)]
    fn add_guide_land(
        &self,
        guide: &GuideLand,
        t: f64,
        y: &[f64],
        sums: &mut BallCoupling,
        sink: Option<&mut Dissipation>,
    ) {
        let c = self.elements.layout.cage();
        let cage_centre = Vector3::new(0.0, y[c], y[c + 1]);
        let (centre, centre_velocity, land_speed) = self.elements.guide_ring(guide, t, y);
        let cage_velocity = Vector3::new(0.0, y[c + 3], y[c + 4]);
        let gf = guide.forces(&(cage_centre - centre), y[c + 5], land_speed);
        sums.cage_force += gf.force;
        sums.cage_torque += gf.torque;
        // Fluid power is dissipation; the stop spring is conservative.
        let stop_force = -guide.stop_stiffness * gf.stop * (cage_centre - centre).normalize();
        let fluid = gf.force
            - if gf.stop > 0.0 {
                stop_force
            } else {
                Vector3::zeros()
            };
        let fluid_power =
            -(fluid.dot(&(cage_velocity - centre_velocity)) + gf.torque * (y[c + 5] - land_speed));
        sums.dissipation += fluid_power;
        if let Some(d) = sink {
            d.guide_land = fluid_power;
        }
        match guide.ring {
            RingKind::Inner => {
                sums.ring_force -= gf.force;
                sums.ring_moment -= gf.torque * Vector3::x();
            }
            RingKind::Outer => sums.outer_force -= gf.force,
        }
    }

    /// The outer ring's equations (`dy` starts at its first state): the
    /// sliding ring's axial motion under the bore's friction, the housed
    /// ring's radial motion on its housing; their dissipation into `sums`.
    #[inline(always)]
    fn outer_ring_rhs(
        &self,
        y: &[f64],
        sums: &mut BallCoupling,
        dy: &mut [f64],
        mut sink: Option<&mut Dissipation>,
    ) {
        let (l, p) = (self.elements.layout, &self.elements.params);
        let o = l.outer();
        if let Some(ring) = &p.sliding_outer_ring {
            // The bore takes the balls' radial load on the ring and holds
            // it axially by friction.
            let s = l.slide();
            let speed = y[s + 1];
            let friction = ring.friction_force(speed, sums.outer_force.y.hypot(sums.outer_force.z));
            sums.dissipation -= friction * speed;
            if let Some(d) = sink.as_deref_mut() {
                d.support_damping -= friction * speed;
            }
            let ds = s - l.outer();
            dy[ds] = speed;
            dy[ds + 1] = (sums.outer_force.x + friction) / ring.mass;
        }
        dy[..4].fill(0.0);
        if let Some(ring) = &p.outer_ring {
            let position = Vector3::new(0.0, y[o], y[o + 1]);
            let velocity = Vector3::new(0.0, y[o + 2], y[o + 3]);
            sums.outer_force += ring.housing.force(&position, &velocity);
            sums.dissipation += ring.housing.dissipation(&velocity);
            if let Some(d) = sink {
                d.support_damping += ring.housing.dissipation(&velocity);
            }
            dy[0] = y[o + 2];
            dy[1] = y[o + 3];
            dy[2] = sums.outer_force.y / ring.mass;
            dy[3] = sums.outer_force.z / ring.mass - p.gravity;
        }
    }
}
