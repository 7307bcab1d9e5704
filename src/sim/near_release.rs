//! The wall phase near the release push: θ̇0 just below Ω √cos θ0, the push at which the top
//! leaves the wall at once (from upright, θ̇0 → Ω = √(3g/4l)). Integrated as the deviation from
//! the start.
//!
//! **Why.** In θ the separation factor Ω² cos θ − θ̇² (`rigid::separation_factor`) is a
//! difference of two numbers of size Ω² cos θ0 whose root lies where they agree to
//! D0 = Ω² cos θ0 − θ̇0², the factor at the start: an ulp of θ̇ or cos θ is a relative error
//! u κ of the root, κ = Ω² cos θ0 / D0. Measured before this module (issue 38), from upright at
//! tolerance 1e-13 every method's separation was off by 1e-8 relative at θ̇0 = Ω(1 − 1e-9),
//! 1.5e-3 at Ω(1 − 1e-14) and 15-22 % one ulp below fl(Ω) (dop853: θ_s = 1.30055e-8 for
//! 1.57537e-8), all with exit 0.
//!
//! **The form.** y = [u, v] with θ = θ0 + u, θ̇ = θ̇0 + v:
//!
//!   u' = θ̇0 + v,   v' = Ω² sin(θ0 + u)   (eq. (5)),
//!
//! and the factor written out from the start,
//!
//!   Ω² cos θ − θ̇² = D0 − Ω² (cos θ0 − cos θ) − v (2θ̇0 + v),
//!   cos θ0 − cos θ = sin θ0 sin u + 2 cos θ0 sin²(u/2),
//!
//! with D0 carried exactly from the scene's inputs (`sim::start_margin`). Near the root each
//! term is of the size of D0 and carries the relative precision the integrator gave u and v, so
//! the root keeps it too. u and v start at 0 and hold full relative precision where θ̇ = θ̇0 + v
//! cannot (v is below an ulp of θ̇0 one ulp below Ω).
//!
//! **Error control.** Each component against its own size at the separation, estimated from
//! the energy integral (cos θ0 − cos θ_s = D0/(3Ω²) and θ̇_s² − θ̇0² = 2D0/3): the root's
//! relative error follows the tolerance. (Against max(|u|, |v|/Ω), as in θ, v would be held
//! only to τ u Ω, and v is second order in u from upright: the root's error would be τ/u.)
//!
//! **When** ([`applies`]): κ > [`KAPPA`] = 4, where the form in θ loses two bits or more. The
//! phase always starts at t = 0 (a tiny start's lead-in never meets a push near Ω √cos θ0).
//!
//! **Second-order layout.** The position's rate is the velocity plus the constant θ̇0; the
//! symplectic methods step the position with f_q(q0, v1) = v1 + (f_q0 − v0), which is that
//! (`integrators::symplectic_euler`, `integrators::verlet`).

use super::event::{Direction, Event};
use super::integrators::taylor::{sin_cos_coefficient, Series, MAX_ORDER};
use super::integrators::{Ode, Stepper};
use super::rigid::{event_safe_step, taylor_event_safe_step};

use super::run::{integrate_phase, Observer, PhaseEnd, RunError};
use super::start_margin::{start_margin, Lean};
use crate::ladder::Ladder;
use num_dual::DualNum;

/// Least κ = Ω² cos θ0 / D0 at which the wall phase runs in the deviation form.
pub const KAPPA: f64 = 4.0;

/// Whether the start (cos θ0 = `cos0`, θ̇0 = `rate0`) is near the release push by the f64
/// margin: D0 < Ω² cos θ0 / [`KAPPA`] (with room for the f64 margin's own error, a few u Ω²),
/// including D0 ≤ 0 (the top leaves at once). Then the margin is formed exactly.
pub fn applies(big_omega2: f64, cos0: f64, rate0: f64) -> bool {
    let scale = big_omega2 * cos0;
    rate0 > 0.0 && scale.is_finite() && big_omega2 * cos0 - rate0 * rate0 < scale / KAPPA
}

/// D0 = Ω² cos θ0 − θ̇0² of `ladder` (s⁻²) to f64's precision when the start is near the
/// release push ([`applies`]), else None (the f64 factor is then good to a few ulps).
pub fn near_margin(ladder: &Ladder<f64>, lean: Lean, rate0: f64) -> Option<f64> {
    applies(ladder.big_omega2(), lean.cos(), rate0).then(|| start_margin(ladder, lean, rate0))
}

/// The wall phase in the deviation from the start (module docs).
#[derive(Clone, Copy, Debug)]
pub struct NearRelease {
    big_omega2: f64,
    big_omega: f64,
    /// θ̇0.
    rate0: f64,
    /// sin θ0 (from φ0 when given).
    pub sin0: f64,
    /// cos θ0 (from φ0 when given).
    pub cos0: f64,
    /// D0 = Ω² cos θ0 − θ̇0² (> 0).
    margin: f64,
    /// u and v at the separation, from the energy (the error control's floors).
    pub size: [f64; 2],
}

impl NearRelease {
    /// The wall phase from `lean`, θ̇0 = `rate0` > 0 with Ω² = `big_omega2` and the start's
    /// margin D0 = `margin` > 0 ([`near_margin`], in the same units).
    pub fn new(big_omega2: f64, lean: Lean, rate0: f64, margin: f64) -> Self {
        let (sin0, cos0) = (lean.sin(), lean.cos());
        // cos θ0 − cos θ_s = Δ = D0/(3Ω²): the travel x solves (cos θ0/2) x² + sin θ0 x = Δ
        // to second order (a floor of the error control, needed only to a factor of two).
        let delta = margin / (3.0 * big_omega2);
        let travel = 2.0 * delta / (sin0 + (sin0 * sin0 + 2.0 * delta * cos0).sqrt());
        // θ̇_s² − θ̇0² = 2 Ω² Δ.
        let gain = 2.0 * big_omega2 * delta;
        let rate_gain = gain / (rate0 + (rate0 * rate0 + gain).sqrt());
        NearRelease {
            big_omega2,
            big_omega: big_omega2.sqrt(),
            rate0,
            sin0,
            cos0,
            margin,
            size: [travel, rate_gain],
        }
    }

    /// (θ − θ0, θ̇) of the deviation state `y`: the travel, and the rate.
    pub fn travel_and_rate(&self, y: &[f64; 2]) -> (f64, f64) {
        (y[0], self.rate0 + y[1])
    }

    /// The wall force's factor Ω² cos θ − θ̇² at `y` (module docs), with
    /// cos θ0 − cos θ = sin θ0 sin u + 2 cos θ0 sin²(u/2): two terms of one sign for u ≥ 0.
    pub fn factor(&self, y: &[f64; 2]) -> f64 {
        let [u, v] = *y;
        let half = (0.5 * u).sin();
        let fall = self.sin0 * u.sin() + 2.0 * self.cos0 * half * half;
        self.margin - self.big_omega2 * fall - v * (2.0 * self.rate0 + v)
    }
}

impl Ode<2> for NearRelease {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 2]) -> [D; 2] {
        let (s, c) = y[0].sin_cos();
        [
            y[1] + self.rate0,
            (s * self.cos0 + c * self.sin0) * self.big_omega2,
        ]
    }
    fn max_step(&self, y: &[f64; 2]) -> f64 {
        event_safe_step(self.big_omega, self.rate0 + y[1])
    }
    fn taylor_max_step(&self, y: &[f64; 2]) -> f64 {
        taylor_event_safe_step(self.big_omega, self.rate0 + y[1])
    }
    /// Each component against its size at the separation (module docs).
    fn scale(&self, y: &[f64; 2]) -> [f64; 2] {
        [y[0].abs().max(self.size[0]), y[1].abs().max(self.size[1])]
    }
    fn accel_uses_velocity(&self) -> bool {
        false
    }
    /// u' = θ̇0 + v, v' = Ω² (sin θ0 cos u + cos θ0 sin u), with sin u and cos u by the
    /// recursion of `integrators::taylor` (the carried angle is u).
    fn taylor_series(&self, s: &mut Series<2>) -> bool {
        let p = s.order;
        let inv = *s.unit_over_k();
        let mut d = [0.0; MAX_ORDER + 1];
        d[0] = self.rate0 + s.y[1][0];
        for k in 0..=p {
            if k > 0 {
                (s.sin[k], s.cos[k]) =
                    sin_cos_coefficient(&inv[k], &d[..k], &s.sin[..k], &s.cos[..k]);
            }
            if k < p {
                s.y[0][k + 1] = d[k] * inv[k + 1];
                s.y[1][k + 1] =
                    (self.sin0 * s.cos[k] + self.cos0 * s.sin[k]) * (self.big_omega2 * inv[k + 1]);
                d[k + 1] = s.y[1][k + 1];
            }
        }
        true
    }
}

/// Separation: the factor, in the deviation form, falls through zero.
pub struct NearSeparation<'a>(pub &'a NearRelease);

impl Event<2> for NearSeparation<'_> {
    fn value(&self, _t: f64, y: &[f64; 2]) -> f64 {
        self.0.factor(y)
    }
    fn direction(&self) -> Direction {
        Direction::Falling
    }
    /// d/dt (Ω² cos θ − θ̇²) = −Ω² sin θ θ̇ − 2 θ̇ θ̈, with θ̇ = u' and θ̈ = v'.
    fn rate(&self, _t: f64, y: &[f64; 2], dy: &[f64; 2]) -> Option<f64> {
        let m = self.0;
        let (s, c) = y[0].sin_cos();
        let sin_theta = s * m.cos0 + c * m.sin0;
        Some(-m.big_omega2 * sin_theta * dy[0] - 2.0 * (m.rate0 + y[1]) * dy[1])
    }
}

/// An observer of (θ, θ̇) fed from a run in the deviation form; θ = θ0 + u with `theta0` as
/// the caller holds it.
pub struct InTheta<'a, O> {
    /// The model.
    pub model: &'a NearRelease,
    /// θ0.
    pub theta0: f64,
    /// The observer of (θ, θ̇).
    pub inner: &'a mut O,
}

impl<O: Observer<2>> InTheta<'_, O> {
    fn theta(&self, y: &[f64; 2]) -> [f64; 2] {
        let (u, rate) = self.model.travel_and_rate(y);
        [self.theta0 + u, rate]
    }
}

impl<O: Observer<2>> Observer<2> for InTheta<'_, O> {
    fn samples_per_step(&self) -> usize {
        self.inner.samples_per_step()
    }
    fn observe(&mut self, t: f64, y: &[f64; 2]) {
        let y = self.theta(y);
        self.inner.observe(t, &y);
    }
    fn wants_steps(&self) -> bool {
        self.inner.wants_steps()
    }
    fn step(&mut self, t0: f64, t1: f64, dense: &dyn Fn(f64) -> [f64; 2]) {
        let (model, theta0) = (self.model, self.theta0);
        let to_theta = |y: [f64; 2]| {
            let (u, rate) = model.travel_and_rate(&y);
            [theta0 + u, rate]
        };
        self.inner.step(t0, t1, &|t| to_theta(dense(t)));
    }
}

/// Run the wall phase of `model` from t = 0 with `stepper` (started at y = [0, 0]) until the
/// separation or `t_end`; the end in the deviation form (y = [u, v]).
pub fn integrate<St: Stepper<2>, O: Observer<2>>(
    model: &NearRelease,
    stepper: &mut St,
    t_end: f64,
    max_steps: u64,
    observer: &mut O,
) -> Result<PhaseEnd<2>, RunError> {
    let event = NearSeparation(model);
    integrate_phase(model, stepper, &[&event], t_end, max_steps, observer)
}
