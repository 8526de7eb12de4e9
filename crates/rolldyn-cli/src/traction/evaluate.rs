//! One contact's traction evaluated: the contact set up from the case's
//! raceway or from explicit semi-axes, then the case's traction law, the
//! tabulated exact theory (`--method table`) or Kalker's exact theory
//! (`--method exact`), with the FASTSIM or exact stick/slip map.

use super::{Contact, ExactGrid, ExactReport, Inputs, Load, Motion, TractionReport};
use nalgebra::Vector3;
use rolldyn::contact::RacewayContactModel;
use rolldyn::material::effective_modulus;
use rolldyn::traction::exact::ExactRolling;
use rolldyn::traction::fastsim::MapCell;
use rolldyn::traction::kalker::check_axes;
use rolldyn::traction::{
    ContactConditions, ContactKinematics, ContactPatch, ExactTable, Fastsim, TractionModel,
    TractionResult,
};
use std::fmt::Write;

fn law_name(model: &TractionModel) -> &'static str {
    match model {
        TractionModel::None => "none",
        TractionModel::ModifiedCoulomb(_) => "modified_coulomb",
        TractionModel::TractionCurve(_) => "traction_curve",
        TractionModel::Ehl(_) => "ehl",
        TractionModel::Fastsim(_) => "fastsim",
        TractionModel::ExactTable(_) => "exact_table",
    }
}

/// Friction, combined G and ν and regularisation speed of the models that
/// carry them (FASTSIM, the exact table).
fn contact_constants(model: &TractionModel) -> Option<ExactTable> {
    match model {
        TractionModel::Fastsim(f) => Some(ExactTable {
            friction: f.friction,
            shear_modulus: f.shear_modulus,
            poisson_ratio: f.poisson_ratio,
            regularisation_speed: f.regularisation_speed,
        }),
        TractionModel::ExactTable(t) => Some(*t),
        _ => None,
    }
}

/// The contact an evaluation runs: its traction law and grid, the Hertz
/// ellipse, and for a bearing's raceway the radii, film data and ring.
struct Setup {
    model: TractionModel,
    integration: rolldyn::traction::TractionIntegration,
    /// Semi-axis along the rolling direction \[m\].
    along: f64,
    /// Semi-axis across it \[m\].
    across: f64,
    /// Normal load \[N\].
    load: f64,
    /// Radius of the deformed surface across the rolling direction \[m\].
    deformed_radius: f64,
    /// Rolling radius of the raceway contact \[m\].
    rolling_radius: Option<f64>,
    /// Effective modulus \[Pa\] and ellipticity, for the film.
    film_of: Option<(f64, f64)>,
    /// The ring's name and the contact angle \[rad\].
    ring: Option<(&'static str, f64)>,
}

fn setup(contact: &Contact) -> Result<Setup, String> {
    let setup = match contact {
        Contact::Bearing {
            case,
            ring,
            load,
            angle,
        } => {
            let params = case
                .dynamics_parameters()
                .map_err(|e| format!("{}: {}", e.key, e.rule))?;
            let g = &case.bearing.geometry;
            let angle = angle.unwrap_or_else(|| g.nominal_contact_angle());
            let (ball, rings) = (
                &case.materials.ball.material,
                &case.materials.rings.material,
            );
            let ep = effective_modulus(ball, rings);
            let raceway = RacewayContactModel::new(g, *ring, ep, case.contact_stiffness);
            let h = raceway
                .coefficients(angle)
                .map_err(|e| format!("{} raceway contact: {e}", ring.name()))?;
            let q = match load {
                Load::Force(q) => *q,
                Load::Approach(d) => h.load(*d),
            };
            let at = h.at_load(q);
            let rg = g.raceway(*ring).groove_radius;
            let rb = 0.5 * g.ball_diameter;
            Setup {
                model: params.traction,
                integration: params.traction_integration,
                along: at.semi_minor,
                across: at.semi_major,
                load: q,
                deformed_radius: 2.0 * rg * rb / (rg + rb),
                rolling_radius: Some(raceway.curvature(angle).rolling_radius),
                film_of: Some((ep, h.ellipticity)),
                ring: Some((ring.name(), angle)),
            }
        }
        Contact::Explicit {
            along,
            across,
            load,
            shear_modulus,
            poisson_ratio,
            friction,
        } => {
            let flag = |field: &str| {
                if field.starts_with("semi_axis") {
                    "--semi-axes".to_string()
                } else {
                    format!("--{}", field.replace('_', "-"))
                }
            };
            check_axes(*along, *across, *poisson_ratio)
                .map_err(|e| format!("{}: {e}", flag(e.field)))?;
            let m = Fastsim::new(*friction, *shear_modulus, *poisson_ratio);
            m.validate()
                .map_err(|e| format!("{}: {e}", flag(e.field)))?;
            Setup {
                model: TractionModel::Fastsim(m),
                integration: Default::default(),
                along: *along,
                across: *across,
                load: *load,
                deformed_radius: f64::INFINITY,
                rolling_radius: None,
                film_of: None,
                ring: None,
            }
        }
    };
    let load = setup.load;
    if !(load.is_finite() && load >= 0.0) {
        return Err(format!("normal load {load} N: must be ≥ 0"));
    }
    Ok(setup)
}

/// The tabulated exact theory with the friction and elastic constants of
/// `model`'s law (`--method table`).
fn tabulated(model: &TractionModel) -> Result<TractionModel, String> {
    contact_constants(model)
        .map(TractionModel::ExactTable)
        .ok_or_else(|| {
            format!(
                "--method table: the tabulated exact theory takes its friction and elastic constants from the fastsim or exact_table traction law (the case has {}; e.g. --set 'model.traction={{ law = \"exact_table\", friction = 0.1 }}')",
                law_name(model)
            )
        })
}

/// Kalker's exact steady-rolling theory on `grid` (one grid, or the default
/// three extrapolated to zero cell size) with the friction and elastic
/// constants of `model`'s law; `map` (if given) receives the (finest
/// grid's) cells as CSV text. The result, its report and the cells written.
fn solve_exact(
    model: &TractionModel,
    grid: ExactGrid,
    kinematics: &ContactKinematics,
    rolling_speed: f64,
    map: Option<&mut String>,
) -> Result<(TractionResult, ExactReport, usize), String> {
    let Some(f) = contact_constants(model) else {
        return Err(format!(
            "--method exact: the exact theory takes its friction and elastic constants from the fastsim or exact_table traction law (the case has {}; e.g. --set 'model.traction={{ law = \"fastsim\", friction = 0.1 }}')",
            law_name(model)
        ));
    };
    if rolling_speed == 0.0 {
        return Err(
            "--method exact: the steady-rolling theory needs a rolling speed (--rolling-speed ≠ 0)"
                .into(),
        );
    }
    let mut m = ExactRolling::new(f.friction, f.shear_modulus, f.poisson_ratio);
    let solve = |m: &ExactRolling| {
        m.solve(
            &kinematics.patch,
            &kinematics.slip,
            &kinematics.relative_spin,
            rolling_speed,
        )
    };
    let (sol, extrapolated_from, force_error_estimate_n, converged) = match grid {
        ExactGrid::Cells(along, across) => {
            m.cells_along = along;
            m.cells_across = across;
            let sol = solve(&m);
            let converged = sol.converged;
            (sol, Vec::new(), None, converged)
        }
        ExactGrid::Extrapolated => {
            let e = m.solve_extrapolated(
                &kinematics.patch,
                &kinematics.slip,
                &kinematics.relative_spin,
                rolling_speed,
            );
            m.cells_along = e.grids[2];
            m.cells_across = e.grids[2];
            let error = e.force_error();
            (e.solution, e.grids.to_vec(), Some(error), e.converged)
        }
    };
    let mut cells = 0;
    if let Some(text) = map {
        text.push_str(MapCell::CSV_HEADER);
        text.push('\n');
        for c in &sol.cells {
            let _ = writeln!(text, "{}", c.csv_row());
        }
        cells = sol.cells.len();
    }
    let report = ExactReport {
        cells_along: m.cells_along,
        cells_across: m.cells_across,
        extrapolated_from,
        force_error_estimate_n,
        contact_cells: sol.cells.len(),
        sweeps: sol.sweeps,
        converged,
        frictional_power_w: sol.resultants.frictional_power,
    };
    Ok((sol.result, report, cells))
}

/// Evaluates the contact; `map` (if given) receives the FASTSIM stick/slip
/// map as CSV text.
pub fn evaluate(
    contact: &Contact,
    inputs: &Inputs,
    map: Option<&mut String>,
) -> Result<TractionReport, String> {
    // Contact frame: normal z, rolling direction x, y = z × x.
    let (normal, x, y) = (Vector3::z(), Vector3::x(), Vector3::y());
    let v = inputs.rolling_speed;
    let Setup {
        model,
        integration,
        along,
        across,
        load,
        deformed_radius,
        rolling_radius,
        film_of,
        ring,
    } = setup(contact)?;
    let model = if inputs.table {
        tabulated(&model)?
    } else {
        model
    };
    // The Hertz ellipse with its minor axis along the rolling direction x.
    let patch = ContactPatch {
        point: 0.5e-3 * normal,
        normal,
        rolling_direction: x,
        semi_major: across,
        semi_minor: along,
        load,
        deformed_radius,
    };
    let regularisation = contact_constants(&model).map_or(0.0, |t| t.regularisation_speed);
    let speed = v.hypot(regularisation);
    let (slip, spin_n) = match inputs.motion {
        Motion::Creepages([xi, eta, phi]) => (speed * (xi * x + eta * y), speed * phi),
        Motion::Slip([sx, sy], spin) => (sx * x + sy * y, spin),
    };
    // Rolling of the ball relative to the ring about y: V/R_x.
    let rolling_rate = rolling_radius.map_or(0.0, |r| v / r);
    let relative_spin = spin_n * normal + rolling_rate * y;
    let film = film_of.map_or(0.0, |(ep, kappa)| {
        model.central_film(v.abs(), load, rolling_radius.unwrap_or(1.0), ep, kappa)
    });
    let conditions = ContactConditions {
        film,
        entrainment_speed: v.abs(),
        rolling_velocity: v,
    };
    let kinematics = ContactKinematics {
        patch,
        ball_centre: Vector3::zeros(),
        slip,
        relative_spin,
        conditions,
    };
    let mut cells = 0;
    let mut exact_report = None;
    let result: TractionResult = match (&model, inputs.exact, map) {
        (_, Some(grid), map) => {
            let (result, report, mapped) = solve_exact(&model, grid, &kinematics, v, map)?;
            cells = mapped;
            exact_report = Some(report);
            result
        }
        (TractionModel::Fastsim(f), None, Some(text)) => {
            text.push_str(MapCell::CSV_HEADER);
            text.push('\n');
            f.evaluate_mapped(&kinematics, |c: &MapCell| {
                cells += 1;
                let _ = writeln!(text, "{}", c.csv_row());
            })
        }
        (_, None, Some(_)) => {
            return Err(format!(
                "--map: the stick/slip map needs the fastsim traction law (the case has {})",
                law_name(&model)
            ));
        }
        (m, None, None) => m.evaluate(
            &rolldyn::traction::TractionGrid::new(integration),
            &kinematics,
        ),
    };
    let (fx, fy) = (result.force.dot(&x), result.force.dot(&y));
    Ok(TractionReport {
        traction_law: law_name(&model),
        ring: ring.map(|r| r.0),
        contact_angle_deg: ring.map(|r| r.1.to_degrees()),
        load_n: load,
        semi_axis_along_m: along,
        semi_axis_across_m: across,
        rolling_speed_m_s: v,
        creepage_longitudinal: slip.dot(&x) / speed,
        creepage_lateral: slip.dot(&y) / speed,
        creepage_spin_1_m: spin_n / speed,
        force_x_n: fx,
        force_y_n: fy,
        force_n: fx.hypot(fy),
        traction_coefficient: if load > 0.0 { fx.hypot(fy) / load } else { 0.0 },
        spin_moment_nm: result.couple.dot(&normal),
        power_w: result.dissipation,
        stick_fraction: result.creep.map(|c| c.stick_fraction),
        map_cells: (cells > 0).then_some(cells),
        method: match (&exact_report, inputs.table) {
            (Some(_), _) => "exact",
            (None, true) => "table",
            (None, false) => "fastsim",
        },
        exact: exact_report,
    })
}
