//! Race drive: how far the inner raceway sets a ball's kinematics
//! (rolldyn's regularisation; Jones–Harris has every ball touching both
//! raceways).
//!
//! Jones–Harris imposes rolling at both contacts and, under inner
//! control, no spin at the inner one. At an open inner contact rolldyn
//! used the normal towards the nearest point of the inner groove, a
//! raceway the ball does not touch: a free ball then orbited at several
//! times the cage speed (7218B under a tilt), and where that normal turns
//! parallel to the outer one (n_i = n_o, a ball far from an axially
//! displaced inner ring) the rolling and spin equations become singular
//! and Newton stalls.
//!
//! The drive weight w is 1 while the inner contact is closed (loaded
//! balls are Jones–Harris exactly) and falls as it opens,
//! w = 1/(1 + (g/g_ref)³) for a gap g, written through the signed Hertz
//! extension Q_s = K δ|δ|^{1/2} < 0 as w = 1/(1 + (Q_s/Q_ref)²), which is
//! C¹ at δ = 0 and has analytic gradients. g_ref = [`GAP_FRACTION`] D
//! (22 µm on a 7218B), Q_ref = K_i(0) g_ref^{3/2}: a ball that almost
//! touches keeps the Jones–Harris kinematics (its nearest inner point is
//! where its contact would be), one far from the groove gets the outer
//! contact's. The inner contact as the kinematics see it has the normal
//! n = w n_i − (1 − w) n_o: a free ball (w → 0) rolls as if it touched
//! the inner raceway opposite its outer contact, which carries it at
//! about the epicyclic cage speed.
//! Under inner control the no-spin condition is w s_i − (1 − w) s_o and
//! the gyroscopic friction 2w M_g/D at the inner contact (a free ball's
//! gyroscopic pivoting is resisted by no friction it could carry;
//! Jones–Harris put the full 2 M_g/D at the open contact, on ball and
//! ring). With the minus signs these blends stay regular for every w < 1.
//! Under outer control a free ball exerts no force on the inner ring, so
//! the drive changes nothing but the free balls' own speeds and places.

use super::{QuasiStaticSolver, Row3, Row5};
use crate::quasistatic::ring_contact::RingContactEval;

/// Inner gap, as a fraction of the ball diameter, at which the drive
/// weight is one half.
pub(super) const GAP_FRACTION: f64 = 1e-3;

/// The drive weight w and its gradients in the ball centre and the ring
/// displacement.
pub(super) struct RaceDrive {
    pub weight: f64,
    pub dq: Row3,
    pub du: Row5,
}

/// The [`RaceDrive`] of a ball from its inner contact (evaluated with the
/// signed extension), Q_ref \[N\] and the strength σ
/// (w = 1/(1 + σ (Q_s/Q_ref)²); σ = 0 is Jones–Harris).
pub(super) fn race_drive(inner: &RingContactEval, reference: f64, strength: f64) -> RaceDrive {
    if inner.in_contact() {
        return RaceDrive {
            weight: 1.0,
            dq: Row3::zeros(),
            du: Row5::zeros(),
        };
    }
    // Q_s = −F·n (F = −Q_s n); dQ_s = −(nᵀ dF + Fᵀ dn).
    let signed_load = -inner.force.dot(&inner.normal);
    let x = signed_load / reference;
    let den = 1.0 + strength * x * x;
    let dw_dload = -2.0 * strength * x / (reference * den * den);
    let (n, f) = (inner.normal.transpose(), inner.force.transpose());
    RaceDrive {
        weight: 1.0 / den,
        dq: -dw_dload * (n * inner.dforce_dball + f * inner.dnormal_dball),
        du: -dw_dload * (n * inner.dforce_dring + f * inner.dnormal_dring),
    }
}

/// The inner contact as the rolling equation sees it: the normal
/// n = w n_i − (1 − w) n_o and its gradients (the outer contact does not
/// depend on the inner ring's displacement).
pub(super) fn kinematic_inner(
    inner: &RingContactEval,
    outer: &RingContactEval,
    drive: &RaceDrive,
) -> RingContactEval {
    let w = drive.weight;
    let sum = inner.normal + outer.normal;
    RingContactEval {
        normal: w * inner.normal - (1.0 - w) * outer.normal,
        dnormal_dball: w * inner.dnormal_dball - (1.0 - w) * outer.dnormal_dball + sum * drive.dq,
        dnormal_dring: w * inner.dnormal_dring + sum * drive.du,
        ..*inner
    }
}

impl QuasiStaticSolver {
    /// Q_ref of [`race_drive`] \[N\]: the inner contact's Hertz load at the
    /// groove bottom at a penetration of [`GAP_FRACTION`] D.
    pub(super) fn drive_reference(&self) -> f64 {
        let gap = GAP_FRACTION * self.geometry.ball_diameter;
        self.inner_table.stiffness_with_derivative(0.0).0 * gap * gap.sqrt()
    }
}
