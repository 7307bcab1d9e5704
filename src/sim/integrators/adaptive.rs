//! Step scaffolding shared by the adaptive methods (Hairer, Nørsett & Wanner, *Solving ODEs I*,
//! sec. II.4, and the drivers of dopri5.f / dop853.f): the first slope with FSAL reuse, the
//! proposal of the first step, the clipping of the last step to the stop time, the
//! step-too-small test, the PI step-size controller and the accept/reject bookkeeping.
//!
//! Each method keeps its own tableau, error estimate and dense output in its own file; what is
//! here is the part that does not depend on the formula.

use super::{all_finite, eval, initial_step, Ode, Stats, StepError};
use crate::sim::exact::twofold::two_sum;

/// The time after an accepted step `h` from `t` whose rounding so far is `lo` (the exact time
/// is t + lo): the new (t, lo) by Knuth's TwoSum, so that a long run's time carries one
/// rounding, not one per step. Summed as t + h, a run of n steps drifted by up to n half-ulps
/// of t (issue 38: radau5 at tolerance 1e-16 from θ0 = 0.3, 4,656 steps, t_s off by 5.9e-14
/// relative where θ_s was within 2.5e-16). Used by every adaptive method (dopri5, dop853,
/// radau5, taylor); `t_stop` ends a run exactly (lo = 0).
pub fn advance_time(t: f64, lo: f64, h: f64, last: bool, t_stop: f64) -> (f64, f64) {
    if last {
        return (t_stop, 0.0);
    }
    two_sum(t, h + lo)
}

/// Start of an adaptive step at `(t, y)`: the first slope (the cached `fsal` slope when there is
/// one, else a fresh evaluation), its finiteness check, the model's longest step, and, when no
/// step has been proposed yet (`*h == 0`), the initial step for a method of order `order`.
///
/// Returns the first slope and the longest step allowed.
#[allow(clippy::too_many_arguments)]
pub fn start_step<const N: usize, S: Ode<N>>(
    sys: &S,
    t: f64,
    y: &[f64; N],
    fsal: Option<[f64; N]>,
    rtol: f64,
    order: i32,
    h: &mut f64,
    stats: &mut Stats,
) -> Result<([f64; N], f64), StepError> {
    let f0 = match fsal {
        Some(f) => f,
        None => {
            stats.rhs_evals += 1;
            eval(sys, t, y)
        }
    };
    if !all_finite(&f0) {
        return Err(StepError::NotFinite { t });
    }
    let h_max = sys.max_step(y);
    if *h == 0.0 {
        *h = initial_step(sys, t, y, &f0, rtol, order, h_max, &mut stats.rhs_evals);
    }
    Ok((f0, h_max))
}

/// The step to try from `t` given the proposal `h`: at most `h_max`, clipped to land on `t_stop`.
///
/// Returns the step and whether it is the last one before `t_stop`, or
/// [`StepError::StepTooSmall`] when the step is below what f64 resolves at `t`.
pub fn trial_step(h: f64, h_max: f64, t: f64, t_stop: f64) -> Result<(f64, bool), StepError> {
    let mut h = h.min(h_max);
    // A remainder below 1e-8 h would only be a rounding-sized extra step: take it now.
    let last = t + h >= t_stop || t_stop - (t + h) <= 1e-8 * h;
    if last {
        h = t_stop - t;
    }
    if h <= 10.0 * f64::EPSILON * t.abs().max(1e-300) || h <= 0.0 {
        return Err(StepError::StepTooSmall { t, h });
    }
    Ok((h, last))
}

/// Parameters of the step-size controller of dopri5.f / dop853.f: the new step is `h / fac` with
/// `fac = err^expo / facold^beta / 0.9` clamped to `[fac_lo, fac_hi]` (`beta = 0`: plain I
/// control).
#[derive(Clone, Copy, Debug)]
pub struct Controller {
    /// Exponent of the error in `fac` (`1/(q+1)` less `0.75 beta` for an estimate of order `q`).
    pub expo: f64,
    /// Exponent of the last accepted error (the PI part).
    pub beta: f64,
    /// Smallest `fac` (largest growth of the step is `1 / fac_lo`).
    pub fac_lo: f64,
    /// Largest `fac` (largest shrink of the step is `1 / fac_hi`).
    pub fac_hi: f64,
}

/// The state an explicit adaptive Runge-Kutta stepper carries between steps, apart from its
/// stages and dense output.
#[derive(Clone, Debug)]
pub struct AdaptiveState<const N: usize> {
    /// Relative tolerance.
    pub rtol: f64,
    /// End of the last accepted step.
    pub t: f64,
    /// The rounding of `t` so far: the exact sum of the steps is t + t_lo ([`advance_time`]).
    pub t_lo: f64,
    /// State at `t`.
    pub y: [f64; N],
    /// The slope at `(t, y)` when the last step computed it (first same as last).
    pub f: Option<[f64; N]>,
    /// The proposed next step (0 until the first step chooses one).
    pub h: f64,
    /// The last accepted error (PI control memory).
    pub facold: f64,
    /// Whether the last trial was rejected (then the next accepted step may not grow).
    pub last_rejected: bool,
    /// Start of the last accepted step.
    pub t_prev: f64,
    /// State at `t_prev`.
    pub y_prev: [f64; N],
    /// Counters.
    pub stats: Stats,
}

impl<const N: usize> AdaptiveState<N> {
    /// Start at `(t0, y0)` with relative tolerance `rtol`.
    pub fn new(t0: f64, y0: [f64; N], rtol: f64) -> Self {
        AdaptiveState {
            rtol,
            t: t0,
            t_lo: 0.0,
            y: y0,
            f: None,
            h: 0.0,
            facold: 1e-4,
            last_rejected: false,
            t_prev: t0,
            y_prev: y0,
            stats: Stats::default(),
        }
    }

    /// [`start_step`] from the current point, reusing the cached slope.
    pub fn start<S: Ode<N>>(&mut self, sys: &S, order: i32) -> Result<([f64; N], f64), StepError> {
        let (t, y, f) = (self.t, self.y, self.f);
        start_step(
            sys,
            t,
            &y,
            f,
            self.rtol,
            order,
            &mut self.h,
            &mut self.stats,
        )
    }

    /// Reject a trial step `h` whose error or new state is not finite: shrink hard.
    pub fn reject_non_finite(&mut self, h: f64) {
        self.stats.rejected += 1;
        self.h = h * 0.1;
        self.last_rejected = true;
    }

    /// Judge a trial step `h` with finite error norm `err`. On acceptance (`err <= 1`) returns
    /// the next step proposal; on rejection records it, shrinks the proposal and returns `None`.
    pub fn control(&mut self, ctrl: &Controller, h: f64, err: f64) -> Option<f64> {
        let fac11 = err.powf(ctrl.expo);
        if err <= 1.0 {
            let fac = (fac11 / self.facold.powf(ctrl.beta) / 0.9).clamp(ctrl.fac_lo, ctrl.fac_hi);
            self.facold = err.max(1e-4);
            let mut h_new = h / fac;
            if self.last_rejected {
                h_new = h_new.min(h);
            }
            return Some(h_new);
        }
        self.stats.rejected += 1;
        self.last_rejected = true;
        self.h = h / (fac11 / 0.9).min(ctrl.fac_hi);
        None
    }

    /// Accept the step `h` from `(t, y)` to `y1` with slope `f1` there; `h_new` becomes the next
    /// proposal unless this was the `last` step before `t_stop`.
    pub fn accept(
        &mut self,
        h: f64,
        h_new: f64,
        last: bool,
        t_stop: f64,
        y1: [f64; N],
        f1: [f64; N],
    ) {
        self.last_rejected = false;
        self.t_prev = self.t;
        self.y_prev = self.y;
        (self.t, self.t_lo) = advance_time(self.t, self.t_lo, h, last, t_stop);
        self.y = y1;
        self.f = Some(f1);
        if !last {
            self.h = h_new;
        }
        self.stats.steps += 1;
    }
}
