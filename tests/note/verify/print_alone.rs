//! `verify::print_judge` for a display with no Rust check (the print alone): the row counts the
//! states the print evaluated, its Schwartz-Zippel bound is taken over its rational points, and
//! off the motion it fails, holds for any motion or has no ladder, by the display's kind; a law
//! step is found off the motion, or held to the one the display marks.

use sliding_ladder::registry::check::{Config, EXACT_SET_SIZE};
use sliding_ladder::registry::print_check::check_print;
use sliding_ladder::registry::{equations, Equation, Kind};
use sliding_ladder::verify::{
    judge_with_print, EquationResult, OffMotion, Status, LAW_FOUND, PRINT_ALONE,
};

fn cfg(exact_points: usize) -> Config {
    Config {
        float_cases: 3,
        exact_points,
        seed: 11,
    }
}

/// The first display of `kind` (with a marked law, when `law`), its Rust checks taken away.
fn alone(kind: Kind, law: bool) -> Equation {
    let mut e = equations()
        .into_iter()
        .find(|e| e.kind == kind && e.erratum.is_none() && e.law.is_some() == law)
        .expect("a display of that kind");
    e.checks.clear();
    e
}

fn judged(e: &Equation, exact_points: usize) -> EquationResult {
    judge_with_print(e, &[], &cfg(exact_points))
}

#[test]
fn print_alone_counts_the_states_of_the_print_and_bounds_over_them() {
    let e = alone(Kind::OnShell, true);
    let r = judged(&e, 2);
    assert_eq!(
        r.status,
        Status::Verified,
        "({}) {:?}",
        e.number,
        r.problems
    );
    assert_eq!(r.checks, [PRINT_ALONE]);
    assert_eq!((r.cases, r.exact_points, r.exact_failures), (3, 2, 0));
    assert!(r.exact);
    // Schwartz-Zippel over two rational points: (d/N)², d the degree the print check found.
    let d = f64::from(check_print(&e, e.latex(), &cfg(2)).degree.max(1));
    let bound = (d / EXACT_SET_SIZE) * (d / EXACT_SET_SIZE);
    assert!(bound > 0.0 && bound < 1.0);
    assert!(
        (r.sz_bound / bound - 1.0).abs() < 1e-12,
        "{} {bound}",
        r.sz_bound
    );
    assert!((r.sz_bound_log10 - bound.log10()).abs() < 1e-12);
    assert_eq!(r.sz_bound_rational_log10, r.sz_bound_log10);
    // No exact point: nothing was shown exactly, and the bound is 1 (no evidence).
    let none = judged(&e, 0);
    assert!(!none.exact);
    assert_eq!((none.exact_points, none.sz_bound), (0, 1.0));
}

#[test]
fn print_alone_says_what_each_kind_does_off_the_motion() {
    let on = judged(&alone(Kind::OnShell, true), 1);
    assert_eq!(on.off_motion, OffMotion::Fails);
    assert_eq!(on.fails_off_shell, Some(true));
    let kinematic = judged(&alone(Kind::Kinematic, false), 1);
    assert_eq!(kinematic.off_motion, OffMotion::AnyMotion);
    assert_eq!(kinematic.fails_off_shell, None);
    let general = judged(&alone(Kind::General, false), 1);
    assert_eq!(general.off_motion, OffMotion::NotApplicable);
    for r in [on, kinematic, general] {
        assert_eq!(r.status, Status::Verified, "{} {:?}", r.label, r.problems);
    }
}

#[test]
fn print_alone_finds_the_law_step_or_holds_the_marked_one() {
    let marked = alone(Kind::OnShell, true);
    let step = marked.law.expect("a law").step;
    assert_eq!(judged(&marked, 1).law_step, Some(step));
    // With no `*Law:*` line the step is found off the motion: the same `=`.
    let mut unmarked = marked.clone();
    unmarked.law = None;
    let r = judged(&unmarked, 1);
    assert_eq!((r.law_step, r.law), (Some(step), Some(LAW_FOUND)));
    assert!(r.problems.is_empty(), "{:?}", r.problems);
    // A law marked at another `=` is a problem that names both.
    let mut wrong = marked.clone();
    wrong.law = marked.law.map(|mut l| {
        l.step += 1;
        l
    });
    let r = judged(&wrong, 1);
    assert_eq!(r.status, Status::Failed);
    assert!(
        r.problems.iter().any(|p| p.contains(&format!(
            "the law is marked at `=` no. {}, but off the motion the display breaks at [{step}]",
            step + 1
        ))),
        "{:?}",
        r.problems
    );
}
