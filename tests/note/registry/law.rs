//! The law and the algebra told apart (issue 16, item 1): for every display the registry marks,
//! off the motion (θ̈ free) the chain breaks at the marked `=` and nowhere else, computed at
//! exact rational points; a wrong mark is reported by `ladder verify`.

use sliding_ladder::registry::check::{run_check, Config};
use sliding_ladder::registry::law::{breaks, equals_signs};
use sliding_ladder::registry::{equations, printed, reference, Kind, Law};
use sliding_ladder::scalar::{Rational, Scalar};
use sliding_ladder::verify::{judge, Status};

fn cfg() -> Config {
    Config {
        float_cases: 1,
        exact_points: 3,
        seed: 2019,
    }
}

#[test]
fn every_marked_law_step_is_where_the_display_breaks_off_the_motion() {
    let mut marked = 0;
    for e in equations() {
        let Some(law) = e.law else { continue };
        marked += 1;
        assert_eq!(
            e.kind,
            Kind::OnShell,
            "({}) marks a law but is {:?}",
            e.number,
            e.kind
        );
        assert!(
            (1..=equals_signs(e.latex())).contains(&law.step),
            "({}) law step {} but the display has {} `=`",
            e.number,
            law.step,
            equals_signs(e.latex())
        );
        let on_shell: Vec<_> = e
            .checks
            .iter()
            .map(|c| run_check(c, &cfg()))
            .filter(|r| r.off_shell_fails.is_some())
            .collect();
        assert!(!on_shell.is_empty(), "({}) has no on-shell check", e.number);
        for r in on_shell {
            assert!(r.passed(), "({}) {} failed", e.number, r.name);
            assert_eq!(
                r.off_motion_breaks.as_deref(),
                Some(&[law.step][..]),
                "({}) {}: off the motion the display breaks elsewhere",
                e.number,
                r.name
            );
        }
    }
    // The five torque analyses of sec. 2, (11), (53), (54), (59)-(63), (4), (5), (10).
    assert!(marked >= 16, "only {marked} displays mark a law step");
}

/// The teaching point of sec. 2: in each torque analysis the law is the 2nd `=`, between the
/// rate of change of the angular momentum and the torque; everything right of it holds for any θ̈.
#[test]
fn in_each_torque_analysis_the_law_is_between_dl_dt_and_the_torque() {
    for n in [16, 19, 22, 25, 28] {
        let e = equations().into_iter().find(|e| e.number == n).unwrap();
        assert_eq!(e.law.map(|l| l.step), Some(2), "({n})");
    }
}

#[test]
fn kinematic_newton_definition_and_general_displays_mark_no_law() {
    for e in equations() {
        if matches!(e.kind, Kind::Kinematic | Kind::Newton | Kind::Definition) {
            assert!(
                e.law.is_none(),
                "({}) is {:?} but marks a law",
                e.number,
                e.kind
            );
        }
    }
}

/// A mark at the wrong `=` is a failure of `ladder verify`, not a silent label.
#[test]
fn a_wrong_mark_fails_verify() {
    for (n, wrong) in [(25, 1), (25, 3), (16, 1), (53, 1), (11, 2)] {
        let mut e = equations().into_iter().find(|e| e.number == n).unwrap();
        let reports: Vec<_> = e.checks.iter().map(|c| run_check(c, &cfg())).collect();
        assert_ne!(
            judge(&e, &reports).status,
            Status::Failed,
            "({n}) as marked"
        );
        e.law = Some(Law {
            step: wrong,
            statement: "a wrong mark",
        });
        let r = judge(&e, &reports);
        assert_eq!(r.status, Status::Failed, "({n}) marked at {wrong} passed");
        assert!(
            r.problems.iter().any(|p| p.contains("breaks at")),
            "{:?}",
            r.problems
        );
    }
}

/// `breaks` itself: it names every `=` whose two forms differ, and ignores references after
/// the last printed form.
#[test]
fn breaks_finds_each_differing_step() {
    let q = |v: i64| Rational::int(v);
    let chain = vec![
        printed("a", q(1)),
        printed("b", q(1)),
        printed("c", q(2)),
        printed("d", q(2)),
        reference("trailing model", q(7)),
    ];
    assert_eq!(breaks(&[chain]), vec![2]);
    let chain = vec![
        reference("lead", q(1)),
        printed("b", q(2)),
        printed("c", q(3)),
    ];
    assert_eq!(breaks(&[chain]), vec![1, 2]);
    let chain = vec![printed("a", q(5)), printed("b", q(5))];
    assert_eq!(breaks(&[chain]), Vec::<u32>::new());
}

/// `ladder verify --only`: numbers, labels and sections select rows; an unknown item is an error.
#[test]
fn only_selects_rows_by_number_or_section_and_rejects_unknown_items() {
    use sliding_ladder::verify::legend::{law_lines, only};
    // Rows judged without checks carry what `only` reads: number, label and section.
    let all: Vec<_> = sliding_ladder::registry::equations()
        .iter()
        .chain(&sliding_ladder::registry::extensions())
        .map(|e| sliding_ladder::verify::judge(e, &[]))
        .collect();
    let picked = only(all.clone(), "25, 28,2.3").expect("known items");
    let numbers: Vec<u32> = picked.iter().map(|r| r.number).collect();
    assert_eq!(numbers, vec![17, 18, 19, 25, 28]);
    let beyond = only(all.clone(), "P8, P1").expect("labels beyond the note");
    let numbers: Vec<u32> = beyond.iter().map(|r| r.number).collect();
    assert_eq!(numbers, vec![1001, 1008]);
    assert!(only(all.clone(), "91").is_err());
    assert!(only(all.clone(), "P99").is_err());
    assert!(only(all.clone(), "2.9").is_err());
    let lines = law_lines(&picked);
    assert!(
        lines.contains("(25)  2nd `=`") && !lines.contains("(17)"),
        "{lines}"
    );
}

/// Only an `=` outside braces joins two forms: the one in an evaluation bar's subscript does not.
#[test]
fn equals_signs_counts_only_the_equals_outside_braces() {
    assert_eq!(equals_signs(r"L = a \Big|_{\mathbf{x}_P=0} = b"), 2);
    assert_eq!(equals_signs(r"x_{a=b}"), 0);
    assert_eq!(equals_signs("a = b = c"), 2);
}
