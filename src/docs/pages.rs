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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn headings_are_found_by_label_with_file_and_line() {
        let dir = std::env::temp_dir().join(format!("ladder-pages-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(
            dir.join("b.md"),
            "# B\n\ntext (7)\n### (7) Seven\n### (P2) Two\n",
        )
        .unwrap();
        std::fs::write(dir.join("a.md"), "x\n## (7) First seven\n").unwrap();
        std::fs::write(dir.join("c.txt"), "### (9) not markdown\n").unwrap();
        let h = headings(&dir);
        std::fs::remove_dir_all(&dir).ok();
        assert_eq!(h["(7)"].file, "equations/a.md");
        assert_eq!(h["(7)"].line, 2);
        assert_eq!(h["(P2)"].line, 5);
        assert_eq!(h["(P2)"].heading, "(P2) Two");
        assert!(!h.contains_key("(9)"));
        assert!(headings(Path::new("/nonexistent/ladder")).is_empty());
    }

    #[test]
    fn the_books_torque_analysis_about_d_is_in_its_section_file() {
        let h = headings(&crate::docs::default_dir());
        assert_eq!(h["(25)"].file, "equations/05-point-d.md");
        assert!(h["(25)"]
            .heading
            .starts_with("(25) Torque analysis about D"));
        assert_eq!(h["(P1)"].file, "equations/phase2.md");
        assert_eq!(
            crate::registry::equations()
                .iter()
                .filter(|e| h.contains_key(&e.label()))
                .count(),
            crate::registry::equations().len()
        );
    }
}
