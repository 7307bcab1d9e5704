//! `sim::event`: event functions and where a step samples them.

mod defaults;
mod interior_samples;

// The root finders of `sim::event` on functions with known roots: accuracy, cost, fall-backs.

use sliding_ladder::sim::event::{brent, crosses, newton_in_bracket, Direction};

#[test]
fn brent_finds_cos_root_to_the_last_ulp() {
    let r = brent(f64::cos, 1.0, 2.0, 1f64.cos(), 2f64.cos());
    assert!((r - std::f64::consts::FRAC_PI_2).abs() <= 2.0 * f64::EPSILON * 2.0);
}

#[test]
fn newton_finds_cos_root_and_falls_back_without_derivative() {
    let f = |t: f64| Some((t.cos(), -t.sin()));
    let r = newton_in_bracket(f, 1.0, 2.0, 1f64.cos(), 2f64.cos()).unwrap();
    assert!((r - std::f64::consts::FRAC_PI_2).abs() <= 8.0 * f64::EPSILON * 2.0);
    // A wrong derivative still ends inside the bracket at the root (bisection guard).
    let g = |t: f64| Some((t.cos(), 1.0));
    let r = newton_in_bracket(g, 1.0, 2.0, 1f64.cos(), 2f64.cos()).unwrap();
    assert!(
        (r - std::f64::consts::FRAC_PI_2).abs() <= 4.0 * f64::EPSILON * 2.0,
        "{r}"
    );
    assert!(newton_in_bracket(|_| None, 1.0, 2.0, 0.5, -0.4).is_none());
}

/// rtsafe's guarantee: a poor derivative costs speed, never more than bisection would
/// take plus the Newton steps between bisections. With a slope 100 times too steep each
/// Newton step covers 1 % of the way to the root; the "not halving" test bisects instead,
/// so [1, 2] narrows in at most about 2 × 53 evaluations (a Newton step and a bisection in
/// turn). Without that test Newton crawls and 2,200 iterations end 1e-10 short of the root.
/// The noise stop trusts the derivative: a correction under 8 ulps stands for a distance
/// 100 times that here, so the root is held to 100 × 8 ulps. (The events' rates are their
/// exact derivatives along the motion, each checked against a difference quotient.)
#[test]
fn a_poor_derivative_costs_at_most_a_bisection_s_count_twice() {
    let evals = std::cell::Cell::new(0);
    let f = |t: f64| {
        evals.set(evals.get() + 1);
        Some((t.cos(), -100.0 * t.sin()))
    };
    let r = newton_in_bracket(f, 1.0, 2.0, 1f64.cos(), 2f64.cos()).unwrap();
    let half_pi = std::f64::consts::FRAC_PI_2;
    assert!(
        (r - half_pi).abs() <= 100.0 * 8.0 * f64::EPSILON * 2.0,
        "{r}"
    );
    assert!(evals.get() <= 2 * 53 + 4, "{} evaluations", evals.get());
}

#[test]
fn newton_stops_when_the_correction_is_below_an_ulp() {
    // f = (t − 2) + 1e-17: from t = 3 Newton lands on t = 2 exactly, where f is 1e-17 and
    // the correction 1e-17 vanishes in t. That is converged; bisecting on from there
    // towards the other end of the bracket took 50 more evaluations.
    let evals = std::cell::Cell::new(0);
    let f = |t: f64| {
        evals.set(evals.get() + 1);
        Some(((t - 2.0) + 1e-17, 1.0))
    };
    let r = newton_in_bracket(f, 1.0, 3.0, -1.0, 1.0).unwrap();
    assert_eq!(r, 2.0);
    assert!(evals.get() <= 3, "{} evaluations", evals.get());
}

#[test]
fn newton_stops_when_two_corrections_bound_the_rest_within_the_noise() {
    // cos from the secant's start on [1, 2]: the contraction rule saves the evaluation that
    // would only confirm the root, and the root is still within the noise (8 ulps).
    let evals = std::cell::Cell::new(0);
    let f = |t: f64| {
        evals.set(evals.get() + 1);
        Some((t.cos(), -t.sin()))
    };
    let r = newton_in_bracket(f, 1.0, 2.0, 1f64.cos(), 2f64.cos()).unwrap();
    let half_pi = std::f64::consts::FRAC_PI_2;
    assert!((r - half_pi).abs() <= 8.0 * f64::EPSILON * 2.0, "{r}");
    // Secant start, then corrections 7e-3, 1e-7, 5e-22: the third (converged by the
    // contraction rule) is not evaluated again, so three evaluations, not four.
    assert_eq!(evals.get(), 3);
    // A linearly contracting iteration (slope 4/3 of the true one: each correction a
    // quarter of the last) may stop by the rule, but only within the noise of the root.
    let g = |t: f64| Some((t - 1.3, 4.0 / 3.0));
    let r = newton_in_bracket(g, 1.0, 2.0, -0.3, 0.7).unwrap();
    assert!((r - 1.3).abs() <= 8.0 * f64::EPSILON * 1.3, "{r}");
}

/// Brent's interpolation is what makes the method fast: on smooth simple roots it
/// converges superlinearly, where bisection alone needs about 52 evaluations to narrow
/// [1, 2] to adjacent floats. The count: the first evaluation (a secant point) is good to
/// a digit or two, inverse quadratic interpolation multiplies the digits by about 1.84 an
/// evaluation (2 → 3.7 → 6.8 → 12.5 → 23: four more for 16 digits), and one step of the
/// tolerance closes the bracket: 6, and 7 allows one spare. Measured: 5-6. An interpolant
/// the safeguard keeps rejecting leaves the root right but falls back to bisection:
/// `(b − a) + (r − 1)` for `(b − a) (r − 1)` takes 21 on the cubic, and a wrong ratio
/// `f_a/f_c` → `f_a · f_c` or `f_a % f_c` (or `f_b/f_c` → `f_b · f_c`) 8-10 (mutation
/// testing: these went unseen under the earlier allowance of 12).
#[test]
fn brent_converges_superlinearly_on_smooth_roots() {
    // (function, bracket, root)
    type Case = (fn(f64) -> f64, f64, f64, f64);
    let cases: [Case; 3] = [
        (f64::cos, 1.0, 2.0, std::f64::consts::FRAC_PI_2),
        (
            |x| x * x * x - 2.0 * x - 5.0,
            2.0,
            3.0,
            2.094_551_481_542_326_6,
        ),
        (|x| x.exp() - 3.0, 1.0, 2.0, 3f64.ln()),
    ];
    for (g, a, b, root) in cases {
        let evals = std::cell::Cell::new(0);
        let f = |x: f64| {
            evals.set(evals.get() + 1);
            g(x)
        };
        let r = brent(f, a, b, g(a), g(b));
        assert!(
            (r - root).abs() <= 4.0 * f64::EPSILON * root,
            "{r} vs {root}"
        );
        assert!(evals.get() <= 7, "{} evaluations for {root}", evals.get());
    }
}

#[test]
fn crossing_needs_the_right_direction() {
    assert!(crosses(Direction::Falling, 1.0, -1.0));
    assert!(!crosses(Direction::Falling, -1.0, 1.0));
    assert!(crosses(Direction::Rising, -1.0, 0.0));
    assert!(!crosses(Direction::Rising, 0.0, 1.0));
}

/// Newton's method in a bracket does not depend on the scale of the event's value: with f and
/// its derivative times a power of two λ every quotient and comparison (the secant start, the
/// correction v/d, rtsafe's test |2v| > |dx_old d|) is the same in f64, so the root and the
/// number of evaluations are identical bit for bit (mutation testing: `dx_old · d` →
/// `dx_old / d` in that test went unseen; it compares a value with a time² over a value, so
/// λ = 2^60 bisects where Newton would do).
#[test]
fn newton_in_a_bracket_does_not_depend_on_the_value_s_scale() {
    // (value and derivative, bracket)
    type Case = (fn(f64) -> (f64, f64), f64, f64);
    let cases: [Case; 3] = [
        (|x| (x.cos(), -x.sin()), 1.0, 2.0),
        (|x| (x * x * x - 2.0 * x - 5.0, 3.0 * x * x - 2.0), 2.0, 3.0),
        (
            |x| ((x - 0.3).tanh(), 1.0 / (x - 0.3).cosh().powi(2)),
            -1.0,
            4.0,
        ),
    ];
    for (g, a, b) in cases {
        let run = |scale: f64| {
            let evals = std::cell::Cell::new(0);
            let f = |x: f64| {
                evals.set(evals.get() + 1);
                let (v, d) = g(x);
                Some((scale * v, scale * d))
            };
            let r = newton_in_bracket(f, a, b, scale * g(a).0, scale * g(b).0).unwrap();
            (r, evals.get())
        };
        let unit = run(1.0);
        for scale in [2f64.powi(-60), 2f64.powi(60)] {
            assert_eq!(run(scale), unit, "[{a}, {b}] at a scale {scale:e}");
        }
    }
}

/// Nothing in the root finder assumes positive times: a bracket across t = 0, [−3, 1], holds
/// the root of tanh t + 1/2 at −atanh(1/2) (closed form), found to the noise (8 ulps). The
/// bracket's width is measured as h − l (mutation testing: h + l, which is negative here, stopped
/// at its first bisection, t = −0.436 for the root −0.549).
#[test]
fn a_bracket_across_zero_time_finds_its_root() {
    let f = |t: f64| Some((t.tanh() + 0.5, 1.0 - t.tanh() * t.tanh()));
    let root = -0.5f64.atanh();
    let r = newton_in_bracket(f, -3.0, 1.0, (-3f64).tanh() + 0.5, 1f64.tanh() + 0.5).unwrap();
    assert!((r - root).abs() <= 8.0 * f64::EPSILON * root.abs(), "{r}");
}

/// A falling crossing is a rising crossing of the negated value, zeros included: arriving at 0
/// is a crossing, leaving it is not (it was counted on arrival). (Mutation testing: Falling's
/// `before > 0` → `before >= 0` counted a value leaving 0 downwards again.)
#[test]
fn falling_is_rising_of_the_negated_value() {
    let values = [-2.0, -0.0, 0.0, 1.5, f64::MIN_POSITIVE];
    for a in values {
        for b in values {
            assert_eq!(
                crosses(Direction::Falling, a, b),
                crosses(Direction::Rising, -a, -b),
                "{a} → {b}"
            );
        }
    }
    assert!(crosses(Direction::Falling, 1.0, 0.0));
    assert!(!crosses(Direction::Falling, 0.0, -1.0));
}

/// The root stays in the bracket even when the secant start rounds past its end. The event
/// k (t − r1)(t − r2) crosses zero at r1, inside the bracket [0, b], and again at r2 one ulp
/// past b: the value at b is then 1e-19 of the value at 0, (b − 0) fa/(fb − fa) rounds up by
/// an ulp and the secant lands on r2 itself. The start must then be an end of the bracket, as
/// for any secant not strictly inside it; taken as it is (mutation testing: `&&` → `||` in
/// the start's test), the value there is exactly 0 and r2, outside the bracket and 6.5e-3
/// after the crossing, was returned. Newton's steps from b head for r2 too, and are refused
/// as outside, so the answer is r1 to the iteration's noise (8 ulps).
#[test]
fn a_secant_start_past_the_bracket_is_not_taken() {
    // Found by a search over random brackets of this shape (f64 arithmetic as here).
    let (b, r1, k) = (
        0.895_717_908_424_955_4,
        0.889_211_112_921_108,
        6.070_788_974_335_778,
    );
    let r2 = b + f64::EPSILON * 0.5; // the next float after b (b in [0.5, 1))
    assert!(r2 > b && (r2 - b) == f64::EPSILON * 0.5);
    let f = |t: f64| k * (t - r1) * (t - r2);
    let (fa, fb) = (f(0.0), f(b));
    let secant = -fa * (b / (fb - fa));
    assert_eq!(
        secant, r2,
        "the case: the secant rounds onto the root past b"
    );
    let event = |t: f64| Some((f(t), k * ((t - r1) + (t - r2))));
    let root = newton_in_bracket(event, 0.0, b, fa, fb).expect("a root");
    assert!(
        (root - r1).abs() <= 8.0 * f64::EPSILON * r1,
        "{root} against the crossing in the bracket, {r1}"
    );
}

/// The contraction rule at work: t² − 2 on [1, 2] from the secant's start 4/3. Newton's
/// corrections there are 8.3e-2, 2.5e-3, 2.1e-6, then c = 1.6e-12 with 2c² = 5e-24 within
/// noise × c_prev = 8 ε √2 × 2.1e-6 = 5e-21 (the error after a Newton step is
/// f''/(2f') c² = 0.35 c²), so `newton` is taken without a fifth evaluation to confirm it:
/// four evaluations, and √2 to the noise. Mutation testing: the rule's bracket test
/// `newton ≤ h` → `newton > h` went unseen (the evaluation it saves was spent; the cos case
/// above stops on the noise test before the rule applies).
#[test]
fn the_contraction_rule_saves_the_confirming_evaluation() {
    let evals = std::cell::Cell::new(0);
    let f = |t: f64| {
        evals.set(evals.get() + 1);
        Some((t * t - 2.0, 2.0 * t))
    };
    let r = newton_in_bracket(f, 1.0, 2.0, -1.0, 2.0).unwrap();
    let root = std::f64::consts::SQRT_2;
    assert!((r - root).abs() <= 8.0 * f64::EPSILON * root, "{r}");
    assert_eq!(evals.get(), 4);
}

/// The contraction rule stops only within the noise when Newton contracts linearly: with
/// the slope of t³ − 2 reported 1.5 times too steep each correction is about a third of the
/// last (r = 1/3), the rest of the way is r c/(1 − r) = c/2, and the rule's 2c² ≤ noise ·
/// c_prev = 3c noise stops at c ≤ 1.5 noise: the root within the noise, as a slope k times
/// too steep allows k times the noise (16 ε here). A rule loosened to `noise / c_prev` stops
/// 1.4e-6 from the root (tried by hand); the mutants of shards 79-86 made the rule stricter
/// and are caught by the count above.
#[test]
fn the_contraction_rule_stops_within_the_noise_on_a_linear_contraction() {
    let f = |t: f64| Some((t * t * t - 2.0, 1.5 * 3.0 * t * t));
    let r = newton_in_bracket(f, 1.0, 2.0, -1.0, 6.0).unwrap();
    let root = 2f64.cbrt();
    assert!(
        (r - root).abs() <= 16.0 * f64::EPSILON * root,
        "{r} against {root}"
    );
}
