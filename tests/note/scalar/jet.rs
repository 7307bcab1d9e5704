//! Tests of `sliding_ladder::scalar::jet` (src/scalar/jet.rs).

use sliding_ladder::scalar::jet::Jet;
use sliding_ladder::scalar::Rational;
use sliding_ladder::scalar::Scalar;

#[test]
fn quotient_rule_is_exact() {
    // d/dx (1/(1+x²)) = -2x/(1+x²)², at x = 3: -6/100.
    let x = Jet::new(Rational::int(3), Rational::int(1));
    let one = Jet::<Rational>::int(1);
    let f = one.clone() / (one + x.clone() * x);
    assert_eq!(f.eps, Rational::ratio(-6, 100));
    assert_ne!(f.eps, Rational::ratio(6, 100));
}
