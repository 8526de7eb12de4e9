//! `rolldyn contact`: Hertz contact of one ball on the case's inner and
//! outer raceways, or, for tribologists, of an explicit contact (`--radii
//! R_x,R_y` or `--ball-on-flat D`) with the case's materials; with
//! `--entrainment-speed` also the lubricant film of each contact
//! (Hamrock–Dowson, starved by the supply, Λ, K_oil; docs/model.md §4,
//! docs/lubrication.md) and the contact's normal stiffness in series with
//! the film's. Keys in docs/cli.md.

use crate::quasistatic_films::ContactFilmRow;
use crate::report::ContactReport;
use crate::{CaseArgs, Failure, bad_arg, emit, json, parse_angle};
use clap::Args;
use rolldyn::RingKind;
use rolldyn::contact::{Curvature, HertzCoefficients};
use rolldyn::lubrication::{self, ContactFilm, FilmConditions, Supply, contact_film};
use rolldyn::material::effective_modulus;
use rolldyn_case::Case;
use rolldyn_case::units::{Force, Length, Quantity, Velocity};
use serde::Serialize;
use std::fmt::Write as _;

/// Arguments of `rolldyn contact` (`Default`: the command line's defaults,
/// the built-in case, no load: give one).
#[derive(Args, Debug, Default)]
pub struct ContactArgs {
    #[command(flatten)]
    pub case: CaseArgs,
    /// Normal load per contact, e.g. "500 N".
    #[arg(long, value_name = "FORCE", allow_hyphen_values = true)]
    pub load: String,
    /// Contact angle, e.g. "20 deg" (raceway contacts; default: nominal angle).
    #[arg(long, value_name = "ANGLE", allow_hyphen_values = true)]
    pub angle: Option<String>,
    /// Entrainment (mean rolling) speed u, e.g. "10 m/s": adds the
    /// lubricant film (needs a `[lubricant]`).
    #[arg(long, value_name = "SPEED", allow_hyphen_values = true)]
    pub entrainment_speed: Option<String>,
    /// Explicit contact instead of the raceways: radii of relative
    /// curvature along and across the rolling direction, "R_x,R_y", e.g.
    /// "2.8 mm,20 mm" (R_y ≥ R_x); ball material against ring material.
    #[arg(long, value_name = "RX,RY", allow_hyphen_values = true)]
    pub radii: Option<String>,
    /// Explicit contact: a ball of this diameter on a flat, e.g. "19.05 mm".
    #[arg(long, value_name = "DIAMETER", allow_hyphen_values = true)]
    pub ball_on_flat: Option<String>,
    /// Inlet distance ratio L of an explicit contact (starvation; raceway
    /// contacts use the case's `[lubricant]` supply).
    #[arg(long, value_name = "L", allow_hyphen_values = true)]
    pub inlet_distance_ratio: Option<f64>,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
}

/// An explicit contact (`--radii`, `--ball-on-flat`).
#[derive(Serialize)]
pub struct ExplicitReport {
    load_n: f64,
    effective_modulus_pa: f64,
    rolling_radius_m: f64,
    transverse_radius_m: f64,
    ellipticity: f64,
    semi_major_m: f64,
    semi_minor_m: f64,
    max_pressure_pa: f64,
    approach_m: f64,
    /// dQ/dδ = 1.5 Q/δ \[N/m\].
    contact_stiffness_n_per_m: f64,
    /// Contact and film in series \[N/m\] (null without a film).
    series_stiffness_n_per_m: Option<f64>,
    film: Option<ContactFilmRow>,
}

fn quantity<D: rolldyn_case::units::Dimension>(flag: &str, text: &str) -> Result<f64, Failure> {
    Quantity::<D>::parse(text)
        .map(|q| q.si)
        .map_err(|e| bad_arg(flag, text, e))
}

fn lubricant(case: &Case) -> Result<lubrication::Lubricant, Failure> {
    let l = case.lubricant.as_ref().ok_or_else(|| {
        Failure::BadInput(
            "--entrainment-speed: the case has no [lubricant] (viscosity, pressure_viscosity)"
                .into(),
        )
    })?;
    Ok(lubrication::Lubricant {
        viscosity: l.viscosity,
        pressure_viscosity: l.pressure_viscosity,
        pressure_model: l.pressure_viscosity_model,
    })
}

/// dQ/dδ of a Hertz contact at load Q with approach δ \[N/m\].
fn hertz_stiffness(load: f64, approach: f64) -> f64 {
    if approach > 0.0 {
        1.5 * load / approach
    } else {
        0.0
    }
}

/// `rolldyn contact`: loads the case and prints the contact.
pub fn command(args: ContactArgs) -> Result<(), Failure> {
    let (_, case) = args.case.load()?;
    let report = evaluate(&args, &case)?;
    if args.json {
        json(&report)
    } else {
        emit(&report.to_text())
    }
}

/// What `rolldyn contact` prints: the raceway contacts of the case, or an
/// explicit contact.
#[derive(Serialize)]
#[serde(untagged)]
pub enum ContactOutput {
    Raceways(Box<ContactReport>),
    Explicit(Box<ExplicitReport>),
}

impl ContactOutput {
    /// The text `rolldyn contact` prints.
    pub fn to_text(&self) -> String {
        match self {
            ContactOutput::Raceways(r) => r.to_text(),
            ContactOutput::Explicit(r) => r.to_text(),
        }
    }
}

/// The curvature of an explicit contact (`--radii` or `--ball-on-flat`),
/// None for the case's raceways.
fn explicit_curvature(args: &ContactArgs) -> Result<Option<Curvature>, Failure> {
    Ok(match (&args.radii, &args.ball_on_flat) {
        (Some(_), Some(_)) => {
            return Err(bad_arg(
                "--radii",
                args.radii.as_deref().unwrap_or_default(),
                "give --radii or --ball-on-flat, not both",
            ));
        }
        (Some(text), None) => {
            let parts: Vec<&str> = text.split(',').collect();
            let [rx, ry] = parts.as_slice() else {
                return Err(bad_arg(
                    "--radii",
                    text,
                    "expected R_x,R_y, e.g. \"2.8 mm,20 mm\"",
                ));
            };
            let (rx, ry) = (
                quantity::<Length>("--radii", rx.trim())?,
                quantity::<Length>("--radii", ry.trim())?,
            );
            if !(rx > 0.0 && ry >= rx && ry.is_finite()) {
                return Err(bad_arg(
                    "--radii",
                    text,
                    "needs 0 < R_x ≤ R_y (the rolling direction is the one of larger curvature, κ ≥ 1)",
                ));
            }
            Some(Curvature {
                rolling_radius: rx,
                transverse_radius: ry,
            })
        }
        (None, Some(text)) => {
            let d = quantity::<Length>("--ball-on-flat", text)?;
            if !(d > 0.0 && d.is_finite()) {
                return Err(bad_arg(
                    "--ball-on-flat",
                    text,
                    "the ball diameter must be positive",
                ));
            }
            Some(Curvature::circular(0.5 * d))
        }
        (None, None) => None,
    })
}

/// The films of the raceway contacts of `report` at entrainment speed
/// `u` \[m/s\] and load \[N\], with the film in series with Hertz.
fn raceway_films(
    case: &Case,
    report: &mut ContactReport,
    u: f64,
    load: f64,
    ep: f64,
) -> Result<(), Failure> {
    let lub = lubricant(case)?;
    let supply = case
        .lubricant
        .as_ref()
        .map_or(Default::default(), |l| l.supply);
    report.entrainment_speed_m_s = Some(u);
    for (k, (ring, raceway)) in [
        (RingKind::Inner, &mut report.inner),
        (RingKind::Outer, &mut report.outer),
    ]
    .into_iter()
    .enumerate()
    {
        let (Some(b), Some(a), Some(d)) = (
            raceway.semi_minor_m,
            raceway.semi_major_m,
            raceway.approach_m,
        ) else {
            continue;
        };
        let film = contact_film(
            &lub,
            &supply[k],
            case.surface.composite_roughness(ring),
            &FilmConditions {
                entrainment_speed: u,
                load,
                rolling_radius: raceway.rolling_radius_m,
                effective_modulus: ep,
                ellipticity: a / b,
                semi_minor: b,
                ring_speed: 0.0,
            },
        );
        raceway.film = Some(ContactFilmRow::new(&film, u));
        raceway.series_stiffness_n_per_m = film
            .stiffness
            .is_finite()
            .then(|| lubrication::series_stiffness(hertz_stiffness(load, d), film.stiffness));
    }
    Ok(())
}

/// Evaluates the contact that `args` describe on `case` (its materials,
/// raceways and lubricant; `args.case` is not read).
pub fn evaluate(args: &ContactArgs, case: &Case) -> Result<ContactOutput, Failure> {
    let load = quantity::<Force>("--load", &args.load)?;
    if load.is_nan() || load < 0.0 {
        return Err(bad_arg(
            "--load",
            &args.load,
            "a contact load cannot be negative",
        ));
    }
    let speed = args
        .entrainment_speed
        .as_ref()
        .map(|s| {
            let u = quantity::<Velocity>("--entrainment-speed", s)?;
            if u >= 0.0 {
                Ok(u)
            } else {
                Err(bad_arg("--entrainment-speed", s, "must not be negative"))
            }
        })
        .transpose()?;
    if let Some(l) = args.inlet_distance_ratio {
        Supply::InletDistance(l)
            .validate()
            .map_err(|e| bad_arg("--inlet-distance-ratio", &l.to_string(), e.rule))?;
    }
    let ep = effective_modulus(
        &case.materials.ball.material,
        &case.materials.rings.material,
    );
    let explicit = explicit_curvature(args)?;
    match explicit {
        Some(curvature) => {
            explicit_report(case, curvature, ep, load, speed, args.inlet_distance_ratio)
                .map(|r| ContactOutput::Explicit(Box::new(r)))
        }
        None => {
            if args.inlet_distance_ratio.is_some() {
                return Err(Failure::BadInput(
                    "argument --inlet-distance-ratio: only for explicit contacts (--radii, --ball-on-flat); raceway contacts use [lubricant] inlet_distance_ratio".into(),
                ));
            }
            let angle = parse_angle("--angle", args.angle.as_ref())?;
            let mut report = ContactReport::new(case, load, angle).map_err(Failure::BadInput)?;
            if let Some(u) = speed {
                raceway_films(case, &mut report, u, load, ep)?;
            }
            Ok(ContactOutput::Raceways(Box::new(report)))
        }
    }
}

fn explicit_report(
    case: &Case,
    curvature: Curvature,
    ep: f64,
    load: f64,
    speed: Option<f64>,
    inlet: Option<f64>,
) -> Result<ExplicitReport, Failure> {
    let hertz = HertzCoefficients::exact(&curvature, ep)
        .map_err(|e| Failure::BadInput(format!("contact: {e}")))?;
    let at = hertz.at_load(load);
    let stiffness = hertz_stiffness(load, at.approach);
    let film: Option<ContactFilm> = match speed {
        None => None,
        Some(u) => Some(contact_film(
            &lubricant(case)?,
            &inlet.map_or(Supply::Flooded, Supply::InletDistance),
            case.surface
                .ball_roughness
                .hypot(case.surface.inner.roughness),
            &FilmConditions {
                entrainment_speed: u,
                load,
                rolling_radius: curvature.rolling_radius,
                effective_modulus: ep,
                ellipticity: hertz.ellipticity,
                semi_minor: at.semi_minor,
                ring_speed: 0.0,
            },
        )),
    };
    Ok(ExplicitReport {
        load_n: load,
        effective_modulus_pa: ep,
        rolling_radius_m: curvature.rolling_radius,
        transverse_radius_m: curvature.transverse_radius,
        ellipticity: hertz.ellipticity,
        semi_major_m: at.semi_major,
        semi_minor_m: at.semi_minor,
        max_pressure_pa: at.max_pressure,
        approach_m: at.approach,
        contact_stiffness_n_per_m: stiffness,
        series_stiffness_n_per_m: film
            .filter(|f| f.stiffness.is_finite())
            .map(|f| lubrication::series_stiffness(stiffness, f.stiffness)),
        film: film.zip(speed).map(|(f, u)| ContactFilmRow::new(&f, u)),
    })
}

impl ExplicitReport {
    fn to_text(&self) -> String {
        let mut out = format!(
            "Explicit contact: R_x {:.4} mm, R_y {:.4} mm, E' = {:.2} GPa, Q = {} N\n",
            self.rolling_radius_m * 1e3,
            self.transverse_radius_m * 1e3,
            self.effective_modulus_pa * 1e-9,
            self.load_n
        );
        let _ = writeln!(
            out,
            "  ellipticity κ {:.5}, semi-axes a {:.4} mm, b {:.4} mm, p₀ {:.1} MPa, δ {:.3} µm, dQ/dδ {:.4e} N/m",
            self.ellipticity,
            self.semi_major_m * 1e3,
            self.semi_minor_m * 1e3,
            self.max_pressure_pa * 1e-6,
            self.approach_m * 1e6,
            self.contact_stiffness_n_per_m
        );
        if let Some(f) = &self.film {
            f.text(&mut out);
            if let Some(k) = self.series_stiffness_n_per_m {
                let _ = writeln!(out, "  contact and film in series {k:.4e} N/m");
            }
        }
        out
    }
}
