//! Time integrators with dense output, written by hand.
//!
//! Why by hand: no Rust crate offers DOP853 with dense output *and* event location on that
//! interpolant (ode_solvers 0.6 stops only at step boundaries; differential-equations 0.7 was
//! found off by 1e-3 in its dense output), and the event logic of this project (never step over
//! the separation, refine the root on the interpolant) needs access to every accepted step.
//!
//! Every method implements [`Stepper`]: it advances one accepted step at a time, never past a
//! stop time and never longer than the model's [`Ode::max_step`], and after each step offers an
//! interpolant over the step just taken ([`Stepper::prepare_dense`], [`Stepper::interpolate`]).
//! Fixed-step methods interpolate with a cubic Hermite polynomial (free: the end slope is the
//! next step's first stage); the adaptive methods use their own dense output formulas.
//!
//! Models implement [`Ode`] once, generic over the scalar, so the same right-hand side runs in
//! `f64` and in `num_dual::Dual64` (the implicit method's Jacobian, column by column).

// Index loops mirror the formulas (a_ij k_j, J_ij) and are kept on purpose.
#![allow(clippy::needless_range_loop)]

pub mod adaptive;
pub mod card;
pub mod dense_lu;
mod dop853_tables;
pub mod fixed;
#[macro_use]
mod table;
pub mod taylor_f64;
pub mod taylor_poly;
pub mod taylor_series;

pub use table::Integrator;

// The list of integrators, one line each: its module and its stepper type (`table` makes the
// module, the variant of `AnyStepper` and the entry of `TABLE` from it).
integrators! {
    euler::Euler,
    symplectic_euler::SymplecticEuler,
    verlet::Verlet,
    rk4::Rk4,
    dopri5::Dopri5,
    dop853::Dop853,
    radau5::Radau5,
    taylor::Taylor,
}

impl<const N: usize> AnyStepper<N> {
    /// The method called `name` (a name of [`TABLE`]) with its step or tolerance, or None when
    /// the name is unknown or the control does not fit the method.
    #[inline]
    pub fn new(name: &str, control: Control, t0: f64, y0: [f64; N]) -> Option<Self> {
        Self::with_order(name, control, None, t0, y0)
    }
}

use num_dual::DualNum;
use std::fmt;

/// A first-order system y' = f(t, y) of dimension `N`.
///
/// Second-order models order the state as `[q_1..q_d, v_1..v_d]` with `N = 2d` and return
/// `[v, a(q, v)]`; the symplectic methods rely on that layout.
pub trait Ode<const N: usize> {
    /// The right-hand side, generic over the scalar so that it also runs in dual numbers.
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, t: f64, y: &[D; N]) -> [D; N];

    /// The longest step allowed from state `y` (event safety; see `sim::event`).
    fn max_step(&self, _y: &[f64; N]) -> f64 {
        f64::INFINITY
    }

    /// The longest step the Taylor method may take from `y`: [`Ode::max_step`] unless the model
    /// proves a wider bound (the wall phase: [`crate::sim::rigid::taylor_event_safe_step`]).
    fn taylor_max_step(&self, y: &[f64; N]) -> f64 {
        self.max_step(y)
    }

    /// Characteristic magnitude of each component at `y`, used by the error norm
    /// `|err_i| / (rtol * scale_i)`. Default: `|y_i|` (pure relative control).
    fn scale(&self, y: &[f64; N]) -> [f64; N] {
        y.map(f64::abs)
    }

    /// Components that act as *index-2* variables in the stiff limit (Hairer & Wanner II,
    /// sec. VII.4): rates of stiff components whose own values are nearly algebraic, so that an
    /// implicit method determines them only to (rounding of the values)/h. Implicit methods
    /// divide their error weight by min(h, 1), as radau5.f does for index-2 variables.
    /// Default: none.
    fn index2(&self) -> [bool; N] {
        [false; N]
    }

    /// Whether the acceleration of a second-order model depends on the velocity
    /// (then Störmer-Verlet solves its implicit half step by fixed-point iteration).
    fn accel_uses_velocity(&self) -> bool {
        true
    }

    /// The Taylor coefficients of the solution through `series.y[i][0]` (with sin and cos of
    /// `y[0]` in `series.sin[0]`, `series.cos[0]`) to order `series.order`, for the Taylor
    /// method ([`taylor`]). Default: the model has no recursion (`false`).
    fn taylor_series(&self, _series: &mut taylor::Series<N>) -> bool {
        false
    }
}

/// Evaluate `sys.rhs` in `f64`.
#[inline]
pub fn eval<const N: usize, S: Ode<N>>(sys: &S, t: f64, y: &[f64; N]) -> [f64; N] {
    sys.rhs::<f64>(t, y)
}

/// Counters that tests and reports read.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Right-hand-side evaluations in f64 (including dense-output stages).
    pub rhs_evals: u64,
    /// Jacobian evaluations (each costs `N` dual-number right-hand sides, not counted above).
    pub jacobians: u64,
    /// Accepted steps.
    pub steps: u64,
    /// Rejected steps.
    pub rejected: u64,
}

/// Why a step could not be taken.
#[derive(Clone, Debug, PartialEq)]
pub enum StepError {
    /// The step size fell below what f64 can resolve at time `t`.
    StepTooSmall { t: f64, h: f64 },
    /// The right-hand side or the new state was not finite.
    NotFinite { t: f64 },
    /// Newton's method did not converge even at tiny steps (implicit methods).
    NewtonFailed { t: f64 },
    /// The Taylor method was asked to integrate a model without Taylor recursions.
    NoTaylorSeries { t: f64 },
}

impl fmt::Display for StepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StepError::StepTooSmall { t, h } => {
                write!(
                    f,
                    "step size {h:e} too small at t = {t} (tolerance unreachable)"
                )
            }
            StepError::NotFinite { t } => write!(f, "state became non-finite at t = {t}"),
            StepError::NewtonFailed { t } => write!(f, "Newton iteration failed at t = {t}"),
            StepError::NoTaylorSeries { t } => write!(
                f,
                "the Taylor method has no recursion for this model (at t = {t}); it covers the rigid wall and floor phases"
            ),
        }
    }
}

/// How a method is driven: fixed step or adaptive tolerance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Control {
    /// Fixed step size `h` (seconds); the last step is shortened to land on a stop time.
    Fixed(f64),
    /// Relative tolerance for the adaptive methods (error norm from [`Ode::scale`]).
    Tolerance(f64),
}

/// One accepted step at a time, with an interpolant over the last step.
pub trait Stepper<const N: usize> {
    /// Current time (end of the last accepted step).
    fn t(&self) -> f64;
    /// Current state.
    fn y(&self) -> [f64; N];
    /// Start of the last accepted step.
    fn t_prev(&self) -> f64;
    /// Take one accepted step, ending at or before `t_stop`.
    fn step<S: Ode<N>>(&mut self, sys: &S, t_stop: f64) -> Result<(), StepError>;
    /// Make [`Stepper::interpolate`] valid over the last step (may evaluate the rhs).
    fn prepare_dense<S: Ode<N>>(&mut self, sys: &S);
    /// The interpolant at `t` in `[t_prev, t]` (call [`Stepper::prepare_dense`] first).
    fn interpolate(&self, t: f64) -> [f64; N];
    /// The time derivative of the interpolant at `t`, when the method has it exactly (the
    /// Taylor method: its step's polynomial); events are then refined by Newton's method.
    fn interpolate_rate(&self, _t: f64) -> Option<[f64; N]> {
        None
    }
    /// The Taylor method's series of the last step (in τ = t − t_prev), from which an event may
    /// form its own polynomial ([`Taylor::series`](taylor::Taylor::series)); None for other methods.
    fn step_series(&self) -> Option<&taylor::Series<N>> {
        None
    }
    /// (sin, cos) of `y[0]` at the current state when the stepper carries them (the Taylor
    /// method: the values of their own series), so an event needs no sin or cos per step
    /// ([`crate::sim::event::Event::value_with_trig`]); None for other methods.
    fn trig(&self) -> Option<(f64, f64)> {
        None
    }
    /// Counters so far.
    fn stats(&self) -> Stats;
}

/// Weighted RMS norm of `err` with weights `rtol * max(scale(y0), scale(y1))`.
pub fn error_norm<const N: usize, S: Ode<N>>(
    sys: &S,
    err: &[f64; N],
    y0: &[f64; N],
    y1: &[f64; N],
    rtol: f64,
) -> f64 {
    let (s0, s1) = (sys.scale(y0), sys.scale(y1));
    // The floor keeps the weight positive at an exact equilibrium (all scales zero).
    let ratio: [f64; N] =
        std::array::from_fn(|i| err[i] / (rtol * s0[i].max(s1[i])).max(f64::MIN_POSITIVE));
    rms(&ratio)
}

/// The root mean square of `ratio`, without overflow: a state of size 1e-273 (a start that
/// close to the floor) has error ratios ~1e284 whose squares overflow, and an infinite norm
/// made the first step 0 (issue 17, F7). NaN stays NaN.
pub fn rms<const N: usize>(ratio: &[f64; N]) -> f64 {
    let sum: f64 = ratio.iter().map(|r| r * r).sum();
    if sum.is_finite() || sum.is_nan() {
        return (sum / N as f64).sqrt();
    }
    let big = ratio.iter().fold(0.0f64, |m, r| m.max(r.abs()));
    if big.is_infinite() {
        return big;
    }
    let sum: f64 = ratio.iter().map(|r| (r / big).powi(2)).sum();
    big * (sum / N as f64).sqrt()
}

/// Initial step size (Hairer, Nørsett & Wanner, *Solving ODEs I*, sec. II.4, "Starting step
/// size"; the `hinit` routine of dopri5.f / dop853.f), for a method of order `order`.
#[allow(clippy::too_many_arguments)]
pub fn initial_step<const N: usize, S: Ode<N>>(
    sys: &S,
    t: f64,
    y0: &[f64; N],
    f0: &[f64; N],
    rtol: f64,
    order: i32,
    h_max: f64,
    evals: &mut u64,
) -> f64 {
    let d0 = error_norm(sys, y0, y0, y0, rtol);
    let d1 = error_norm(sys, f0, y0, y0, rtol);
    let mut h0 = if d0 < 1e-5 || d1 < 1e-5 {
        1e-6
    } else {
        0.01 * d0 / d1
    };
    h0 = h0.min(h_max);
    let y1: [f64; N] = std::array::from_fn(|i| y0[i] + h0 * f0[i]);
    let f1 = eval(sys, t + h0, &y1);
    *evals += 1;
    let df: [f64; N] = std::array::from_fn(|i| f1[i] - f0[i]);
    let d2 = error_norm(sys, &df, y0, y0, rtol) / h0;
    let h1 = if d1.max(d2) <= 1e-15 {
        (h0 * 1e-3).max(1e-6)
    } else {
        (0.01 / d1.max(d2)).powf(1.0 / f64::from(order + 1))
    };
    (100.0 * h0).min(h1).min(h_max)
}

/// Cubic Hermite interpolant through `(t0, y0, f0)` and `(t0 + h, y1, f1)`.
pub fn hermite<const N: usize>(
    t0: f64,
    h: f64,
    y0: &[f64; N],
    f0: &[f64; N],
    y1: &[f64; N],
    f1: &[f64; N],
    t: f64,
) -> [f64; N] {
    let s = (t - t0) / h;
    let (s2, s3) = (s * s, s * s * s);
    let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
    let h10 = s3 - 2.0 * s2 + s;
    let h01 = -2.0 * s3 + 3.0 * s2;
    let h11 = s3 - s2;
    std::array::from_fn(|i| h00 * y0[i] + h10 * h * f0[i] + h01 * y1[i] + h11 * h * f1[i])
}

/// The card of the method called `name`, if the table has one.
pub fn card(name: &str) -> Option<&'static card::Card> {
    TABLE.iter().copied().find(|c| c.name == name)
}

/// The names of every method, in the table's order (a rigid scene may name any of them).
pub fn names() -> impl Iterator<Item = &'static str> {
    TABLE.iter().map(|c| c.name)
}

/// The names of the methods that run on any model (not only the rigid phases): what a scene
/// with penalty contact, or the constrained model, may name.
pub fn any_model_names() -> impl Iterator<Item = &'static str> {
    TABLE.iter().filter(|c| !c.rigid_only).map(|c| c.name)
}

/// Whether `method` takes a tolerance (adaptive) rather than a step; false for a name the table
/// does not know.
pub fn is_adaptive(method: &str) -> bool {
    card(method).is_some_and(|c| c.is_adaptive())
}

/// The classical order of `method` (None for the Taylor method, whose order follows the
/// tolerance, [`taylor::order_for`], and for a name the table does not know).
pub fn order(method: &str) -> Option<u32> {
    card(method).and_then(|c| c.order)
}

/// True when every component is finite.
#[inline]
pub fn all_finite<const N: usize>(y: &[f64; N]) -> bool {
    y.iter().all(|v| v.is_finite())
}
