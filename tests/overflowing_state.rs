//! A motion that leaves f64: ẏ = 1e307 from y = 1.7e308 reaches f64's largest number
//! (1.797e308) at t = 0.98. No method may accept a step whose end state is not finite,
//! whatever its error estimate says: each step ends finite or with an error, and the run stops
//! with an error before t = 0.98. (Mutation testing: dopri5's
//! `!err.is_finite() || !all_finite(y1)` → `&&` went unseen. Here the error estimate is finite
//! while y1 overflows, since the embedded error of a constant slope is 0 and the error norm is
//! measured against the scale of y1, ∞: the infinite state was accepted.)

use num_dual::DualNum;
use sliding_ladder::sim::integrators::any::AnyStepper;
use sliding_ladder::sim::integrators::{Control, Ode, Stepper};

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
