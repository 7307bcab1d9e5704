//! Assembling the book: which pages, in which order, and how links map from the repository's
//! layout (`equations/*.md`, `../src/…`, `figures/…`) to the book's.

use super::about;
use super::code::{locate, page_of};
use super::markdown::{heading_number, links_in, render, title_of, Hooks};
use super::pages::{page, NavItem, STYLE};
use super::panel::{numbered_display, Function};
use super::{generated, BookData, BookFile, Built};
use crate::registry::Equation;
use std::cell::RefCell;
use std::collections::{BTreeMap, BTreeSet};
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

/// Every registered equation by number (extensions 1000 + k).
fn registry() -> BTreeMap<u32, Equation> {
    crate::registry::equations()
        .into_iter()
        .chain(crate::registry::extensions())
        .map(|e| (e.number, e))
        .collect()
}

/// Resolve a markdown link of a file in the folder `base` (`equations`, `docs`, ...) to the
/// book's address: a chapter, an about page, a figure, or any other file of the repository as
/// a source page (recorded in `code`).
fn resolve(
    root: &Path,
    base: &str,
    dest: &str,
    code_text: Option<&str>,
    code: &RefCell<BTreeSet<String>>,
) -> Option<String> {
    if dest.starts_with("https://") || dest.starts_with("http://") {
        return Some(dest.to_string());
    }
    // The reader's pages (`docs/book/`) link the book's own pages and their own anchors; the
    // link checker of the tests holds every such target against the book as written.
    if base == super::reader_pages::FOLDER && (dest.starts_with('#') || is_book_page(dest)) {
        return Some(dest.to_string());
    }
    let (path, frag) = match dest.split_once('#') {
        Some((p, f)) => (p, format!("#{f}")),
        None => (dest, String::new()),
    };
    let file = about::join_relative(base, path)?;
    if !root.join(&file).is_file() {
        return None;
    }
    if let Some(rest) = file.strip_prefix("equations/") {
        if rest.ends_with(".md") && !rest.contains('/') {
            return Some(format!("{}{frag}", page_name(rest)));
        }
        if rest.starts_with("figures/") {
            return Some(rest.to_string());
        }
    }
    if file.starts_with("docs/") && file.ends_with(".md") {
        return Some(format!("{}{frag}", about::page_name(&file)));
    }
    code.borrow_mut().insert(file.clone());
    let line = code_text
        .and_then(|c| locate(root, c))
        .filter(|l| l.file == file)
        .map(|l| format!("#L{}", l.line))
        .unwrap_or_default();
    Some(format!("{}{line}", page_of(&file)))
}

/// A page of the book by its own name (`errata.html`, `phase2.html#x`), not a repository path.
fn is_book_page(dest: &str) -> bool {
    let page = dest.split('#').next().unwrap_or(dest);
    page.ends_with(".html") && !page.contains('/')
}

/// Make every file of the book.
pub fn build(root: &Path, data: &BookData) -> Built {
    let dir = data.dir.clone();
    let mut problems = Vec::new();
    let readme = std::fs::read_to_string(dir.join("README.md")).unwrap_or_else(|e| {
        problems.push(format!("equations/README.md: cannot read: {e}"));
        String::new()
    });
    let files = ordered_files(&dir, &readme);
    let sources: BTreeMap<String, String> = files
        .iter()
        .filter_map(|f| match std::fs::read_to_string(dir.join(f)) {
            Ok(s) => Some((f.clone(), s)),
            Err(e) => {
                problems.push(format!("equations/{f}: cannot read: {e}"));
                None
            }
        })
        .collect();
    // Where each numbered display lives.
    let mut home: BTreeMap<u32, String> = BTreeMap::new();
    for (f, src) in &sources {
        for l in src.lines().filter(|l| l.starts_with('#')) {
            if let Some(n) = heading_number(l.trim_start_matches('#')) {
                home.entry(n).or_insert_with(|| page_name(f));
            }
        }
    }
    let mut nav: Vec<NavItem> = vec![("index.html".into(), "Contents".into())];
    for f in &files {
        if let Some(src) = sources.get(f) {
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
    let reg = registry();
    let results: BTreeMap<u32, _> = data
        .results
        .iter()
        .chain(&data.extensions)
        .map(|r| (r.number, r))
        .collect();
    let errata: BTreeMap<u32, _> = data.errata.iter().map(|e| (e.number, e)).collect();
    let code = RefCell::new(BTreeSet::new());
    let missing = RefCell::new(Vec::new());
    let display = |n: u32, latex: &str| -> Option<Result<String, String>> {
        let r = results.get(&n)?;
        let e = reg.get(&n)?;
        let functions: Vec<Function> = e
            .functions
            .iter()
            .map(|p| {
                let location = locate(root, p);
                match &location {
                    Some(l) => {
                        code.borrow_mut().insert(l.file.clone());
                    }
                    None => missing
                        .borrow_mut()
                        .push(format!("({n}): function {p} not found in the source")),
                }
                Function { path: p, location }
            })
            .collect();
        Some(numbered_display(
            latex,
            r,
            &functions,
            errata.get(&n).copied(),
        ))
    };
    let link = |dest: &str, text: Option<&str>| resolve(root, "equations", dest, text, &code);
    let equation = |n: u32| {
        let page = home.get(&n)?;
        let anchor = match n.checked_sub(crate::registry::EXTENSION_BASE) {
            Some(k) if k > 0 => format!("eq-P{k}"),
            _ => format!("eq-{n}"),
        };
        Some(format!("{page}#{anchor}"))
    };
    let hooks = Hooks {
        display: &display,
        link: &link,
        equation: &equation,
    };
    let mut out: Vec<BookFile> = Vec::new();
    let mut bodies: BTreeMap<String, String> = BTreeMap::new();
    for (f, src) in sources
        .iter()
        .chain(std::iter::once((&"README.md".to_string(), &readme)))
    {
        let (html, p) = render(&format!("equations/{f}"), src, &hooks);
        problems.extend(p);
        bodies.insert(f.clone(), html);
    }
    for f in &files {
        let name = page_name(f);
        let body = super::harness::fold_rust_lists(&bodies.remove(f).unwrap_or_default());
        let body = match f.as_str() {
            "ERRATA.md" => generated::errata_page(data, &home, &body, &mut problems),
            "problems.md" => {
                super::problems::fold_declarations(&super::problems::fold_solutions(&body))
            }
            _ => body,
        };
        let title = sources.get(f).map(|s| title_of(s)).unwrap_or_default();
        out.push((
            name.clone(),
            page(&title, 0, &nav, &name, &body).into_bytes(),
        ));
    }
    let fall = generated::full_fall(root);
    let mut reader_problem = String::new();
    let mut reader_out = Vec::new();
    for d in super::reader_pages::documents(root, &mut problems) {
        let link = |dest: &str, text: Option<&str>| {
            resolve(root, super::reader_pages::FOLDER, dest, text, &code)
        };
        let hooks = Hooks {
            display: &display,
            link: &link,
            equation: &equation,
        };
        let (body, p) = render(&d.file, &d.source, &hooks);
        problems.extend(p);
        match d.page {
            Some(name) => reader_out.push((name, d.title, body)),
            None => reader_problem = body,
        }
    }
    let mut opening = String::new();
    match &fall {
        Ok((scene, o)) => match super::intro::answer(scene, o) {
            Some(a) => {
                opening.push_str(&reader_problem);
                opening.push_str(&super::intro::answer_html(&a, scene));
            }
            None => problems.push(format!("{}: the run did not reach flat", scene.file)),
        },
        Err(e) => problems.push(e.clone()),
    }
    if opening.is_empty() {
        opening.push_str(&reader_problem);
    }
    opening.push_str(super::intro::NEXT);
    let index_body = generated::index_page(
        data,
        &home,
        &opening,
        bodies.get("README.md").map_or("", |s| s),
    );
    out.push((
        "index.html".into(),
        page("Contents", 0, &nav, "index.html", &index_body).into_bytes(),
    ));
    for (name, title, body) in &reader_out {
        out.push((name.clone(), page(title, 0, &nav, name, body).into_bytes()));
    }
    out.push((
        "derivations.html".into(),
        page(
            "Six derivations",
            0,
            &nav,
            "derivations.html",
            &super::derivations::page(&data.results, &home),
        )
        .into_bytes(),
    ));
    out.push((
        "methods.html".into(),
        page(
            "Methods",
            0,
            &nav,
            "methods.html",
            &generated::methods_page(data),
        )
        .into_bytes(),
    ));
    let mut figures = generated::figure_files(&dir);
    if let Ok((scene, o)) = &fall {
        figures.extend(generated::fall_figures(scene, o));
    }
    out.push((
        "figures.html".into(),
        page(
            "Figures",
            0,
            &nav,
            "figures.html",
            &generated::figures_page(
                &figures,
                &[generated::WORK_PRECISION]
                    .into_iter()
                    .filter(|(f, _)| root.join("docs").join(f).is_file())
                    .collect::<Vec<_>>(),
            ),
        )
        .into_bytes(),
    ));
    match super::animation::svg(root) {
        Ok(svg) => out.push((super::animation::FILE.into(), svg.into_bytes())),
        Err(e) => problems.push(format!("animation.html: {e}")),
    }
    out.push((
        "animation.html".into(),
        page(
            "The fall, animated",
            0,
            &nav,
            "animation.html",
            &super::animation::page(),
        )
        .into_bytes(),
    ));
    for (name, bytes) in figures {
        out.push((format!("figures/{name}"), bytes));
    }
    let docs = about::documents(root, &mut problems);
    for d in &docs {
        let base = d.file.rsplit_once('/').map_or("", |(b, _)| b);
        let link = |dest: &str, text: Option<&str>| resolve(root, base, dest, text, &code);
        let hooks = Hooks {
            display: &display,
            link: &link,
            equation: &equation,
        };
        let (body, p) = render(&d.file, &d.source, &hooks);
        problems.extend(p);
        out.push((
            d.page.clone(),
            page(&d.title, 0, &nav, &d.page, &body).into_bytes(),
        ));
    }
    out.extend(about::pictures(root, &mut problems));
    out.push((
        "about.html".into(),
        page(
            "About the checks",
            0,
            &nav,
            "about.html",
            &about::index_body(&docs),
        )
        .into_bytes(),
    ));
    for file in code.into_inner() {
        match std::fs::read_to_string(root.join(&file)) {
            Ok(src) => {
                let name = page_of(&file);
                let depth = name.matches('/').count();
                let body = super::code::source_html(&file, &src);
                out.push((
                    name.clone(),
                    page(&file, depth, &nav, &name, &body).into_bytes(),
                ));
            }
            Err(e) => problems.push(format!("{file}: cannot read: {e}")),
        }
    }
    out.push(("style.css".into(), STYLE.as_bytes().to_vec()));
    problems.extend(missing.into_inner());
    for r in data.results.iter().chain(&data.extensions) {
        if !home.contains_key(&r.number) {
            problems.push(format!(
                "{}: no page of equations/ has this display",
                r.label
            ));
        }
    }
    Built {
        files: out,
        problems,
    }
}
