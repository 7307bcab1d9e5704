//! Tests of `sliding_ladder::registry::source::note` (src/registry/source/note.rs).

use sliding_ladder::registry::fns;
use sliding_ladder::registry::source::note::{misprinted_forms, Note};

#[test]
fn the_embedded_note_reads_without_a_problem() {
    let note = Note::embedded();
    assert!(note.errors.is_empty(), "{:?}", note.errors);
    // Every display of the note's chapters names its Rust checks; the problems' answers
    // (equations/problems.md, issue 39) are checked from their markdown alone, by design.
    assert!(note
        .sections
        .iter()
        .filter(|s| !s.file.ends_with("/problems.md"))
        .all(|s| !s.checks.is_empty()));
    assert!(note
        .sections
        .iter()
        .any(|s| s.file.ends_with("/problems.md")));
}

/// The misprints found from each erratum's two lines are the forms that were listed by hand
/// before the markdown was the source (the list `MISPRINTS` of commit 5245033).
#[test]
fn the_misprints_are_the_forms_the_correction_does_not_have() {
    let note = Note::embedded();
    let found: Vec<(u32, Vec<&str>)> = note
        .sections
        .iter()
        .filter_map(|s| Some((s.number, s.erratum.as_ref()?)))
        .map(|(n, e)| (n, misprinted_forms(&e.printed, &e.corrected)))
        .collect();
    let by_hand: [(u32, &str); 5] = [
        (28, r"\tau_E - F_{E,y} l \sin \theta"),
        (
            49,
            r"\frac{m l^2 \dot{\theta}}{3} \hat{\mathbf{z}} + l^2 \dot{\theta} (\cos^2 \theta - \sin^2 \theta) \hat{\mathbf{z}}",
        ),
        (54, r"\frac{4m l^2 \dot{\theta}^2}{3}"),
        (
            62,
            r"m l g \sin \theta - m l \sin^2 \theta \ddot{\theta} - m l \cos \theta \sin \theta \dot{\theta}^2",
        ),
        (68, r"\sum \mathbf{r} \wedge \ddot{\mathbf{r}}"),
    ];
    let want: Vec<(u32, Vec<&str>)> = by_hand.iter().map(|(n, f)| (*n, vec![*f])).collect();
    assert_eq!(found, want);
    // A correction that changes nothing leaves no misprint, which the note refuses.
    assert!(misprinted_forms("a = b", "a = b").is_empty());
}

#[test]
fn a_display_that_begins_with_equals_continues_the_one_before() {
    let note = Note::embedded();
    let continued: Vec<(u32, &str)> = note
        .sections
        .iter()
        .filter_map(|s| Some((s.number, s.continues.as_deref()?)))
        .collect();
    assert_eq!(continued, vec![(57, r"\boldsymbol{\tau}_P")]);
}

#[test]
fn a_number_used_twice_or_an_unknown_function_is_refused_with_its_line() {
    let one =
        "### (7) Seven\n\n$$\nx = y\n$$\n\n*Kind:* kinematic\n\n*Rust:*\n- `eq7` (kinematic): w\n";
    let two = "# T\n\n### (8) Eight\n\n$$\nx = y\n$$\n\n*Kind:* kinematic\n\n*Rust:*\n- `eq7x` (kinematic): w\n- `eq7` (general): w\n";
    let note = Note::parse([("a.md", one), ("b.md", one), ("c.md", two)]);
    let msgs: Vec<String> = note.errors.iter().map(ToString::to_string).collect();
    assert_eq!(note.sections.len(), 1, "{msgs:?}");
    assert!(
        msgs.contains(&"b.md:1: (7) appears twice (first at a.md:1)".to_string()),
        "{msgs:?}"
    );
    assert!(
        msgs.iter()
            .any(|m| m.starts_with("c.md:12: (8): `eq7x` is not")),
        "{msgs:?}"
    );
    assert!(
        msgs.iter()
            .any(|m| m.starts_with("c.md:13: (8): `eq7` is evaluated at states")),
        "{msgs:?}"
    );
}

#[test]
fn every_name_is_unique_and_every_function_is_named_by_the_note() {
    let all: Vec<&str> = fns::table().map(|(n, _)| *n).collect();
    let mut sorted = all.clone();
    sorted.sort_unstable();
    sorted.dedup();
    assert_eq!(sorted.len(), all.len(), "a name twice in the table");
    let note = Note::embedded();
    let named: Vec<&str> = note
        .sections
        .iter()
        .flat_map(|s| s.checks.iter().map(|c| c.function.as_str()))
        .collect();
    let unnamed: Vec<&&str> = all.iter().filter(|n| !named.contains(n)).collect();
    assert!(unnamed.is_empty(), "named by no section: {unnamed:?}");
}

/// A note display's print must read as LaTeX even beside Rust checks: (5) with a fraction missing its denominator
/// is refused at its `$$` line. An extension's print beside Rust checks is checked by those
/// checks alone (the floor phase's prints), so the same LaTeX as (P1) is not refused here.
#[test]
fn an_unreadable_print_of_the_note_is_refused_beside_its_checks() {
    let section = |label: &str| {
        "### LABEL Falls\n\n$$\n\\ddot{\\theta} = \\frac{3g}\n$$\n\n*Kind:* on-shell\n\n*Rust:*\n- `eq5_on_shell` (on-shell): w\n"
            .replace("LABEL", label)
    };
    let (note_display, extension) = (section("(5)"), section("(P1)"));
    let note = Note::parse([("a.md", note_display.as_str())]);
    let msgs: Vec<String> = note.errors.iter().map(ToString::to_string).collect();
    assert_eq!(msgs.len(), 1, "{msgs:?}");
    assert!(
        msgs[0].starts_with("a.md:3: (5): the display cannot be read as LaTeX of the note"),
        "{msgs:?}"
    );
    let ext = Note::parse([("b.md", extension.as_str())]);
    assert!(ext.errors.is_empty(), "{:?}", ext.errors);
}
