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

/// The command blocks a document marks runnable (a fence opened with
/// "```sh runnable"): (document, commands, continuation lines joined,
/// comments and blank lines left out).
fn runnable_blocks() -> Vec<(PathBuf, Vec<String>)> {
    let mut out = Vec::new();
    for doc in documents() {
        let text = std::fs::read_to_string(&doc).unwrap();
        let mut lines = text.lines();
        while let Some(line) = lines.next() {
            if line.trim() != "```sh runnable" {
                continue;
            }
            let mut commands = Vec::new();
            let mut current = String::new();
            for l in lines.by_ref() {
                if l.trim_start().starts_with("```") {
                    break;
                }
                let l = l.trim();
                if l.starts_with('#') || l.is_empty() {
                    continue;
                }
                match l.strip_suffix('\\') {
                    Some(head) => current.push_str(head),
                    None => {
                        current.push_str(l);
                        commands.push(std::mem::take(&mut current));
                    }
                }
            }
            out.push((doc.clone(), commands));
        }
    }
    out
}

/// Copies `from` into `to`, leaving out run outputs (`out`, `sweep`).
fn copy_tree(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let entry = entry.unwrap();
        let name = entry.file_name();
        let path = entry.path();
        if path.is_dir() {
            if name != "out" && name != "sweep" {
                copy_tree(&path, &to.join(&name));
            }
        } else {
            std::fs::copy(&path, to.join(&name)).unwrap();
        }
    }
}

/// Every block a document marks runnable runs as written, each in a
/// fresh directory holding a copy of `examples/`, with `rolldyn` (and
/// `cargo run --release --`) the built command-line program: exit 0.
#[test]
fn every_runnable_block_runs() {
    let blocks = runnable_blocks();
    assert!(
        blocks.iter().any(|(doc, _)| doc.ends_with("README.md")),
        "the README's block is marked runnable"
    );
    let binary = PathBuf::from(env!("CARGO_BIN_EXE_rolldyn"));
    let bin_dir = binary.parent().unwrap().to_path_buf();
    let path = format!(
        "{}:{}",
        bin_dir.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    for (k, (doc, commands)) in blocks.iter().enumerate() {
        let dir =
            std::env::temp_dir().join(format!("rolldyn-doc-block-{}-{k}", std::process::id()));
        std::fs::remove_dir_all(&dir).ok();
        copy_tree(&root().join("examples"), &dir.join("examples"));
        for command in commands {
            let command = command.replace("cargo run --release --", "rolldyn");
            let o = std::process::Command::new("bash")
                .args(["-euo", "pipefail", "-c", &command])
                .current_dir(&dir)
                .env("PATH", &path)
                .output()
                .unwrap();
            assert!(
                o.status.success(),
                "{}: `{command}` failed: {}",
                doc.display(),
                String::from_utf8_lossy(&o.stderr)
            );
        }
        std::fs::remove_dir_all(&dir).ok();
    }
}
