//! `ladder book --out DIR`: the note as verified, as a static HTML book that opens offline in
//! any browser, with no script and no network.
//!
//! One page per file of `equations/`, in the order of the contents table of
//! `equations/README.md` (the note's order); every display typeset as MathML; beside each
//! numbered display its status, live from the checks run at build time. Generated pages: the
//! index with the summary table, the errata (printed against corrected, with the symbolic
//! difference), the derivations (methods) and the figures; every linked Rust source file as a
//! page with line anchors, so `file:line` links resolve inside the book.
//!
//! Crates: pulldown-cmark reads the markdown (math events, tables), pulldown-latex turns LaTeX
//! into MathML Core ([`math`] says why). The HTML frame, the stylesheet and the atomic write are
//! written by hand: a template engine would add a dependency for five page shapes.

pub mod about;
pub mod animation;
pub mod code;
pub mod derivations;
pub mod generated;
pub mod harness;
pub mod intro;
pub mod markdown;
pub mod math;
pub mod pages;
pub mod panel;
pub mod problems;
pub mod reader;
pub mod reader_pages;
pub mod refs;
pub mod site;
pub mod terms;
pub mod write;

pub use write::write_atomically;

use crate::registry::check::Config;
use crate::verify::errata::ErratumReport;
use crate::verify::{EquationResult, MethodResult};
use std::path::Path;

/// Everything the book shows that comes from running the checks.
pub struct BookData {
    /// The displays of the note, judged.
    pub results: Vec<EquationResult>,
    /// The extension beyond the note, (P1)-(P5).
    pub extensions: Vec<EquationResult>,
    /// The misprints with their evidence.
    pub errata: Vec<ErratumReport>,
    /// The prose claims, checked.
    pub claims: Vec<crate::verify::claims::Claim>,
    /// The derivations of the equation of motion.
    pub methods: Vec<MethodResult>,
    /// Problems the doc-as-test harness found in `equations/`.
    pub docs_problems: Vec<String>,
    /// The summary line of `ladder verify`.
    pub summary: String,
    /// The folder of markdown the book is made from (`equations/`, or `--equations DIR`).
    pub dir: std::path::PathBuf,
}

impl BookData {
    /// Run every check (as `ladder verify` and `ladder errata` do) with `cfg`.
    pub fn gather(cfg: &Config) -> BookData {
        let t = std::time::Instant::now();
        let results = crate::verify::verify_all(cfg);
        let dir = crate::docs::note_dir();
        let docs = crate::docs::check_book(&dir);
        let summary =
            crate::verify::summary::summary_line(&results, cfg, t.elapsed().as_secs_f64());
        BookData {
            extensions: crate::verify::verify_extensions(cfg),
            errata: crate::verify::errata::errata(cfg),
            claims: crate::verify::claims::claims(),
            methods: crate::verify::check_methods(cfg),
            docs_problems: docs.problems,
            summary,
            results,
            dir,
        }
    }

    /// True when every display passed (verified, proved where claimed, erratum or definition),
    /// every method passed and the markdown matches the registry.
    pub fn all_good(&self) -> bool {
        let ok = |r: &EquationResult| r.status != crate::verify::Status::Failed;
        self.results.iter().all(ok)
            && self.extensions.iter().all(ok)
            && self.methods.iter().all(|m| m.passed)
            && self.docs_problems.is_empty()
    }
}

/// A file of the book: its path below the book's root (`/`-separated) and its bytes.
pub type BookFile = (String, Vec<u8>);

/// The book in memory, and what went wrong while making it (a display that did not typeset,
/// a link that does not resolve).
pub struct Built {
    /// Every file.
    pub files: Vec<BookFile>,
    /// Problems, as `file: message`.
    pub problems: Vec<String>,
}

/// Make the book from the markdown of `data.dir` (source pages from `root`) and the check
/// results.
pub fn build(root: &Path, data: &BookData) -> Built {
    site::build(root, data)
}

/// Write the book to `out` (`ladder book --out DIR`): the checks run, the pages built and
/// written atomically. An error means nothing was written (the folder cannot be used, or a
/// write failed and was rolled back); the caller says what and chooses the exit code.
pub fn write_book(out: &Path, cfg: &Config) -> Result<(Built, BookData), String> {
    write::check_out(out)?;
    let data = BookData::gather(cfg);
    let built = build(&code::crate_root(), &data);
    write_atomically(out, &built.files)?;
    Ok((built, data))
}
