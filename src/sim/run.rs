//! The phase driver: step, watch the events, refine the first crossing on the interpolant,
//! feed an observer. Nothing is stored here; what is kept is the observer's business, so a run
//! that asks for nothing but the separation keeps O(1) memory.

use super::event::{brent, crosses, newton_in_bracket, Event};
use super::integrators::{Ode, StepError, Stepper};
use std::fmt;

/// Receives the accepted states of a run (and, if it asks, dense samples inside each step).
pub trait Observer<const N: usize> {
    /// Interior dense-output samples wanted per step (0: step ends only).
    fn samples_per_step(&self) -> usize {
        0
    }
    /// One state of the motion, in time order.
    fn observe(&mut self, t: f64, y: &[f64; N]);
    /// Whether [`Observer::step`] should be called (it costs preparing the dense output).
    fn wants_steps(&self) -> bool {
        false
    }
    /// After each accepted step: its span [t0, t1] (t1 the event time when one ended the phase)
    /// and its dense output, for observers that look between samples (minima of outputs).
    fn step(&mut self, _t0: f64, _t1: f64, _dense: &dyn Fn(f64) -> [f64; N]) {}
}

/// The observer that keeps nothing.
impl<const N: usize> Observer<N> for () {
    fn observe(&mut self, _t: f64, _y: &[f64; N]) {}
}

/// Why a run stopped early.
#[derive(Clone, Debug, PartialEq)]
pub enum RunError {
    /// The integrator failed.
    Step(StepError),
    /// The hard step limit was reached before the end.
    TooManySteps {
        /// The limit.
        limit: u64,
        /// Time reached.
        t: f64,
    },
    /// The floor force reached zero in the floor phase: the foot would leave the floor.
    LiftOff {
        /// Time of lift-off.
        t: f64,
        /// Angle there.
        theta: f64,
    },
    /// The run cannot start (e.g. at equilibrium nothing ever happens).
    Start(String),
}

impl fmt::Display for RunError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RunError::Step(e) => write!(f, "integration failed: {e}"),
            RunError::TooManySteps { limit, t } => write!(
                f,
                "stopped after the step limit of {limit} steps at t = {t}: use a larger step or tolerance"
            ),
            RunError::LiftOff { t, theta } => write!(
                f,
                "the floor force reaches zero at t = {t}, θ = {theta}: the foot would lift off the floor, which this model does not follow"
            ),
            RunError::Start(m) => f.write_str(m),
        }
    }
}

impl From<StepError> for RunError {
    fn from(e: StepError) -> Self {
        RunError::Step(e)
    }
}

/// Where a phase ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhaseEnd<const N: usize> {
    /// Time.
    pub t: f64,
    /// State.
    pub y: [f64; N],
    /// Index of the event that ended the phase, None when `t_end` was reached.
    pub event: Option<usize>,
}

/// Most events a phase watches.
pub const MAX_EVENTS: usize = 4;

/// Integrate until the first event crossing or `t_end`, at most `max_steps` steps.
/// The observer sees the state at every accepted step end (and dense samples if it asks), the
/// last one at the end of the phase; the caller reports the initial state.
pub fn integrate_phase<const N: usize, S: Ode<N>, St: Stepper<N>, O: Observer<N>>(
    sys: &S,
    stepper: &mut St,
    events: &[&dyn Event<N>],
    t_end: f64,
    max_steps: u64,
    observer: &mut O,
) -> Result<PhaseEnd<N>, RunError> {
    assert!(events.len() <= MAX_EVENTS, "too many events");
    let mut prev = [0.0; MAX_EVENTS];
    for (i, ev) in events.iter().enumerate() {
        let (t, y) = (stepper.t(), stepper.y());
        prev[i] = value_at(*ev, stepper, t, &y);
    }
    let mut steps = 0u64;
    loop {
        if steps >= max_steps {
            return Err(RunError::TooManySteps {
                limit: max_steps,
                t: stepper.t(),
            });
        }
        steps += 1;
        let t0 = stepper.t();
        stepper.step(sys, t_end)?;
        let (t1, y1) = (stepper.t(), stepper.y());
        let first = earliest_crossing(sys, stepper, events, &mut prev, (t0, t1, &y1));
        let t_stop = first.map_or(t1, |(r, _)| r);
        observe_step(sys, stepper, observer, t0, t1, t_stop);
        if let Some((root, i)) = first {
            let y = stepper.interpolate(root);
            observer.observe(root, &y);
            return Ok(PhaseEnd {
                t: root,
                y,
                event: Some(i),
            });
        }
        observer.observe(t1, &y1);
        if t1 >= t_end {
            return Ok(PhaseEnd {
                t: t1,
                y: y1,
                event: None,
            });
        }
    }
}

/// Event `ev`'s value at `(t, y)`, the stepper's state, given the (sin, cos) the stepper
/// carries when it does.
fn value_at<const N: usize, St: Stepper<N>>(
    ev: &dyn Event<N>,
    stepper: &St,
    t: f64,
    y: &[f64; N],
) -> f64 {
    match stepper.trig() {
        Some(trig) => ev.value_with_trig(t, y, trig),
        None => ev.value(t, y),
    }
}

/// The earliest crossing among the events over the step from `t0` to `(t1, y1)`: (root time,
/// event index). `prev` holds each event's value at `t0` and is moved on to `t1`.
fn earliest_crossing<const N: usize, S: Ode<N>, St: Stepper<N>>(
    sys: &S,
    stepper: &mut St,
    events: &[&dyn Event<N>],
    prev: &mut [f64; MAX_EVENTS],
    (t0, t1, y1): (f64, f64, &[f64; N]),
) -> Option<(f64, usize)> {
    let mut first: Option<(f64, usize)> = None;
    for (i, ev) in events.iter().enumerate() {
        let v1 = value_at(*ev, stepper, t1, y1);
        let bracket = find_bracket(sys, stepper, *ev, (t0, prev[i]), (t1, v1));
        prev[i] = v1;
        if let Some((a, fa, b, fb)) = bracket {
            if first.is_some_and(|(r, _)| r <= a) {
                continue;
            }
            let root = locate_root(sys, stepper, *ev, (a, fa), (b, fb));
            if first.is_none_or(|(r, _)| root < r) {
                first = Some((root, i));
            }
        }
    }
    first
}

/// Show the observer the step from `t0` to `t1`, cut at `t_stop`: its dense samples before
/// `t_stop` and the step's interpolant, when it asks for them.
fn observe_step<const N: usize, S: Ode<N>, St: Stepper<N>, O: Observer<N>>(
    sys: &S,
    stepper: &mut St,
    observer: &mut O,
    t0: f64,
    t1: f64,
    t_stop: f64,
) {
    let k = observer.samples_per_step();
    if k > 0 {
        stepper.prepare_dense(sys);
        for j in 1..=k {
            let tj = t0 + (t1 - t0) * j as f64 / (k + 1) as f64;
            if tj < t_stop {
                observer.observe(tj, &stepper.interpolate(tj));
            }
        }
    }
    if observer.wants_steps() {
        stepper.prepare_dense(sys);
        let dense = |t: f64| stepper.interpolate(t);
        observer.step(t0, t_stop, &dense);
    }
}

/// The first sign change of `ev` over the step from `(t0, v0)` to `(t1, v1)`, sampling the
/// step's interpolant at the event's interior points first: (a, f(a), b, f(b)).
fn find_bracket<const N: usize, S: Ode<N>, St: Stepper<N>>(
    sys: &S,
    stepper: &mut St,
    ev: &dyn Event<N>,
    (t0, v0): (f64, f64),
    (t1, v1): (f64, f64),
) -> Option<(f64, f64, f64, f64)> {
    let (mut ta, mut va) = (t0, v0);
    let k = ev.interior_samples();
    if k > 0 {
        stepper.prepare_dense(sys);
        for j in 1..=k {
            let tj = t0 + (t1 - t0) * j as f64 / (k + 1) as f64;
            let vj = ev.value(tj, &stepper.interpolate(tj));
            if crosses(ev.direction(), va, vj) {
                return Some((ta, va, tj, vj));
            }
            (ta, va) = (tj, vj);
        }
    }
    crosses(ev.direction(), va, v1).then_some((ta, va, t1, v1))
}

/// The root of `ev` in the bracket [a, b] of the last step.
fn locate_root<const N: usize, S: Ode<N>, St: Stepper<N>>(
    sys: &S,
    stepper: &mut St,
    ev: &dyn Event<N>,
    (a, fa): (f64, f64),
    (b, fb): (f64, f64),
) -> f64 {
    stepper.prepare_dense(sys);
    let t1 = stepper.t();
    let value_at = |s: &St, t: f64| ev.value(t, &s.interpolate(t));
    // The Taylor method with an event it can evaluate on the step's polynomials: Newton on
    // them (no transcendental function per iterate). At the step's ends fa and fb are already
    // the polynomials' values (the stepper's end values come from the same polynomials); a
    // sampled end is evaluated on them again.
    let t_prev = stepper.t_prev();
    let on_series = |t: f64| ev.on_series(stepper.step_series()?, t - t_prev);
    let at = |t: f64, v: f64, end: f64| {
        if t == end {
            Some(v)
        } else {
            on_series(t).map(|(v, _)| v)
        }
    };
    let on_poly = match (at(a, fa, t_prev), at(b, fb, t1)) {
        (Some(ia), Some(ib)) if ia * ib <= 0.0 => Some((ia, ib)),
        (Some(_), Some(_)) => Some((fa, fb)),
        _ => None,
    };
    // None when the event or the stepper has no polynomials.
    if let Some(r) = on_poly.and_then(|(fa, fb)| newton_in_bracket(on_series, a, b, fa, fb)) {
        return r;
    }
    // Refine on the interpolant; its end values may differ from the step's by a rounding, so
    // fall back to the step's values where they disagree in sign.
    let (ia, ib) = (value_at(stepper, a), value_at(stepper, b));
    let (fa, fb) = if ia * ib <= 0.0 { (ia, ib) } else { (fa, fb) };
    // Newton's method where the interpolant and the event have exact derivatives (the Taylor
    // method), else Brent's.
    let with_rate = |t: f64| {
        let dy = stepper.interpolate_rate(t)?;
        let y = stepper.interpolate(t);
        Some((ev.value(t, &y), ev.rate(t, &y, &dy)?))
    };
    newton_in_bracket(with_rate, a, b, fa, fb)
        .unwrap_or_else(|| brent(|t| value_at(stepper, t), a, b, fa, fb))
}
