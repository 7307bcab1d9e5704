//! `verify::check_methods` (the note's derivations of the equation of motion, each run through
//! its checks) and `verify::counts`, over rows set by hand: what a row says must be what its
//! checks did.

use crate::common::equation;
use sliding_ladder::derivation::derivations;
use sliding_ladder::registry::check::{Config, TOLERANCE_FACTOR};
use sliding_ladder::verify::{check_methods, counts, judge, Status};

/// Every method's row: its name in the order of `derivations`, passed with no problem listed,
/// the float states of all its checks counted, and a worst residual that was measured (above 0:
/// a float check of a nonzero θ̈ rounds) and within the threshold.
#[test]
fn check_methods_reports_each_derivation_by_its_checks() {
    let cfg = Config {
        float_cases: 7,
        exact_points: 1,
        seed: 4,
    };
    let rows = check_methods(&cfg);
    let methods = derivations();
    assert_eq!(rows.len(), methods.len());
    for (row, (name, checks)) in rows.iter().zip(&methods) {
        assert_eq!(row.name, *name);
        assert!(row.passed, "{name}: {:?}", row.problems);
        assert!(row.problems.is_empty(), "{name}: {:?}", row.problems);
        assert!(!checks.is_empty(), "{name} has no check");
        assert_eq!(row.cases, checks.len() * cfg.float_cases, "{name}");
        assert!(
            row.max_residual > 0.0 && row.max_residual <= TOLERANCE_FACTOR,
            "{name}: {}",
            row.max_residual
        );
    }
}

/// `counts` tallies each status into its own slot: (verified, erratum, definition, failed).
#[test]
fn counts_tallies_each_status_into_its_slot() {
    let row = |s: Status| {
        let mut r = judge(&equation(25), &[]);
        r.status = s;
        r
    };
    let rows = [
        row(Status::Verified),
        row(Status::Failed),
        row(Status::Verified),
        row(Status::Definition),
        row(Status::Erratum),
        row(Status::Verified),
        row(Status::Failed),
        row(Status::Definition),
        row(Status::Definition),
        row(Status::Definition),
    ];
    assert_eq!(counts(&rows), (3, 1, 4, 2));
    assert_eq!(counts(&[]), (0, 0, 0, 0));
}
