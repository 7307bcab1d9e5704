//! Explicit Euler, order 1: y1 = y0 + h f(t0, y0). The baseline of every work-precision plot.

use super::fixed::{FixedStep, SlopeOnlyMethod};

/// Explicit Euler's step.
#[derive(Clone, Copy, Debug)]
pub struct EulerStep;

impl<const N: usize> SlopeOnlyMethod<N> for EulerStep {
    fn update(y: &[f64; N], f0: &[f64; N], h: f64) -> [f64; N] {
        std::array::from_fn(|i| y[i] + h * f0[i])
    }
}

/// Explicit Euler with a fixed step.
pub type Euler<const N: usize> = FixedStep<EulerStep, N>;
