//! The condition indicators of a vibration record: RMS, peak, crest factor
//! and kurtosis about the record's mean (Randall 2011, "Vibration-based
//! condition monitoring": kurtosis 3 for a Gaussian record; impacts
//! raise it and the crest factor).

/// RMS, peak |a|, crest factor (peak / RMS) and kurtosis (m₄ / m₂², 3 for
/// a Gaussian record; impacts raise it) of `record` about its mean.
pub fn statistics(record: &[f64]) -> [f64; 4] {
    let n = record.len() as f64;
    let mean = record.iter().sum::<f64>() / n;
    let (mut m2, mut m4, mut peak) = (0.0, 0.0, 0.0f64);
    for &x in record {
        let d = x - mean;
        m2 += d * d;
        m4 += d * d * d * d;
        peak = peak.max(d.abs());
    }
    let (m2, m4) = (m2 / n, m4 / n);
    let rms = m2.sqrt();
    [rms, peak, peak / rms, m4 / (m2 * m2)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn statistics_of_a_sine_and_of_impacts() {
        let sine: Vec<f64> = (0..10_000)
            .map(|k| (std::f64::consts::TAU * k as f64 / 100.0).sin())
            .collect();
        let [rms, peak, crest, kurtosis] = statistics(&sine);
        assert!((rms - 0.5f64.sqrt()).abs() < 1e-9);
        assert!((peak - 1.0).abs() < 1e-9);
        assert!((crest - 2.0f64.sqrt()).abs() < 1e-9);
        // A sine's kurtosis is 1.5; sparse impacts raise it far above 3.
        assert!((kurtosis - 1.5).abs() < 1e-6);
        let impacts: Vec<f64> = (0..10_000)
            .map(|k| if k % 1000 == 0 { 10.0 } else { 0.0 })
            .collect();
        assert!(statistics(&impacts)[3] > 100.0);
    }
}
