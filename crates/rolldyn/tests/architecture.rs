//! The workspace's dependency structure (ARCHITECTURE.md, "Layers"): in
//! every crate no module uses one in a higher layer, every module is in
//! exactly one layer, no modules or files import each other in a circle,
//! and the command-line tool's commands do not use one another; and no
//! function in the workspace (library, tests, examples) is longer than
//! [`MAX_FUNCTION_LINES`].
//!
//! Read from the sources: every `crate::…`, `super::…` and `self::…` path
//! in code is an edge from the file's module to the longest module prefix
//! of the path. Comments, string and character literals are blanked first,
//! and items under `#[cfg(test)]` (a test module in braces, wherever it
//! stands in the file, or a test module in a file of its own) are skipped
//! by matching their braces, not by cutting the file. Uses of an enclosing
//! module are the module tree's own structure, not edges. Method calls
//! between `impl` blocks of one type are not edges.

// A test that cannot read its sources should fail loudly.
#![allow(clippy::unwrap_used)]

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// A crate's layers, lowest first: a module may use modules of its own
/// layer and of lower layers.
struct Crate {
    dir: &'static str,
    layers: &'static [(&'static str, &'static [&'static str])],
    /// The layer whose modules must not use one another (the commands).
    apart: Option<&'static str>,
}

const CRATES: [Crate; 6] = [
    Crate {
        dir: "rolldyn",
        layers: &[
            (
                "foundations",
                &[
                    "math",
                    "error",
                    "material",
                    "integrate",
                    "kinematics",
                    "threads",
                ],
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
            ("dynamics", &["dynamics", "stability"]),
            ("test fixtures", &["testing"]),
        ],
        apart: None,
    },
    Crate {
        dir: "rolldyn-io",
        layers: &[
            ("the time series", &["dataset"]),
            ("the run directory", &["run_dir"]),
        ],
        apart: None,
    },
    Crate {
        dir: "rolldyn-case",
        layers: &[
            (
                "units, errors, preset texts",
                &["units", "error", "presets"],
            ),
            ("the case file's syntax", &["raw"]),
            ("the validated case", &["case", "catalogue", "mounting"]),
            ("loading", &["load"]),
            ("from a case to the engine", &["simulation"]),
        ],
        apart: None,
    },
    Crate {
        dir: "rolldyn-report",
        layers: &[
            ("drawing and reading", &["svg", "vibration_data"]),
            ("a run's data", &["run_data"]),
            ("sections", &["vibration", "sweep"]),
            ("a run's report", &["run"]),
            ("a set's report", &["set"]),
        ],
        apart: None,
    },
    Crate {
        dir: "rolldyn-cli",
        layers: &[
            (
                "foundations",
                &[
                    "finite",
                    "catalogue",
                    "channel_groups",
                    "sweep_grid",
                    "thermal_nodes",
                ],
            ),
            (
                "reports shared by commands",
                &[
                    "vibration",
                    "mounting_report",
                    "quasistatic_films",
                    "traction_equilibrium",
                    "report",
                    "power_report",
                ],
            ),
            (
                "the run pipeline",
                &[
                    "run_options",
                    "pipeline",
                    "run_stats",
                    "power_channels",
                    "recorder",
                    "checkpoint",
                    "accuracy",
                    "run_summary",
                    "run",
                    "run_set",
                    "html_report",
                ],
            ),
            (
                "commands",
                &[
                    "contact",
                    "traction",
                    "quasistatic",
                    "power",
                    "thermal",
                    "run_sweep",
                    "spectrum",
                ],
            ),
        ],
        apart: Some("commands"),
    },
    Crate {
        dir: "rolldyn-py",
        layers: &[],
        apart: None,
    },
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
    if matches!(
        parts.last().map(String::as_str),
        Some("mod" | "lib" | "main")
    ) {
        parts.pop();
    }
    parts
}

/// The text with comments and the contents of string and character
/// literals replaced by spaces (lines kept), so that braces and paths are
/// those of code.
fn blank(text: &str) -> String {
    let c: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let ident = |ch: char| ch.is_alphanumeric() || ch == '_';
    let keep = |ch: char| if ch == '\n' { '\n' } else { ' ' };
    let mut i = 0;
    while i < c.len() {
        if c[i] == '/' && c.get(i + 1) == Some(&'/') {
            while i < c.len() && c[i] != '\n' {
                out.push(' ');
                i += 1;
            }
        } else if c[i] == '/' && c.get(i + 1) == Some(&'*') {
            let mut depth = 0;
            while i < c.len() {
                if c[i] == '/' && c.get(i + 1) == Some(&'*') {
                    depth += 1;
                    out.push_str("  ");
                    i += 2;
                } else if c[i] == '*' && c.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    out.push_str("  ");
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    out.push(keep(c[i]));
                    i += 1;
                }
            }
        } else if c[i] == 'r'
            && (i == 0 || !ident(c[i - 1]))
            && matches!(c.get(i + 1), Some('"' | '#'))
        {
            // A raw string r"…" or r#"…"#.
            let hashes = c[i + 1..].iter().take_while(|&&h| h == '#').count();
            if c.get(i + 1 + hashes) != Some(&'"') {
                out.push(c[i]);
                i += 1;
                continue;
            }
            let close: String = std::iter::once('"')
                .chain(std::iter::repeat_n('#', hashes))
                .collect();
            out.push('r');
            out.extend(std::iter::repeat_n(' ', hashes + 1));
            i += hashes + 2;
            while i < c.len() && !c[i..].iter().collect::<String>().starts_with(&close) {
                out.push(keep(c[i]));
                i += 1;
            }
            out.extend(std::iter::repeat_n(' ', close.chars().count()));
            i += close.chars().count();
        } else if c[i] == '"' {
            out.push(' ');
            i += 1;
            while i < c.len() && c[i] != '"' {
                let step = if c[i] == '\\' { 2 } else { 1 };
                for _ in 0..step.min(c.len() - i) {
                    out.push(keep(c[i]));
                    i += 1;
                }
            }
            out.push(' ');
            i += 1;
        } else if c[i] == '\'' && (c.get(i + 1) == Some(&'\\') || c.get(i + 2) == Some(&'\'')) {
            // A character literal ('{', '\n', '\u{7b}'); a lifetime has no
            // closing quote two places on.
            out.push(' ');
            i += 1;
            while i < c.len() && c[i] != '\'' {
                let step = if c[i] == '\\' { 2 } else { 1 };
                for _ in 0..step.min(c.len() - i) {
                    out.push(' ');
                    i += 1;
                }
            }
            out.push(' ');
            i += 1;
        } else {
            out.push(c[i]);
            i += 1;
        }
    }
    out
}

/// The code of a file without its `#[cfg(test)]` items, and the names of
/// the test modules it declares in files of their own (`mod tests;`).
fn code(text: &str) -> (String, Vec<String>) {
    const GATE: &str = "#[cfg(test)]";
    let blanked = blank(text);
    let bytes = blanked.as_bytes();
    let mut out = String::with_capacity(blanked.len());
    let mut test_files = Vec::new();
    let mut from = 0;
    while let Some(k) = blanked[from..].find(GATE) {
        let start = from + k;
        out.push_str(&blanked[from..start]);
        let mut i = start + GATE.len();
        // The item: to its `;` if that comes before any brace, else to the
        // brace that closes its first one.
        let semicolon = blanked[i..].find(';').map(|s| i + s);
        let brace = blanked[i..].find('{').map(|b| i + b);
        match (semicolon, brace) {
            (Some(s), b) if b.is_none_or(|b| s < b) => {
                let item = blanked[i..s].split_whitespace().collect::<Vec<_>>();
                if let [.., "mod", name] = item.as_slice() {
                    test_files.push((*name).to_owned());
                }
                i = s + 1;
            }
            (_, Some(b)) => i = (closing_brace(bytes, b) + 1).min(bytes.len()),
            _ => i = bytes.len(),
        }
        from = i;
    }
    out.push_str(&blanked[from..]);
    (out, test_files)
}

/// The index of the brace that closes the one at `open` in blanked code
/// (the end of the text when it stays open).
fn closing_brace(bytes: &[u8], open: usize) -> usize {
    let mut depth = 0usize;
    for (i, &b) in bytes.iter().enumerate().skip(open) {
        match b {
            b'{' => depth += 1,
            b'}' => {
                depth -= 1;
                if depth == 0 {
                    return i;
                }
            }
            _ => {}
        }
    }
    bytes.len()
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

type Edges = BTreeMap<Module, BTreeSet<Module>>;

/// A crate's modules (without test modules) and their edges (file's
/// module → used module).
fn edges(dir: &str) -> (BTreeSet<Module>, Edges) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join(dir)
        .join("src");
    let mut files = Vec::new();
    rust_files(&root, &mut files);
    files.sort();
    let mut sources = BTreeMap::new();
    let mut tests: BTreeSet<Module> = BTreeSet::new();
    for file in &files {
        let here = module_of(&root, file);
        let (code, test_files) = code(&std::fs::read_to_string(file).unwrap());
        for name in test_files {
            let mut m = here.clone();
            m.push(name);
            tests.insert(m);
        }
        sources.insert(here, code);
    }
    sources.retain(|m, _| !tests.iter().any(|t| m.starts_with(t)));
    // The binary's root is the crate's root too (a binary is a crate of
    // its own, using the library by its name).
    let modules: BTreeSet<Module> = sources.keys().cloned().collect();
    let mut edges: Edges = BTreeMap::new();
    for (here, code) in &sources {
        for path in paths(code) {
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
            if !here.starts_with(&target) {
                edges.entry(here.clone()).or_default().insert(target);
            }
        }
    }
    (modules, edges)
}

/// The circles (strongly connected components of more than one node) of
/// the graph with nodes cut to `depth` segments, within `prefix`.
fn circles(edges: &Edges, prefix: &[&str], depth: usize) -> Vec<Vec<String>> {
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

/// Every circle of a crate: between its top modules, and inside each, file
/// by file (and sub-module by sub-module).
fn all_circles(edges: &Edges) -> Vec<Vec<String>> {
    let mut all: BTreeSet<Vec<String>> = circles(edges, &[], 1).into_iter().collect();
    let tops: BTreeSet<String> = edges.keys().filter_map(|m| m.first().cloned()).collect();
    for top in &tops {
        for depth in 2..=3 {
            all.extend(circles(edges, &[top.as_str()], depth));
        }
    }
    all.into_iter().collect()
}

/// What breaks a crate's layers: modules in no layer or in two, layer
/// entries with no module, edges up the layers, edges between the modules
/// of the `apart` layer.
fn layer_faults(spec: &Crate, modules: &BTreeSet<Module>, edges: &Edges) -> Vec<String> {
    let mut faults = Vec::new();
    let tops: BTreeSet<&str> = modules
        .iter()
        .filter_map(|m| m.first().map(String::as_str))
        .collect();
    let layer_of = |m: &str| spec.layers.iter().position(|(_, ms)| ms.contains(&m));
    for top in &tops {
        let count = spec
            .layers
            .iter()
            .filter(|(_, ms)| ms.contains(top))
            .count();
        if count != 1 {
            faults.push(format!("{}: module `{top}` is in {count} layers", spec.dir));
        }
    }
    for (name, ms) in spec.layers {
        for m in ms.iter().filter(|m| !tops.contains(*m)) {
            faults.push(format!(
                "{}: layer \"{name}\" names `{m}`, which is no module",
                spec.dir
            ));
        }
    }
    for (from, tos) in edges {
        let Some(a) = from.first() else { continue };
        for to in tos {
            let Some(b) = to.first() else { continue };
            let (Some(la), Some(lb)) = (layer_of(a), layer_of(b)) else {
                continue;
            };
            if lb > la {
                faults.push(format!(
                    "{}: {} → {} ({} → {})",
                    spec.dir,
                    from.join("::"),
                    to.join("::"),
                    spec.layers[la].0,
                    spec.layers[lb].0
                ));
            } else if a != b && la == lb && spec.apart == Some(spec.layers[la].0) {
                faults.push(format!(
                    "{}: {} → {} (the {} do not use one another)",
                    spec.dir,
                    from.join("::"),
                    to.join("::"),
                    spec.layers[la].0
                ));
            }
        }
    }
    faults
}

#[test]
fn every_crate_keeps_its_layers() {
    let mut faults = Vec::new();
    for spec in &CRATES {
        let (modules, edges) = edges(spec.dir);
        assert!(!modules.is_empty(), "{}: no sources read", spec.dir);
        faults.extend(layer_faults(spec, &modules, &edges));
    }
    assert!(faults.is_empty(), "layers broken:\n{}", faults.join("\n"));
}

#[test]
fn no_modules_or_files_import_each_other_in_a_circle() {
    let mut found = Vec::new();
    for spec in &CRATES {
        for circle in all_circles(&edges(spec.dir).1) {
            found.push(format!("{}: {circle:?}", spec.dir));
        }
    }
    assert!(found.is_empty(), "import circles:\n{}", found.join("\n"));
}

/// The checks above could pass by reading nothing: they are run here on
/// planted faults they must find.
#[test]
fn the_reader_finds_planted_faults() {
    // Comments and literals are not code; a test module is skipped by its
    // braces wherever it stands, and code after it is read.
    let source = "use super::{film::FilmWork, layout};\n// use crate::x::Y;\n\
        /* crate::hidden::A */ let σ = crate::math::brent(f);\n\
        #[cfg(test)]\nmod tests {\n    use crate::testing::T;\n    \
        fn f() { let s = \"}\"; let c = '{'; g::<'static>(); }\n}\n\
        let t = \"crate::quoted\";\nuse crate::dynamics::Late;\n\
        #[cfg(test)]\nmod more_tests;\n";
    let (code, test_files) = code(source);
    assert_eq!(test_files, vec!["more_tests"]);
    assert_eq!(
        paths(&code),
        vec![
            vec!["super", "film"],
            vec!["super", "layout"],
            vec!["super"],
            vec!["crate", "math", "brent"],
            vec!["crate", "dynamics", "Late"],
        ]
    );
    // The real sources: edges that exist are found.
    let (_, core) = edges("rolldyn");
    let model = vec!["dynamics".to_owned(), "model".to_owned()];
    assert!(core[&model].contains(&vec!["dynamics".to_owned(), "elements".to_owned()]));
    assert!(core[&model].contains(&vec!["quasistatic".to_owned()]));
    let (_, cli) = edges("rolldyn-cli");
    assert!(cli[&vec!["run".to_owned()]].contains(&vec!["run_summary".to_owned()]));
    // A circle, an edge up the layers (after a test module), an edge
    // between commands, a module in no layer and a stale layer entry.
    let m = |s: &str| s.split("::").map(str::to_owned).collect::<Module>();
    let planted: Edges = [
        (m("a::x"), BTreeSet::from([m("b")])),
        (m("b"), BTreeSet::from([m("a")])),
    ]
    .into_iter()
    .collect();
    assert_eq!(
        all_circles(&planted),
        vec![vec!["a".to_owned(), "b".to_owned()]]
    );
    let spec = Crate {
        dir: "planted",
        layers: &[("low", &["low", "gone"]), ("commands", &["one", "two"])],
        apart: Some("commands"),
    };
    let modules: BTreeSet<Module> = ["low", "one", "two", "stray"].map(m).into();
    let up = file_edges("low", "#[cfg(test)]\nmod tests { }\nuse crate::one::X;");
    let planted: Edges = [up, (m("one"), BTreeSet::from([m("two")]))]
        .into_iter()
        .collect();
    let faults = layer_faults(&spec, &modules, &planted);
    for expected in [
        "module `stray` is in 0 layers",
        "names `gone`, which is no module",
        "low → one (low → commands)",
        "one → two (the commands do not use one another)",
    ] {
        assert!(
            faults.iter().any(|f| f.contains(expected)),
            "not found: {expected} in {faults:?}"
        );
    }
}

/// The most lines a function may span, its signature to its closing brace.
const MAX_FUNCTION_LINES: usize = 120;

/// The functions of `source` longer than `limit` lines: (first line, name,
/// lines). Read from the blanked code, so braces in comments and literals
/// do not count; a `fn` without a body (a trait's declaration) is skipped.
fn long_functions(source: &str, limit: usize) -> Vec<(usize, String, usize)> {
    let code = blank(source);
    let bytes = code.as_bytes();
    let ident = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
    let line_of = |at: usize| code[..at].matches('\n').count() + 1;
    let mut found = Vec::new();
    let mut from = 0;
    while let Some(k) = code[from..].find("fn ") {
        let at = from + k;
        from = at + 3;
        if at > 0 && ident(bytes[at - 1]) {
            continue;
        }
        let name: String = code[at + 3..]
            .trim_start()
            .chars()
            .take_while(|&c| c.is_alphanumeric() || c == '_')
            .collect();
        let (Some(brace), semicolon) = (code[at..].find('{'), code[at..].find(';')) else {
            continue;
        };
        if name.is_empty() || semicolon.is_some_and(|s| s < brace) {
            continue;
        }
        let end = closing_brace(bytes, at + brace);
        let lines = line_of(end) - line_of(at) + 1;
        if lines > limit {
            found.push((line_of(at), name, lines));
        }
    }
    found
}

#[test]
fn no_function_is_longer_than_its_limit() {
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut files = Vec::new();
    for spec in &CRATES {
        for part in ["src", "tests", "benches", "examples"] {
            let dir = workspace.join("crates").join(spec.dir).join(part);
            if dir.is_dir() {
                rust_files(&dir, &mut files);
            }
        }
    }
    rust_files(&workspace.join("examples"), &mut files);
    files.sort();
    assert!(files.len() > 100, "{} files read", files.len());
    let mut long = Vec::new();
    for file in &files {
        let source = std::fs::read_to_string(file).unwrap();
        let shown = file.strip_prefix(&workspace).unwrap_or(file).display();
        for (line, name, lines) in long_functions(&source, MAX_FUNCTION_LINES) {
            long.push(format!("{shown}:{line} `{name}`: {lines} lines"));
        }
    }
    assert!(
        long.is_empty(),
        "functions over {MAX_FUNCTION_LINES} lines (split them):\n{}",
        long.join("\n")
    );
}

/// The length check on planted functions: the limit is exclusive, braces in
/// literals and comments do not count, a declaration without a body and an
/// identifier ending in `fn` are not functions.
#[test]
fn the_length_check_finds_planted_long_functions() {
    let body = |n: usize| "    let x = 1;\n".repeat(n);
    let source = format!(
        "trait T {{ fn declared(&self); }}\nfn ok() {{\n{}}}\n\
         fn long(a: u8) -> u8 {{\n    let s = \"}}\"; // }}\n{}    a\n}}\nlet myfn = 1;\n",
        body(3),
        body(5)
    );
    // `ok` spans lines 2–6 (5 lines), `long` lines 7–15 (9).
    assert_eq!(long_functions(&source, 5), vec![(7, "long".to_owned(), 9)]);
    assert_eq!(long_functions(&source, 4).len(), 2);
    assert!(long_functions(&source, 9).is_empty());
}

/// The edges of one file's code (module `here`) to top-level modules.
fn file_edges(here: &str, source: &str) -> (Module, BTreeSet<Module>) {
    let targets = paths(&code(source).0)
        .into_iter()
        .map(|p| p[1..2].to_vec())
        .collect();
    (vec![here.to_owned()], targets)
}
