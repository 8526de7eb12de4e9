//! The core's dependency structure (ARCHITECTURE.md, "Layers"): no module
//! uses one in a higher layer, and no modules or files import each other
//! in a circle.
//!
//! Read from the sources: every `crate::…`, `super::…` and `self::…` path
//! in code (not comments, not the `#[cfg(test)]` module at a file's end)
//! is an edge from the file's module to the longest module prefix of the
//! path. Method calls between `impl` blocks of one type are not edges.

// A test that cannot read its sources should fail loudly.
#![allow(clippy::unwrap_used)]

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The layers, lowest first: a module may use modules of its own layer and
/// of lower layers.
const LAYERS: [(&str, &[&str]); 6] = [
    (
        "foundations",
        &["math", "error", "material", "integrate", "kinematics"],
    ),
    ("the bearing and its operation", &["geometry", "operating"]),
    (
        "contacts, surfaces and their laws",
        &[
            "contact",
            "surface",
            "lubrication",
            "traction",
            "cage",
            "life",
            "signal",
            "seals",
        ],
    ),
    (
        "quasi-static solutions",
        &["quasistatic", "power", "thermal"],
    ),
    ("dynamics", &["dynamics"]),
    ("test fixtures", &["testing"]),
];

type Module = Vec<String>;

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

fn module_of(root: &Path, file: &Path) -> Module {
    let relative = file.strip_prefix(root).unwrap().with_extension("");
    let mut parts: Module = relative
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib")) {
        parts.pop();
    }
    parts
}

/// The code of a file without comments and without its test module.
fn code(text: &str) -> String {
    let text = match text.find("#[cfg(test)]\nmod tests") {
        Some(i) => &text[..i],
        None => text,
    };
    text.lines()
        .filter(|l| !l.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The paths a file's code names, each as its segments (a `{…}` group
/// gives one path per member).
fn paths(code: &str) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    let bytes = code.as_bytes();
    let ident = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
    let mut i = 0;
    while i < bytes.len() {
        let starts = ["crate::", "super::", "self::"]
            .iter()
            .any(|p| bytes[i..].starts_with(p.as_bytes()))
            && (i == 0 || !ident(bytes[i - 1]));
        if !starts {
            i += 1;
            continue;
        }
        let mut j = i;
        while j < bytes.len() && (ident(bytes[j]) || bytes[j..].starts_with(b"::")) {
            j += if bytes[j] == b':' { 2 } else { 1 };
        }
        let head: Vec<String> = code[i..j]
            .split("::")
            .filter(|s| !s.is_empty())
            .map(str::to_owned)
            .collect();
        if code[j..].starts_with('{') {
            let end = code[j..].find('}').map_or(code.len(), |k| j + k);
            for member in code[j + 1..end].split(',') {
                let first = member.trim().split("::").next().unwrap_or("").trim();
                if !first.is_empty() && first != "self" {
                    let mut p = head.clone();
                    p.push(first.to_owned());
                    out.push(p);
                }
            }
            i = end;
        }
        out.push(head);
        i = j.max(i + 1);
    }
    out
}

/// Module-level edges of the core crate (file's module → used module).
fn edges() -> BTreeMap<Module, BTreeSet<Module>> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&root, &mut files);
    let modules: BTreeSet<Module> = files.iter().map(|f| module_of(&root, f)).collect();
    let mut edges: BTreeMap<Module, BTreeSet<Module>> = BTreeMap::new();
    for file in &files {
        let here = module_of(&root, file);
        let text = std::fs::read_to_string(file).unwrap();
        for path in paths(&code(&text)) {
            let mut full: Module = match path[0].as_str() {
                "crate" => Vec::new(),
                "self" => here.clone(),
                _ => {
                    let supers = path.iter().take_while(|s| *s == "super").count();
                    here[..here.len().saturating_sub(supers)].to_vec()
                }
            };
            full.extend(
                path.iter()
                    .skip_while(|s| matches!(s.as_str(), "crate" | "self" | "super"))
                    .cloned(),
            );
            let target = (0..=full.len())
                .rev()
                .map(|n| full[..n].to_vec())
                .find(|m| modules.contains(m))
                .unwrap_or_default();
            // Uses of an enclosing module (its re-exports, its types) are
            // the tree's own structure, not edges.
            if !here.starts_with(&target) {
                edges.entry(here.clone()).or_default().insert(target);
            }
        }
    }
    edges
}

/// The circles (strongly connected components of more than one node) of
/// the graph with nodes cut to `depth` segments, within `prefix`.
fn circles(
    edges: &BTreeMap<Module, BTreeSet<Module>>,
    prefix: &[&str],
    depth: usize,
) -> Vec<Vec<String>> {
    let inside = |m: &Module| m.len() > prefix.len() && m.iter().zip(prefix).all(|(a, b)| a == b);
    let node = |m: &Module| m[..depth.min(m.len())].join("::");
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (from, tos) in edges {
        for to in tos.iter().filter(|t| inside(from) && inside(t)) {
            let (a, b) = (node(from), node(to));
            if a != b {
                graph.entry(a).or_default().insert(b.clone());
                graph.entry(b).or_default();
            }
        }
    }
    // Kosaraju: a node's circle is the nodes it reaches that reach it.
    let reach = |start: &String| {
        let mut seen = BTreeSet::from([start.clone()]);
        let mut stack = vec![start.clone()];
        while let Some(n) = stack.pop() {
            for m in &graph[&n] {
                if seen.insert(m.clone()) {
                    stack.push(m.clone());
                }
            }
        }
        seen
    };
    let reached: BTreeMap<&String, BTreeSet<String>> =
        graph.keys().map(|n| (n, reach(n))).collect();
    let mut found: BTreeSet<Vec<String>> = BTreeSet::new();
    for (n, r) in &reached {
        let circle: Vec<String> = r
            .iter()
            .filter(|m| reached[m].contains(*n))
            .cloned()
            .collect();
        if circle.len() > 1 {
            found.insert(circle);
        }
    }
    found.into_iter().collect()
}

#[test]
fn no_module_uses_a_higher_layer() {
    let layer_of = |m: &str| LAYERS.iter().position(|(_, ms)| ms.contains(&m));
    let mut upward = Vec::new();
    for (from, tos) in edges() {
        let Some(a) = from.first() else { continue };
        let la = layer_of(a).unwrap_or_else(|| panic!("module `{a}` is in no layer of LAYERS"));
        for to in tos {
            let Some(b) = to.first() else { continue };
            let lb = layer_of(b).unwrap_or_else(|| panic!("module `{b}` is in no layer of LAYERS"));
            if lb > la {
                upward.push(format!(
                    "{} → {} ({} → {})",
                    from.join("::"),
                    to.join("::"),
                    LAYERS[la].0,
                    LAYERS[lb].0
                ));
            }
        }
    }
    assert!(
        upward.is_empty(),
        "dependencies pointing up the layers:\n{}",
        upward.join("\n")
    );
}

#[test]
fn no_modules_or_files_import_each_other_in_a_circle() {
    let edges = edges();
    let mut all: BTreeSet<Vec<String>> = circles(&edges, &[], 1).into_iter().collect();
    let tops: BTreeSet<String> = edges.keys().filter_map(|m| m.first().cloned()).collect();
    for top in &tops {
        // Within each module, file by file (and sub-module by sub-module).
        for depth in 2..=3 {
            all.extend(circles(&edges, &[top.as_str()], depth));
        }
    }
    assert!(all.is_empty(), "import circles: {all:?}");
}

#[test]
fn the_reader_finds_edges_and_circles() {
    // The test above could pass by reading nothing: check the reader on
    // code it must understand.
    let found = paths(&code(
        "use super::{film::FilmWork, layout};\n// use crate::x::Y;\nlet σ = crate::math::brent(f);",
    ));
    assert_eq!(
        found,
        vec![
            vec!["super", "film"],
            vec!["super", "layout"],
            vec!["super"],
            vec!["crate", "math", "brent"],
        ]
    );
    let e = edges();
    let dynamics = vec!["dynamics".to_owned(), "model".to_owned()];
    assert!(e[&dynamics].contains(&vec!["dynamics".to_owned(), "elements".to_owned()]));
    assert!(e[&dynamics].contains(&vec!["quasistatic".to_owned()]));
    let mut circular = BTreeMap::new();
    circular.insert(
        vec!["a".to_owned(), "x".to_owned()],
        BTreeSet::from([vec!["b".to_owned()]]),
    );
    circular.insert(vec!["b".to_owned()], BTreeSet::from([vec!["a".to_owned()]]));
    assert_eq!(
        circles(&circular, &[], 1),
        vec![vec!["a".to_owned(), "b".to_owned()]]
    );
}
