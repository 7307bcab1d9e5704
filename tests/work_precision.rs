//! Work-precision on real runs: dop853's observed order on the fitted range is near 8, the
//! Pareto front of a real sweep has no dominated run, and the full fall's flat-time reference
//! agrees with an independent method.

use sliding_ladder::report::work_precision::{default_scenes, measure, report, Timing};
use sliding_ladder::report::work_precision_fit::{dominates, observed_order, Point};
use sliding_ladder::sim::scene::End;

/// One timed repeat: these tests judge errors and work, not speed.
const ONCE: Timing = Timing {
    budget: 0.0,
    min: 1,
    max: 1,
};

/// The criterion, held on the upright start and on θ0 = 0.1 from rest. Measured with
/// the fitting rule of `work_precision_fit` (ties at the step limit out, floor from the sweep's
/// own rounding level): upright 8.12 over rhs 413..1059, θ0 = 0.1 8.29 over 113..281; θ0 = 0.3
/// comes out 8.99 over 65..185 (five runs of a short fall: printed, not held, as it sits on the
/// edge); θ0 = 1 and 1.5 have fewer than three runs in range (printed as None).
#[test]
fn dop853_order_is_within_one_of_eight_on_the_fitted_range() {
    for sc in default_scenes().iter().filter(|s| s.end == End::Separation) {
        let runs = measure(sc, &["dop853"], ONCE, |_| {}).unwrap();
        let fit = observed_order(&runs, "dop853");
        println!("{}: {fit:?}", sc.file);
        if sc.theta0 == 0.0 || sc.theta0 == 0.1 {
            let fit = fit.unwrap();
            assert!((fit.order - 8.0).abs() <= 1.0, "{}: {fit:?}", sc.file);
            assert!(fit.runs >= 3 && fit.error_range.1 >= fit.floor, "{fit:?}");
        }
    }
}

#[test]
fn a_real_front_has_no_dominated_run_and_the_flat_reference_holds() {
    let scenes = default_scenes();
    let flat = scenes.iter().find(|s| s.end == End::Flat).unwrap();
    let rep = report(flat, ONCE, |_| {}).unwrap();
    for r in &rep.pareto {
        assert!(!rep.runs.iter().any(|q| dominates(q, r)), "{r:?}");
    }
    for r in &rep.runs {
        if !rep.pareto.contains(r) {
            assert!(rep.runs.iter().any(|q| dominates(q, r)), "{r:?} left out");
        }
    }
    // The reference (Taylor, order 40, from the exact separation) and DOP853 at 1e-16 agree.
    let best = rep
        .runs
        .iter()
        .filter(|r| r.method == "dop853")
        .map(|r| r.flat_time_error.unwrap())
        .fold(f64::INFINITY, f64::min);
    assert!(best < 1e-13, "dop853's best flat-time error {best:e}");
    assert!(rep.runs.iter().all(|r| r.error() >= r.angle_error));
}
