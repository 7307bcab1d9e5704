//! Tests of `sliding_ladder::scalar::modp` (src/scalar/modp.rs).

use num_traits::Zero;
use sliding_ladder::scalar::modp::{Modp, MODULUS};
use sliding_ladder::scalar::Rational;
use sliding_ladder::scalar::Scalar;

fn reduce(q: &Rational) -> Modp {
    Modp::of_rational(q)
}

/// The same generic expression in rationals, reduced mod p, and in `Modp` agree (the
/// homomorphism every modular point relies on), including a derivative through `Jet`.
#[test]
fn agrees_with_reduced_rationals() {
    fn expr<S: Scalar>(t: S, m: S) -> S {
        let one = S::int(1);
        let den = one.clone() + t.clone() * t.clone();
        let sin = S::int(2) * t.clone() / den.clone();
        let d = S::lift(sin, S::int(3));
        let q = d.clone() * d.clone() / (S::lift(m, S::int(-7)) + S::constant(S::ratio(3, 4)));
        let (re, eps) = S::split(q);
        re * S::int(5) - eps / S::int(1 << 40)
    }
    let (t, m) = (987_654_321_987_654_321_i64, -(1_i64 << 59) + 17);
    let exact = expr(Rational::int(t), Rational::int(m));
    let modular = expr(Modp::int(t), Modp::int(m));
    assert_eq!(reduce(&exact), modular);
    // A changed input changes the residue: the comparison can fail.
    assert_ne!(reduce(&exact), expr(Modp::int(t + 1), Modp::int(m)));
}

#[test]
fn field_laws_at_the_edges() {
    let big = Modp::of(-1);
    assert_eq!(big.residue(), Some(MODULUS - 1));
    assert_eq!(big * big, Modp::int(1));
    assert_eq!(Modp::of(i64::MIN) + Modp::of(i64::MAX), Modp::of(-1));
    let x = Modp::int(123_456_789);
    assert_eq!(x / x, Modp::int(1));
    assert_eq!((x / Modp::int(7)) * Modp::int(7), x);
    assert_ne!(x / Modp::int(7), x / Modp::int(8));
    assert_eq!(Modp::int(2).pow(61), Modp::int(1));
    assert_eq!(
        reduce(&Rational::ratio(-3, 4)) * Modp::int(4),
        Modp::int(-3)
    );
    assert!(!reduce(&Rational::ratio(1, MODULUS as i64)).is_defined());
}

#[test]
fn division_by_zero_is_undefined_and_stays_so() {
    let x = Modp::int(5);
    let bad = x / Modp::of(MODULUS as i64);
    assert!(!bad.is_defined());
    for y in [bad + x, x - bad, bad * x, x / bad, -bad] {
        assert!(!y.is_defined());
        assert!(!y.is_zero());
    }
    assert!((x - x).is_zero() && (x - x).is_defined());
}

/// Zero is the residue 0, and a residue has no real value: `to_f64` is NaN, never a number a
/// float check could mistake for a value.
#[test]
fn modp_zero_is_the_residue_zero_and_has_no_float_value() {
    assert_eq!(Modp::zero(), Modp::of(0));
    assert!(Modp::zero().is_zero() && !Modp::int(1).is_zero());
    assert_eq!(Modp::zero() + Modp::int(5), Modp::int(5));
    assert!(Modp::int(3).to_f64().is_nan());
}
