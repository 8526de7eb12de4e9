//! Cage-whirl metrics from the cage-centre orbit.
//!
//! * orbit radius: distance of the cage centre from its mean position (mean
//!   and maximum over the record);
//! * whirl speed: the mean rate of the orbit angle about the mean position
//!   (unwrapped angle, end minus start over the time span), also as a ratio
//!   to the cage speed (1: synchronous whirl);
//! * σ, the deviation ratio of the cage whirl speed (Deng et al. 2022 eq 41):
//!   σ = √(Σ(v − v̄)²/N) / v̄ with v = |(ẏ_c, ż_c)| the speed of the cage
//!   centre; small σ is a steady whirl, large σ an erratic one.

/// Whirl metrics of one record.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WhirlMetrics {
    /// Mean orbit radius \[m\].
    pub orbit_radius_mean: f64,
    /// Largest orbit radius \[m\].
    pub orbit_radius_max: f64,
    /// Mean whirl speed \[rad/s\] (positive: with the +x rotation).
    pub whirl_speed: f64,
    /// Deviation ratio σ of the cage-centre speed (Deng et al. 2022 eq 41) \[-\]
    /// (0 when the centre does not move).
    pub sigma: f64,
}

/// Metrics of the orbit (y, z) with velocities (v_y, v_z) sampled at times `t`.
pub fn whirl_metrics(t: &[f64], y: &[f64], z: &[f64], vy: &[f64], vz: &[f64]) -> WhirlMetrics {
    let n = t
        .len()
        .min(y.len())
        .min(z.len())
        .min(vy.len())
        .min(vz.len());
    if n < 2 {
        return WhirlMetrics::default();
    }
    let nf = n as f64;
    let (cy, cz) = (
        y[..n].iter().sum::<f64>() / nf,
        z[..n].iter().sum::<f64>() / nf,
    );
    let radii: Vec<f64> = (0..n).map(|k| (y[k] - cy).hypot(z[k] - cz)).collect();
    let mut angle = 0.0;
    let mut previous = (z[0] - cz).atan2(y[0] - cy);
    for k in 1..n {
        let a = (z[k] - cz).atan2(y[k] - cy);
        angle += crate::surface::spall::wrap(a - previous);
        previous = a;
    }
    let speeds: Vec<f64> = (0..n).map(|k| vy[k].hypot(vz[k])).collect();
    let mean_speed = speeds.iter().sum::<f64>() / nf;
    let deviation = (speeds.iter().map(|v| (v - mean_speed).powi(2)).sum::<f64>() / nf).sqrt();
    let span = t[n - 1] - t[0];
    WhirlMetrics {
        orbit_radius_mean: radii.iter().sum::<f64>() / nf,
        orbit_radius_max: radii.iter().copied().fold(0.0, f64::max),
        whirl_speed: if span > 0.0 { angle / span } else { 0.0 },
        sigma: if mean_speed > 0.0 {
            deviation / mean_speed
        } else {
            0.0
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    #[test]
    fn a_circular_orbit_has_its_radius_speed_and_zero_sigma() {
        // Ten whole turns in 0.2 s.
        let (r, w) = (2e-5, 50.0 * TAU);
        let t: Vec<f64> = (0..=2000).map(|k| k as f64 * 1e-4).collect();
        let y: Vec<f64> = t.iter().map(|t| 1e-6 + r * (w * t).cos()).collect();
        let z: Vec<f64> = t.iter().map(|t| r * (w * t).sin()).collect();
        let vy: Vec<f64> = t.iter().map(|t| -r * w * (w * t).sin()).collect();
        let vz: Vec<f64> = t.iter().map(|t| r * w * (w * t).cos()).collect();
        let m = whirl_metrics(&t, &y, &z, &vy, &vz);
        assert!(
            (m.orbit_radius_mean - r).abs() < 1e-3 * r,
            "{}",
            m.orbit_radius_mean
        );
        assert!((m.whirl_speed - w).abs() < 1e-6 * w, "{}", m.whirl_speed);
        assert!(m.sigma < 1e-12);
        // Backwards whirl has a negative speed.
        let z_back: Vec<f64> = z.iter().map(|v| -v).collect();
        assert!(whirl_metrics(&t, &y, &z_back, &vy, &vz).whirl_speed < 0.0);
    }

    #[test]
    fn an_erratic_speed_gives_a_positive_sigma() {
        let t = [0.0, 1.0, 2.0, 3.0];
        let zero = [0.0; 4];
        let m = whirl_metrics(&t, &zero, &zero, &[1.0, 3.0, 1.0, 3.0], &zero);
        assert!((m.sigma - 0.5).abs() < 1e-12);
        assert_eq!(whirl_metrics(&t, &zero, &zero, &zero, &zero).sigma, 0.0);
    }
}
