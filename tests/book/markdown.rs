//! Tests of `sliding_ladder::book::markdown` (src/book/markdown.rs).

use sliding_ladder::book::markdown::{is_comment, render, Hooks};

fn plain(src: &str) -> String {
    let hooks = Hooks {
        display: &|_, _| None,
        link: &|d, _| Some(d.to_string()),
        equation: &|_| None,
    };
    let (html, problems) = render("t.md", src, &hooks);
    assert!(problems.is_empty(), "{problems:?}");
    html
}

#[test]
fn a_harness_comment_is_not_shown_and_other_html_is_shown_as_text() {
    let html = plain(
        "Before.\n\n<!-- worked-example 25 -->\nInside.\n<!-- end worked-example -->\n\nAfter.\n",
    );
    assert!(!html.contains("worked-example"), "{html}");
    assert!(
        html.contains("Inside.") && html.contains("After."),
        "{html}"
    );
    let html = plain("A <b>bold</b> claim.\n");
    assert!(html.contains("&lt;b&gt;bold&lt;/b&gt;"), "{html}");
    assert!(!is_comment("<!-- a --> <b>x</b> <!-- b -->"));
}

#[test]
fn a_display_is_not_wrapped_in_a_paragraph_but_inline_math_is() {
    let html = plain("Text before.\n\n$$\nx = 1\n$$\n\nAnd $y$ inline.\n");
    assert!(!html.contains("<p><div"), "{html}");
    assert!(html.contains("<div class=\"display\">"), "{html}");
    assert!(html.contains("<p>And <math"), "{html}");
    // A display inside a sentence keeps its paragraph (the sentence is not dropped).
    let html = plain("We have $$x = 1$$ here.\n");
    assert!(html.contains("<p>We have"), "{html}");
}
