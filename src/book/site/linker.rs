//! What a page's markdown asks of the rest of the book while it is rendered: the panel of a
//! numbered display, the book's address of a link or of display (N). The source files these
//! touch are gathered (`code`) to become the book's source pages.

use crate::book::about;
use crate::book::code::{locate, page_of};
use crate::book::markdown::{render, Hooks};
use crate::book::panel::{numbered_display, Function};
use crate::book::BookData;
use crate::registry::Equation;
use crate::verify::errata::ErratumReport;
use crate::verify::EquationResult;
use std::cell::RefCell;
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

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
    if base == crate::book::reader_pages::FOLDER && (dest.starts_with('#') || is_book_page(dest)) {
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
            return Some(format!("{}{frag}", super::page_name(rest)));
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

/// The hooks of every page: the judged displays, the registry and where each display lives.
pub struct Linker<'a> {
    root: &'a Path,
    reg: BTreeMap<u32, Equation>,
    results: BTreeMap<u32, &'a EquationResult>,
    errata: BTreeMap<u32, &'a ErratumReport>,
    home: &'a BTreeMap<u32, String>,
    /// The repository files linked or shown so far: each becomes a source page.
    pub code: RefCell<BTreeSet<String>>,
    /// Functions named by the registry that the source does not hold, as problems.
    pub missing: RefCell<Vec<String>>,
}

impl<'a> Linker<'a> {
    /// The hooks for the book of `data`, with `home` the page of each numbered display.
    pub fn new(root: &'a Path, data: &'a BookData, home: &'a BTreeMap<u32, String>) -> Self {
        let reg = registry();
        let results: BTreeMap<u32, _> = data
            .results
            .iter()
            .chain(&data.extensions)
            .map(|r| (r.number, r))
            .collect();
        let errata: BTreeMap<u32, _> = data.errata.iter().map(|e| (e.number, e)).collect();
        Linker {
            root,
            reg,
            results,
            errata,
            home,
            code: RefCell::new(BTreeSet::new()),
            missing: RefCell::new(Vec::new()),
        }
    }

    /// The repository's root, where the source files are read.
    pub fn root(&self) -> &'a Path {
        self.root
    }

    /// Display `n` with its panel (its verdict, its functions linked to their source).
    fn display(&self, n: u32, latex: &str) -> Option<Result<String, String>> {
        let r = self.results.get(&n)?;
        let e = self.reg.get(&n)?;
        let functions: Vec<Function> = e
            .functions
            .iter()
            .map(|p| {
                let location = locate(self.root, p);
                match &location {
                    Some(l) => {
                        self.code.borrow_mut().insert(l.file.clone());
                    }
                    None => self
                        .missing
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
            self.errata.get(&n).copied(),
        ))
    }

    /// The book's address of display `n`: its page and anchor (`eq-P{k}` for extensions).
    fn equation(&self, n: u32) -> Option<String> {
        let page = self.home.get(&n)?;
        let anchor = match n.checked_sub(crate::registry::EXTENSION_BASE) {
            Some(k) if k > 0 => format!("eq-P{k}"),
            _ => format!("eq-{n}"),
        };
        Some(format!("{page}#{anchor}"))
    }

    /// Render the markdown `source` of `file`, its links relative to the folder `base`: the
    /// HTML and the problems met.
    pub fn render(&self, base: &str, file: &str, source: &str) -> (String, Vec<String>) {
        let display = |n: u32, latex: &str| self.display(n, latex);
        let link =
            |dest: &str, text: Option<&str>| resolve(self.root, base, dest, text, &self.code);
        let equation = |n: u32| self.equation(n);
        let hooks = Hooks {
            display: &display,
            link: &link,
            equation: &equation,
        };
        render(file, source, &hooks)
    }
}
