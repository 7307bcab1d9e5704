//! Tests of `sliding_ladder::registry::source::fields` (src/registry/source/fields.rs).

use sliding_ladder::registry::source::fields::{
    read_check, read_law, read_paragraph, read_points, read_symbol, split_fields, Fields, FileDecls,
};
use sliding_ladder::registry::source::LawSpec;

#[test]
fn fields_split_at_markers_after_a_dot_only() {
    let f = split_fields("*Kind:* on-shell · *Code:* [`a::b`](x) · *Checked:* a *b:* c");
    assert_eq!(
        f,
        vec![
            ("Kind", "on-shell"),
            ("Code", "[`a::b`](x)"),
            ("Checked", "a *b:* c")
        ]
    );
    assert!(split_fields("Prose with *Kind:* inside").is_empty());
}

/// A field's name is a capitalised word of two letters or more: a one-letter emphasis such as
/// `*P:*` opening a paragraph (a point named in prose) is not a field, and a lower-case or
/// non-alphabetic name is not either.
#[test]
fn split_fields_takes_names_of_two_capitalised_letters_or_more() {
    assert!(split_fields("*P:* the point about which torques are taken").is_empty());
    assert!(split_fields("*kind:* general").is_empty());
    assert!(split_fields("*K2:* general").is_empty());
    assert_eq!(split_fields("*Ab:* x"), vec![("Ab", "x")]);
    // Within a paragraph of fields, a one-letter marker after a dot stays in the value.
    assert_eq!(
        split_fields("*Kind:* general · *P:* x"),
        vec![("Kind", "general · *P:* x")]
    );
}

#[test]
fn a_law_line_gives_its_step_and_statement() {
    let l = read_law("the 2nd `=` is the law of motion: dL/dt = τ. Every other `=` is …");
    assert_eq!(
        l,
        Ok(LawSpec {
            step: 2,
            statement: "dL/dt = τ".into()
        })
    );
    assert_eq!(read_law("the 1st `=`").map(|l| l.step), Ok(1));
    assert!(read_law("the second `=` is the law").is_err());
    assert!(read_law("the 0th `=`").is_err());
    assert!(read_law("2nd `=`").is_err());
}

#[test]
fn a_check_item_needs_function_states_and_words() {
    let mut f = Fields::default();
    read_check("- `eq25` (on-shell): AD of (24) = forms", 7, &mut f);
    read_check("- eq25 (on-shell): no backticks", 8, &mut f);
    read_check("- `eq25`: no states", 9, &mut f);
    assert_eq!(f.checks.len(), 1);
    assert_eq!(f.checks[0].function, "eq25");
    assert_eq!(f.checks[0].sample, "on-shell");
    assert_eq!(f.checks[0].name, "AD of (24) = forms");
    assert_eq!(f.errors.iter().map(|e| e.0).collect::<Vec<_>>(), vec![8, 9]);
}

#[test]
fn an_erratum_needs_math_and_its_correction() {
    let mut f = Fields::default();
    read_paragraph(
        "*Misprint:* $a = b$ · *Why:* because",
        3,
        &mut f,
        &mut FileDecls::default(),
    );
    assert_eq!(
        f.erratum.as_ref().map(|e| e.printed.as_str()),
        Some("a = b")
    );
    // A missing *Corrected:* is known only when the section closes (it may come a paragraph
    // later): the paragraph records where the erratum began, parse_file reports it there.
    assert!(f.errors.is_empty(), "{:?}", f.errors);
    assert_eq!(f.erratum_line, 3);
    let section =
        "### (4) T\n\n$$\na = b\n$$\n\n*Kind:* kinematic\n\n*Misprint:* $a = b$ · *Why:* because\n";
    let errors = sliding_ladder::registry::source::parse_file("t.md", section).errors;
    let shown: Vec<String> = errors.iter().map(ToString::to_string).collect();
    assert_eq!(
        shown,
        ["t.md:9: (4): a *Misprint:* needs its *Corrected:* form"]
    );
    let mut g = Fields::default();
    read_paragraph(
        "*Misprint:* a = b · *Corrected:* $c$",
        3,
        &mut g,
        &mut FileDecls::default(),
    );
    assert!(g.errors.iter().any(|e| e.1.contains("between single `$`")));
}

#[test]
fn points_and_symbols_are_read_with_their_errors() {
    let mut d = FileDecls::default();
    read_points(
        "Q = ladder:1/4; R = lab:1/2,3/2; S = ladder:5/4; T = moon; Q' = ladder:1/2; = ladder:1/3",
        4,
        &mut d,
    );
    let got: Vec<(&str, &str)> = d
        .points
        .iter()
        .map(|p| (p.name.as_str(), p.point.as_str()))
        .collect();
    assert_eq!(got, vec![("Q", "ladder:1/4"), ("R", "lab:1/2,3/2")]);
    // S and T name no point; Q' and the empty name are not names (letters and digits only).
    assert_eq!(d.errors.len(), 4, "{:?}", d.errors);
    assert!(
        d.errors[2..].iter().all(|e| e.1.contains("is not NAME = ")),
        "{:?}",
        d.errors
    );
    read_symbol(
        "- $L_Q$ = `relative_angular_momentum:Q.z` [M L^2 T^-1]: about Q",
        9,
        &mut d,
    );
    read_symbol(
        "- $L_Q$ = relative_angular_momentum:Q.z: no backticks",
        10,
        &mut d,
    );
    assert_eq!(d.symbols.len(), 1);
    assert_eq!(d.symbols[0].quantity, "relative_angular_momentum:Q.z");
    assert_eq!(d.symbols[0].dimension, "M L^2 T^-1");
    assert_eq!(d.errors.last().map(|e| e.0), Some(10));
}
