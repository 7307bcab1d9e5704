//! Error scales. First, a tolerance in an error scale far below the state's rounding: ẏ = ω cos ω t (ω = 50) from
//! y(0) = 0 with errors measured in units of 1e-200 (`Ode::scale`), so a step may err by at most
//! τ 1e-200 = 1e-206. Near t = 0 that is met only by steps so short that cos ω t is 1 to the
//! last bit (the step is then exact but for its rounding); once ω t is above 1e-8 no step can
//! meet it, and the method must say so (StepTooSmall) rather than go on. The error ratios are
//! 1e150 and more here, whose squares overflow: dop853 sums them in units of the largest (F7
//! of issue 17), dopri5 shrinks the step tenfold while its norm is not finite. Over up to 40
//! steps, every accepted one keeps y = sin ω t to the tolerance plus k ulps after k steps.
//! (Mutation testing: dop853's third-order sum in those units `r3 / big` → `r3 · big`
//! overflowed to ∞, which made every error estimate 0: its steps grew sixfold each, to where
//! their truncation error is far above the rounding.)
//!
//! Second, a system that sets no scale is measured relative to its own size.

use num_dual::DualNum;
use sliding_ladder::sim::integrators::AnyStepper;
use sliding_ladder::sim::integrators::{Control, Ode, StepError, Stepper};

const OMEGA: f64 = 50.0;

/// ẏ = ω cos ω t, errors in units of 1e-200.
struct TinyScale;

impl Ode<1> for TinyScale {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, t: f64, y: &[D; 1]) -> [D; 1] {
        [y[0] * 0.0 + OMEGA * (OMEGA * t).cos()]
    }
    fn scale(&self, _y: &[f64; 1]) -> [f64; 1] {
        [1e-200]
    }
}

#[test]
fn a_tolerance_below_rounding_is_met_or_refused_never_ignored() {
    for method in ["dopri5", "dop853"] {
        let mut st = AnyStepper::new(method, Control::Tolerance(1e-6), 0.0, [0.0]).unwrap();
        for k in 1..=40 {
            match st.step(&TinyScale, 1.0) {
                Ok(()) => {}
                Err(StepError::StepTooSmall { .. }) => break,
                Err(e) => panic!("{method}: {e}"),
            }
            let (t, y) = (st.t(), st.y()[0]);
            let exact = (OMEGA * t).sin();
            // k steps, each rounding y and t by an ulp or two: 4 k ulps of y.
            let bound = 1e-206 + 4.0 * k as f64 * f64::EPSILON * exact.abs();
            assert!(
                (y - exact).abs() <= bound,
                "{method}, step {k} to t = {t:e}: y = {y:e}, sin ω t = {exact:e}"
            );
        }
    }
}

/// ẏ = −y, with the default error scale.
struct Decay;

impl Ode<1> for Decay {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 1]) -> [D; 1] {
        [-y[0]]
    }
}

/// A system that sets no error scale is measured relative to its own size (`Ode::scale`'s
/// default |y|): ẏ = −y from y = 1e-10 to t = 5 at τ = 1e-8 ends within 10 N τ of
/// 1e-10 e^(−5), relative, as it would from y = 1. (Mutation testing: the default → 1, an
/// absolute error of 1e-8 against a state of 1e-10, went unseen: every test system either set
/// its scale or started near 1. It took steps as long as its growth limit allowed.)
#[test]
fn the_default_error_scale_is_relative() {
    for method in ["dopri5", "dop853", "radau5"] {
        let tol = 1e-8;
        let mut st = AnyStepper::new(method, Control::Tolerance(tol), 0.0, [1e-10]).unwrap();
        while st.t() < 5.0 {
            st.step(&Decay, 5.0).unwrap();
        }
        let want = 1e-10 * (-5.0f64).exp();
        let rel = (st.y()[0] - want).abs() / want;
        let bound = 10.0 * st.stats().steps as f64 * tol;
        assert!(rel <= bound, "{method}: {rel:e} > {bound:e}");
    }
}
