//! Tests of `sliding_ladder::book::refs` (src/book/refs.rs).

use pulldown_cmark::{html, Options, Parser};
use sliding_ladder::book::refs::link_references;

fn render(md: &str) -> String {
    let target = |n: u32| (n <= 90 || n > 1000).then(|| format!("p.html#eq-{n}"));
    let events = link_references(Parser::new_ext(md, Options::empty()).collect(), &target);
    let mut s = String::new();
    html::push_html(&mut s, events.into_iter());
    s
}

#[test]
fn a_number_in_parentheses_links_and_nothing_else_does() {
    let h = render("By (40) and (P3), not (2/3) nor (1 − m) nor (91).\n");
    assert!(h.contains("<a href=\"p.html#eq-40\">(40)</a>"), "{h}");
    assert!(h.contains("<a href=\"p.html#eq-1003\">(P3)</a>"), "{h}");
    assert!(h.contains("not (2/3) nor (1 − m) nor (91)."), "{h}");
}

#[test]
fn headings_links_and_code_keep_their_text() {
    let h = render("# (11) Torque\n\nSee [eq. (12)](x.html) and `(13)`.\n\n    (14)\n");
    assert!(h.contains("<h1>(11) Torque</h1>"), "{h}");
    assert!(h.contains("<a href=\"x.html\">eq. (12)</a>"), "{h}");
    assert!(h.contains("<code>(13)</code>"), "{h}");
    assert!(h.contains("<pre><code>(14)"), "{h}");
}
