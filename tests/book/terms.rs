//! Tests of `sliding_ladder::book::terms` (src/book/terms.rs).

use pulldown_cmark::{html, Options, Parser};
use sliding_ladder::book::terms::link_terms;

fn render(md: &str) -> String {
    let events = link_terms(Parser::new_ext(md, Options::empty()).collect());
    let mut s = String::new();
    html::push_html(&mut s, events.into_iter());
    s
}

#[test]
fn the_first_plain_occurrence_links_and_headings_links_code_do_not() {
    let h =
        render("# on-shell\n\nIt is on-shell; on-shell again. See [on-shell](x.html), `chains`.\n");
    assert!(h.contains("<h1>on-shell</h1>"), "{h}");
    assert!(
        h.contains("It is <a href=\"glossary.html#on-shell\">on-shell</a>; on-shell again."),
        "{h}"
    );
    assert!(h.contains("<a href=\"x.html\">on-shell</a>"), "{h}");
    assert!(h.contains("<code>chains</code>"), "{h}");
}
