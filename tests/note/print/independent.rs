//! An erratum's correct side held to an independent value (issue 37, item 4): in (54) and (62)
//! the only printed form besides the misprint is the correct side, so a typo there used to be
//! caught only because the hand-typed Rust copy disagreed. Now every correct printed form of an
//! erratum display is held to its check's independent values (τ′_C from the forces and lever
//! arms for (54); Hu's dL_C/dt by automatic differentiation for (62); the particle models of
//! (28), (49), (68)), and the failure names the form and that value.

use crate::common::equation;
use sliding_ladder::registry::check::Config;
use sliding_ladder::registry::print_check::check_print;
use sliding_ladder::registry::{equations, printed_latex};

fn quick() -> Config {
    Config {
        float_cases: 20,
        exact_points: 1,
        seed: 37,
    }
}

/// (display, printed text, typo in a correct form, the independent value the failure names).
const TYPOS: [(u32, &str, &str, &str); 5] = [
    (54, r"= m g l \sin \theta", r"= m g l \cos \theta", "form 2"),
    (
        62,
        r"+ 2m l^2 \cos^2 \theta \ddot{\theta}",
        r"+ 2m l^2 \sin^2 \theta \ddot{\theta}",
        "form 1",
    ),
    (
        28,
        r"&= m g l \sin \theta - 2m l^2 \ddot{\theta},",
        r"&= m g l \sin \theta - 3m l^2 \ddot{\theta},",
        "form 6",
    ),
    (
        49,
        r"\times m \mathbf{v}_{\text{cm}}",
        r"\times 2m \mathbf{v}_{\text{cm}}",
        "form 2",
    ),
    (
        68,
        r"\sum_i \mathbf{x}_i \times \mathbf{F}_i",
        r"\sum_i \mathbf{x}_i \times 2\mathbf{F}_i",
        "form 2",
    ),
];

#[test]
fn every_erratum_as_printed_holds_against_its_independent_values() {
    for e in equations().iter().filter(|e| e.erratum.is_some()) {
        let r = check_print(e, e.latex(), &quick());
        assert!(
            !r.problems.iter().any(|p| p.contains("independent")),
            "({}) {:?}",
            e.number,
            r.problems
        );
    }
}

#[test]
fn a_typo_in_a_correct_form_of_each_erratum_is_flagged_against_the_independent_value() {
    let errata: Vec<u32> = equations()
        .iter()
        .filter(|e| e.erratum.is_some())
        .map(|e| e.number)
        .collect();
    let mut planted: Vec<u32> = TYPOS.iter().map(|t| t.0).collect();
    planted.sort_unstable();
    assert_eq!(planted, errata, "one typo per erratum display");
    for (n, from, to, form) in TYPOS {
        let printed = printed_latex(n);
        let edited = printed.replacen(from, to, 1);
        assert_ne!(edited, printed, "({n}) the edit must apply");
        let r = check_print(&equation(n), &edited, &quick());
        let held: Vec<&String> = r
            .problems
            .iter()
            .filter(|p| p.contains("a correct form of the erratum, differs from the independent"))
            .collect();
        assert!(
            held.iter()
                .any(|p| p.starts_with(&format!("print: {form}"))),
            "({n}): {:?}",
            r.problems
        );
    }
}

#[test]
fn the_independent_values_of_54_and_62_are_the_torque_and_the_rate() {
    // The failure names what the correct side is, not only that the Rust copy disagrees.
    for (n, from, to, what) in [
        (
            54,
            TYPOS[0].1,
            TYPOS[0].2,
            "independent torque τ′_C about C of gravity, wall, floor",
        ),
        (
            62,
            TYPOS[1].1,
            TYPOS[1].2,
            "independent rate dL_C/dt about the fixed lab point where C is now",
        ),
    ] {
        let edited = printed_latex(n).replacen(from, to, 1);
        let r = check_print(&equation(n), &edited, &quick());
        assert!(
            r.problems.iter().any(|p| p.contains(what)),
            "({n}): {:?}",
            r.problems
        );
    }
}
