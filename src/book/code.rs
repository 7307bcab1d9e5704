//! Where each registered Rust function lives (file and line), and the source files as pages.
//!
//! The registry names functions by path below the crate root (`ladder::torque::torque_about_a`);
//! the line is found by reading the module's source for its `fn` item, so the link cannot go
//! stale when code moves. Written by hand: it is a line scan for one item kind, which a Rust
//! parser (syn) would do at the cost of a heavy dependency for no gain here.

use std::path::{Path, PathBuf};

/// A function found in the source: its file (relative to the crate root, `/`-separated) and
/// its 1-based line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Location {
    /// The file, e.g. `src/ladder/torque.rs`.
    pub file: String,
    /// The line of the `fn` item.
    pub line: usize,
}

/// The files that may hold module `path` (`ladder::torque` → `src/ladder/torque.rs` or
/// `src/ladder/torque/mod.rs`).
fn module_files(module: &[&str]) -> Vec<String> {
    let base = format!("src/{}", module.join("/"));
    vec![format!("{base}.rs"), format!("{base}/mod.rs")]
}

/// The 1-based line of `fn name` in `source` (a free function or a method), if any.
pub fn fn_line(source: &str, name: &str) -> Option<usize> {
    let needle = format!("fn {name}");
    source
        .lines()
        .position(|l| {
            let t = l.trim_start();
            let t = t.strip_prefix("pub(crate) ").unwrap_or(t);
            let t = t.strip_prefix("pub ").unwrap_or(t);
            t.strip_prefix(&needle)
                .is_some_and(|rest| rest.starts_with('(') || rest.starts_with('<'))
        })
        .map(|i| i + 1)
}

/// The 1-based line of method `name` of type `ty`: the first `fn name` after an `impl` line
/// that names `ty`.
fn method_line(source: &str, ty: &str, name: &str) -> Option<usize> {
    let impl_line = source.lines().position(|l| {
        let t = l.trim_start();
        t.starts_with("impl")
            && t.split(|c: char| !c.is_alphanumeric() && c != '_')
                .any(|w| w == ty)
    })?;
    let rest: String = source
        .lines()
        .skip(impl_line)
        .collect::<Vec<_>>()
        .join("\n");
    fn_line(&rest, name).map(|l| l + impl_line)
}

/// Find the function with path `path` below the crate root (a free function
/// `ladder::torque::torque_about_a` or a method `system::Particle::momentum`), reading the
/// sources under `root`.
pub fn locate(root: &Path, path: &str) -> Option<Location> {
    let parts: Vec<&str> = path.split("::").collect();
    let (name, module) = parts.split_last()?;
    let (ty, module) = match module.split_last() {
        Some((t, m)) if t.starts_with(|c: char| c.is_ascii_uppercase()) => (Some(*t), m),
        _ => (None, module),
    };
    for file in module_files(module) {
        if let Ok(src) = std::fs::read_to_string(root.join(&file)) {
            let line = match ty {
                Some(t) => method_line(&src, t, name),
                None => fn_line(&src, name),
            };
            if let Some(line) = line {
                return Some(Location { file, line });
            }
        }
    }
    None
}

/// The crate root (the directory holding `src/` and `equations/`).
pub fn crate_root() -> PathBuf {
    let docs = crate::docs::default_dir();
    docs.parent()
        .filter(|p| !p.as_os_str().is_empty())
        .map(Path::to_path_buf)
        .unwrap_or_else(|| PathBuf::from("."))
}

/// The book page of a source file: `src/ladder/torque.rs` → `code/src/ladder/torque.rs.html`.
pub fn page_of(file: &str) -> String {
    format!("code/{file}.html")
}

/// A source file as an HTML page body: one `<span id="L<n>">` per line, so `#L<n>` links land
/// on the line.
pub fn source_html(file: &str, source: &str) -> String {
    let mut out = format!(
        "<h1><code>{}</code></h1>\n<pre class=\"source\"><code>",
        super::pages::esc(file)
    );
    for (i, line) in source.lines().enumerate() {
        out.push_str(&format!(
            "<span class=\"line\" id=\"L{n}\"><a class=\"ln\" href=\"#L{n}\">{n}</a>{}</span>\n",
            super::pages::esc(line),
            n = i + 1
        ));
    }
    out.push_str("</code></pre>\n");
    out
}
