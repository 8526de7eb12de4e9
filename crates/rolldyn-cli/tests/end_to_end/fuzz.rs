//! the fuzzing harness: the presets' case files, a matched set, a shaft
//! and a case with a sensor and a spall (with sections added: a set, a
//! sensor, a growing spall) and the CLI flags (with `--set` on nested
//! arrays, drive torques, growth rates), mutated as a careless or hostile
//! user would, fed to every command (`traction --method exact` and
//! `table` among them). For each case: no panic, exit code 0, 2 or 3 (130
//! never: nothing interrupts), an exit 2 with a located `error:` message,
//! no hang beyond [`TIMEOUT`], no non-finite number in JSON, CSV or text
//! output (the JSON writers name one on standard error: `finite.rs`; the
//! text is searched for `NaN` and `inf`), and no partial file at a final
//! path (temporary files gone, results readable).
//!
//! The generator is a seeded SplitMix64, so a run is reproducible from its
//! seed and case number (printed with every failure). CI runs a fixed
//! budget of [`CI_CASES`]; `scripts/fuzz.sh` runs hours of it with
//! `ROLLDYN_FUZZ_CASES` and `ROLLDYN_FUZZ_SEED` on the release build.
//! Failures found are kept as regression cases in [`REGRESSIONS`].

#![allow(clippy::unwrap_used)]

use crate::common;

use rolldyn_case::presets::PRESETS;
use serde_json::Value;
use std::io::Write;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Cases of the CI run (about 60 s on 2 cores, debug build).
const CI_CASES: u64 = 2000;
/// Longest a command may take before it counts as a hang.
const TIMEOUT: Duration = Duration::from_secs(60);
/// Longest a `run` goes on before it is interrupted (SIGINT); it counts as
/// slow, not hung, if it stops within [`GRACE`] with a summary that shows
/// progress: a stiff case the engine integrates at a tiny step
/// (docs/reliability.md). Shorter than [`TIMEOUT`]: the check is the same
/// after 20 s as after 60 s, and CI's time is spent on other cases.
const RUN_TIMEOUT: Duration = Duration::from_secs(20);
/// Time a `run` gets to stop after SIGINT.
const GRACE: Duration = Duration::from_secs(15);
/// Pseudo exit code of a slow run (interrupted while progressing).
const SLOW: i32 = -2;

/// Inputs that failed once, replayed as they were found: (preset,
/// command with `{dir}` for the output directory, expected exit code).
const REGRESSIONS: &[(&str, &[&str], i32)] = &[
    // Orders at rest were NaN, written as null unseen.
    (
        "7008C",
        &["frequencies", "-", "--json", "--speed", "0 rpm"],
        0,
    ),
    // L10 under a vanishing load overflowed to +inf (null in JSON).
    (
        "7218B",
        &[
            "quasistatic",
            "-",
            "--sweep",
            "speed=0rpm..20000rpm/3",
            "-o",
            "{dir}",
            "--json",
            "--radial-load",
            "1e-300 N",
        ],
        0,
    ),
    // A plotted series flat to round-off (ring displacements over 0.1 ms)
    // made the report's tick labels panic.
    (
        "6304",
        &[
            "run",
            "-",
            "-o",
            "{dir}",
            "--duration",
            "0.1 ms",
            "--report",
        ],
        0,
    ),
    // 100 MN on a 7008C (99 GPa) was accepted and the run crawled for ever.
    (
        "7008C",
        &[
            "run",
            "-",
            "-o",
            "{dir}",
            "--duration",
            "0.3 ms",
            "--radial-load",
            "1e8 N",
        ],
        2,
    ),
];

/// Case files beside the presets: a matched set, a case with a housing
/// sensor and a spall (and the tests' shaft on two bearings,
/// `common::SHAFT`).
const EXAMPLES: &[&str] = &[
    include_str!("../../../../examples/spindle_pair/case.toml"),
    include_str!("../../../../examples/cwru6205/case.toml"),
];

/// Sections added to a preset's text (one of them, a third of the time).
const SECTIONS: &[&str] = &[
    "\n[arrangement]\nkind = \"back_to_back\"\npreload = \"100 N\"\n",
    "\n[arrangement]\nkind = \"tandem_face_to_face\"\npreload_displacement = \"2 um\"\n",
    "\n[sensor]\n",
    "\n[[surface.outer.spall]]\nposition = \"90 deg\"\nlength = \"0.5 mm\"\ndepth = \"0.1 mm\"\ngrowth_rate = \"5 mm/s\"\n",
];

struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }
}

const NUMBERS: &[&str] = &[
    "0",
    "-0.0",
    "-1",
    "1",
    "3.5",
    "1e300",
    "-1e300",
    "1e-300",
    "1e9",
    "2147483648",
    "18446744073709551616",
    "nan",
    "inf",
    "-inf",
    "0.5",
    "100000",
];
const STRINGS: &[&str] = &[
    "\"\"",
    "\"abc\"",
    "\"1e300 N\"",
    "\"-5 mm\"",
    "\"0 rpm\"",
    "\"1e12 Hz\"",
    "\"1e-300 s\"",
    "\"nan mm\"",
    "\"inf N\"",
    "\"1e-300 Pa\"",
    "\"1e300 rpm\"",
    "\"0 mm\"",
    "\"1 furlong\"",
    "\"hertz\"",
    "\"fastsim\"",
    "true",
    "[]",
    "[1, 2]",
    "{}",
    "[[0, 1], [1, 2]]",
    "[\"cage\"]",
    "[\"rings\", \"contacts\"]",
    "[\"sensor\"]",
    "[0, 99]",
    "[-1]",
    "\"float32\"",
    "\"float16\"",
    "\"ambient\"",
    "\"2 mm/s\"",
    "\"1e5 N.m\"",
    "\"1e-6 kg.m^2\"",
    "\"1 kHz\"",
    "\"back_to_back\"",
];
/// Factors applied to the number of a quantity ("6.35 mm" → "…e300 mm").
const FACTORS: &[f64] = &[0.0, -1.0, 1e-300, 1e300, 1e6, 1e-6, 1e3, 1e-3, 2.0, 0.5];
/// Flag values by flag; a fifth of the time any of [`HOSTILE`].
const SPEEDS: &[&str] = &[
    "0 rpm",
    "-1 rpm",
    "1e6 rpm",
    "20000 rpm",
    "1 rpm",
    "3000 rpm",
];
const FORCES: &[&str] = &["1e8 N", "-5 kN", "0 N", "50 kN", "1e-300 N", "10 N", "1 kN"];
const ANGLES: &[&str] = &["0 deg", "0.1 deg", "-2 deg", "45 deg", "1e-9 rad"];
const HOSTILE: &[&str] = &["nan N", "abc", "", "1e300 rpm", "inf deg", "5 kN"];

/// A command line for a case read from standard input; `dir` for outputs.
fn command(rng: &mut Rng, dir: &str) -> Vec<String> {
    let mut args = base_command(rng, dir);
    // Half the time the text output (searched for NaN and inf).
    if rng.below(2) == 0 {
        args.retain(|a| a != "--json");
    }
    push_case_flags(rng, &mut args);
    args
}

/// The command and its own options, drawn.
fn base_command(rng: &mut Rng, dir: &str) -> Vec<String> {
    let base: &[&str] = match rng.below(12) {
        10 => &[
            "traction",
            "-",
            "--load",
            "500 N",
            "--rolling-speed",
            "10 m/s",
            "--creepages",
            "1e-3,0,5",
            "--method",
            "exact",
            "--cells",
            "16",
        ],
        11 => &[
            "traction",
            "-",
            "--load",
            "500 N",
            "--rolling-speed",
            "10 m/s",
            "--creepages",
            "2e-3,1e-3,20",
            "--method",
            "table",
            "--json",
        ],
        0 => &["check", "-", "--json"],
        1 => &["frequencies", "-", "--json"],
        2 => &["contact", "-", "--load", "500 N", "--json"],
        3 => &[
            "contact",
            "-",
            "--load",
            "20 N",
            "--entrainment-speed",
            "5 m/s",
            "--json",
        ],
        4 => &["quasistatic", "-", "--json"],
        5 => &["power", "-", "--json"],
        6 => &["thermal", "-", "--json"],
        7 => &[
            "quasistatic",
            "-",
            "--sweep",
            "speed=0rpm..20000rpm/3",
            "-o",
            dir,
            "--json",
        ],
        8 => &[
            "traction",
            "-",
            "--load",
            "500 N",
            "--rolling-speed",
            "10 m/s",
            "--creepages",
            "1e-3,0,5",
            "--json",
        ],
        // 60 samples, so that the run's spectrum has data to work on.
        _ => &[
            "run",
            "-",
            "-o",
            dir,
            "--duration",
            "0.3 ms",
            "--set",
            "output.sample_rate=\"200 kHz\"",
        ],
    };
    base.iter().map(|s| s.to_string()).collect()
}

/// The `--set` keys the flags draw from.
const SET_KEYS: &[&str] = &[
    "solver.relative_tolerance",
    "operating.speed",
    "bearing.ball_count",
    "output.sample_rate",
    "solver.max_step",
    "model.traction",
    "operating.radial_load_angle",
    "life.contamination_factor",
    "life.viscosity_ratio",
    "output.channels",
    "output.balls",
    "output.precision",
    "output.slow_channels",
    "output.slow_rate",
    "thermal.run_start",
    "operating.drive_torque",
    "operating.rotor_inertia",
    "surface.outer.spall.0.length",
    "surface.outer.spall.0.growth_rate",
    "sensor.modes.0.frequency",
    "shaft.loads.0.force_z",
    "shaft.bearings.1.position",
    "arrangement.preload",
    "arrangement.kind",
];

/// Up to two distinct case flags (`--speed`, `--axial-load`,
/// `--radial-load`, `--misalignment`, `--set`) with drawn values.
fn push_case_flags(rng: &mut Rng, args: &mut Vec<String>) {
    let flags = [
        "--speed",
        "--axial-load",
        "--radial-load",
        "--misalignment",
        "--set",
    ];
    let first = rng.below(flags.len());
    for k in 0..rng.below(3) {
        // Distinct flags (clap refuses a repeated one; that is tested elsewhere).
        let flag = flags[(first + k) % flags.len()];
        args.push(flag.to_string());
        if flag == "--set" {
            let key = *rng.pick(SET_KEYS);
            let value = if rng.below(2) == 0 {
                *rng.pick(NUMBERS)
            } else {
                *rng.pick(STRINGS)
            };
            args.push(format!("{key}={value}"));
        } else {
            let pool = match (rng.below(5), flag) {
                (0, _) => HOSTILE,
                (_, "--speed") => SPEEDS,
                (_, "--misalignment") => ANGLES,
                _ => FORCES,
            };
            args.push(rng.pick(pool).to_string());
        }
    }
}

/// Every `key = value` line of the presets, as (key, value).
fn known_lines() -> Vec<(String, String)> {
    PRESETS
        .iter()
        .flat_map(|p| p.text.lines())
        .filter_map(|l| {
            let l = l.trim();
            if l.starts_with('#') || l.starts_with('[') {
                return None;
            }
            let (k, v) = l.split_once('=')?;
            Some((k.trim().to_string(), v.trim().to_string()))
        })
        .collect()
}

/// A quantity "x unit" with x scaled.
fn scaled(value: &str, factor: f64) -> Option<String> {
    let inner = value.strip_prefix('"')?.strip_suffix('"')?;
    let (number, unit) = inner.split_once(' ')?;
    let x: f64 = number.parse().ok()?;
    Some(format!("\"{:e} {unit}\"", x * factor))
}

/// A preset's text with 0–3 mutations (mostly a quantity scaled, which
/// keeps the file well-formed so that the solvers see absurd values).
fn mutated_case(rng: &mut Rng, known: &[(String, String)]) -> String {
    let text = match rng.below(PRESETS.len() + EXAMPLES.len() + 1) {
        i if i < PRESETS.len() => {
            let mut text = PRESETS[i].text.to_string();
            if rng.below(3) == 0 {
                let section: &str = rng.pick::<&str>(SECTIONS);
                text.push_str(section);
            }
            text
        }
        i if i < PRESETS.len() + EXAMPLES.len() => EXAMPLES[i - PRESETS.len()].to_string(),
        _ => common::SHAFT.replace("ORIENTATION", "reversed"),
    };
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    for _ in 0..rng.below(4) {
        let values: Vec<usize> = (0..lines.len())
            .filter(|&i| {
                let l = lines[i].trim();
                !l.starts_with('#') && !l.starts_with('[') && l.contains('=')
            })
            .collect();
        if values.is_empty() {
            break;
        }
        let i = *rng.pick(&values);
        let (key, value) = {
            let (k, v) = lines[i].split_once('=').unwrap();
            (k.trim().to_string(), v.trim().to_string())
        };
        match rng.below(12) {
            0 => lines[i] = format!("{key} = {}", rng.pick(NUMBERS)),
            1 => lines[i] = format!("{key} = {}", rng.pick(STRINGS)),
            2..=7 => {
                let factor = *rng.pick(FACTORS);
                if let Some(v) = scaled(&value, factor) {
                    lines[i] = format!("{key} = {v}");
                }
            }
            8 | 9 => {
                lines.remove(i);
            }
            10 => {
                // A key of another preset (another section's, perhaps).
                let (k, v) = rng.pick(known);
                let v = scaled(v, *rng.pick(FACTORS)).unwrap_or_else(|| v.clone());
                lines.insert(i, format!("{k} = {v}"));
            }
            _ => lines.insert(i, lines[i].clone()),
        }
    }
    lines.join("\n") + "\n"
}

/// `text` without `check`'s list of the case's assumptions, whose texts
/// it prints as written ("inf N" among them when fuzzed).
fn without_assumptions(text: &str) -> String {
    let mut inside = false;
    text.lines()
        .filter(|line| {
            if line.starts_with("Assumed values") {
                inside = true;
            } else if line.trim().is_empty() {
                inside = false;
            }
            !inside
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// Runs one case; its exit code, or what broke.
/// `fresh`: start from an empty output directory.
fn check_case(args: &[String], case: &str, dir: &Path, fresh: bool) -> Result<i32, String> {
    if fresh {
        std::fs::remove_dir_all(dir).ok();
    }
    let mut child = Command::new(env!("CARGO_BIN_EXE_rolldyn"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| e.to_string())?;
    {
        let mut pipe = child.stdin.take().unwrap();
        let _ = pipe.write_all(case.as_bytes()); // may exit before reading
    }
    // Drain the pipes on threads so that a chatty command cannot block.
    let mut out_pipe = child.stdout.take().unwrap();
    let mut err_pipe = child.stderr.take().unwrap();
    let out_thread = std::thread::spawn(move || {
        let mut s = String::new();
        std::io::Read::read_to_string(&mut out_pipe, &mut s).ok();
        s
    });
    let err_thread = std::thread::spawn(move || {
        let mut s = String::new();
        std::io::Read::read_to_string(&mut err_pipe, &mut s).ok();
        s
    });
    let begun = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().map_err(|e| e.to_string())? {
            break status;
        }
        if args[0] == "run" && begun.elapsed() > RUN_TIMEOUT {
            return interrupted(&mut child, dir);
        }
        if begun.elapsed() > TIMEOUT {
            child.kill().ok();
            child.wait().ok();
            return Err(format!("hang: no exit after {TIMEOUT:?}"));
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    let stdout = out_thread.join().unwrap_or_default();
    let stderr = err_thread.join().unwrap_or_default();
    let code = status.code();
    if stderr.contains("panicked") || !matches!(code, Some(0 | 2 | 3)) {
        return Err(format!("exit {code:?}: {stderr}"));
    }
    if code == Some(2) && !stderr.starts_with("error: ") {
        return Err(format!("exit 2 without an error message: {stderr:?}"));
    }
    // Every JSON writer names a non-finite number on standard error (an
    // integration that diverges says "non-finite" too: exit 3, fine).
    if stderr.contains("warning: non-finite number") {
        return Err(format!("non-finite output: {stderr}"));
    }
    if code == Some(0) && args.iter().any(|a| a == "--json") {
        serde_json::from_str::<Value>(&stdout)
            .map_err(|e| format!("invalid JSON ({e}): {stdout:.200}"))?;
    } else if let Some(word) = without_assumptions(&stdout)
        .split(|c: char| !(c.is_ascii_alphanumeric() || c == '.'))
        .find(|w| {
            matches!(
                w.to_ascii_lowercase().as_str(),
                "nan" | "inf" | "-inf" | "infinity"
            )
        })
    {
        return Err(format!(
            "non-finite number in the text output ({word}): {stdout:.400}"
        ));
    }
    if dir.exists() {
        for entry in std::fs::read_dir(dir).map_err(|e| e.to_string())? {
            let name = entry.map_err(|e| e.to_string())?.file_name();
            let name = name.to_string_lossy();
            if name.starts_with('.') {
                return Err(format!("partial file left: {name}"));
            }
            let path = dir.join(&*name);
            if name.ends_with(".json") {
                let text = std::fs::read_to_string(&path).map_err(|e| e.to_string())?;
                serde_json::from_str::<Value>(&text)
                    .map_err(|e| format!("{name} is not JSON: {e}"))?;
            }
            if name.ends_with(".csv") {
                let text = std::fs::read_to_string(&path).map_err(|e| e.to_string())?;
                let bad = text.split([',', '\n']).find(|f| {
                    matches!(
                        f.trim().to_ascii_lowercase().as_str(),
                        "nan" | "inf" | "-inf"
                    )
                });
                if let Some(f) = bad {
                    return Err(format!("{name} holds a non-finite number: {f}"));
                }
            }
            if name.ends_with(".parquet") {
                rolldyn_io::read_parquet(&path).map_err(|e| e.to_string())?;
            }
        }
    }
    Ok(code.unwrap_or(-1))
}

/// A `run` past [`RUN_TIMEOUT`]: Ctrl-C (SIGINT) must stop it within
/// [`GRACE`] with exit 130, an `interrupted` summary of the steps done and
/// a readable time series: slow ([`SLOW`]); else a hang.
fn interrupted(child: &mut std::process::Child, dir: &Path) -> Result<i32, String> {
    Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .map_err(|e| e.to_string())?;
    let asked = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().map_err(|e| e.to_string())? {
            break status;
        }
        if asked.elapsed() > GRACE {
            child.kill().ok();
            child.wait().ok();
            return Err(format!(
                "hang: no exit after {RUN_TIMEOUT:?}, nor {GRACE:?} after Ctrl-C"
            ));
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    if status.code() != Some(130) {
        return Err(format!(
            "interrupted run exited {:?}, not 130",
            status.code()
        ));
    }
    let text = std::fs::read_to_string(dir.join("summary.json"))
        .map_err(|e| format!("interrupted run left no summary: {e}"))?;
    let summary: Value = serde_json::from_str(&text).map_err(|e| e.to_string())?;
    let simulated = summary["simulated_time_s"].as_f64().unwrap_or(0.0);
    let steps = summary["steps"].as_f64().unwrap_or(0.0);
    if summary["status"] != "interrupted" || steps <= 0.0 {
        return Err(format!(
            "hang: interrupted after {RUN_TIMEOUT:?} without progress: {text:.300}"
        ));
    }
    rolldyn_io::read_parquet(&dir.join("timeseries.parquet"))
        .map_err(|e| format!("interrupted run's time series: {e}"))?;
    eprintln!(
        "fuzz: slow run interrupted after {RUN_TIMEOUT:?}: {steps} steps, {simulated:e} s simulated"
    );
    Ok(SLOW)
}

fn env_u64(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

#[test]
fn fuzzed_cases_and_flags_never_panic_hang_or_print_non_finite_numbers() {
    let cases = env_u64("ROLLDYN_FUZZ_CASES", CI_CASES);
    let seed = env_u64("ROLLDYN_FUZZ_SEED", 17);
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get()) as u64;
    let known = known_lines();
    let base = common::temp_dir("fuzz");
    let failures: Vec<String> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..threads)
            .map(|worker| {
                let known = &known;
                let base = &base;
                scope.spawn(move || {
                    let dir = base.join(format!("w{worker}"));
                    let d = dir.to_string_lossy().into_owned();
                    let mut failures = Vec::new();
                    let mut counts = std::collections::BTreeMap::new();
                    for n in (worker..cases).step_by(threads as usize) {
                        // One generator per case: reproducible from (seed, n).
                        let mut rng = Rng(seed ^ n.wrapping_mul(0x2545_f491_4f6c_dd1d));
                        let case = mutated_case(&mut rng, known);
                        let args = command(&mut rng, &d);
                        let mut result = check_case(&args, &case, &dir, true);
                        if matches!(result, Ok(SLOW)) {
                            // Not a failure; shown so that a slow input can
                            // be looked into.
                            eprintln!("fuzz: slow: seed {seed} case {n}: {args:?}\n{case}");
                        }
                        if args[0] == "run" && matches!(result, Ok(0)) {
                            *counts.entry(("run".to_string(), 0)).or_insert(0u64) += 1;
                            // The run's spectrum reads its files back.
                            let spectrum: Vec<String> =
                                ["spectrum", &d, "--json"].map(String::from).to_vec();
                            result = check_case(&spectrum, "", &dir, false)
                                .map_err(|e| format!("spectrum of the run: {e}"));
                            if let Ok(code) = result {
                                *counts.entry(("spectrum".to_string(), code)).or_insert(0u64) += 1;
                            }
                        } else if let Ok(code) = result {
                            *counts.entry((args[0].clone(), code)).or_insert(0u64) += 1;
                        }
                        if let Err(e) = result {
                            failures.push(format!(
                                "seed {seed} case {n}: {args:?}\n{e}\n--- case ---\n{case}"
                            ));
                        }
                    }
                    (failures, counts)
                })
            })
            .collect();
        let mut all = Vec::new();
        let mut counts = std::collections::BTreeMap::new();
        for h in handles {
            let (f, c) = h.join().unwrap();
            all.extend(f);
            for (k, v) in c {
                *counts.entry(k).or_insert(0u64) += v;
            }
        }
        // Coverage: how many cases each command ran to each exit code.
        for ((command, code), n) in &counts {
            if *code == SLOW {
                eprintln!("fuzz: {command:<12} slow (interrupted, progressing): {n}");
            } else {
                eprintln!("fuzz: {command:<12} exit {code}: {n}");
            }
        }
        all
    });
    std::fs::remove_dir_all(&base).ok();
    eprintln!(
        "fuzz: {cases} cases (seed {seed}), {} failures",
        failures.len()
    );
    assert!(
        failures.is_empty(),
        "{} of {cases} fuzzed cases failed:\n{}",
        failures.len(),
        failures.join("\n\n")
    );
}

#[test]
fn regressions_found_by_fuzzing_stay_fixed() {
    let dir = common::temp_dir("fuzz-regressions");
    let d = dir.to_string_lossy().into_owned();
    for (preset, args, expected) in REGRESSIONS {
        let case = PRESETS.iter().find(|p| p.name == *preset).unwrap().text;
        let args: Vec<String> = args.iter().map(|a| a.replace("{dir}", &d)).collect();
        let code = check_case(&args, case, &dir, true).unwrap_or_else(|e| panic!("{args:?}: {e}"));
        assert_eq!(code, *expected, "{args:?}");
    }
    std::fs::remove_dir_all(&dir).ok();
}
