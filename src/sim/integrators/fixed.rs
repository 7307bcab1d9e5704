//! The driver shared by the fixed-step methods: step bookkeeping, the cached slope, and the cubic
//! Hermite interpolant over the last step (free, since the end slope is the next step's first
//! stage).
//!
//! **Time on the grid.** The time after n whole steps from t0 is t0 + n h, rounded once, not
//! the running sum t + h: that sum rounds at every step, each time by up to half an ulp of t,
//! and the roundings of one step size at times of one binade lean the same way, so the error
//! grew with the number of steps (issue 38: rk4's separation time from θ0 = 1e-4 at rest, off by
//! 1.15e-12 relative at h = 1e-4 T, 1.1e5 steps). A step shortened by the event-safety cap or
//! to land on the stop time starts a new grid at its end.

use super::{all_finite, eval, hermite, Control, Integrator, Ode, Stats, StepError, Stepper};

/// One step of a fixed-step method.
pub trait FixedMethod<const N: usize> {
    /// Advance from `(t, y)` with slope `f0 = f(t, y)` by `h`. Returns the new state and, when the
    /// method computed it anyway, the slope there. Adds its own rhs evaluations to `evals`.
    fn advance<S: Ode<N>>(
        sys: &S,
        t: f64,
        y: &[f64; N],
        f0: &[f64; N],
        h: f64,
        evals: &mut u64,
    ) -> ([f64; N], Option<[f64; N]>);
}

/// A one-stage fixed-step method: its step needs only the first slope `f0 = f(t, y)`, so it
/// evaluates nothing itself (explicit and symplectic Euler). Every such method is a
/// [`FixedMethod`].
pub trait SlopeOnlyMethod<const N: usize> {
    /// The state after a step `h` from `y` with slope `f0`.
    fn update(y: &[f64; N], f0: &[f64; N], h: f64) -> [f64; N];
}

impl<M: SlopeOnlyMethod<N>, const N: usize> FixedMethod<N> for M {
    fn advance<S: Ode<N>>(
        _sys: &S,
        _t: f64,
        y: &[f64; N],
        f0: &[f64; N],
        h: f64,
        _evals: &mut u64,
    ) -> ([f64; N], Option<[f64; N]>) {
        (M::update(y, f0, h), None)
    }
}

/// A fixed-step integrator built from a [`FixedMethod`].
#[derive(Clone, Debug)]
pub struct FixedStep<M, const N: usize> {
    h: f64,
    t: f64,
    y: [f64; N],
    f: Option<[f64; N]>,
    t_prev: f64,
    y_prev: [f64; N],
    f_prev: [f64; N],
    /// The grid's origin and the whole steps taken on it (module docs).
    grid: (f64, u64),
    stats: Stats,
    _method: std::marker::PhantomData<M>,
}

impl<M: FixedMethod<N>, const N: usize> Integrator<N> for FixedStep<M, N> {
    fn start(t0: f64, y0: [f64; N], control: Control, _order: Option<usize>) -> Option<Self> {
        match control {
            Control::Fixed(h) => Some(FixedStep::new(t0, y0, h)),
            Control::Tolerance(_) => None,
        }
    }
}

impl<M: FixedMethod<N>, const N: usize> FixedStep<M, N> {
    /// Start at `(t0, y0)` with step `h > 0`.
    pub fn new(t0: f64, y0: [f64; N], h: f64) -> Self {
        FixedStep {
            h,
            t: t0,
            y: y0,
            f: None,
            t_prev: t0,
            y_prev: y0,
            f_prev: [0.0; N],
            grid: (t0, 0),
            stats: Stats::default(),
            _method: std::marker::PhantomData,
        }
    }

    fn slope<S: Ode<N>>(&mut self, sys: &S) -> [f64; N] {
        match self.f {
            Some(f) => f,
            None => {
                self.stats.rhs_evals += 1;
                let f = eval(sys, self.t, &self.y);
                self.f = Some(f);
                f
            }
        }
    }
}

impl<M: FixedMethod<N>, const N: usize> Stepper<N> for FixedStep<M, N> {
    fn t(&self) -> f64 {
        self.t
    }
    fn y(&self) -> [f64; N] {
        self.y
    }
    fn t_prev(&self) -> f64 {
        self.t_prev
    }

    fn step<S: Ode<N>>(&mut self, sys: &S, t_stop: f64) -> Result<(), StepError> {
        // A step longer than the event-safety cap is shortened (documented in sim::event).
        let mut h = self.h.min(sys.max_step(&self.y));
        if self.t + h >= t_stop || t_stop - (self.t + h) < 1e-9 * h {
            h = t_stop - self.t;
        }
        if h <= 4.0 * f64::EPSILON * self.t.abs().max(1.0) {
            return Err(StepError::StepTooSmall { t: self.t, h });
        }
        let f0 = self.slope(sys);
        let (y1, f1) = M::advance(sys, self.t, &self.y, &f0, h, &mut self.stats.rhs_evals);
        if !all_finite(&y1) {
            return Err(StepError::NotFinite { t: self.t });
        }
        self.t_prev = self.t;
        self.y_prev = self.y;
        self.f_prev = f0;
        self.t = if self.t + h == t_stop || h == t_stop - self.t_prev {
            t_stop
        } else if h == self.h {
            // A whole step on the grid: t0 + n h.
            self.grid.1 += 1;
            self.grid.0 + self.grid.1 as f64 * h
        } else {
            self.t_prev + h
        };
        if h != self.h || self.t == t_stop {
            self.grid = (self.t, 0);
        }
        self.y = y1;
        self.f = f1;
        self.stats.steps += 1;
        Ok(())
    }

    fn prepare_dense<S: Ode<N>>(&mut self, sys: &S) {
        self.slope(sys);
    }

    fn interpolate(&self, t: f64) -> [f64; N] {
        let f1 = self.f.expect("prepare_dense before interpolate");
        let h = self.t - self.t_prev;
        if h == 0.0 {
            return self.y;
        }
        hermite(self.t_prev, h, &self.y_prev, &self.f_prev, &self.y, &f1, t)
    }

    fn stats(&self) -> Stats {
        self.stats
    }
}
