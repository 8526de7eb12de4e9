//! Prescribed ring displacements: any of the five ring
//! displacements (x, y, z, θ_y, θ_z) may be held at a given value, a fixed
//! tilt (0) or misalignment, instead of following its load. The Newton
//! iteration then drops that ring equation and keeps the displacement
//! (the row of the Schur system becomes the identity with a zero
//! right-hand side); the load the constraint must supply, the reaction
//! R = −(applied + contact loads on the ring), is reported; the
//! bearing stiffness K stays the full 5×5 matrix of the unconstrained
//! equations.

use super::{Assembly, Matrix5, QuasiStaticSolver, Setup, State};
use crate::geometry::RingKind;

impl QuasiStaticSolver {
    /// `state` with its prescribed displacements set.
    pub(super) fn with_prescribed(state: State, setup: Setup<'_>) -> State {
        let mut state = state;
        for (k, v) in setup.options.prescribed_displacement.iter().enumerate() {
            if let Some(v) = v {
                state.ring[k] = *v;
            }
        }
        state
    }

    /// Whether any displacement is prescribed.
    pub(super) fn constrained(setup: Setup<'_>) -> bool {
        setup
            .options
            .prescribed_displacement
            .iter()
            .any(Option::is_some)
    }

    /// The assembly with the prescribed displacements' ring equations
    /// replaced by Δu_k = 0.
    pub(super) fn constrained_assembly(
        &self,
        state: &State,
        controls: &[RingKind],
        setup: Setup<'_>,
    ) -> Assembly {
        let mut asm = self.assemble(state, controls, setup);
        for (k, v) in setup.options.prescribed_displacement.iter().enumerate() {
            if v.is_some() {
                asm.ring[k] = 0.0;
                asm.d.row_mut(k).fill(0.0);
                asm.d[(k, k)] = 1.0;
                for c in &mut asm.c {
                    c.row_mut(k).fill(0.0);
                }
            }
        }
        asm
    }

    /// Full Schur complement S (K = −S) of the unconstrained equations.
    pub(super) fn full_schur(
        &self,
        state: &State,
        controls: &[RingKind],
        setup: Setup<'_>,
    ) -> Matrix5 {
        Self::newton_step(&self.assemble(state, controls, setup))
            .map(|(_, _, s)| s)
            .unwrap_or_else(Matrix5::zeros)
    }

    /// Loads the constraints apply to the ring (zero on free displacements).
    pub(super) fn reaction(
        &self,
        state: &State,
        controls: &[RingKind],
        setup: Setup<'_>,
    ) -> [f64; 5] {
        if !Self::constrained(setup) {
            return [0.0; 5];
        }
        let asm = self.assemble(state, controls, setup);
        std::array::from_fn(|k| {
            if setup.options.prescribed_displacement[k].is_some() {
                -asm.ring[k]
            } else {
                0.0
            }
        })
    }
}
