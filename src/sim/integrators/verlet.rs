//! Störmer-Verlet, order 2 (Hairer, Lubich & Wanner, *Geometric Numerical Integration*,
//! sec. I.1.4 and VI.3): half kick, drift, half kick.
//!
//! For an acceleration that depends on the velocity (the floor phase, and the penalty model's
//! force coordinates) each half kick takes the velocity of its own end of the step: the first,
//! v½ = v0 + h/2 a(q0, v0), is explicit, and the second, v1 = v½ + h/2 a(q1, v1), is implicit
//! and solved by fixed-point iteration. The step is its own adjoint (run backwards with −h it
//! retraces itself), so it is symmetric and of order 2.
//!
//! # Why this pairing
//! The other symmetric pairing, v½ = v0 + h/2 a(q0, v½) and v1 = v½ + h/2 a(q1, v½), feeds
//! both kicks the mid-step velocity. On the penalty model that is wrong by a stiff amount: the
//! spring-force equations carry κ sin θ θ̇² (`sim::penalty`, κ up to 1e12), and taking θ̇ half a
//! step off shifts the velocities v_n at whole steps by κ sin θ θ̇ θ̈ h²/2 from the motion's. A
//! start on the true motion (the pre-loaded springs) is then off the method's own slow motion,
//! and the springs ring at their frequencies √κ and 2√κ with a force amplitude of about
//! ω sin θ0 θ̇0 θ̈0 h²/4 (ω = 2√κ) that a symplectic method never damps. That moved the
//! separation of pushed starts by up to 0.017 ω h² (the reliability campaign's F14: κ = 3.1e9
//! at h ω = 0.17, 3.9e-9 rad where the bound allowed 1.4e-9). With each kick at its own time
//! level the velocities at whole steps are the motion's to O(h²) without the factor κ, and
//! nothing is excited (`tests/sim/penalty/verlet_start.rs`). For a separable model the two
//! pairings are the same step.
//!
//! The drift takes the position's rate at the half-step velocity: v½ for the usual layout,
//! v½ + (f_q0 − v0) for a model whose position moves at the velocity plus a constant
//! (`sim::near_release`; see `symplectic_euler`). For the usual layout the offset is exactly
//! 0 and the steps are bit for bit the plain ones.

use super::fixed::{FixedMethod, FixedStep};
use super::{eval, Ode};
use super::card::{Card, ControlKind, Stiffness, Sweep};
use super::Control;

/// Fixed-point iterations allowed for the implicit half kick.
const MAX_ITER: usize = 50;


/// The card of Störmer-Verlet ([`mod@super::card`]).
pub const CARD: Card = Card {
    name: "verlet",
    title: "Störmer-Verlet",
    control: ControlKind::Step,
    order: Some(2),
    dense_order: Some(2),
    // 2: the step's matrix on q'' = −ω² q has trace 2 − (h ω)², stable while |trace| ≤ 2.
    stiffness: Stiffness::Explicit { oscillation_limit: 2.0 },
    rigid_only: false,
    sweep: Sweep::Steps { first: 0.05, count: 10 },
    penalty_fit: None,
    stiff_case: Some(Control::Fixed(1e-3)),
};
/// The Störmer-Verlet step for a second-order state `[q, v]`.
#[derive(Clone, Copy, Debug)]
pub struct VerletStep;

impl<const N: usize> FixedMethod<N> for VerletStep {
    fn advance<S: Ode<N>>(
        sys: &S,
        t: f64,
        y: &[f64; N],
        f0: &[f64; N],
        h: f64,
        evals: &mut u64,
    ) -> ([f64; N], Option<[f64; N]>) {
        let d = N / 2;
        // Explicit half kick with a(q0, v0), then the drift.
        let mut y1 = *y;
        for i in 0..d {
            y1[d + i] = y[d + i] + 0.5 * h * f0[d + i];
        }
        let half = y1;
        // The position's rate less the velocity: 0 but for a uniformly moving frame.
        let offset: [f64; N] = std::array::from_fn(|i| if i < d { f0[i] - y[d + i] } else { 0.0 });
        for i in 0..d {
            y1[i] = y[i] + h * (half[d + i] + offset[i]);
        }
        let mut f1 = eval(sys, t + h, &y1);
        *evals += 1;
        for i in 0..d {
            y1[d + i] = half[d + i] + 0.5 * h * f1[d + i];
        }
        if !sys.accel_uses_velocity() {
            // a(q1) does not depend on v: the slope at the new state is known.
            for i in 0..d {
                f1[i] = y1[d + i] + offset[i];
            }
            return (y1, Some(f1));
        }
        // Implicit half kick v1 = v½ + h/2 a(q1, v1), from the guess v½ + h/2 a(q1, v½).
        for _ in 0..MAX_ITER {
            f1 = eval(sys, t + h, &y1);
            *evals += 1;
            let mut change = 0.0f64;
            for i in 0..d {
                let v = half[d + i] + 0.5 * h * f1[d + i];
                change = change.max((v - y1[d + i]).abs() / v.abs().max(f64::MIN_POSITIVE));
                y1[d + i] = v;
            }
            if change <= 4.0 * f64::EPSILON {
                break;
            }
        }
        (y1, None)
    }
}

/// Störmer-Verlet with a fixed step.
pub type Verlet<const N: usize> = FixedStep<VerletStep, N>;
