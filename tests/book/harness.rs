//! `book::harness`: a display's `*Rust:*` list (data for the checks) is folded on every page of
//! the book, and the fold keeps the list whole.

use crate::built::book;
use sliding_ladder::book::harness::{fold_rust_lists, SUMMARY};

#[test]
fn fold_rust_lists_folds_the_list_and_only_a_list() {
    let html = "<p>a</p>\n<p><em>Rust:</em></p>\n<ul>\n<li>eq43</li>\n</ul>\n<p>b</p>";
    let f = fold_rust_lists(html);
    assert_eq!(
        f,
        format!("<p>a</p>\n<details class=\"harness checks\">{SUMMARY}\n<ul>\n<li>eq43</li>\n</ul></details>\n<p>b</p>")
    );
    // The Kind line right before the list goes into the fold with it; a paragraph before that
    // stays out.
    let with_kind =
        "<p>a</p>\n<p><em>Kind:</em> kinematic</p>\n<p><em>Rust:</em></p>\n<ul>\n<li>x</li>\n</ul>";
    assert_eq!(
        fold_rust_lists(with_kind),
        format!("<p>a</p>\n<details class=\"harness checks\">{SUMMARY}\n<p><em>Kind:</em> kinematic</p>\n<ul>\n<li>x</li>\n</ul></details>")
    );
    // Without a list after it the paragraph stays, and nothing else changes.
    let lone = "<p><em>Rust:</em></p>\n<p>c</p>";
    assert_eq!(fold_rust_lists(lone), lone);
    // A Kind line of a display without a Rust list is folded on its own.
    assert_eq!(
        fold_rust_lists("<h3>x</h3>\n<p><em>Kind:</em> k</p>\n<p>d</p>"),
        format!("<h3>x</h3>\n<details class=\"harness\">{SUMMARY}\n<p><em>Kind:</em> k</p></details>\n<p>d</p>")
    );
}

/// The `*Rust:*` fields of the chapters, as written in `equations/*.md`.
fn rust_fields_in_markdown() -> usize {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("equations");
    std::fs::read_dir(dir)
        .expect("equations/")
        .flatten()
        .filter(|e| e.path().extension().is_some_and(|x| x == "md"))
        .map(|e| {
            let text = std::fs::read_to_string(e.path()).expect("a chapter");
            text.lines().filter(|l| l.trim() == "*Rust:*").count()
        })
        .sum()
}

/// No page of the written book shows a `*Rust:*` list or a `*Kind:*` line unfolded, and every
/// list the chapters write is there, folded.
#[test]
fn every_rust_list_of_the_book_is_folded() {
    let mut folded = 0;
    for entry in std::fs::read_dir(book()).expect("the book").flatten() {
        let path = entry.path();
        if path.extension().is_none_or(|x| x != "html") {
            continue;
        }
        let page = std::fs::read_to_string(&path).expect("a page");
        assert!(
            !page.contains("<p><em>Rust:</em></p>"),
            "{}: a Rust list shown unfolded",
            path.display()
        );
        assert_eq!(
            page.matches("<p><em>Kind:</em>").count(),
            page.matches(&format!("{SUMMARY}\n<p><em>Kind:</em>"))
                .count(),
            "{}: a Kind line shown unfolded",
            path.display()
        );
        folded += page.matches("<details class=\"harness checks\">").count();
    }
    assert_eq!(folded, rust_fields_in_markdown());
}
