//! Doc-as-test: the book in `equations/*.md` is the note the registry is built from, and the
//! figures and examples it states are what the code computes.
//!
//! The registry is derived from the markdown ([`crate::registry::source`]), so the book and the
//! registry cannot disagree about a display; what can go wrong is the folder itself (a section
//! the parser cannot read: `file:line: reason`), a binary built from another version of it (a
//! section that differs from the note in use is reported, with its line: rebuild), and the prose
//! around the displays. A table whose first header cell is an inline-code name of an example
//! function ([`examples`]) is executable: each row gives the inputs, the expected value and the
//! tolerance, and is run. A worked example ([`worked`]) must be what the code generates now.
//! Every problem is reported as `file:line: message`; nothing panics on malformed input.

pub mod examples;
pub mod facts;
pub mod pages;
pub mod worked;

use crate::registry::source::{Lines, Note, Section};
use crate::registry::{label_of, EXTENSION_BASE};
use pulldown_cmark::{Event, Options, Parser, Tag, TagEnd};
use std::path::{Path, PathBuf};

/// The result of checking the book.
#[derive(Clone, Debug, Default)]
pub struct BookReport {
    /// Every problem found, as `file:line: message`.
    pub problems: Vec<String>,
    /// Number of the note's displays found (extensions (Pk) left out).
    pub equations_found: usize,
    /// Example table rows run.
    pub examples_run: usize,
}

/// The `equations/` directory of this crate.
pub fn default_dir() -> PathBuf {
    let here = Path::new("equations");
    if here.is_dir() {
        here.to_path_buf()
    } else {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("equations")
    }
}

/// The folder of the note in use: `ladder --equations DIR`'s, else this crate's `equations/`.
pub fn note_dir() -> PathBuf {
    crate::registry::source::current()
        .dir
        .clone()
        .unwrap_or_else(default_dir)
}

pub use crate::registry::source::normalize_latex;

/// Check the book in `dir` against the note in use ([`crate::registry::source::current`]).
pub fn check_book(dir: &Path) -> BookReport {
    check_book_against(dir, crate::registry::source::current())
}

/// Check the book in `dir`: every section readable, each the same as in `built` (the note the
/// registry was built from), every example and worked example as the code computes it.
pub fn check_book_against(dir: &Path, built: &Note) -> BookReport {
    let mut rep = BookReport::default();
    let note = match Note::from_dir(dir) {
        Ok(n) => n,
        Err(e) => {
            rep.problems.push(e.to_string());
            return rep;
        }
    };
    rep.problems
        .extend(note.errors.iter().map(ToString::to_string));
    in_step(&note, built, &mut rep.problems);
    rep.equations_found = note
        .sections
        .iter()
        .filter(|s| s.number < EXTENSION_BASE)
        .count();
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|rd| rd.flatten().map(|e| e.path()).collect())
        .unwrap_or_default();
    files.retain(|p| p.extension().is_some_and(|x| x == "md"));
    files.sort();
    for f in &files {
        if let Ok(src) = std::fs::read_to_string(f) {
            check_file(&f.display().to_string(), &src, &mut rep);
        }
    }
    facts::check_facts(dir, &facts::facts(), &mut rep.problems);
    rep
}

/// What of a section the registry uses, for comparing two versions of it (not its place).
fn content(s: &Section) -> impl PartialEq + '_ {
    (
        (&s.title, &s.section, &s.latex, s.kind, &s.functions),
        (&s.checks, &s.law, &s.erratum, &s.continues),
    )
}

/// The sections of the folder against those of the note the registry was built from: a
/// difference means the binary was built from another version of the markdown.
fn in_step(folder: &Note, built: &Note, problems: &mut Vec<String>) {
    let built_from = "the note this binary was built from";
    let rebuild = "(rebuild: cargo build)";
    for s in &folder.sections {
        let at = format!("{}:{}", s.file, s.line);
        let label = label_of(s.number);
        match built.section(s.number) {
            None => problems.push(format!("{at}: {label} is not in {built_from} {rebuild}")),
            Some(b) if content(b) != content(s) => {
                problems.push(format!("{at}: {label} differs from {built_from} {rebuild}"))
            }
            Some(_) => {}
        }
    }
    for b in &built.sections {
        let label = label_of(b.number);
        let gone = folder.section(b.number).is_none();
        let broken = folder.errors.iter().any(|e| e.reason.starts_with(&label));
        if gone && !broken {
            problems.push(format!(
                "{}:{}: {label} of {built_from} is not in the folder {rebuild}",
                b.file, b.line
            ));
        }
    }
}

/// Run the example tables and worked examples of one markdown source; `name` is used in
/// messages.
pub fn check_file(name: &str, src: &str, rep: &mut BookReport) {
    let mut in_table = false;
    let mut table: Vec<Vec<String>> = Vec::new();
    let mut table_line = 0;
    let mut cell = String::new();
    let lines = Lines::new(src);
    for (ev, range) in
        Parser::new_ext(src, Options::ENABLE_MATH | Options::ENABLE_TABLES).into_offset_iter()
    {
        match ev {
            Event::Start(Tag::Table(_)) => {
                in_table = true;
                table.clear();
                table_line = lines.line_of(range.start);
            }
            Event::End(TagEnd::Table) => {
                in_table = false;
                rep.examples_run +=
                    examples::run_table(&format!("{name}:{table_line}"), &table, &mut rep.problems);
            }
            Event::Start(Tag::TableHead) | Event::Start(Tag::TableRow) => table.push(Vec::new()),
            Event::Start(Tag::TableCell) => cell.clear(),
            Event::End(TagEnd::TableCell) => {
                if let Some(row) = table.last_mut() {
                    row.push(cell.trim().to_string());
                }
            }
            Event::Code(t) | Event::Text(t) | Event::InlineMath(t) if in_table => cell.push_str(&t),
            _ => {}
        }
    }
    for (number, line, text) in worked::blocks(src) {
        match worked::worked_example(number) {
            Ok(want) if normalize_latex(&want) == normalize_latex(&text) => {}
            Ok(_) => rep.problems.push(format!(
                "{name}:{line}: the worked example of ({number}) differs from what the code gives now \
                 (regenerate: LADDER_BLESS_DOCS=1 cargo test --test book docs)"
            )),
            Err(e) => rep.problems.push(format!("{name}:{line}: worked example: {e}")),
        }
        rep.examples_run += 1;
    }
}

/// "1st", "2nd", "3rd", "4th", ...
pub fn ordinal(n: u32) -> String {
    let suffix = match (n % 10, n % 100) {
        (1, k) if k != 11 => "st",
        (2, k) if k != 12 => "nd",
        (3, k) if k != 13 => "rd",
        _ => "th",
    };
    format!("{n}{suffix}")
}
