//! The book's "About the checks" pages: the tool's own documents under `docs/` (how to extend
//! the harness, the units of every symbol, the mutation records), apart from the note's
//! chapters. They are reached from one page, `about.html`, which is one entry of the
//! navigation; the chapters of `equations/` stay the book's sections.

use super::markdown::title_of;
use std::path::Path;

/// One document of `docs/`, as the book shows it.
pub struct AboutDoc {
    /// Its path in the repository, e.g. `docs/mutation/MUTATION-SIM.md`.
    pub file: String,
    /// Its page in the book, e.g. `about-mutation-sim.html`.
    pub page: String,
    /// Its first `# ` heading.
    pub title: String,
    /// Its markdown.
    pub source: String,
}

/// The folders of `docs/` whose markdown becomes pages, in the order the about page lists them.
pub const FOLDERS: [&str; 2] = ["docs", "docs/mutation"];

/// The book page of a markdown file of `docs/`: its path below `docs/`, lowercased, with `/`
/// as `-` (`docs/mutation/MUTATION-SIM.md` → `about-mutation-mutation-sim.html`).
pub fn page_name(file: &str) -> String {
    let rest = file.trim_start_matches("docs/").trim_end_matches(".md");
    format!("about-{}.html", rest.replace('/', "-").to_lowercase())
}

/// The names of the markdown files of `dir`, sorted (none when it cannot be read).
pub fn markdown_names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .map(|rd| {
            rd.filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().to_string())
                .filter(|n| n.ends_with(".md"))
                .collect()
        })
        .unwrap_or_default();
    names.sort();
    names
}

/// Every markdown document of [`FOLDERS`], each folder sorted by name; files that cannot be
/// read are reported in `problems`.
pub fn documents(root: &Path, problems: &mut Vec<String>) -> Vec<AboutDoc> {
    let mut out = Vec::new();
    for folder in FOLDERS {
        for name in markdown_names(&root.join(folder)) {
            let file = format!("{folder}/{name}");
            match std::fs::read_to_string(root.join(&file)) {
                Ok(source) => out.push(AboutDoc {
                    page: page_name(&file),
                    title: title_of(&source),
                    file,
                    source,
                }),
                Err(e) => problems.push(format!("{file}: cannot read: {e}")),
            }
        }
    }
    out
}

/// The pictures of `docs/` (`*.png`), which its pages embed by bare name: the book keeps them
/// beside the about pages so the same relative address works in both.
pub fn pictures(root: &Path, problems: &mut Vec<String>) -> Vec<(String, Vec<u8>)> {
    let mut names: Vec<String> = std::fs::read_dir(root.join("docs"))
        .map(|rd| {
            rd.filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().to_string())
                .filter(|n| n.ends_with(".png"))
                .collect()
        })
        .unwrap_or_default();
    names.sort();
    names
        .into_iter()
        .filter_map(|n| match std::fs::read(root.join("docs").join(&n)) {
            Ok(bytes) => Some((n, bytes)),
            Err(e) => {
                problems.push(format!("docs/{n}: cannot read: {e}"));
                None
            }
        })
        .collect()
}

/// The body of `about.html`: what these pages are, then one link per document.
pub fn index_body(docs: &[AboutDoc]) -> String {
    let mut out = String::from(
        "<h1>About the checks</h1>\n<p>The pages below are about the tool rather than the \
note: how a new display, point, derivation or integrator is added and checked, the units of \
every symbol, and the lab records of mutation testing (which mutants of the checking code \
each test catches). The note's own sections are in the navigation above.</p>\n<ul>\n",
    );
    for d in docs {
        out.push_str(&format!(
            "<li><a href=\"{}\">{}</a> <code>{}</code></li>\n",
            super::pages::esc(&d.page),
            super::pages::esc(&d.title),
            super::pages::esc(&d.file)
        ));
    }
    out.push_str("</ul>\n");
    out
}

/// `rel` joined to the folder `base` (both relative to the repository root), with `.` and
/// `..` resolved; None when it would leave the repository.
pub fn join_relative(base: &str, rel: &str) -> Option<String> {
    let mut parts: Vec<&str> = base.split('/').filter(|p| !p.is_empty()).collect();
    for seg in rel.split('/') {
        match seg {
            "" | "." => {}
            ".." => {
                parts.pop()?;
            }
            s => parts.push(s),
        }
    }
    Some(parts.join("/"))
}
