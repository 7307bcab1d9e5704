//! Tests of `sliding_ladder::report::stability::stiff` (src/report/stability/stiff.rs).

use sliding_ladder::report::stability::stiff::{spread_failure, ULP_SPREAD_LIMIT};

/// The spread check passes a spread at the limit and fails one just past it, and a NaN.
#[test]
fn spread_check_can_fail() {
    let at = 0.84;
    assert_eq!(spread_failure((at, at + 0.5 * ULP_SPREAD_LIMIT)), None);
    let wide = spread_failure((at, at + 2.0 * ULP_SPREAD_LIMIT)).expect("2e-9 must fail");
    assert!(wide.contains("2.0e-9") && wide.contains("> 1e-9"), "{wide}");
    assert!(spread_failure((at, f64::NAN)).is_some());
}
