//! Words for readers: the status of a display as a student reads it ("checked", "misprint in
//! the note", "definition"), and links from the words of verification to the glossary
//! (`docs/book/glossary.md`, the page `glossary.html`). The technical status (`verified`,
//! `erratum`, ...) stays in `data-status` and in the folded panel of checks.

use super::pages::esc;
use crate::verify::Status;

/// The book's page of the glossary.
pub const GLOSSARY: &str = "glossary.html";

/// The status as a reader sees it on the badge.
pub fn status_word(s: Status) -> &'static str {
    match s {
        Status::Verified => "checked",
        Status::Erratum => "misprint in the note",
        Status::Definition => "definition",
        Status::Failed => "failed",
    }
}

/// The glossary entry that explains a status.
pub fn status_term(s: Status) -> &'static str {
    match s {
        Status::Verified => "checked",
        Status::Erratum => "misprint",
        Status::Definition => "definition",
        Status::Failed => "checked",
    }
}

/// The glossary entry of a kind of display (`on-shell`, `kinematic`, ...), if it has one.
pub fn kind_term(kind: &str) -> Option<&'static str> {
    match kind {
        "on-shell" => Some("on-shell"),
        "kinematic" => Some("kinematic"),
        "newton" => Some("newton"),
        "definition" => Some("definition"),
        _ => None,
    }
}

/// `text` (HTML already) as a link to the glossary entry `id`, from a page at the book's root.
pub fn term(id: &str, text: &str) -> String {
    format!(
        "<a class=\"term\" href=\"{GLOSSARY}#{}\">{text}</a>",
        esc(id)
    )
}

/// The badge of a status: the reader's word, linked to its glossary entry.
pub fn badge(s: Status) -> String {
    // The technical word, as `data-status` and `ladder verify` have it (here, not from the
    // panel, which uses this module).
    let tech = match s {
        Status::Verified => "verified",
        Status::Erratum => "erratum",
        Status::Definition => "definition",
        Status::Failed => "failed",
    };
    term(
        status_term(s),
        &format!(
            "<span class=\"badge {tech}\" title=\"{tech}\">{}</span>",
            status_word(s)
        ),
    )
}
