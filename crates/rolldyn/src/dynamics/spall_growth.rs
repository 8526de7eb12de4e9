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
use crate::surface::{SpallSite, SpallSize};

/// Smallest growth step, relative to the spall's length.
pub const MIN_INCREMENT: f64 = 0.01;

/// A growing spall: where it is (its site and index among that surface's
/// spalls), its length at t = 0 \[m\] and its rate \[m/s\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Growing {
    site: SpallSite,
    index: usize,
    initial_length: f64,
    rate: f64,
}

impl BearingModel {
    /// The growing spalls of the model's surfaces.
    pub(super) fn growing_spalls(&self) -> Vec<Growing> {
        let surface = &self.elements.params.surface;
        let mut out = Vec::new();
        let mut push = |site, spalls: &[crate::surface::Spall]| {
            for (index, s) in spalls.iter().enumerate() {
                if let (SpallSize::Length(length), true) = (s.size, s.growth_rate > 0.0) {
                    out.push(Growing {
                        site,
                        index,
                        initial_length: length,
                        rate: s.growth_rate,
                    });
                }
            }
        };
        push(SpallSite::Inner, &surface.inner.spalls);
        push(SpallSite::Outer, &surface.outer.spalls);
        for (j, ball) in surface.balls.iter().enumerate() {
            push(SpallSite::Ball(j), &ball.spalls);
        }
        out
    }

    fn spall_mut(&mut self, site: SpallSite, index: usize) -> &mut crate::surface::Spall {
        let surface = &mut self.elements.params.surface;
        match site {
            SpallSite::Inner => &mut surface.inner.spalls[index],
            SpallSite::Outer => &mut surface.outer.spalls[index],
            SpallSite::Ball(j) => &mut surface.balls[j].spalls[index],
        }
    }

    /// The growing spalls' current lengths \[m\], in the order of
    /// [`crate::surface::SurfaceModel::spalls`] (empty without growth).
    pub fn growing_spall_lengths(&self) -> Vec<f64> {
        self.growth
            .iter()
            .map(|g| match self.spall(g.site, g.index).size {
                SpallSize::Length(l) => l,
                SpallSize::Angle(_) => f64::NAN,
            })
            .collect()
    }

    fn spall(&self, site: SpallSite, index: usize) -> &crate::surface::Spall {
        let surface = &self.elements.params.surface;
        match site {
            SpallSite::Inner => &surface.inner.spalls[index],
            SpallSite::Outer => &surface.outer.spalls[index],
            SpallSite::Ball(j) => &surface.balls[j].spalls[index],
        }
    }

    /// Sets the growing spalls' lengths (a checkpoint's).
    pub(super) fn set_growing_spall_lengths(&mut self, lengths: &[f64]) {
        for (g, &length) in self.growth.clone().iter().zip(lengths) {
            self.spall_mut(g.site, g.index).size = SpallSize::Length(length);
        }
    }

    /// The growth at an accepted step at (t, y); true when a spall grew
    /// (the right-hand side changed).
    pub(super) fn grow_spalls(&mut self, t: f64, y: &[f64]) -> bool {
        let mut grown = false;
        for g in self.growth.clone() {
            let spall = *self.spall(g.site, g.index);
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
                *self.spall_mut(g.site, g.index) = grown_spall;
                grown = true;
            }
        }
        grown
    }
}
