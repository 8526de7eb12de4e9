//! The application layer of rolldyn: what the `rolldyn` command does,
//! as a library, so that the Python package (`crates/rolldyn-py`) runs
//! cases, sweeps and reports with exactly the CLI's code. The binary
//! (`main.rs`) only parses arguments and maps [`Failure`] to exit codes.

pub mod accuracy;
pub mod catalogue;
pub mod channel_groups;
pub mod checkpoint;
pub mod contact;
pub mod finite;
pub mod html_report;
pub mod mounting_report;
pub mod pipeline;
pub mod power;
pub mod power_channels;
pub mod power_report;
pub mod quasistatic;
pub mod quasistatic_films;
pub mod recorder;
pub mod report;
pub mod run;
pub mod run_options;
pub mod run_set;
pub mod run_stats;
pub mod run_summary;
pub mod run_sweep;
pub mod spectrum;
pub mod sweep_grid;
pub mod thermal;
pub mod thermal_nodes;
pub mod traction;
pub mod traction_equilibrium;
pub mod vibration;

use clap::Args;
use rolldyn_case::units::{Angle, Quantity};
use rolldyn_case::{Case, CaseError, Override, OverrideSource, load_case, load_default};
use std::io::{Read, Write};

/// The case to work on, and overrides of its values.
#[derive(Args, Debug, Clone, Default)]
pub struct CaseArgs {
    /// Case file (TOML); `-` reads standard input; omitted: the built-in
    /// default case (7008C at 10 000 rpm, F_x = 200 N).
    pub case: Option<String>,
    #[command(flatten)]
    pub overrides: CaseOverrides,
    /// A case given in memory (the Python package): its source name and
    /// text (None: the built-in default); takes the place of `case`.
    #[arg(skip)]
    pub given: Option<(String, Option<String>)>,
}

/// Overrides of a case's values from the command line (also kept in a
/// run's `run.json`, so that `--resume` rebuilds the same case).
#[derive(Args, Debug, Clone, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct CaseOverrides {
    /// Override the inner-ring speed, e.g. "8000 rpm".
    #[arg(long, value_name = "SPEED", allow_hyphen_values = true)]
    pub speed: Option<String>,
    /// Override the axial load F_x, e.g. "500 N" (negative values allowed).
    #[arg(long, value_name = "FORCE", allow_hyphen_values = true)]
    pub axial_load: Option<String>,
    /// Override the radial load F_z, e.g. "1 kN" (negative values allowed).
    #[arg(long, value_name = "FORCE", allow_hyphen_values = true)]
    pub radial_load: Option<String>,
    /// Hold the inner ring's tilts at zero (quasi-static: the holding
    /// moments are reported; a run: a shaft held in tilt by its other bearing).
    #[arg(long)]
    pub fix_tilt: bool,
    /// Prescribe the inner ring's tilt θ_y, e.g. "0.05 deg" (quasi-static).
    #[arg(long, value_name = "ANGLE", allow_hyphen_values = true)]
    pub misalignment: Option<String>,
    /// Override any key: --set bearing.ball_count=22 (repeatable).
    #[arg(long = "set", value_name = "KEY=VALUE", allow_hyphen_values = true)]
    pub set: Vec<String>,
    /// Typed assignments from Python's `Case.set`, applied before the
    /// `set`s (so that `--resume --until` extends such a run).
    #[arg(skip)]
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub values: Vec<CaseValue>,
    /// The `set` assignments came from Python's `Case.set` (records that
    /// rolldyn 0.1.0 wrote before Python's values crossed typed; kept so
    /// that their checkpoints, tied to the record, still resume).
    #[arg(skip)]
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub from_python: bool,
}

/// A case key's value set from Python (`Case.set`), typed: a number, a
/// bool, a string with its unit, an array or a table, as a case file
/// holds it; `run.json` records it as it is.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct CaseValue {
    /// Dotted key, e.g. `operating.speed`.
    pub key: String,
    /// The value.
    pub value: toml::Value,
}

impl CaseValue {
    /// The `--set KEY=VALUE` text that sets the same value: a string as
    /// it is where `--set` reads it back as that string (`operating.speed=3000
    /// rpm`), anything else as TOML (`bearing.ball_count=22`).
    pub fn set_text(&self) -> String {
        match &self.value {
            toml::Value::String(s)
                if s.trim() == s && Override::value_from_text(s) == self.value =>
            {
                format!("{}={s}", self.key)
            }
            other => format!("{}={other}", self.key),
        }
    }
}

/// Output directory of `rolldyn run` when none is given.
pub const DEFAULT_RUN_DIR: &str = "rolldyn-run";

/// A failure with its exit code.
#[derive(Debug)]
pub enum Failure {
    /// 2: the user's input, arguments or output path.
    BadInput(String),
    /// 3: the model failed to converge or diverged.
    Model(String),
    /// 130: interrupted by the user.
    Interrupted(String),
    /// 1: an internal error.
    Internal(String),
}

/// A quasi-static solver error: no convergence, or a solution branch that
/// ends short of the axial load (a least axial load), is the model's
/// failure (3); an unsupported load (no ball in its direction) the input's
/// (2).
pub fn quasistatic_failure(e: rolldyn::quasistatic::QuasiStaticError) -> Failure {
    match e {
        rolldyn::quasistatic::QuasiStaticError::NoConvergence { .. }
        | rolldyn::quasistatic::QuasiStaticError::AxialLoadTooSmall { .. } => {
            Failure::Model(e.to_string())
        }
        other => Failure::BadInput(other.to_string()),
    }
}

/// A case's invalid value (key and rule) as bad input.
pub fn invalid(e: rolldyn_case::case::Invalid) -> Failure {
    Failure::BadInput(format!("{}: {}", e.key, e.rule))
}

/// A case-to-simulation failure: a failed quasi-static solve (of the
/// bearing, or of a set's bearing or shaft) as [`quasistatic_failure`]
/// says, everything else bad input.
pub fn simulation_failure(e: rolldyn_case::simulation::SimulationError) -> Failure {
    use rolldyn::quasistatic::QuasiStaticError as Q;
    use rolldyn::quasistatic::system::SystemError as S;
    use rolldyn_case::simulation::SimulationError as E;
    match e {
        E::QuasiStatic(q) => quasistatic_failure(q),
        E::Set(
            S::NoConvergence { .. }
            | S::Bearing {
                source: Q::NoConvergence { .. } | Q::AxialLoadTooSmall { .. },
                ..
            },
        ) => Failure::Model(e.to_string()),
        E::WarmEquilibrium(_) => Failure::Model(e.to_string()),
        other => Failure::BadInput(other.to_string()),
    }
}

impl From<CaseError> for Failure {
    fn from(e: CaseError) -> Self {
        Failure::BadInput(e.to_string())
    }
}

pub fn bad_arg(flag: &str, value: &str, rule: impl std::fmt::Display) -> Failure {
    Failure::BadInput(format!("argument {flag} {value}: {rule}"))
}

impl CaseOverrides {
    /// The case's overrides, in the order they apply: the operating
    /// point's flags ([`Self::operating_flags`]), `--fix-tilt`,
    /// `--misalignment`, Python's typed values, then the `--set`s.
    pub fn overrides(&self) -> Result<Vec<Override>, Failure> {
        let mut out: Vec<Override> = self.operating_flags().into_iter().flatten().collect();
        if self.fix_tilt {
            out.push(Override::parse_set("operating.fixed_tilt=true")?);
        }
        if let Some(a) = &self.misalignment {
            out.push(Override::flag("--misalignment", "operating.tilt_y", a));
        }
        out.extend(
            self.values
                .iter()
                .map(|v| Override::typed(&v.key, v.value.clone(), OverrideSource::Python)),
        );
        let source = if self.from_python {
            OverrideSource::Python
        } else {
            OverrideSource::CommandLine
        };
        for s in &self.set {
            out.push(Override::parse_from(s, source)?);
        }
        Ok(out)
    }

    /// `--speed`, `--axial-load` and `--radial-load` as overrides of
    /// `operating.speed`, `operating.force_x` and `operating.force_z`.
    pub fn operating_flags(&self) -> [Option<Override>; 3] {
        let flag = |value: &Option<String>, flag: &str, key: &str| {
            value.as_deref().map(|v| Override::flag(flag, key, v))
        };
        [
            flag(&self.speed, "--speed", "operating.speed"),
            flag(&self.axial_load, "--axial-load", "operating.force_x"),
            flag(&self.radial_load, "--radial-load", "operating.force_z"),
        ]
    }

    /// Loads and validates a case from its text (None: the built-in
    /// default case) with these overrides.
    pub fn load_text(&self, source: &str, text: Option<&str>) -> Result<Case, Failure> {
        load_with(source, text, &self.overrides()?)
    }
}

/// Loads and validates a case from its text (None: the built-in default
/// case) with `overrides`, applied in order.
pub fn load_with(
    source: &str,
    text: Option<&str>,
    overrides: &[Override],
) -> Result<Case, Failure> {
    Ok(match text {
        None => load_default(overrides)?,
        Some(text) => load_case(source, text, overrides)?,
    })
}

impl CaseArgs {
    /// The case's source name and text (None: the built-in default).
    pub fn read(&self) -> Result<(String, Option<String>), Failure> {
        if let Some(given) = &self.given {
            return Ok(given.clone());
        }
        match self.case.as_deref() {
            None => Ok(("built-in default case (7008C)".into(), None)),
            Some("-") => {
                let mut text = String::new();
                std::io::stdin().read_to_string(&mut text).map_err(|e| {
                    Failure::BadInput(format!("cannot read the case from standard input: {e}"))
                })?;
                Ok(("<stdin>".to_string(), Some(text)))
            }
            Some(path) => {
                let text = std::fs::read_to_string(path)
                    .map_err(|e| Failure::BadInput(format!("cannot read case file {path}: {e}")))?;
                Ok((path.to_string(), Some(text)))
            }
        }
    }

    /// Loads and validates the case with its overrides.
    pub fn load(&self) -> Result<(String, Case), Failure> {
        // Overrides are checked before a case is read from standard input.
        self.overrides.overrides()?;
        let (source, text) = self.read()?;
        let case = self.overrides.load_text(&source, text.as_deref())?;
        Ok((source, case))
    }
}

/// A time option's value ("0.1 s", "20 ms") in seconds, parsed as case
/// files parse times (a bare number is refused with the same message):
/// clap's `value_parser` for time options that are numbers in the library.
pub fn time_value(text: &str) -> Result<f64, String> {
    Quantity::<rolldyn_case::units::Time>::parse(text).map(|q| q.si)
}

pub fn parse_angle(flag: &str, text: Option<&String>) -> Result<Option<f64>, Failure> {
    text.map(|t| {
        let a = Quantity::<Angle>::parse(t)
            .map_err(|e| bad_arg(flag, t, e))?
            .si;
        if (0.0..=std::f64::consts::FRAC_PI_2).contains(&a) {
            Ok(a)
        } else {
            Err(bad_arg(flag, t, "contact angle must lie in [0, 90] deg"))
        }
    })
    .transpose()
}

/// Writes `text` to standard output; a closed pipe ends quietly.
pub fn emit(text: &str) -> Result<(), Failure> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|_| out.flush()) {
        // A reader that closed the pipe (`| head`) has what it wanted.
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        result => {
            result.map_err(|e| Failure::BadInput(format!("cannot write to standard output: {e}")))
        }
    }
}

pub fn json<T: serde::Serialize>(value: &T) -> Result<(), Failure> {
    let text = crate::finite::to_json(value).map_err(|e| Failure::Internal(e.to_string()))?;
    emit(&(text + "\n"))
}

#[cfg(test)]
mod tests {
    use clap::Parser;

    #[derive(Parser)]
    struct Flags<A: clap::Args> {
        #[command(flatten)]
        args: A,
    }

    /// A command's arguments parsed from `required` flags only.
    fn parsed<A: clap::Args>(required: &[&str]) -> A {
        Flags::<A>::try_parse_from(std::iter::once("rolldyn").chain(required.iter().copied()))
            .expect("parses")
            .args
    }

    /// The arguments' `Default`s (what the Python package starts from) are
    /// the command line's defaults.
    #[test]
    fn argument_defaults_are_the_command_lines() {
        use super::{contact, spectrum, thermal, traction};
        let same = |a: String, b: String| assert_eq!(a, b);
        same(
            format!("{:?}", contact::ContactArgs::default()),
            format!("{:?}", parsed::<contact::ContactArgs>(&["--load", ""])),
        );
        same(
            format!("{:?}", thermal::ThermalArgs::default()),
            format!("{:?}", parsed::<thermal::ThermalArgs>(&[])),
        );
        same(
            format!("{:?}", traction::TractionArgs::default()),
            format!(
                "{:?}",
                parsed::<traction::TractionArgs>(&["--rolling-speed", ""])
            ),
        );
        same(
            format!("{:?}", spectrum::SpectrumArgs::default()),
            format!("{:?}", parsed::<spectrum::SpectrumArgs>(&[""])),
        );
    }

    /// A typed value's `--set` text sets the same value, and a run's
    /// record reads back the values it wrote; `--set`s apply after them
    /// (`--resume --until` extends a run from Python).
    #[test]
    fn typed_values_replay_as_set_text_and_apply_before_the_sets() {
        use super::{CaseOverrides, CaseValue};
        use rolldyn_case::Override;
        let table: toml::Value =
            toml::from_str("depth = \"20 um\"\nposition = \"90 deg\"").unwrap();
        let values = [
            toml::Value::String("3000 rpm".into()),
            toml::Value::String("22".into()),
            toml::Value::String(" padded".into()),
            toml::Value::Integer(22),
            toml::Value::Float(0.1 + 0.2),
            toml::Value::Boolean(true),
            toml::Value::Array(vec![table]),
        ];
        for value in values {
            let v = CaseValue {
                key: "a.b".into(),
                value,
            };
            let back = Override::parse_set(&v.set_text()).unwrap();
            assert_eq!(
                (back.key.as_str(), &back.value),
                ("a.b", &v.value),
                "{}",
                v.set_text()
            );
        }
        let record = CaseOverrides {
            set: vec!["solver.duration=2 ms".into()],
            values: vec![CaseValue {
                key: "solver.duration".into(),
                value: toml::Value::String("1 ms".into()),
            }],
            ..Default::default()
        };
        let json = serde_json::to_string(&record).unwrap();
        let read: CaseOverrides = serde_json::from_str(&json).unwrap();
        assert_eq!(read, record);
        // A record from Python written before the values crossed typed
        // reads back and writes again as it was (its checkpoint's hash).
        let old = r#"{"speed":null,"axial_load":null,"radial_load":null,"fix_tilt":false,"misalignment":null,"set":["solver.duration=1 ms"],"from_python":true}"#;
        let legacy: CaseOverrides = serde_json::from_str(old).unwrap();
        assert_eq!(serde_json::to_string(&legacy).unwrap(), old);
        let applied = read.overrides().unwrap();
        assert_eq!(
            applied.last().unwrap().value,
            toml::Value::String("2 ms".into())
        );
    }
}
