//! Tests of `sliding_ladder::registry::source::premises` (src/registry/source/premises.rs).

use sliding_ladder::registry::source::premises::{read_premise, PremiseSource};

#[test]
fn an_item_gives_source_condition_and_words_and_a_bad_one_is_refused() {
    let p = read_premise(r"- bar: $\mathbf{x}_P = 0$ (P at the origin now)", 3).unwrap();
    assert_eq!(p.source, PremiseSource::Bar);
    assert_eq!(p.latex.as_deref(), Some(r"\mathbf{x}_P = 0"));
    assert_eq!(p.words, "P at the origin now");
    assert!(read_premise("- prose: a rigid body", 4)
        .unwrap()
        .latex
        .is_none());
    assert!(read_premise(r"- maybe: $x = 0$", 5)
        .unwrap_err()
        .contains("not a source"));
    assert!(read_premise("- bar: no condition", 6)
        .unwrap_err()
        .contains("needs"));
}
