//! The lubricant film in the normal approach (MODEL §4, option): the film
//! as a state of each contact that follows its steady thickness.
//!
//! MODEL §4 puts the central film into the elastic compression,
//! δ_el = δ + h_c, so a contact carries load through its film before the
//! surfaces overlap and the film's own compliance acts in series with
//! Hertz. It offers h_c from the current load (a fixed point) or from the
//! previous accepted step. Neither closes the energy balance:
//! - the step-lagged film pumps energy into contact vibrations at a rate
//!   set by the integrator's step (docs/lubrication.md);
//! - the fixed point h_c(Q, u, α) has a potential in Q only. Its work
//!   ∫Q dh also moves with the entrainment speed u and the contact angle α,
//!   whose rates need the accelerations of the bodies.
//!
//! rolldyn therefore carries h as a state of each ball–raceway contact
//! that relaxes to its steady value h_ss (Hamrock–Dowson central film,
//! starved by the ring's supply) over the time the lubricant takes from
//! the edge of the Hertz zone to its centre:
//!
//! ```text
//! ḣ = (|u|/b) (h_ss(Q, u, α) − h)
//! ```
//!
//! b/|u| is the time scale of transient EHL: Venner & Lubrecht
//! (*Multilevel Methods in Lubrication*, Elsevier 2000) write time as
//! t u_m/a, the Hertz half-width a being our b. The first-order lag is
//! rolldyn's assumption, not a paper's equation. Its limit b/|u| → 0 is
//! MODEL §4's fixed point; at steady conditions h = h_ss exactly. The film
//! then does the work ∫Q ḣ dt on the contact, an explicit power in the
//! energy balance. Vibrations faster than |u|/b see a stiffer film.
//!
//! **Light loads.** Hamrock–Dowson's film grows without bound as Q → 0
//! (h ∝ W^−0.067) and its semi-axis b vanishes, so h_ss and b are taken
//! at W ≥ [`FLOOR_LOAD_PARAMETER`] (1e-8): below Q_f = W_f E' R_x² the
//! film stays at h_ss(Q_f), and an open contact's film relaxes towards it.
//! Hamrock & Dowson's fits cover W over one decade around 1e-6 (Part III,
//! J. Lubr. Technol. 99 (1977) 264–276), so the floor lies well below any
//! film the formula was made for; it bounds the film at about 1.3 times
//! its 1e-6 value. A contact opens when its gap exceeds its film.

/// Dimensionless load W = Q/(E' R_x²) below which the steady film and the
/// relaxation rate are held at their values at W (light-load floor).
pub const FLOOR_LOAD_PARAMETER: f64 = 1e-8;

/// The light-load floor Q_f = W_f E' R_x² \[N\] of a contact with
/// effective modulus E' \[Pa\] and rolling radius R_x \[m\].
pub fn floor_load(effective_modulus: f64, rolling_radius: f64) -> f64 {
    FLOOR_LOAD_PARAMETER * effective_modulus * rolling_radius * rolling_radius
}

/// Relaxation rate |u|/b \[1/s\] of the film of a contact with entrainment
/// speed u \[m/s\] and semi-axis b along the rolling direction \[m\]
/// (0 when b is not positive: no film response).
pub fn relaxation_rate(entrainment_speed: f64, semi_minor: f64) -> f64 {
    if semi_minor > 0.0 {
        entrainment_speed.abs() / semi_minor
    } else {
        0.0
    }
}

/// Film rate ḣ = (|u|/b)(h_ss − h) \[m/s\].
pub fn film_rate(steady: f64, film: f64, entrainment_speed: f64, semi_minor: f64) -> f64 {
    relaxation_rate(entrainment_speed, semi_minor) * (steady - film)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_film_relaxes_over_the_transit_time_and_stops_at_its_steady_value() {
        // 10 m/s over b = 0.1 mm: τ = 10 µs.
        let (u, b) = (10.0, 1e-4);
        assert_eq!(relaxation_rate(u, b), 1e5);
        assert_eq!(relaxation_rate(-u, b), 1e5);
        assert_eq!(film_rate(0.3e-6, 0.3e-6, u, b), 0.0);
        assert!((film_rate(0.3e-6, 0.1e-6, u, b) - 0.2e-6 * 1e5).abs() < 1e-18);
        // Integrated exactly over one τ from h = 0: 1 − 1/e of the way.
        let (steady, tau) = (0.3e-6, b / u);
        let mut h = 0.0;
        let n = 100_000;
        let dt = tau / n as f64;
        for _ in 0..n {
            // Midpoint rule.
            let half = h + 0.5 * dt * film_rate(steady, h, u, b);
            h += dt * film_rate(steady, half, u, b);
        }
        let exact = steady * (1.0 - (-1.0f64).exp());
        assert!((h - exact).abs() < 1e-9 * steady, "{h} vs {exact}");
        // No entrainment or no contact: the film does not move.
        assert_eq!(film_rate(0.3e-6, 0.1e-6, 0.0, b), 0.0);
        assert_eq!(film_rate(0.3e-6, 0.1e-6, u, 0.0), 0.0);
    }

    #[test]
    fn the_floor_load_is_the_floor_parameter_in_hamrock_dowson_units() {
        // E' = 2.29e11 Pa, R_x = 4 mm: Q_f = 1e-8 · 2.29e11 · 1.6e-5 N.
        let q = floor_load(2.29e11, 4e-3);
        assert!((q - 0.03664).abs() < 1e-12);
    }
}
