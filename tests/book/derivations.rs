//! Tests of `sliding_ladder::book::derivations` (src/book/derivations.rs).

use sliding_ladder::book::derivations::{needs, size};
use sliding_ladder::ladder::geometry::Corner;
use sliding_ladder::scalar::{Rational, Scalar};

/// The needs read off the model agree with the note's sec. 2.7 table: about C only F_f and
/// gravity, about D only F_w and gravity, about E gravity alone; A is at rest.
#[test]
fn the_forces_with_a_torque_are_those_whose_line_misses_the_point() {
    let has = |k, s: &str| needs(k).torques.iter().any(|t| t == s);
    assert!(has(Corner::A, "F_w") && has(Corner::A, "F_f"));
    assert!(has(Corner::C, "F_f") && !has(Corner::C, "F_w"));
    assert!(has(Corner::D, "F_w") && !has(Corner::D, "F_f"));
    assert!(!has(Corner::E, "F_w") && !has(Corner::E, "F_f"));
    assert!(!has(Corner::B, "m g"));
    assert!(!needs(Corner::A).accelerates && needs(Corner::C).accelerates);
    // I_C = 4ml²/3 (21): L′_C = (4/3) m l² θ̇; about B it is I_cm θ̇ = (1/3) m l² θ̇ (18).
    assert_eq!(needs(Corner::C).l_coefficient, Some(Rational::ratio(4, 3)));
    assert_eq!(needs(Corner::B).l_coefficient, Some(Rational::ratio(1, 3)));
}

#[test]
fn terms_count_the_additive_terms_of_a_form() {
    assert_eq!(
        size(r"a_x = l \cos\theta \ddot{\theta} - l \sin\theta \dot{\theta}^2"),
        Some((2, 2))
    );
}
