//! A note: the display sections of a folder of markdown, and the registry's equations built from
//! them. The note of this crate is embedded at build time (`build.rs`); a user's folder is read
//! with [`Note::from_dir`]. The note in use is chosen once per process ([`use_note`]), before the
//! first equation is asked for, and lives as long as the process: the equations borrow their
//! titles, LaTeX and check names from it.

use super::{parse_file, symbols, top_level_forms, Section, SourceError};
use crate::print::symbols::Entry;
use crate::registry::fns;
use crate::registry::{Check, Equation, Erratum, Law, EXTENSION_BASE};
use std::path::Path;
use std::sync::OnceLock;

mod embedded {
    include!(concat!(env!("OUT_DIR"), "/chapters.rs"));
}

/// The display sections of a folder of markdown, and every problem found in them.
#[derive(Debug, Default)]
pub struct Note {
    /// The sections, in file order then print order.
    pub sections: Vec<Section>,
    /// Every problem, `file:line: reason`; a section with a problem is not in `sections`.
    pub errors: Vec<SourceError>,
    /// The symbol table: `symbols.toml`'s entries, then those the files declare.
    pub symbols: Vec<Entry>,
    /// The folder it was read from; `None` for the note built into the binary.
    pub dir: Option<std::path::PathBuf>,
}

impl Note {
    /// Read markdown files given as (name, text), in the order given.
    pub fn parse<'a>(files: impl IntoIterator<Item = (&'a str, &'a str)>) -> Note {
        let mut note = Note {
            symbols: crate::print::symbols::table().to_vec(),
            ..Note::default()
        };
        for (name, text) in files {
            let mut f = parse_file(name, text);
            link_continuations(&mut f.sections);
            let numbers: Vec<u32> = f.sections.iter().map(|s| s.number).collect();
            let extra = symbols::entries(name, &f.points, &f.symbols, &numbers, &mut f.errors);
            note.symbols.extend(extra);
            note.sections.extend(f.sections);
            note.errors.extend(f.errors);
        }
        note.resolve();
        note
    }

    /// The note of this crate, `equations/*.md` as built into the binary.
    pub fn embedded() -> &'static Note {
        static NOTE: OnceLock<Note> = OnceLock::new();
        NOTE.get_or_init(|| Note::parse(embedded::CHAPTERS.iter().copied()))
    }

    /// Read every `*.md` file of a folder (sorted by name); a folder or file that cannot be read
    /// is an error of its own.
    pub fn from_dir(dir: &Path) -> Result<Note, SourceError> {
        let io = |file: &Path, e: std::io::Error| SourceError {
            file: file.display().to_string(),
            line: 1,
            reason: format!("cannot read: {e}"),
        };
        let mut files: Vec<_> = std::fs::read_dir(dir)
            .map_err(|e| io(dir, e))?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "md"))
            .collect();
        files.sort();
        let texts = files
            .iter()
            .map(|f| {
                Ok((
                    f.display().to_string(),
                    std::fs::read_to_string(f).map_err(|e| io(f, e))?,
                ))
            })
            .collect::<Result<Vec<_>, SourceError>>()?;
        if texts.is_empty() {
            return Err(SourceError {
                file: dir.display().to_string(),
                line: 1,
                reason: "no *.md file in the folder".into(),
            });
        }
        let mut note = Note::parse(texts.iter().map(|(n, t)| (n.as_str(), t.as_str())));
        note.dir = Some(dir.to_path_buf());
        Ok(note)
    }

    /// Check what needs more than one section: numbers used once, and every check's function
    /// known to the registry with states it can take. A section that fails is moved out.
    fn resolve(&mut self) {
        let mut kept: Vec<Section> = Vec::new();
        for s in std::mem::take(&mut self.sections) {
            let err = |line, reason| SourceError {
                file: s.file.clone(),
                line,
                reason,
            };
            let label = crate::registry::label_of(s.number);
            if let Some(first) = kept.iter().find(|k| k.number == s.number) {
                let reason = format!(
                    "{label} appears twice (first at {}:{})",
                    first.file, first.line
                );
                self.errors.push(err(s.line, reason));
                continue;
            }
            let mut bad = Vec::new();
            for c in &s.checks {
                if let Err(reason) = fns::check_of(c.function.as_str(), &c.sample, "") {
                    bad.push(err(c.line, format!("{label}: {reason}")));
                }
            }
            let src = match &s.continues {
                Some(prefix) => format!("{prefix} {}", s.latex),
                None => s.latex.clone(),
            };
            // The floor phase's prints are checked by their Rust functions only (see
            // `verify::judge_with_print`); every other print must be readable.
            let print_checked = s.number < EXTENSION_BASE || s.checks.is_empty();
            let parsed = crate::print::parser::parse_display(&src);
            if let (true, Err(reason)) = (print_checked, parsed) {
                bad.push(err(
                    s.latex_line,
                    format!("{label}: the display cannot be read as LaTeX of the note: {reason}"),
                ));
            }
            for p in &s.premises {
                let Some(latex) = &p.latex else { continue };
                if let Err(reason) = crate::print::parser::parse_display(latex) {
                    bad.push(err(
                        p.line,
                        format!("{label}: the premise ${latex}$ cannot be read: {reason}"),
                    ));
                }
            }
            if let Some((name, line)) = &s.states {
                if let Err(reason) = fns::print_states(name) {
                    bad.push(err(*line, format!("{label}: {reason}")));
                }
            }
            if let Some(e) = &s.erratum {
                if misprinted_forms(&e.printed, &e.corrected).is_empty() {
                    bad.push(err(
                        s.line,
                        format!(
                            "{label}: the misprint has no form that the correction does not have"
                        ),
                    ));
                }
            }
            if bad.is_empty() {
                kept.push(s);
            } else {
                self.errors.extend(bad);
            }
        }
        self.sections = kept;
    }

    /// The sections of the note's own displays, (1), (2), ... (not the extensions (Pk)).
    pub fn equations(&'static self) -> Vec<Equation> {
        self.build(|n| n < EXTENSION_BASE)
    }

    /// The extensions beyond the note, (P1), (P2), ...
    pub fn extensions(&'static self) -> Vec<Equation> {
        self.build(|n| n > EXTENSION_BASE)
    }

    fn build(&'static self, keep: impl Fn(u32) -> bool) -> Vec<Equation> {
        let mut out: Vec<Equation> = self
            .sections
            .iter()
            .filter(|s| keep(s.number))
            .map(equation)
            .collect();
        out.sort_by_key(|e| e.number);
        out
    }

    /// The section of display `number`, if the note has it.
    pub fn section(&self, number: u32) -> Option<&Section> {
        self.sections.iter().find(|s| s.number == number)
    }
}

/// A display that begins with `=` continues the chain of the display before it in its file,
/// from that display's last form ((57) continues (56) from τ_P).
fn link_continuations(sections: &mut [Section]) {
    for k in 1..sections.len() {
        if sections[k].latex.trim_start().starts_with('=') {
            let prev = top_level_forms(&sections[k - 1].latex)
                .last()
                .map(|f| f.trim_end_matches([',', '.']).trim().to_string());
            sections[k].continues = prev;
        }
    }
}

/// The forms of an erratum's printed statement that its correction does not have (compared as
/// the print parser reads them, or as written where it cannot).
pub fn misprinted_forms<'a>(printed: &'a str, corrected: &str) -> Vec<&'a str> {
    let key = |f: &str| crate::print::parser::canonical(f).unwrap_or_else(|_| f.to_string());
    let good: Vec<String> = top_level_forms(corrected).into_iter().map(key).collect();
    top_level_forms(printed)
        .into_iter()
        .filter(|f| !good.contains(&key(f)))
        .collect()
}

/// The registry's equation of a section.
fn equation(s: &'static Section) -> Equation {
    let checks: Vec<Check> = s
        .checks
        .iter()
        .filter_map(|c| fns::check_of(&c.function, &c.sample, &c.name).ok())
        .collect();
    Equation {
        number: s.number,
        section: &s.section,
        title: &s.title,
        kind: s.kind,
        functions: &s.functions,
        checks,
        erratum: s.erratum.as_ref().map(|e| Erratum {
            printed: &e.printed,
            corrected: &e.corrected,
            why: &e.why,
        }),
        law: s.law.as_ref().map(|l| Law {
            step: l.step,
            statement: &l.statement,
        }),
        latex: &s.latex,
        continues: s.continues.as_deref(),
        states: s
            .states
            .as_ref()
            .and_then(|(n, _)| fns::print_states(n).ok()),
        premises: &s.premises,
        file: &s.file,
        line: s.line,
    }
}

static CURRENT: OnceLock<&'static Note> = OnceLock::new();

/// The note in use: the one given to [`use_note`], else the embedded one.
pub fn current() -> &'static Note {
    CURRENT.get_or_init(Note::embedded)
}

/// Use `note` for the rest of the process (`ladder verify --equations DIR`). An error when a
/// note is already in use.
pub fn use_note(note: Note) -> Result<&'static Note, String> {
    let leaked: &'static Note = Box::leak(Box::new(note));
    CURRENT
        .set(leaked)
        .map_err(|_| "the note is chosen once, before any display is read".to_string())?;
    Ok(leaked)
}
