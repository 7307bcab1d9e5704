//! Tests of `sliding_ladder::sim::fall::observer` (src/sim/fall/observer.rs).

use sliding_ladder::ladder::Ladder;
use sliding_ladder::sim::exact::PhaseOne;
use sliding_ladder::sim::fall::observer::{
    gauss_legendre_5, impulse_pieces, rigid_momentum_x, TraceObserver,
};
use sliding_ladder::sim::floor;
use sliding_ladder::sim::outcome::FloorReport;
use sliding_ladder::sim::rigid;
use sliding_ladder::sim::run::Observer;

/// The wall's impulse over [0, t_s] of the exact motion (m = l = 1, g = 4/3: Ω = 1) by GL5 on
/// steps `c` times the event-safe step long, each in [`impulse_pieces`] pieces when `split`,
/// and its error against m l Δ(cos θ θ̇) (eq. (7): m Ẍ = F_w, an independent reference).
fn impulse_error(theta0: f64, rate0: f64, c: f64, split: bool) -> f64 {
    let ladder = Ladder {
        m: 1.0,
        l: 1.0,
        g: 4.0 / 3.0,
    };
    let exact = PhaseOne::new(theta0, rate0, 1.0).unwrap();
    let ts = exact.separation().unwrap().time;
    let force = |t: f64| {
        let (th, w) = exact.theta_rate(t);
        rigid::wall_force(&ladder, th, w)
    };
    let (mut t, mut j) = (0.0, 0.0);
    while t < ts {
        let t1 = (t + c * rigid::event_safe_step(1.0, exact.rate(t))).min(ts);
        let rate = exact.rate(t).abs().max(exact.rate(t1).abs());
        let n = if split {
            impulse_pieces(1.0, rate, t1 - t)
        } else {
            1
        };
        let h = (t1 - t) / n as f64;
        for i in 0..n {
            let a = t + i as f64 * h;
            j += gauss_legendre_5(force, a, if i + 1 == n { t1 } else { a + h });
        }
        t = t1;
    }
    let (ths, ws) = exact.theta_rate(ts);
    (j - (rigid_momentum_x(ths, ws) - rigid_momentum_x(theta0, rate0))).abs()
}

/// Error model: the impulse (< 1 here) is a sum of ~20 pieces and the reference a difference
/// of two products, each rounded: 16 ulps of 1 cover it. Steps of 3 caps are the Taylor
/// method's longest; 1 cap the other methods'. The same check on whole steps fails by
/// orders of magnitude (it can fail), which is what a Taylor run did before the split.
#[test]
fn the_impulse_quadrature_is_resolved_by_the_motion_not_by_the_step() {
    let bound = 16.0 * f64::EPSILON;
    for (theta0, rate0) in [(0.0, 0.25), (1e-6, 0.0), (0.1, 0.0), (0.3, 0.0), (1.0, 0.0)] {
        for c in [0.5, 1.0, 2.0, 3.0] {
            let e = impulse_error(theta0, rate0, c, true);
            assert!(e <= bound, "θ0 = {theta0}, θ̇0 = {rate0}, {c} caps: {e:e}");
        }
        let whole = impulse_error(theta0, rate0, 3.0, false);
        assert!(whole > 1e3 * bound, "θ0 = {theta0}: {whole:e}");
    }
    // The rule in f64: exact on t⁸ up to the rounding of the nodes (relative U/2 each, 8 U/2
    // in t⁸) and of the sum; on 1 to one ulp (the weights rounded to 15 digits, as they
    // were, summed to 2 − 4 ulps).
    let t8 = gauss_legendre_5(|t| t.powi(8), 0.0, 1.0);
    assert!((t8 - 1.0 / 9.0).abs() <= 8.0 * f64::EPSILON / 9.0, "{t8:e}");
    assert!((gauss_legendre_5(|_| 1.0, 0.0, 2.0) - 2.0).abs() <= f64::EPSILON);
}

/// An observer of the unit-Ω ladder (m = l = 1, g = 4/3) that computes only `impulse` and
/// `monitor`, from the phase start `t0`.
fn observer(t0: f64, impulse: bool, monitor: bool) -> TraceObserver<'static> {
    TraceObserver {
        ladder: Ladder {
            m: 1.0,
            l: 1.0,
            g: 4.0 / 3.0,
        },
        phase: 1,
        trace: None,
        monitor: monitor.then_some(FloorReport {
            floor_force_min: f64::INFINITY,
            top_clearance_min: f64::INFINITY,
        }),
        force_evals: 0,
        phase_start: t0,
        impulse: impulse.then_some(0.0),
    }
}

/// A wall-phase step is split by its own length h into ⌈h (|θ̇| + Ω)/0.25⌉ pieces of five
/// force evaluations, wherever it lies in time (mutation testing: `t1 − t0` → `t1 + t0` went
/// unseen: same impulse, up to 64 pieces). A constant force F integrates to F h up to
/// rounding: GL5's weights sum to 2 within an ulp, and each of the n pieces' ends and the
/// step's end t0 + h are rounded at the size of t: |F| (4 u h + 2 (n + 2) u (|t0| + h)).
#[test]
fn a_wall_step_is_split_by_its_own_length() {
    let (theta, rate) = (0.3, 0.1);
    for (t0, h) in [(0.0, 0.1), (100.0, 0.1), (100.0, 1.0), (1e6, 0.5)] {
        let mut ob = observer(t0, true, false);
        Observer::<2>::step(&mut ob, t0, t0 + h, &|_| [theta, rate]);
        let pieces = (h * (rate + 1.0) / 0.25).ceil() as u64;
        assert_eq!(ob.force_evals, 5 * pieces, "step [{t0}, {t0} + {h}]");
        let want = rigid::wall_force(&ob.ladder, theta, rate) * h;
        let got = ob.impulse.unwrap();
        let u = f64::EPSILON;
        let bound = want.abs() / h * (4.0 * u * h + 2.0 * (pieces + 2) as f64 * u * (t0 + h));
        assert!((got - want).abs() <= bound, "{got} against {want}");
    }
}

/// A step whose length is exactly k pieces of 0.25/(|θ̇| + Ω) is k pieces, and so is one an
/// ulp longer (the length read as a sum of times is rounded); one a millionth of a piece
/// longer is k + 1 (mutation testing: the slack's `− 1e-9` → `+ 1e-9` went unseen: a step
/// of exactly two pieces became three).
#[test]
fn a_step_of_exactly_k_pieces_is_not_split_into_more() {
    for (big_omega, rate, piece) in [(1.0, 0.0, 0.25), (1.0, 1.0, 0.125), (2.0, 2.0, 0.0625)] {
        for k in 2..=5usize {
            let h = piece * k as f64;
            assert_eq!(impulse_pieces(big_omega, rate, h), k, "{h}");
            assert_eq!(impulse_pieces(big_omega, rate, h.next_up()), k, "{h}");
            assert_eq!(impulse_pieces(big_omega, rate, h + 1e-6 * piece), k + 1);
        }
        // However short, a step is one piece (mutation testing: `n.is_finite() && n > 1`
        // → `||` gave a step under 1e-9 of a piece none, dropping its impulse).
        assert_eq!(impulse_pieces(big_omega, rate, 1e-12 * piece), 1);
    }
}

/// The pieces tile the step: on a motion θ = θ0 + w (t − t0) (θ̇ = w) the impulse of
/// F_w = m l sin θ (Ω² cos θ − θ̇²) (eq. (14)) is, in closed form,
/// m l (Ω² (sin²θ1 − sin²θ0)/(2w) − w (cos θ0 − cos θ1)). Pieces of 0.25/(w + Ω) turn θ by
/// under 1/4 rad, where GL5's error (tenth derivative, h¹¹) is below 1e-20: what is left is
/// rounding, of the 5n forces and weights (16 u of |F|max h) and of the pieces' ends at the
/// size of t (2 (n + 2) u (|t0| + h) |F|max), with |F|max ≤ m l (Ω² + w²). (A constant force
/// cannot see the pieces' length: any chain of pieces from t0 to t1 sums to F h. Mutation
/// testing: the piece length (t1 − t0)/n → (t1 − t0) · n and → (t1 − t0) % n went unseen.)
#[test]
fn the_wall_impulse_of_a_turning_ladder_is_its_closed_form() {
    let (theta0, w) = (0.3f64, 0.5f64);
    for (t0, h) in [(0.0, 1.0), (100.0, 1.0), (100.0, 2.5)] {
        let mut ob = observer(t0, true, false);
        let dense = |t: f64| [theta0 + w * (t - t0), w];
        Observer::<2>::step(&mut ob, t0, t0 + h, &dense);
        let theta1 = theta0 + w * h;
        let want = (theta1.sin().powi(2) - theta0.sin().powi(2)) / (2.0 * w)
            - w * (theta0.cos() - theta1.cos());
        let got = ob.impulse.unwrap();
        let n = (h * (w + 1.0) / 0.25).ceil();
        let (u, f_max) = (f64::EPSILON, 1.0 + w * w);
        let bound = f_max * (16.0 * u * h + 2.0 * (n + 2.0) * u * (t0 + h));
        assert!(
            (got - want).abs() <= bound,
            "[{t0}, {t0} + {h}]: {got} against {want}"
        );
    }
}

/// The top clearance is 0 at the floor phase's start by construction, so the first step's
/// minimum is searched after its start, not at its end: a top that dips into the wall by
/// h²/4 within the first step is seen (mutation testing: the search's start `(t1 − t0)/5` →
/// `(t1 − t0) % 5` moved it to the step's end, where the clearance is 0 again). The dip is
/// found to rounding: the golden section's 1e-9 h in t moves a parabola's value by 1e-18 h²,
/// and X − sin θ cancels 0.48 to 0.06: 8 ulps of 1.
#[test]
fn the_first_floor_step_sees_the_top_dip_into_the_wall() {
    let theta = 0.5f64;
    for (t0, h) in [(0.0, 0.5), (3.0, 0.5), (3.0, 2.0)] {
        let t1 = t0 + h;
        let mut ob = observer(t0, false, true);
        let dense = |t: f64| [theta, theta.sin() + (t - t0) * (t - t1), 0.0, 0.0];
        Observer::<4>::step(&mut ob, t0, t1, &dense);
        let got = ob.monitor.unwrap().top_clearance_min;
        let want = -h * h / 4.0;
        assert!(
            (got - want).abs() <= 8.0 * f64::EPSILON,
            "[{t0}, {t1}]: {got} against {want}"
        );
    }
}

/// Each state a monitor sees costs one floor force (with the top's position, which costs
/// none), and `force_evals` counts it: 7 samples, 7 evaluations, with the least force of
/// the 7; without a monitor none. Mutation testing: the count's `+= 1` → `*= 1` went
/// unseen, the run tests bounded the floor phase's count from below only.
#[test]
fn each_monitored_sample_costs_one_floor_force() {
    let states: Vec<[f64; 4]> = (0..7)
        .map(|i| {
            let theta = 0.6 + 0.1 * f64::from(i);
            [theta, theta.sin(), -0.5 - 0.1 * f64::from(i), 0.2]
        })
        .collect();
    for monitor in [true, false] {
        let mut ob = observer(0.0, false, monitor);
        for (i, y) in states.iter().enumerate() {
            Observer::<4>::observe(&mut ob, 0.1 * i as f64, y);
        }
        assert_eq!(ob.force_evals, if monitor { 7 } else { 0 });
        if monitor {
            let least = states
                .iter()
                .map(|y| floor::floor_force(&ob.ladder, y[0], y[2]))
                .fold(f64::INFINITY, f64::min);
            assert_eq!(ob.monitor.unwrap().floor_force_min, least);
        }
    }
}
