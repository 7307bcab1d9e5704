//! The pages of the book, made in the order they are listed (the order of the files and of
//! the problems in [`Built`]).

use super::linker::Linker;
use super::{page_name, top_page, Sources};
use crate::book::markdown::title_of;
use crate::book::pages::{page, NavItem};
use crate::book::{about, generated, BookData, Built};
use crate::sim::outcome::Outcome;
use crate::sim::scene::Scene;
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The full fall of `scenes/full-fall.toml`, or why it could not be run.
pub type Fall = Result<(Scene, Outcome), String>;

/// One page per chapter of `equations/`; returns the rendered bodies not used by a chapter
/// (the README's, for the index).
pub fn chapter_pages(
    linker: &Linker,
    data: &BookData,
    home: &BTreeMap<u32, String>,
    sources: &Sources,
    nav: &[NavItem],
    built: &mut Built,
) -> BTreeMap<String, String> {
    let mut bodies: BTreeMap<String, String> = BTreeMap::new();
    for (f, src) in sources
        .texts
        .iter()
        .chain(std::iter::once((&"README.md".to_string(), &sources.readme)))
    {
        let (html, p) = linker.render("equations", &format!("equations/{f}"), src);
        built.problems.extend(p);
        bodies.insert(f.clone(), html);
    }
    for f in &sources.files {
        let name = page_name(f);
        let body = crate::book::harness::fold_rust_lists(&bodies.remove(f).unwrap_or_default());
        let body = match f.as_str() {
            "ERRATA.md" => generated::errata_page(data, home, &body, &mut built.problems),
            "problems.md" => crate::book::problems::fold_declarations(
                &crate::book::problems::fold_solutions(&body),
            ),
            _ => body,
        };
        let title = sources
            .texts
            .get(f)
            .map(|s| title_of(s))
            .unwrap_or_default();
        built.files.push(top_page(&title, nav, &name, &body));
    }
    bodies
}

/// The index (the reader's opening with the answer of the full fall, then the README's
/// contents) and the reader's pages of `docs/book/`.
pub fn index_and_reader_pages(
    linker: &Linker,
    data: &BookData,
    home: &BTreeMap<u32, String>,
    fall: &Fall,
    readme: &str,
    nav: &[NavItem],
    built: &mut Built,
) {
    use crate::book::{intro, reader_pages};
    let mut reader_problem = String::new();
    let mut reader_out = Vec::new();
    for d in reader_pages::documents(linker.root(), &mut built.problems) {
        let (body, p) = linker.render(reader_pages::FOLDER, &d.file, &d.source);
        built.problems.extend(p);
        match d.page {
            Some(name) => reader_out.push((name, d.title, body)),
            None => reader_problem = body,
        }
    }
    let mut opening = String::new();
    match fall {
        Ok((scene, o)) => match intro::answer(scene, o) {
            Some(a) => {
                opening.push_str(&reader_problem);
                opening.push_str(&intro::answer_html(&a, scene));
            }
            None => built
                .problems
                .push(format!("{}: the run did not reach flat", scene.file)),
        },
        Err(e) => built.problems.push(e.clone()),
    }
    if opening.is_empty() {
        opening.push_str(&reader_problem);
    }
    opening.push_str(intro::NEXT);
    let index_body = generated::index_page(data, home, &opening, readme);
    built
        .files
        .push(top_page("Contents", nav, "index.html", &index_body));
    for (name, title, body) in &reader_out {
        built.files.push(top_page(title, nav, name, body));
    }
}

/// The pages made from the checks and the simulator: derivations, methods, figures (with
/// the full fall's) and the animation, then the figures' files.
pub fn generated_pages(
    root: &Path,
    data: &BookData,
    home: &BTreeMap<u32, String>,
    fall: &Fall,
    nav: &[NavItem],
    built: &mut Built,
) {
    use crate::book::animation;
    let derivations = crate::book::derivations::page(&data.results, home);
    built.files.push(top_page(
        "Six derivations",
        nav,
        "derivations.html",
        &derivations,
    ));
    let methods = generated::methods_page(data);
    built
        .files
        .push(top_page("Methods", nav, "methods.html", &methods));
    let mut figures = generated::figure_files(&data.dir);
    if let Ok((scene, o)) = fall {
        figures.extend(generated::fall_figures(scene, o));
    }
    // The work-precision figure is shown only when docs/ holds it.
    let docs_figures = [generated::WORK_PRECISION]
        .into_iter()
        .filter(|(f, _)| root.join("docs").join(f).is_file())
        .collect::<Vec<_>>();
    let figures_body = generated::figures_page(&figures, &docs_figures);
    built
        .files
        .push(top_page("Figures", nav, "figures.html", &figures_body));
    match animation::svg(root) {
        Ok(svg) => built.files.push((animation::FILE.into(), svg.into_bytes())),
        Err(e) => built.problems.push(format!("animation.html: {e}")),
    }
    built.files.push(top_page(
        "The fall, animated",
        nav,
        "animation.html",
        &animation::page(),
    ));
    for (name, bytes) in figures {
        built.files.push((format!("figures/{name}"), bytes));
    }
}

/// The about pages of `docs/` (their links relative to their own folder), their pictures and
/// their index.
pub fn about_pages(linker: &Linker, nav: &[NavItem], built: &mut Built) {
    let docs = about::documents(linker.root(), &mut built.problems);
    for d in &docs {
        let base = d.file.rsplit_once('/').map_or("", |(b, _)| b);
        let (body, p) = linker.render(base, &d.file, &d.source);
        built.problems.extend(p);
        built.files.push(top_page(&d.title, nav, &d.page, &body));
    }
    built
        .files
        .extend(about::pictures(linker.root(), &mut built.problems));
    let index = about::index_body(&docs);
    built
        .files
        .push(top_page("About the checks", nav, "about.html", &index));
}

/// One page per source file linked or shown, at its path's depth.
pub fn source_pages(root: &Path, code: BTreeSet<String>, nav: &[NavItem], built: &mut Built) {
    use crate::book::code::{page_of, source_html};
    for file in code {
        match std::fs::read_to_string(root.join(&file)) {
            Ok(src) => {
                let name = page_of(&file);
                let depth = name.matches('/').count();
                let body = source_html(&file, &src);
                built.files.push((
                    name.clone(),
                    page(&file, depth, nav, &name, &body).into_bytes(),
                ));
            }
            Err(e) => built.problems.push(format!("{file}: cannot read: {e}")),
        }
    }
}
