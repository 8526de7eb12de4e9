//! rolldyn reports: one self-contained HTML file per run or sweep
//! directory (`rolldyn report DIR`, `rolldyn run --report`).
//!
//! The page is built from [`Section`]s, each a list of [`Block`]s
//! (paragraphs, tables, preformatted text, plots as inline SVG from
//! [`svg`]). Nothing is loaded from the network and no script runs: the
//! file opens the same in any browser, offline, and can be mailed or
//! archived with the results. The markup is well-formed XML (every
//! element closed, text escaped), which the tests check with an XML
//! parser.
//!
//! A run report ([`run`]) and a sweep report ([`sweep`]) are lists of
//! section builders; a later model adds its section by adding one
//! function to its list.

pub mod run;
pub mod run_data;
pub mod set;
pub mod svg;
pub mod sweep;
pub mod vibration;
pub mod vibration_data;

use rolldyn_io::RunDir;
use std::fmt::Write;
use std::path::Path;
use svg::{Plot, escape};

/// Why a report could not be made.
#[derive(Debug, thiserror::Error)]
pub enum ReportError {
    /// The directory holds neither a run nor a sweep.
    #[error(
        "{dir}: not a run or sweep directory (expected summary.json and timeseries.parquet from `rolldyn run`, or sweep.json from a sweep)"
    )]
    NotAResultDirectory {
        /// The directory.
        dir: String,
    },
    /// A result file could not be read.
    #[error("{path}: {message}")]
    Read {
        /// The file.
        path: String,
        /// Cause.
        message: String,
    },
}

/// One block of a section.
#[derive(Debug, Clone, PartialEq)]
pub enum Block {
    /// A paragraph of plain text.
    Paragraph(String),
    /// A table: header and rows of cells (plain text).
    Table {
        /// Column headings.
        header: Vec<String>,
        /// Rows of cells.
        rows: Vec<Vec<String>>,
    },
    /// Preformatted text (case file, check report).
    Pre {
        /// Summary line of the collapsible block.
        summary: String,
        /// The text.
        text: String,
    },
    /// A plot.
    Figure(Plot),
}

/// A section of a report.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    /// Anchor id (stable: tests and links use it).
    pub id: &'static str,
    /// Heading.
    pub title: String,
    /// Content.
    pub blocks: Vec<Block>,
}

impl Section {
    /// An empty section.
    pub fn new(id: &'static str, title: impl Into<String>) -> Self {
        Self {
            id,
            title: title.into(),
            blocks: Vec::new(),
        }
    }

    /// Adds a paragraph.
    pub fn paragraph(mut self, text: impl Into<String>) -> Self {
        self.blocks.push(Block::Paragraph(text.into()));
        self
    }

    /// Adds a plot if it has data to draw.
    pub fn figure(mut self, plot: Plot) -> Self {
        if plot.has_data() {
            self.blocks.push(Block::Figure(plot));
        }
        self
    }

    /// Adds a table if it has rows.
    pub fn table(mut self, header: &[&str], rows: Vec<Vec<String>>) -> Self {
        if !rows.is_empty() {
            self.blocks.push(Block::Table {
                header: header.iter().map(|h| h.to_string()).collect(),
                rows,
            });
        }
        self
    }
}

/// A report: a title, a subtitle and sections.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// Page title.
    pub title: String,
    /// Line under the title (source, status).
    pub subtitle: String,
    /// Warnings shown in a banner under the title (an unconverged run).
    pub warnings: Vec<String>,
    /// Sections in order.
    pub sections: Vec<Section>,
}

const STYLE: &str = "body{font-family:system-ui,-apple-system,'Segoe UI',sans-serif;margin:0 auto;max-width:1000px;padding:1em 2em;color:#222}\
h1{font-size:1.5em;margin-bottom:0.2em}h2{border-bottom:1px solid #ccc;padding-bottom:0.2em;margin-top:1.6em}\
p.subtitle{color:#555;margin-top:0}nav ul{columns:3;list-style:none;padding:0}\
table{border-collapse:collapse;margin:0.6em 0;font-size:0.92em}th,td{border:1px solid #ccc;padding:0.2em 0.6em;text-align:right;overflow-wrap:anywhere}\
th{background:#f2f2f2}td:first-child,th:first-child{text-align:left}\
pre{background:#f7f7f7;padding:0.6em;overflow-x:auto;font-size:0.85em}\
svg.plot{display:block;max-width:100%;height:auto;margin:0.8em 0;font-size:11px;font-family:system-ui,sans-serif}\
svg .grid{stroke:#e4e4e4;stroke-width:1}svg .frame{fill:none;stroke:#555;stroke-width:1}\
svg .title{font-size:13px;font-weight:600}svg .legend-box{fill:#fff;fill-opacity:0.85;stroke:#ccc}svg text{fill:#222}\
footer{color:#777;font-size:0.85em;margin-top:2em}\
div.warning{background:#fff4e5;border:1px solid #e8a33d;border-left:6px solid #e8a33d;padding:0.5em 1em;margin:0.8em 0}";

impl Report {
    /// The page: well-formed, self-contained HTML.
    pub fn to_html(&self) -> String {
        let mut out = String::new();
        let _ = write!(
            out,
            "<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\"><head><meta charset=\"utf-8\"/><title>{}</title><style>{STYLE}</style></head><body>",
            escape(&self.title)
        );
        let _ = write!(
            out,
            "<h1>{}</h1><p class=\"subtitle\">{}</p>",
            escape(&self.title),
            escape(&self.subtitle)
        );
        for w in &self.warnings {
            let _ = write!(
                out,
                "<div class=\"warning\" role=\"alert\"><strong>Warning:</strong> {}</div>",
                escape(w)
            );
        }
        out.push_str("<nav><ul>");
        for s in &self.sections {
            let _ = write!(
                out,
                "<li><a href=\"#{}\">{}</a></li>",
                s.id,
                escape(&s.title)
            );
        }
        out.push_str("</ul></nav>");
        for s in &self.sections {
            let _ = write!(
                out,
                "<section id=\"{}\"><h2>{}</h2>",
                s.id,
                escape(&s.title)
            );
            for b in &s.blocks {
                block_html(&mut out, b);
            }
            out.push_str("</section>");
        }
        let _ = writeln!(
            out,
            "<footer>Made by rolldyn {} (`rolldyn report`). Plots and tables are computed from the files in this directory.</footer></body></html>",
            env!("CARGO_PKG_VERSION")
        );
        out
    }
}

fn block_html(out: &mut String, block: &Block) {
    match block {
        Block::Paragraph(text) => {
            let _ = write!(out, "<p>{}</p>", escape(text));
        }
        Block::Table { header, rows } => {
            out.push_str("<table><thead><tr>");
            for h in header {
                let _ = write!(out, "<th>{}</th>", escape(h));
            }
            out.push_str("</tr></thead><tbody>");
            for row in rows {
                out.push_str("<tr>");
                for cell in row {
                    let _ = write!(out, "<td>{}</td>", escape(cell));
                }
                out.push_str("</tr>");
            }
            out.push_str("</tbody></table>");
        }
        Block::Pre { summary, text } => {
            let _ = write!(
                out,
                "<details><summary>{}</summary><pre>{}</pre></details>",
                escape(summary),
                escape(text)
            );
        }
        Block::Figure(plot) => {
            let _ = write!(out, "<figure>{}</figure>", plot.to_svg());
        }
    }
}

/// The report of a result directory: a run (`summary.json` and
/// `timeseries.parquet`) or a sweep (`sweep.json`). `case_description`
/// is the case as the CLI describes it (`rolldyn check`), when known.
pub fn report_for(dir: &Path, case_description: Option<String>) -> Result<Report, ReportError> {
    if RunDir::new(dir).has_sweep() {
        sweep::report(dir)
    } else if RunDir::new(dir).has_summary() {
        if set::is_set_summary(&read_json(&RunDir::new(dir).summary())?) {
            set::report(dir, case_description)
        } else {
            run::report(dir, case_description)
        }
    } else {
        Err(ReportError::NotAResultDirectory {
            dir: dir.display().to_string(),
        })
    }
}

/// Reads a JSON file.
fn read_json(path: &Path) -> Result<serde_json::Value, ReportError> {
    let fail = |message: String| ReportError::Read {
        path: path.display().to_string(),
        message,
    };
    let text = std::fs::read_to_string(path).map_err(|e| fail(e.to_string()))?;
    serde_json::from_str(&text).map_err(|e| fail(format!("not valid JSON: {e}")))
}

/// A number for a table cell: 5 significant digits, "—" when undefined.
pub fn cell(value: Option<f64>) -> String {
    match value {
        Some(0.0) => "0".into(),
        // Counts and round values without decimals.
        Some(v) if v.fract() == 0.0 && v.abs() < 1e9 => format!("{v:.0}"),
        Some(v) if v.is_finite() => {
            if v.abs() < 1e-3 || v.abs() >= 1e6 {
                format!("{v:.4e}")
            } else {
                let digits = (4 - v.abs().max(1e-300).log10().floor() as i32).clamp(0, 6) as usize;
                format!("{v:.digits$}")
            }
        }
        _ => "—".into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_show_five_significant_digits() {
        assert_eq!(cell(Some(4443.98997)), "4444.0");
        assert_eq!(cell(Some(0.44439899)), "0.44440");
        assert_eq!(cell(Some(1.96e-8)), "1.9600e-8");
        assert_eq!(cell(Some(0.0)), "0");
        assert_eq!(cell(Some(271.0)), "271");
        assert_eq!(cell(None), "—");
        assert_eq!(cell(Some(f64::NAN)), "—");
    }
}
