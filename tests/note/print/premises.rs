//! `sliding_ladder::registry::print_check::premises`: a display checked at exactly the states its
//! own words allow (issue 37). Evaluation bars are substitutions, an implication's conclusion is
//! claimed where its premise holds and its premise nowhere, and the print's bars and
//! implications are held to the display's `*Premises:*`. Each check is shown able to fail.

use sliding_ladder::registry::check::Config;
use sliding_ladder::registry::print_check::{check_print_with, misprints, PrintReport};
use sliding_ladder::registry::sample::{ParticleSample, PrintSample};
use sliding_ladder::registry::source::{PremiseSource, PremiseSpec};
use sliding_ladder::registry::{equations, Equation};

fn quick() -> Config {
    Config {
        float_cases: 20,
        exact_points: 1,
        seed: 37,
    }
}

fn display(n: u32) -> Equation {
    equations()
        .into_iter()
        .find(|e| e.number == n)
        .expect("a display of the note")
}

/// The display without its `*Premises:*` list, on the same general states (its stated and prose
/// premises, where it has any, are then not imposed): only the values can flag an edit.
fn bare(n: u32) -> Equation {
    let mut e = display(n);
    e.premises = &[];
    e.states = Some(PrintSample::Particles(ParticleSample::General));
    e
}

fn check(e: &Equation, latex: &str) -> PrintReport {
    check_print_with(e, latex, &quick(), &misprints())
}

/// The problems the values found (not the premises' bookkeeping).
fn value_problems(r: &PrintReport) -> Vec<&String> {
    r.problems
        .iter()
        .filter(|p| p.contains("differs from its chain") || p.contains("out of tolerance"))
        .collect()
}

fn edit(n: u32, from: &str, to: &str) -> String {
    let latex = display(n).latex();
    assert!(latex.contains(from), "({n}) prints no '{from}'");
    latex.replacen(from, to, 1)
}

#[test]
fn the_displays_with_premises_are_correct_as_printed() {
    for n in [41, 56, 57, 70, 71, 84, 86, 87, 88, 89] {
        let e = display(n);
        let r = check(&e, e.latex());
        assert!(r.problems.is_empty(), "({n}): {:?}", r.problems);
    }
}

#[test]
fn a_dropped_or_changed_bar_changes_the_values() {
    let bar = r"\Big|_{\mathbf{x}_P=0}";
    let cases = [
        // (86): dL_P/dt with P anywhere is not dL/dt − v_P × m v_cm.
        (
            86,
            format!(r"\frac{{d\mathbf{{L}}_P}}{{dt}} {bar}"),
            r"\frac{d\mathbf{L}_P}{dt}".to_string(),
        ),
        // (86): the condition changed, x_P = x_cm instead of x_P = 0.
        (
            86,
            format!(r"\frac{{d\mathbf{{L}}_P}}{{dt}} {bar}"),
            r"\frac{d\mathbf{L}_P}{dt} \Big|_{\mathbf{x}_P=\mathbf{x}_{\text{cm}}}".to_string(),
        ),
        // (87): the rate of L at the origin is τ, not τ_cm, unless the centre of mass is there.
        (
            87,
            r"\frac{d\mathbf{L}}{dt} \Big|_{\mathbf{x}_P=\mathbf{x}_{\text{cm}}=0} =".to_string(),
            r"\frac{d\mathbf{L}}{dt} =".to_string(),
        ),
        (
            88,
            r"\frac{d\mathbf{L}}{dt} \Big|_{\mathbf{x}_{\text{cm}}=0}".to_string(),
            r"\frac{d\mathbf{L}}{dt}".to_string(),
        ),
    ];
    for (n, from, to) in cases {
        let e = bare(n);
        let good = check(&e, e.latex());
        assert!(
            value_problems(&good).is_empty(),
            "({n}) as printed: {:?}",
            good.problems
        );
        let r = check(&e, &edit(n, &from, &to));
        assert!(
            !value_problems(&r).is_empty(),
            "({n}) '{to}': {:?}",
            r.problems
        );
    }
}

#[test]
fn the_bars_are_held_to_the_premises_even_where_the_values_cannot_see() {
    // (88) with the bar strengthened to x_P = x_cm = 0: dL/dt does not depend on P, so the
    // values agree; the premises name the change.
    let e = display(88);
    let strong = edit(
        88,
        r"\Big|_{\mathbf{x}_{\text{cm}}=0}",
        r"\Big|_{\mathbf{x}_P=\mathbf{x}_{\text{cm}}=0}",
    );
    let r = check(&e, &strong);
    assert!(value_problems(&r).is_empty(), "{:?}", r.problems);
    assert!(
        r.problems
            .iter()
            .any(|p| p.contains("not among the display's premises")),
        "{:?}",
        r.problems
    );
    assert!(
        r.problems.iter().any(|p| p.contains("printed nowhere")),
        "{:?}",
        r.problems
    );
    // (89): x_P = 0 is the section's premise, so its bars are invisible to the values.
    let e = display(89);
    assert!(e.premises.iter().any(|p| p.source == PremiseSource::Stated));
    let dropped = e.latex().replace(r"\Big|_{\mathbf{x}_P=0}", "");
    let mut stated_only = e.clone();
    let kept: Vec<PremiseSpec> = e
        .premises
        .iter()
        .filter(|p| p.source == PremiseSource::Stated)
        .cloned()
        .collect();
    stated_only.premises = Box::leak(kept.into_boxed_slice());
    let dropped = dropped
        .replace(r"\Big|_{O=O'}", "")
        .replace(r"]_{O=O'}", "]");
    let r = check(&stated_only, &dropped);
    assert!(value_problems(&r).is_empty(), "{:?}", r.problems);
    let r = check(&e, &dropped);
    assert!(
        r.problems.iter().any(|p| p.contains("printed nowhere")),
        "{:?}",
        r.problems
    );
}

#[test]
fn an_implication_claims_its_conclusion_where_its_premise_holds_and_its_premise_nowhere() {
    for (n, premise, conclusion) in [
        (70, r"\mathbf{F} = 0", r"\mathbf{P} = \text{const}"),
        (71, r"\boldsymbol{\tau} = 0", r"\mathbf{L} = \text{const}"),
    ] {
        let e = bare(n);
        let good = check(&e, e.latex());
        assert!(
            value_problems(&good).is_empty(),
            "({n}): {:?}",
            good.problems
        );
        // ⇒ made a comma: the premise is now claimed for every system, and fails.
        let comma = edit(
            n,
            &format!(r"{premise} \Rightarrow {conclusion}"),
            &format!(r"{premise}, \quad {conclusion}"),
        );
        let r = check(&e, &comma);
        assert!(
            !value_problems(&r).is_empty(),
            "({n}) comma: {:?}",
            r.problems
        );
        // The conclusion alone (premise dropped) is false for a general system.
        let alone = edit(n, &format!(r"{premise} \Rightarrow "), "");
        let r = check(&e, &alone);
        assert!(
            !value_problems(&r).is_empty(),
            "({n}) alone: {:?}",
            r.problems
        );
        // With the premises listed, the change of shape is named as such.
        let r = check(&display(n), &comma);
        assert!(
            r.problems
                .iter()
                .any(|p| p.contains("the implication became a claim")),
            "({n}): {:?}",
            r.problems
        );
    }
}

#[test]
fn every_display_prints_each_listed_bar_and_implication_and_lists_each_printed_one() {
    for e in equations() {
        let r = check(&e, e.latex());
        let named: Vec<&String> = r
            .problems
            .iter()
            .filter(|p| p.contains("premise"))
            .collect();
        assert!(named.is_empty(), "({}): {named:?}", e.number);
        let bars = e.latex().matches(r"\Big|_{").count();
        let implies = e.latex().matches(r"\Rightarrow").count();
        if bars + implies > 0 {
            assert!(
                !e.premises.is_empty(),
                "({}) has bars or ⇒ but no *Premises:*",
                e.number
            );
        }
    }
}

/// A bar is found wherever the print nests it: under a sign, a power, a sum, a derivative (total or partial), a z component, either side of +, −, a product, a fraction or
/// a cross product, and in a tuple. (88)'s listed bar stays on the left; on the right the
/// strengthened bar x_P = x_cm = 0, listed nowhere, is nested in each construct in turn, and
/// must be named each time (the values may differ too: they are not what is asked here). The
/// parser gives sin and cos a symbol only, so no bar can stand under them.
#[test]
fn an_unlisted_bar_is_named_wherever_the_print_nests_it() {
    let e = display(88);
    let bar = r"\mathbf{L} \Big|_{\mathbf{x}_P=\mathbf{x}_{\text{cm}}=0}";
    let nests = [
        format!("-{bar}"),
        format!(r"({bar})^{{2}}"),
        format!(r"\sum_i {bar}"),
        format!(r"\frac{{d}}{{dt}} ({bar})"),
        format!(r"\frac{{\partial {bar}}}{{\partial \theta}}"),
        format!(r"({bar})|_z"),
        format!(r"\mathbf{{x}}_P + {bar}"),
        format!(r"{bar} - \mathbf{{x}}_P"),
        format!(r"m {bar}"),
        format!(r"\frac{{{bar}}}{{m}}"),
        format!(r"\mathbf{{x}}_P \times {bar}"),
        format!(r"({bar}, m)"),
    ];
    let left = r"\frac{d\mathbf{L}}{dt} \Big|_{\mathbf{x}_{\text{cm}}=0}";
    // The left side alone against a plain right side: no premise is named.
    let plain = check(&e, &format!(r"{left} = \mathbf{{x}}_P"));
    assert!(
        !plain
            .problems
            .iter()
            .any(|p| p.contains("not among the display's premises")),
        "{:?}",
        plain.problems
    );
    for nest in &nests {
        let r = check(&e, &format!("{left} = {nest}"));
        assert!(
            r.problems
                .iter()
                .any(|p| p.contains("not among the display's premises")),
            "'{nest}': {:?} {:?}",
            r.problems,
            r.unparsed
        );
    }
}

/// A premise's condition is one statement `a = b` (or a longer chain): a single form states no
/// condition, nor do two statements or an implication.
#[test]
fn condition_forms_takes_one_chain_of_two_forms_or_more() {
    use sliding_ladder::registry::print_check::premises::condition_forms;
    assert_eq!(condition_forms(r"\mathbf{x}_P = 0").map(|f| f.len()), Ok(2));
    assert_eq!(condition_forms(r"a = b = 0").map(|f| f.len()), Ok(3));
    assert!(condition_forms(r"\mathbf{x}_P").is_err());
    assert!(condition_forms(r"a = b, \quad c = d").is_err());
    assert!(condition_forms(r"a = b \Rightarrow c = d").is_err());
}

/// A display of one implication with one `implies` premise is consistent: (70) cut to its own
/// statement, F = 0 ⇒ P = const, with the premise F = 0 alone. (Every display of the note
/// prints two implications, ours and Milne's; an extender may print one.)
#[test]
fn a_single_implication_matches_its_single_premise() {
    let mut e = display(70);
    let premises = e.premises;
    e.premises = &premises[..1];
    assert_eq!(e.premises[0].source, PremiseSource::Implies);
    let r = check(&e, r"\mathbf{F} = 0 \Rightarrow \mathbf{P} = \text{const}");
    assert!(r.problems.is_empty(), "{:?}", r.problems);
}
