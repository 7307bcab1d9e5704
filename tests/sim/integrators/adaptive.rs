//! Tests of `sliding_ladder::sim::integrators::adaptive` (src/sim/integrators/adaptive.rs).

use sliding_ladder::scalar::{rational_from_float, Rational};
use sliding_ladder::sim::integrators::adaptive::{advance_time, AdaptiveState, Controller};

/// 10⁶ steps of h = 0.1 (not a binary fraction) from t = 3: the carried time is the exact
/// sum of the steps (rationals) to half an ulp of t plus half an ulp of h per step (the
/// sum h + lo is rounded), 1.7e-12 here; the plain running sum drifts by far more (its
/// roundings at one binade lean one way). The last step lands on t_stop exactly.
#[test]
fn the_carried_time_is_the_sum_of_the_steps() {
    let (h, n) = (0.1, 1_000_000u32);
    let (mut t, mut lo, mut plain) = (3.0, 0.0, 3.0);
    for _ in 0..n {
        (t, lo) = advance_time(t, lo, h, false, f64::INFINITY);
        plain += h;
    }
    let exact = rational_from_float(3.0).unwrap()
        + rational_from_float(h).unwrap() * Rational::from_integer(n.into());
    let err = |x: f64| {
        let d = rational_from_float(x).unwrap() - exact.clone();
        num_traits::ToPrimitive::to_f64(&d).unwrap().abs()
    };
    let bound = 0.5 * f64::EPSILON * t + n as f64 * 0.5 * f64::EPSILON * h;
    assert!(err(t) <= bound, "{} against {bound:e}", err(t));
    assert!(err(plain) > 1e3 * bound, "{}", err(plain));
    assert_eq!(advance_time(t, lo, h, true, 7.5), (7.5, 0.0));
}

/// dopri5.f's controller constants (the `CONTROL` of `dopri5.rs`).
const PI: Controller = Controller {
    expo: 0.2 - 0.75 * 0.04,
    beta: 0.04,
    fac_lo: 0.1,
    fac_hi: 5.0,
};

/// The proposals at the controller's fixed points, as dopri5.f makes them: a negligible
/// error grows the step by the cap 1/fac_lo = 10; an error of exactly 1 after an accepted
/// error of 1 gives the safety factor 0.9, after one of 2⁻¹⁰ that times 2^−0.4 (the PI
/// part, β = 0.04); after a rejection an accepted step may not grow;
/// a rejected error of 2^(1/expo) shrinks the step by 2/0.9. Checked to a few ulps (one
/// power and a division or two). Mutation testing: the PI part `err^expo / facold^β` → `%`
/// and `·` went unseen, the runs' errors stayed within their tolerance while the proposals
/// were wrong.
#[test]
fn the_proposals_follow_dopri5s_controller() {
    let close = |got: f64, want: f64| (got - want).abs() <= 4.0 * f64::EPSILON * want;
    for h in [1.0, 0.37, 3e-5] {
        let mut st = AdaptiveState::new(0.0, [1.0], 1e-8);
        let grown = st.control(&PI, h, 1e-20).expect("accepted");
        assert!(close(grown, 10.0 * h), "h {h}: {grown}");
        st.facold = 1.0;
        let safe = st.control(&PI, h, 1.0).expect("accepted");
        assert!(close(safe, 0.9 * h), "h {h}: {safe}");
        // The PI memory: after an accepted error of 2⁻¹⁰ an error of 1 means errors are
        // rising, so the step shrinks by the further factor (2⁻¹⁰)^β = 2^−0.4.
        st.facold = 2f64.powi(-10);
        let careful = st.control(&PI, h, 1.0).expect("accepted");
        assert!(
            close(careful, 0.9 * 2f64.powf(-0.4) * h),
            "h {h}: {careful}"
        );
        assert_eq!(
            st.control(&PI, h, 2f64.powf(1.0 / PI.expo)),
            None,
            "rejected"
        );
        assert!(close(st.h, h * 0.9 / 2.0), "h {h}: {}", st.h);
        assert_eq!(st.stats.rejected, 1);
        let after = st.control(&PI, h, 1e-20).expect("accepted");
        assert_eq!(after, h, "no growth right after a rejection");
    }
}
