//! A torque analysis about ANY reference point gives the equation of motion (5), with either
//! angular momentum (L_P with (38), L'_P with (40)): points fixed in the lab, fixed on the ladder
//! at a fraction λ, and combinations of the corners A, C, D, E. Exactly, and in floats within the
//! running error bound.

use proptest::prelude::*;
use sliding_ladder::ladder::analysis::{solve_angular_acceleration, AngularMomentum, Reference};
use sliding_ladder::ladder::energy::angular_acceleration;
use sliding_ladder::registry::check::TOLERANCE_FACTOR;
use sliding_ladder::registry::sample::{exact_ladder, LadderSample};
use sliding_ladder::scalar::{Bound, Rational, Scalar, UNIT_ROUNDOFF};

fn reference() -> impl Strategy<Value = Reference> {
    let small = -50i64..=50;
    let den = 1i64..=20;
    prop_oneof![
        (small.clone(), small.clone(), den.clone()).prop_map(|(x, y, d)| Reference::Lab(x, y, d)),
        (small.clone(), den.clone()).prop_map(|(n, d)| Reference::OnLadder(n, d)),
        prop::array::uniform4((small, den)).prop_map(Reference::Combination),
    ]
}

fn definition() -> impl Strategy<Value = AngularMomentum> {
    prop_oneof![
        Just(AngularMomentum::Absolute),
        Just(AngularMomentum::Relative)
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(crate::common::cases(64)))]

    #[test]
    fn exactly_for_any_point(p in reference(), def in definition(), ints in crate::common::exact_ladder_ints()) {
        let (l, s) = exact_ladder(LadderSample::Kinematic, ints.map(Rational::int));
        prop_assert_eq!(solve_angular_acceleration(&p, def, &l, &s), angular_acceleration(&l, &s), "{:?} {:?}", p, def);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(crate::common::cases(1000)))]

    #[test]
    fn in_floats_for_any_point(p in reference(), def in definition(), raw in crate::common::raw_ladder()) {
        let ((l, s), (lb, sb)) = raw.build(LadderSample::Kinematic);
        let solved = solve_angular_acceleration(&p, def, &l, &s);
        let want = angular_acceleration(&l, &s);
        let (solved_b, want_b): (Bound, Bound) = (solve_angular_acceleration(&p, def, &lb, &sb), angular_acceleration(&lb, &sb));
        let tol = TOLERANCE_FACTOR * UNIT_ROUNDOFF * (solved_b.e + want_b.e);
        prop_assert!((solved - want).abs() <= tol, "{:?} {:?}: {} vs {} (tolerance {:e})", p, def, solved, want, tol);
    }
}

#[test]
fn a_wrong_torque_is_caught_for_any_point() {
    // Dropping the velocity term of (38) (treating L_P as if P were at rest) gives a wrong θ̈ for
    // a moving point: the analysis is not vacuous.
    use sliding_ladder::ladder::analysis::{torque_equation, ReferencePoint};
    use sliding_ladder::ladder::solve_for_accel;
    let (l, s) = exact_ladder(
        LadderSample::Kinematic,
        [3, 7, 2, 11, -5, 13, 4].map(Rational::int),
    );
    let p = Reference::OnLadder(1, 3);
    let v_p = p.motion(&l, &s).v;
    assert_ne!(
        v_p.x.clone() * v_p.x.clone() + v_p.y.clone() * v_p.y,
        Rational::int(0)
    );
    let naive = solve_for_accel(&l, &s, |x| {
        let (lhs, rhs) = torque_equation(&p, AngularMomentum::Absolute, &l, x);
        let sys = sliding_ladder::ladder::particles::as_system(&l, x);
        let m = sys.total_mass();
        let extra = sys.cm_velocity().scale(&m).cross(&p.motion(&l, x).v).z;
        lhs - (rhs - extra)
    });
    assert_ne!(naive, angular_acceleration(&l, &s));
}
