//! Tests of `sliding_ladder::scalar`.

mod bound;
mod coeff;
mod degree;
mod dimension;
mod gcd;
mod int;
mod jet;
mod modp;
mod poly;
mod si_unit;
mod sym_factor;
mod sym_print;
mod sym_reading;
mod symbolic;

use num_dual::Dual;
use sliding_ladder::scalar::{Jet, Rational, Scalar};

/// d/dx (x³) at 2 is 12 in every type that has values; the derivative goes through each
/// type's own `Dual`.
fn cube_derivative<S: Scalar>(x: S) -> S {
    let d = S::lift(x, S::int(1));
    S::split(d.clone() * d.clone() * d).1
}

#[test]
fn derivatives_agree_across_types() {
    assert_eq!(cube_derivative(2.0_f64), 12.0);
    assert_eq!(cube_derivative(Rational::int(2)), Rational::int(12));
    assert_eq!(cube_derivative(Jet::<Rational>::int(2)), Jet::int(12));
    assert_eq!(cube_derivative(Dual::<f64>::int(2)).re, 12.0);
    // A wrong power would not give 12.
    assert_ne!(cube_derivative(Rational::int(3)), Rational::int(12));
}

#[test]
fn rational_ratio_is_exact() {
    let third = Rational::ratio(1, 3);
    assert_eq!(third.clone() + third.clone() + third, Rational::int(1));
    assert_ne!(f64::ratio(1, 3) * 3.0 - 1.0, f64::ratio(1, 7));
}

/// `to_f64` reads the value, never the derivative, in each type that carries one: a dual
/// number 2.5 + 7ε and a jet are 2.5 (a derivative type's `to_f64` is reached by no path of the
/// crate itself, so only this test holds it).
#[test]
fn to_f64_reads_the_value_part() {
    assert_eq!(Scalar::to_f64(&Dual::<f64>::new(2.5, 7.0)), 2.5);
    let jet = Rational::lift(Rational::ratio(5, 2), Rational::int(7));
    assert_eq!(Scalar::to_f64(&jet), 2.5);
}
