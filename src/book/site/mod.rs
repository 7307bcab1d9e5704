//! Assembling the book: which pages, in which order, and how links map from the repository's
//! layout (`equations/*.md`, `../src/…`, `figures/…`) to the book's.

mod linker;
mod parts;

use super::markdown::{heading_number, links_in, title_of};
use super::pages::{page, NavItem, STYLE};
use super::{BookData, BookFile, Built};
use linker::Linker;
use std::collections::BTreeMap;
use std::path::Path;

/// The book page of a markdown file: `README.md` is the index, `ERRATA.md` joins the errata
/// page, any other `X.md` becomes `x.html`.
pub fn page_name(md: &str) -> String {
    match md {
        "README.md" => "index.html".into(),
        _ => format!("{}.html", md.trim_end_matches(".md").to_lowercase()),
    }
}

/// The markdown files in the note's order: the contents table of `README.md`, then any other.
fn ordered_files(dir: &Path, readme: &str) -> Vec<String> {
    let contents = readme.find("## Contents").map_or(readme, |i| &readme[i..]);
    let mut order: Vec<String> = Vec::new();
    for l in links_in(contents) {
        if l.ends_with(".md") && !l.contains('/') && dir.join(&l).is_file() && !order.contains(&l) {
            order.push(l);
        }
    }
    let mut rest: Vec<String> = std::fs::read_dir(dir)
        .map(|rd| {
            rd.filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().to_string())
                .filter(|n| n.ends_with(".md") && n != "README.md")
                .collect()
        })
        .unwrap_or_default();
    rest.sort();
    for r in rest {
        if !order.contains(&r) {
            order.push(r);
        }
    }
    order
}

/// A short navigation label: "Sec. 2.2 — Torque …" → "2.2", "Phase 2: the floor …" →
/// "Phase 2", "Errata of the note" → "Errata".
fn short_label(title: &str) -> String {
    let head = title.split(" — ").next().unwrap_or(title);
    let head = head.split(':').next().unwrap_or(head);
    let head = head.trim_start_matches("Sec. ").trim();
    if head.chars().count() > 12 {
        head.split_whitespace().next().unwrap_or(head).to_string()
    } else {
        head.to_string()
    }
}

/// The markdown of `equations/`: the README, the other files in the note's order, and the
/// text of each file that could be read.
struct Sources {
    readme: String,
    files: Vec<String>,
    texts: BTreeMap<String, String>,
}

/// Read the markdown of `dir`; what cannot be read goes to `problems`.
fn read_sources(dir: &Path, problems: &mut Vec<String>) -> Sources {
    let readme = std::fs::read_to_string(dir.join("README.md")).unwrap_or_else(|e| {
        problems.push(format!("equations/README.md: cannot read: {e}"));
        String::new()
    });
    let files = ordered_files(dir, &readme);
    let texts: BTreeMap<String, String> = files
        .iter()
        .filter_map(|f| match std::fs::read_to_string(dir.join(f)) {
            Ok(s) => Some((f.clone(), s)),
            Err(e) => {
                problems.push(format!("equations/{f}: cannot read: {e}"));
                None
            }
        })
        .collect();
    Sources {
        readme,
        files,
        texts,
    }
}

/// Where each numbered display lives: the page of the first heading `(N) …` naming it.
fn display_homes(texts: &BTreeMap<String, String>) -> BTreeMap<u32, String> {
    let mut home: BTreeMap<u32, String> = BTreeMap::new();
    for (f, src) in texts {
        for l in src.lines().filter(|l| l.starts_with('#')) {
            if let Some(n) = heading_number(l.trim_start_matches('#')) {
                home.entry(n).or_insert_with(|| page_name(f));
            }
        }
    }
    home
}

/// The navigation bar: the contents, the chapters in order, then the book's own pages.
fn navigation(sources: &Sources) -> Vec<NavItem> {
    let mut nav: Vec<NavItem> = vec![("index.html".into(), "Contents".into())];
    for f in &sources.files {
        if let Some(src) = sources.texts.get(f) {
            nav.push((page_name(f), short_label(&title_of(src))));
        }
    }
    nav.push(("derivations.html".into(), "Six derivations".into()));
    nav.push(("animation.html".into(), "The fall, animated".into()));
    nav.push(("methods.html".into(), "Methods".into()));
    nav.push(("figures.html".into(), "Figures".into()));
    nav.push(("glossary.html".into(), "Glossary".into()));
    nav.push(("references.html".into(), "References".into()));
    nav.push(("about.html".into(), "About the checks".into()));
    nav
}

/// A page at the top of the book (depth 0), as the file `name`.
fn top_page(title: &str, nav: &[NavItem], name: &str, body: &str) -> BookFile {
    (
        name.to_string(),
        page(title, 0, nav, name, body).into_bytes(),
    )
}

/// Make every file of the book. The order of the files and of the problems is the order the
/// pages are made in: chapters, index and reader's pages, generated pages, about pages,
/// source pages.
pub fn build(root: &Path, data: &BookData) -> Built {
    let mut built = Built {
        files: Vec::new(),
        problems: Vec::new(),
    };
    let sources = read_sources(&data.dir, &mut built.problems);
    let home = display_homes(&sources.texts);
    let nav = navigation(&sources);
    let linker = Linker::new(root, data, &home);
    let bodies = parts::chapter_pages(&linker, data, &home, &sources, &nav, &mut built);
    let fall = super::generated::full_fall(root);
    let readme = bodies.get("README.md").map_or("", |s| s);
    parts::index_and_reader_pages(&linker, data, &home, &fall, readme, &nav, &mut built);
    parts::generated_pages(root, data, &home, &fall, &nav, &mut built);
    parts::about_pages(&linker, &nav, &mut built);
    let Linker { code, missing, .. } = linker;
    parts::source_pages(root, code.into_inner(), &nav, &mut built);
    built
        .files
        .push(("style.css".into(), STYLE.as_bytes().to_vec()));
    built.problems.extend(missing.into_inner());
    for r in data.results.iter().chain(&data.extensions) {
        if !home.contains_key(&r.number) {
            built.problems.push(format!(
                "{}: no page of equations/ has this display",
                r.label
            ));
        }
    }
    built
}
