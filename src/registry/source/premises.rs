//! The items of a display's `*Premises:*` list: what the display assumes, each written once
//! beside it. An item reads `- SOURCE: $condition$ words`, SOURCE one of
//!
//! * `bar`: an evaluation bar of the print, `…\Big|_{condition}` (held to the print: every bar
//!   is listed, every listed bar is printed);
//! * `implies`: the left side of a `\Rightarrow` of the print (held to the print the same way);
//! * `stated`: a condition the display states in words ("for P fixed", a heading's "when
//!   x_P = 0");
//! * `prose`: what the section's prose assumes.
//!
//! A `stated` or `prose` premise with a condition is imposed on every state the print is
//! checked at ([`crate::print::condition`]); one in words only (a rigid body, rolling) names the
//! states of `*States:*` that realise it. Bars and implications are imposed where they are
//! printed, by the evaluator.

use super::PremiseSpec;

/// Where a premise comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum PremiseSource {
    /// An evaluation bar of the print.
    Bar,
    /// The left side of an implication of the print.
    Implies,
    /// A condition the display or its heading states in words.
    Stated,
    /// What the section's prose assumes.
    Prose,
}

impl PremiseSource {
    /// Its name in the markdown.
    pub fn name(self) -> &'static str {
        match self {
            PremiseSource::Bar => "bar",
            PremiseSource::Implies => "implies",
            PremiseSource::Stated => "stated",
            PremiseSource::Prose => "prose",
        }
    }
    /// Imposed on the whole display (not only where printed).
    pub fn whole_display(self) -> bool {
        matches!(self, PremiseSource::Stated | PremiseSource::Prose)
    }
}

/// Read one `- SOURCE: $condition$ words` item.
pub fn read_premise(raw: &str, line: usize) -> Result<PremiseSpec, String> {
    let shape = "a premise reads - bar|implies|stated|prose: $condition$ words";
    let item = raw.trim().trim_start_matches(['-', '*']).trim();
    let (name, rest) = item.split_once(':').ok_or(shape)?;
    let source = match name.trim() {
        "bar" => PremiseSource::Bar,
        "implies" => PremiseSource::Implies,
        "stated" => PremiseSource::Stated,
        "prose" => PremiseSource::Prose,
        other => return Err(format!("*Premises:* '{other}' is not a source: {shape}")),
    };
    let rest = rest.trim();
    let (latex, words) = match rest.strip_prefix('$') {
        Some(r) => {
            let (l, w) = r.split_once('$').ok_or(shape)?;
            (Some(super::normalize_latex(l)), w.trim())
        }
        None => (None, rest),
    };
    if latex.is_none() && source != PremiseSource::Prose {
        return Err(format!(
            "*Premises:* a {} premise needs its $condition$",
            source.name()
        ));
    }
    Ok(PremiseSpec {
        source,
        latex,
        words: words
            .trim_matches(|c: char| c == '(' || c == ')' || c == '.')
            .trim()
            .to_string(),
        line,
    })
}
