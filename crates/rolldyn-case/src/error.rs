//! Case-file errors: what is wrong (key, value, rule) and where it came
//! from (file position, a command-line override, or a preset).

use std::collections::HashMap;
use std::fmt;
use std::ops::Range;

/// Where a bad value came from.
#[derive(Debug, Clone, PartialEq)]
pub enum Origin {
    /// A position in the case file (1-based line and column) and that line's text.
    File {
        /// 1-based line.
        line: usize,
        /// 1-based column (in characters).
        column: usize,
        /// The text of the line.
        line_text: String,
    },
    /// An override, described with its source (``command-line override
    /// `--set bearing.ball_count=22` ``, or a Python `Case.set`).
    Override(String),
    /// A value taken from a built-in preset or a catalogue bearing
    /// ("preset 6304", "catalogue bearing 6205").
    Preset(String),
    /// No position known (e.g. a key that is missing from an empty file).
    Unknown,
}

/// A rejected case file. Displays as
/// `case.toml:12:17: bearing.ball_diameter = "6.35 mmm": unknown unit ...`
/// followed by the offending line and a caret.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub struct CaseError {
    /// Name of the case source (`case.toml`, `<stdin>`, `built-in default`).
    pub source_name: String,
    /// Where in that source (boxed: errors travel on the cold path and a
    /// small `Result` keeps the happy path lean).
    pub origin: Box<Origin>,
    /// The dotted key, when the error concerns one.
    pub key: Option<String>,
    /// The offending value as written, when there is one.
    pub value: Option<String>,
    /// The rule that was broken.
    pub rule: String,
}

impl fmt::Display for CaseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.origin.as_ref() {
            Origin::File { line, column, .. } => {
                write!(f, "{}:{line}:{column}: ", self.source_name)?
            }
            Origin::Override(text) => write!(f, "{text}: ")?,
            Origin::Preset(name) => write!(f, "{} (value from {name}): ", self.source_name)?,
            Origin::Unknown => write!(f, "{}: ", self.source_name)?,
        }
        match (&self.key, &self.value) {
            (Some(k), Some(v)) => write!(f, "{k} = {v}: ")?,
            (Some(k), None) => write!(f, "{k}: ")?,
            _ => {}
        }
        f.write_str(&self.rule)?;
        if let Origin::File {
            line,
            column,
            line_text,
        } = self.origin.as_ref()
        {
            let gutter = line.to_string().len();
            write!(
                f,
                "\n{:gutter$} |\n{line} | {line_text}\n{:gutter$} | {}^",
                "",
                "",
                " ".repeat(column.saturating_sub(1))
            )?;
        }
        Ok(())
    }
}

/// Byte spans of every key's value in a TOML text, by dotted path
/// (`bearing.ball_diameter`, `operating.speed_profile[1].time`).
#[derive(Debug, Clone, Default)]
pub struct SpanMap {
    spans: HashMap<String, Range<usize>>,
}

impl SpanMap {
    /// Collects spans from a parsed document.
    pub fn from_document(table: &toml::de::DeTable<'_>) -> Self {
        let mut map = Self::default();
        map.walk_table("", table);
        map
    }

    fn walk_table(&mut self, prefix: &str, table: &toml::de::DeTable<'_>) {
        for (key, value) in table.iter() {
            let path = if prefix.is_empty() {
                key.get_ref().to_string()
            } else {
                format!("{prefix}.{}", key.get_ref())
            };
            self.walk_value(&path, value);
        }
    }

    fn walk_value(&mut self, path: &str, value: &toml::Spanned<toml::de::DeValue<'_>>) {
        self.spans.insert(path.to_string(), value.span());
        match value.get_ref() {
            toml::de::DeValue::Table(t) => self.walk_table(path, t),
            toml::de::DeValue::Array(items) => {
                for (i, item) in items.iter().enumerate() {
                    self.walk_value(&format!("{path}[{i}]"), item);
                }
            }
            _ => {}
        }
    }

    /// Span of `path`, or of its nearest enclosing key that has one.
    pub fn find(&self, path: &str) -> Option<Range<usize>> {
        let mut p = path;
        loop {
            if let Some(span) = self.spans.get(p) {
                return Some(span.clone());
            }
            let cut = p.rfind(['.', '['])?;
            p = &p[..cut];
        }
    }

    /// The innermost key whose value spans byte offset `at` (a value
    /// the TOML reader refused after parsing, e.g. a float that
    /// overflows).
    pub fn key_at(&self, at: usize) -> Option<String> {
        self.spans
            .iter()
            .filter(|(_, span)| span.contains(&at))
            .min_by_key(|(key, span)| (span.len(), key.len()))
            .map(|(key, _)| key.clone())
    }

    /// Whether `path` itself (not a parent) appears in the document.
    pub fn contains(&self, path: &str) -> bool {
        self.spans.contains_key(path)
    }

    /// The source text of `path`'s value, if it is a short one-line value.
    pub fn value_text<'t>(&self, path: &str, text: &'t str) -> Option<&'t str> {
        let span = self.spans.get(path)?;
        let value = text.get(span.clone())?.trim();
        (!value.contains('\n') && value.len() <= 80).then_some(value)
    }
}

/// 1-based line and column of byte offset `pos` in `text`, with the line.
pub fn position(text: &str, pos: usize) -> Origin {
    let pos = pos.min(text.len());
    let before = &text[..pos];
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let line_end = text[pos..].find('\n').map_or(text.len(), |i| pos + i);
    Origin::File {
        line,
        column: text[line_start..pos].chars().count() + 1,
        line_text: text[line_start..line_end]
            .trim_end_matches('\r')
            .to_string(),
    }
}
