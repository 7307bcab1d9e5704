//! Tests of `sliding_ladder::book::math` (src/book/math.rs).

use pulldown_latex::{push_mathml, Parser, RenderConfig, Storage};
use sliding_ladder::book::math::{mathml, space_before_scripted_function, FN_SPACE};

#[test]
fn every_display_of_the_note_renders() {
    for n in sliding_ladder::registry::equations()
        .iter()
        .map(|e| e.number)
    {
        let m = mathml(sliding_ladder::registry::printed_latex(n), true)
            .unwrap_or_else(|e| panic!("({n}): {e}"));
        assert!(
            m.starts_with("<math") && m.contains("display=\"block\""),
            "({n}): {m}"
        );
        assert!(!m.contains('\\'), "({n}) keeps raw LaTeX: {m}");
    }
}

/// The first child elements of the first `tag` element of `m` (by a plain tag count: the
/// renderer's output has no comments or CDATA).
fn children_of_first(m: &str, tag: &str) -> Vec<String> {
    let start = m.find(&format!("<{tag}>")).expect(tag) + tag.len() + 2;
    let (mut depth, mut names, mut i) = (0, Vec::new(), start);
    while let Some(o) = m[i..].find('<').map(|o| o + i) {
        let end = m[o..].find('>').unwrap() + o;
        let t = &m[o + 1..end];
        if let Some(closing) = t.strip_prefix('/') {
            if depth == 0 {
                assert_eq!(closing, tag);
                return names;
            }
            depth -= 1;
        } else {
            if depth == 0 {
                names.push(t.split([' ', '/']).next().unwrap().to_string());
            }
            if !t.ends_with('/') {
                depth += 1;
            }
        }
        i = end + 1;
    }
    panic!("unclosed <{tag}> in {m}")
}

#[test]
fn a_squared_function_after_an_ordinary_atom_is_a_two_child_script() {
    // After an Ord (l²) the renderer adds the thin space; it must stand before the msup.
    for (latex, tag) in [
        (r"l^2 \sin^2 \theta", "msup"),
        (r"m \cos_1 \theta", "msub"),
        (r"x \cos_1^2 \theta", "msubsup"),
    ] {
        let m = mathml(latex, true).unwrap();
        let kids = children_of_first(&m, tag);
        let want = if tag == "msubsup" { 3 } else { 2 };
        assert_eq!(kids.len(), want, "{latex}: {kids:?} in {m}");
        assert_eq!(kids[0], "mi", "{latex}: {m}");
        assert!(m.contains(&format!("{FN_SPACE}<{tag}>")), "{latex}: {m}");
    }
    // At the start (no Ord before it) there is no space to move, and none is added.
    let m = mathml(r"\sin^2 \theta", true).unwrap();
    assert_eq!(children_of_first(&m, "msup"), ["mi", "mn"], "{m}");
    assert!(!m.contains("<mspace width=\"0.1667em\" /><msup>"), "{m}");
}

#[test]
fn the_unfixed_renderer_output_has_three_children_so_the_test_can_fail() {
    let bad =
        "<math><mi>l</mi><msup><mspace width=\"0.1667em\" /><mi>sin</mi><mn>2</mn></msup></math>";
    assert_eq!(children_of_first(bad, "msup").len(), 3);
    let fixed = space_before_scripted_function(bad.to_string());
    assert_eq!(children_of_first(&fixed, "msup"), ["mi", "mn"], "{fixed}");
    // A space that is not a script's first child stays where it is.
    let plain = "<math><mi>a</mi><mspace width=\"0.1667em\" /><mi>b</mi></math>";
    assert_eq!(space_before_scripted_function(plain.to_string()), plain);
}

#[test]
fn a_no_break_space_is_a_space_not_the_text_nbsp() {
    for latex in [r"a,\ b", "a~b"] {
        let m = mathml(latex, false).unwrap();
        assert!(!m.contains("nbsp"), "{latex}: {m}");
        assert!(m.contains("<mspace width=\"0.3333em\""), "{latex}: {m}");
    }
    // Without the mapping the renderer shows the entity as text: the mapping is needed.
    let storage = Storage::new();
    let mut raw = String::new();
    push_mathml(
        &mut raw,
        Parser::new("a~b", &storage),
        RenderConfig::default(),
    )
    .unwrap();
    assert!(raw.contains("&amp;nbsp;"), "{raw}");
    // A text's trailing blank is kept, as a character reference XML knows.
    let m = mathml(r"x, \text{Milne: } y", false).unwrap();
    assert!(
        m.contains("Milne:&#160;</mtext>") && !m.contains("&nbsp;"),
        "{m}"
    );
}

#[test]
fn a_bad_command_or_unbalanced_brace_is_an_error() {
    assert!(mathml(r"\frac{1}{2", true).is_err());
    assert!(mathml(r"\notacommand x", false).is_err());
    assert!(mathml(r"\frac{1}{2}", false).is_ok());
}
