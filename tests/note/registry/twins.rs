//! `registry::print_check::twins`: the pairs of symbols a display's states cannot tell apart, as
//! `ladder show` lists them under `blind:`.

use crate::common::equation;
use sliding_ladder::registry::print_check::twins::{indistinguishable, unbold};
use sliding_ladder::registry::symbol_table;

#[test]
fn unbold_reads_every_bold_symbol_as_its_argument() {
    assert_eq!(unbold(r"\mathbf{v}_{\text{cm}}"), r"v_{\text{cm}}");
    assert_eq!(unbold(r"\mathbf{L}'_{\text{cm}}"), r"L'_{\text{cm}}");
    assert_eq!(unbold(r"\dot{\mathbf{x}}_P"), r"\dot{x}_P");
    assert_eq!(unbold(r"\mathbf{\tau}_{\mathbf{x}}"), r"\tau_{x}");
    assert_eq!(unbold(r"I_{\text{cm}}"), r"I_{\text{cm}}");
    // A brace group inside the bold closes where it is written, not as the bold's end.
    assert_eq!(unbold(r"\mathbf{\dot{x}_P}"), r"\dot{x}_P");
    // Unbalanced braces are read to the end, not a panic.
    assert_eq!(unbold(r"\mathbf{v"), "v");
    assert_eq!(unbold("}}"), "}}");
}

#[test]
fn indistinguishable_lists_no_symbol_beside_its_own_bold_form() {
    // Sec. 2 prints v_cm plain (its square is the speed squared) and the appendix bold: one
    // quantity under two keys, which (2) must not list as a pair it cannot tell apart.
    let table = symbol_table();
    let keys: Vec<&str> = table
        .iter()
        .filter(|t| t.quantity == "velocity:cm" && !t.milne)
        .map(|t| t.key.as_str())
        .collect();
    assert!(
        keys.contains(&r"v_{\text{cm}}") && keys.contains(&r"\mathbf{v}_{\text{cm}}"),
        "the case this test is about: {keys:?}"
    );
    let twins = indistinguishable(&equation(2));
    assert!(
        twins.iter().all(|t| unbold(&t.printed) != unbold(&t.other)),
        "{twins:?}"
    );
    // Distinct symbols of equal value are still listed: (13)'s moments of inertia.
    let of_13 = indistinguishable(&equation(13));
    assert!(
        of_13
            .iter()
            .any(|t| t.printed == "I_{A}" && t.other == "I_{C}"),
        "{of_13:?}"
    );
}

/// A per-particle symbol (xᵢ, vᵢ) outside a Σ means particle 1, which on the ladder sits at C:
/// it has C's values but is no twin of x_C or x_P. No display lists a per-particle quantity.
#[test]
fn indistinguishable_never_pairs_a_per_particle_quantity() {
    let mut with_c = 0;
    for e in &sliding_ladder::registry::equations() {
        let twins = indistinguishable(e);
        with_c += usize::from(twins.iter().any(|t| t.quantities.0 == "position:C"));
        assert!(
            twins
                .iter()
                .all(|t| !t.quantities.0.starts_with("particle_")
                    && !t.quantities.1.starts_with("particle_")),
            "({}) {twins:?}",
            e.number
        );
    }
    // The case this test is about: displays where x_C has a twin to be listed.
    assert!(with_c > 0);
}

/// Each pair is listed once: no display lists a pair and the same pair the other way round,
/// or any pair twice. (13)'s moments of inertia give the case: I_A with I_C, and not also I_C
/// with I_A.
#[test]
fn indistinguishable_lists_each_pair_once() {
    let mut pairs_seen = 0;
    for e in &sliding_ladder::registry::equations() {
        let twins = indistinguishable(e);
        for (i, t) in twins.iter().enumerate() {
            let again = twins[i + 1..].iter().any(|u| {
                (u.printed == t.printed && u.other == t.other)
                    || (u.printed == t.other && u.other == t.printed)
            });
            assert!(
                !again,
                "({}): {} and {} twice",
                e.number, t.printed, t.other
            );
            pairs_seen += 1;
        }
    }
    assert!(pairs_seen > 0);
    let of_13 = indistinguishable(&equation(13));
    assert!(!of_13
        .iter()
        .any(|t| t.printed == "I_{C}" && t.other == "I_{A}"));
}

/// One quantity under two printed names is a twin pair: in A.1, where P is C, x_P is C's
/// position under P's name, and a display printing x_C cannot tell it from x_P. Only the same
/// quantity printed plain and bold is one notation, not a pair.
#[test]
fn indistinguishable_lists_one_quantity_under_two_names() {
    let mut same_quantity = Vec::new();
    for e in &sliding_ladder::registry::equations() {
        for t in indistinguishable(e) {
            if t.quantities.0 == t.quantities.1 {
                assert_ne!(unbold(&t.printed), unbold(&t.other), "({}) {t:?}", e.number);
                same_quantity.push((e.number, t.printed, t.other));
            }
        }
    }
    assert!(!same_quantity.is_empty());
}
/// Twins are an equivalence: (13) prints I_A = I_C = I_D = I_E, four moments of one value, so
/// every one of the 4·3/2 = 6 pairs is listed, the later symbols' pairs too (a pair-once guard
/// that dropped every pair of a symbol already listed as someone's twin left only I_A's three).
#[test]
fn indistinguishable_lists_every_pair_of_equal_printed_symbols() {
    let moments = ["I_{A}", "I_{C}", "I_{D}", "I_{E}"];
    let of_13 = indistinguishable(&equation(13));
    for (i, a) in moments.iter().enumerate() {
        for b in &moments[i + 1..] {
            assert!(
                of_13
                    .iter()
                    .any(|t| (t.printed == *a && t.other == *b)
                        || (t.printed == *b && t.other == *a)),
                "{a} and {b} not listed: {of_13:?}"
            );
        }
    }
}
