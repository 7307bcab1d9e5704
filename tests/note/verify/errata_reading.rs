//! Tests of `sliding_ladder::verify::errata_reading` (src/verify/errata_reading.rs).

use sliding_ladder::registry::equations;
use sliding_ladder::registry::Equation;
use sliding_ladder::scalar::Dimension;
use sliding_ladder::verify::errata_reading::{reading, residual_unit, unit_name};

fn eq(n: u32) -> Equation {
    equations().into_iter().find(|e| e.number == n).unwrap()
}

#[test]
fn the_five_errata_read_in_physical_terms_with_their_units() {
    // From the print: (49) and (68) lost a mass, (62) a factor 2l, (54) has θ̇² for θ̈.
    let r49 = reading(&eq(49)).unwrap().0;
    assert!(r49.ends_with("lacks a factor m"), "{r49}");
    let r62 = reading(&eq(62)).unwrap().0;
    assert!(r62.ends_with("lacks a factor 2l"), "{r62}");
    let r54 = reading(&eq(54)).unwrap().0;
    assert!(r54.contains("has θ̇² where θ̈ belongs"), "{r54}");
    let r68 = reading(&eq(68)).unwrap().0;
    assert!(
        r68.starts_with("in each component (x, y, z), the printed term lacks a factor m₁: ("),
        "{r68}"
    );
    // (28) lost a whole term, F_E,x l cos θ: no reading, the difference is shown instead.
    assert_eq!(reading(&eq(28)), None);
    // Torques in N·m, (49)'s angular momentum in kg·m²/s; (68) is a torque too.
    for (n, unit) in [
        (28, "N·m"),
        (49, "kg·m²/s"),
        (54, "N·m"),
        (62, "N·m"),
        (68, "N·m"),
    ] {
        assert_eq!(residual_unit(&eq(n)), unit, "({n})");
    }
}

#[test]
fn an_unnamed_dimension_is_in_base_units() {
    assert_eq!(unit_name(Dimension::new(0, 1, -3)), "m s^-3");
    assert_eq!(unit_name(Dimension::new(1, 2, -2)), "N·m");
}

/// A planted erratum whose chain opens with its misprint (an angular momentum printed without
/// its mass, l²θ̇) before the correction (m l²θ̇).
fn misprint_first<S: sliding_ladder::scalar::Scalar>(
    l: &sliding_ladder::ladder::Ladder<S>,
    s: &sliding_ladder::ladder::State<S>,
) -> Vec<sliding_ladder::registry::Chain<S>> {
    use sliding_ladder::registry::{corrected, misprint};
    let l2 = l.l.clone() * l.l.clone() * s.rate.clone();
    vec![vec![
        misprint("printed: l² θ̇", l2.clone()),
        corrected("corrected: m l² θ̇", l.m.clone() * l2),
    ]]
}

/// The residual's unit is the corrected form's, wherever the misprint stands in the chain:
/// kg·m²/s here, not the misprint's m²/s.
#[test]
fn residual_unit_is_the_corrected_forms_even_after_a_misprint() {
    use sliding_ladder::registry::sample::LadderSample;
    use sliding_ladder::registry::{Check, Eval};
    let mut e = eq(49);
    e.checks = vec![Check {
        name: "planted",
        eval: Eval::Ladder(
            LadderSample::Kinematic,
            sliding_ladder::ladder_fns!(misprint_first),
        ),
    }];
    assert_eq!(residual_unit(&e), "kg·m²/s");
}
