//! `verify::summary`: the one-line summary of a verify run. Every count in it is set by hand on
//! two rows, so a count taken from the wrong field, or a worst bound taken as the best, is seen.

use crate::common::equation;
use sliding_ladder::registry::check::Config;
use sliding_ladder::verify::proof::ProofVerdict;
use sliding_ladder::verify::summary::{print_proof_counts, proof_counts, summary_line};
use sliding_ladder::verify::{add_proof_verdict, judge, EquationResult, Status};

/// Two rows, (12) verified and exact, (25) failed and not exact, with every summed or counted
/// field set by hand.
fn two_rows() -> Vec<EquationResult> {
    let mut a = judge(&equation(12), &[]);
    let mut b = judge(&equation(25), &[]);
    a.status = Status::Verified;
    b.status = Status::Failed;
    a.checks = vec!["one", "two"];
    b.checks = vec!["three"];
    (a.exact, b.exact) = (true, false);
    (a.sz_bound_log10, b.sz_bound_log10) = (-40.0, -28.4);
    (a.sz_bound_rational_log10, b.sz_bound_rational_log10) = (-14.2, -20.0);
    (a.proved, b.proved) = (true, false);
    a.proof = "proved".into();
    b.proof = "sampled only: root: a square root".into();
    (a.proof_seconds, b.proof_seconds) = (0.25, 0.5);
    (a.print_proved, b.print_proved) = (Some(true), Some(false));
    (a.print_forms, b.print_forms) = (3, 5);
    vec![a, b]
}

#[test]
fn summary_line_states_every_count_of_the_run() {
    let cfg = Config {
        float_cases: 7,
        ..Config::default()
    };
    // Written by hand from the two rows: the worst (largest) bounds are 1e-28.4 → 1e-28 over all
    // points and 1e-14.2 → 1e-14 over the rational ones.
    assert_eq!(
        summary_line(&two_rows(), &cfg, 1.5),
        "2 equations: 1 verified, 0 erratum, 0 definition, 1 failed; 3 checks, 7 float cases \
         each, 1 exact (Schwartz-Zippel bound ≤ 1e-28; ≤ 1e-14 from the rational points alone); \
         1 proved symbolically, 1 sampled only (0.75 s of proofs); 1.50 s"
    );
}

#[test]
fn proof_counts_count_proved_and_sampled_rows_apart() {
    let mut rows = two_rows();
    assert_eq!(proof_counts(&rows), (1, 1, 0.75));
    // A row not proved for another reason is neither.
    rows[1].proof = "not proved".into();
    assert_eq!(proof_counts(&rows), (1, 0, 0.75));
}

#[test]
fn print_proof_counts_add_the_forms_of_proved_prints_only() {
    let mut rows = two_rows();
    assert_eq!(print_proof_counts(&rows), (1, 3));
    rows[1].print_proved = Some(true);
    assert_eq!(print_proof_counts(&rows), (2, 8));
    rows[0].print_proved = None;
    assert_eq!(print_proof_counts(&rows), (1, 5));
}

#[test]
fn add_proof_verdict_fails_a_row_whose_proof_found_a_problem() {
    let verdict = |problem: Option<&str>| ProofVerdict {
        proved: problem.is_none(),
        proof: if problem.is_none() {
            "proved"
        } else {
            "not proved"
        }
        .into(),
        problem: problem.map(Into::into),
        seconds: 0.5,
        print_proved: Some(problem.is_none()),
        print_forms: 2,
    };
    let mut row = two_rows().remove(0);
    add_proof_verdict(&mut row, verdict(None));
    assert_eq!(row.status, Status::Verified);
    assert!(row.proved && row.problems.is_empty());
    assert_eq!((row.proof.as_str(), row.proof_seconds), ("proved", 0.5));
    assert_eq!(row.print_proved, Some(true));
    add_proof_verdict(&mut row, verdict(Some("print: form 2 differs")));
    assert_eq!(row.status, Status::Failed);
    assert!(!row.proved);
    assert_eq!(row.problems, ["print: form 2 differs"]);
    assert_eq!(row.print_proved, Some(false));
}
