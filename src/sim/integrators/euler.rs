//! Explicit Euler, order 1: y1 = y0 + h f(t0, y0). The baseline of every work-precision plot.

use super::fixed::{FixedMethod, FixedStep};
use super::Ode;

/// Explicit Euler's step.
#[derive(Clone, Copy, Debug)]
pub struct EulerStep;

impl<const N: usize> FixedMethod<N> for EulerStep {
    fn advance<S: Ode<N>>(
        _sys: &S,
        _t: f64,
        y: &[f64; N],
        f0: &[f64; N],
        h: f64,
        _evals: &mut u64,
    ) -> ([f64; N], Option<[f64; N]>) {
        (std::array::from_fn(|i| y[i] + h * f0[i]), None)
    }
}

/// Explicit Euler with a fixed step.
pub type Euler<const N: usize> = FixedStep<EulerStep, N>;
