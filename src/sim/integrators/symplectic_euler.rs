//! Symplectic Euler, order 1 (Hairer, Lubich & Wanner, *Geometric Numerical Integration*,
//! sec. I.1.2, variant "kick then drift"): v1 = v0 + h a(q0, v0), q1 = q0 + h v1.
//!
//! For a separable model (acceleration independent of velocity, the wall phase) it is
//! symplectic, so the energy error stays bounded instead of drifting as with explicit Euler.
//!
//! The drift takes the position's rate at the new velocity, f_q(q0, v1). For the usual layout
//! that is v1; for a model whose position moves at the velocity plus a constant (the deviation
//! from a uniform rotation, `sim::near_release`) it is v1 + (f_q0 − v0), read off the first
//! slope. Written that way for both: for the usual layout f_q0 − v0 is exactly 0, so its steps
//! are bit for bit those of q0 + h v1.

use super::fixed::{FixedStep, SlopeOnlyMethod};
use super::card::{Card, ControlKind, Stiffness, Sweep};


/// The card of symplectic Euler ([`mod@super::card`]).
pub const CARD: Card = Card {
    name: "symplectic-euler",
    title: "symplectic Euler",
    control: ControlKind::Step,
    order: Some(1),
    dense_order: Some(1),
    // 2: the step's matrix on q'' = −ω² q has trace 2 − (h ω)², stable while |trace| ≤ 2.
    stiffness: Stiffness::Explicit { oscillation_limit: 2.0 },
    rigid_only: false,
    sweep: Sweep::Steps { first: 0.01, count: 9 },
    penalty_fit: None,
    stiff_case: None,
};
/// The symplectic Euler step for a second-order state `[q, v]`.
#[derive(Clone, Copy, Debug)]
pub struct SymplecticEulerStep;

impl<const N: usize> SlopeOnlyMethod<N> for SymplecticEulerStep {
    fn update(y: &[f64; N], f0: &[f64; N], h: f64) -> [f64; N] {
        let d = N / 2;
        let mut y1 = *y;
        for i in 0..d {
            y1[d + i] = y[d + i] + h * f0[d + i];
            y1[i] = y[i] + h * (y1[d + i] + (f0[i] - y[d + i]));
        }
        y1
    }
}

/// Symplectic Euler with a fixed step.
pub type SymplecticEuler<const N: usize> = FixedStep<SymplecticEulerStep, N>;
