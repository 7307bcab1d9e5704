//! Störmer-Verlet, order 2 (Hairer, Lubich & Wanner, *Geometric Numerical Integration*,
//! sec. I.1.4 and VI.3): half kick, drift, half kick.
//!
//! For an acceleration that depends on the velocity (the floor phase) the first half kick
//! v½ = v0 + h/2 a(q0, v½) is implicit and is solved by fixed-point iteration; the second,
//! v1 = v½ + h/2 a(q1, v½), is its adjoint, so the step stays symmetric and of order 2.
//! For a separable model the last acceleration is the next step's first: one rhs per step.

use super::fixed::{FixedMethod, FixedStep};
use super::{eval, Ode};

/// Fixed-point iterations allowed for the implicit half kick.
const MAX_ITER: usize = 50;

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
        let mut half = *y;
        for i in 0..d {
            half[d + i] = y[d + i] + 0.5 * h * f0[d + i];
        }
        if sys.accel_uses_velocity() {
            for _ in 0..MAX_ITER {
                let mut probe = *y;
                probe[d..].copy_from_slice(&half[d..]);
                let f = eval(sys, t, &probe);
                *evals += 1;
                let mut change = 0.0f64;
                for i in 0..d {
                    let v = y[d + i] + 0.5 * h * f[d + i];
                    change = change.max((v - half[d + i]).abs() / v.abs().max(f64::MIN_POSITIVE));
                    half[d + i] = v;
                }
                if change <= 4.0 * f64::EPSILON {
                    break;
                }
            }
        }
        let mut y1 = half;
        for i in 0..d {
            y1[i] = y[i] + h * half[d + i];
        }
        let f1 = eval(sys, t + h, &y1);
        *evals += 1;
        for i in 0..d {
            y1[d + i] = half[d + i] + 0.5 * h * f1[d + i];
        }
        if sys.accel_uses_velocity() {
            (y1, None)
        } else {
            // a(q1) does not depend on v: the slope at the new state is known.
            let mut f_end = f1;
            f_end[..d].copy_from_slice(&y1[d..]);
            (y1, Some(f_end))
        }
    }
}

/// Störmer-Verlet with a fixed step.
pub type Verlet<const N: usize> = FixedStep<VerletStep, N>;
