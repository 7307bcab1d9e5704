//! Where each display's section starts in the book: the line of its heading `### (N) …` in
//! `equations/*.md`. `ladder verify` prints it beside each row and `ladder show` links it; both
//! read it here, from the files as they are, so a moved section moves its reference.

use std::collections::BTreeMap;
use std::path::Path;

/// A display's place in the book.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Page {
    /// The file, as the repository names it: `equations/05-point-d.md`.
    pub file: String,
    /// The line of the heading, from 1.
    pub line: usize,
    /// The heading's text without the `#`s: `(25) Torque analysis about D`.
    pub heading: String,
}

/// Every display heading of the `*.md` files in `dir`, keyed by its label (`(25)`, `(P3)`); the
/// first heading wins when a label occurs twice (the book check reports the duplicate). A missing
/// directory or unreadable file gives no entries, never an error.
pub fn headings(dir: &Path) -> BTreeMap<String, Page> {
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .map(|rd| {
            rd.flatten()
                .map(|f| f.path())
                .filter(|p| p.extension().is_some_and(|x| x == "md"))
                .collect()
        })
        .unwrap_or_default();
    files.sort();
    let mut out = BTreeMap::new();
    for f in files {
        let Ok(text) = std::fs::read_to_string(&f) else {
            continue;
        };
        let name = f
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        for (i, l) in text.lines().enumerate() {
            let t = l.trim_start();
            if !t.starts_with('#') {
                continue;
            }
            let heading = t.trim_start_matches('#').trim();
            let Some(label) = heading
                .strip_prefix('(')
                .and_then(|r| r.split_once(')'))
                .map(|(inner, _)| format!("({inner})"))
            else {
                continue;
            };
            out.entry(label).or_insert_with(|| Page {
                file: format!("equations/{name}"),
                line: i + 1,
                heading: heading.to_string(),
            });
        }
    }
    out
}
