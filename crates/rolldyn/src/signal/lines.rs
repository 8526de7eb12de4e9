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
    /// The fastest rate at which a defect's impacts repeat \[Hz\]: the
    /// larger of BPFO, BPFI and 2 × BSF (a ball defect strikes both races
    /// once a spin).
    pub fn fastest_defect_rate(&self) -> f64 {
        self.bpfo.max(self.bpfi).max(2.0 * self.ball_spin)
    }

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

impl Line {
    /// The harmonic number k of a line named `k×…` (1 for a fundamental).
    pub fn order(&self) -> usize {
        self.name
            .split_once('×')
            .and_then(|(k, _)| k.parse().ok())
            .unwrap_or(1)
    }
}

impl CharacteristicFrequencies {
    /// The lines of [`Self::lines`] up to `max_frequency` \[Hz\], each
    /// family's harmonics as far as they reach (at most `limit` of the
    /// lowest line's): the lines a spectrum up to `max_frequency` can show.
    pub fn lines_up_to(&self, max_frequency: f64, limit: usize) -> Vec<Line> {
        let lowest = [self.shaft, self.cage, self.bpfo, self.bpfi, self.ball_spin]
            .into_iter()
            .filter(|f| *f > 0.0)
            .fold(f64::INFINITY, f64::min);
        if !(lowest.is_finite() && max_frequency > 0.0) {
            return Vec::new();
        }
        let harmonics = ((max_frequency / lowest).ceil() as usize).clamp(1, limit.max(1));
        let mut lines = self.lines(harmonics);
        lines.retain(|l| l.frequency <= max_frequency);
        lines
    }
}

/// The line family of a fault: what its envelope spectrum shows
/// (Randall & Antoni 2011): an outer-race fault BPFO and its harmonics
/// (with ±f_c sidebands), an inner-race fault BPFI (with ±f_i sidebands),
/// a ball fault 2×BSF (with ±f_c sidebands).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fault {
    /// A fault on the outer raceway.
    OuterRace,
    /// A fault on the inner raceway.
    InnerRace,
    /// A fault on a ball.
    Ball,
}

impl Fault {
    /// Whether `line` belongs to the fault's family.
    pub fn shows(self, line: &Line) -> bool {
        match self {
            Self::OuterRace => line.name.contains("BPFO"),
            Self::InnerRace => line.name.contains("BPFI"),
            Self::Ball => line.name.contains("BSF"),
        }
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
    /// The other lines within `tolerance`, nearest first: the spectrum
    /// cannot tell them from the named one.
    pub other_lines: Vec<String>,
}

/// The `count` largest local maxima of `spectrum` above `min_frequency`
/// (strictly greater than both neighbours), largest first, each named by a
/// line within `tolerance` \[Hz\] (none beyond it): of the lines there,
/// one of the `faults`' families first (the case's faults: a spectrum too
/// coarse to tell 6×BPFO from 4×BPFI names a peak of an outer-race fault
/// by BPFO), then harmonics before sidebands (a spectrum too coarse to
/// separate a sideband names the peak by its carrier), then the lower
/// harmonic (BPFO before 10×f_i: the simpler account of a peak the
/// spectrum cannot resolve), then the nearest. The others within
/// `tolerance` are the peak's `other_lines`.
pub fn find_peaks(
    spectrum: &Spectrum,
    min_frequency: f64,
    count: usize,
    lines: &[Line],
    tolerance: f64,
    faults: &[Fault],
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
            let distance = |l: &Line| (l.frequency - frequency).abs();
            let mut near: Vec<&Line> = lines.iter().filter(|l| distance(l) <= tolerance).collect();
            near.sort_by(|a, b| distance(a).total_cmp(&distance(b)));
            let off_fault = |l: &Line| !faults.iter().any(|f| f.shows(l));
            let named = near
                .iter()
                .min_by(|a, b| {
                    off_fault(a)
                        .cmp(&off_fault(b))
                        .then(a.sideband.cmp(&b.sideband))
                        .then(a.order().cmp(&b.order()))
                        .then(distance(a).total_cmp(&distance(b)))
                })
                .copied();
            Peak {
                frequency,
                value,
                line: named.map(|l| l.name.clone()),
                line_frequency: named.map(|l| l.frequency),
                other_lines: near
                    .iter()
                    .filter(|l| named.is_some_and(|n| n.name != l.name))
                    .map(|l| l.name.clone())
                    .collect(),
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
    fn the_fastest_defect_rate_is_the_largest_of_the_defect_lines() {
        // 7008C at 10 000 rpm: BPFI leads; two large balls: 2 × BSF.
        let fi = 10_000.0 / 60.0;
        let many = CharacteristicFrequencies::new(fi, 0.43 * fi, 22, 0.118, 0.3);
        assert_eq!(many.fastest_defect_rate(), many.bpfi);
        let few = CharacteristicFrequencies::new(fi, 0.3 * fi, 2, 0.4, 0.0);
        assert_eq!(few.fastest_defect_rate(), 2.0 * few.ball_spin);
        assert!(2.0 * few.ball_spin > few.bpfi.max(few.bpfo));
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
        let peaks = find_peaks(&spectrum, 1.0, 5, &lines, 1.0, &[]);
        assert_eq!(peaks.len(), 2);
        // The harmonic wins over the nearer sideband, which is shown.
        assert_eq!(peaks[0].line.as_deref(), Some("A"));
        assert_eq!(peaks[0].other_lines, ["A+f"]);
        assert_eq!(peaks[1].frequency, 53.0);
        assert_eq!(peaks[1].line, None);
    }

    /// The issue's case: a peak at 645 Hz of an outer-race fault between
    /// 6×BPFO (645.0 Hz) and 4×BPFI (648.2 Hz), in 4 Hz bins: named by
    /// the fault's family, the other line shown; without a fault, by the
    /// nearest.
    #[test]
    fn a_fault_names_its_peaks_and_the_band_bounds_the_lines() {
        let spectrum = Spectrum {
            frequency: (0..400).map(|k| 4.0 * k as f64).collect(),
            value: (0..400).map(|k| if k == 162 { 5.0 } else { 0.1 }).collect(),
        };
        let line = |name: &str, frequency: f64| Line {
            name: name.into(),
            frequency,
            sideband: false,
        };
        let lines = [line("6×BPFO", 645.0), line("4×BPFI", 648.2)];
        let peak = |faults: &[Fault]| find_peaks(&spectrum, 4.0, 1, &lines, 6.0, faults).remove(0);
        assert_eq!(peak(&[]).line.as_deref(), Some("4×BPFI"));
        let outer = peak(&[Fault::OuterRace]);
        assert_eq!(outer.line.as_deref(), Some("6×BPFO"));
        assert_eq!(outer.other_lines, ["4×BPFI"]);
        assert_eq!(peak(&[Fault::InnerRace]).line.as_deref(), Some("4×BPFI"));
        // The lower harmonic names a peak the bins cannot resolve.
        let lines = [line("10×f_i", 648.5), line("BPFO", 646.0)];
        let unresolved = find_peaks(&spectrum, 4.0, 1, &lines, 6.0, &[]).remove(0);
        assert_eq!(unresolved.line.as_deref(), Some("BPFO"));
        assert_eq!(unresolved.other_lines, ["10×f_i"]);
        // Lines up to a band: every family as far as it reaches, no
        // further, whatever the limit asked.
        let f = CharacteristicFrequencies::new(30.0, 12.0, 9, 0.2, 0.0);
        let up_to = f.lines_up_to(1000.0, 1_000_000);
        assert!(up_to.iter().all(|l| l.frequency <= 1000.0));
        assert!(
            up_to.iter().any(|l| l.name == "83×f_c"),
            "f_c's 83rd harmonic (996 Hz)"
        );
        assert!(
            up_to
                .iter()
                .any(|l| l.name.ends_with("×BPFO") && l.frequency > 900.0)
        );
    }
}
