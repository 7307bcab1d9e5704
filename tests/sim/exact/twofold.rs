//! Tests of `sliding_ladder::sim::exact::twofold` (src/sim/exact/twofold.rs).

use num_traits::Signed;
use sliding_ladder::scalar::{rational_from_float, Rational};
use sliding_ladder::sim::exact::twofold::{cos_minus_ratio, two_prod, two_sum};

fn exact(x: f64) -> Rational {
    rational_from_float(x).expect("finite")
}

/// Both transformations are exact: hi + lo equals a + b (a·b) in rational arithmetic, with
/// zero residual, on pairs whose low part is not zero (for the product, away from underflow).
#[test]
fn the_transformations_lose_nothing() {
    let pairs = [
        (1.0, 1e-20),
        (0.1, 0.2),
        (1e16, 3.7),
        (-3.7, 3.700000000000001),
        (2.5e-300, -1e-310),
    ];
    for (a, b) in pairs {
        let (hi, lo) = two_sum(a, b);
        assert_eq!(
            exact(hi) + exact(lo),
            exact(a) + exact(b),
            "two_sum({a}, {b})"
        );
        // The product is exact only while a·b and its low part do not underflow.
        if (a * b).abs() > 1e-280 {
            let (hi, lo) = two_prod(a, b);
            assert_eq!(
                exact(hi) + exact(lo),
                exact(a) * exact(b),
                "two_prod({a}, {b})"
            );
        }
    }
    // Not vacuous: the low parts of these are not zero.
    assert_ne!(two_sum(1.0, 1e-20).1, 0.0);
    assert_ne!(two_prod(0.1, 0.2).1, 0.0);
}

/// cos θ₀ − θ̇₀²/Ω² is the exact value of its f64 inputs rounded once or twice (the final
/// sum d + (d_lo − q_lo) and q_lo's own rounding, far below it): within 2 ulps of the
/// exact rational, also where the two terms nearly cancel (the second case).
#[test]
fn the_margin_is_exact_up_to_its_last_rounding() {
    for (cos0, rate0, w2) in [
        (0.75, 0.75, 0.75),
        (0.9, 0.8215838362577491, 0.75),
        (0.3, 0.1, 4.0 / 3.0),
    ] {
        let got = cos_minus_ratio(cos0, rate0, w2);
        let want = exact(cos0) - exact(rate0) * exact(rate0) / exact(w2);
        let err = (exact(got) - want.clone()).abs();
        let ulp = exact(f64::EPSILON * got.abs().max(f64::MIN_POSITIVE));
        assert!(
            err <= ulp * Rational::from_integer(2.into()),
            "{cos0}, {rate0}, {w2}: {got}"
        );
    }
}
