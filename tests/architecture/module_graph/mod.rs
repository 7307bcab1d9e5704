//! The module graph of the crate read from its source (used by tests/architecture/main.rs): one
//! node per file module, one edge per module a file names, siblings' edges, and cycles.
//! Written by hand (a token scan of a few hundred lines, no new dependency) because a full
//! parser such as syn would only add build time for what a token scan answers.

pub mod scan;

use scan::{imports, Import};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// A module: its path below the crate root (`["sim", "scene"]`; `[]` is `lib.rs`).
pub type Module = Vec<String>;

/// Where an edge was first seen: file, line and the path as written.
#[derive(Clone, Debug)]
pub struct Seen {
    /// The file, from the crate root.
    pub file: String,
    /// Its line.
    pub line: usize,
    /// The path as written.
    pub path: String,
}

/// `a::b`, or `crate` for the root.
pub fn name(m: &Module) -> String {
    if m.is_empty() {
        "crate".into()
    } else {
        m.join("::")
    }
}

/// The module of each source file under `src/`.
pub fn modules(src: &Path) -> BTreeMap<Module, PathBuf> {
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

/// The names each module brings in with a `use` at its top level: name -> absolute path.
pub type Names = BTreeMap<Module, BTreeMap<String, Vec<String>>>;

/// The file module an absolute path lands in: its longest known prefix, following a name that
/// module only imports (`pub use jet::Jet` in `scalar`, so `scalar::Jet` is `scalar::jet`).
pub fn target(path: &[String], known: &BTreeSet<Module>, names: &Names) -> Option<Module> {
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

/// The import graph of the crate: file module -> file module, with where each edge was first
/// seen.
pub fn graph(root: &Path) -> BTreeMap<(Module, Module), Seen> {
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
pub fn sibling_edges<'a>(
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
pub fn cycles<N: Ord + Clone>(edges: &BTreeSet<(N, N)>) -> Vec<Vec<N>> {
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
