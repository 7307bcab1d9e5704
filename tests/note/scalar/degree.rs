//! Tests of `sliding_ladder::scalar::degree` (src/scalar/degree.rs).

use sliding_ladder::scalar::degree::Degree;
use sliding_ladder::scalar::Scalar;

#[test]
fn degrees_of_the_circle_parametrisation() {
    // sin θ = 2t/(1+t²): numerator 1, denominator 2.
    let t = Degree::variable();
    let one = Degree::int(1);
    let s = Degree::int(2) * t / (one + t * t);
    assert_eq!(s, Degree { num: 1, den: 2 });
    // s² + c² - 1 over the common denominator has numerator degree at most 4.
    let c = (one - t * t) / (one + t * t);
    let r = s * s + c * c - one;
    assert!(r.num >= 4, "{r:?}");
}

/// A degree has no numerical value: `to_f64` is NaN.
#[test]
fn degree_to_f64_is_not_a_number() {
    assert!(Degree::variable().to_f64().is_nan());
    assert!(Degree::int(2).to_f64().is_nan());
}

/// Each rule of the module's table at operands whose degrees are all distinct and above 1 (so a
/// sum taken for a product, or a product for a sum, shows): a = n 1 / d 2, b = n 3 / d 5.
#[test]
fn degree_arithmetic_follows_the_table() {
    let a = Degree { num: 1, den: 2 };
    let b = Degree { num: 3, den: 5 };
    // a ± b: max(n_a + d_b, n_b + d_a) = max(6, 5), d_a + d_b = 7.
    assert_eq!(a + b, Degree { num: 6, den: 7 });
    assert_eq!(a - b, Degree { num: 6, den: 7 });
    assert_eq!(b + a, Degree { num: 6, den: 7 });
    // a · b: n_a + n_b = 4, d_a + d_b = 7.
    assert_eq!(a * b, Degree { num: 4, den: 7 });
    // a / b: n_a + d_b = 6, d_a + n_b = 5.
    assert_eq!(a / b, Degree { num: 6, den: 5 });
    assert_eq!(-a, a);
}
