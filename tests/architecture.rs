//! The module graph of the crate, read from the source (ARCHITECTURE.md states the rules):
//! * no import cycle between modules (each file is a module; a cycle through any number of
//!   files fails, a parent `mod.rs` and its child included);
//! * no top-level module imports a module of a higher layer (`LAYERS`, bottom to top).
//!
//! Every path to a module of this crate counts, in `use` trees and in code: `crate::a::b`,
//! `super::x`, `self::x`, a child module named at the start of a `use`, and
//! `sliding_ladder::...` in `src/main.rs`. `mod` declarations and comments do not. Written by hand
//! (a scanner of a few dozen lines) because a full parser such as syn would only add build time
//! for what a token scan answers.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The layers from bottom to top: a module may import its own layer and those below, never
/// one above. Keep in step with ARCHITECTURE.md.
const LAYERS: &[&[&str]] = &[
    &["scalar"],
    &["vector"],
    &["system"],
    &["ladder", "milne", "sim"],
    &["print"],
    &["registry"],
    &["method", "docs", "verify"],
    &["report"],
    &["show", "book"],
    &["cli"],
    &["main"],
];

/// A module: its path below the crate root (`["sim", "scene"]`; `[]` is `lib.rs`).
type Module = Vec<String>;

/// Where an edge was first seen: file, line and the path as written.
#[derive(Clone, Debug)]
struct Seen {
    file: String,
    line: usize,
    path: String,
}

fn name(m: &Module) -> String {
    if m.is_empty() {
        "crate".into()
    } else {
        m.join("::")
    }
}

/// The module of each source file under `src/`.
fn modules(src: &Path) -> BTreeMap<Module, PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for e in std::fs::read_dir(dir).expect("src is readable") {
            let p = e.expect("dir entry").path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(p);
            }
        }
    }
    let mut files = Vec::new();
    walk(src, &mut files);
    files
        .into_iter()
        .map(|f| {
            let rel = f.strip_prefix(src).expect("under src");
            let mut m: Module = rel
                .iter()
                .map(|c| c.to_string_lossy().trim_end_matches(".rs").to_string())
                .collect();
            if m.last().is_some_and(|l| l == "mod" || l == "lib") {
                m.pop();
            }
            (m, f)
        })
        .collect()
}

/// The character at `k`, or NUL past the end.
fn at(c: &[char], k: usize) -> char {
    c.get(k).copied().unwrap_or('\0')
}

/// The text with comments, strings and character literals blanked (newlines kept, so line
/// numbers stay right).
fn code_only(text: &str) -> String {
    let c: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let blank = |out: &mut String, ch: char| out.push(if ch == '\n' { '\n' } else { ' ' });
    let mut i = 0;
    while i < c.len() {
        if c[i] == '/' && at(&c, i + 1) == '/' {
            while i < c.len() && c[i] != '\n' {
                i += 1;
            }
        } else if c[i] == '/' && at(&c, i + 1) == '*' {
            let mut depth = 0;
            while i < c.len() {
                if c[i] == '/' && at(&c, i + 1) == '*' {
                    depth += 1;
                    i += 2;
                } else if c[i] == '*' && at(&c, i + 1) == '/' {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    blank(&mut out, c[i]);
                    i += 1;
                }
            }
        } else if c[i] == 'r' && raw_start(&c, i) {
            let mut hashes = 0;
            i += 1;
            while at(&c, i) == '#' {
                hashes += 1;
                i += 1;
            }
            i += 1; // the opening quote
            while i < c.len() {
                if c[i] == '"' && (1..=hashes).all(|k| at(&c, i + k) == '#') {
                    i += 1 + hashes;
                    break;
                }
                blank(&mut out, c[i]);
                i += 1;
            }
            out.push(' ');
        } else if c[i] == '"' {
            i += 1;
            while i < c.len() && c[i] != '"' {
                if c[i] == '\\' {
                    blank(&mut out, c[i]);
                    i += 1;
                }
                if i < c.len() {
                    blank(&mut out, c[i]);
                    i += 1;
                }
            }
            i += 1;
            out.push(' ');
        } else if c[i] == '\'' && (at(&c, i + 1) == '\\' || at(&c, i + 2) == '\'') {
            // a character literal (a lifetime has no closing quote); skip an escaped character
            i += if at(&c, i + 1) == '\\' { 3 } else { 2 };
            while i < c.len() && c[i] != '\'' {
                i += 1;
            }
            i += 1;
            out.push(' ');
        } else {
            out.push(c[i]);
            i += 1;
        }
    }
    out
}

/// Whether `c[i]` (an `r`) opens a raw string `r"..."`, `r#"..."#` or `br"..."`, not a raw
/// identifier `r#type` or the end of a name.
fn raw_start(c: &[char], i: usize) -> bool {
    let at = |k: usize| at(c, k);
    let name = |ch: char| ch.is_alphanumeric() || ch == '_';
    let mut k = i + 1;
    while at(k) == '#' {
        k += 1;
    }
    let starts = i == 0 || !name(at(i - 1)) || (at(i - 1) == 'b' && (i < 2 || !name(at(i - 2))));
    starts && at(k) == '"'
}

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Ident(String),
    Path, // ::
    Open,
    Close,
    Comma,
    Semi,
    Other,
}

fn tokens(code: &str) -> Vec<(Tok, usize)> {
    let c: Vec<char> = code.chars().collect();
    let mut v = Vec::new();
    let (mut i, mut line) = (0, 1);
    while i < c.len() {
        let ch = c[i];
        if ch == '\n' {
            line += 1;
            i += 1;
        } else if ch.is_whitespace() {
            i += 1;
        } else if ch.is_alphanumeric() || ch == '_' {
            let s = i;
            while i < c.len() && (c[i].is_alphanumeric() || c[i] == '_') {
                i += 1;
            }
            v.push((Tok::Ident(c[s..i].iter().collect()), line));
        } else if ch == ':' && c.get(i + 1) == Some(&':') {
            v.push((Tok::Path, line));
            i += 2;
        } else {
            v.push((
                match ch {
                    '{' => Tok::Open,
                    '}' => Tok::Close,
                    ',' => Tok::Comma,
                    ';' => Tok::Semi,
                    _ => Tok::Other,
                },
                line,
            ));
            i += 1;
        }
    }
    v
}

fn ident(t: Option<&(Tok, usize)>) -> Option<&str> {
    match t {
        Some((Tok::Ident(s), _)) => Some(s),
        _ => None,
    }
}

/// One path of a `use` tree: its segments and the name it binds (`None` for a glob).
type UsePath = (Vec<String>, Option<String>);

/// The paths of a `use` tree starting at token `i` (after `use`).
fn use_tree(t: &[(Tok, usize)], i: &mut usize, prefix: &[String], out: &mut Vec<UsePath>) {
    let mut path = prefix.to_vec();
    loop {
        match t.get(*i).map(|x| &x.0) {
            Some(Tok::Ident(s)) if s == "as" => {
                let alias = ident(t.get(*i + 1)).map(str::to_string);
                *i += 2;
                out.push((path, alias));
                return;
            }
            Some(Tok::Ident(s)) => {
                if s != "self" || path.is_empty() {
                    path.push(s.clone());
                }
                *i += 1;
            }
            Some(Tok::Path) => *i += 1,
            Some(Tok::Open) => {
                *i += 1;
                loop {
                    match t.get(*i).map(|x| &x.0) {
                        Some(Tok::Close) => {
                            *i += 1;
                            return;
                        }
                        Some(Tok::Comma) => *i += 1,
                        None => return,
                        _ => use_tree(t, i, &path, out),
                    }
                }
            }
            Some(Tok::Other) => {
                *i += 1; // the glob `*`
                out.push((path, None));
                return;
            }
            _ => {
                let bound = path.last().cloned();
                out.push((path, bound));
                return;
            }
        }
    }
}

/// `segments` written in module `here` (inline modules included) as a path from the crate
/// root, or `None` when it leaves the crate.
fn absolute(
    segments: &[String],
    here: &[String],
    known: &BTreeSet<Module>,
    is_main: bool,
) -> Option<Vec<String>> {
    let first = segments.first()?;
    let mut m: Vec<String>;
    let mut rest = &segments[1..];
    match first.as_str() {
        "crate" => m = Vec::new(),
        "sliding_ladder" if is_main => m = Vec::new(),
        "self" => m = here.to_vec(),
        "super" => {
            m = here.to_vec();
            m.pop()?;
            while rest.first().is_some_and(|s| s == "super") {
                m.pop()?;
                rest = &rest[1..];
            }
        }
        _ => {
            // a child module of `here`, named without `self::`
            m = here.to_vec();
            m.push(first.clone());
            if is_main || !known.iter().any(|k| k.starts_with(&m)) {
                return None;
            }
        }
    }
    m.extend(rest.iter().cloned());
    Some(m)
}

/// The names each module brings in with a `use` at its top level: name -> absolute path.
type Names = BTreeMap<Module, BTreeMap<String, Vec<String>>>;

/// The file module an absolute path lands in: its longest known prefix, following a name that
/// module only imports (`pub use jet::Jet` in `scalar`, so `scalar::Jet` is `scalar::jet`).
fn target(path: &[String], known: &BTreeSet<Module>, names: &Names) -> Option<Module> {
    let mut p = path.to_vec();
    for _ in 0..8 {
        let mut k = p.clone();
        while !known.contains(&k) {
            k.pop()?;
        }
        match p.get(k.len()).and_then(|n| names.get(&k)?.get(n)) {
            Some(through) if through.as_slice() != p.as_slice() => {
                p = through.iter().chain(&p[k.len() + 1..]).cloned().collect()
            }
            _ => return Some(k),
        }
    }
    None
}

/// One path to this crate named in a file.
struct Import {
    /// From the crate root.
    path: Vec<String>,
    line: usize,
    /// As written.
    text: String,
    /// The name a top-level `use` binds in the file's module.
    binds: Option<String>,
}

/// The paths to this crate a file names: `use` trees and paths in code.
fn imports(
    file_module: &Module,
    text: &str,
    known: &BTreeSet<Module>,
    is_main: bool,
) -> Vec<Import> {
    let t = tokens(&code_only(text));
    let mut out = Vec::new();
    // inline modules (`mod tests { ... }`): their name and the brace depth they opened at
    let mut inline: Vec<(String, usize)> = Vec::new();
    let mut depth = 0usize;
    let mut i = 0;
    while i < t.len() {
        let here: Module = file_module
            .iter()
            .cloned()
            .chain(inline.iter().map(|(n, _)| n.clone()))
            .collect();
        let line = t[i].1;
        let mut push = |p: &[String], binds: Option<String>| {
            if let Some(path) = absolute(p, &here, known, is_main) {
                out.push(Import {
                    path,
                    line,
                    text: p.join("::"),
                    binds,
                });
            }
        };
        match &t[i].0 {
            Tok::Open => depth += 1,
            Tok::Close => {
                depth = depth.saturating_sub(1);
                if inline.last().is_some_and(|(_, d)| *d == depth) {
                    inline.pop();
                }
            }
            Tok::Ident(s) if s == "mod" => {
                if let (Some(n), Some((Tok::Open, _))) = (ident(t.get(i + 1)), t.get(i + 2)) {
                    inline.push((n.to_string(), depth));
                    depth += 1;
                    i += 3;
                    continue;
                }
            }
            Tok::Ident(s) if s == "use" => {
                let mut paths = Vec::new();
                let mut j = i + 1;
                if t.get(j).map(|x| &x.0) == Some(&Tok::Path) {
                    j += 1; // `use ::std::...`
                }
                use_tree(&t, &mut j, &[], &mut paths);
                for (p, bound) in paths {
                    push(&p, bound.filter(|_| depth == 0));
                }
                i = j;
                continue;
            }
            Tok::Ident(s)
                if (s == "crate"
                    || s == "super"
                    || s == "self"
                    || (is_main && s == "sliding_ladder"))
                    && t.get(i + 1).map(|x| &x.0) == Some(&Tok::Path)
                    && (i == 0 || t[i - 1].0 != Tok::Path) =>
            {
                let mut p = vec![s.clone()];
                let mut j = i + 1;
                while t.get(j).map(|x| &x.0) == Some(&Tok::Path) {
                    match ident(t.get(j + 1)) {
                        Some(n) => p.push(n.to_string()),
                        None => break,
                    }
                    j += 2;
                }
                push(&p, None);
                i = j;
                continue;
            }
            // a child module named in code: `child::f()` in a `mod.rs`
            Tok::Ident(s)
                if !is_main
                    && t.get(i + 1).map(|x| &x.0) == Some(&Tok::Path)
                    && (i == 0 || t[i - 1].0 != Tok::Path) =>
            {
                let mut child = here.clone();
                child.push(s.clone());
                if known.contains(&child) {
                    push(std::slice::from_ref(s), None);
                }
            }
            _ => {}
        }
        i += 1;
    }
    out
}

/// The import graph of the crate: file module -> file module, with where each edge was first
/// seen.
fn graph(root: &Path) -> BTreeMap<(Module, Module), Seen> {
    let src = root.join("src");
    let mut mods = modules(&src);
    let main_rs = mods.remove(&vec!["main".to_string()]);
    let known: BTreeSet<Module> = mods.keys().cloned().collect();
    let main: Module = vec!["main".to_string()];
    let files: Vec<(Module, PathBuf, bool)> = mods
        .into_iter()
        .map(|(m, f)| (m, f, false))
        .chain(main_rs.map(|f| (main.clone(), f, true)))
        .collect();
    let read: Vec<(Module, String, Vec<Import>)> = files
        .iter()
        .map(|(m, f, is_main)| {
            let text = std::fs::read_to_string(f).expect("source is readable");
            let file = f.strip_prefix(root).unwrap_or(f).display().to_string();
            (m.clone(), file, imports(m, &text, &known, *is_main))
        })
        .collect();
    let mut names = Names::new();
    for (m, _, found) in &read {
        for im in found {
            if let Some(n) = &im.binds {
                names
                    .entry(m.clone())
                    .or_default()
                    .insert(n.clone(), im.path.clone());
            }
        }
    }
    let mut edges = BTreeMap::new();
    for (from, file, found) in read {
        for im in found {
            let Some(to) = target(&im.path, &known, &names) else {
                continue;
            };
            if to != from {
                edges.entry((from.clone(), to)).or_insert(Seen {
                    file: file.clone(),
                    line: im.line,
                    path: im.text,
                });
            }
        }
    }
    edges
}

/// The edges between siblings: an import from `a::x::..` to `a::y::..` is an edge `a::x ->
/// a::y` (a module stands for everything under it). A module and its own submodules are one
/// unit (the parent gathers its children, they may use what it defines), so an edge between
/// them is no sibling edge.
fn sibling_edges<'a>(
    edges: impl Iterator<Item = &'a (Module, Module)>,
) -> BTreeSet<(Module, Module)> {
    edges
        .filter(|(a, b)| !a.starts_with(b) && !b.starts_with(a))
        .map(|(a, b)| {
            let l = a.iter().zip(b).take_while(|(x, y)| x == y).count();
            (a[..=l].to_vec(), b[..=l].to_vec())
        })
        .collect()
}

/// The strongly connected components with more than one module (Tarjan), each sorted.
fn cycles<N: Ord + Clone>(edges: &BTreeSet<(N, N)>) -> Vec<Vec<N>> {
    let nodes: BTreeSet<N> = edges
        .iter()
        .flat_map(|(a, b)| [a.clone(), b.clone()])
        .collect();
    let nodes: Vec<N> = nodes.into_iter().collect();
    let ix = |n: &N| nodes.binary_search(n).expect("a node");
    let mut adj = vec![Vec::new(); nodes.len()];
    for (a, b) in edges {
        adj[ix(a)].push(ix(b));
    }
    struct T {
        index: Vec<Option<usize>>,
        low: Vec<usize>,
        on: Vec<bool>,
        stack: Vec<usize>,
        next: usize,
        out: Vec<Vec<usize>>,
    }
    fn visit(v: usize, adj: &[Vec<usize>], t: &mut T) {
        t.index[v] = Some(t.next);
        t.low[v] = t.next;
        t.next += 1;
        t.stack.push(v);
        t.on[v] = true;
        for &w in &adj[v] {
            match t.index[w] {
                None => {
                    visit(w, adj, t);
                    t.low[v] = t.low[v].min(t.low[w]);
                }
                Some(iw) if t.on[w] => t.low[v] = t.low[v].min(iw),
                _ => {}
            }
        }
        if Some(t.low[v]) == t.index[v] {
            let mut c = Vec::new();
            loop {
                let w = t.stack.pop().expect("on the stack");
                t.on[w] = false;
                c.push(w);
                if w == v {
                    break;
                }
            }
            if c.len() > 1 {
                t.out.push(c);
            }
        }
    }
    let n = nodes.len();
    let mut t = T {
        index: vec![None; n],
        low: vec![0; n],
        on: vec![false; n],
        stack: Vec::new(),
        next: 0,
        out: Vec::new(),
    };
    for v in 0..n {
        if t.index[v].is_none() {
            visit(v, &adj, &mut t);
        }
    }
    t.out
        .into_iter()
        .map(|c| {
            let mut c: Vec<N> = c.into_iter().map(|i| nodes[i].clone()).collect();
            c.sort();
            c
        })
        .collect()
}

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
                "{a} -> {b}: a top-level module missing from LAYERS (tests/architecture.rs) and ARCHITECTURE.md"
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
