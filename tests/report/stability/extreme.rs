//! Tests of `sliding_ladder::report::stability::extreme` (src/report/stability/extreme.rs).

// The references keep the digits mpmath printed: more than f64 holds, on purpose.
#![allow(clippy::excessive_precision)]

use sliding_ladder::report::stability::case::{Verdict, TOL, U, UNIT};
use sliding_ladder::report::stability::extreme::{member_rows, Form};
use sliding_ladder::sim::exact::PhaseOne;

/// The old angle check, |cos θ_s − cos θ_s,theory| ≤ 10 N τ max(θ_s, 1) + 4 u with
/// cos θ_s,theory = 2/3 + 4 θ̇0²/9 (g = l = 1), passed main's dop853 answer one ulp below
/// fl(Ω) from upright: θ_s = 1.300549668599140e-8, t_s = 1.501745402520385e-8 in one step,
/// where mpmath gives 1.575373387247517e-8 and 1.819084498403054e-8
/// (tools/near_release_reference.py). The relative checks fail that answer and pass the
/// rows of today's run.
#[test]
fn the_old_absolute_check_was_blind_and_the_relative_ones_are_not() {
    let w: f64 = 0.8660254037844385;
    let (wrong_angle, wrong_time): (f64, f64) = (1.300_549_668_599_14e-8, 1.501745402520385e-8);
    let cs = 2.0 / 3.0 + 4.0 * w * w / 9.0;
    let old_bound = 10.0 * TOL * wrong_angle.max(1.0) + 4.0 * U;
    assert!((wrong_angle.cos() - cs.min(1.0)).abs() <= old_bound);
    let x = PhaseOne::new(0.0, w, UNIT.big_omega2())
        .unwrap()
        .separation()
        .unwrap();
    // The closed form is mpmath's to 2 ulps.
    assert!((x.angle - 1.575_373_387_247_517_4e-8).abs() <= 4.0 * U * x.angle);
    assert!((x.time - 1.819_084_498_403_053_8e-8).abs() <= 8.0 * U * x.time);
    assert_eq!(Form::of(0.0, w), Form::Near);
    let (angle_bound, time_bound) = Form::Near.bounds(1.0, TOL, 0.0, x.angle);
    assert!((wrong_angle - x.angle).abs() / x.angle > 1e3 * angle_bound);
    assert!((wrong_time - x.time).abs() / x.time > 1e3 * time_bound);
    let rows = member_rows("one ulp below fl(Ω)", 0.0, w);
    assert_eq!(rows.len(), 2, "{rows:?}");
    for c in &rows {
        assert_eq!(c.verdict, Verdict::Ok, "{c:?}");
    }
}
