//! Reports of the CLI: derived quantities of a case as a stable JSON object
//! (snake_case keys that carry their SI unit) and as aligned text in
//! engineering units. The JSON keys are documented in docs/cli.md.

use rolldyn::contact::table::RacewayContactModel;
use rolldyn::contact::{Curvature, HertzCoefficients};
use rolldyn::geometry::{Clearance, RingKind};
use rolldyn::kinematics::{Frequencies, WavyPart, waviness_frequencies};
use rolldyn::material::effective_modulus;
use rolldyn_case::Case;
use rolldyn_case::presets::Preset;
use serde::Serialize;
use std::f64::consts::PI;
use std::fmt::Write;

const RPM: f64 = 60.0 / (2.0 * PI);

/// One preset in `rolldyn presets --json`.
#[derive(Serialize)]
pub struct PresetEntry {
    pub name: &'static str,
    pub summary: &'static str,
}

impl From<&Preset> for PresetEntry {
    fn from(p: &Preset) -> Self {
        Self {
            name: p.name,
            summary: p.summary,
        }
    }
}

/// Hertz data of one raceway at one contact angle (and optionally a load).
#[derive(Serialize)]
pub struct RacewayContact {
    pub contact_angle_deg: f64,
    pub curvature_sum_per_m: f64,
    pub curvature_difference: f64,
    pub rolling_radius_m: f64,
    pub transverse_radius_m: f64,
    pub ellipticity: f64,
    pub elliptic_k: f64,
    pub elliptic_e: f64,
    pub stiffness_n_per_m1_5: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_n: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub semi_major_m: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub semi_minor_m: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_pressure_pa: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub approach_m: Option<f64>,
    /// Film at the contact (`contact --entrainment-speed`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub film: Option<crate::quasistatic_films::ContactFilmRow>,
    /// Hertz contact and film in series \[N/m\] (`contact --entrainment-speed`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub series_stiffness_n_per_m: Option<f64>,
}

fn raceway_contact(
    case: &Case,
    ring: RingKind,
    angle: f64,
    load: Option<f64>,
) -> Result<RacewayContact, String> {
    let g = &case.bearing.geometry;
    let ep = effective_modulus(
        &case.materials.ball.material,
        &case.materials.rings.material,
    );
    let model = RacewayContactModel::new(g, ring, ep, case.contact_stiffness);
    let curvature: Curvature = model.curvature(angle);
    let h: HertzCoefficients = model
        .coefficients(angle)
        .map_err(|e| format!("{} raceway contact: {e}", ring.name()))?;
    let at = load.map(|q| h.at_load(q));
    Ok(RacewayContact {
        contact_angle_deg: angle.to_degrees(),
        curvature_sum_per_m: curvature.sum(),
        curvature_difference: curvature.difference(),
        rolling_radius_m: curvature.rolling_radius,
        transverse_radius_m: curvature.transverse_radius,
        ellipticity: h.ellipticity,
        elliptic_k: h.elliptic_k,
        elliptic_e: h.elliptic_e,
        stiffness_n_per_m1_5: h.stiffness,
        load_n: load,
        semi_major_m: at.map(|r| r.semi_major),
        semi_minor_m: at.map(|r| r.semi_minor),
        max_pressure_pa: at.map(|r| r.max_pressure),
        approach_m: at.map(|r| r.approach),
        film: None,
        series_stiffness_n_per_m: None,
    })
}

fn raceway_text(out: &mut String, ring: &str, c: &RacewayContact) {
    let _ = writeln!(out, "  {ring} raceway (α = {:.3}°)", c.contact_angle_deg);
    let _ = writeln!(
        out,
        "    curvature sum Σρ      {:>12.4} 1/m     F(ρ) = {:.6}",
        c.curvature_sum_per_m, c.curvature_difference
    );
    let _ = writeln!(
        out,
        "    R_x, R_y              {:>12.4} mm, {:.4} mm",
        c.rolling_radius_m * 1e3,
        c.transverse_radius_m * 1e3
    );
    let _ = writeln!(
        out,
        "    ellipticity κ = a/b   {:>12.6}        K(m) = {:.6}, E(m) = {:.6}",
        c.ellipticity, c.elliptic_k, c.elliptic_e
    );
    let _ = writeln!(
        out,
        "    stiffness K_c         {:>12.6e} N/m^1.5",
        c.stiffness_n_per_m1_5
    );
    if let (Some(q), Some(a), Some(b), Some(p), Some(d)) = (
        c.load_n,
        c.semi_major_m,
        c.semi_minor_m,
        c.max_pressure_pa,
        c.approach_m,
    ) {
        let _ = writeln!(out, "    load Q                {q:>12.3} N");
        let _ = writeln!(
            out,
            "    semi-axes a, b        {:>12.4} mm, {:.4} mm",
            a * 1e3,
            b * 1e3
        );
        let _ = writeln!(out, "    max pressure p₀       {:>12.1} MPa", p * 1e-6);
        let _ = writeln!(out, "    approach δ            {:>12.3} µm", d * 1e6);
    }
    if let Some(f) = &c.film {
        let mut film = String::new();
        f.text(&mut film);
        for line in film.lines() {
            let _ = writeln!(out, "  {line}");
        }
        if let Some(k) = c.series_stiffness_n_per_m {
            let _ = writeln!(out, "    contact and film in series {k:.4e} N/m");
        }
    }
}

/// `rolldyn contact` output.
#[derive(Serialize)]
pub struct ContactReport {
    pub load_n: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub entrainment_speed_m_s: Option<f64>,
    pub contact_stiffness_model: &'static str,
    pub effective_modulus_pa: f64,
    pub inner: RacewayContact,
    pub outer: RacewayContact,
}

impl ContactReport {
    pub fn new(case: &Case, load: f64, angle: Option<f64>) -> Result<Self, String> {
        let angle = angle.unwrap_or_else(|| case.bearing.geometry.nominal_contact_angle());
        Ok(Self {
            load_n: load,
            entrainment_speed_m_s: None,
            contact_stiffness_model: case.contact_stiffness.name(),
            effective_modulus_pa: effective_modulus(
                &case.materials.ball.material,
                &case.materials.rings.material,
            ),
            inner: raceway_contact(case, RingKind::Inner, angle, Some(load))?,
            outer: raceway_contact(case, RingKind::Outer, angle, Some(load))?,
        })
    }

    pub fn to_text(&self) -> String {
        let mut out = format!(
            "Hertz contact ({} model, E' = {:.2} GPa)\n",
            self.contact_stiffness_model,
            self.effective_modulus_pa * 1e-9
        );
        raceway_text(&mut out, "inner", &self.inner);
        raceway_text(&mut out, "outer", &self.outer);
        out
    }
}

/// One waviness excitation line (Deng et al. 2022 Table 2).
#[derive(Serialize)]
pub struct WavinessEntry {
    pub part: WavyPart,
    pub order: u32,
    pub frequency_hz: f64,
    pub motion: rolldyn::kinematics::Motion,
}

/// `rolldyn frequencies` output.
/// Orders (frequency / f_i); None where undefined (0 rpm: JSON null).
#[derive(Serialize)]
pub struct OrderReport {
    pub cage: Option<f64>,
    pub bpfo: Option<f64>,
    pub bpfi: Option<f64>,
    pub ball_spin: Option<f64>,
}

impl From<rolldyn::kinematics::Orders> for OrderReport {
    fn from(o: rolldyn::kinematics::Orders) -> Self {
        let defined = |v: f64| v.is_finite().then_some(v);
        Self {
            cage: defined(o.cage),
            bpfo: defined(o.bpfo),
            bpfi: defined(o.bpfi),
            ball_spin: defined(o.ball_spin),
        }
    }
}

#[derive(Serialize)]
pub struct FrequencyReport {
    pub speed_rpm: f64,
    pub contact_angle_deg: f64,
    pub shaft_hz: f64,
    pub cage_hz: f64,
    pub cage_speed_rpm: f64,
    pub bpfo_hz: f64,
    pub bpfi_hz: f64,
    pub ball_spin_hz: f64,
    pub ball_defect_hz: f64,
    pub orders: OrderReport,
    pub waviness: Vec<WavinessEntry>,
    #[serde(skip)]
    from_profile: bool,
}

impl FrequencyReport {
    pub fn new(case: &Case, angle: Option<f64>) -> Result<Self, String> {
        let speed = case
            .speed
            .as_ref()
            .ok_or("the case gives no speed: set operating.speed or pass --speed, e.g. --speed \"10000 rpm\"")?;
        let from_profile = matches!(speed, rolldyn::operating::SpeedProfile::PiecewiseLinear(_));
        let omega = speed.final_speed();
        let g = &case.bearing.geometry;
        let alpha = angle.unwrap_or_else(|| g.nominal_contact_angle());
        let f = Frequencies::new(
            g.ball_diameter,
            g.pitch_diameter,
            g.ball_count,
            alpha,
            omega / (2.0 * PI),
            0.0,
        );
        let z = g.ball_count as u32;
        let mut waviness = Vec::new();
        for part in [WavyPart::OuterRace, WavyPart::InnerRace] {
            for order in [z - 1, z, z + 1, 2 * z - 1, 2 * z, 2 * z + 1] {
                for line in waviness_frequencies(&f, part, order) {
                    waviness.push(WavinessEntry {
                        part,
                        order,
                        frequency_hz: line.frequency_hz,
                        motion: line.motion,
                    });
                }
            }
        }
        for order in [2, 4] {
            for line in waviness_frequencies(&f, WavyPart::Ball, order) {
                waviness.push(WavinessEntry {
                    part: WavyPart::Ball,
                    order,
                    frequency_hz: line.frequency_hz,
                    motion: line.motion,
                });
            }
        }
        Ok(Self {
            speed_rpm: omega * RPM,
            contact_angle_deg: alpha.to_degrees(),
            shaft_hz: f.shaft_hz,
            cage_hz: f.cage_hz,
            cage_speed_rpm: f.cage_hz * 60.0,
            bpfo_hz: f.bpfo_hz,
            bpfi_hz: f.bpfi_hz,
            ball_spin_hz: f.ball_spin_hz,
            ball_defect_hz: 2.0 * f.ball_spin_hz,
            orders: OrderReport::from(f.orders()),
            waviness,
            from_profile,
        })
    }

    /// The lines as the spectra name them.
    pub fn lines(&self) -> rolldyn::signal::CharacteristicFrequencies {
        rolldyn::signal::CharacteristicFrequencies {
            shaft: self.shaft_hz,
            cage: self.cage_hz,
            bpfo: self.bpfo_hz,
            bpfi: self.bpfi_hz,
            ball_spin: self.ball_spin_hz,
        }
    }

    pub fn to_text(&self) -> String {
        let mut out = String::new();
        let note = if self.from_profile {
            " (final speed of the profile)"
        } else {
            ""
        };
        let _ = writeln!(
            out,
            "Pure-rolling frequencies at {:.1} rpm{note}, contact angle {:.2}°",
            self.speed_rpm, self.contact_angle_deg
        );
        let o = &self.orders;
        let rows = [
            ("shaft f_i", self.shaft_hz, Some(1.0)),
            ("cage f_c (FTF)", self.cage_hz, o.cage),
            ("BPFO", self.bpfo_hz, o.bpfo),
            ("BPFI", self.bpfi_hz, o.bpfi),
            ("ball spin f_b (BSF)", self.ball_spin_hz, o.ball_spin),
            (
                "ball defect 2 f_b",
                self.ball_defect_hz,
                o.ball_spin.map(|b| 2.0 * b),
            ),
        ];
        let _ = writeln!(out, "  {:<22} {:>12} {:>10}", "", "Hz", "order");
        for (name, hz, order) in rows {
            // An order is undefined at 0 rpm: "—" here, null in JSON.
            let order = order.map_or_else(|| "—".to_string(), |o| format!("{o:.5}"));
            let _ = writeln!(out, "  {name:<22} {hz:>12.3} {order:>10}");
        }
        let _ = writeln!(
            out,
            "  cage speed             {:>12.1} rpm",
            self.cage_speed_rpm
        );
        let _ = writeln!(out, "Waviness excitation (Deng et al. 2022 Table 2):");
        for w in &self.waviness {
            let part = match w.part {
                WavyPart::OuterRace => "outer race",
                WavyPart::InnerRace => "inner race",
                WavyPart::Ball => "ball",
            };
            let _ = writeln!(
                out,
                "  {part:<10} order {:>3}  {:>10.1} Hz  {:?}",
                w.order, w.frequency_hz, w.motion
            );
        }
        out
    }
}

/// Derived geometry in `rolldyn check`.
#[derive(Serialize)]
pub struct GeometryReport {
    pub parametrization: &'static str,
    pub ball_diameter_m: f64,
    pub ball_count: usize,
    pub pitch_diameter_m: f64,
    pub inner_groove_curvature: f64,
    pub outer_groove_curvature: f64,
    pub total_curvature: f64,
    pub diametral_clearance_m: f64,
    pub axial_play_m: f64,
    pub free_contact_angle_deg: f64,
    pub nominal_contact_angle_deg: f64,
    pub inner_raceway_diameter_m: f64,
    pub outer_raceway_diameter_m: f64,
    pub inner_groove_centre_radius_m: f64,
    pub inner_groove_centre_axial_m: f64,
    pub outer_groove_centre_radius_m: f64,
    pub outer_groove_centre_axial_m: f64,
    pub ball_mass_kg: f64,
}

/// A material in `rolldyn check`.
#[derive(Serialize)]
pub struct MaterialReport {
    pub name: String,
    pub elastic_modulus_pa: f64,
    pub poisson_ratio: f64,
    pub density_kg_per_m3: f64,
}

/// One assumed value.
#[derive(Serialize)]
pub struct AssumptionReport {
    pub key: String,
    pub reason: String,
}

/// `rolldyn check` output.
#[derive(Serialize)]
pub struct CheckReport {
    pub source: String,
    pub title: Option<String>,
    pub designation: Option<String>,
    pub preset: Option<String>,
    pub geometry: GeometryReport,
    pub ball_material: MaterialReport,
    pub ring_material: MaterialReport,
    pub effective_modulus_pa: f64,
    pub normal_law: &'static str,
    pub contact_stiffness_model: &'static str,
    pub inner_contact: RacewayContact,
    pub outer_contact: RacewayContact,
    pub force_x_n: f64,
    pub force_y_n: f64,
    pub force_z_n: f64,
    pub moment_y_n_m: f64,
    pub moment_z_n_m: f64,
    pub frequencies: Option<FrequencyReport>,
    /// The mounting: rotor, housing and their natural frequencies (null
    /// for a bearing set or a shaft, which have their own).
    pub mounting: Option<crate::mounting_report::MountingReport>,
    pub surfaces: Vec<SurfaceEntry>,
    /// A case with a spall: why the envelope band at its sample rate (the
    /// default 0.1–0.4 of it) cannot show the fastest defect rate, with
    /// the sample rate that would; null when it can, or without a spall.
    pub envelope_band_warning: Option<String>,
    /// The bearing set of `[arrangement]` (null for one bearing).
    pub arrangement: Option<CheckArrangement>,
    pub assumptions: Vec<AssumptionReport>,
}

/// `[arrangement]` as `check` reports it.
#[derive(Serialize)]
pub struct CheckArrangement {
    pub kind: &'static str,
    pub spacing_m: f64,
    /// The preload force at rest as given (null if none or a displacement).
    pub preload_n: Option<f64>,
    /// The preload displacement as given (null if none or a force).
    pub preload_displacement_m: Option<f64>,
    /// A rotating unbalance on the shaft: mass × radius \[kg·m\] (null:
    /// none) and its position \[m\].
    pub unbalance_kg_m: Option<f64>,
    pub unbalance_position_m: Option<f64>,
}

/// One surface feature set of `[surface]` (check report).
#[derive(Serialize)]
pub struct SurfaceEntry {
    /// `inner`, `outer` or `ball{j}`.
    pub part: String,
    pub radial_waviness_terms: usize,
    pub axial_waviness_terms: usize,
    pub max_order: u32,
    /// Largest waviness amplitude \[m\].
    pub max_amplitude_m: f64,
    pub spalls: usize,
}

fn surface_entries(surface: &rolldyn::surface::SurfaceModel) -> Vec<SurfaceEntry> {
    let max_amplitude =
        |w: &rolldyn::surface::Waviness| w.terms.iter().map(|t| t.amplitude).fold(0.0, f64::max);
    let mut out = Vec::new();
    for (part, race) in [("inner", &surface.inner), ("outer", &surface.outer)] {
        if !race.is_smooth() {
            out.push(SurfaceEntry {
                part: part.into(),
                radial_waviness_terms: race.radial.terms.len(),
                axial_waviness_terms: race.axial.terms.len(),
                max_order: race.radial.max_order().max(race.axial.max_order()),
                max_amplitude_m: max_amplitude(&race.radial).max(max_amplitude(&race.axial)),
                spalls: race.spalls.len(),
            });
        }
    }
    for (j, ball) in surface.balls.iter().enumerate() {
        if !ball.is_smooth() {
            out.push(SurfaceEntry {
                part: format!("ball{j}"),
                radial_waviness_terms: ball.waviness.terms.len(),
                axial_waviness_terms: 0,
                max_order: ball.waviness.max_order(),
                max_amplitude_m: max_amplitude(&ball.waviness),
                spalls: ball.spalls.len(),
            });
        }
    }
    out
}

fn material_report(m: &rolldyn_case::case::NamedMaterial) -> MaterialReport {
    MaterialReport {
        name: m.name.clone(),
        elastic_modulus_pa: m.material.elastic_modulus,
        poisson_ratio: m.material.poisson_ratio,
        density_kg_per_m3: m.material.density,
    }
}

impl CheckReport {
    pub fn new(source: &str, case: &Case) -> Result<Self, String> {
        // A shaft's bearings are cases of their own: check them too.
        rolldyn_case::simulation::ShaftModel::from_case(case).map_err(|e| e.to_string())?;
        let g = &case.bearing.geometry;
        let alpha = g.nominal_contact_angle();
        let frequencies = case
            .speed
            .as_ref()
            .map(|_| FrequencyReport::new(case, None))
            .transpose()?;
        let envelope_band_warning = frequencies
            .as_ref()
            .filter(|_| case.surface.spalls().next().is_some())
            .and_then(|f| {
                let sample_rate = case
                    .sample_rate
                    .unwrap_or(rolldyn_case::case::DEFAULT_SAMPLE_RATE);
                let band = rolldyn::signal::default_envelope_band(sample_rate);
                crate::vibration::band_warning(band, &f.lines())
            });
        Ok(Self {
            source: source.to_string(),
            title: case.title.clone(),
            designation: case.bearing.designation.clone(),
            preset: case.bearing.preset.clone(),
            geometry: GeometryReport {
                parametrization: match g.clearance {
                    Clearance::FreeContactAngle(_) => "free_contact_angle",
                    Clearance::Diametral(_) => "diametral_clearance",
                    Clearance::RacewayDiameters { .. } => "raceway_diameters",
                },
                ball_diameter_m: g.ball_diameter,
                ball_count: g.ball_count,
                pitch_diameter_m: g.pitch_diameter,
                inner_groove_curvature: g.inner.groove_curvature,
                outer_groove_curvature: g.outer.groove_curvature,
                total_curvature: g.total_curvature(),
                diametral_clearance_m: g.equivalent_diametral_clearance(),
                axial_play_m: g.axial_play(),
                free_contact_angle_deg: g.free_contact_angle().to_degrees(),
                nominal_contact_angle_deg: alpha.to_degrees(),
                inner_raceway_diameter_m: g.inner.groove_bottom_diameter,
                outer_raceway_diameter_m: g.outer.groove_bottom_diameter,
                inner_groove_centre_radius_m: g.inner.groove_centre_radius,
                inner_groove_centre_axial_m: g.inner.groove_centre_axial,
                outer_groove_centre_radius_m: g.outer.groove_centre_radius,
                outer_groove_centre_axial_m: g.outer.groove_centre_axial,
                ball_mass_kg: g.ball_mass(case.materials.ball.material.density),
            },
            ball_material: material_report(&case.materials.ball),
            ring_material: material_report(&case.materials.rings),
            effective_modulus_pa: effective_modulus(
                &case.materials.ball.material,
                &case.materials.rings.material,
            ),
            normal_law: case.normal_law.name(),
            contact_stiffness_model: case.contact_stiffness.name(),
            inner_contact: raceway_contact(case, RingKind::Inner, alpha, None)?,
            outer_contact: raceway_contact(case, RingKind::Outer, alpha, None)?,
            force_x_n: case.loads.force[0],
            force_y_n: case.loads.force[1],
            force_z_n: case.loads.force[2],
            moment_y_n_m: case.loads.moment[0],
            moment_z_n_m: case.loads.moment[1],
            frequencies,
            mounting: crate::mounting_report::MountingReport::new(case),
            surfaces: surface_entries(&case.surface),
            envelope_band_warning,
            arrangement: case.bearing_set().map(|a| {
                use rolldyn_case::case::Preload;
                CheckArrangement {
                    kind: rolldyn_case::case::kind_name(a.kind),
                    spacing_m: a.spacing,
                    preload_n: match a.preload {
                        Preload::Force(f) => Some(f),
                        _ => None,
                    },
                    preload_displacement_m: match a.preload {
                        Preload::Displacement(d) => Some(d),
                        _ => None,
                    },
                    unbalance_kg_m: a.unbalance.map(|u| u.0),
                    unbalance_position_m: a.unbalance.map(|u| u.1),
                }
            }),
            assumptions: case
                .assumptions
                .iter()
                .map(|(key, reason)| AssumptionReport {
                    key: key.clone(),
                    reason: reason.clone(),
                })
                .collect(),
        })
    }

    pub fn to_text(&self) -> String {
        let mut out = String::new();
        let g = &self.geometry;
        let _ = writeln!(out, "Case {}: valid", self.source);
        if let Some(t) = &self.title {
            let _ = writeln!(out, "  {t}");
        }
        let name = self
            .designation
            .as_deref()
            .or(self.preset.as_deref())
            .unwrap_or("(unnamed bearing)");
        let _ = writeln!(
            out,
            "\nBearing {name} (geometry from {})",
            g.parametrization.replace('_', " ")
        );
        geometry_text(&mut out, g);
        let _ = writeln!(out, "\nMaterials");
        for (role, m) in [
            ("balls", &self.ball_material),
            ("rings", &self.ring_material),
        ] {
            let _ = writeln!(
                out,
                "  {role:<6} {:<28} E = {:.1} GPa, ν = {}, ρ = {} kg/m³",
                m.name,
                m.elastic_modulus_pa * 1e-9,
                m.poisson_ratio,
                m.density_kg_per_m3
            );
        }
        let _ = writeln!(
            out,
            "  effective modulus E' = {:.2} GPa",
            self.effective_modulus_pa * 1e-9
        );
        let _ = writeln!(
            out,
            "\nContact ({} stiffness, normal law {})",
            self.contact_stiffness_model, self.normal_law
        );
        raceway_text(&mut out, "inner", &self.inner_contact);
        raceway_text(&mut out, "outer", &self.outer_contact);
        let _ = writeln!(
            out,
            "\nLoads on the inner ring: F_x {} N, F_y {} N, F_z {} N, M_y {} N·m, M_z {} N·m",
            self.force_x_n, self.force_y_n, self.force_z_n, self.moment_y_n_m, self.moment_z_n_m
        );
        if let Some(a) = &self.arrangement {
            arrangement_text(&mut out, a);
        }
        if let Some(f) = &self.frequencies {
            let _ = writeln!(out);
            out.push_str(&f.to_text());
        }
        if let Some(m) = &self.mounting {
            m.to_text(&mut out);
        }
        if !self.surfaces.is_empty() {
            let _ = writeln!(out, "\nSurfaces ([surface], docs/dynamics.md):");
            for e in &self.surfaces {
                let _ = writeln!(
                    out,
                    "  {:<7} waviness {} radial + {} axial terms (orders ≤ {}, ≤ {:.3} µm), {} spall(s)",
                    e.part,
                    e.radial_waviness_terms,
                    e.axial_waviness_terms,
                    e.max_order,
                    e.max_amplitude_m * 1e6,
                    e.spalls
                );
            }
            if let Some(warning) = &self.envelope_band_warning {
                let _ = writeln!(out, "  warning: {warning}");
            }
        }
        if self.assumptions.is_empty() {
            let _ = writeln!(out, "\nAssumed values: none");
        } else {
            let _ = writeln!(out, "\nAssumed values (not from the source; check them):");
            for a in &self.assumptions {
                let _ = writeln!(out, "  {:<32} {}", a.key, a.reason);
            }
        }
        out
    }
}

/// The geometry lines of `rolldyn check`.
fn geometry_text(out: &mut String, g: &GeometryReport) {
    let mm = |v: f64| v * 1e3;
    let lines = [
        (
            "ball diameter D",
            format!("{:.4} mm", mm(g.ball_diameter_m)),
        ),
        ("number of balls Z", g.ball_count.to_string()),
        (
            "pitch diameter d_m",
            format!("{:.4} mm", mm(g.pitch_diameter_m)),
        ),
        (
            "groove curvature f_i, f_o",
            format!(
                "{:.4}, {:.4} (B = f_i + f_o − 1 = {:.4})",
                g.inner_groove_curvature, g.outer_groove_curvature, g.total_curvature
            ),
        ),
        (
            "diametral clearance P_d",
            format!("{:.2} µm", g.diametral_clearance_m * 1e6),
        ),
        ("axial play", format!("{:.2} µm", g.axial_play_m * 1e6)),
        (
            "free contact angle",
            format!("{:.3}°", g.free_contact_angle_deg),
        ),
        (
            "nominal contact angle",
            format!("{:.3}°", g.nominal_contact_angle_deg),
        ),
        (
            "raceway diameters d_i, d_o",
            format!(
                "{:.4} mm, {:.4} mm",
                mm(g.inner_raceway_diameter_m),
                mm(g.outer_raceway_diameter_m)
            ),
        ),
        (
            "inner groove centre (r, x)",
            format!(
                "{:.4} mm, {:+.4} mm",
                mm(g.inner_groove_centre_radius_m),
                mm(g.inner_groove_centre_axial_m)
            ),
        ),
        (
            "outer groove centre (r, x)",
            format!(
                "{:.4} mm, {:+.4} mm",
                mm(g.outer_groove_centre_radius_m),
                mm(g.outer_groove_centre_axial_m)
            ),
        ),
        ("ball mass", format!("{:.4} g", g.ball_mass_kg * 1e3)),
    ];
    for (k, v) in lines {
        let _ = writeln!(out, "  {k:<28} {v}");
    }
}

/// The bearing set's line of `rolldyn check`.
fn arrangement_text(out: &mut String, a: &CheckArrangement) {
    let preload = match (a.preload_n, a.preload_displacement_m) {
        (Some(f), _) => format!("preload {f} N at rest"),
        (_, Some(d)) => format!("preload displacement {:.3} µm", d * 1e6),
        _ => "no preload".into(),
    };
    let unbalance = match (a.unbalance_kg_m, a.unbalance_position_m) {
        (Some(u), Some(x)) => format!(
            "; a rotating unbalance of {:.3} g·mm at {:+.1} mm (in runs)",
            u * 1e6,
            x * 1e3
        ),
        _ => String::new(),
    };
    let _ = writeln!(
        out,
        "Bearing set ([arrangement], docs/systems.md): {}, pitch planes {:.2} mm apart, {preload}; the loads act on the shaft between the bearings{unbalance}",
        a.kind,
        a.spacing_m * 1e3
    );
}
