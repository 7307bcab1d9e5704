//! The print proved: every parsed printed form of every display evaluated in the symbolic scalar
//! (src/registry/print_check/prove.rs), for all values of the variables, not only sampled. Each
//! way a print proof can fail is planted below and seen to fail.

use sliding_ladder::registry::print_check::misprints;
use sliding_ladder::registry::print_check::prove::{prove_print, prove_print_with};
use sliding_ladder::registry::{equations, Equation};

fn display(n: u32) -> Equation {
    equations()
        .into_iter()
        .find(|e| e.number == n)
        .expect("a display of the note")
}

#[test]
fn every_display_is_proved_as_printed() {
    let mut forms = 0;
    let mut bad = Vec::new();
    for e in equations() {
        let p = prove_print(&e, e.latex());
        forms += p.forms;
        if !p.proved {
            bad.push(format!("{}: {:?}", e.label(), p.problem));
        }
    }
    assert!(bad.is_empty(), "{bad:#?}");
    assert_eq!(forms, 345, "every printed form of the note");
}

#[test]
fn a_planted_wrong_printed_form_is_not_proved_and_its_difference_prints() {
    // (12) with its last form printed as −ml²θ̇/3 instead of −2ml²θ̇/3.
    let e = display(12);
    let wrong =
        r#"L_A = -ml^2 \dot{\theta} + \frac{ml^2 \dot{\theta}}{3} = -\frac{ml^2 \dot{\theta}}{3}"#;
    let p = prove_print(&e, wrong);
    assert!(!p.proved);
    // form 3 − form 1 = −1/3 + 2/3 = 1/3 m l² θ̇, by hand.
    let problem = p.problem.expect("a difference");
    assert!(
        problem.contains("form 3") && problem.ends_with("= 1/3 m l^2 θ̇ (not zero)"),
        "{problem}"
    );
}

#[test]
fn an_erratum_not_recorded_as_a_misprint_is_not_proved() {
    // (49) without its misprint recorded: the printed last form must be shown false for any
    // state; (68) likewise for systems of particles.
    for n in [49, 68] {
        let e = display(n);
        let p = prove_print_with(&e, e.latex(), &[]);
        assert!(!p.proved, "({n})");
        let problem = p.problem.expect("a difference");
        assert!(problem.contains("(not zero)"), "({n}) {problem}");
    }
}

#[test]
fn a_right_form_recorded_as_a_misprint_is_caught() {
    let e = display(12);
    let list = [(12, r#"-\frac{2ml^2 \dot{\theta}}{3}"#)];
    let p = prove_print_with(&e, e.latex(), &list);
    assert!(!p.proved);
    assert!(
        p.problem
            .as_deref()
            .is_some_and(|s| s.contains("is symbolically right")),
        "{:?}",
        p.problem
    );
    // With the real list it holds.
    assert!(prove_print_with(&e, e.latex(), &misprints()).proved);
}

#[test]
fn an_on_shell_print_that_holds_off_the_motion_is_caught() {
    // (5) is on shell; a chain that holds for any θ̈ cannot be the equation of motion.
    let e = display(5);
    let p = prove_print(&e, r#"\ddot{\theta} = \ddot{\theta}"#);
    assert!(!p.proved);
    assert_eq!(
        p.problem.as_deref(),
        Some("print: holds symbolically off the motion too")
    );
}

#[test]
fn a_rust_form_missing_from_the_print_is_caught() {
    // (49) with its misprinted last form cut from the print: the Rust misprint side equals no
    // printed form.
    let e = display(49);
    let cut = r#"\mathbf{L}_C = \mathbf{L}_{\text{cm}} + (\mathbf{x}_{\text{cm}} - \mathbf{x}_P) \times m \mathbf{v}_{\text{cm}}"#;
    let p = prove_print(&e, cut);
    assert!(!p.proved);
    assert!(
        p.problem
            .as_deref()
            .is_some_and(|s| s.starts_with("print vs code:")),
        "{:?}",
        p.problem
    );
}
