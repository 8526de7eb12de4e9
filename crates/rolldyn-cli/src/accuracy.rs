//! How accurate a run is: the `accuracy` object of `summary.json`, the
//! warning on stderr and the report's banner, and what `run --verify`
//! changes (ten times tighter tolerances, the traction's grid refined
//! two-fold each way) and reports (the changes of the summary's main
//! quantities, compared by `run_summary::verify`; the verifying run is
//! `run`'s). docs/dynamics.md, "Accuracy at default
//! settings", explains the measures and their limits.

use crate::checkpoint::RunRecord;
use rolldyn_case::Case;
use serde::Serialize;

/// Largest energy-balance error, relative to the drive work, that a run
/// reports as `ok`.
pub const ENERGY_BALANCE_LIMIT: f64 = 1e-3;

/// Largest relative change under `--verify` of the cage speed, the contact
/// loads and the power loss that passes.
pub const VERIFY_LIMIT_MEANS: f64 = 0.01;

/// Largest relative change under `--verify` of the vibration RMS values and
/// the cage-whirl radius that passes.
pub const VERIFY_LIMIT_VIBRATION: f64 = 0.05;

/// Vibration RMS values below this many times the run's velocity
/// tolerance (rtol × 1 mm/s, the integrator's absolute tolerance of the
/// ring velocities) are integration noise, not vibration: `--verify`
/// does not compare them (an axially loaded bearing without defects).
pub const VIBRATION_NOISE_FACTOR: f64 = 10.0;

/// Factor by which `--verify` tightens the tolerances.
pub const VERIFY_TIGHTENING: f64 = 10.0;

/// The `accuracy` object of `summary.json`.
#[derive(Debug, Clone, Serialize)]
pub struct Accuracy {
    /// The energy balance error relative to the drive work (the same value
    /// as the summary's `energy_balance_relative_error`).
    pub energy_balance_relative_error: f64,
    /// The limit above which the status is `warning`.
    pub energy_balance_limit: f64,
    /// `ok` or `warning`.
    pub status: &'static str,
    /// Why the status is `warning` (null when `ok`).
    pub reason: Option<String>,
    /// What to do about it (null when `ok`).
    pub hint: Option<String>,
    /// The `--verify` comparison (null without `--verify`).
    pub verify: Option<Verification>,
}

/// One quantity compared by `--verify`.
#[derive(Debug, Clone, Serialize)]
pub struct Change {
    /// Summary key.
    pub key: std::borrow::Cow<'static, str>,
    /// Value of the run.
    pub value: f64,
    /// Value at the tighter tolerances.
    pub reference: f64,
    /// |value − reference| / |reference|.
    pub relative_change: f64,
    /// The limit it is held to.
    pub limit: f64,
    /// How much the run's own value moves within its averaging window:
    /// |first half − second half| / |value| (null when the window has
    /// fewer than two blocks of samples or a half has no value).
    pub window_spread: Option<f64>,
    /// |value − grid value| / |grid value|, the grid value from a third run
    /// with only the traction grid refined (null when that run was not
    /// needed: see [`Cause::Grid`]).
    pub grid_change: Option<f64>,
}

impl Change {
    /// The window spread of `key` whose run value is `value`, from the
    /// run's compared quantities over its window's halves (None when the
    /// key has none or the spread is not finite).
    pub fn window_spread<K: AsRef<str>>(
        halves: &[(K, [f64; 2])],
        key: &str,
        value: f64,
    ) -> Option<f64> {
        halves
            .iter()
            .find(|(k, _)| k.as_ref() == key)
            .map(|(_, [a, b])| (a - b).abs() / value.abs())
            .filter(|spread| spread.is_finite())
    }

    /// Beyond its limit.
    pub fn beyond(&self) -> bool {
        self.relative_change > self.limit
    }

    /// Beyond its limit, but by no more than it moves between the halves
    /// of the run's own window: a statistic the window is too short to
    /// settle, whatever the tolerance.
    pub fn within_window_spread(&self) -> bool {
        self.window_spread
            .is_some_and(|spread| self.relative_change <= spread)
    }

    /// The finer grid alone moved it by at least half of what the finer
    /// grid and the tighter tolerances moved it together.
    pub fn moved_by_grid(&self) -> bool {
        self.grid_change
            .is_some_and(|change| change >= 0.5 * self.relative_change)
    }
}

/// The result of `run --verify`.
#[derive(Debug, Clone, Serialize)]
pub struct Verification {
    /// Relative tolerance of the verifying run.
    pub relative_tolerance: Option<f64>,
    /// Energy tolerance of the verifying run (null: off).
    pub energy_tolerance: Option<f64>,
    /// The traction's integration grid of the verifying run, refined
    /// two-fold each way, with the run's (null: no grid, e.g. traction at
    /// the contact centre).
    pub traction_grid: Option<String>,
    /// Where the verifying run was written.
    pub directory: String,
    /// Its wall time \[s\].
    pub wall_time_s: f64,
    /// Its energy-balance error relative to the drive work.
    pub energy_balance_relative_error: f64,
    /// The compared quantities.
    pub changes: Vec<Change>,
    /// The largest relative change over the limits, as a fraction of its
    /// limit (≤ 1 passes).
    pub worst_ratio_to_limit: f64,
    /// `ok` or `warning`.
    pub status: &'static str,
    /// Why a `warning`: `tolerance` when a quantity beyond its limit moved
    /// more than it does between the halves of the run's averaging window
    /// (tighten the tolerances), `window` when every one moved no more
    /// than that (the window is too short for them: run longer); null
    /// when `ok`.
    pub cause: Option<Cause>,
}

/// Why `--verify` warns (`summary.json`: `"window"` or `"tolerance"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Cause {
    /// Every quantity beyond its limit moved no more than it does between
    /// the halves of the run's window: run longer.
    Window,
    /// Some moved more: tighten the tolerances.
    Tolerance,
    /// Every one that moved more than its window spread moved as much
    /// with the traction grid refined alone (the run's tolerances kept):
    /// refine the grid, not the tolerances.
    Grid,
}

impl Verification {
    /// The `cause` of a comparison's `changes` (null when none is beyond
    /// its limit).
    pub fn cause_of(changes: &[Change]) -> Option<Cause> {
        let beyond: Vec<&Change> = changes.iter().filter(|c| c.beyond()).collect();
        let unsettled: Vec<&Change> = beyond
            .iter()
            .copied()
            .filter(|c| !c.within_window_spread())
            .collect();
        if beyond.is_empty() {
            None
        } else if unsettled.is_empty() {
            Some(Cause::Window)
        } else if unsettled.iter().all(|c| c.moved_by_grid()) {
            Some(Cause::Grid)
        } else {
            Some(Cause::Tolerance)
        }
    }

    /// Whether a run with the grid refined alone would tell the grid's
    /// share: the cause is `tolerance` and the run has a grid.
    pub fn wants_grid_run(&self) -> bool {
        self.cause == Some(Cause::Tolerance) && self.traction_grid.is_some()
    }

    /// Records the changes of a run with only the traction grid refined,
    /// `grid_value(key)` its value of each compared key, and the cause that
    /// follows.
    pub fn attribute_to_grid(&mut self, grid_value: impl Fn(&str) -> Option<f64>) {
        for change in &mut self.changes {
            change.grid_change = grid_value(&change.key)
                .filter(|g| g.is_finite() && *g != 0.0)
                .map(|g| (change.value - g).abs() / g.abs());
        }
        self.cause = Self::cause_of(&self.changes);
    }

    /// The line `rolldyn run --verify` prints: the tighter settings and
    /// the largest change against its limit.
    pub fn line(&self) -> String {
        let worst = self
            .changes
            .iter()
            .max_by(|a, b| (a.relative_change / a.limit).total_cmp(&(b.relative_change / b.limit)));
        format!(
            "verify ({}): at rtol {}{} the largest change is {}; energy balance error {:.2e}\n",
            self.status,
            self.relative_tolerance
                .map_or("-".into(), |r| format!("{r:e}")),
            self.traction_grid
                .as_ref()
                .map_or(String::new(), |g| format!(" and a traction grid of {g}")),
            worst.map_or("none".into(), |c| format!(
                "{} {:.3} % (limit {} %)",
                c.key,
                100.0 * c.relative_change,
                100.0 * c.limit
            )),
            self.energy_balance_relative_error
        )
    }
}

/// The accuracy of a run from its summary's energy balance (relative, and
/// the error and drive work in joules for the message); the integrator and
/// tolerances name what to tighten in the hint.
pub fn assess(
    relative_error: f64,
    error_j: f64,
    drive_j: f64,
    integrator: &str,
    relative_tolerance: Option<f64>,
    energy_tolerance: Option<f64>,
) -> Accuracy {
    let ok = relative_error.abs() <= ENERGY_BALANCE_LIMIT;
    let (reason, hint) = if ok {
        (None, None)
    } else {
        let reason = format!(
            "the energy balance closes to {relative_error:.2e} of the drive work ({error_j:.3e} J of {drive_j:.3e} J), above the {ENERGY_BALANCE_LIMIT:.0e} of a converged run: the integration error is large"
        );
        let hint = match (relative_tolerance, energy_tolerance) {
            (None, _) => format!(
                "{integrator} has a fixed step: take a smaller solver.time_step, or an adaptive solver.integrator"
            ),
            (Some(rtol), Some(eps)) => format!(
                "tighten the tolerances ten-fold (--set solver.relative_tolerance={:e} --set solver.energy_tolerance={:e}) and compare, or run with --verify",
                rtol / VERIFY_TIGHTENING,
                eps / VERIFY_TIGHTENING
            ),
            (Some(rtol), None) => format!(
                "the energy error control is off (solver.energy_tolerance = 0): remove that setting, or tighten solver.relative_tolerance to {:e}; --verify compares",
                rtol / VERIFY_TIGHTENING
            ),
        };
        (Some(reason), Some(hint))
    };
    Accuracy {
        energy_balance_relative_error: relative_error,
        energy_balance_limit: ENERGY_BALANCE_LIMIT,
        status: if ok { "ok" } else { "warning" },
        reason,
        hint,
        verify: None,
    }
}

/// The tolerances of a completed run, which `--verify` tightens.
#[derive(Debug, Clone, Copy)]
pub struct RunTolerances {
    /// The relative tolerance (None: a fixed-step method).
    pub relative: Option<f64>,
    /// The energy tolerance (None: no energy error control).
    pub energy: Option<f64>,
    /// A fixed-step method's step \[s\], tightened when there is no
    /// relative tolerance (None: left as it is).
    pub fixed_step: Option<f64>,
}

/// What `--verify` changes in a case, as typed values: the tolerances
/// tightened [`VERIFY_TIGHTENING`]-fold (the relative and energy
/// tolerances, or a fixed-step method's step) and the traction grid
/// refined two-fold each way. [`Tightening::apply`] changes a loaded case;
/// [`Tightening::overrides`] writes the same changes as the `--set`
/// overrides that the verifying run's `run.json` records.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tightening {
    /// The relative tolerance (with a relative tolerance).
    relative_tolerance: Option<f64>,
    /// The energy tolerance (with the energy error control).
    energy_tolerance: Option<f64>,
    /// A fixed-step method's step \[s\] (without a relative tolerance).
    time_step: Option<f64>,
    /// The refined traction grid (None: no grid to refine).
    grid: Option<RefinedGrid>,
}

/// A traction grid refined two-fold each way.
#[derive(Debug, Clone, Copy, PartialEq)]
enum RefinedGrid {
    /// FASTSIM's strips and elements.
    Fastsim { strips: usize, elements: usize },
    /// A stress law's integration over the ellipse.
    Cells(rolldyn::traction::TractionIntegration),
}

impl Tightening {
    /// The changes of `--verify` to `case`, which ran at `tolerances`.
    pub fn of(case: &Case, tolerances: RunTolerances) -> Self {
        let (relative_tolerance, energy_tolerance, time_step) =
            match (tolerances.relative, tolerances.fixed_step) {
                (Some(rtol), _) => (
                    Some((rtol / VERIFY_TIGHTENING).max(1e-12)),
                    tolerances
                        .energy
                        .map(|eps| (eps / VERIFY_TIGHTENING).max(1e-9)),
                    None,
                ),
                (None, Some(step)) => (None, None, Some((step / VERIFY_TIGHTENING).max(1e-10))),
                (None, None) => (None, None, None),
            };
        Self {
            relative_tolerance,
            energy_tolerance,
            time_step,
            grid: refined_grid(case),
        }
    }

    /// The `--set` overrides of the changes, in the order a run's record
    /// keeps them (the tolerances, then the grid).
    pub fn overrides(&self) -> Vec<String> {
        let mut sets = Vec::new();
        if let Some(rtol) = self.relative_tolerance {
            sets.push(format!("solver.relative_tolerance={rtol:e}"));
        }
        if let Some(eps) = self.energy_tolerance {
            sets.push(format!("solver.energy_tolerance={eps:e}"));
        }
        if let Some(step) = self.time_step {
            sets.push(format!("solver.time_step={step:e} s"));
        }
        match self.grid {
            None => {}
            Some(RefinedGrid::Fastsim { strips, elements }) => sets.extend([
                format!("model.traction.strips={strips}"),
                format!("model.traction.elements={elements}"),
            ]),
            Some(RefinedGrid::Cells(integration)) => {
                let (across, along) = integration.cells().unwrap_or_default();
                // The method too: a case that relies on the default grid
                // has no such table to amend.
                sets.extend([
                    format!(
                        "model.traction_integration.method={}",
                        integration.method_name()
                    ),
                    format!("model.traction_integration.across={across}"),
                    format!("model.traction_integration.along={along}"),
                ]);
            }
        }
        sets
    }

    /// Makes the changes in `case`. As with an override, a changed value is
    /// no longer an assumption of the case.
    pub fn apply(&self, case: &mut Case) {
        use rolldyn::traction::TractionModel;
        if let Some(rtol) = self.relative_tolerance {
            case.relative_tolerance = Some(rtol);
        }
        if let Some(eps) = self.energy_tolerance {
            case.energy_tolerance = Some(eps);
        }
        if let Some(step) = self.time_step {
            case.time_step = Some(step);
        }
        match (self.grid, &mut case.traction) {
            (Some(RefinedGrid::Fastsim { strips, elements }), TractionModel::Fastsim(f)) => {
                (f.strips, f.elements) = (strips, elements);
            }
            (Some(RefinedGrid::Cells(integration)), _) => {
                case.traction_integration = integration;
            }
            _ => {}
        }
        let changed: Vec<String> = self
            .overrides()
            .iter()
            .filter_map(|set| set.split_once('=').map(|(key, _)| key.to_string()))
            .collect();
        case.assumptions.retain(|(key, _)| !changed.contains(key));
    }

    /// The run's record and case with the changes made.
    fn changed(&self, record: &RunRecord, case: &Case) -> (RunRecord, Case) {
        let mut changed = record.clone();
        changed.overrides.set.extend(self.overrides());
        let mut changed_case = case.clone();
        self.apply(&mut changed_case);
        (changed, changed_case)
    }

    /// The refined grid's description (None: no grid to refine), e.g.
    /// "graded 24 × 12 cells (run: 12 × 6)".
    pub fn grid_description(&self) -> Option<String> {
        use rolldyn::traction::TractionIntegration;
        self.grid.map(|grid| match grid {
            RefinedGrid::Fastsim { strips, elements } => format!(
                "FASTSIM {strips} × {elements} (run: {} × {})",
                strips / 2,
                elements / 2
            ),
            RefinedGrid::Cells(integration) => {
                let (a, b) = integration.cells().unwrap_or_default();
                format!(
                    "{}{a} × {b} cells (run: {} × {})",
                    match integration {
                        TractionIntegration::Graded { .. } => "graded ",
                        _ => "",
                    },
                    a / 2,
                    b / 2
                )
            }
        })
    }
}

/// The verifying run of `--verify`: the run's `case` with
/// [`Tightening`]'s changes, its record with the same changes as `--set`
/// overrides (so that the verifying run's `run.json` says what it ran),
/// and the refined grid's description (None: no grid to refine).
pub fn verifying_case(
    record: &RunRecord,
    case: &Case,
    tolerances: RunTolerances,
) -> (RunRecord, Case, Option<String>) {
    let tightening = Tightening::of(case, tolerances);
    let (tight, tight_case) = tightening.changed(record, case);
    (tight, tight_case, tightening.grid_description())
}

/// The run of `--verify` that tells the grid's share (when the verifying
/// run warns with cause `tolerance`): the run's `case` and record with
/// only the traction grid refined, the tolerances kept.
pub fn grid_case(record: &RunRecord, case: &Case) -> (RunRecord, Case) {
    let tightening = Tightening {
        relative_tolerance: None,
        energy_tolerance: None,
        time_step: None,
        grid: refined_grid(case),
    };
    tightening.changed(record, case)
}

/// A case's traction grid refined two-fold each way (None: no grid, or
/// beyond the case's limits: FASTSIM's
/// [`rolldyn::traction::fastsim::MAX_DIVISIONS`], 10 000 grid cells).
fn refined_grid(case: &Case) -> Option<RefinedGrid> {
    use rolldyn::traction::{TractionIntegration, TractionModel, fastsim::MAX_DIVISIONS};
    match (&case.traction, case.traction_integration) {
        // No grid: the table's error is stated with it (docs/validation.md).
        (TractionModel::None | TractionModel::ExactTable(_), _) => None,
        (TractionModel::Fastsim(f), _) => {
            let (strips, elements) = (2 * f.strips, 2 * f.elements);
            (strips.max(elements) <= MAX_DIVISIONS)
                .then_some(RefinedGrid::Fastsim { strips, elements })
        }
        (_, integration) => {
            let (across, along) = integration.cells()?;
            let (across, along) = (2 * across, 2 * along);
            (across * along <= 10_000).then_some(RefinedGrid::Cells(match integration {
                TractionIntegration::Graded { .. } => TractionIntegration::Graded { across, along },
                _ => TractionIntegration::Grid { across, along },
            }))
        }
    }
}

/// The warning for stderr, if the run's accuracy needs one.
pub fn warning(accuracy: &Accuracy) -> Option<String> {
    let mut lines = Vec::new();
    if let (Some(reason), Some(hint)) = (&accuracy.reason, &accuracy.hint) {
        lines.push(format!("warning: {reason}; {hint}"));
    }
    if let Some(v) = accuracy.verify.as_ref().filter(|v| v.status != "ok") {
        let moved: Vec<String> = v
            .changes
            .iter()
            .filter(|c| c.beyond())
            .map(|c| match c.window_spread {
                Some(spread) => format!(
                    "{} by {:.2} % (between its window's halves: {:.2} %)",
                    c.key,
                    100.0 * c.relative_change,
                    100.0 * spread
                ),
                None => format!("{} by {:.2} %", c.key, 100.0 * c.relative_change),
            })
            .collect();
        let verdict = match v.cause {
            Some(Cause::Window) => {
                "each by no more than it moves between the halves of the run's averaging window: statistics the window is too short to settle, not an integration error; run longer (--duration) before reading them to better than that".to_string()
            }
            Some(Cause::Grid) => format!(
                "the finer traction grid alone moves them as much (`grid_change` in summary.json): the results are not converged in the traction grid, whatever the tolerances; refine the grid (model.traction's strips and elements for FASTSIM, else model.traction_integration's across and along; the verifying run's: {}) before reading them to better than that",
                v.traction_grid.as_deref().unwrap_or("-")
            ),
            _ => "the results are not converged at these settings".to_string(),
        };
        lines.push(format!(
            "warning: --verify: at ten times tighter tolerances{} {} moved beyond their limits ({} % for means and loads, {} % for vibration); {verdict}",
            if v.traction_grid.is_some() {
                " and a finer traction grid"
            } else {
                ""
            },
            moved.join(", "),
            100.0 * VERIFY_LIMIT_MEANS,
            100.0 * VERIFY_LIMIT_VIBRATION
        ));
    }
    (!lines.is_empty()).then(|| lines.join("\n") + "\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_closed_balance_is_ok_and_an_open_one_warns_with_a_hint() {
        let ok = assess(-5e-4, -5e-7, 1e-3, "ros34pw2", Some(1e-3), Some(1e-4));
        assert_eq!(ok.status, "ok");
        assert!(ok.reason.is_none() && ok.hint.is_none());
        assert!(warning(&ok).is_none());
        let bad = assess(0.25, 2.5e-4, 1e-3, "ros34pw2", Some(1e-3), Some(1e-4));
        assert_eq!(bad.status, "warning");
        let hint = bad.hint.clone().unwrap();
        assert!(hint.contains("solver.relative_tolerance=1e-4"), "{hint}");
        assert!(hint.contains("solver.energy_tolerance=1e-5"), "{hint}");
        let text = warning(&bad).unwrap();
        assert!(
            text.contains("2.50e-1 of the drive work (2.500e-4 J of 1.000e-3 J)"),
            "{text}"
        );
        let fixed = assess(0.25, 2.5e-4, 1e-3, "rk4", None, None);
        assert!(fixed.hint.unwrap().contains("solver.time_step"));
        let off = assess(-0.1, -1e-4, 1e-3, "dopri5", Some(1e-3), None);
        assert!(off.hint.unwrap().contains("energy_tolerance = 0"));
    }

    /// `--verify`'s typed changes give the case that loading the case
    /// again with their `--set` overrides gives (which the verifying run's
    /// `run.json` records): a stress law's grid (the default case), FASTSIM
    /// (7218B), no grid (6205), a fixed step, a bearing set, and
    /// assumptions the overrides displace.
    #[test]
    fn typed_tightening_equals_the_recorded_overrides() {
        use rolldyn_case::{Override, load_case, presets};
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let spindle_pair =
            std::fs::read_to_string(root.join("examples/spindle_pair/case.toml")).unwrap();
        let preset = |name: &str| presets::find(name).unwrap().text.to_string();
        // An assumption on a value the tightening changes.
        let assumed = preset("6304").replacen(
            "\n[assumptions]\n",
            "\n[assumptions]\n\"solver.relative_tolerance\" = \"as the paper\"\n",
            1,
        );
        // A fixed-step run.
        let rk4 = preset("6304").replace(
            "\nrelative_tolerance = 1e-3",
            "\nintegrator = \"rk4\"\ntime_step = \"2e-7 s\"\n# rtol",
        );
        let cases = [
            (preset("7008C"), Some(1e-3), Some(1e-4), None),
            (preset("7218B"), Some(1e-3), Some(1e-4), None),
            (preset("6205"), Some(1e-3), None, None),
            (rk4, None, None, Some(2e-7)),
            (assumed, Some(1e-3), Some(1e-4), None),
            (spindle_pair, Some(1e-3), Some(1e-4), None),
        ];
        for (text, relative, energy, fixed_step) in cases {
            let case = load_case("case.toml", &text, &[]).unwrap();
            let tightening = Tightening::of(
                &case,
                RunTolerances {
                    relative,
                    energy,
                    fixed_step,
                },
            );
            let mut typed = case.clone();
            tightening.apply(&mut typed);
            let overrides: Vec<Override> = tightening
                .overrides()
                .iter()
                .map(|set| Override::parse_set(set).unwrap())
                .collect();
            let reloaded = load_case("case.toml", &text, &overrides).unwrap();
            assert_eq!(typed, reloaded, "{:?}", tightening.overrides());
            assert_ne!(typed, case);
        }
    }

    fn change(relative_change: f64, limit: f64, window_spread: Option<f64>) -> Change {
        Change {
            key: "k".into(),
            value: 1.0,
            reference: 1.0,
            relative_change,
            limit,
            window_spread,
            grid_change: None,
        }
    }

    /// A warning's cause is the window only when every quantity beyond its
    /// limit moved no more than it does between its window's halves.
    #[test]
    fn the_cause_of_a_warning_is_the_window_only_when_every_change_is_within_its_spread() {
        let within = change(0.08, 0.05, Some(0.1));
        let beyond = change(0.08, 0.05, Some(0.02));
        let unsplit = change(0.08, 0.05, None);
        let passing = change(0.001, 0.01, Some(0.0));
        assert_eq!(Verification::cause_of(std::slice::from_ref(&passing)), None);
        assert_eq!(
            Verification::cause_of(&[passing.clone(), within.clone()]),
            Some(Cause::Window)
        );
        assert_eq!(
            Verification::cause_of(&[within.clone(), beyond]),
            Some(Cause::Tolerance)
        );
        assert_eq!(
            Verification::cause_of(&[within, unsplit]),
            Some(Cause::Tolerance)
        );
    }

    /// The grid is the cause when the finer grid alone moved every
    /// unsettled quantity by half or more of the whole change; a quantity
    /// within its window's spread does not count either way.
    #[test]
    fn the_grid_is_the_cause_when_it_alone_moves_what_moved() {
        let with_grid = |relative: f64, spread: Option<f64>, grid: Option<f64>| Change {
            grid_change: grid,
            ..change(relative, 0.05, spread)
        };
        let by_grid = with_grid(0.7, Some(0.39), Some(0.66));
        let by_tolerance = with_grid(0.7, Some(0.39), Some(0.2));
        let settled = with_grid(0.06, Some(1.3), Some(0.0));
        let unknown = with_grid(0.7, Some(0.39), None);
        assert!(by_grid.moved_by_grid() && !by_tolerance.moved_by_grid());
        for (changes, cause) in [
            (vec![by_grid.clone(), settled], Cause::Grid),
            (vec![by_grid, by_tolerance], Cause::Tolerance),
            (vec![unknown], Cause::Tolerance),
        ] {
            assert_eq!(Verification::cause_of(&changes), Some(cause), "{changes:?}");
        }
        // The third run's values turn a `tolerance` cause into `grid`.
        let mut v = Verification {
            relative_tolerance: Some(1e-4),
            energy_tolerance: None,
            traction_grid: Some("FASTSIM 32 × 20 (run: 16 × 10)".into()),
            directory: String::new(),
            wall_time_s: 0.0,
            energy_balance_relative_error: 0.0,
            changes: vec![Change {
                value: 1.7,
                reference: 1.0,
                ..with_grid(0.7, Some(0.39), None)
            }],
            worst_ratio_to_limit: 14.0,
            status: "warning",
            cause: Some(Cause::Tolerance),
        };
        assert!(v.wants_grid_run());
        v.attribute_to_grid(|_| Some(1.05));
        let grid_change = v.changes[0].grid_change.unwrap();
        assert!((grid_change - 0.65 / 1.05).abs() < 1e-12, "{grid_change}");
        assert_eq!(v.cause, Some(Cause::Grid));
        assert!(!v.wants_grid_run());
        let text = warning(&Accuracy {
            verify: Some(v),
            ..assess(0.0, 0.0, 1.0, "auto", Some(1e-3), Some(1e-4))
        })
        .unwrap();
        assert!(
            text.contains("not converged in the traction grid"),
            "{text}"
        );
        assert!(
            text.contains("the verifying run's: FASTSIM 32 × 20 (run: 16 × 10)"),
            "{text}"
        );
    }
}
