//! The mounting as `rolldyn check` reports it (docs/dynamics.md,
//! "Mounting"): masses, the outer ring's mode on its housing, the bearing's
//! radial stiffness, the radial chain's frequencies and the housing modes
//! the `[sensor]` sees.

use rolldyn_case::Case;
use serde::Serialize;
use std::fmt::Write;

/// The mounting of one bearing as `check` reports it (docs/dynamics.md,
/// "Mounting").
#[derive(Serialize)]
pub struct MountingReport {
    /// Inner ring with what turns with it \[kg\].
    pub inner_ring_mass_kg: f64,
    /// Outer ring with the housing's moving mass \[kg\] (null: fixed).
    pub outer_ring_mass_kg: Option<f64>,
    pub housing_stiffness_n_per_m: Option<f64>,
    pub housing_damping_n_s_per_m: Option<f64>,
    /// The outer ring on its housing alone: frequency \[Hz\], damping ratio.
    pub housing_mode_hz: Option<f64>,
    pub housing_damping_ratio: Option<f64>,
    /// The bearing's radial stiffness along the radial load (z without
    /// one) at the quasi-static solution \[N/m\] (null if it has none).
    pub bearing_radial_stiffness_n_per_m: Option<f64>,
    /// The inner ring on the bearing with a rigid housing \[Hz\].
    pub rotor_on_bearing_hz: Option<f64>,
    /// The bearing's damping between its rings (`model.bearing_damping`
    /// τ k_r) \[N·s/m\] (null without it).
    pub bearing_damping_n_s_per_m: Option<f64>,
    /// The damping ratio it gives the inner ring's mode on the bearing
    /// (null without it).
    pub rotor_on_bearing_damping_ratio: Option<f64>,
    /// The radial chain rotor–bearing–housing \[Hz\], lower first.
    pub chain_hz: Option<[f64; 2]>,
    /// Gravity on.
    pub gravity: bool,
    /// The inner ring's tilts held (`operating.fixed_tilt`: the shaft's
    /// other bearing holds them).
    pub inner_ring_tilt_held: bool,
    /// The housing's modes the `[sensor]` sees (empty without one).
    pub sensor_modes: Vec<SensorModeReport>,
}

/// One housing mode of the `[sensor]` (docs/signal.md, "Sensor chain").
#[derive(Serialize)]
pub struct SensorModeReport {
    /// Natural frequency \[Hz\].
    pub frequency_hz: f64,
    /// Damping ratio.
    pub damping_ratio: f64,
    /// Modal mass at the seat \[kg\].
    pub mass_kg: f64,
}

impl MountingReport {
    pub(crate) fn new(case: &Case) -> Option<Self> {
        if case.bearing_set().is_some() || case.shaft.is_some() {
            return None;
        }
        let p = case.dynamics_parameters().ok()?;
        let outer = p.outer_ring.as_ref();
        let housing = outer.map(|o| {
            rolldyn_case::mounting::oscillator(o.mass, o.housing.stiffness[2], o.housing.damping[2])
        });
        let bearing = case.radial_stiffness().ok();
        let m = p.inner_ring_mass;
        let bearing_damping = case
            .bearing_damping
            .filter(|&tau| tau > 0.0)
            .zip(bearing)
            .map(|(tau, k)| tau * k);
        Some(Self {
            inner_ring_mass_kg: m,
            outer_ring_mass_kg: outer.map(|o| o.mass),
            housing_stiffness_n_per_m: outer.map(|o| o.housing.stiffness[2]),
            housing_damping_n_s_per_m: outer.map(|o| o.housing.damping[2]),
            housing_mode_hz: housing.map(|h| h.0),
            housing_damping_ratio: housing.map(|h| h.1),
            bearing_radial_stiffness_n_per_m: bearing,
            rotor_on_bearing_hz: bearing.map(|k| rolldyn_case::mounting::oscillator(m, k, 0.0).0),
            bearing_damping_n_s_per_m: bearing_damping,
            rotor_on_bearing_damping_ratio: bearing
                .zip(bearing_damping)
                .map(|(k, c)| rolldyn_case::mounting::oscillator(m, k, c).1),
            chain_hz: bearing.zip(outer).map(|(k, o)| {
                rolldyn_case::mounting::chain_frequencies(m, k, o.mass, o.housing.stiffness[2])
            }),
            gravity: case.gravity,
            inner_ring_tilt_held: p.inner_ring_tilt_held,
            sensor_modes: case
                .sensor
                .iter()
                .flat_map(|s| &s.modes)
                .map(|m| SensorModeReport {
                    frequency_hz: m.frequency,
                    damping_ratio: m.damping_ratio,
                    mass_kg: m.mass,
                })
                .collect(),
        })
    }

    pub(crate) fn to_text(&self, out: &mut String) {
        let _ = writeln!(
            out,
            "\nMounting (docs/dynamics.md, \"Mounting\"; gravity {})",
            if self.gravity { "on" } else { "off" }
        );
        let _ = writeln!(
            out,
            "  inner ring with what turns with it  {:.3} kg, tilts {}",
            self.inner_ring_mass_kg,
            if self.inner_ring_tilt_held {
                "held (operating.fixed_tilt: the shaft's other bearing)"
            } else {
                "free"
            }
        );
        match (
            self.outer_ring_mass_kg,
            self.housing_stiffness_n_per_m,
            self.housing_damping_n_s_per_m,
        ) {
            (Some(m), Some(k), Some(c)) => {
                let _ = writeln!(
                    out,
                    "  outer ring in its housing           {m:.3} kg on {k:.3e} N/m, {c:.3e} N·s/m"
                );
            }
            _ => {
                let _ = writeln!(
                    out,
                    "  outer ring                          fixed (no [outer_ring] housing)"
                );
            }
        }
        if let Some(k) = self.bearing_radial_stiffness_n_per_m {
            let _ = writeln!(
                out,
                "  bearing radial stiffness            {k:.3e} N/m (quasi-static, along the radial load)"
            );
        }
        if let (Some(f), Some(z)) = (self.housing_mode_hz, self.housing_damping_ratio) {
            let _ = writeln!(
                out,
                "  housing mode                        {f:.1} Hz, damping ratio {z:.3}"
            );
        }
        if let Some(f) = self.rotor_on_bearing_hz {
            let _ = writeln!(
                out,
                "  inner ring on the bearing           {f:.1} Hz (rigid housing)"
            );
        }
        if let (Some(c), Some(z)) = (
            self.bearing_damping_n_s_per_m,
            self.rotor_on_bearing_damping_ratio,
        ) {
            let _ = writeln!(
                out,
                "  bearing damping between the rings   {c:.3e} N·s/m (model.bearing_damping), damping ratio {z:.3} of that mode"
            );
        }
        if let Some([lo, hi]) = self.chain_hz {
            let _ = writeln!(
                out,
                "  radial chain rotor–bearing–housing  {lo:.1} Hz, {hi:.1} Hz"
            );
        }
        for m in &self.sensor_modes {
            let _ = writeln!(
                out,
                "  housing mode at the sensor          {:.1} Hz, damping ratio {:.3}, {:.3} kg (one way: [sensor])",
                m.frequency_hz, m.damping_ratio, m.mass_kg
            );
        }
    }
}
