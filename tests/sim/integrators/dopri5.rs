//! Tests of `sliding_ladder::sim::integrators::dopri5` (src/sim/integrators/dopri5.rs).

use sliding_ladder::sim::integrators::dopri5::CONTROL;

/// The step-size control is dopri5.f's defaults (Hairer & Wanner): β = 0.04, the error's
/// exponent expo1 = 1/5 − 0.75 β = 0.17, and a new step between 0.2 and 10 times the old
/// (FAC1 = 0.2, FAC2 = 10, here as the reciprocal factor's bounds 0.1 and 5). The exponent
/// is one subtraction and a product: within 2 ulps of 0.17. (Mutation testing: `0.2 −
/// 0.75 β` → `0.2 + 0.75 β` went unseen; every accepted step was still held to its
/// tolerance, the proposals were off.)
#[test]
fn the_controller_is_dopri5s() {
    assert!((CONTROL.expo - 0.17).abs() <= 2.0 * f64::EPSILON * 0.17);
    assert_eq!(CONTROL.beta, 0.04);
    assert_eq!((CONTROL.fac_lo, CONTROL.fac_hi), (0.1, 5.0));
}
