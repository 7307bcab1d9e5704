//! Work-precision on real runs: dop853's observed order on the fitted range is near 8, the
//! Pareto front of a real sweep has no dominated run and no point below its reference's
//! accuracy, and the full fall's flat-time reference (closed form and quadrature, independent
//! of the integrators) agrees with DOP853.

use sliding_ladder::report::work_precision::fit::{
    dominates, order_fit, rounding_floor, Point, ASYMPTOTIC, MIN_RUNS, MIN_STEPS,
};
use sliding_ladder::report::work_precision::report::report;
use sliding_ladder::report::work_precision::FLAT_ACCURACY;
use sliding_ladder::report::work_precision::{
    default_scenes, flat_reference, measure, scene_at, Run, Timing,
};
use sliding_ladder::sim::event::{Direction, Event};
use sliding_ladder::sim::exact::PhaseOne;
use sliding_ladder::sim::fall;
use sliding_ladder::sim::floor::{self, FloorPhase};
use sliding_ladder::sim::integrators::taylor::{Taylor, MAX_ORDER};
use sliding_ladder::sim::integrators::Control;
use sliding_ladder::sim::run::integrate_phase;
use sliding_ladder::sim::scene::End;
use std::f64::consts::FRAC_PI_2;

/// One timed repeat: these tests judge errors and work, not speed.
const ONCE: Timing = Timing {
    budget: 0.0,
    min: 1,
    max: 1,
};

/// The criterion on its scenes, with the fitting rule of `work_precision::fit` (at least
/// five runs of at least 10 steps in every phase above the sweep's rounding floor, spanning two
/// decades of error, fitted against steps). Every order reported is within 1 of 8, and one is
/// reported where the range holds five runs: upright with a push and θ0 = 0.1 from rest. From
/// θ0 = 0.3 four runs are in range (issue 38: such fits on 3-4 runs gave slopes far from the
/// method's), from θ0 = 1 and 1.5 dop853 reaches the rounding floor in fewer than 10 steps,
/// and in the full fall to flat fewer than five runs above the floor take 10 steps in each
/// phase. There no order is reported, and the test holds the reason.
#[test]
fn dop853_order_is_within_one_of_eight_on_the_fitted_range() {
    for sc in default_scenes() {
        let runs = measure(&sc, &["dop853"], ONCE, |_| {}).unwrap();
        let fit = order_fit(&runs, "dop853");
        println!("{}: {fit:?}", sc.file);
        if sc.end == End::Separation && sc.theta0 < 0.2 {
            let f = fit.expect("a fitted range");
            assert!((f.order - 8.0).abs() <= 1.0, "{}: {f:?}", sc.file);
            assert!(f.runs >= MIN_RUNS && f.error_range.1 >= f.floor, "{f:?}");
            assert!(f.error_range.0 / f.error_range.1 >= 100.0, "{f:?}");
            assert!(f.steps_range.0 >= MIN_STEPS, "{f:?}");
        } else {
            let why = fit.expect_err("too few runs in range");
            assert!(why.contains("runs in range"), "{why}");
            let floor = rounding_floor(&runs, "dop853");
            let above: Vec<&Run> = runs
                .iter()
                .filter(|r| (floor..=ASYMPTOTIC).contains(&r.error()))
                .collect();
            let long = above
                .iter()
                .filter(|r| r.shortest_phase_steps() >= MIN_STEPS)
                .count();
            assert!(above.len() >= 3 && long < MIN_RUNS, "{}: {long}", sc.file);
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
    // No point of the front lies below the reference's accuracy (the front ended on an error
    // of 0 when the reference was the Taylor method at order 40).
    assert!(rep.pareto.iter().all(|r| r.error() >= FLAT_ACCURACY));
    // The reference (the closed form and the floor phase's quadrature) and DOP853 agree.
    let best = rep
        .runs
        .iter()
        .filter(|r| r.method == "dop853")
        .map(|r| r.flat_time_error.unwrap())
        .fold(f64::INFINITY, f64::min);
    assert!(best < 1e-13, "dop853's best flat-time error {best:e}");
    assert!(rep.runs.iter().all(|r| r.error() >= r.angle_error));
}

/// Flat: θ − π/2 rises through zero (the old reference's event, in θ).
struct FlatInTheta;
impl Event<4> for FlatInTheta {
    fn value(&self, _t: f64, y: &[f64; 4]) -> f64 {
        y[0] - FRAC_PI_2
    }
    fn direction(&self) -> Direction {
        Direction::Rising
    }
    fn rate(&self, _t: f64, _y: &[f64; 4], dy: &[f64; 4]) -> Option<f64> {
        Some(dy[0])
    }
}

/// Near the floor (θ0 = π/2 − 1e-9, φ_s = 6.7e-10) the flat-time reference runs the floor phase
/// in φ = π/2 − θ: it agrees with DOP853's whole fall (an independent method, also in φ, from its
/// own separation). The same reference run in θ, as it was before, starts from θ_s with an
/// absolute error of up to an ulp of π/2 (2.2e-16, i.e. 3e-7 of φ_s) and misses.
#[test]
fn the_flat_reference_runs_in_the_complement_near_the_floor() {
    let mut sc = scene_at(FRAC_PI_2 - 1e-9, 0.0);
    sc.end = End::Flat;
    let ladder = sc.ladder;
    let sep = PhaseOne::new(sc.theta0, sc.rate0, ladder.big_omega2())
        .unwrap()
        .separation()
        .unwrap();
    let reference = flat_reference(&sc, &sep).unwrap();
    let old = {
        let y = floor::state_at_separation(&ladder, sep.angle, sep.rate);
        let mut st = Taylor::with_order(sep.time, y, 1e-16, MAX_ORDER);
        let end = integrate_phase(
            &FloorPhase::new(&ladder),
            &mut st,
            &[&FlatInTheta],
            sep.time + 100.0,
            1_000_000,
            &mut (),
        )
        .unwrap();
        end.t
    };
    sc.method = "dop853".into();
    sc.control = Some(Control::Tolerance(1e-14));
    let independent = fall::run(&sc, fall::MAX_STEPS).unwrap().flat.unwrap().time;
    let rel = |t: f64| (t - independent).abs() / independent;
    println!(
        "flat time {reference} (φ) vs DOP853 {independent}: {:.1e}; in θ {old}: {:.1e}; floor phase {:.1e} s",
        rel(reference),
        rel(old),
        reference - sep.time
    );
    assert!(rel(reference) < 1e-14, "{:e}", rel(reference));
    assert!(rel(old) > 1e-13, "{:e}", rel(old));
}
