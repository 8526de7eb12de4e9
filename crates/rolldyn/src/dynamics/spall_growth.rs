//! Spall growth over a run: a spall with a growth rate g lengthens towards
//! L(t) = L₀ + g t (symmetrically about its centre), for run-to-failure
//! trends in one record (docs/dynamics.md, "Spall growth").
//!
//! The surface must not change under a loaded contact: the contact's
//! potential energy would jump, or, changed smoothly, the surface would do
//! work Q ∂Δδ/∂t on the bearing that no force element accounts for. So the
//! spall grows in steps at accepted integration steps when no ball's
//! contact lies on it (nor on the part it grows into, with a tenth of its
//! half-width to spare) and the length it lags behind L(t) is at least
//! [`MIN_INCREMENT`] of it. The right-hand side then changes (the
//! integrator restarts its step from there), and the energy balance stays
//! exact: the drop is zero wherever the surface changed.

use super::model::BearingModel;
use crate::surface::SpallSize;

/// Smallest growth step, relative to the spall's length.
pub const MIN_INCREMENT: f64 = 0.01;

impl BearingModel {
    /// The growing spalls' current lengths \[m\], in the order of
    /// [`crate::surface::SurfaceModel::spalls`] (empty without growth).
    pub fn growing_spall_lengths(&self) -> impl Iterator<Item = f64> + '_ {
        self.growth.iter().map(
            |g| match self.elements.params.surface.spall(g.site, g.index).size {
                SpallSize::Length(l) => l,
                SpallSize::Angle(_) => f64::NAN,
            },
        )
    }

    /// The growing spalls' (current length, length L₀ + g t asked at time
    /// `t`, growth rate g) \[m, m, m/s\], in the order of
    /// [`Self::growing_spall_lengths`].
    pub fn spall_growth_at(&self, t: f64) -> impl Iterator<Item = (f64, f64, f64)> + '_ {
        self.growing_spall_lengths()
            .zip(&self.growth)
            .map(move |(length, g)| (length, g.initial_length + g.rate * t, g.rate))
    }

    /// Sets the growing spalls' lengths (a checkpoint's).
    pub(super) fn set_growing_spall_lengths(&mut self, lengths: &[f64]) {
        let surface = &mut self.elements.params.surface;
        for (g, &length) in self.growth.iter().zip(lengths) {
            surface.spall_mut(g.site, g.index).size = SpallSize::Length(length);
        }
    }

    /// The growth at an accepted step at (t, y); true when a spall grew
    /// (the right-hand side changed).
    pub(super) fn grow_spalls(&mut self, t: f64, y: &[f64]) -> bool {
        let mut grown = false;
        for k in 0..self.growth.len() {
            let g = self.growth[k];
            let spall = *self.elements.params.surface.spall(g.site, g.index);
            let SpallSize::Length(current) = spall.size else {
                continue;
            };
            let target = g.initial_length + g.rate * t;
            if target - current < MIN_INCREMENT * current {
                continue;
            }
            let grown_spall = crate::surface::Spall {
                size: SpallSize::Length(target),
                ..spall
            };
            if !self.elements.spall_is_loaded(t, y, g.site, &grown_spall) {
                *self.elements.params.surface.spall_mut(g.site, g.index) = grown_spall;
                grown = true;
            }
        }
        grown
    }
}
