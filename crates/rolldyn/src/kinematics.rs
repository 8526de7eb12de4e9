//! Pure-rolling kinematics and characteristic frequencies (docs/model.md §7, end).
//!
//! # Cage speed with different contact angles
//! With outer ring fixed, inner contact angle α_i, outer α_o, ball attitude
//! angle β and γ = D/d_m (Zhang et al. 2025 eq 26, printed garbled; Harris &
//! Kotzalas, *Advanced Concepts of Bearing Technology*, eq. 2.39 form):
//! ```text
//! ω_c/ω_i = 1 / (1 + (1 + γ cos α_o)(cos α_i + tan β sin α_i)
//!                   / ((1 − γ cos α_i)(cos α_o + tan β sin α_o)))
//! ```
//! which is ½(1 − γ cos α) when α_i = α_o = β = α (validation A8).
//!
//! # Defect frequencies (Deng et al. 2022 Table 2 notation; Harris & Kotzalas ch. 8)
//! With shaft (inner-ring) frequency f_i, outer-ring frequency f_o (usually
//! 0) and γ = D cos α / d_m:
//! ```text
//! f_c  = ½ [f_i (1 − γ) + f_o (1 + γ)]          cage (FTF)
//! BPFO = Z |f_c − f_o|,   BPFI = Z |f_i − f_c|
//! f_b  = (d_m / 2D) |f_i − f_o| (1 − γ²)        ball spin (BSF, relative to the cage)
//! ```
//! 7008C at 10 000 rpm: f_c ≈ 73.96 Hz, f_b ≈ 699.7 Hz (Deng et al. 2022 Table 3).
//!
//! # Waviness excitation (Deng et al. 2022 Table 2)
//! [`waviness_frequencies`] maps a waviness order l on the outer race, the
//! inner race or a ball to its principal vibration frequencies.

use serde::Serialize;

/// Cage-to-inner-ring speed ratio ω_c/ω_i for pure rolling with the outer
/// ring fixed, for γ = D/d_m (not multiplied by cos α), contact angles α_i,
/// α_o and attitude angle β (all in rad).
pub fn cage_speed_ratio(d_over_dm: f64, inner_angle: f64, outer_angle: f64, attitude: f64) -> f64 {
    let g = d_over_dm;
    let tb = attitude.tan();
    let num = (1.0 + g * outer_angle.cos()) * (inner_angle.cos() + tb * inner_angle.sin());
    let den = (1.0 - g * inner_angle.cos()) * (outer_angle.cos() + tb * outer_angle.sin());
    1.0 / (1.0 + num / den)
}

/// Characteristic frequencies of a bearing at one speed and contact angle.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Frequencies {
    /// Inner-ring (shaft) rotation frequency f_i \[Hz\].
    pub shaft_hz: f64,
    /// Outer-ring rotation frequency f_o \[Hz\].
    pub outer_ring_hz: f64,
    /// Contact angle used \[deg\].
    pub contact_angle_deg: f64,
    /// Cage (fundamental train) frequency f_c \[Hz\].
    pub cage_hz: f64,
    /// Ball pass frequency, outer race \[Hz\].
    pub bpfo_hz: f64,
    /// Ball pass frequency, inner race \[Hz\].
    pub bpfi_hz: f64,
    /// Ball spin frequency relative to the cage f_b \[Hz\] (twice this is
    /// the ball-defect frequency that some tables, e.g. CWRU's, call BSF).
    pub ball_spin_hz: f64,
    /// Number of balls Z.
    pub ball_count: usize,
}

impl Frequencies {
    /// Frequencies for `ball_count` balls of diameter D on pitch diameter
    /// d_m at contact angle α \[rad\], inner ring at `shaft_hz`, outer ring at
    /// `outer_ring_hz`.
    pub fn new(
        ball_diameter: f64,
        pitch_diameter: f64,
        ball_count: usize,
        contact_angle: f64,
        shaft_hz: f64,
        outer_ring_hz: f64,
    ) -> Self {
        let gamma = ball_diameter * contact_angle.cos() / pitch_diameter;
        let z = ball_count as f64;
        let cage_hz = 0.5 * (shaft_hz * (1.0 - gamma) + outer_ring_hz * (1.0 + gamma));
        Self {
            shaft_hz,
            outer_ring_hz,
            contact_angle_deg: contact_angle.to_degrees(),
            cage_hz,
            bpfo_hz: z * (cage_hz - outer_ring_hz).abs(),
            bpfi_hz: z * (shaft_hz - cage_hz).abs(),
            ball_spin_hz: pitch_diameter / (2.0 * ball_diameter)
                * (shaft_hz - outer_ring_hz).abs()
                * (1.0 - gamma * gamma),
            ball_count,
        }
    }

    /// Orders: each frequency divided by the shaft frequency (speed-independent).
    pub fn orders(&self) -> Orders {
        let f = self.shaft_hz;
        Orders {
            cage: self.cage_hz / f,
            bpfo: self.bpfo_hz / f,
            bpfi: self.bpfi_hz / f,
            ball_spin: self.ball_spin_hz / f,
        }
    }
}

/// Characteristic frequencies as multiples of the shaft frequency.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Orders {
    /// f_c / f_i.
    pub cage: f64,
    /// BPFO / f_i.
    pub bpfo: f64,
    /// BPFI / f_i.
    pub bpfi: f64,
    /// f_b / f_i.
    pub ball_spin: f64,
}

/// Where a waviness lies.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum WavyPart {
    /// Outer raceway.
    OuterRace,
    /// Inner raceway.
    InnerRace,
    /// A ball.
    Ball,
}

/// Direction of the vibration a waviness line excites.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Motion {
    /// Along the bearing axis.
    Axial,
    /// In the radial plane.
    Radial,
}

/// One principal vibration frequency excited by a waviness order.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct WavinessLine {
    /// Frequency \[Hz\].
    pub frequency_hz: f64,
    /// Axial or radial vibration.
    pub motion: Motion,
    /// The harmonic k of the Table 2 rule that produced the line.
    pub harmonic: u32,
}

/// Principal vibration frequencies excited by waviness of order l on `part`
/// (Deng et al. 2022 Table 2, after Yhland 1992 and Wardle 1988):
///
/// | part | order | frequency | motion |
/// |---|---|---|---|
/// | outer race | l = kZ | kZ f_c | axial |
/// | outer race | l = kZ ± 1 | kZ f_c | radial |
/// | inner race | l = kZ | kZ (f_i − f_c) | axial |
/// | inner race | l = kZ ± 1 | kZ (f_i − f_c) ± f_i | radial |
/// | ball | l = 2k | 2k f_b | axial |
/// | ball | l = 2k | 2k f_b ± f_c | radial |
///
/// Orders that fit no rule excite no principal line (empty result). Written
/// for an inner ring rotating in a fixed outer ring (f_o = 0).
pub fn waviness_frequencies(freqs: &Frequencies, part: WavyPart, order: u32) -> Vec<WavinessLine> {
    let z = freqs.ball_count as u32;
    let line = |frequency_hz: f64, motion: Motion, harmonic: u32| WavinessLine {
        frequency_hz,
        motion,
        harmonic,
    };
    let mut lines = Vec::new();
    match part {
        WavyPart::OuterRace | WavyPart::InnerRace => {
            let base = match part {
                WavyPart::OuterRace => freqs.cage_hz,
                _ => freqs.shaft_hz - freqs.cage_hz,
            };
            if order > 0 && order % z == 0 {
                let k = order / z;
                lines.push(line((k * z) as f64 * base, Motion::Axial, k));
            }
            for (kz, sign) in [(order + 1, -1.0), (order.wrapping_sub(1), 1.0)] {
                if order >= 1 && kz > 0 && kz % z == 0 {
                    let k = kz / z;
                    let f = match part {
                        WavyPart::OuterRace => kz as f64 * base,
                        // l = kZ − 1 → − f_i ; l = kZ + 1 → + f_i
                        _ => kz as f64 * base + sign * freqs.shaft_hz,
                    };
                    lines.push(line(f, Motion::Radial, k));
                }
            }
        }
        WavyPart::Ball => {
            if order > 0 && order % 2 == 0 {
                let k = order / 2;
                let f = order as f64 * freqs.ball_spin_hz;
                lines.push(line(f, Motion::Axial, k));
                lines.push(line(f - freqs.cage_hz, Motion::Radial, k));
                lines.push(line(f + freqs.cage_hz, Motion::Radial, k));
            }
        }
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn outer_ring_rotation_is_symmetric() {
        // Swapping which ring turns leaves the relative frequencies unchanged
        // in magnitude: BPFO with the outer ring turning equals the classical
        // BPFI form with γ → −γ.
        let f = Frequencies::new(8e-3, 60e-3, 18, 0.0, 0.0, 100.0);
        assert!((f.cage_hz - 50.0 * (1.0 + 8.0 / 60.0)).abs() < 1e-12);
        assert!((f.bpfo_hz - 18.0 * (100.0 - f.cage_hz)).abs() < 1e-9);
    }

    #[test]
    fn unrelated_orders_excite_nothing() {
        let f = Frequencies::new(6.35e-3, 54e-3, 22, 0.3, 166.0, 0.0);
        assert!(waviness_frequencies(&f, WavyPart::OuterRace, 10).is_empty());
        assert!(waviness_frequencies(&f, WavyPart::Ball, 3).is_empty());
        assert!(waviness_frequencies(&f, WavyPart::InnerRace, 0).is_empty());
    }
}
