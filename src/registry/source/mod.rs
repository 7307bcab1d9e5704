//! The note's markdown as the one home of each display (issue 36): `equations/*.md` holds, for
//! every display, what a person writes about it, and the registry is derived from it.
//!
//! # A display's section
//! ````markdown
//! ### (25) Torque analysis about D              <- the number (or (P3)) and the title
//!
//! $$
//! \frac{dL_D}{dt} = ...                         <- the display as printed (the first $$ block)
//! $$
//!
//! Prose, as much as wanted.
//!
//! *Kind:* on-shell · *Code:* [`ladder::torque::torque_about_d`](../src/ladder/torque.rs) · *Checked:* words
//!
//! *Rust:*
//! - `eq25` (on-shell): AD of (24) = printed forms = particle torques
//!
//! *Misprint:* $...$ · *Corrected:* $...$ · *Why:* words        <- an erratum only
//!
//! *Law:* the 2nd `=` is the law of motion: dL'_D/dt = τ_D + .... Every other `=` ...
//! ````
//! * The section of the note is the label of the nearest heading of level 1 or 2 above that has
//!   one (`# Sec. 2.5 — …` gives `2.5`, `## B.7 — …` gives `B.7`, `# Appendix A — …` gives `A`),
//!   else the file's stem.
//! * `*Kind:*` is one of the kinds of [`super::Kind`]; `*Code:*` links the physics functions that
//!   encode the display (documentation: the book shows their source).
//! * `*Rust:*` lists the checks: each item names a generic chain function of the registry by the
//!   name the compiler checks ([`super::fns`]), the states it is evaluated at, and the check's name.
//! * `*Misprint:*` is the printed form (or statement) that fails, `*Corrected:*` its correction;
//!   the misprinted forms are those of the printed statement that the correction does not have.
//! * `*Law:*` names the `=` that is the law of motion and says which law, in words.
//! * `*Premises:*` (optional) lists what the display assumes, one item per premise:
//!   `- bar|implies|stated|prose: $condition$ words` ([`premises`]).
//! * `*States:*` (optional) names the states the print is evaluated at when no `*Rust:*` check
//!   gives them: one of the names of [`super::fns::LADDER_SAMPLES`] or
//!   [`super::fns::PARTICLE_SAMPLES`]; without it, the kind decides (on-shell: the motion;
//!   general, notation: any particles; else: any motion of the ladder).
//!
//! A section needs no Rust: with no `*Rust:*` list its print alone is checked (every `=` on the
//! independent models, the proof, the units, and for an on-shell display where it breaks off the
//! motion). Anywhere in a file, two more fields declare what its displays may use:
//! * `*Points:* Q = ladder:1/4; R = lab:1/2,3/2` names points of the ladder (the fraction of the
//!   way from C to D) or of the lab (x, y in units of l), usable as `:Q` in quantities;
//! * `*Symbols:*` followed by a list of `` $L_Q$ = `relative_angular_momentum:Q.z` [M L^2 T^-1]: meaning ``
//!   adds symbols to the table of `symbols.toml` for the displays of that file.
//!
//! Every problem is a [`SourceError`], `file:line: reason`; nothing here panics on any input
//! (a fuzz test edits the note's own sections at random).

pub mod fields;
pub mod note;
pub mod parse;
pub mod premises;
pub mod symbols;

pub use note::{current, misprinted_forms, use_note, Note};
pub use parse::{parse_file, Lines, ParsedFile};
pub use premises::PremiseSource;
pub use symbols::point_id;

use super::Kind;

/// A problem in the markdown, at a line of a file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SourceError {
    /// The file, as given (`equations/05-point-d.md`).
    pub file: String,
    /// The line, from 1.
    pub line: usize,
    /// What is wrong, in a sentence.
    pub reason: String,
}

impl std::fmt::Display for SourceError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}:{}: {}", self.file, self.line, self.reason)
    }
}

/// One check as a section names it: `` - `eq25` (on-shell): words ``.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CheckSpec {
    /// The chain function's name in [`super::fns`].
    pub function: String,
    /// The sort of state, `kinematic`, `on-shell`, `general`, `p-at-cm`, ... ([`super::fns`]).
    pub sample: String,
    /// What the check compares, in words.
    pub name: String,
    /// Its line.
    pub line: usize,
}

/// The `*Law:*` line: which `=` is the law of motion, and the law in words.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LawSpec {
    /// The `=`, counted from 1 left to right.
    pub step: u32,
    /// The law, in words (may be empty).
    pub statement: String,
}

/// The `*Misprint:*` paragraph of an erratum.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ErratumSpec {
    /// The printed form or statement, LaTeX.
    pub printed: String,
    /// The corrected one, LaTeX.
    pub corrected: String,
    /// Why, in words.
    pub why: String,
}

/// A point named in a file: `Q = ladder:1/4`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PointSpec {
    /// Its name, as quantities use it after `:`.
    pub name: String,
    /// What it is: `ladder:1/4` or `lab:1/2,3/2`.
    pub point: String,
    /// Its line.
    pub line: usize,
}

/// A symbol added by a file: `` $L_Q$ = `relative_angular_momentum:Q.z` [M L^2 T^-1]: meaning ``.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SymbolSpec {
    /// The symbol as printed.
    pub latex: String,
    /// The model quantity it denotes (points by name or by id).
    pub quantity: String,
    /// Its dimension.
    pub dimension: String,
    /// Its meaning.
    pub meaning: String,
    /// Its line.
    pub line: usize,
}

/// One display's section, as written.
#[derive(Clone, Debug, PartialEq)]
pub struct Section {
    /// Its number: N for (N), [`super::EXTENSION_BASE`] + k for (Pk).
    pub number: u32,
    /// The file, as given.
    pub file: String,
    /// The heading's line.
    pub line: usize,
    /// The title, the heading after its label.
    pub title: String,
    /// The section of the note ("2.5", "A.1", "B.7").
    pub section: String,
    /// The display's LaTeX, whitespace collapsed.
    pub latex: String,
    /// The line of its `$$`.
    pub latex_line: usize,
    /// Its kind.
    pub kind: Kind,
    /// The physics functions of `*Code:*`.
    pub functions: Vec<String>,
    /// The checks of `*Rust:*`.
    pub checks: Vec<CheckSpec>,
    /// The `*Law:*` line.
    pub law: Option<LawSpec>,
    /// The erratum, if recorded.
    pub erratum: Option<ErratumSpec>,
    /// For a display that begins with `=` (it continues the one before, as (57) continues
    /// (56)): the last form of the display before it, LaTeX.
    pub continues: Option<String>,
    /// The states of `*States:*`, by name, and its line.
    pub states: Option<(String, usize)>,
    /// The premises of `*Premises:*`.
    pub premises: Vec<PremiseSpec>,
}

/// One premise of a display ([`premises`]).
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct PremiseSpec {
    /// Where it comes from.
    pub source: PremiseSource,
    /// The condition, LaTeX (none for a premise in words only).
    pub latex: Option<String>,
    /// What it says, in words.
    pub words: String,
    /// Its line.
    pub line: usize,
}

/// Collapse whitespace, so that line breaks in the markdown do not matter.
pub fn normalize_latex(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The forms of a display or statement joined by `=` outside braces, as LaTeX (an `=` in a
/// subscript such as `\Big|_{\mathbf{x}_P=0}` joins nothing).
pub fn top_level_forms(latex: &str) -> Vec<&str> {
    let mut depth = 0i32;
    let mut out = Vec::new();
    let mut start = 0;
    for (i, c) in latex.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            '=' if depth == 0 => {
                out.push(latex[start..i].trim());
                start = i + 1;
            }
            _ => {}
        }
    }
    out.push(latex[start..].trim());
    out
}
