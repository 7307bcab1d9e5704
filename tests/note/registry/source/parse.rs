//! Tests of `sliding_ladder::registry::source::parse` (src/registry/source/parse.rs).

use sliding_ladder::registry::source::parse::{
    heading_label, heading_text, parse_file, section_label,
};

#[test]
fn labels_and_sections_are_read_from_headings() {
    assert_eq!(
        heading_label("(25) Torque about D").map(|x| x.1),
        Some("Torque about D")
    );
    assert_eq!(
        heading_label("(P3) Floor").and_then(|x| x.0.ok()),
        Some(1003)
    );
    assert!(heading_label("(0) Zero").is_some_and(|x| x.0.is_err()));
    // (P0) is refused too: the number 1000 itself is neither the note's nor an extension's, and
    // `equations` and `extensions` both leave it out.
    assert!(heading_label("(P0) Zero").is_some_and(|x| x.0.is_err()));
    // Numbers run below the extensions' base, 1000, in both series: (999) and (P999) are the
    // last, (1000) and (P1000) are refused (a (P1000) would take the number 2000).
    let number = |h| heading_label(h).map(|x| x.0);
    assert_eq!(number("(999) Last"), Some(Ok(999)));
    assert_eq!(number("(P999) Last"), Some(Ok(1999)));
    assert!(number("(1000) Too far").is_some_and(|n| n.is_err()));
    assert!(number("(P1000) Too far").is_some_and(|n| n.is_err()));
    assert!(heading_label("(a) not a display").is_none());
    assert!(heading_label("Title (3)").is_none());
    assert_eq!(
        section_label("Sec. 2.5 — Torque analysis about D"),
        Some("2.5")
    );
    assert_eq!(section_label("Appendix A — Angular momentum"), Some("A"));
    assert_eq!(section_label("B.7 — Sec. 303: the rate"), Some("B.7"));
    assert_eq!(section_label("What each point costs"), None);
    assert_eq!(
        heading_text("### (25) Torque about D ##\n"),
        "(25) Torque about D"
    );
}

#[test]
fn a_section_lacking_display_or_kind_is_an_error_at_its_line() {
    let src = "# Sec. 9.1 — Test\n\n### (1) No display\n\ntext\n\n### (2) No kind\n\n$$\na = b\n$$\n\n### (3) Law too far\n\n$$\na = b\n$$\n\n*Kind:* kinematic\n\n*Law:* the 2nd `=` is the law of motion: x\n\n### (4) Fine\n\n$$\na\n= b\n$$\n\n*Kind:* on-shell\n\n*Law:* the 1st `=` is the law of motion: the law. Every other `=` holds.\n";
    let parsed = parse_file("t.md", src);
    let (ok, errs) = (parsed.sections, parsed.errors);
    let msgs: Vec<String> = errs.iter().map(ToString::to_string).collect();
    assert_eq!(
        msgs,
        vec![
            "t.md:3: (1) has no display (the LaTeX between two `$$` lines)".to_string(),
            "t.md:7: (2) does not state its kind (a line `*Kind:* on-shell`, ...)".to_string(),
            "t.md:21: (3): *Law:* names `=` no. 2, the display has 1".to_string(),
        ]
    );
    assert_eq!(ok.len(), 1);
    let s = &ok[0];
    assert_eq!((s.number, s.line, s.section.as_str()), (4, 23, "9.1"));
    assert_eq!((s.latex.as_str(), s.latex_line), ("a = b", 25));
    let law = s.law.as_ref().expect("law");
    assert_eq!((law.step, law.statement.as_str()), (1, "the law"));
}

/// `Lines::line_of` against counting the line breaks before each offset, on text with empty
/// lines, a trailing break and none; an offset on a break belongs to the line it ends.
#[test]
fn lines_line_of_counts_the_breaks_before_the_offset() {
    use sliding_ladder::registry::source::Lines;
    for src in ["", "a", "a\n", "\n\nab\n\ncd", "### (1) T\n\n$$\nx\n$$\n"] {
        let lines = Lines::new(src);
        for offset in 0..=src.len() + 2 {
            let want = src.as_bytes()[..offset.min(src.len())]
                .iter()
                .filter(|&&b| b == b'\n')
                .count()
                + 1;
            assert_eq!(lines.line_of(offset), want, "{src:?} at {offset}");
        }
    }
    let lines = Lines::new("a\nb\nc");
    assert_eq!(
        [0, 1, 2, 4].map(|o| lines.line_of(o)),
        [1, 1, 2, 3],
        "the break at 1 ends line 1"
    );
}

/// A section states its kind once: a second `*Kind:*` line is an error at its own line (11,
/// counted by hand), and the section is left out, whatever the two kinds are.
#[test]
fn parse_file_refuses_a_second_kind_line() {
    let src = "# Sec. 9.1 — Test\n\n### (1) Twice\n\n$$\na = b\n$$\n\n*Kind:* kinematic\n\n*Kind:* general\n";
    let parsed = parse_file("t.md", src);
    let msgs: Vec<String> = parsed.errors.iter().map(ToString::to_string).collect();
    assert_eq!(msgs.len(), 1, "{msgs:?}");
    assert!(
        msgs[0].starts_with("t.md:11:") && msgs[0].contains("a second *Kind:* line"),
        "{msgs:?}"
    );
    assert!(parsed.sections.is_empty());
}

/// Only the items of the list right after `*Rust:*` are checks, not the items of a list nested in
/// one: a remark under a check is no second check (and no malformed one).
#[test]
fn parse_file_reads_no_nested_item_as_a_check() {
    let src = "### (4) T\n\n$$\na = b\n$$\n\n*Kind:* kinematic\n\n*Rust:*\n- `eq4` (kinematic): w\n  - a remark under the check\n";
    let parsed = parse_file("t.md", src);
    assert!(parsed.errors.is_empty(), "{:?}", parsed.errors);
    assert_eq!(parsed.sections.len(), 1);
    assert_eq!(parsed.sections[0].checks.len(), 1);
}
