//! `verify::proof`: the proof column of one equation from its check proofs and its print.
//! Each branch of the verdict is driven by a hand-made check proof, so a verdict that could not
//! fail (or a branch that names the wrong reason) is seen here.

use crate::common::equation as display;
use sliding_ladder::registry::print_check::prove::PrintProof;
use sliding_ladder::registry::prove::CheckProof;
use sliding_ladder::registry::{equations, Kind};
use sliding_ladder::scalar::Scalar;
use sliding_ladder::scalar::Sym;
use sliding_ladder::verify::proof::{verdict, with_print, ProofVerdict};

/// A check proof that holds: proved, no misprint, needing the motion.
fn holding(name: &'static str, seconds: f64) -> CheckProof {
    CheckProof {
        name,
        proved: true,
        failure: None,
        misprints: vec![],
        off_shell_fails: Some(true),
        sampled_only: None,
        seconds,
    }
}

fn x() -> Sym {
    Sym::var("x", "x")
}

#[test]
fn verdict_names_each_kind_of_display_that_holds() {
    // An identity, an erratum and a definition of the note (their kinds read from the registry).
    let twelve = display(12);
    assert!(twelve.erratum.is_none() && twelve.kind != Kind::Definition);
    let v = verdict(&twelve, &[holding("a", 0.25), holding("b", 0.5)]);
    assert!(v.proved && v.problem.is_none(), "{v:?}");
    assert_eq!(v.proof, "proved");
    // The seconds of every check are added: 0.25 + 0.5, exact in binary.
    assert_eq!(v.seconds, 0.75);
    let erratum = equations()
        .into_iter()
        .find(|e| e.erratum.is_some())
        .expect("an erratum");
    assert_eq!(verdict(&erratum, &[holding("a", 0.0)]).proof, "erratum");
    let definition = equations()
        .into_iter()
        .find(|e| e.kind == Kind::Definition && e.erratum.is_none())
        .expect("a definition");
    assert_eq!(
        verdict(&definition, &[holding("a", 0.0)]).proof,
        "definition"
    );
}

#[test]
fn verdict_fails_on_each_lapse_of_a_check_and_names_it() {
    let e = display(12);
    let judge = |p: CheckProof| verdict(&e, &[holding("fine", 0.0), p]);
    // A side that differs from the first: its label and difference are printed.
    let differs = judge(CheckProof {
        proved: false,
        failure: Some(("rust", x())),
        ..holding("differs", 0.0)
    });
    assert!(!differs.proved);
    assert_eq!(differs.proof, "not proved");
    assert_eq!(
        differs.problem.as_deref(),
        Some("differs: not proved: rust − first side = x")
    );
    // A misprint that is symbolically right.
    let right = judge(CheckProof {
        misprints: vec![("(1)", x()), ("(2)", Sym::int(0))],
        ..holding("typo", 0.0)
    });
    assert!(!right.proved);
    assert_eq!(
        right.problem.as_deref(),
        Some("typo: the misprint '(2)' is symbolically right")
    );
    // A misprint that differs is what an erratum needs: no problem.
    let wrong = judge(CheckProof {
        misprints: vec![("(1)", x())],
        ..holding("typo", 0.0)
    });
    assert!(wrong.proved && wrong.problem.is_none(), "{wrong:?}");
    // An on-shell check that holds off the motion too cannot tell the motion apart.
    let off = judge(CheckProof {
        off_shell_fails: Some(false),
        ..holding("off", 0.0)
    });
    assert!(!off.proved);
    assert_eq!(
        off.problem.as_deref(),
        Some("off: holds symbolically off shell too")
    );
    // A check not on shell (None) is not asked to fail off it.
    let not_on_shell = judge(CheckProof {
        off_shell_fails: None,
        ..holding("kinematic", 0.0)
    });
    assert!(not_on_shell.proved, "{not_on_shell:?}");
}

#[test]
fn verdict_reports_the_first_check_that_fails() {
    let e = display(12);
    let bad = |name| CheckProof {
        off_shell_fails: Some(false),
        ..holding(name, 0.0)
    };
    let v = verdict(&e, &[holding("ok", 0.0), bad("first"), bad("second")]);
    assert_eq!(
        v.problem.as_deref(),
        Some("first: holds symbolically off shell too")
    );
}

#[test]
fn verdict_of_a_check_only_sampled_is_not_proved_and_says_why() {
    let e = display(12);
    let sampled = CheckProof {
        sampled_only: Some("a square root".into()),
        ..holding("root", 1.0)
    };
    let v = verdict(&e, &[holding("ok", 0.5), sampled]);
    assert!(!v.proved);
    assert_eq!(v.proof, "sampled only: root: a square root");
    // Not a problem to report: the check still runs at random states.
    assert!(v.problem.is_none());
    assert_eq!(v.seconds, 1.5);
}

/// A proof of a print of `forms` forms, proved unless it names a problem, taking no time.
fn print_proof(forms: usize, problem: Option<&str>) -> PrintProof {
    PrintProof {
        forms,
        proved: problem.is_none(),
        problem: problem.map(Into::into),
        seconds: 0.0,
    }
}

fn proved_verdict() -> ProofVerdict {
    verdict(&display(12), &[holding("ok", 0.25)])
}

#[test]
fn with_print_fails_a_proved_display_whose_print_is_not_proved() {
    // No print (an extension): the verdict is unchanged.
    let none = with_print(proved_verdict(), None);
    assert!(none.proved && none.print_proved.is_none() && none.print_forms == 0);
    // A proved print: the forms and seconds are carried.
    let good = with_print(
        proved_verdict(),
        Some(PrintProof {
            forms: 3,
            proved: true,
            problem: None,
            seconds: 0.5,
        }),
    );
    assert!(good.proved, "{good:?}");
    assert_eq!(good.proof, "proved");
    assert_eq!((good.print_proved, good.print_forms), (Some(true), 3));
    assert_eq!(good.seconds, 0.75);
    // A print with a problem fails the display and names the problem.
    let bad = with_print(
        proved_verdict(),
        Some(print_proof(2, Some("print: form 2 differs"))),
    );
    assert!(!bad.proved);
    assert_eq!(bad.proof, "not proved");
    assert_eq!(bad.problem.as_deref(), Some("print: form 2 differs"));
    assert_eq!(bad.print_proved, Some(false));
    // A display already not proved keeps its own, earlier problem.
    let mut failed = proved_verdict();
    failed.proved = false;
    failed.problem = Some("checks: first".into());
    let kept = with_print(failed, Some(print_proof(1, Some("print: second"))));
    assert_eq!(kept.problem.as_deref(), Some("checks: first"));
}
