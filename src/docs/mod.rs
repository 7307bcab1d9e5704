//! Doc-as-test: the book in `equations/*.md` is held against the registry.
//!
//! Every markdown file is parsed with pulldown-cmark (math enabled). A heading that starts with
//! `(N)` opens the section of equation N; in it the harness requires
//!
//! * the first display-math block to equal the registry's printed LaTeX (whitespace aside),
//! * every function named in a link's inline code to be one of the registry's functions for N,
//!   and at least one such link,
//! * a line `*Kind:* <kind>` naming the registry's kind,
//!
//! and across all files every number 1..=90 exactly once. A table whose first header cell is
//! an inline-code name of an example function ([`examples`]) is executable: each row gives the
//! inputs, the expected value and the tolerance, and is run. Every problem is reported as
//! `file:line: message`; nothing panics on malformed input.

pub mod examples;
pub mod facts;
pub mod pages;
pub mod worked;

use crate::registry::{equations, extensions};
use pulldown_cmark::{Event, Options, Parser, Tag, TagEnd};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The result of checking the book.
#[derive(Clone, Debug, Default)]
pub struct BookReport {
    /// Every problem found, as `file:line: message`.
    pub problems: Vec<String>,
    /// Number of distinct equations found.
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

/// Collapse whitespace so that line breaks in the markdown do not matter.
pub fn normalize_latex(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

fn line_of(src: &str, offset: usize) -> usize {
    src[..offset.min(src.len())].matches('\n').count() + 1
}

/// Check every `*.md` file in `dir` (sorted by name).
pub fn check_book(dir: &Path) -> BookReport {
    let mut rep = BookReport::default();
    let mut files: Vec<PathBuf> = match std::fs::read_dir(dir) {
        Ok(rd) => rd
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "md"))
            .collect(),
        Err(e) => {
            rep.problems
                .push(format!("{}: cannot read the directory: {e}", dir.display()));
            return rep;
        }
    };
    files.sort();
    let mut seen: BTreeMap<u32, String> = BTreeMap::new();
    for f in &files {
        match std::fs::read_to_string(f) {
            Ok(src) => check_file(&f.display().to_string(), &src, &mut seen, &mut rep),
            Err(e) => rep
                .problems
                .push(format!("{}:1: cannot read: {e}", f.display())),
        }
    }
    for n in 1..=90 {
        if !seen.contains_key(&n) {
            rep.problems.push(format!(
                "{}: equation ({n}) is not documented in any file",
                dir.display()
            ));
        }
    }
    for e in extensions() {
        if !seen.contains_key(&e.number) {
            rep.problems.push(format!(
                "{}: extension {} is not documented in any file",
                dir.display(),
                e.label()
            ));
        }
    }
    facts::check_facts(dir, &facts::facts(), &mut rep.problems);
    rep.equations_found = seen.keys().filter(|&&n| n <= 90).count();
    rep
}

/// What one equation's section contained.
#[derive(Default)]
struct Section {
    number: u32,
    line: usize,
    start: usize,
    math: Option<(String, usize)>,
    functions: Vec<(String, usize)>,
}

/// Check one markdown source; `name` is used in messages.
pub fn check_file(name: &str, src: &str, seen: &mut BTreeMap<u32, String>, rep: &mut BookReport) {
    let registry: Vec<_> = equations().into_iter().chain(extensions()).collect();
    let mut sections: Vec<Section> = Vec::new();
    let mut heading: Option<(String, usize)> = None;
    let (mut in_link, mut in_table, mut in_header) = (false, false, false);
    let mut table: Vec<Vec<String>> = Vec::new();
    let mut table_line = 0;
    let mut cell = String::new();
    for (ev, range) in
        Parser::new_ext(src, Options::ENABLE_MATH | Options::ENABLE_TABLES).into_offset_iter()
    {
        let line = line_of(src, range.start);
        match ev {
            Event::Start(Tag::Heading { .. }) => heading = Some((String::new(), line)),
            Event::End(TagEnd::Heading(_)) => {
                if let Some((text, hl)) = heading.take() {
                    if let Some(n) = heading_number(&text) {
                        let here = format!("{name}:{hl}");
                        if let Some(first) = seen.get(&n) {
                            rep.problems.push(format!(
                                "{here}: equation ({n}) documented twice (first at {first})"
                            ));
                        } else if !(1..=90).contains(&n) && !registry.iter().any(|e| e.number == n)
                        {
                            rep.problems.push(format!(
                                "{here}: {text} is not an equation of the note (1..=90) or a registered extension"
                            ));
                        } else {
                            seen.insert(n, here);
                        }
                        sections.push(Section {
                            number: n,
                            line: hl,
                            start: range.start,
                            ..Default::default()
                        });
                    }
                }
            }
            Event::Text(t) | Event::Code(t) if heading.is_some() => {
                if let Some((h, _)) = heading.as_mut() {
                    h.push_str(&t)
                }
            }
            Event::DisplayMath(m) => {
                if let Some(s) = sections.last_mut() {
                    if s.math.is_none() {
                        s.math = Some((m.to_string(), line));
                    }
                }
            }
            Event::Start(Tag::Link { .. }) => in_link = true,
            Event::End(TagEnd::Link) => in_link = false,
            Event::Start(Tag::Table(_)) => {
                in_table = true;
                table.clear();
                table_line = line;
            }
            Event::End(TagEnd::Table) => {
                in_table = false;
                rep.examples_run +=
                    examples::run_table(&format!("{name}:{table_line}"), &table, &mut rep.problems);
            }
            Event::Start(Tag::TableHead) => {
                in_header = true;
                table.push(Vec::new());
            }
            Event::End(TagEnd::TableHead) => in_header = false,
            Event::Start(Tag::TableRow) => table.push(Vec::new()),
            Event::Start(Tag::TableCell) => cell.clear(),
            Event::End(TagEnd::TableCell) => {
                if let Some(row) = table.last_mut() {
                    row.push(cell.trim().to_string());
                }
            }
            Event::Code(c) => {
                if in_table {
                    cell.push_str(&c);
                } else if in_link {
                    if let Some(s) = sections.last_mut() {
                        s.functions.push((c.to_string(), line));
                    }
                }
            }
            Event::Text(t) if in_table => cell.push_str(&t),
            Event::InlineMath(t) if in_table => cell.push_str(&t),
            _ => {}
        }
        let _ = in_header;
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
    for (k, s) in sections.iter().enumerate() {
        let end = sections.get(k + 1).map_or(src.len(), |n| n.start);
        check_section(name, &src[s.start..end], s, &registry, rep);
    }
}

/// The number in a heading "(12) ..." (12), or "(P3) ..." for an extension (1003).
fn heading_number(text: &str) -> Option<u32> {
    let t = text.trim_start();
    let rest = t.strip_prefix('(')?;
    let close = rest.find(')')?;
    let inner = rest[..close].trim();
    match inner.strip_prefix('P') {
        Some(k) => k
            .parse::<u32>()
            .ok()
            .map(|k| crate::registry::EXTENSION_BASE + k),
        None => inner.parse().ok(),
    }
}

fn check_section(
    name: &str,
    body: &str,
    s: &Section,
    registry: &[crate::registry::Equation],
    rep: &mut BookReport,
) {
    let at = |line: usize| format!("{name}:{line}");
    let Some(entry) = registry.iter().find(|e| e.number == s.number) else {
        rep.problems.push(format!(
            "{}: equation ({}) has no registry entry",
            at(s.line),
            s.number
        ));
        return;
    };
    match &s.math {
        None => rep.problems.push(format!(
            "{}: equation ({}) has no display math block",
            at(s.line),
            s.number
        )),
        Some((m, line)) => {
            if normalize_latex(m) != normalize_latex(entry.latex()) {
                rep.problems.push(format!(
                    "{}: the LaTeX of ({}) differs from the registry's printed form",
                    at(*line),
                    s.number
                ));
            }
        }
    }
    if s.functions.is_empty() {
        rep.problems.push(format!(
            "{}: equation ({}) links to no function",
            at(s.line),
            s.number
        ));
    }
    for (f, line) in &s.functions {
        if !entry.functions.contains(&f.as_str()) {
            rep.problems.push(format!(
                "{}: `{f}` is not a registry function of ({})",
                at(*line),
                s.number
            ));
        }
    }
    check_law_line(&at(s.line), body, entry, rep);
    let kind = body
        .lines()
        .find_map(|l| l.split("Kind:*").nth(1).or_else(|| l.split("Kind:").nth(1)));
    match kind.map(|k| {
        k.trim()
            .trim_start_matches('*')
            .split_whitespace()
            .next()
            .unwrap_or("")
            .trim_end_matches(['.', ',', '·'])
    }) {
        Some(k) if k == entry.kind.name() => {}
        Some(k) => rep.problems.push(format!(
            "{}: ({}) says kind '{k}', the registry says '{}'",
            at(s.line),
            s.number,
            entry.kind.name()
        )),
        None => rep.problems.push(format!(
            "{}: ({}) does not state its kind (*Kind:* ...)",
            at(s.line),
            s.number
        )),
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

/// The line that marks the law of motion in a section: `*Law:* the 2nd `=` ...`.
pub fn law_line(step: u32) -> String {
    format!("*Law:* the {} `=`", ordinal(step))
}

/// A display whose registry entry marks a law step must say so in a `*Law:*` line naming the
/// same `=`; a display without one must not claim a law step.
fn check_law_line(at: &str, body: &str, entry: &crate::registry::Equation, rep: &mut BookReport) {
    let stated = body.lines().find(|l| l.starts_with("*Law:*"));
    match (entry.law, stated) {
        (Some(law), Some(line)) if line.starts_with(&law_line(law.step)) => {}
        (Some(law), Some(line)) => rep.problems.push(format!(
            "{at}: ({}) marks the law as \"{}\", the registry at the {} `=`",
            entry.number,
            line.chars().take(40).collect::<String>(),
            ordinal(law.step)
        )),
        (Some(law), None) => rep.problems.push(format!(
            "{at}: ({}) does not say which `=` is the law of motion (expected a line \"{} ...\")",
            entry.number,
            law_line(law.step)
        )),
        (None, Some(_)) => rep.problems.push(format!(
            "{at}: ({}) has a *Law:* line but the registry marks no law step",
            entry.number
        )),
        (None, None) => {}
    }
}
