//! `sliding_ladder::verify::fill` at its edges, every expected line worked out by hand from the
//! module's rules: a line filled up to the width and not one column short, a label column that
//! ends at column 30 at the latest, a hanging indent two columns right of any indent, a line of
//! exactly the width left alone, and the width of combining marks from both of their blocks.

use sliding_ladder::verify::fill::{fill, fill_line, widest, width, wrap};

#[test]
fn wrap_fills_each_line_up_to_the_width_and_breaks_before_operators() {
    // "aa bb" is exactly 5 columns: it stays on one line at width 5, not at 4.
    assert_eq!(wrap("aa bb cc", 5), ["aa bb", "cc"]);
    assert_eq!(wrap("aa bb cc", 4), ["aa", "bb", "cc"]);
    // Combining dots take no column: "θ̇θ̇ bb" is 5 columns.
    assert_eq!(wrap("θ̇θ̇ bb", 5), ["θ̇θ̇ bb"]);
    // A lone operator goes with the word after it, so the break falls before it.
    assert_eq!(wrap("x + y", 1), ["x", "+ y"]);
    // A word that ends in ≈ keeps the next word; a trailing operator is kept.
    assert_eq!(wrap("value (≈ 3.5) more", 9), ["value", "(≈ 3.5)", "more"]);
    assert_eq!(wrap("a = b −", 100), ["a = b −"]);
}

#[test]
fn width_skips_combining_marks_of_both_blocks() {
    assert_eq!(width("θ\u{307}"), 1); // combining dot above (U+0300 block)
    assert_eq!(width("z\u{302}"), 1); // combining circumflex
    assert_eq!(width("r\u{20D7}"), 1); // combining right arrow above (U+20D0 block)
    assert_eq!(width("m l²"), 4);
    assert_eq!(widest(""), 0);
    assert_eq!(widest("ab\nθ\u{307}θ\u{307}θ\u{307}\n"), 3);
}

/// A label column is one whose text starts by column 30: the line continues under that text.
/// One column later it is no label, and the line continues two columns right of its indent.
#[test]
fn fill_line_takes_a_label_column_ending_at_column_30_at_most() {
    let text = "alpha beta gamma delta epsilon";
    let at30 = format!("  label{}{text}", " ".repeat(23));
    assert_eq!(width(&at30[..at30.find("alpha").unwrap()]), 30);
    let under = " ".repeat(30);
    assert_eq!(
        fill_line(&at30, 45),
        format!(
            "{}alpha beta\n{under}gamma delta\n{under}epsilon",
            &at30[..30]
        )
    );
    let at31 = format!("  label{}{text}", " ".repeat(24));
    assert_eq!(
        fill_line(&at31, 45),
        "  label alpha beta gamma delta epsilon"
    );
}

#[test]
fn fill_line_hangs_two_columns_right_of_any_indent() {
    assert_eq!(
        fill_line("    one two three four", 12),
        "    one two\n      three\n      four"
    );
    // A trailing space is not a label's gap, and is dropped with the other spaces.
    assert_eq!(
        fill_line("  one two three four ", 10),
        "  one two\n    three\n    four"
    );
}

/// A line exactly as wide as the terminal is left as it is (its double space kept); one column
/// narrower and it is filled (the double space, past column 30, is no label's gap).
#[test]
fn fill_line_leaves_a_line_of_exactly_the_width() {
    let line = format!("  {}  b", "a".repeat(28));
    assert_eq!(width(&line), 33);
    assert_eq!(fill_line(&line, 33), line);
    assert_eq!(fill_line(&line, 32), format!("  {} b", "a".repeat(28)));
}

#[test]
fn fill_keeps_the_trailing_newline_and_the_blank_lines() {
    assert_eq!(fill("a b\n", 100), "a b\n");
    assert_eq!(fill("a b", 100), "a b");
    assert_eq!(fill("a b\n\nc\n", 100), "a b\n\nc\n");
    assert_eq!(fill("  one two three\n", 9), "  one two\n    three\n");
}
