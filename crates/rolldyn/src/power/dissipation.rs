//! Where the dynamic model dissipates energy: the exact bookkeeping of
//! docs/model.md §10, split by force element and mechanism.
//!
//! The traction of a ball–raceway contact dissipates −Σ dF·s over the
//! ellipse cells, with the slip linear in the cell position,
//! s(X) = s_P + Ω × (X − P) ([`crate::traction::ellipse`]). Hence exactly
//! ```text
//! −Σ dF·s = −F·s_P − Ω·C          (C = Σ (X − P) × dF, the couple about P)
//!         = −F_roll s_roll − F_⊥ s_⊥ − C_n Ω_n − C_t·Ω_t
//! ```
//! rigid sliding in the rolling direction, transverse sliding, spin (about
//! the contact normal) and the rest: the differential (Heathcote) slip of
//! the curved contact, which Harris & Kotzalas (*Advanced Concepts*, §6.4)
//! call differential sliding. The last is taken as the remainder
//! `traction − the first three`, so the parts sum to the traction's
//! dissipation to rounding for every traction model (FASTSIM, which works
//! on a flat patch, has none). Hysteresis is M_h |ω_roll| (Lei et al. 2023 eq 21),
//! damping the normal law's (Q − K δ^{3/2}) δ̇, and the EHL rolling
//! resistance the power of its force and couple (2 F_R u in pure rolling;
//! `lubrication::rolling_resistance`).

/// Dissipated power of one ball–raceway contact by mechanism \[W\].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactLosses {
    /// Rigid sliding along the rolling direction, −F_roll s_roll.
    pub rolling_sliding: f64,
    /// Rigid sliding across the rolling direction, −F_⊥ s_⊥.
    pub transverse_sliding: f64,
    /// Spin about the contact normal, −C_n Ω_n.
    pub spin: f64,
    /// Differential (Heathcote) sliding: the rest of the traction's power.
    pub differential_sliding: f64,
    /// Elastic hysteresis (rolling resistance).
    pub hysteresis: f64,
    /// Normal damping of the contact law.
    pub damping: f64,
    /// EHL (Poiseuille) rolling resistance.
    pub rolling_resistance: f64,
}

impl ContactLosses {
    /// Sum of the mechanisms \[W\].
    pub fn total(&self) -> f64 {
        self.rolling_sliding
            + self.transverse_sliding
            + self.spin
            + self.differential_sliding
            + self.hysteresis
            + self.damping
            + self.rolling_resistance
    }

    /// Adds `other`, mechanism by mechanism.
    pub fn add(&mut self, other: &Self) {
        self.rolling_sliding += other.rolling_sliding;
        self.transverse_sliding += other.transverse_sliding;
        self.spin += other.spin;
        self.differential_sliding += other.differential_sliding;
        self.hysteresis += other.hysteresis;
        self.damping += other.damping;
        self.rolling_resistance += other.rolling_resistance;
    }

    /// The mechanisms with their channel names.
    pub fn named(&self) -> [(&'static str, f64); 7] {
        [
            ("rolling_sliding", self.rolling_sliding),
            ("transverse_sliding", self.transverse_sliding),
            ("spin", self.spin),
            ("differential_sliding", self.differential_sliding),
            ("hysteresis", self.hysteresis),
            ("damping", self.damping),
            ("rolling_resistance", self.rolling_resistance),
        ]
    }
}

/// Dissipated power of the whole bearing by component \[W\] at one
/// instant of a dynamic run, and the torque that drives the inner ring.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Dissipation {
    /// Ball–inner-raceway contacts, summed over the balls.
    pub inner: ContactLosses,
    /// Ball–outer-raceway contacts, summed over the balls.
    pub outer: ContactLosses,
    /// Friction in the ball–pocket contacts.
    pub pocket_friction: f64,
    /// Normal damping (or squeeze film) in the ball–pocket contacts.
    pub pocket_damping: f64,
    /// Fluid shear and squeeze of the cage guide land.
    pub guide_land: f64,
    /// Air–oil drag on the balls (orbit and spin).
    pub ball_drag: f64,
    /// Viscous and windage drag on the cage.
    pub cage_drag: f64,
    /// Dampers of the inner-ring support and the housing, and the friction
    /// of a floating bearing's outer ring sliding in its bore.
    pub support_damping: f64,
    /// Friction of the contact seals on the inner ring.
    pub seals: f64,
    /// Churning of an oil bath or jet.
    pub churning: f64,
    /// Torque the drive supplies to the inner ring about its axis \[N·m\]
    /// (not a power): with a prescribed speed the torque that holds it (the
    /// friction torque), with a torque drive the applied torque.
    pub drive_torque: f64,
    /// The bearing's friction torque: the moment of its forces on the inner
    /// ring (contacts, an inner guide land, seals) against the rotation,
    /// −M_x \[N·m\].
    pub friction_torque: f64,
}

impl Dissipation {
    /// Adds `other`, component by component.
    pub fn add(&mut self, other: &Self) {
        self.inner.add(&other.inner);
        self.outer.add(&other.outer);
        self.pocket_friction += other.pocket_friction;
        self.pocket_damping += other.pocket_damping;
        self.guide_land += other.guide_land;
        self.ball_drag += other.ball_drag;
        self.cage_drag += other.cage_drag;
        self.support_damping += other.support_damping;
        self.seals += other.seals;
        self.churning += other.churning;
        self.drive_torque += other.drive_torque;
        self.friction_torque += other.friction_torque;
    }

    /// Total dissipated power \[W\]: the rate of the energy balance's
    /// dissipated-energy accumulator.
    pub fn total(&self) -> f64 {
        self.inner.total() + self.outer.total() + self.others().iter().map(|(_, p)| p).sum::<f64>()
    }

    /// The components outside the raceway contacts with their channel names.
    pub fn others(&self) -> [(&'static str, f64); 8] {
        [
            ("pocket_friction", self.pocket_friction),
            ("pocket_damping", self.pocket_damping),
            ("guide_land", self.guide_land),
            ("ball_drag", self.ball_drag),
            ("cage_drag", self.cage_drag),
            ("support_damping", self.support_damping),
            ("seals", self.seals),
            ("churning", self.churning),
        ]
    }
}

#[cfg(test)]
mod tests {
    use crate::traction::TractionGrid;
    use crate::traction::ellipse::{
        ContactKinematics, ContactPatch, TractionIntegration, integrate,
    };
    use crate::traction::{ContactConditions, ModifiedCoulomb};
    use nalgebra::Vector3;

    /// A curved patch (R_d = 4 mm) under Coulomb friction.
    fn evaluate(slip: Vector3<f64>, spin: Vector3<f64>) -> crate::traction::TractionResult {
        let patch = ContactPatch {
            deformed_radius: 4e-3,
            ..crate::traction::ellipse::test_patch()
        };
        let law = ModifiedCoulomb {
            friction: 0.1,
            stick_speed: 0.0,
            full_speed: 1e-3,
        };
        let method = TractionIntegration::Grid {
            across: 24,
            along: 8,
        };
        let conditions = ContactConditions::default();
        integrate(
            &law,
            &TractionGrid::new(method),
            &ContactKinematics {
                patch,
                ball_centre: Vector3::zeros(),
                slip,
                relative_spin: spin,
                conditions,
            },
        )
    }

    /// The split's premise: the traction's power is −F·s_P − Ω·C exactly
    /// (the slip is linear in the cell position), and the rest after
    /// sliding and spin, −Ω_t·C_t, is the differential slip of the curved
    /// patch: zero for pure rolling on a flat patch, positive on a curved one.
    #[test]
    fn traction_power_splits_into_sliding_spin_and_differential() {
        let n = Vector3::new(0.0, 0.0, -1.0);
        let slip = Vector3::new(0.3, -0.2, 0.0);
        let spin = Vector3::new(150.0, 20.0, 80.0);
        let r = evaluate(slip, spin);
        let split = -r.force.dot(&slip) - spin.dot(&r.couple);
        assert!((split - r.dissipation).abs() < 1e-12 * r.dissipation.abs());
        let spin_part = -r.couple.dot(&n) * spin.dot(&n);
        let rest = r.dissipation + r.force.dot(&slip) - spin_part;
        let tangential = |v: Vector3<f64>| v - v.dot(&n) * n;
        let differential = -tangential(spin).dot(&tangential(r.couple));
        assert!((rest - differential).abs() < 1e-9 * r.dissipation);
        // Pure rolling about the axis across the rolling direction: only
        // the curved patch's Heathcote slip dissipates.
        let rolling = evaluate(Vector3::zeros(), Vector3::new(1000.0, 0.0, 0.0));
        assert!(rolling.dissipation > 0.0);
        let rolling_differential = -1000.0 * rolling.couple.x;
        assert!((rolling_differential - rolling.dissipation).abs() < 1e-12);
    }
}
