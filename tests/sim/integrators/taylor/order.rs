//! `[integrator] order` for `method = "taylor"` (issue 13): accepted and used when in range,
//! refused with one line `file:line: [section] key: what is wrong; allowed: …` otherwise.

use sliding_ladder::sim::fall;
use sliding_ladder::sim::integrators::taylor::{order_for, MAX_ORDER, MIN_ORDER};
use sliding_ladder::sim::scene::parse;

/// A Taylor scene ending at separation; line 12 is the tolerance, line 13 the extra key.
fn scene(method: &str, extra: &str) -> String {
    format!(
        "[ladder]
mass = 1.0
half_length = 1.0
gravity = 9.81
[start]
angle = 0.3
angular_velocity = 0.0
[contact]
model = \"rigid\"
[integrator]
method = \"{method}\"
tolerance = 1e-10
{extra}
[end]
at = \"separation\"
[outputs]
want = [\"separation_angle\", \"rhs_evals\"]
"
    )
}

#[test]
fn the_order_is_read_and_used() {
    let default = parse("scene.toml", &scene("taylor", "")).unwrap();
    assert_eq!(default.order, None);
    let given = parse("scene.toml", &scene("taylor", "order = 8")).unwrap();
    assert_eq!(given.order, Some(8));
    // The stepper counts one evaluation per order per step: the order shows in the counts.
    let evals = |sc| {
        let w = fall::run(sc, fall::MAX_STEPS).unwrap().work.wall;
        (w.rhs_evals, w.steps)
    };
    let (e8, s8) = evals(&given);
    let (ed, sd) = evals(&default);
    assert_eq!(e8, 8 * s8);
    assert_eq!(ed, order_for(1e-10) as u64 * sd);
    assert_ne!(order_for(1e-10), 8);
    // Order 8 at the same tolerance needs more steps than the default order (21).
    assert!(s8 > sd, "order 8: {s8} steps, default: {sd}");
}

#[test]
fn a_bad_order_is_one_line_naming_the_key() {
    let range = format!(
        "allowed: a whole number in [{MIN_ORDER}, {MAX_ORDER}] (default: from the tolerance, the least work per unit time)"
    );
    let cases = [
        (
            scene("dop853", "order = 12"),
            "scene.toml:13: [integrator] order: \"dop853\" takes no order; allowed: order with method = \"taylor\" only".to_string(),
        ),
        (
            scene("taylor", "order = 1"),
            format!("scene.toml:13: [integrator] order: 1 is out of range; {range}"),
        ),
        (
            scene("taylor", "order = 41"),
            format!("scene.toml:13: [integrator] order: 41 is out of range; {range}"),
        ),
        (
            scene("taylor", "order = 12.5"),
            format!("scene.toml:13: [integrator] order: 12.5 is out of range; {range}"),
        ),
    ];
    for (text, expected) in cases {
        let e = parse("scene.toml", &text).expect_err(&expected);
        assert_eq!(e.to_string(), expected);
    }
    // The edges of the range are accepted.
    for p in [MIN_ORDER, MAX_ORDER] {
        let sc = parse("scene.toml", &scene("taylor", &format!("order = {p}"))).unwrap();
        assert_eq!(sc.order, Some(p));
    }
}

/// The default order is the least work per unit time of `order_for`'s model, found here by
/// brute force over every order: a step of order p costs p² + C (C = `STEP_COST` terms of
/// the recursion) and covers h(p) ∝ tol^{1/p} e^{−0.7/(p−1)} (Jorba-Zou's step), so the work
/// per unit time is (p² + C) tol^{−1/p} e^{0.7/(p−1)}.
#[test]
fn the_default_order_is_the_least_work_of_the_model() {
    use sliding_ladder::sim::integrators::taylor::STEP_COST;
    let work = |p: usize, tol: f64, c: f64| {
        let p = p as f64;
        (p * p + c) * (-tol.ln() / p + 0.7 / (p - 1.0)).exp()
    };
    let least = |tol: f64, c: f64| {
        (MIN_ORDER.max(3)..=MAX_ORDER)
            .min_by(|&a, &b| work(a, tol, c).total_cmp(&work(b, tol, c)))
            .unwrap()
    };
    // Between the decades, every eighth of one from 1e-4 to 1e-16: `order_for` stops where the
    // model's slope in p at p + ½ turns positive, which differs from the discrete comparison
    // w(p + 1) ≥ w(p) by w'''/24 (the midpoint rule's error). So near a change of order it may
    // take the neighbour, at an excess work of at most |Δ³w|/24 of the least (2e-5 to 5e-5 here;
    // measured: 5e-6 at 5.6e-14, order 24 for 25). Mutation testing: (q − 1)² → (q + 1)(q − 1)
    // in the slope went unseen at the decades; it picks orders 1e-4 to 5e-4 too costly.
    for j in 32..=128 {
        let tol = 10f64.powf(-f64::from(j) / 8.0);
        let (p, b) = (order_for(tol), least(tol, STEP_COST));
        let w = |p: usize| work(p, tol, STEP_COST);
        let excess = w(p) / w(b) - 1.0;
        let bound = (w(b + 2) - 3.0 * w(b + 1) + 3.0 * w(b) - w(b - 1)).abs() / 24.0 / w(b);
        assert!(
            excess <= bound,
            "tol {tol:e}: order {p} costs {excess:e} more than {b}, over {bound:e}"
        );
    }
    for k in 4..=16 {
        let tol = 10f64.powi(-k);
        assert_eq!(order_for(tol), least(tol, STEP_COST), "tol {tol:e}");
        // Without the step's fixed cost the least work is far lower (Jorba-Zou's ~−ln(tol)/2):
        // the comparison sees the constant.
        if k >= 8 {
            assert!(least(tol, 0.0) + 4 < order_for(tol), "tol {tol:e}");
        }
    }
    // README's figures (the model evaluated by hand).
    assert_eq!(
        (order_for(1e-10), order_for(1e-11), order_for(1e-12)),
        (21, 22, 23)
    );
}
