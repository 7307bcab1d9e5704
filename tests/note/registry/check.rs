//! Tests of `sliding_ladder::registry::check` (src/registry/check.rs).

use sliding_ladder::registry::check::{run_check, Config};
use sliding_ladder::registry::{equations, extensions, Equation, Eval};

/// Every check of every display (the note's and those beyond it) evaluates as many float states and exact points as it
/// reports, and as the configuration asks; with no exact point its Schwartz-Zippel bound is 1
/// (no evidence), with one it is below 1. A check that evaluated nothing could never fail, and
/// its report must not say otherwise (mutation shard registry 3/40 emptied the floor-phase
/// runner and every verdict stood).
#[test]
fn run_check_evaluates_every_state_it_reports() {
    let some = Config {
        float_cases: 2,
        exact_points: 1,
        seed: 5,
    };
    let none = Config {
        float_cases: 0,
        exact_points: 0,
        seed: 5,
    };
    // The note's displays and those beyond it (the floor phase's are there).
    let all: Vec<Equation> = equations().into_iter().chain(extensions()).collect();
    let (mut ladder, mut floor, mut particles) = (0, 0, 0);
    for e in &all {
        for c in &e.checks {
            let r = run_check(c, &some);
            assert_eq!(
                (r.float_cases, r.exact_points),
                (2, 1),
                "({}) {}",
                e.number,
                c.name
            );
            assert!(
                r.sz_bound < 1.0 && r.sz_bound_log10 < 0.0,
                "({}) {}",
                e.number,
                c.name
            );
            match c.eval {
                Eval::Ladder(..) => ladder += 1,
                Eval::Floor(..) => floor += 1,
                Eval::Particles(..) => particles += 1,
            }
        }
    }
    // All three runners were exercised.
    assert!(
        ladder > 0 && floor > 0 && particles > 0,
        "{ladder} {floor} {particles}"
    );
    let floor_check = all
        .iter()
        .flat_map(|e| &e.checks)
        .find(|c| matches!(c.eval, Eval::Floor(..)))
        .expect("a floor-phase check");
    let r = run_check(floor_check, &none);
    assert_eq!((r.float_cases, r.exact_points), (0, 0));
    assert_eq!((r.sz_bound, r.sz_bound_log10), (1.0, 0.0));
}

/// A float state whose sides differ by more than 4 of their error bounds fails, and so does one
/// whose value is NaN; sides equal, or within the bound, pass. The worst residual and its side
/// are kept across states.
#[test]
fn record_float_fails_a_state_beyond_tolerance_or_not_a_number() {
    use sliding_ladder::registry::check::{record_float, CheckReport, TOLERANCE_FACTOR};
    use sliding_ladder::registry::printed;
    use sliding_ladder::scalar::bound::{Bound, UNIT_ROUNDOFF};
    // Two sides a and b, each with an error bound of one unit of roundoff: tolerance 2u.
    let state = |a: f64, b: f64| {
        (
            vec![vec![printed("a", a), printed("b", b)]],
            vec![vec![
                printed("a", Bound::inexact(a, 1.0)),
                printed("b", Bound::inexact(b, 1.0)),
            ]],
        )
    };
    let mut rep = CheckReport::default();
    // 4u apart: half the tolerance of 4 × 2u.
    let within = 1.0 + TOLERANCE_FACTOR * UNIT_ROUNDOFF;
    for (a, b) in [(1.0, 1.0), (1.0, within)] {
        let (v, e) = state(a, b);
        record_float(&mut rep, v, e);
    }
    assert_eq!((rep.float_cases, rep.float_failures), (2, 0));
    // 4u over u·(1 + (1 + 4u)): 2 less a few ulps.
    assert!((rep.max_scaled_residual - 2.0).abs() <= 4.0 * f64::EPSILON);
    let (v, e) = state(1.0, 1.0 + 1e-9);
    record_float(&mut rep, v, e);
    assert_eq!((rep.float_cases, rep.float_failures), (3, 1));
    assert!(rep.max_scaled_residual > 1e6);
    assert_eq!(rep.worst_side, "b");
    let (v, e) = state(1.0, f64::NAN);
    record_float(&mut rep, v, e);
    assert_eq!((rep.float_cases, rep.float_failures), (4, 2));
    assert!(!rep.max_scaled_residual.is_finite());
}

/// The Schwartz-Zippel bounds of a check (Config of 3 exact points): (d/N)³ over all points,
/// and over the rational points alone (the first `RATIONAL_POINTS` of them) (d/N)^k, with d the
/// residual's degree and N the sample set's size.
#[test]
fn run_check_bounds_over_all_points_and_over_the_rational_ones() {
    use sliding_ladder::registry::check::{EXACT_SET_SIZE, RATIONAL_POINTS};
    let cfg = Config {
        float_cases: 1,
        exact_points: 3,
        seed: 8,
    };
    let e = equations()
        .into_iter()
        .find(|e| e.number == 12)
        .expect("(12)");
    let r = run_check(&e.checks[0], &cfg);
    let p = f64::from(r.degree.max(1)) / EXACT_SET_SIZE;
    assert!(p > 0.0 && p < 1e-6, "{p}");
    let rational = RATIONAL_POINTS.min(3) as i32;
    // Error model: k·log10(p) against log10(pᵏ), a few roundings of numbers below 100 in
    // magnitude (16 ulps of the value); the bound itself, a few roundings of its relative size.
    let close = |a: f64, b: f64| (a - b).abs() <= 16.0 * f64::EPSILON * b.abs().max(1.0);
    assert!(close(r.sz_bound / p.powi(3), 1.0), "{}", r.sz_bound);
    assert!(close(r.sz_bound_log10, p.powi(3).log10()));
    assert!(
        close(r.sz_bound_rational_log10, p.powi(rational).log10()),
        "{} against {}",
        r.sz_bound_rational_log10,
        p.powi(rational).log10()
    );
}

/// Chains of powers of θ̇, one of the kinematic sample's seven random coordinates (a polynomial
/// of degree one there), so a side's degree bound is its largest exponent: `Degree` assumes no
/// cancellation, so θ̇ + (θ̇³ − θ̇³) is θ̇ with a bound of 3.
mod rate_powers {
    use sliding_ladder::ladder::{Ladder, State};
    use sliding_ladder::registry::{printed, reference, Chain, Side};
    use sliding_ladder::scalar::Scalar;

    fn pow<S: Scalar>(s: &State<S>, k: u32) -> S {
        (0..k).fold(S::int(1), |p, _| p * s.rate.clone())
    }
    /// θ̇ + (θ̇ᵏ − θ̇ᵏ): θ̇ in value, degree k in the bound.
    fn padded<S: Scalar>(s: &State<S>, k: u32) -> Side<S> {
        reference("θ̇ padded", pow(s, 1) + (pow(s, k) - pow(s, k)))
    }
    /// θ̇² = θ̇² and θ̇⁵ = θ̇⁵: the largest is the second chain's, 5.
    pub fn two_chains<S: Scalar>(_: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
        vec![
            vec![printed("θ̇²", pow(s, 2)), reference("θ̇²", pow(s, 2))],
            vec![printed("θ̇⁵", pow(s, 5)), reference("θ̇⁵", pow(s, 5))],
        ]
    }
    /// θ̇ = θ̇ = θ̇ + (θ̇³ − θ̇³): a later side carries the degree, 3.
    pub fn late_side<S: Scalar>(_: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
        vec![vec![
            printed("θ̇", pow(s, 1)),
            reference("θ̇", pow(s, 1)),
            padded(s, 3),
        ]]
    }
    /// p = 0 with p = 2⁶¹ − 1: false in rationals, true modulo p.
    pub fn multiple_of_p<S: Scalar>(_: &Ladder<S>, _: &State<S>) -> Vec<Chain<S>> {
        vec![vec![
            printed("p", S::int(p_as_int())),
            reference("0", S::int(0)),
        ]]
    }
    /// 0 with a misprint p (p = 2⁶¹ − 1): the misprint is wrong in rationals and agrees modulo p.
    pub fn misprint_multiple_of_p<S: Scalar>(_: &Ladder<S>, _: &State<S>) -> Vec<Chain<S>> {
        vec![vec![
            reference("0", S::int(0)),
            sliding_ladder::registry::misprint("p", S::int(p_as_int())),
        ]]
    }
    /// θ̇ + (θ̇³ − θ̇³) = θ̇ + (1/θ̇ − 1/θ̇): the second side's denominator θ̇² multiplies the
    /// first's numerator in the difference, degree 3 + 2 = 5 (and θ̇² · θ̇ over θ̇², 3, the
    /// other way).
    pub fn side_with_denominator<S: Scalar>(_: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
        let over = S::int(1) / pow(s, 1);
        vec![vec![
            padded(s, 3),
            reference("θ̇ + (1/θ̇ − 1/θ̇)", pow(s, 1) + (over.clone() - over)),
        ]]
    }
    /// The prime of the modular points, p = 2⁶¹ − 1, as an integer of the scalars.
    fn p_as_int() -> i64 {
        i64::try_from(sliding_ladder::scalar::MODULUS).expect("p < 2⁶³")
    }
    /// θ̇ + (θ̇⁴ − θ̇⁴) = θ̇ = θ̇: the first side carries it, 4.
    pub fn first_side<S: Scalar>(_: &Ladder<S>, s: &State<S>) -> Vec<Chain<S>> {
        vec![vec![
            padded(s, 4),
            reference("θ̇", pow(s, 1)),
            reference("θ̇", pow(s, 1)),
        ]]
    }
}

/// The degree a check reports, which its Schwartz-Zippel bound rests on, is the largest degree
/// of any side's difference from its chain's first side, over every chain: planted chains of
/// powers of θ̇ (degree one in the exact draws) give 5, 3, 4 and 5, worked out by hand from the
/// exponents and the rules of `Degree`. A degree that took the smallest chain, or only the first sides, would understate
/// the chance that a false identity passes.
#[test]
fn run_check_degree_is_the_largest_of_any_sides_difference() {
    use sliding_ladder::registry::sample::LadderSample;
    use sliding_ladder::registry::Check;
    let cfg = Config {
        float_cases: 1,
        exact_points: 1,
        seed: 3,
    };
    let cases = [
        (
            "two chains",
            sliding_ladder::ladder_fns!(rate_powers::two_chains),
            5,
        ),
        (
            "late side",
            sliding_ladder::ladder_fns!(rate_powers::late_side),
            3,
        ),
        (
            "first side",
            sliding_ladder::ladder_fns!(rate_powers::first_side),
            4,
        ),
        (
            "side with a denominator",
            sliding_ladder::ladder_fns!(rate_powers::side_with_denominator),
            5,
        ),
    ];
    for (name, f, degree) in cases {
        let check = Check {
            name,
            eval: Eval::Ladder(LadderSample::Kinematic, f),
        };
        let r = run_check(&check, &cfg);
        assert_eq!(r.degree, degree, "{name}");
        // The planted chains are identities: the degree is all that differs between them.
        assert_eq!((r.float_failures, r.exact_failures), (0, 0), "{name}");
    }
}

/// Planted floor-phase chains: Ẍ = 0, which holds on the floor's motion ((P2): no horizontal
/// force) and not off it, and X = X, which holds anywhere.
mod floor_planted {
    use sliding_ladder::ladder::floor_phase::Slide;
    use sliding_ladder::ladder::{Ladder, State};
    use sliding_ladder::registry::{printed, reference, Chain};
    use sliding_ladder::scalar::Scalar;

    pub fn needs_the_law<S: Scalar>(_: &Ladder<S>, _: &State<S>, x: &Slide<S>) -> Vec<Chain<S>> {
        vec![vec![
            printed("Ẍ", x.accel.clone()),
            reference("0", S::int(0)),
        ]]
    }
    pub fn any_motion<S: Scalar>(_: &Ladder<S>, _: &State<S>, x: &Slide<S>) -> Vec<Chain<S>> {
        vec![vec![printed("X", x.x.clone()), reference("X", x.x.clone())]]
    }
    pub fn off_by_one<S: Scalar>(_: &Ladder<S>, _: &State<S>, x: &Slide<S>) -> Vec<Chain<S>> {
        vec![vec![
            printed("X + 1", x.x.clone() + S::int(1)),
            reference("X", x.x.clone()),
        ]]
    }
}

/// An on-shell check of the floor phase is re-run off the motion, where it must fail: Ẍ = 0
/// holds on the motion and fails off it (off_shell_fails = true); X = X holds off it too, and
/// the report says so (false), which `ladder verify` flags. A kinematic floor check is not
/// re-run (None).
#[test]
fn run_check_of_the_floor_phase_tells_a_check_that_needs_the_law() {
    use sliding_ladder::registry::sample::LadderSample;
    use sliding_ladder::registry::Check;
    let cfg = Config {
        float_cases: 3,
        exact_points: 3,
        seed: 6,
    };
    let run = |sort, f| {
        run_check(
            &Check {
                name: "planted floor check",
                eval: Eval::Floor(sort, f),
            },
            &cfg,
        )
    };
    let law = run(
        LadderSample::OnShell,
        sliding_ladder::floor_fns!(floor_planted::needs_the_law),
    );
    assert!(law.passed(), "{law:?}");
    assert_eq!(law.off_shell_fails, Some(true));
    let any = run(
        LadderSample::OnShell,
        sliding_ladder::floor_fns!(floor_planted::any_motion),
    );
    assert_eq!((any.float_failures, any.exact_failures), (0, 0));
    assert_eq!(any.off_shell_fails, Some(false));
    let kinematic = run(
        LadderSample::Kinematic,
        sliding_ladder::floor_fns!(floor_planted::any_motion),
    );
    assert_eq!(kinematic.off_shell_fails, None);
}

/// `float_residual` maps a side that is not a number to an infinite residual (so a NaN, an
/// overflow, or a difference with no error bound to scale it fails and prints as ∞), an exact
/// agreement to 0, and otherwise scales the difference by u·(e_a + e_b).
#[test]
fn float_residual_scales_a_difference_and_makes_a_non_number_infinite() {
    use sliding_ladder::registry::check::float_residual;
    use sliding_ladder::registry::{printed, reference};
    use sliding_ladder::scalar::{Bound, UNIT_ROUNDOFF};
    let run = |a: f64, b: f64, e: f64| {
        float_residual(
            &[vec![printed("a", a), reference("b", b)]],
            &[vec![
                printed("a", Bound { v: a, e }),
                reference("b", Bound { v: b, e }),
            ]],
        )
    };
    assert_eq!(run(f64::NAN, 1.0, 1.0), (f64::INFINITY, "b"));
    assert_eq!(run(1.0, f64::NAN, 1.0), (f64::INFINITY, "b"));
    assert_eq!(run(f64::INFINITY, 1.0, 1.0), (f64::INFINITY, "b"));
    assert_eq!(run(1.0, 1.0 + f64::EPSILON, 0.0), (f64::INFINITY, "b"));
    assert_eq!(run(3.0, 3.0, 0.0), (0.0, ""));
    // |1 − (1 + ε)| / (u (1 + 1)) = ε / (2u) = 1: one ulp against two half-ulp bounds.
    assert_eq!(
        run(1.0, 1.0 + f64::EPSILON, 1.0).0,
        f64::EPSILON / (2.0 * UNIT_ROUNDOFF)
    );
}

/// A floor-phase check that fails counts every exact point it fails at (and every float state):
/// X = X + 1 planted, 3 of 3 of each.
#[test]
fn run_check_of_the_floor_phase_counts_its_failures() {
    use sliding_ladder::registry::sample::LadderSample;
    let r = run_planted(
        Eval::Floor(
            LadderSample::Kinematic,
            sliding_ladder::floor_fns!(floor_planted::off_by_one),
        ),
        3,
    );
    assert_eq!((r.float_failures, r.exact_failures), (3, 3), "{r:?}");
    assert!(!r.passed());
}

/// A value that is a multiple of p = 2⁶¹ − 1 is zero modulo p: only the rational points see it.
/// With three exact points, the first in rationals and the rest modulo p ([`RATIONAL_POINTS`]
/// = 1), the planted p = 0 fails at exactly one point.
#[test]
fn run_check_takes_its_first_points_in_rationals_and_the_rest_modulo_p() {
    use sliding_ladder::registry::check::RATIONAL_POINTS;
    use sliding_ladder::registry::sample::LadderSample;
    assert_eq!(RATIONAL_POINTS, 1);
    let r = run_planted(
        Eval::Ladder(
            LadderSample::Kinematic,
            sliding_ladder::ladder_fns!(rate_powers::multiple_of_p),
        ),
        0,
    );
    assert_eq!((r.exact_points, r.exact_failures), (3, 1), "{r:?}");
}

/// A misprint is shown wrong only if it differs from the true side at every exact point: the
/// planted misprint p of 0 differs at the rational point and agrees at the two modulo p, so it is
/// not shown wrong and the check fails.
#[test]
fn run_check_shows_a_misprint_wrong_only_where_it_differs_at_every_exact_point() {
    use sliding_ladder::registry::sample::LadderSample;
    let r = run_planted(
        Eval::Ladder(
            LadderSample::Kinematic,
            sliding_ladder::ladder_fns!(rate_powers::misprint_multiple_of_p),
        ),
        0,
    );
    assert_eq!((r.exact_points, r.exact_failures), (3, 0), "{r:?}");
    assert_eq!(r.misprints, vec![("p", false)], "{r:?}");
    assert!(!r.passed());
}

/// A planted check run with `float_cases` float states and three exact points.
fn run_planted(eval: Eval, float_cases: usize) -> sliding_ladder::registry::check::CheckReport {
    let cfg = Config {
        float_cases,
        exact_points: 3,
        seed: 6,
    };
    run_check(
        &sliding_ladder::registry::Check {
            name: "planted",
            eval,
        },
        &cfg,
    )
}
