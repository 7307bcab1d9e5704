//! A motion that leaves f64: ẏ = 1e307 from y = 1.7e308 reaches f64's largest number
//! (1.797e308) at t = 0.98. No method may accept a step whose end state is not finite,
//! whatever its error estimate says: each step ends finite or with an error, and the run stops
//! with an error before t = 0.98. (Mutation testing: dopri5's
//! `!err.is_finite() || !all_finite(y1)` → `&&` went unseen. Here the error estimate is finite
//! while y1 overflows, since the embedded error of a constant slope is 0 and the error norm is
//! measured against the scale of y1, ∞: the infinite state was accepted.)
//!
//! The Taylor method also carries sin y0 and cos y0 from step to step: a step whose carried
//! sine or cosine is not finite is refused too (the rotor below).

use num_dual::DualNum;
use sliding_ladder::sim::integrators::AnyStepper;
use sliding_ladder::sim::integrators::{taylor, Control, Ode, StepError, Stepper};

const SLOPE: f64 = 1e307;
const Y0: f64 = 1.7e308;

/// ẏ = 1e307.
struct Drift;

impl Ode<1> for Drift {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, _y: &[D; 1]) -> [D; 1] {
        // Not y · 0 + SLOPE: at y = ∞ that is NaN, which every method rejects anyway.
        [D::from(SLOPE)]
    }
}

#[test]
fn no_method_accepts_a_state_that_overflows() {
    let overflow_at = (f64::MAX - Y0) / SLOPE;
    for method in ["dopri5", "dop853", "radau5"] {
        let mut st = AnyStepper::new(method, Control::Tolerance(1e-8), 0.0, [Y0]).unwrap();
        let mut stopped = None;
        for _ in 0..1_000_000 {
            if let Err(e) = st.step(&Drift, 2.0) {
                stopped = Some(e);
                break;
            }
            let (t, y) = (st.t(), st.y()[0]);
            assert!(y.is_finite(), "{method}: y = {y} at t = {t}");
        }
        assert!(
            stopped.is_some(),
            "{method}: still running at t = {}",
            st.t()
        );
        assert!(st.t() < overflow_at, "{method}: t = {}", st.t());
    }
}

/// A rotor θ = w t at w = 8.3e15 rad/s, for the Taylor method, which carries sin θ and cos θ
/// as series of their own: with unit H = 1 s their coefficients are (w H)^k/k!, and at order
/// 21 the last, sin θ's (w H)²¹/21!, overflows while cos θ's last, (w H)²⁰/20! ≈ 1e300, does
/// not. θ itself is finite. A step whose carried sin θ or cos θ is not finite must be refused
/// like one whose state is not (the next step's recursion and every event read them).
/// (Mutation testing: `!finite(y1) || !finite(sin) || !finite(cos)` → `… && …` at either
/// place went unseen: no test reached an end trig that was not finite.)
struct Rotor;

const SPIN: f64 = 8.3e15;

impl Ode<2> for Rotor {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 2]) -> [D; 2] {
        [y[1], D::from(0.0)]
    }
    fn max_step(&self, _y: &[f64; 2]) -> f64 {
        1.0
    }
    /// θ = θ0 + w τ and w constant; sin and cos of θ from θ0 = 0: the k-th coefficients
    /// ±(w H)^k/k!, sin's at odd k and cos's at even k, formed by k multiplications.
    fn taylor_series(&self, s: &mut taylor::Series<2>) -> bool {
        let x = s.y[1][0] * s.unit();
        s.y[0][1] = x;
        let mut term = 1.0;
        for k in 1..=s.order {
            term *= x / k as f64;
            let sign = if (k / 2) % 2 == 0 { 1.0 } else { -1.0 };
            if k % 2 == 1 {
                s.sin[k] = sign * term;
            } else {
                s.cos[k] = sign * term;
            }
        }
        true
    }
}

#[test]
fn the_taylor_method_refuses_a_carried_sine_that_overflows() {
    let mut st = taylor::Taylor::with_order(0.0, [0.0, SPIN], 1e-8, 21);
    assert_eq!(st.order(), 21);
    // The premise: the last coefficients, as the recursion forms them.
    let last = (1..=21).fold(1.0f64, |t, k| t * SPIN / k as f64);
    let before = (1..=20).fold(1.0f64, |t, k| t * SPIN / k as f64);
    assert!(
        last.is_infinite() && before.is_finite() && before > 1e299,
        "{before:e}"
    );
    match st.step(&Rotor, 1.0) {
        Err(StepError::NotFinite { t }) => assert_eq!(t, 0.0),
        other => panic!("{other:?}: t = {}, y = {:?}", st.t(), st.y()),
    }
}
