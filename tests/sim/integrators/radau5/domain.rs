//! radau5 on a right-hand side with a domain: ẏ = −y until t = 1, then ẏ = −k y, and NaN for
//! y < 0 (as √y or ln y would give). The step across t = 1 is far too long for the new
//! stiffness; its error estimate says so, and radau5's second estimate (the first applied once
//! more, from y + e) then evaluates the right-hand side at y + e, which lies below 0: NaN.
//!
//! An estimate that is NaN must reject the step (and shrink it tenfold). It was read as the
//! smallest error, `NaN.max(1e-10)` being 1e-10, and the step accepted: the run ended with
//! y = −2.3 where the motion has 2.5e-3, and no error (found while mutation testing the
//! rejection's step size, which no test reached).

use num_dual::DualNum;
use sliding_ladder::sim::integrators::AnyStepper;
use sliding_ladder::sim::integrators::{Control, Ode, StepError, Stepper};

/// ẏ = −y for t < 1, −k y after; NaN below y = 0.
struct StiffensWithDomain {
    k: f64,
}

impl Ode<1> for StiffensWithDomain {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, t: f64, y: &[D; 1]) -> [D; 1] {
        if y[0].re() < 0.0 {
            return [D::from(f64::NAN)];
        }
        [y[0] * if t < 1.0 { -1.0 } else { -self.k }]
    }
    fn scale(&self, _y: &[f64; 1]) -> [f64; 1] {
        [1.0]
    }
}

/// To t = 1 + 5/k, where y = e^(−1) e^(−5) exactly. Error model: each step's local error is
/// held to τ in the system's scale (1, so absolutely), and the decay damps every earlier step's
/// error, so the global error stays within a few local ones: 10 τ. The NaN-accepting estimate
/// ended at y = −1.6 to −2.7 in five of these six runs (k = 1e2 at τ = 1e-8 escaped it).
#[test]
fn a_nan_error_estimate_rejects_the_step() {
    let exact = (-6.0f64).exp();
    for k in [1e2, 1e4, 1e6] {
        for tol in [1e-6, 1e-8] {
            let sys = StiffensWithDomain { k };
            let mut st = AnyStepper::new("radau5", Control::Tolerance(tol), 0.0, [1.0]).unwrap();
            let t_end = 1.0 + 5.0 / k;
            while st.t() < t_end {
                st.step(&sys, t_end).unwrap();
            }
            let err = (st.y()[0] - exact).abs();
            assert!(err <= 10.0 * tol, "k = {k}, τ = {tol}: y = {}", st.y()[0]);
        }
    }
}

/// ẏ = √y from y = 0: the right-hand side is 0 there but its slope is infinite, so the iteration
/// matrix I − h (A ⊗ J) has infinite entries at every step size and cannot be factored.
/// radau5 halves the step on each failed factorisation (as a singular matrix at one size may
/// factor at another) until the step is below rounding, and says so within the same call:
/// an error, not a hang (mutation testing: `h · 0.5` → `h + 0.5` grew the step there for ever).
struct RootOfY;

impl Ode<1> for RootOfY {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 1]) -> [D; 1] {
        [y[0].sqrt()]
    }
    fn scale(&self, _y: &[f64; 1]) -> [f64; 1] {
        [1.0]
    }
}

#[test]
fn an_infinite_jacobian_ends_the_step_with_an_error() {
    let mut st = AnyStepper::new("radau5", Control::Tolerance(1e-8), 1.0, [0.0]).unwrap();
    let err = st.step(&RootOfY, 2.0).unwrap_err();
    assert!(
        matches!(err, StepError::StepTooSmall { t, .. } if t == 1.0),
        "{err:?}"
    );
    assert_eq!(st.t(), 1.0);
    // Each failed factorisation is a rejected trial step, counted as such.
    assert!(st.stats().rejected > 0, "{:?}", st.stats());
}
