//! Tests of `sliding_ladder::scalar::bound` (src/scalar/bound.rs).

use sliding_ladder::scalar::bound::{Bound, UNIT_ROUNDOFF};
use sliding_ladder::scalar::Scalar;

#[test]
fn cancellation_is_charged_at_the_size_of_the_terms() {
    // (1 + 1e-10) - 1: the result is tiny, the bound is not.
    let a = Bound::exact(1.0) + Bound::exact(1e-10);
    let r = a - Bound::exact(1.0);
    assert!(
        r.abs_error() >= UNIT_ROUNDOFF,
        "bound {} too small",
        r.abs_error()
    );
    // And the bound does cover the real error of this computation.
    let real_error = (r.v - 1e-10).abs();
    assert!(
        real_error <= r.abs_error(),
        "{real_error} > {}",
        r.abs_error()
    );
}

#[test]
fn exact_integers_carry_no_error() {
    let r = Bound::int(3) * Bound::int(4) - Bound::int(12);
    assert_eq!(r.v, 0.0);
    assert_eq!(r.e, 12.0); // the rounding charge of the product, |12|·u, not zero
    assert!(Bound::int(3).e == 0.0);
}

/// `to_f64` is the float value, without its error bound.
#[test]
fn bound_to_f64_is_the_value() {
    let r = Bound::int(1) / Bound::int(3);
    assert_eq!(r.to_f64(), 1.0 / 3.0);
    assert!(r.e > 0.0);
    assert_eq!(Bound::int(-7).to_f64(), -7.0);
}
