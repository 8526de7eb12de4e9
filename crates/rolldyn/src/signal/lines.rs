//! Characteristic frequencies of a ball bearing with harmonics and
//! sidebands, and a peak list that names the nearest line.
//!
//! From the shaft frequency f_i and the cage frequency f_c (the run's
//! measured mean, so cage slip moves the lines as it does on a test rig),
//! with the outer ring fixed (Deng et al. 2022 Table 2, docs/model.md §7; Harris &
//! Kotzalas, Essential Concepts of Bearing Technology, ch. 8):
//!
//! ```text
//! BPFO = Z f_c,   BPFI = Z (f_i − f_c),
//! BSF  = (d_m/D)(1 − γ cos α)(f_i − f_c)      (ball spin relative to the cage;
//!        = (d_m/2D) f_i (1 − γ² cos² α) at pure rolling)
//! ```
//! Lines: harmonics k = 1…H of f_i, f_c, BPFO, BPFI, BSF and 2×BSF; BPFI
//! harmonics with ±f_i sidebands (inner-race defect under radial load);
//! 2×BSF harmonics and BPFO harmonics with ±f_c sidebands.

use super::Spectrum;

/// One characteristic line.
#[derive(Debug, Clone, PartialEq)]
pub struct Line {
    /// Name, e.g. "BPFO", "3×BPFI", "BPFI+f_i", "2×BSF−f_c".
    pub name: String,
    /// Frequency \[Hz\].
    pub frequency: f64,
    /// Whether it is a sideband (a peak near both a harmonic and a
    /// sideband is named by the harmonic).
    pub sideband: bool,
}

/// Fundamental characteristic frequencies \[Hz\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CharacteristicFrequencies {
    /// Shaft (inner-ring) rotation f_i.
    pub shaft: f64,
    /// Cage rotation f_c.
    pub cage: f64,
    /// Ball pass frequency, outer race.
    pub bpfo: f64,
    /// Ball pass frequency, inner race.
    pub bpfi: f64,
    /// Ball spin frequency (relative to the cage).
    pub ball_spin: f64,
}

impl CharacteristicFrequencies {
    /// From f_i, f_c \[Hz\], the ball count Z, D/d_m (γ₀) and the contact angle α.
    pub fn new(
        shaft: f64,
        cage: f64,
        balls: usize,
        diameter_ratio: f64,
        contact_angle: f64,
    ) -> Self {
        let z = balls as f64;
        let relative = shaft - cage;
        Self {
            shaft,
            cage,
            bpfo: z * cage,
            bpfi: z * relative,
            ball_spin: (1.0 - diameter_ratio * contact_angle.cos()) * relative / diameter_ratio,
        }
    }

    /// Harmonics 1…`harmonics` and the sidebands of the module doc, sorted by
    /// frequency; lines at or below 0 Hz are left out.
    pub fn lines(&self, harmonics: usize) -> Vec<Line> {
        let mut out = Vec::new();
        let mut push = |name: String, frequency: f64| {
            if frequency > 0.0 {
                let sideband = name.contains('+') || name.contains('−');
                out.push(Line {
                    name,
                    frequency,
                    sideband,
                });
            }
        };
        let named = |k: usize, base: &str| {
            if k == 1 {
                base.to_string()
            } else {
                format!("{k}×{base}")
            }
        };
        for k in 1..=harmonics {
            let kf = k as f64;
            push(named(k, "f_i"), kf * self.shaft);
            push(named(k, "f_c"), kf * self.cage);
            push(named(k, "BPFO"), kf * self.bpfo);
            push(named(k, "BPFI"), kf * self.bpfi);
            push(named(k, "BSF"), kf * self.ball_spin);
            push(named(2 * k, "BSF"), 2.0 * kf * self.ball_spin);
            for (sign, s) in [(1.0, '+'), (-1.0, '−')] {
                push(
                    format!("{}{s}f_i", named(k, "BPFI")),
                    kf * self.bpfi + sign * self.shaft,
                );
                push(
                    format!("{}{s}f_c", named(2 * k, "BSF")),
                    2.0 * kf * self.ball_spin + sign * self.cage,
                );
                push(
                    format!("{}{s}f_c", named(k, "BPFO")),
                    kf * self.bpfo + sign * self.cage,
                );
            }
        }
        // Even BSF harmonics appear twice (k×BSF and 2k×BSF): keep one.
        out.sort_by(|a, b| {
            a.frequency
                .total_cmp(&b.frequency)
                .then(a.name.cmp(&b.name))
        });
        out.dedup_by(|a, b| a.name == b.name);
        out
    }
}

/// A spectral peak with the nearest characteristic line.
#[derive(Debug, Clone, PartialEq)]
pub struct Peak {
    /// Frequency \[Hz\].
    pub frequency: f64,
    /// Value at the peak.
    pub value: f64,
    /// Nearest line's name, if any line lies within `tolerance`.
    pub line: Option<String>,
    /// That line's frequency \[Hz\].
    pub line_frequency: Option<f64>,
}

/// The `count` largest local maxima of `spectrum` above `min_frequency`
/// (strictly greater than both neighbours), largest first, each named by the
/// nearest line within `tolerance` \[Hz\] (none beyond it); harmonics
/// before sidebands, so that a spectrum too coarse to separate a sideband
/// names the peak by its carrier.
pub fn find_peaks(
    spectrum: &Spectrum,
    min_frequency: f64,
    count: usize,
    lines: &[Line],
    tolerance: f64,
) -> Vec<Peak> {
    let v = &spectrum.value;
    let mut peaks: Vec<(usize, f64)> = (1..v.len().saturating_sub(1))
        .filter(|&k| spectrum.frequency[k] >= min_frequency && v[k] > v[k - 1] && v[k] > v[k + 1])
        .map(|k| (k, v[k]))
        .collect();
    peaks.sort_by(|a, b| b.1.total_cmp(&a.1).then(a.0.cmp(&b.0)));
    peaks.truncate(count);
    peaks
        .into_iter()
        .map(|(k, value)| {
            let frequency = spectrum.frequency[k];
            let nearest = lines
                .iter()
                .filter(|l| (l.frequency - frequency).abs() <= tolerance)
                .min_by(|a, b| {
                    a.sideband.cmp(&b.sideband).then(
                        (a.frequency - frequency)
                            .abs()
                            .total_cmp(&(b.frequency - frequency).abs()),
                    )
                });
            Peak {
                frequency,
                value,
                line: nearest.map(|l| l.name.clone()),
                line_frequency: nearest.map(|l| l.frequency),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::Frequencies;

    #[test]
    fn pure_rolling_lines_match_the_kinematics() {
        // 7008C at 10 000 rpm (docs/model.md §7: f_b ≈ 699.7 Hz).
        let (d, dm, z, alpha) = (6.35e-3, 54e-3, 22, 17.7f64.to_radians());
        let gamma = d / dm;
        let fi = 10_000.0 / 60.0;
        let fc = 0.5 * fi * (1.0 - gamma * alpha.cos());
        let f = CharacteristicFrequencies::new(fi, fc, z, gamma, alpha);
        let reference = Frequencies::new(d, dm, z, alpha, fi, 0.0);
        assert!((f.ball_spin - 699.7).abs() < 0.1, "{}", f.ball_spin);
        assert!((f.bpfo - reference.bpfo_hz).abs() < 1e-9 * f.bpfo);
        assert!((f.bpfi - reference.bpfi_hz).abs() < 1e-9 * f.bpfi);
        assert!((f.ball_spin - reference.ball_spin_hz).abs() < 1e-9 * f.ball_spin);
        let lines = f.lines(3);
        let names: Vec<&str> = lines.iter().map(|l| l.name.as_str()).collect();
        for expected in [
            "BPFO",
            "3×BPFI",
            "BPFI+f_i",
            "2×BSF−f_c",
            "6×BSF",
            "BPFO+f_c",
        ] {
            assert!(names.contains(&expected), "{expected} missing");
        }
        assert!(lines.windows(2).all(|w| w[0].frequency <= w[1].frequency));
    }

    #[test]
    fn peaks_are_named_by_the_nearest_line_within_the_tolerance() {
        let spectrum = Spectrum {
            frequency: (0..100).map(|k| k as f64).collect(),
            value: (0..100)
                .map(|k| match k {
                    20 => 5.0,
                    53 => 3.0,
                    _ => 0.1,
                })
                .collect(),
        };
        let lines = vec![
            Line {
                name: "A+f".into(),
                frequency: 20.1,
                sideband: true,
            },
            Line {
                name: "A".into(),
                frequency: 20.4,
                sideband: false,
            },
            Line {
                name: "B".into(),
                frequency: 60.0,
                sideband: false,
            },
        ];
        let peaks = find_peaks(&spectrum, 1.0, 5, &lines, 1.0);
        assert_eq!(peaks.len(), 2);
        // The harmonic wins over the nearer sideband.
        assert_eq!(peaks[0].line.as_deref(), Some("A"));
        assert_eq!(peaks[1].frequency, 53.0);
        assert_eq!(peaks[1].line, None);
    }
}
