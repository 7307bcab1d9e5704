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
