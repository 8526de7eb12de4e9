//! `rolldyn traction`: the traction of one ball–raceway contact with the
//! case's traction model (FASTSIM, Coulomb, traction curve or EHL), or of
//! an explicit elliptic contact with FASTSIM, for comparing models.
//!
//! Frame: x along the flow (rolling) direction, z = n the contact normal
//! from the ball into the ring, y = n × x. The ball is given the creepages
//! (ξ, η, φ) at rolling speed V (or the slip velocities and spin rate);
//! with a bearing, the ball also rolls relative to the ring about y at
//! V/R_x (R_x the rolling radius), which on the conforming groove adds the
//! differential (Heathcote) slip. Outputs are on the ball. docs/cli.md
//! lists the keys.

use crate::{CaseArgs, Failure, bad_arg, emit, json, parse_angle};
use clap::Args;
use rolldyn::RingKind;
use rolldyn::traction::exact::MAX_CELLS;
use rolldyn_case::Case;
use rolldyn_case::units::{AngularSpeed, Dimension, Force, Length, Pressure, Quantity, Velocity};
use serde::Serialize;
use std::fmt::Write;

mod evaluate;
pub use evaluate::evaluate;

/// Arguments of `rolldyn traction`. The ring constraints of the shared
/// case flags (`--fix-tilt`, `--misalignment`) do not enter one contact's
/// traction and are refused, so its help does not offer them.
/// `--ring` and `--method` by default.
pub const DEFAULT_RING: &str = "inner";
pub const DEFAULT_METHOD: &str = "fastsim";

/// Arguments of `rolldyn traction` (`Default`: the command line's
/// defaults, the built-in case, no rolling speed: give one).
#[derive(Args, Debug)]
#[command(
    mut_arg("fix_tilt", |a| a.hide(true)),
    mut_arg("misalignment", |a| a.hide(true))
)]
pub struct TractionArgs {
    #[command(flatten)]
    pub case: CaseArgs,
    /// Raceway: inner or outer.
    #[arg(long, value_name = "RING", default_value = DEFAULT_RING)]
    pub ring: String,
    /// Normal load, e.g. "2 kN".
    #[arg(long, value_name = "FORCE", allow_hyphen_values = true)]
    pub load: Option<String>,
    /// Elastic approach instead of the load, e.g. "10 um" (with a case).
    #[arg(long, value_name = "LENGTH", allow_hyphen_values = true)]
    pub approach: Option<String>,
    /// Contact angle, e.g. "40 deg" (default: nominal angle).
    #[arg(long, value_name = "ANGLE", allow_hyphen_values = true)]
    pub angle: Option<String>,
    /// Rolling speed V along the rolling direction, e.g. "10 m/s".
    #[arg(long, value_name = "SPEED", allow_hyphen_values = true)]
    pub rolling_speed: String,
    /// Creepages ξ,η,φ (φ in 1/m), e.g. "1e-3,0,2".
    #[arg(long, value_name = "XI,ETA,PHI", allow_hyphen_values = true)]
    pub creepages: Option<String>,
    /// Slip velocities of the ball along and across the rolling
    /// direction instead of creepages, e.g. "5 mm/s,0 mm/s".
    #[arg(long, value_name = "VX,VY", allow_hyphen_values = true)]
    pub slip: Option<String>,
    /// Spin rate of the ball relative to the ring about the normal, with
    /// --slip, e.g. "20 rad/s" (default 0).
    #[arg(long, value_name = "RATE", allow_hyphen_values = true)]
    pub spin: Option<String>,
    /// Explicit contact without a bearing: semi-axes along and across
    /// the rolling direction, e.g. "0.3 mm,2 mm" (FASTSIM; needs --load,
    /// --shear-modulus, --poisson-ratio, --friction).
    #[arg(long, value_name = "ALONG,ACROSS", allow_hyphen_values = true)]
    pub semi_axes: Option<String>,
    /// Combined shear modulus G of the explicit contact, e.g. "80 GPa".
    #[arg(long, value_name = "MODULUS", allow_hyphen_values = true)]
    pub shear_modulus: Option<String>,
    /// Combined Poisson ratio ν of the explicit contact (0 … 0.5).
    #[arg(long, value_name = "NU", allow_hyphen_values = true)]
    pub poisson_ratio: Option<f64>,
    /// Friction coefficient μ of the explicit contact.
    #[arg(long, value_name = "MU", allow_hyphen_values = true)]
    pub friction: Option<f64>,
    /// Tangential solution: `fastsim` (the case's law, or FASTSIM for an
    /// explicit contact) or `exact` (Kalker's exact steady-rolling theory
    /// by boundary elements; needs the fastsim law's friction and elastic
    /// constants, or an explicit contact) or `table` (the exact theory
    /// tabulated, the `exact_table` law, with the same constants).
    #[arg(long, value_name = "METHOD", default_value = DEFAULT_METHOD)]
    pub method: String,
    /// Cells along and across the rolling direction of `--method exact`,
    /// e.g. "64" or "48,32": one grid, not extrapolated (default: 32, 48 and
    /// 64 cells extrapolated to zero cell size).
    #[arg(long, value_name = "N[,M]")]
    pub cells: Option<String>,
    /// Write the stick/slip map (one row per element or cell) to FILE as CSV.
    #[arg(long, value_name = "FILE")]
    pub map: Option<String>,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
}

impl Default for TractionArgs {
    fn default() -> Self {
        Self {
            case: CaseArgs::default(),
            ring: DEFAULT_RING.into(),
            load: None,
            approach: None,
            angle: None,
            rolling_speed: String::new(),
            creepages: None,
            slip: None,
            spin: None,
            semi_axes: None,
            shear_modulus: None,
            poisson_ratio: None,
            friction: None,
            method: DEFAULT_METHOD.into(),
            cells: None,
            map: None,
            json: false,
        }
    }
}

/// A quantity given on the command line, in SI units.
fn quantity<D: Dimension>(flag: &str, text: &str) -> Result<f64, Failure> {
    Quantity::<D>::parse(text.trim())
        .map(|q| q.si)
        .map_err(|e| bad_arg(flag, text, e))
}

/// Largest ratio of an explicit contact's semi-axes for the exact theory
/// and its table.
const MAX_EXACT_ASPECT: f64 = 100.0;

/// Largest rolling speed \[m/s\] (a 100 mm ball at 1.9·10⁴ rad/s).
const MAX_ROLLING_SPEED: f64 = 1000.0;
/// Largest longitudinal or lateral creepage: slip ten times the rolling
/// speed, far into full sliding for any friction law.
const MAX_CREEPAGE: f64 = 10.0;
/// Largest spin creepage \[1/m\]: a spin of 10⁵ rad/s per m/s of rolling.
const MAX_SPIN_CREEPAGE: f64 = 1e5;

/// Refuses creepages (given, or the slip's over the rolling speed) beyond
/// [`MAX_CREEPAGE`] and [`MAX_SPIN_CREEPAGE`]: no contact rolls so, and
/// the forces and power would overflow.
fn check_creepages(motion: &Motion, rolling_speed: f64) -> Result<(), Failure> {
    let (flag, [xi, eta, phi]) = match *motion {
        Motion::Creepages(c) => ("--creepages", c),
        Motion::Slip([vx, vy], spin) => (
            "--slip",
            [vx / rolling_speed, vy / rolling_speed, spin / rolling_speed],
        ),
    };
    if xi.abs().max(eta.abs()) > MAX_CREEPAGE || phi.abs() > MAX_SPIN_CREEPAGE {
        return Err(Failure::BadInput(format!(
            "argument {flag}: creepages ξ {xi:.3e}, η {eta:.3e}, φ {phi:.3e} 1/m: |ξ| and |η| must be at most {MAX_CREEPAGE} and |φ| at most {MAX_SPIN_CREEPAGE:.0e} 1/m (slip ten times the rolling speed is full sliding for any friction law)"
        )));
    }
    Ok(())
}

/// The sliding motion: `--creepages` or `--slip` (with `--spin`).
fn motion(args: &TractionArgs) -> Result<Motion, Failure> {
    if args.spin.is_some() && args.slip.is_none() {
        return Err(bad_arg(
            "--spin",
            args.spin.as_deref().unwrap_or_default(),
            "goes with --slip; with --creepages give φ",
        ));
    }
    match (&args.creepages, &args.slip) {
        (Some(c), None) => {
            let parts: Vec<f64> = c
                .split(',')
                .map(|p| p.trim().parse::<f64>())
                .collect::<Result<_, _>>()
                .map_err(|e| bad_arg("--creepages", c, e))?;
            match parts[..] {
                [xi, eta, phi] if parts.iter().all(|p| p.is_finite()) => {
                    Ok(Motion::Creepages([xi, eta, phi]))
                }
                _ => Err(bad_arg(
                    "--creepages",
                    c,
                    "expected three finite numbers ξ,η,φ (φ in 1/m)",
                )),
            }
        }
        (None, Some(s)) => {
            let parts: Vec<&str> = s.split(',').collect();
            let [sx, sy] = parts[..] else {
                return Err(bad_arg("--slip", s, "expected two speeds VX,VY"));
            };
            let rate = match &args.spin {
                Some(t) => quantity::<AngularSpeed>("--spin", t)?,
                None => 0.0,
            };
            Ok(Motion::Slip(
                [
                    quantity::<Velocity>("--slip", sx)?,
                    quantity::<Velocity>("--slip", sy)?,
                ],
                rate,
            ))
        }
        (a, b) => Err(Failure::BadInput(format!(
            "give the creepages (--creepages XI,ETA,PHI) or the slip velocities (--slip VX,VY){}",
            one_of(a.is_some() && b.is_some())
        ))),
    }
}

/// The end of a "give A or B" message: ", not both" when both were given,
/// ": neither was given" when none was.
fn one_of(both: bool) -> &'static str {
    if both {
        ", not both"
    } else {
        ": neither was given"
    }
}

/// An explicit flat contact from `--semi-axes` and the elastic constants.
fn explicit_contact(args: &TractionArgs, axes: &str) -> Result<Contact<'static>, Failure> {
    if args.case.case.is_some() {
        return Err(bad_arg(
            "--semi-axes",
            axes,
            "an explicit contact takes no case file",
        ));
    }
    let parts: Vec<&str> = axes.split(',').collect();
    let [along, across] = parts[..] else {
        return Err(bad_arg(
            "--semi-axes",
            axes,
            "expected ALONG,ACROSS, e.g. \"0.3 mm,2 mm\"",
        ));
    };
    let need = |flag: &str| Failure::BadInput(format!("{flag} is needed with --semi-axes"));
    let load = args.load.as_deref().ok_or_else(|| need("--load"))?;
    let shear = args
        .shear_modulus
        .as_deref()
        .ok_or_else(|| need("--shear-modulus"))?;
    let (along, across) = (
        quantity::<Length>("--semi-axes", along)?,
        quantity::<Length>("--semi-axes", across)?,
    );
    // The exact solver meshes the ellipse's bounding box: an ellipse
    // thinner than 1:100 leaves no cell in contact (and Hertz contacts of
    // bearings stay within 1:15).
    let ratio = along.max(across) / along.min(across);
    if args.method != "fastsim" && (ratio > MAX_EXACT_ASPECT || ratio.is_nan()) {
        return Err(bad_arg(
            "--semi-axes",
            axes,
            format!(
                "with --method {} the semi-axes' ratio must be at most {MAX_EXACT_ASPECT} (given {ratio:.3e})",
                args.method
            ),
        ));
    }
    Ok(Contact::Explicit {
        along,
        across,
        load: quantity::<Force>("--load", load)?,
        shear_modulus: quantity::<Pressure>("--shear-modulus", shear)?,
        poisson_ratio: args.poisson_ratio.ok_or_else(|| need("--poisson-ratio"))?,
        friction: args.friction.ok_or_else(|| need("--friction"))?,
    })
}

/// The normal load of a bearing contact: `--load` or `--approach`.
fn bearing_load(args: &TractionArgs) -> Result<Load, Failure> {
    for (flag, given) in [
        ("--shear-modulus", args.shear_modulus.is_some()),
        ("--poisson-ratio", args.poisson_ratio.is_some()),
        ("--friction", args.friction.is_some()),
    ] {
        if given {
            return Err(Failure::BadInput(format!(
                "{flag} goes with --semi-axes; with a case the materials and model.traction set it (e.g. --set 'model.traction={{ law = \"fastsim\", friction = 0.1 }}')"
            )));
        }
    }
    match (&args.load, &args.approach) {
        (Some(t), None) => Ok(Load::Force(quantity::<Force>("--load", t)?)),
        (None, Some(t)) => Ok(Load::Approach(quantity::<Length>("--approach", t)?)),
        (a, b) => Err(Failure::BadInput(format!(
            "give the normal load (--load) or the approach (--approach){}",
            one_of(a.is_some() && b.is_some())
        ))),
    }
}

/// Runs `rolldyn traction`.
pub fn command(args: TractionArgs) -> Result<(), Failure> {
    let report = report(&args)?;
    if args.json {
        json(&report)
    } else {
        emit(&report.to_text())
    }
}

/// What `rolldyn traction --json` prints (and the map file written).
pub fn report(args: &TractionArgs) -> Result<TractionReport, Failure> {
    let exact = match (args.method.as_str(), &args.cells) {
        ("fastsim" | "table", None) => None,
        ("fastsim" | "table", Some(c)) => {
            return Err(bad_arg("--cells", c, "goes with --method exact"));
        }
        ("exact", cells) => Some(exact_grid(cells.as_deref())?),
        (other, _) => {
            return Err(bad_arg(
                "--method",
                other,
                "expected fastsim, exact or table",
            ));
        }
    };
    let rolling_speed = quantity::<Velocity>("--rolling-speed", &args.rolling_speed)?;
    if !(rolling_speed > 0.0 && rolling_speed <= MAX_ROLLING_SPEED) {
        return Err(bad_arg(
            "--rolling-speed",
            &args.rolling_speed,
            format!(
                "must lie in (0, {MAX_ROLLING_SPEED}] m/s: the creepages are the slip over the rolling speed (a contact that does not roll is outside steady rolling theory)"
            ),
        ));
    }
    let motion = motion(args)?;
    check_creepages(&motion, rolling_speed)?;
    let inputs = Inputs {
        rolling_speed,
        motion,
        exact,
        table: args.method == "table",
    };
    let case;
    let contact = match &args.semi_axes {
        Some(axes) => explicit_contact(args, axes)?,
        None => {
            let load = bearing_load(args)?;
            let ring = match args.ring.as_str() {
                "inner" => RingKind::Inner,
                "outer" => RingKind::Outer,
                _ => return Err(bad_arg("--ring", &args.ring, "expected inner or outer")),
            };
            let angle = parse_angle("--angle", args.angle.as_ref())?;
            if args.case.overrides.fix_tilt {
                return Err(bad_arg(
                    "--fix-tilt",
                    "",
                    "the inner ring's constraints do not enter one contact's traction",
                ));
            }
            case = args.case.load()?.1;
            Contact::Bearing {
                case: &case,
                ring,
                load,
                angle,
            }
        }
    };
    let mut map_text = args.map.as_ref().map(|_| String::new());
    let report = evaluate(&contact, &inputs, map_text.as_mut()).map_err(Failure::BadInput)?;
    if let (Some(path), Some(text)) = (&args.map, &map_text) {
        rolldyn_io::write_atomic(std::path::Path::new(path), text.as_bytes())
            .map_err(|e| Failure::BadInput(e.to_string()))?;
    }
    Ok(report)
}

/// `--cells` of `--method exact`: one grid of cells along and across, or
/// without it the default three grids extrapolated to zero cell size.
fn exact_grid(text: Option<&str>) -> Result<ExactGrid, Failure> {
    let Some(text) = text else {
        return Ok(ExactGrid::Extrapolated);
    };
    let parts: Result<Vec<usize>, _> = text.split(',').map(|p| p.trim().parse()).collect();
    let rule = format!("expected one or two whole numbers of cells between 4 and {MAX_CELLS}");
    let ok = |n: &usize| (4..=MAX_CELLS).contains(n);
    match parts.as_deref() {
        Ok([n]) if ok(n) => Ok(ExactGrid::Cells(*n, *n)),
        Ok([a, b]) if ok(a) && ok(b) => Ok(ExactGrid::Cells(*a, *b)),
        _ => Err(bad_arg("--cells", text, rule)),
    }
}

/// The contact and its kinematics, in SI units.
pub struct Inputs {
    /// Rolling (entrainment) speed V \[m/s\], signed along x.
    pub rolling_speed: f64,
    /// What slides.
    pub motion: Motion,
    /// `--method exact` with its grid, or None (FASTSIM or the case's law).
    pub exact: Option<ExactGrid>,
    /// `--method table`: the exact theory tabulated (the `exact_table` law).
    pub table: bool,
}

/// The grid of `--method exact`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ExactGrid {
    /// The default: 32, 48 and 64 cells per direction, extrapolated to zero
    /// cell size (`ExactRolling::solve_extrapolated`).
    Extrapolated,
    /// One grid of cells along and across (`--cells`), not extrapolated.
    Cells(usize, usize),
}

/// Creepages or slip velocities.
pub enum Motion {
    /// ξ, η \[-\], φ \[1/m\].
    Creepages([f64; 3]),
    /// Slip velocities along x and y \[m/s\], spin rate about n \[rad/s\].
    Slip([f64; 2], f64),
}

/// Where the contact comes from.
pub enum Contact<'a> {
    /// A ring of the case: load Q \[N\] (or approach) and contact angle.
    Bearing {
        case: &'a Case,
        ring: RingKind,
        load: Load,
        angle: Option<f64>,
    },
    /// An explicit ellipse with FASTSIM.
    Explicit {
        /// Semi-axis along the rolling direction \[m\].
        along: f64,
        /// Semi-axis across \[m\].
        across: f64,
        load: f64,
        shear_modulus: f64,
        poisson_ratio: f64,
        friction: f64,
    },
}

/// The normal load or the approach that sets it.
#[derive(Clone, Copy)]
pub enum Load {
    /// Q \[N\].
    Force(f64),
    /// δ \[m\].
    Approach(f64),
}

/// `rolldyn traction` output.
#[derive(Serialize)]
pub struct TractionReport {
    pub traction_law: &'static str,
    pub ring: Option<&'static str>,
    pub contact_angle_deg: Option<f64>,
    pub load_n: f64,
    pub semi_axis_along_m: f64,
    pub semi_axis_across_m: f64,
    pub rolling_speed_m_s: f64,
    pub creepage_longitudinal: f64,
    pub creepage_lateral: f64,
    pub creepage_spin_1_m: f64,
    pub force_x_n: f64,
    pub force_y_n: f64,
    pub force_n: f64,
    pub traction_coefficient: f64,
    pub spin_moment_nm: f64,
    pub power_w: f64,
    pub stick_fraction: Option<f64>,
    pub map_cells: Option<usize>,
    /// `fastsim` (or the case's law) or `exact`.
    pub method: &'static str,
    /// The exact solver's grid and convergence (`--method exact`).
    pub exact: Option<ExactReport>,
}

/// How the exact solution was obtained.
#[derive(Serialize)]
pub struct ExactReport {
    /// The (finest) grid.
    pub cells_along: usize,
    pub cells_across: usize,
    /// Cells per direction of the extrapolation's grids, coarsest first
    /// (empty with `--cells`).
    pub extrapolated_from: Vec<usize>,
    /// Estimated error of the force: the extrapolation's correction, or the
    /// change between the two finest grids where the values did not
    /// converge regularly \[N\] (null with `--cells`).
    pub force_error_estimate_n: Option<f64>,
    /// Cells of the numerical contact area (loaded by the normal problem).
    pub contact_cells: usize,
    pub sweeps: usize,
    pub converged: bool,
    /// −Σ p·s V ΔA over the cells: the power friction dissipates \[W\].
    pub frictional_power_w: f64,
}

impl TractionReport {
    pub fn to_text(&self) -> String {
        let mut out = if self.method == "exact" {
            "Traction (Kalker's exact steady-rolling theory)".to_string()
        } else {
            format!("Traction ({} law)", self.traction_law)
        };
        if let (Some(ring), Some(angle)) = (self.ring, self.contact_angle_deg) {
            let _ = write!(out, ", {ring} raceway at α = {angle:.3}°");
        }
        out.push('\n');
        let _ = writeln!(
            out,
            "  load Q                {:>12.4} N      semi-axes along/across {:.4} / {:.4} mm",
            self.load_n,
            self.semi_axis_along_m * 1e3,
            self.semi_axis_across_m * 1e3
        );
        let _ = writeln!(
            out,
            "  rolling speed V       {:>12.4} m/s    creepages ξ {:.4e}, η {:.4e}, φ {:.4e} 1/m",
            self.rolling_speed_m_s,
            self.creepage_longitudinal,
            self.creepage_lateral,
            self.creepage_spin_1_m
        );
        let _ = writeln!(
            out,
            "  F_x {:.6e} N   F_y {:.6e} N   |F| {:.6e} N (|F|/Q = {:.5})",
            self.force_x_n, self.force_y_n, self.force_n, self.traction_coefficient
        );
        let _ = writeln!(
            out,
            "  spin moment M_z {:.6e} N·m   power {:.6e} W",
            self.spin_moment_nm, self.power_w
        );
        if let Some(s) = self.stick_fraction {
            let _ = writeln!(out, "  stick area fraction {s:.4}");
        }
        if let Some(e) = &self.exact {
            let grid = match (e.extrapolated_from.as_slice(), e.force_error_estimate_n) {
                ([a, b, c], Some(error)) => format!(
                    "extrapolated to zero cell size from {a}, {b} and {c} cells per direction (force error estimate {error:.2e} N); finest grid"
                ),
                _ => "grid".to_string(),
            };
            let _ = writeln!(
                out,
                "  exact theory: {grid} {} × {} cells ({} in contact), {} sweeps{}; frictional power {:.6e} W",
                e.cells_along,
                e.cells_across,
                e.contact_cells,
                e.sweeps,
                if e.converged { "" } else { ", NOT converged" },
                e.frictional_power_w
            );
        }
        out
    }
}
