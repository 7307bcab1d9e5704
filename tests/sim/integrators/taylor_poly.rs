//! Tests of `sliding_ladder::sim::integrators::taylor_poly` (src/sim/integrators/taylor_poly.rs).

use sliding_ladder::sim::integrators::taylor_poly::power_of_two_below;

/// The time unit is the largest power of two at or below a positive normal number, and 1
/// for anything else (mutation testing: `&&` → `||` let a negative, subnormal or infinite
/// unit through: −2 for −3, 0 for a subnormal, ∞ for ∞).
#[test]
fn the_unit_is_a_power_of_two_at_or_below_a_positive_normal_number() {
    let cases = [
        (1.0, 1.0),
        (3.0, 2.0),
        (0.75, 0.5),
        (f64::MAX, 2f64.powi(1023)),
        (f64::MIN_POSITIVE, f64::MIN_POSITIVE),
    ];
    for (x, want) in cases {
        assert_eq!(power_of_two_below(x), want, "{x}");
    }
    let not_positive_normal = [
        0.0,
        -0.0,
        -3.0,
        f64::MIN_POSITIVE / 2.0,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
    ];
    for x in not_positive_normal {
        assert_eq!(power_of_two_below(x), 1.0, "{x}");
    }
}
