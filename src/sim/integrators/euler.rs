//! Explicit Euler, order 1: y1 = y0 + h f(t0, y0). The baseline of every work-precision plot.

use super::fixed::{FixedStep, SlopeOnlyMethod};
use super::card::{Card, ControlKind, Stiffness, Sweep};


/// The card of explicit Euler ([`mod@super::card`]).
pub const CARD: Card = Card {
    name: "euler",
    title: "explicit Euler",
    control: ControlKind::Step,
    order: Some(1),
    dense_order: Some(1),
    // 0: |1 + i h ω| > 1 for every step, so Euler gains energy on any oscillation.
    stiffness: Stiffness::Explicit { oscillation_limit: 0.0 },
    rigid_only: false,
    sweep: Sweep::Steps { first: 0.01, count: 9 },
    penalty_fit: None,
    stiff_case: None,
};
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
