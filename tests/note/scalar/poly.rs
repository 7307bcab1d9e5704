//! Tests of `sliding_ladder::scalar::poly` (src/scalar/poly.rs).

use sliding_ladder::scalar::poly::{var, Poly, C, S};
use sliding_ladder::scalar::Coeff;

fn int(n: i64) -> Poly {
    Poly::constant(Coeff::int(n))
}

#[test]
fn circle_relation_reduces_to_zero() {
    let (s, c) = (Poly::var(S), Poly::var(C));
    let r = &(&(&s * &s) + &(&c * &c)) - &int(1);
    assert!(r.is_zero(), "{r:?}");
    // c⁴ − (1 − s²)² is zero too; c³ is not (it is c − s² c).
    let c2 = &c * &c;
    let one_minus = &int(1) - &(&s * &s);
    assert!((&(&c2 * &c2) - &(&one_minus * &one_minus)).is_zero());
    let c3 = &c2 * &c;
    assert_eq!(c3, &c - &(&(&s * &s) * &c));
    // A planted false identity: s² + c² = 2 does not reduce to zero.
    let wrong = &(&(&s * &s) + &(&c * &c)) - &int(2);
    assert!(!wrong.is_zero());
    assert_eq!(wrong, int(-1));
}

#[test]
fn monomial_content_divides() {
    let m = Poly::var(var("m_test", "m"));
    let p = &(&m * &m) * &(&Poly::var(S) + &m);
    let g = p.mono_content();
    assert_eq!(g, vec![(var("m_test", "m"), 2)]);
    assert_eq!(p.div_mono(&g), &Poly::var(S) + &m);
}
