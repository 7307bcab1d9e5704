//! The reader's pages written in markdown under `docs/book/`: the problem that opens the index
//! (`problem.md`), the glossary of the words of the checks (`glossary.md` → `glossary.html`) and
//! the note's references (`references.md` → `references.html`). Their links may name the book's
//! own pages (`errata.html`) or, like every chapter, files of the repository.

use super::markdown::title_of;
use std::path::Path;

/// The folder of the reader's pages, from the repository root.
pub const FOLDER: &str = "docs/book";

/// The file that opens the index (it has no page of its own).
pub const OPENING: &str = "problem.md";

/// One reader's page.
pub struct ReaderDoc {
    /// Its path in the repository.
    pub file: String,
    /// Its page (`glossary.html`), None for the opening of the index.
    pub page: Option<String>,
    /// Its first heading.
    pub title: String,
    /// Its markdown.
    pub source: String,
}

/// Every markdown file of [`FOLDER`], sorted by name; one that cannot be read is a problem.
pub fn documents(root: &Path, problems: &mut Vec<String>) -> Vec<ReaderDoc> {
    let names = super::about::markdown_names(&root.join(FOLDER));
    if !names.iter().any(|n| n == OPENING) {
        problems.push(format!("{FOLDER}/{OPENING}: missing (it opens the index)"));
    }
    names
        .into_iter()
        .filter_map(|name| {
            let file = format!("{FOLDER}/{name}");
            match std::fs::read_to_string(root.join(&file)) {
                Ok(source) => Some(ReaderDoc {
                    page: (name != OPENING)
                        .then(|| format!("{}.html", name.trim_end_matches(".md").to_lowercase())),
                    title: title_of(&source),
                    file,
                    source,
                }),
                Err(e) => {
                    problems.push(format!("{file}: cannot read: {e}"));
                    None
                }
            }
        })
        .collect()
}
