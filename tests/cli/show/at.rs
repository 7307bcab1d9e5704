//! Tests of `sliding_ladder::show::at` (src/show/at.rs).

use num_traits::{One, Zero};
use sliding_ladder::scalar::Rational;
use sliding_ladder::show::at::parse_at;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

#[test]
fn numbers_are_read_exactly() {
    let at = parse_at("m=2, l=1.5, g=9.81m/s^2, theta_dot=-3/4, theta_ddot=1e-2").unwrap();
    assert_eq!(at.m, Some(q(2, 1)));
    assert_eq!(at.l, Some(q(3, 2)));
    assert_eq!(at.g, Some(q(981, 100)));
    assert_eq!(at.rate, Some(q(-3, 4)));
    assert_eq!(at.accel, Some(q(1, 100)));
    assert_ne!(at.g, Some(q(98, 10)));
}

#[test]
fn exact_angles_lie_on_the_unit_circle() {
    for key in ["sin_theta=3/5", "cos_theta=4/5", "tan_half_theta=1/3"] {
        let a = parse_at(key).unwrap().theta.unwrap();
        let (s, c) = a.exact().unwrap();
        assert_eq!(s.clone() * s + c.clone() * c, Rational::one(), "{key}");
    }
    // sin θ = 1/2 has an irrational cos: float only.
    assert!(parse_at("sin_theta=1/2")
        .unwrap()
        .theta
        .unwrap()
        .exact()
        .is_none());
    assert_eq!(
        parse_at("theta=0deg").unwrap().theta.unwrap().exact(),
        Some((Rational::zero(), Rational::one()))
    );
}

#[test]
fn bad_input_is_refused_with_the_pair_named() {
    for (bad, says) in [
        ("q=1", "unknown symbol 'q'"),
        ("m=", "'m' has no value"),
        ("m=-2", "must be positive"),
        ("m=0", "must be positive"),
        ("theta=90deg", "outside"),
        ("theta=-1deg", "outside"),
        ("theta=1.6", "outside"),
        ("m=abc", "not a number"),
        ("m=1/0", "division by zero"),
        ("m=1e999", "out of range"),
        ("m=nan", "not a number"),
        ("m 2", "not key=value"),
        ("m=1, m=2", "given twice"),
        ("theta=10deg, sin_theta=1/2", "given twice"),
        ("theta=10deg, theta0=20deg", "above theta"),
        ("theta0=5deg, theta_dot=1", "not both"),
        ("sin_theta=1", "[0, 1)"),
        ("", "empty"),
    ] {
        let e = parse_at(bad).unwrap_err();
        assert!(e.contains(says), "{bad}: {e}");
        assert!(!e.contains('\n'), "{bad}: one line");
    }
}
