//! Whatever the start, the exact phase-one solution either refuses it with a message or
//! returns finite numbers: no NaN, infinity or panic reaches a caller (property test).
use proptest::prelude::*;
use sliding_ladder::sim::exact::PhaseOne;
use std::f64::consts::FRAC_PI_2;

fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo.log10()..hi.log10()).prop_map(|e| 10f64.powf(e))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]
    #[test]
    fn finite_or_refused(
        theta0 in prop_oneof![Just(0.0), log_uniform(1e-300, 1.0), 0.0..FRAC_PI_2],
        rate0 in prop_oneof![Just(0.0), log_uniform(1e-300, 1e300)],
        big_omega2 in log_uniform(1e-100, 1e100),
        frac in 0.0..=1.0f64,
    ) {
        let Ok(p) = PhaseOne::new(theta0, rate0, big_omega2) else { return Ok(()); };
        let Some(s) = p.separation() else {
            prop_assert!(theta0 == 0.0 && rate0 == 0.0);
            return Ok(());
        };
        prop_assert!(s.angle.is_finite() && s.time.is_finite() && s.rate.is_finite());
        prop_assert!(s.angle >= theta0 && s.angle < FRAC_PI_2 && s.time >= 0.0);
        let (theta, rate) = p.theta_rate(frac * s.time);
        prop_assert!(theta.is_finite() && rate.is_finite(), "θ = {theta}, θ̇ = {rate}");
        let t = p.time_to_angle(theta0 + frac * (s.angle - theta0));
        prop_assert!(t.is_finite() && t >= 0.0, "t = {t}");
    }
}

#[test]
fn the_property_can_fail() {
    // Below the turning point t(θ) is NaN by design (documented): the check above would see it.
    let p = PhaseOne::new(0.5, 0.0, 1.0).unwrap();
    assert!(p.time_to_angle(0.25).is_nan());
}

/// At the equilibrium θ₀ = θ̇₀ = 0 the ladder never moves: it is at θ = 0 from t = 0 on and
/// never reaches any other angle (mutation testing: `theta == 0.0` → `!=` in
/// `PhaseOne::time_to_angle` went unseen, no test asked the equilibrium for a time).
#[test]
fn the_equilibrium_is_at_zero_at_once_and_never_elsewhere() {
    let rest = PhaseOne::new(0.0, 0.0, 0.75).unwrap();
    assert_eq!(rest.time_to_angle(0.0), 0.0);
    for theta in [1e-300, 0.3, FRAC_PI_2] {
        assert_eq!(rest.time_to_angle(theta), f64::INFINITY, "θ = {theta}");
    }
    // The check can fail: a start a little away from rest does reach 0.3, in finite time.
    let moved = PhaseOne::new(1e-6, 0.0, 0.75).unwrap();
    assert!(moved.time_to_angle(0.3).is_finite());
}

/// The tests' deliberately wrong closed form (`PhaseOne::with_modulus_factor`) is the motion
/// itself at factor 1, bit for bit, and wrong at any other: so a check that fails on it fails
/// because of the factor (mutation testing: the AGM rebuilt from k + k instead of k² went
/// unseen, the tests only needed the wrong form to be wrong).
#[test]
fn the_wrong_closed_form_is_the_motion_at_factor_one() {
    for (theta0, rate0) in [(0.3, 0.0), (1e-3, 0.4), (1.2, 0.1)] {
        let p = PhaseOne::new(theta0, rate0, 0.75).unwrap();
        let same = p.with_modulus_factor(1.0);
        let wrong = p.with_modulus_factor(1.0 - 1e-6);
        let t = 0.7 * p.separation().unwrap().time;
        assert_eq!(
            same.theta_rate(t),
            p.theta_rate(t),
            "start ({theta0}, {rate0})"
        );
        assert_eq!(same.quarter_period(), p.quarter_period());
        assert_ne!(
            wrong.theta_rate(t),
            p.theta_rate(t),
            "start ({theta0}, {rate0})"
        );
    }
}
