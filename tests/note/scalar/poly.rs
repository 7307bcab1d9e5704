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

/// A power of c is reduced by the binomial theorem: c⁴ = (1 − s²)² = 1 − 2s² + s⁴ and
/// 3c⁷ = 3c (1 − s²)³ = 3c − 9s²c + 9s⁴c − 3s⁶c, written out here by hand.
#[test]
fn add_reduced_term_expands_a_power_of_c_by_the_binomial_theorem() {
    let (s, c) = (Poly::var(S), Poly::var(C));
    let s2 = &s * &s;
    let (s4, s6) = (&s2 * &s2, &(&s2 * &s2) * &s2);
    let mut c4 = Poly::zero();
    c4.add_reduced_term(vec![(C, 4)], Coeff::int(1));
    assert_eq!(c4, &(&int(1) - &s2.scale(&Coeff::int(2))) + &s4);
    let mut c7 = Poly::zero();
    c7.add_reduced_term(vec![(C, 7)], Coeff::int(3));
    let by_hand = &(&(&int(3) - &s2.scale(&Coeff::int(9))) + &s4.scale(&Coeff::int(9)))
        - &s6.scale(&Coeff::int(3));
    assert_eq!(c7, &by_hand * &c);
}
