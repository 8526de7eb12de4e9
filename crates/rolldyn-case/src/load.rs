//! From text to a validated [`Case`]: parse (with spans), apply
//! command-line overrides, merge a `bearing.preset`, deserialize with the
//! key path of any error, validate, and map every error back to where the
//! value came from.

use crate::case::{Case, Invalid, PARAMETRIZATIONS};
use crate::catalogue::{CatalogueBearing, CatalogueError};
use crate::error::{CaseError, Origin, SpanMap, position};
use crate::presets;
use crate::raw::RawCase;
use std::collections::BTreeMap;
use toml::{Table, Value};

/// One command-line override of a case key.
#[derive(Debug, Clone, PartialEq)]
pub struct Override {
    /// Dotted key, e.g. `operating.speed`.
    pub key: String,
    /// New value.
    pub value: Value,
    /// Where it came from and how the user wrote it, for messages
    /// (``command-line override `--set bearing.ball_count=22` ``).
    pub text: String,
}

/// Where an assignment override came from, for messages.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum OverrideSource {
    /// `--set key=value` on the command line.
    #[default]
    CommandLine,
    /// `Case.set(key, value)` in the Python package.
    Python,
    /// A point's value of `rolldyn run --sweep`.
    Sweep,
}

impl OverrideSource {
    /// How a message names the assignment `text` (`key=value`).
    fn describe(self, text: &str) -> String {
        match self {
            Self::CommandLine => format!("command-line override `--set {text}`"),
            Self::Python => format!("override `{text}` (Case.set)"),
            Self::Sweep => format!("`--sweep` value `{text}`"),
        }
    }
}

impl Override {
    /// Parses `dotted.key=value` given with `--set`. The value is read as
    /// a TOML value when it is one (`22`, `0.52`, `true`, `"6.35 mm"`,
    /// `{ law = "hertz" }`) and as a plain string otherwise (`6.35 mm`).
    pub fn parse_set(arg: &str) -> Result<Self, CaseError> {
        Self::parse_from(arg, OverrideSource::CommandLine)
    }

    /// As [`Self::parse_set`], for an assignment from `source`.
    pub fn parse_from(arg: &str, source: OverrideSource) -> Result<Self, CaseError> {
        let Some((key, raw)) = arg.split_once('=') else {
            return Err(CaseError {
                source_name: "command line".into(),
                origin: Box::new(Origin::Override(source.describe(arg))),
                key: None,
                value: None,
                rule: "expected dotted.key=value, e.g. bearing.ball_count=22".into(),
            });
        };
        let key = key.trim();
        let raw = raw.trim();
        Ok(Self {
            key: key.to_string(),
            value: Self::value_from_text(raw),
            text: source.describe(&format!("{key}={raw}")),
        })
    }

    /// A value as `--set` reads its text: a TOML value when it is one
    /// (`22`, `true`, `"6.35 mm"`, `{ law = "hertz" }`), the text itself
    /// as a string otherwise (`6.35 mm`).
    pub fn value_from_text(raw: &str) -> Value {
        toml::from_str::<Table>(&format!("v = {raw}"))
            .ok()
            .and_then(|mut t| t.remove("v"))
            .unwrap_or_else(|| Value::String(raw.to_string()))
    }

    /// A typed value for `key` from `source`: a number (`0.1`), or a
    /// quantity as case files write it (`String::from("523.6 rad/s")`).
    pub fn typed(key: &str, value: impl Into<Value>, source: OverrideSource) -> Self {
        let value = value.into();
        let text = source.describe(&format!("{key}={value}"));
        Self {
            key: key.to_string(),
            value,
            text,
        }
    }

    /// A string-valued override from a dedicated flag (`--speed 8000rpm`).
    pub fn flag(flag: &str, key: &str, value: &str) -> Self {
        Self {
            key: key.to_string(),
            value: Value::String(value.to_string()),
            text: format!("command-line override `{flag} {value}`"),
        }
    }
}

/// Keys that replace each other within a table: setting one removes the
/// others (the later source wins instead of conflicting).
fn displaced_keys(table_path: &str, key: &str) -> Vec<&'static str> {
    match (table_path, key) {
        ("operating", "speed") => vec!["speed_profile"],
        ("operating", "speed_profile") => vec!["speed"],
        ("operating", "force_y" | "force_z") => vec!["radial_load", "radial_load_angle"],
        ("operating", "radial_load") => vec!["force_y", "force_z"],
        ("operating", "tilt_y") => vec!["moment_y"],
        ("operating", "tilt_z") => vec!["moment_z"],
        ("operating", "moment_y") => vec!["tilt_y", "fixed_tilt"],
        ("operating", "moment_z") => vec!["tilt_z", "fixed_tilt"],
        ("operating", "fixed_tilt") => vec!["moment_y", "moment_z"],
        ("operating", "displacement_x") => vec!["force_x"],
        ("operating", "force_x") => vec!["displacement_x"],
        ("bearing", "inner_groove_curvature") => vec!["inner_groove_radius"],
        ("bearing", "inner_groove_radius") => vec!["inner_groove_curvature"],
        ("bearing", "outer_groove_curvature") => vec!["outer_groove_radius"],
        ("bearing", "outer_groove_radius") => vec!["outer_groove_curvature"],
        ("bearing", k) => match PARAMETRIZATIONS.iter().position(|g| g.contains(&k)) {
            Some(i) => {
                let mut out: Vec<&'static str> = PARAMETRIZATIONS
                    .iter()
                    .enumerate()
                    .filter(|(j, _)| *j != i)
                    .flat_map(|(_, g)| g.iter().copied())
                    .collect();
                if i == 2 {
                    out.push("pitch_diameter");
                }
                out
            }
            None => vec![],
        },
        _ => vec![],
    }
}

/// Sets `value` at `path` (creating tables), removing displaced keys; the
/// dotted paths of those it removed go to `displaced`. A number after an
/// array of tables picks its entry, from 0 (`surface.outer.spall.0.length`).
fn set_path(
    table: &mut Table,
    path: &str,
    value: Value,
    displaced: &mut Vec<String>,
) -> Result<(), String> {
    let parts: Vec<&str> = path.split('.').collect();
    let (leaf, parents) = parts.split_last().ok_or("empty key")?;
    let mut current = table;
    let mut i = 0;
    while i < parents.len() {
        // An index into an array the case does not have: the array cannot
        // be made an entry at a time.
        let next = parents.get(i + 1).unwrap_or(leaf);
        if !current.contains_key(parents[i]) && next.parse::<usize>().is_ok() {
            let array = parts[..=i].join(".");
            return Err(format!(
                "the case has no {array}: an index ({next}) names an entry of an array of tables the case has; give the array whole, e.g. --set '{array}=[{{ ... }}]'"
            ));
        }
        let entry = current
            .entry(parents[i].to_string())
            .or_insert_with(|| Value::Table(Table::new()));
        let entry = match entry {
            Value::Array(items) => {
                let array = parts[..=i].join(".");
                let index = parents
                    .get(i + 1)
                    .and_then(|n| n.parse::<usize>().ok())
                    .ok_or_else(|| {
                        format!(
                            "{array} is an array of tables: name an entry, e.g. {array}.0.<key>"
                        )
                    })?;
                let count = items.len();
                i += 1;
                items.get_mut(index).ok_or_else(|| {
                    format!(
                        "{array} has {count} {}: index {index} is beyond (they count from 0)",
                        if count == 1 { "entry" } else { "entries" }
                    )
                })?
            }
            other => other,
        };
        current = entry
            .as_table_mut()
            .ok_or_else(|| format!("{} is not a table", parts[..=i].join(".")))?;
        i += 1;
    }
    let table_path = parents.join(".");
    for k in displaced_keys(&table_path, leaf) {
        if current.remove(k).is_some() {
            displaced.push(format!("{table_path}.{k}"));
        }
    }
    current.insert(leaf.to_string(), value);
    Ok(())
}

/// Overlays `top` on `base`, table by table, removing displaced keys (their
/// dotted paths to `displaced`).
fn overlay(base: &mut Table, top: &Table, path: &str, displaced: &mut Vec<String>) {
    for (k, v) in top {
        let child = if path.is_empty() {
            k.clone()
        } else {
            format!("{path}.{k}")
        };
        match (base.get_mut(k), v) {
            (Some(Value::Table(b)), Value::Table(t)) => overlay(b, t, &child, displaced),
            _ => {
                for d in displaced_keys(path, k) {
                    if base.remove(d).is_some() {
                        displaced.push(format!("{path}.{d}"));
                    }
                }
                base.insert(k.clone(), v.clone());
            }
        }
    }
}

/// Every leaf path of a table (`bearing.ball_diameter`, ...).
fn leaf_paths(table: &Table, prefix: &str, out: &mut Vec<String>) {
    for (k, v) in table {
        let p = if prefix.is_empty() {
            k.clone()
        } else {
            format!("{prefix}.{k}")
        };
        match v {
            Value::Table(t) if prefix != "assumptions" && k != "assumptions" => {
                leaf_paths(t, &p, out)
            }
            _ => out.push(p),
        }
    }
}

fn has_path(table: &Table, path: &str) -> bool {
    let mut current = table;
    let parts: Vec<&str> = path.split('.').collect();
    for (i, part) in parts.iter().enumerate() {
        match current.get(*part) {
            Some(Value::Table(t)) if i + 1 < parts.len() => current = t,
            Some(_) if i + 1 == parts.len() => return true,
            _ => return false,
        }
    }
    false
}

/// Sections a `bearing.preset` brings in.
const PRESET_SECTIONS: [&str; 3] = ["bearing", "cage", "materials"];

/// The key of the pockets' squeeze film, which a `bearing.preset` brings
/// only into a case with a `[lubricant]`.
const POCKET_SQUEEZE_FILM: &str = "cage.pocket_squeeze_film";

struct Sources<'a> {
    name: &'a str,
    text: &'a str,
    spans: SpanMap,
    overrides: BTreeMap<String, (String, String)>,
    preset: Option<(String, Table)>,
}

impl Sources<'_> {
    /// The override that set `key` (or a table containing it).
    fn override_of(&self, key: &str) -> Option<(&String, &(String, String))> {
        self.overrides.iter().find(|(o, _)| {
            key == o.as_str()
                || key.starts_with(&format!("{o}."))
                || key.starts_with(&format!("{o}["))
        })
    }

    /// The override that sets a key inside table `key`, if any.
    fn override_within(&self, key: &str) -> Option<(&String, &(String, String))> {
        self.overrides
            .iter()
            .find(|(o, _)| o.starts_with(&format!("{key}.")))
    }

    /// An error about `key`, located at its source; a missing `value` is
    /// filled in from the source text.
    fn error(&self, key: Option<String>, value: Option<String>, rule: String) -> CaseError {
        let (origin, found) = match key.as_deref() {
            None => (Origin::Unknown, None),
            Some(k) => {
                if let Some((set_key, (text, v))) = self.override_of(k) {
                    (
                        Origin::Override(text.clone()),
                        (set_key == k).then(|| v.clone()),
                    )
                } else if self.spans.contains(k) {
                    let at = self
                        .spans
                        .find(k)
                        .map_or(Origin::Unknown, |s| position(self.text, s.start));
                    (at, self.spans.value_text(k, self.text).map(str::to_string))
                } else if let Some((_, (text, _))) = self.override_within(k) {
                    // A table only an override made (an unknown section, a
                    // section missing what the override does not give).
                    (Origin::Override(text.clone()), None)
                } else if let Some((name, _)) = self.preset.as_ref().filter(|(_, t)| has_path(t, k))
                {
                    (Origin::Preset(name.clone()), None)
                } else {
                    (
                        self.spans
                            .find(k)
                            .map_or(Origin::Unknown, |s| position(self.text, s.start)),
                        None,
                    )
                }
            }
        };
        CaseError {
            source_name: self.name.to_string(),
            origin: Box::new(origin),
            key,
            value: value.or(found),
            rule,
        }
    }
}

/// The bearing a case builds on: `bearing.preset` (a built-in case) or
/// `bearing.catalogue` with `bearing.clearance_group` (a catalogue
/// bearing's generated case, docs/catalogue.md): its name for messages
/// and its case text. None when the case gives its own geometry. Errors
/// name the keys under `prefix` (`bearing`, or `shaft.bearings[0]` when
/// the shaft's first bearing stands in).
fn base_bearing(
    table: &Table,
    sources: &Sources,
    prefix: &str,
) -> Result<Option<(String, String)>, CaseError> {
    let Some(bearing) = table.get("bearing").and_then(|b| b.as_table()) else {
        return Ok(None);
    };
    let text_of = |key: &str| -> Result<Option<String>, CaseError> {
        bearing
            .get(key)
            .map(|v| {
                v.as_str().map(str::to_string).ok_or_else(|| {
                    sources.error(
                        Some(format!("{prefix}.{key}")),
                        Some(v.to_string()),
                        "must be a string".into(),
                    )
                })
            })
            .transpose()
    };
    let (preset, designation, group) = (
        text_of("preset")?,
        text_of("catalogue")?,
        text_of("clearance_group")?,
    );
    if group.is_some() && designation.is_none() {
        return Err(sources.error(
            Some(format!("{prefix}.clearance_group")),
            group,
            "a clearance group applies to a catalogue bearing: give bearing.catalogue, or bearing.diametral_clearance".into(),
        ));
    }
    match (preset, designation) {
        (Some(_), Some(d)) => Err(sources.error(
            Some(format!("{prefix}.catalogue")),
            Some(format!("\"{d}\"")),
            "give either bearing.preset or bearing.catalogue, not both".into(),
        )),
        (Some(name), None) => {
            let preset = presets::find(&name).ok_or_else(|| {
                sources.error(
                    Some(format!("{prefix}.preset")),
                    Some(format!("\"{name}\"")),
                    format!("unknown preset; available: {}", presets::names()),
                )
            })?;
            Ok(Some((
                format!("preset {}", preset.name),
                preset.text.to_string(),
            )))
        }
        (None, Some(d)) => {
            let found = CatalogueBearing::lookup(&d, group.as_deref()).map_err(|e| {
                let (key, value) = match &e {
                    CatalogueError::Designation { designation, .. } => {
                        ("catalogue", designation.clone())
                    }
                    CatalogueError::Clearance { group, .. } => ("clearance_group", group.clone()),
                };
                sources.error(
                    Some(format!("{prefix}.{key}")),
                    Some(format!("\"{value}\"")),
                    e.to_string(),
                )
            })?;
            let text = found.case_text().map_err(|e| {
                sources.error(
                    Some(format!("{prefix}.catalogue")),
                    Some(d.clone()),
                    e.to_string(),
                )
            })?;
            Ok(Some((
                format!("catalogue bearing {}", found.designation),
                text,
            )))
        }
        (None, None) => Ok(None),
    }
}

/// A `[shaft]` system names its bearings (presets, catalogue or inline
/// bearings); without a `[bearing]` of its own, the first of them stands
/// in for the case's bearing (inserted into `table`). The key the
/// bearing's errors are named by.
fn shaft_bearing_stand_in(table: &mut Table) -> &'static str {
    let mut bearing_key = "bearing";
    if !table.contains_key("bearing") {
        let first = table
            .get("shaft")
            .and_then(|s| s.get("bearings"))
            .and_then(|b| b.as_array())
            .and_then(|b| b.first())
            .and_then(|b| b.as_table());
        if let Some(first) = first {
            let bearing: Table = match first.get("bearing").and_then(|b| b.as_table()) {
                // An inline bearing stands in as it is.
                Some(inline) => inline.clone(),
                None => ["preset", "catalogue", "clearance_group"]
                    .iter()
                    .filter_map(|k| first.get(*k).map(|v| (k.to_string(), v.clone())))
                    .collect(),
            };
            if !bearing.is_empty() {
                table.insert("bearing".into(), Value::Table(bearing));
                bearing_key = "shaft.bearings[0]";
            }
        }
    }
    bearing_key
}

/// The case `table` laid over the preset or catalogue bearing
/// `base_text` (named `name`): the base's case sections, its assumptions
/// on keys the case does not set, then the case's own keys.
fn on_base(
    table: &Table,
    name: &str,
    base_text: &str,
    sources: &Sources,
    bearing_key: &str,
    displaced: &mut Vec<String>,
) -> Result<Table, CaseError> {
    let key = Some(bearing_key.to_string());
    let base_table: Table = toml::from_str(base_text)
        .map_err(|e| sources.error(key.clone(), None, format!("{name} does not parse: {e}")))?;
    let mut merged = Table::new();
    for section in PRESET_SECTIONS {
        if let Some(v) = base_table.get(section) {
            merged.insert(section.to_string(), v.clone());
        }
    }
    // The pockets' squeeze film is of the preset's oil: a case without a
    // [lubricant] takes the cage without it (docs/case-format.md,
    // `bearing.preset`).
    let dry = !table.contains_key("lubricant");
    if dry && let Some(Value::Table(cage)) = merged.get_mut("cage") {
        cage.remove(POCKET_SQUEEZE_FILM.trim_start_matches("cage."));
    }
    let mut user_leaves = Vec::new();
    leaf_paths(table, "", &mut user_leaves);
    if let Some(Value::Table(assumed)) = base_table.get("assumptions") {
        let inherited: Table = assumed
            .iter()
            .filter(|(k, _)| {
                PRESET_SECTIONS
                    .iter()
                    .any(|s| k.starts_with(&format!("{s}.")))
            })
            .filter(|(k, _)| !(dry && k.as_str() == POCKET_SQUEEZE_FILM))
            .filter(|(k, _)| !user_leaves.contains(k))
            .map(|(k, v)| (k.clone(), v.clone()))
            .collect();
        merged.insert("assumptions".into(), Value::Table(inherited));
    }
    overlay(&mut merged, table, "", displaced);
    Ok(merged)
}

/// Loads and validates a case from `text` (named `source_name` in messages),
/// applying `overrides` in order.
pub fn load_case(source_name: &str, text: &str, overrides: &[Override]) -> Result<Case, CaseError> {
    // A set or a shaft is its own mounting: a single bearing's mounting
    // lines (from a preset's or a catalogue bearing's file) are left out,
    // blanked so that line numbers stay those of the file.
    let system = |t: &Table| t.contains_key("arrangement") || t.contains_key("shaft");
    let unmounted;
    let text = if text.contains(crate::presets::MOUNTING_TAG)
        && (overrides
            .iter()
            .any(|o| o.key.starts_with("arrangement") || o.key.starts_with("shaft"))
            || toml::from_str::<Table>(text).is_ok_and(|t| system(&t)))
    {
        unmounted = crate::presets::without_mounting(text);
        unmounted.as_str()
    } else {
        text
    };
    let document = toml::de::DeTable::parse(text).map_err(|e| CaseError {
        source_name: source_name.to_string(),
        origin: Box::new(
            e.span()
                .map_or(Origin::Unknown, |s| position(text, s.start)),
        ),
        key: None,
        value: None,
        rule: format!("TOML syntax error: {}", e.message().trim()),
    })?;
    let mut sources = Sources {
        name: source_name,
        text,
        spans: SpanMap::from_document(document.get_ref()),
        overrides: BTreeMap::new(),
        preset: None,
    };
    let mut table: Table = toml::from_str(text).map_err(|e| {
        // Located by its span: a number that overflows passes the parse.
        let key = e.span().and_then(|s| sources.spans.key_at(s.start));
        let message = e.message().trim();
        let rule = if message.contains("overflowed") {
            "the number is too large for a 64-bit float (largest 1.8e308)".to_string()
        } else if message.contains("as i128") {
            "the integer is too large (largest 9223372036854775807)".to_string()
        } else {
            message.to_string()
        };
        let mut error = sources.error(key, None, rule);
        if let (Origin::Unknown, Some(span)) = (error.origin.as_ref(), e.span()) {
            error.origin = Box::new(position(text, span.start));
        }
        error
    })?;

    // Keys an override or the case removed from what it builds on (a
    // radial_load replaced by force_z): their assumptions go with them.
    let mut displaced = Vec::new();
    for o in overrides {
        set_path(&mut table, &o.key, o.value.clone(), &mut displaced).map_err(|rule| {
            let mut error = sources.error(Some(o.key.clone()), Some(o.value.to_string()), rule);
            error.origin = Box::new(Origin::Override(o.text.clone()));
            error
        })?;
        sources
            .overrides
            .insert(o.key.clone(), (o.text.clone(), o.value.to_string()));
    }

    let bearing_key = shaft_bearing_stand_in(&mut table);
    if let Some((name, base_text)) = base_bearing(&table, &sources, bearing_key)? {
        let merged = on_base(
            &table,
            &name,
            &base_text,
            &sources,
            bearing_key,
            &mut displaced,
        )?;
        sources.preset = Some((name, merged.clone()));
        table = merged;
    }

    // A value given on the command line is no longer an assumption, nor
    // is one it displaced.
    if let Some(Value::Table(assumed)) = table.get_mut("assumptions") {
        for key in sources.overrides.keys().chain(&displaced) {
            assumed.remove(key);
        }
    }

    let raw: RawCase = serde_path_to_error::deserialize(table.clone()).map_err(|e| {
        let path = e.path().to_string();
        let message = e.inner().message().to_string();
        let rule = message
            .split("\nin `")
            .next()
            .unwrap_or(&message)
            .trim()
            .to_string();
        sources.error((path != ".").then_some(path), None, rule)
    })?;

    for key in raw.assumptions.keys() {
        if !has_path(&table, key) {
            return Err(sources.error(
                Some(format!("assumptions.{key}")),
                None,
                format!("names a key that this case does not set (`{key}`); assumptions must refer to values in the case"),
            ));
        }
    }

    Case::from_raw(&raw)
        .map_err(|Invalid { key, value, rule }| sources.error(Some(key), value, rule))
}

/// The built-in default case (the 7008C preset) with `overrides`.
pub fn load_default(overrides: &[Override]) -> Result<Case, CaseError> {
    let preset = presets::find(presets::DEFAULT_PRESET).map_or("", |p| p.text);
    load_case("built-in default case (7008C)", preset, overrides)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_number_after_an_array_of_tables_picks_its_entry() {
        let mut table: Table = toml::from_str(
            "[[surface.outer.spall]]\nlength = \"1 mm\"\n[[surface.outer.spall]]\nlength = \"2 mm\"\n",
        )
        .unwrap();
        let mut displaced = Vec::new();
        set_path(
            &mut table,
            "surface.outer.spall.1.length",
            Value::from("3 mm"),
            &mut displaced,
        )
        .unwrap();
        let spalls = table["surface"]["outer"]["spall"].as_array().unwrap();
        assert_eq!(spalls[0]["length"].as_str(), Some("1 mm"));
        assert_eq!(spalls[1]["length"].as_str(), Some("3 mm"));
        let mut set = |path: &str| set_path(&mut table, path, Value::from(1), &mut displaced);
        let beyond = set("surface.outer.spall.2.length");
        assert!(beyond.unwrap_err().contains("has 2 entries"));
        let unnamed = set("surface.outer.spall.length");
        assert!(unnamed.unwrap_err().contains("name an entry"));
    }

    #[test]
    fn a_key_displaced_by_an_override_takes_its_assumption_along() {
        let text = "[operating]\nspeed = \"1000 rpm\"\nradial_load = \"500 N\"\n\
                    radial_load_angle = \"-90 deg\"\n\n[assumptions]\n\
                    \"operating.radial_load\" = \"not published\"\n";
        let mut table: Table = toml::from_str(text).unwrap();
        let mut displaced = Vec::new();
        set_path(
            &mut table,
            "operating.force_z",
            Value::from("200 N"),
            &mut displaced,
        )
        .unwrap();
        assert_eq!(
            displaced,
            ["operating.radial_load", "operating.radial_load_angle"]
        );
        assert!(!has_path(&table, "operating.radial_load"));
        // The whole load: the CWRU example states an assumption on its
        // radial_load; `--radial-load` (force_z) replaces both.
        let cwru = include_str!("../../../examples/cwru6205/case.toml");
        let flag = Override::flag("--radial-load", "operating.force_z", "-200 N");
        let case = load_case("cwru6205", cwru, &[flag]).unwrap();
        assert_eq!(case.loads.force[2], -200.0);
    }
}
