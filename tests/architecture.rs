//! The layering ARCHITECTURE.md states, enforced: the crate's files import each other in one
//! direction only — no cycle between files, and no import that runs up the layers
//! (error, sort ← plot ← schema ← … ← view ← web).
//!
//! The graph is read from the source text: every `use` (trees, renames, globs, `pub use`
//! re-exports) and every path written inline in code (`crate::view::text_metrics::text_width(…)`,
//! `super::Scene`, `child::f()`). An imported name is followed through re-exports to the file
//! that defines it, so a facade (`pub use layout::Panel` in a `mod.rs`) hides no edge: importing
//! `crate::view::Panel` depends on `view/layout.rs`, and `view/mod.rs` depends on it too.
//! The checker is tested on small made-up crates below, so that it can be seen to fail.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

#[path = "architecture/graph.rs"]
mod graph;

use graph::{Crate, Edge};

/// The layers, lowest first: a file may import from its own top-level module and from the modules
/// of lower layers only. The same list is in ARCHITECTURE.md (checked below).
const LAYERS: &[&[&str]] = &[
    &["error", "sort"],
    &["plot"],
    &["schema"],
    &["lesson"],
    &["model"],
    &["control"],
    &["analysis"],
    &["words"],
    &["session"],
    &["classroom"],
    &["offline"],
    &["view"],
    &["web"],
];

fn rank(module: &str) -> Option<usize> {
    LAYERS.iter().position(|layer| layer.contains(&module))
}

fn library() -> Crate {
    Crate::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("src").as_path(), &["bin"])
}

/// Edges that run up the layers (or between two modules of one layer), or from a module the
/// list does not place.
fn upward(krate: &Crate) -> Vec<(Edge, String)> {
    let mut out = Vec::new();
    for e in krate.edges() {
        let (from, to) = (krate.top_module(&e.from), krate.top_module(&e.to));
        if from.is_empty() || to.is_empty() || from == to {
            continue;
        }
        let why = match (rank(&from), rank(&to)) {
            (Some(f), Some(t)) if t < f => continue,
            (Some(_), Some(_)) => format!("{from} may not import {to} (same layer or above it)"),
            (None, _) => format!("the module {from} is in no layer"),
            (_, None) => format!("the module {to} is in no layer"),
        };
        out.push((e, why));
    }
    out
}

/// Each cycle's files, and the imports between them (what to cut).
fn show(krate: &Crate, cycles: &[Vec<String>]) -> String {
    let edges = krate.edges();
    let mut out = String::new();
    for c in cycles {
        out += &format!("  {}\n", c.join(", "));
        for e in edges.iter().filter(|e| c.contains(&e.from) && c.contains(&e.to)) {
            out += &format!("    {} → {} ({})\n", e.from, e.to, e.via);
        }
    }
    out
}

#[test]
fn no_file_imports_another_in_a_circle() {
    let krate = library();
    assert!(krate.files().len() > 50, "read the crate: {} files", krate.files().len());
    let cycles = krate.cycles();
    println!("file-level import cycles in src/: {}", cycles.len());
    assert!(cycles.is_empty(), "{} import cycles between files:\n{}", cycles.len(), show(&krate, &cycles));
}

#[test]
fn the_command_line_program_has_no_cycles_either() {
    let bin = Crate::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("src/bin/flexarm").as_path(), &[]);
    assert!(bin.files().len() > 5);
    let cycles = bin.cycles();
    assert!(cycles.is_empty(), "import cycles in src/bin/flexarm:\n{}", show(&bin, &cycles));
}

#[test]
fn no_import_runs_up_the_layers() {
    let krate = library();
    let bad = upward(&krate);
    let text: String = bad.iter().map(|(e, why)| format!("  {} → {} ({}): {why}\n", e.from, e.to, e.via)).collect();
    assert!(bad.is_empty(), "{} imports run up the layers:\n{text}", bad.len());
}

#[test]
fn every_top_level_module_has_a_layer() {
    let krate = library();
    let modules: BTreeSet<String> = krate.files().iter().map(|f| krate.top_module(f)).collect();
    for m in modules.iter().filter(|m| !m.is_empty()) {
        assert!(rank(m).is_some(), "src/{m} is in no layer of tests/architecture.rs");
    }
}

/// ARCHITECTURE.md says the layers in one line, "Layers, lowest first: error, sort ← plot ← …";
/// it must be this test's list.
#[test]
fn architecture_md_states_these_layers() {
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("ARCHITECTURE.md")).unwrap();
    let line = text
        .lines()
        .find_map(|l| l.split_once("Layers, lowest first:").map(|(_, rest)| rest.trim().trim_end_matches('.')))
        .expect("ARCHITECTURE.md has a line 'Layers, lowest first: …'");
    let stated: Vec<Vec<String>> = line
        .split('←')
        .map(|layer| layer.split(',').map(|m| m.trim().trim_matches('`').to_string()).collect())
        .collect();
    let ours: Vec<Vec<String>> = LAYERS.iter().map(|l| l.iter().map(|m| m.to_string()).collect()).collect();
    assert_eq!(stated, ours, "ARCHITECTURE.md's layers differ from tests/architecture.rs");
}

/// The panels of the view import no other panel: each folder holds everything about its panel,
/// and what two panels share lives below them.
#[test]
fn no_panel_imports_another_panel() {
    let krate = library();
    // A panel is a folder under view/panels/; the files beside them (the contract, the registry)
    // are what every panel may read.
    let panel_of = |file: &str| -> Option<String> {
        let (panel, _) = file.strip_prefix("view/panels/")?.split_once('/')?;
        Some(panel.to_string())
    };
    let mut bad = BTreeMap::new();
    for e in krate.edges() {
        if let (Some(a), Some(b)) = (panel_of(&e.from), panel_of(&e.to)) {
            if a != b {
                bad.insert((e.from.clone(), e.to.clone()), e.via.clone());
            }
        }
    }
    assert!(bad.is_empty(), "panels importing other panels: {bad:?}");
}

// ------------------------------------------------------------------ the checker, seen to fail

fn made_up(files: &[(&str, &str)]) -> Crate {
    Crate::from_sources(files.iter().map(|(p, s)| (p.to_string(), s.to_string())).collect())
}

#[test]
fn the_checker_finds_a_cycle_through_use_lines() {
    let k = made_up(&[
        ("lib.rs", "pub mod a; pub mod b;"),
        ("a.rs", "use crate::b::Thing;\npub struct Other;"),
        ("b.rs", "use crate::a::Other;\npub struct Thing;"),
    ]);
    assert_eq!(k.cycles(), vec![vec!["a.rs".to_string(), "b.rs".to_string()]]);
}

#[test]
fn the_checker_finds_a_cycle_through_an_inline_path_and_a_child_module() {
    let k = made_up(&[
        ("lib.rs", "pub mod v;"),
        ("v/mod.rs", "mod scene;\npub struct Panel;\nfn f() { scene::draw(); }"),
        ("v/scene.rs", "pub fn draw() { let _ = super::Panel; }"),
    ]);
    assert_eq!(k.cycles().len(), 1, "{:?}", k.edges());
}

#[test]
fn the_checker_follows_re_exports_and_globs_to_the_defining_file() {
    let k = made_up(&[
        ("lib.rs", "pub mod low; pub mod high;"),
        ("low/mod.rs", "mod inner;\npub use inner::*;"),
        ("low/inner.rs", "use crate::high::{deep::{Top as T}};\npub struct Cell;"),
        ("high/mod.rs", "pub mod deep;"),
        ("high/deep.rs", "use crate::low::Cell;\npub struct Top;"),
    ]);
    let edges: Vec<(String, String)> = k.edges().into_iter().map(|e| (e.from, e.to)).collect();
    assert!(edges.contains(&("high/deep.rs".into(), "low/inner.rs".into())), "{edges:?}");
    assert!(edges.contains(&("low/inner.rs".into(), "high/deep.rs".into())), "{edges:?}");
    assert_eq!(k.cycles().len(), 1);
}

#[test]
fn the_checker_ignores_comments_strings_and_a_files_own_tests() {
    let k = made_up(&[
        ("lib.rs", "pub mod a; pub mod b;"),
        ("a.rs", "// use crate::b::X;\nconst S: &str = \"crate::b::X\";\npub struct Y;\n#[cfg(test)]\nmod tests { use super::*; }"),
        ("b.rs", "use crate::a::Y;\npub struct X;"),
    ]);
    assert!(k.cycles().is_empty(), "{:?}", k.edges());
    assert_eq!(k.edges().len(), 1);
}

#[test]
fn the_checker_finds_an_import_up_the_layers() {
    let k = made_up(&[
        ("lib.rs", "pub mod model; pub mod view;"),
        ("model/mod.rs", "pub fn step() { crate::view::draw(); }"),
        ("view/mod.rs", "pub fn draw() {}"),
    ]);
    let bad = upward(&k);
    assert_eq!(bad.len(), 1, "{bad:?}");
    assert!(bad[0].1.contains("model may not import view"), "{}", bad[0].1);
}
