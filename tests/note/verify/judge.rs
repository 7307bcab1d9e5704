//! Tests of `sliding_ladder::verify::judge` (src/verify/judge.rs): what a verdict says of its
//! checks.

use sliding_ladder::registry::check::{run_check, Config};
use sliding_ladder::registry::equations;
use sliding_ladder::verify::judge;

/// Each row lists its checks by the names the registry gives them, the words `ladder verify
/// --wide` and the book print under "Forms checked" (a report that lost its name would print
/// an empty line there).
#[test]
fn judge_lists_each_check_by_its_registered_name() {
    let cfg = Config {
        float_cases: 2,
        exact_points: 1,
        seed: 2019,
    };
    let mut seen = 0;
    for e in equations()
        .iter()
        .filter(|e| [2, 25, 48, 85].contains(&e.number))
    {
        let reports: Vec<_> = e.checks.iter().map(|c| run_check(c, &cfg)).collect();
        let row = judge(e, &reports);
        let names: Vec<&str> = e.checks.iter().map(|c| c.name).collect();
        assert_eq!(row.checks, names, "({})", e.number);
        assert!(
            row.checks.iter().all(|n| !n.trim().is_empty()),
            "({}): {:?}",
            e.number,
            row.checks
        );
        seen += 1;
    }
    assert_eq!(seen, 4);
}

/// A check report that passed, with every figure set by hand.
fn passing(name: &'static str) -> sliding_ladder::registry::check::CheckReport {
    sliding_ladder::registry::check::CheckReport {
        name,
        float_cases: 10,
        max_scaled_residual: 0.5,
        worst_side: "rust",
        exact_points: 2,
        degree: 4,
        sz_bound: 1e-30,
        sz_bound_log10: -30.0,
        sz_bound_rational_log10: -15.0,
        ..Default::default()
    }
}

/// The first display of the note whose kind, erratum and law are as asked.
fn display(kind: Kind, erratum: bool, law: bool) -> Equation {
    equations()
        .into_iter()
        .find(|e| {
            e.kind == kind
                && e.erratum.is_some() == erratum
                && e.law.is_some() == law
                && !e.checks.is_empty()
        })
        .expect("such a display")
}

use sliding_ladder::registry::{Equation, Kind};
use sliding_ladder::verify::{OffMotion, Status};

/// Each lapse a check report can show is a problem with its own words, and fails the row.
#[test]
fn judge_names_each_lapse_of_a_check_report() {
    let e = display(Kind::Kinematic, false, false);
    let lapse = |f: &dyn Fn(&mut sliding_ladder::registry::check::CheckReport)| {
        let mut r = passing("c");
        f(&mut r);
        let row = judge(&e, &[passing("ok"), r]);
        assert_eq!(row.status, Status::Failed, "{:?}", row.problems);
        row.problems
    };
    assert_eq!(
        lapse(&|r| {
            r.float_failures = 3;
            r.max_scaled_residual = 12.5;
        }),
        ["c: 3 of 10 float states out of tolerance (worst 1.250e1 at rust)"]
    );
    assert_eq!(
        lapse(&|r| r.exact_failures = 1),
        ["c: nonzero exact residual at 1 of 2 points"]
    );
    assert_eq!(
        lapse(&|r| r.misprints = vec![("(1)", true), ("(2)", false)]),
        ["c: the misprint '(2)' did not fail"]
    );
    assert_eq!(
        lapse(&|r| r.off_shell_fails = Some(false)),
        ["c: holds off shell too (the check cannot tell)"]
    );
    // Passing reports: no problem, and the kind's status.
    let ok = judge(&e, &[passing("a"), passing("b")]);
    assert!(ok.problems.is_empty(), "{:?}", ok.problems);
    assert_eq!(ok.status, Status::Verified);
    // An erratum (its law, if any, left aside: the law step is the next test's).
    let mut erratum = equations()
        .into_iter()
        .find(|e| e.erratum.is_some() && !e.checks.is_empty())
        .expect("an erratum");
    erratum.law = None;
    let mut shows = passing("a");
    shows.misprints = vec![("(p)", true)];
    let row = judge(&erratum, &[shows]);
    assert_eq!(row.status, Status::Erratum, "{:?}", row.problems);
    let definition = display(Kind::Definition, false, false);
    assert_eq!(
        judge(&definition, &[passing("a")]).status,
        Status::Definition
    );
}

/// The row sums the reports' states and takes the worst of their residuals and bounds.
#[test]
fn judge_sums_the_reports_and_keeps_the_worst() {
    let e = display(Kind::Kinematic, false, false);
    let mut b = passing("b");
    b.float_cases = 5;
    b.exact_points = 3;
    b.max_scaled_residual = 2.0;
    b.sz_bound = 1e-20;
    b.sz_bound_log10 = -20.0;
    b.sz_bound_rational_log10 = -25.0;
    let row = judge(&e, &[passing("a"), b.clone()]);
    assert_eq!(row.checks, ["a", "b"]);
    assert_eq!(
        (row.cases, row.exact_points, row.exact_failures),
        (15, 5, 0)
    );
    assert!(row.exact);
    assert_eq!(row.max_residual, 2.0);
    assert_eq!(row.sz_bound, 1e-20);
    assert_eq!(
        (row.sz_bound_log10, row.sz_bound_rational_log10),
        (-20.0, -15.0)
    );
    // A report with no exact point: the row is not exact.
    b.exact_points = 0;
    assert!(!judge(&e, &[passing("a"), b]).exact);
    // Kinematic: every check at free θ̈, so any motion.
    assert_eq!(row.off_motion, OffMotion::AnyMotion);
    assert_eq!(row.fails_off_shell, None);
}

/// On shell: the row fails off the motion only if every check does, and each check must break
/// at the marked law's `=` and nowhere else.
#[test]
fn judge_holds_on_shell_checks_to_the_marked_law() {
    let e = display(Kind::OnShell, false, true);
    let step = e.law.expect("a law").step;
    let on = |breaks: Option<Vec<u32>>| {
        let mut r = passing("c");
        r.off_shell_fails = Some(true);
        r.off_motion_breaks = breaks;
        r
    };
    let row = judge(&e, &[on(Some(vec![step]))]);
    assert!(row.problems.is_empty(), "{:?}", row.problems);
    assert_eq!(
        (row.off_motion, row.fails_off_shell, row.law_step),
        (OffMotion::Fails, Some(true), Some(step))
    );
    let elsewhere = judge(&e, &[on(Some(vec![step + 1]))]);
    assert_eq!(
        elsewhere.problems,
        [format!(
            "c: the law is marked at `=` no. {step}, but off the motion the display breaks at [{}]",
            step + 1
        )]
    );
    let twice = judge(&e, &[on(Some(vec![step, step + 1]))]);
    assert_eq!(twice.status, Status::Failed);
    // No check evaluated off the motion: the marked law is not confirmed.
    let unlooked = judge(&e, &[passing("c")]);
    assert_eq!(
        unlooked.problems,
        [format!(
            "the law is marked at `=` no. {step} but no check evaluates the display off the motion"
        )]
    );
    // One check holding off the motion: the row holds there too.
    let mut holds = on(Some(vec![step]));
    holds.off_shell_fails = Some(false);
    let row = judge(&e, &[on(Some(vec![step])), holds]);
    assert_eq!(
        (row.off_motion, row.fails_off_shell),
        (OffMotion::Holds, Some(false))
    );
}
