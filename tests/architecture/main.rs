//! The layering of ARCHITECTURE.md, held against the source (`module_graph` reads it):
//! * no import cycle between modules: between siblings at any depth, each sibling standing for
//!   everything below it (a parent and its own submodules are one unit);
//! * no top-level module imports a module of a higher layer (`LAYERS`, bottom to top).
//!
//! Every path to a module of this crate counts, in `use` trees and in code: `crate::a::b`,
//! `super::x`, `self::x`, a child module named at the start of a path, re-exports followed to
//! the file that defines the name, and `sliding_ladder::...` in `src/main.rs`. `mod`
//! declarations, comments and strings do not. Test modules inside `src/` count too.
//!
//! And no function in `src/` is over 80 lines (`fn_length`).
//!
//! And no unit test hides in `src/`: the library is built without its unit-test harness
//! (`[lib] test = false` in Cargo.toml, docs/build-time.md), so a `#[test]` there never runs.

mod fn_length;
mod module_graph;

use module_graph::scan::{code_only, imports};
use module_graph::{cycles, graph, name, sibling_edges, Module, Seen};
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The layers from bottom to top: a module may import its own layer and those below, never
/// one above. Keep in step with ARCHITECTURE.md.
const LAYERS: &[&[&str]] = &[
    &["scalar"],
    &["vector"],
    &["system"],
    &["ladder", "milne", "sim"],
    &["print"],
    &["registry"],
    &["derivation", "docs", "verify"],
    &["report"],
    &["show", "book"],
    &["cli"],
    &["main"],
];

/// The layer of a top-level module, `None` when `LAYERS` does not list it.
fn layer(top: &str) -> Option<usize> {
    LAYERS.iter().position(|l| l.contains(&top))
}

/// The edges that go up the layers (or touch an unlisted module), as messages.
fn upward<'a>(edges: impl Iterator<Item = (&'a str, &'a str)>) -> Vec<String> {
    let mut bad = Vec::new();
    for (a, b) in edges {
        match (layer(a), layer(b)) {
            (Some(la), Some(lb)) if la < lb => {
                bad.push(format!("{a} (layer {la}) imports {b} (layer {lb}), a higher layer"))
            }
            (Some(_), Some(_)) => {}
            _ => bad.push(format!(
                "{a} -> {b}: a top-level module missing from LAYERS (tests/architecture/main.rs) and ARCHITECTURE.md"
            )),
        }
    }
    bad
}

fn describe(edges: &BTreeMap<(Module, Module), Seen>, cycle: &[Module]) -> String {
    let mut s = format!(
        "cycle: {}\n",
        cycle.iter().map(name).collect::<Vec<_>>().join(", ")
    );
    let inside = |m: &Module| cycle.iter().find(|c| m.starts_with(c));
    for ((a, b), w) in edges {
        if let (Some(x), Some(y)) = (inside(a), inside(b)) {
            if x != y {
                s += &format!(
                    "  {} -> {}   ({}:{} `{}`)\n",
                    name(a),
                    name(b),
                    w.file,
                    w.line,
                    w.path
                );
            }
        }
    }
    s
}

fn crate_graph() -> BTreeMap<(Module, Module), Seen> {
    graph(Path::new(env!("CARGO_MANIFEST_DIR")))
}

#[test]
fn no_two_modules_import_each_other_through_any_path() {
    let edges = crate_graph();
    if std::env::var_os("LADDER_GRAPH").is_some() {
        for ((a, b), w) in &edges {
            println!(
                "{} -> {}   {}:{} {}",
                name(a),
                name(b),
                w.file,
                w.line,
                w.path
            );
        }
    }
    let found = cycles(&sibling_edges(edges.keys()));
    let text: String = found.iter().map(|c| describe(&edges, c)).collect();
    assert!(found.is_empty(), "import cycles between modules:\n{text}");
}

#[test]
fn no_layer_imports_a_higher_one() {
    let edges = crate_graph();
    let tops: BTreeSet<(&str, &str)> = sibling_edges(edges.keys())
        .iter()
        .filter(|(a, _)| a.len() == 1)
        .map(|(a, b)| (layer_name(a), layer_name(b)))
        .collect();
    let bad = upward(tops.iter().copied());
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// The name of a top-level module as `LAYERS` lists it, or "(unlisted)".
fn layer_name(m: &Module) -> &'static str {
    LAYERS
        .iter()
        .flat_map(|l| l.iter())
        .find(|x| **x == m[0])
        .copied()
        .unwrap_or("(unlisted)")
}

#[test]
fn the_scan_sees_the_edges_it_must() {
    // Known edges of the crate in each form of path: a lost form would hide cycles.
    let edges = crate_graph();
    let has = |a: &str, b: &str| edges.keys().any(|(x, y)| name(x) == a && name(y) == b);
    assert!(has("main", "cli"), "sliding_ladder:: in main.rs");
    assert!(has("cli", "cli::verify"), "a child module named in code");
    assert!(
        has("cli::simulate", "sim::scene"),
        "use crate::.. with braces"
    );
    assert!(has("sim::fall", "sim::rigid"), "super::");
    assert!(
        has("scalar::bound", "scalar::jet"),
        "super::Jet, re-exported by scalar"
    );
    assert!(edges.len() > 100, "only {} edges", edges.len());
}

#[test]
fn a_planted_cycle_is_found() {
    let e = |v: &[(&'static str, &'static str)]| v.iter().copied().collect::<BTreeSet<_>>();
    let acyclic = e(&[("a", "b"), ("b", "c"), ("a", "c"), ("d", "c")]);
    assert!(cycles(&acyclic).is_empty());
    // one edge back closes a three-module cycle; d stays out of it
    let planted = e(&[("a", "b"), ("b", "c"), ("a", "c"), ("d", "c"), ("c", "a")]);
    assert_eq!(cycles(&planted), vec![vec!["a", "b", "c"]]);
    // two modules importing each other
    assert_eq!(cycles(&e(&[("x", "y"), ("y", "x")])), vec![vec!["x", "y"]]);
    // files of two folders: sim::fall -> report::plot and report::files -> sim::scene make
    // sim and report import each other, though no file imports itself
    let m = |s: &str| s.split("::").map(str::to_string).collect::<Module>();
    let files = [
        (m("sim::fall"), m("report::plot")),
        (m("report::files"), m("sim::scene")),
        (m("sim"), m("sim::fall")),
    ];
    assert!(cycles(&files.iter().cloned().collect()).is_empty());
    assert_eq!(
        cycles(&sibling_edges(files.iter())),
        vec![vec![m("report"), m("sim")]]
    );
    // the same, planted into the real graph
    let mut real: BTreeSet<(Module, Module)> = sibling_edges(crate_graph().keys());
    assert!(cycles(&real).is_empty(), "the crate itself has a cycle");
    real.insert((m("scalar"), m("cli")));
    let found = cycles(&real);
    assert_eq!(found.len(), 1);
    assert!(found[0].contains(&m("scalar")) && found[0].contains(&m("cli")));
}

#[test]
fn a_planted_upward_import_is_found() {
    assert!(upward([("sim", "scalar"), ("cli", "report")].into_iter()).is_empty());
    let bad = upward([("sim", "scalar"), ("report", "cli")].into_iter());
    assert_eq!(bad.len(), 1);
    assert!(bad[0].contains("report (layer"), "{bad:?}");
    assert_eq!(upward([("sim", "(unlisted)")].into_iter()).len(), 1);
}

#[test]
fn the_scanner_reads_paths_and_skips_comments_and_strings() {
    let known: BTreeSet<Module> = [
        vec![],
        vec!["a".into()],
        vec!["a".into(), "b".into()],
        vec!["c".into()],
    ]
    .into_iter()
    .collect();
    let here: Module = vec!["a".into(), "b".into()];
    let text = r#"
//! [`crate::c`] in a doc comment is no import
use super::{self as up, b::X};
use crate::c::{self, D};
fn f() { let s = "crate::c::x"; let _ = ('x', '\''); crate::c::g(); }
#[cfg(test)]
mod tests { use super::*; }
"#;
    let got: Vec<(String, usize, Option<String>)> = imports(&here, text, &known, false)
        .into_iter()
        .map(|i| (i.path.join("::"), i.line, i.binds))
        .collect();
    let s = |x: &str| Some(x.to_string());
    assert_eq!(
        got,
        vec![
            ("a".to_string(), 3, s("up")),
            ("a::b::X".to_string(), 3, s("X")),
            ("c".to_string(), 4, s("c")),
            ("c::D".to_string(), 4, s("D")),
            ("c::g".to_string(), 5, None),
            ("a::b".to_string(), 7, None),
        ]
    );
}

/// The lines of `text` that open a unit test or a test module (`#[test]`, `#[cfg(test)]`),
/// comments and strings aside.
fn unit_test_lines(text: &str) -> Vec<usize> {
    code_only(text)
        .lines()
        .enumerate()
        .filter(|(_, l)| {
            let l = l.trim_start();
            l.starts_with("#[cfg(test)]") || l.starts_with("#[test]")
        })
        .map(|(i, _)| i + 1)
        .collect()
}

#[test]
fn no_unit_test_hides_in_the_library() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let found: Vec<String> = module_graph::modules(&src)
        .values()
        .flat_map(|p| {
            let text = std::fs::read_to_string(p).expect("src is readable");
            unit_test_lines(&text)
                .into_iter()
                .map(move |l| format!("{}:{l}", p.display()))
        })
        .collect();
    assert!(
        found.is_empty(),
        "unit tests in src/ never run ([lib] test = false): move them to tests/: {found:?}"
    );
}

#[test]
fn a_planted_unit_test_is_found() {
    let text = "// #[cfg(test)] in a comment\nconst S: &str = \"#[test]\";\n#[cfg(test)]\nmod tests {\n    #[test]\n    fn t() {}\n}\n";
    assert_eq!(unit_test_lines(text), vec![3, 5]);
}
