//! Every torque analysis of the note, solved for θ̈, gives the equation of motion (5): the five
//! points A-E as printed and as built from first principles, Jensen's five methods about C, and
//! Lagrange's equation by automatic differentiation. Exact arithmetic: the residual is zero.

use rstest::rstest;
use sliding_ladder::ladder::analysis::{
    solve_angular_acceleration, AngularMomentum, Reference, ReferencePoint,
};
use sliding_ladder::ladder::energy::{
    angular_acceleration, lagrange_residual, NoteLagrangian, ParticleLagrangian,
};
use sliding_ladder::ladder::geometry::Corner;
use sliding_ladder::ladder::jensen::eq53_method_one_c;
use sliding_ladder::ladder::torque::*;
use sliding_ladder::ladder::{solve_for_accel, Ladder, State};
use sliding_ladder::scalar::{Rational, Scalar};
use sliding_ladder::system::rate;

type Q = Rational;

/// A ladder at sin θ = 2t/(1+t²), cos θ = (1−t²)/(1+t²) with m = 3, l = 5/2, g = 49/5, θ̇ = −7/4
/// (θ̈ is what is solved for).
fn state(t: (i64, i64)) -> (Ladder<Q>, State<Q>) {
    let t = Q::ratio(t.0, t.1);
    let den = Q::int(1) + t.clone() * t.clone();
    let st = State {
        sin: Q::int(2) * t.clone() / den.clone(),
        cos: (Q::int(1) - t.clone() * t) / den,
        rate: Q::ratio(-7, 4),
        accel: Q::int(0),
        jerk: Q::int(1),
    };
    (
        Ladder {
            m: Q::int(3),
            l: Q::ratio(5, 2),
            g: Q::ratio(49, 5),
        },
        st,
    )
}

/// The note's analysis about a point: d/dt of its printed angular momentum minus its printed
/// torque side (the second form of each display), as a function of θ̈.
fn printed_residual(k: Corner, l: &Ladder<Q>, s: &State<Q>) -> Q {
    let (lc, sl) = (l.constant(), s.along_motion());
    match k {
        Corner::A => {
            rate::<Q>(angular_momentum_about_a(&lc, &sl)) - eq16_torque_analysis_a(l, s)[1].clone()
        }
        Corner::B => {
            rate::<Q>(angular_momentum_about_b(&lc, &sl)) - eq19_torque_analysis_b(l, s)[1].clone()
        }
        Corner::C => {
            rate::<Q>(eq21_angular_momentum_about_c(&lc, &sl)[1].clone())
                - eq22_torque_analysis_c(l, s)[1].clone()
        }
        Corner::D => {
            rate::<Q>(eq24_angular_momentum_about_d(&lc, &sl)[1].clone())
                - eq25_torque_analysis_d(l, s)[1].clone()
        }
        // The second printed form of (28) is misprinted; the third form is the torque side.
        Corner::E => {
            rate::<Q>(eq27_angular_momentum_about_e(&lc, &sl)[1].clone())
                - eq28_torque_analysis_e(l, s)[2].clone()
        }
    }
}

#[rstest]
fn printed_analysis_gives_the_equation_of_motion(
    #[values(Corner::A, Corner::B, Corner::C, Corner::D, Corner::E)] k: Corner,
    #[values((1, 3), (2, 5), (-7, 11))] t: (i64, i64),
) {
    let (l, s) = state(t);
    let solved = solve_for_accel(&l, &s, |x| printed_residual(k, &l, x));
    assert_eq!(solved, angular_acceleration(&l, &s), "about {}", k.name());
    // ... and the same display off the motion does not balance.
    let off = s.with_accel(angular_acceleration(&l, &s) + Q::ratio(1, 1000));
    assert_ne!(
        printed_residual(k, &l, &off),
        Q::int(0),
        "about {} off shell",
        k.name()
    );
}

#[rstest]
fn first_principles_analysis_gives_the_equation_of_motion(
    #[values(Corner::A, Corner::B, Corner::C, Corner::D, Corner::E)] k: Corner,
    #[values(AngularMomentum::Absolute, AngularMomentum::Relative)] def: AngularMomentum,
    #[values((1, 3), (-7, 11))] t: (i64, i64),
) {
    let (l, s) = state(t);
    assert_eq!(
        solve_angular_acceleration(&Reference::Corner(k), def, &l, &s),
        angular_acceleration(&l, &s)
    );
}

/// Jensen's methods about the contact point C (Appendix A): 1 and 2 use L_P (37) with (38), for
/// P on the wall or on the ladder; 3 and 4 use L'_P (39) with (40); 5 (Hu) freezes P where C is
/// now and uses (56).
#[rstest]
#[case::method_1(1)]
#[case::method_2(2)]
#[case::method_3(3)]
#[case::method_4(4)]
#[case::method_5(5)]
fn jensen_methods_at_c_give_the_equation_of_motion(#[case] method: u8) {
    // t = 1/2: cos θ = 3/5, so C is at (0, 6l/5) = (0, 3) for l = 5/2.
    let (l, s) = state((1, 2));
    let (reference, def) = match method {
        1 => (Reference::Corner(Corner::C), AngularMomentum::Absolute),
        2 => (Reference::OnLadder(0, 1), AngularMomentum::Absolute),
        3 => (Reference::Corner(Corner::C), AngularMomentum::Relative),
        4 => (Reference::OnLadder(0, 1), AngularMomentum::Relative),
        _ => (Reference::Lab(0, 6, 5), AngularMomentum::Absolute),
    };
    assert_eq!(
        reference.position(&l, &s),
        Reference::Corner(Corner::C).position(&l, &s)
    );
    assert_eq!(
        solve_angular_acceleration(&reference, def, &l, &s),
        angular_acceleration(&l, &s),
        "method {method}"
    );
    if method == 1 {
        // The note's own method-1 display (53) solved for θ̈ agrees too.
        let solved = solve_for_accel(&l, &s, |x| {
            let [lhs, rhs] = eq53_method_one_c(&l, x);
            lhs - rhs
        });
        assert_eq!(solved, angular_acceleration(&l, &s));
    }
}

#[test]
fn lagrange_by_automatic_differentiation_gives_the_equation_of_motion() {
    for t in [(1, 3), (2, 5), (-7, 11)] {
        let (l, s) = state(t);
        let want = angular_acceleration(&l, &s);
        assert_eq!(
            solve_for_accel(&l, &s, |x| lagrange_residual(&NoteLagrangian, &l, x)),
            want
        );
        assert_eq!(
            solve_for_accel(&l, &s, |x| lagrange_residual(&ParticleLagrangian, &l, x)),
            want
        );
        // A Lagrangian with the wrong potential sign would not: the check can fail.
        let wrong = Ladder {
            g: -l.g.clone(),
            ..l.clone()
        };
        assert_ne!(
            solve_for_accel(&wrong, &s, |x| lagrange_residual(
                &NoteLagrangian,
                &wrong,
                x
            )),
            want
        );
    }
}

/// The generic reference points are where their names say: λ = 1/2 on the ladder is B, λ = 1 is
/// D, the combination (C + D)/2 is B, C + D is E, and a lab point scales with l.
#[test]
fn reference_points_are_where_they_say() {
    let (l, s) = state((2, 5));
    let at = |k| Reference::Corner(k).position(&l, &s);
    assert_eq!(Reference::OnLadder(1, 2).position(&l, &s), at(Corner::B));
    assert_eq!(Reference::OnLadder(1, 1).position(&l, &s), at(Corner::D));
    assert_eq!(Reference::OnLadder(0, 1).position(&l, &s), at(Corner::C));
    assert_eq!(
        Reference::Combination([(0, 1), (1, 2), (1, 2), (0, 1)]).position(&l, &s),
        at(Corner::B)
    );
    assert_eq!(
        Reference::Combination([(5, 1), (1, 1), (1, 1), (0, 1)]).position(&l, &s),
        at(Corner::E)
    );
    assert_eq!(
        Reference::Combination([(0, 1), (0, 1), (0, 1), (1, 1)]).position(&l, &s),
        at(Corner::E)
    );
    let lab = Reference::Lab(3, -4, 2).position(&l, &s);
    assert_eq!(
        (lab.x, lab.y),
        (Q::ratio(3, 2) * l.l.clone(), Q::int(-2) * l.l.clone())
    );
}
