//! One markdown file read into display sections: pulldown-cmark finds the blocks (headings,
//! display math, paragraphs, list items) with their source ranges; [`super::fields`] reads the
//! `*Field:*` paragraphs.

use super::fields::{self, Fields, FileDecls, ListNext};
use super::{normalize_latex, PointSpec, Section, SourceError, SymbolSpec};
use crate::registry::EXTENSION_BASE;
use pulldown_cmark::{Event, Options, Parser, Tag, TagEnd};

/// The line numbers of one source: the offsets of its line breaks, so a line is a binary search
/// (counting the breaks before every event of a file was quadratic: 80 % of the start-up of
/// every `ladder` command, which reads the note).
pub struct Lines(Vec<usize>);

impl Lines {
    /// The index of `src`'s line breaks.
    pub fn new(src: &str) -> Lines {
        Lines(src.match_indices('\n').map(|(i, _)| i).collect())
    }
    /// The 1-based line of a byte offset.
    pub fn line_of(&self, offset: usize) -> usize {
        self.0.partition_point(|&b| b < offset) + 1
    }
}

/// The number of a display label `(12)` or `(P3)` at the start of a heading's text, and the
/// rest (the title); `None` when the heading is not a display's.
pub fn heading_label(text: &str) -> Option<(Result<u32, String>, &str)> {
    let rest = text.trim_start().strip_prefix('(')?;
    let close = rest.find(')')?;
    let inner = rest[..close].trim();
    let (ext, digits) = match inner.strip_prefix('P') {
        Some(k) => (true, k),
        None => (false, inner),
    };
    if digits.is_empty() || !digits.chars().all(|c| c.is_ascii_digit()) {
        return None;
    }
    let title = rest[close + 1..].trim();
    let n = match digits.parse::<u32>() {
        Ok(0) => Err(format!("({inner}): displays are numbered from 1")),
        Ok(k) if ext && k < EXTENSION_BASE => Ok(EXTENSION_BASE + k),
        Ok(k) if !ext && k < EXTENSION_BASE => Ok(k),
        _ => Err(format!(
            "({inner}): numbers run below {EXTENSION_BASE} (an extension is (P1), (P2), ...)"
        )),
    };
    Some((n, title))
}

/// The section label a chapter heading gives: `Sec. 2.5 — …` → `2.5`, `Appendix A — …` → `A`,
/// `B.7 — …` → `B.7`; `None` for any other heading.
pub fn section_label(text: &str) -> Option<&str> {
    let t = text.trim();
    let t = t
        .strip_prefix("Sec. ")
        .or_else(|| t.strip_prefix("Appendix "))
        .unwrap_or(t);
    let (label, rest) = t.split_once(' ')?;
    let is_label = !label.is_empty()
        && label.starts_with(|c: char| c.is_ascii_uppercase() || c.is_ascii_digit())
        && label
            .split('.')
            .all(|p| !p.is_empty() && p.chars().all(|c| c.is_ascii_alphanumeric()));
    (is_label && rest.trim_start().starts_with('—')).then_some(label)
}

/// The text of a heading's source: `### (25) Title ###` → `(25) Title`.
pub fn heading_text(raw: &str) -> &str {
    let first = raw.lines().next().unwrap_or("");
    first
        .trim()
        .trim_start_matches('#')
        .trim_end_matches('#')
        .trim()
}

/// A section being read: its heading and what has been found under it.
struct Open {
    number: Result<u32, String>,
    line: usize,
    title: String,
    section: String,
    latex: Option<(String, usize)>,
    fields: Fields,
}

/// What one file holds: its display sections, the points and symbols it declares, and every
/// problem found.
#[derive(Default)]
pub struct ParsedFile {
    /// The sections, in print order (those with a problem left out).
    pub sections: Vec<Section>,
    /// The points of its `*Points:*` lines.
    pub points: Vec<PointSpec>,
    /// The symbols of its `*Symbols:*` lists.
    pub symbols: Vec<SymbolSpec>,
    /// Every problem, `file:line: reason`.
    pub errors: Vec<SourceError>,
}

/// Read every display section of one markdown file, and what the file declares. Sections with
/// a problem are left out and the problem reported; the rest are returned in file order.
pub fn parse_file(file: &str, src: &str) -> ParsedFile {
    let stem = std::path::Path::new(file)
        .file_stem()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let mut out = ParsedFile::default();
    let mut decls = FileDecls::default();
    let mut chapter = stem;
    let mut open: Option<Open> = None;
    // Fields outside any display section go nowhere (only the file's own fields count there).
    let mut outside = Fields::default();
    let mut list = ListNext::None;
    let mut depth = 0usize;
    let opts = Options::ENABLE_MATH | Options::ENABLE_TABLES;
    let lines = Lines::new(src);
    for (ev, range) in Parser::new_ext(src, opts).into_offset_iter() {
        let line = lines.line_of(range.start);
        let raw = src.get(range.clone()).unwrap_or("");
        match &ev {
            Event::Start(Tag::Heading { level, .. }) if depth == 0 => {
                list = ListNext::None;
                let text = heading_text(raw);
                if let Some((number, title)) = heading_label(text) {
                    close(open.take(), file, &mut out);
                    open = Some(Open {
                        number,
                        line,
                        title: title.to_string(),
                        section: chapter.clone(),
                        latex: None,
                        fields: Fields::default(),
                    });
                } else if (*level as usize) <= 2 {
                    close(open.take(), file, &mut out);
                    if let Some(label) = section_label(text) {
                        chapter = label.to_string();
                    }
                }
            }
            Event::DisplayMath(m) => {
                if let Some(o) = open.as_mut().filter(|o| o.latex.is_none()) {
                    o.latex = Some((normalize_latex(m), line));
                }
            }
            Event::Start(Tag::Paragraph) if depth == 0 => {
                let fields = open.as_mut().map_or(&mut outside, |o| &mut o.fields);
                list = fields::read_paragraph(raw, line, fields, &mut decls);
            }
            // The items of the list right after `*Rust:*` or `*Symbols:*`.
            Event::Start(Tag::List(_)) if depth == 0 => {}
            Event::Start(Tag::Item) if depth == 1 => match (list, open.as_mut()) {
                (ListNext::Rust, Some(o)) => fields::read_check(raw, line, &mut o.fields),
                (ListNext::Symbols, _) => fields::read_symbol(raw, line, &mut decls),
                (ListNext::Premises, Some(o)) => fields::read_premise(raw, line, &mut o.fields),
                _ => {}
            },
            Event::Start(_) if depth == 0 => list = ListNext::None,
            _ => {}
        }
        match ev {
            Event::Start(_) => depth += 1,
            Event::End(t) => {
                depth = depth.saturating_sub(1);
                if depth == 0 && matches!(t, TagEnd::List(_)) {
                    list = ListNext::None;
                }
            }
            _ => {}
        }
    }
    close(open.take(), file, &mut out);
    out.points = decls.points;
    out.symbols = decls.symbols;
    out.errors
        .extend(decls.errors.into_iter().map(|(line, reason)| SourceError {
            file: file.to_string(),
            line,
            reason,
        }));
    out
}

/// The problems of a section's fields, in line order, with the one known only once the whole
/// section is read: a *Misprint:* with no *Corrected:* (which may come a paragraph later).
fn field_errors(fields: &Fields) -> Vec<(usize, String)> {
    let mut out = fields.errors.clone();
    if fields
        .erratum
        .as_ref()
        .is_some_and(|e| e.corrected.is_empty())
    {
        let reason = "a *Misprint:* needs its *Corrected:* form".to_string();
        out.push((fields.erratum_line, reason));
    }
    out.sort_by_key(|(l, _)| *l);
    out
}

/// Finish a section: check that it has what a display needs.
fn close(o: Option<Open>, file: &str, parsed: &mut ParsedFile) {
    let Some(o) = o else { return };
    let (out, errors) = (&mut parsed.sections, &mut parsed.errors);
    let err = |line: usize, reason: String| SourceError {
        file: file.to_string(),
        line,
        reason,
    };
    let number = match o.number {
        Ok(n) => n,
        Err(reason) => return errors.push(err(o.line, reason)),
    };
    let label = crate::registry::label_of(number);
    let before = errors.len();
    errors.extend(
        field_errors(&o.fields)
            .iter()
            .map(|(l, r)| err(*l, format!("{label}: {r}"))),
    );
    let Some((latex, latex_line)) = o.latex else {
        errors.push(err(
            o.line,
            format!("{label} has no display (the LaTeX between two `$$` lines)"),
        ));
        return;
    };
    if latex.is_empty() {
        errors.push(err(latex_line, format!("{label}: the display is empty")));
    }
    let Some(kind) = o.fields.kind else {
        if o.fields.kind_written {
            return; // the unknown kind is reported already
        }
        errors.push(err(
            o.line,
            format!("{label} does not state its kind (a line `*Kind:* on-shell`, ...)"),
        ));
        return;
    };
    if o.title.is_empty() {
        errors.push(err(
            o.line,
            format!("{label} has no title after its number"),
        ));
    }
    if let Some(law) = &o.fields.law {
        let signs = crate::registry::law::equals_signs(&latex);
        if law.0.step > signs {
            errors.push(err(
                law.1,
                format!(
                    "{label}: *Law:* names `=` no. {}, the display has {signs}",
                    law.0.step
                ),
            ));
        }
    }
    if errors.len() > before {
        return;
    }
    out.push(Section {
        number,
        file: file.to_string(),
        line: o.line,
        title: o.title,
        section: o.section,
        latex,
        latex_line,
        kind,
        functions: o.fields.functions,
        checks: o.fields.checks,
        law: o.fields.law.map(|l| l.0),
        erratum: o.fields.erratum,
        continues: None,
        states: o.fields.states,
        premises: o.fields.premises,
    });
}
