//! What one ball's contacts pass to the border of the block-split
//! equations of motion (docs/model.md §8): forces and moments on the rings and the
//! cage, dissipated power, and the films' work (`dynamics::film`). The
//! balls' couplings are summed in ball order (`ball_pass`).

use nalgebra::Vector3;

/// What one ball's contacts do to the border: forces and moments on the
/// rings and the cage, and dissipated power (the coupling vector of the
/// block split, docs/model.md §8).
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct BallCoupling {
    pub(super) ring_force: Vector3<f64>,
    pub(super) ring_moment: Vector3<f64>,
    pub(super) outer_force: Vector3<f64>,
    pub(super) cage_force: Vector3<f64>,
    pub(super) cage_torque: f64,
    pub(super) dissipation: f64,
    /// Power the films in the approach do on the contacts, the rings'
    /// accelerations aside \[W\] (dynamics::film).
    pub(super) film_power: f64,
    /// ∂(Σ∫h)/∂(inner ring velocity x, y, z, tilt rates) \[N·s, N·m·s\].
    pub(super) ring_velocity_gradient: [f64; 5],
    /// ∂(Σ∫h)/∂(outer ring velocity y, z) \[N·s\].
    pub(super) outer_velocity_gradient: [f64; 2],
}

impl BallCoupling {
    pub(super) const LEN: usize = 22;

    pub(super) fn add(&mut self, other: &Self) {
        self.ring_force += other.ring_force;
        self.ring_moment += other.ring_moment;
        self.outer_force += other.outer_force;
        self.cage_force += other.cage_force;
        self.cage_torque += other.cage_torque;
        self.dissipation += other.dissipation;
        self.film_power += other.film_power;
        add_to(
            &mut self.ring_velocity_gradient,
            &other.ring_velocity_gradient,
        );
        add_to(
            &mut self.outer_velocity_gradient,
            &other.outer_velocity_gradient,
        );
    }

    pub(super) fn write(&self, out: &mut [f64]) {
        out[0..3].copy_from_slice(self.ring_force.as_slice());
        out[3..6].copy_from_slice(self.ring_moment.as_slice());
        out[6..9].copy_from_slice(self.outer_force.as_slice());
        out[9..12].copy_from_slice(self.cage_force.as_slice());
        out[12] = self.cage_torque;
        out[13] = self.dissipation;
        out[14] = self.film_power;
        out[15..20].copy_from_slice(&self.ring_velocity_gradient);
        out[20..22].copy_from_slice(&self.outer_velocity_gradient);
    }

    pub(super) fn read(c: &[f64]) -> Self {
        Self {
            ring_force: Vector3::from_column_slice(&c[0..3]),
            ring_moment: Vector3::from_column_slice(&c[3..6]),
            outer_force: Vector3::from_column_slice(&c[6..9]),
            cage_force: Vector3::from_column_slice(&c[9..12]),
            cage_torque: c[12],
            dissipation: c[13],
            film_power: c[14],
            ring_velocity_gradient: [c[15], c[16], c[17], c[18], c[19]],
            outer_velocity_gradient: [c[20], c[21]],
        }
    }
}

/// a += b, element by element.
pub(super) fn add_to(a: &mut [f64], b: &[f64]) {
    for (a, b) in a.iter_mut().zip(b) {
        *a += b;
    }
}
