//! Tests of `sliding_ladder::scalar::symbolic` (src/scalar/symbolic.rs).

use sliding_ladder::scalar::symbolic::Sym;
use sliding_ladder::scalar::Scalar;

#[test]
fn pythagoras_is_proved_and_a_planted_error_is_not() {
    let (s, c) = (Sym::sin(), Sym::cos());
    assert!((s.clone() * s.clone() + c.clone() * c.clone() - Sym::int(1)).is_zero());
    let planted = s.clone() * s.clone() + c.clone() * c - Sym::ratio(101, 100);
    assert!(!planted.is_zero());
    assert_eq!(planted.to_f64(), -0.01);
    // tan² + 1 = 1/c², through quotients.
    let c = Sym::cos();
    let tan = s / c.clone();
    assert!((tan.clone() * tan + Sym::int(1) - Sym::int(1) / (c.clone() * c)).is_zero());
}

#[test]
fn fractions_cancel_and_compare_by_cross_multiplication() {
    let (m1, m2) = (Sym::var("m_1", "m_1"), Sym::var("m_2", "m_2"));
    let total = m1.clone() + m2.clone();
    let x = (m1.clone() * Sym::var("x_1", "x_1")) / total.clone();
    let back = x.clone() * total.clone();
    assert!(back.den.factors.is_empty(), "{back:?}");
    assert_eq!(back, m1.clone() * Sym::var("x_1", "x_1"));
    assert_ne!(x, m1 * Sym::var("x_1", "x_1") / (total + Sym::int(1)));
}
