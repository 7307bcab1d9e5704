//! The classic Runge-Kutta method of order 4 (Kutta 1901; Hairer, Nørsett & Wanner, *Solving
//! ODEs I*, Table II.1.2, left), fixed step, four evaluations per step.

use super::fixed::{FixedMethod, FixedStep};
use super::{eval, Ode};
use super::card::{Card, ControlKind, Stiffness, Sweep};
use super::Control;


/// The card of classic Runge-Kutta 4 ([`mod@super::card`]).
pub const CARD: Card = Card {
    name: "rk4",
    title: "classic Runge-Kutta 4",
    control: ControlKind::Step,
    order: Some(4),
    dense_order: Some(4),
    // 2√2: |R(i y)| ≤ 1 for R(z) = Σ_{k≤4} z^k/k! exactly while y ≤ 2√2.
    stiffness: Stiffness::Explicit { oscillation_limit: 2.828_427_124_746_190_3 },
    rigid_only: false,
    sweep: Sweep::Steps { first: 0.1, count: 10 },
    penalty_fit: None,
    stiff_case: Some(Control::Fixed(1e-3)),
};
/// The classic RK4 step.
#[derive(Clone, Copy, Debug)]
pub struct Rk4Step;

impl<const N: usize> FixedMethod<N> for Rk4Step {
    fn advance<S: Ode<N>>(
        sys: &S,
        t: f64,
        y: &[f64; N],
        k1: &[f64; N],
        h: f64,
        evals: &mut u64,
    ) -> ([f64; N], Option<[f64; N]>) {
        let stage =
            |k: &[f64; N], c: f64| -> [f64; N] { std::array::from_fn(|i| y[i] + c * h * k[i]) };
        let k2 = eval(sys, t + 0.5 * h, &stage(k1, 0.5));
        let k3 = eval(sys, t + 0.5 * h, &stage(&k2, 0.5));
        let k4 = eval(sys, t + h, &stage(&k3, 1.0));
        *evals += 3;
        let y1 = std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]));
        (y1, None)
    }
}

/// Classic RK4 with a fixed step.
pub type Rk4<const N: usize> = FixedStep<Rk4Step, N>;
