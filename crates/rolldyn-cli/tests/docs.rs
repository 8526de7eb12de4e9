//! The documents cannot drift silently from the repository: every path a
//! document names exists, and every preset is named in the README.

// A test that cannot read the documents should fail loudly.
#![allow(clippy::unwrap_used)]

use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The repository's documents: the README, ARCHITECTURE.md,
/// CONTRIBUTING.md, CHANGELOG.md, docs/*.md and every example's README.
fn documents() -> Vec<PathBuf> {
    let root = root();
    let mut out: Vec<PathBuf> = ["README.md", "ARCHITECTURE.md", "CONTRIBUTING.md"]
        .iter()
        .map(|f| root.join(f))
        .collect();
    for dir in ["docs", "examples"] {
        for entry in std::fs::read_dir(root.join(dir)).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "md") {
                out.push(path);
            } else if path.join("README.md").is_file() {
                out.push(path.join("README.md"));
            }
        }
    }
    out
}

/// The repository paths a text names: words starting at one of the
/// repository's top-level folders, up to a character no path has
/// (backquotes, spaces, brackets, quotes, commas), without a final stop or
/// colon; placeholders (`DIR`, `E`, `P`, `*`, `…`) and globs left out.
fn named_paths(text: &str) -> Vec<String> {
    const ROOTS: [&str; 4] = ["crates/", "scripts/", "examples/", "docs/"];
    let mut out = Vec::new();
    let bytes = text.as_bytes();
    for (i, _) in text.char_indices() {
        let Some(root) = ROOTS.iter().find(|r| text[i..].starts_with(**r)) else {
            continue;
        };
        let before = if i == 0 { b' ' } else { bytes[i - 1] };
        if before.is_ascii_alphanumeric() || matches!(before, b'/' | b'_' | b'-' | b'.') {
            continue;
        }
        let end = text[i..]
            .find(|c: char| c.is_whitespace() || "`'\"()[]<>,;|{}".contains(c))
            .map_or(text.len(), |k| i + k);
        let path = text[i..end].trim_end_matches(['.', ':']);
        // A placeholder is a part in capitals (DIR, E, PRESET.toml).
        let placeholder = path.split('/').any(|part| {
            let stem = part.split('.').next().unwrap_or(part);
            (!stem.is_empty() && stem.chars().all(|c| c.is_ascii_uppercase() || c == '_'))
                || part.contains('*')
                || part.contains('…')
                || part == "..."
        });
        if path.len() > root.len() && !placeholder {
            out.push(path.to_owned());
        }
    }
    out
}

/// The output directories a text's commands write (`-o DIR`,
/// `--output DIR`): made by running them, not in the repository.
fn outputs(text: &str) -> Vec<String> {
    let words: Vec<&str> = text.split_whitespace().collect();
    words
        .windows(2)
        .filter(|w| matches!(w[0], "-o" | "--output"))
        .map(|w| w[1].trim_matches('`').to_owned())
        .collect()
}

#[test]
fn every_path_a_document_names_exists() {
    let root = root();
    let mut missing = Vec::new();
    for doc in documents() {
        let text = std::fs::read_to_string(&doc).unwrap();
        let written = outputs(&text);
        for path in named_paths(&text) {
            // A path may name a line or an anchor.
            let file = path.split(['#']).next().unwrap_or(&path);
            // The examples' outputs are made by running them.
            let output = file.contains("/out/")
                || file.ends_with("/out")
                || written.iter().any(|o| Path::new(file).starts_with(o));
            if output {
                continue;
            }
            if !root.join(file).exists() {
                missing.push(format!(
                    "{}: {path}",
                    doc.strip_prefix(&root).unwrap_or(&doc).display()
                ));
            }
        }
    }
    assert!(
        missing.is_empty(),
        "paths named in the documents that do not exist:\n{}",
        missing.join("\n")
    );
}

#[test]
fn the_readme_names_every_preset() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let named = |name: &str| match name {
        "ceramic_45x75" => readme.contains("ceramic 45 × 75"),
        "acbb_30x62" => readme.contains("30 × 62"),
        _ => readme.contains(name),
    };
    let unnamed: Vec<&str> = rolldyn_case::presets::PRESETS
        .iter()
        .map(|p| p.name)
        .filter(|n| !named(n))
        .collect();
    assert!(
        unnamed.is_empty(),
        "presets the README does not name: {unnamed:?}"
    );
}

#[test]
fn the_path_reader_reads_paths() {
    let text = "see `crates/rolldyn/src/lib.rs`, docs/cli.md: and (examples/seed001/plot.py).\n\
        not a/crates/x, nor examples/*/README.md or `rolldyn run -o DIR` with docs/DIR/x \
        or crates/rolldyn-case/presets/PRESET.toml";
    assert_eq!(
        named_paths(text),
        vec![
            "crates/rolldyn/src/lib.rs",
            "docs/cli.md",
            "examples/seed001/plot.py"
        ]
    );
    assert_eq!(
        outputs("rolldyn run c.toml -o examples/x/run --report"),
        vec!["examples/x/run"]
    );
}
