//! Events: sign changes of a function of the state, located on the integrator's own interpolant
//! to full f64 precision.
//!
//! **Never stepping over the separation.** On the wall-phase motion the wall force is
//! F_w = m l sin θ · g(θ, θ̇) with g = Ω² cos θ − θ̇² (see [`super::rigid::separation_factor`]).
//! Watching g, not F_w, removes the roots of sin θ at θ = 0 (the start of the classic problem)
//! and θ = π. On the energy integral g = 3Ω² cos θ − 2Ω² cos θ0 − θ̇0², so g < 0 exactly on
//! (θ_s, 2π − θ_s): its two roots are at least π apart in θ. The integrators therefore never take
//! a step with |Δθ| > 5/8 rad ([`super::rigid::event_safe_step`], enforced through
//! `Ode::max_step`), and a sign check at the step ends cannot miss a crossing. This costs no
//! extra evaluations (unlike sampling the dense output inside every step, which for DOP853
//! would add three stages per step) and limits steps only where they are a sizeable fraction of
//! the fall anyway. The Taylor method, whose steps at tight tolerances are longer than that,
//! may take |Δθ| up to 2.625 rad < π in the wall phase
//! ([`super::rigid::taylor_event_safe_step`]): still less than the roots' distance. Events that may touch zero and turn back (lift-off: the floor force) ask for
//! interior samples of the dense output as well ([`Event::interior_samples`]).
//!
//! **Refinement.** The root is found by Brent's method ([`brent`]) on the interpolant of the step
//! that brackets it, iterated until the bracket is two adjacent floats (tolerance zero).

use super::integrators::taylor::Series;

/// Most iterations of the root finders: enough to bisect from any positive f64 down to the
/// smallest (2098 halvings) and resolve the last binade. A bracket [0, h] whose root lies many
/// binades below h (a separation 1e-137 into a fixed step of 1, from a start 1e-273 rad from
/// the floor) needs ~440 halvings before Newton or interpolation can take over; with 200 the
/// finders stopped short and returned a time ~1e-60, far past the root (issue 17, F7).
const MAX_ITERATIONS: usize = 2200;

/// Which sign changes count.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// From negative to non-negative.
    Rising,
    /// From positive to non-positive.
    Falling,
}

/// A scalar function of `(t, y)` whose sign change ends a phase.
pub trait Event<const N: usize> {
    /// The event function.
    fn value(&self, t: f64, y: &[f64; N]) -> f64;
    /// Which crossing counts.
    fn direction(&self) -> Direction;
    /// Interior points of each step where the sign is checked too (0: ends only).
    fn interior_samples(&self) -> usize {
        0
    }
    /// d/dt of [`Event::value`] along a motion through `y` with state rate `dy` (None: not
    /// known; the root is then refined by Brent's method alone).
    fn rate(&self, _t: f64, _y: &[f64; N], _dy: &[f64; N]) -> Option<f64> {
        None
    }
    /// [`Event::value`] and its time derivative at τ into a step of the Taylor method, from the
    /// step's polynomials (the state's and those of sin and cos of `y[0]`); None when the event
    /// cannot (it is then evaluated on the interpolant). With it the root is found by Newton's
    /// method without a transcendental function per iterate.
    fn on_series(&self, _series: &Series<N>, _tau: f64) -> Option<(f64, f64)> {
        None
    }
    /// [`Event::value`] given (sin, cos) of `y[0]` as the stepper carries them
    /// ([`crate::sim::integrators::Stepper::trig`]): events that need them override this to
    /// save a transcendental function per step.
    fn value_with_trig(&self, t: f64, y: &[f64; N], _trig: (f64, f64)) -> f64 {
        self.value(t, y)
    }
}

/// Where [`newton_in_bracket`] starts: the secant's root (regula falsi) when it lies inside
/// the bracket (on a smooth event it is much nearer the root than either end, which saves
/// Newton iterations), else the end with the smaller value.
fn first_iterate(a: f64, b: f64, fa: f64, fb: f64) -> f64 {
    let secant = a - fa * ((b - a) / (fb - fa));
    if secant > a.min(b) && secant < a.max(b) {
        secant
    } else if fa.abs() < fb.abs() {
        a
    } else {
        b
    }
}

/// A root of `f` in the bracket `[a, b]` (`f(a)`, `f(b)` of opposite signs or one zero) by
/// Newton's method safeguarded by bisection, with `f` returning the value and its derivative.
/// Stops when the Newton correction is within 8 ulps of the iterate (rounding noise), when two
/// successive Newton corrections bound the rest within that noise (a contracting iteration), or
/// when the bracket is two adjacent floats; None when `f` has no derivative (the caller falls back to [`brent`]).
pub fn newton_in_bracket(
    f: impl Fn(f64) -> Option<(f64, f64)>,
    a: f64,
    b: f64,
    fa: f64,
    fb: f64,
) -> Option<f64> {
    if fa == 0.0 {
        return Some(a);
    }
    if fb == 0.0 {
        return Some(b);
    }
    // lo keeps the sign of fa, hi the sign of fb. As in `rtsafe` (Press et al., *Numerical
    // Recipes*, sec. 9.4): bisect when Newton would leave the bracket or is not halving the
    // step, so a poor derivative costs speed and the root stays in the bracket. (The stop on
    // a correction within the noise trusts the derivative: a slope k times too steep stops
    // within k times the noise.)
    let (mut lo, mut hi) = (a, b);
    let mut t = first_iterate(a, b, fa, fb);
    let (mut dx, mut dx_old) = ((b - a).abs(), (b - a).abs());
    // The previous iteration's Newton correction (None after a bisection or at the start).
    let mut last_newton: Option<f64> = None;
    for _ in 0..MAX_ITERATIONS {
        let (v, d) = f(t)?;
        if v == 0.0 {
            return Some(t);
        }
        if (v > 0.0) == (fa > 0.0) {
            lo = t;
        } else {
            hi = t;
        }
        let (l, h) = (lo.min(hi), lo.max(hi));
        let newton = t - v / d;
        // Near the root the event's value is rounding noise and so is the correction: a
        // correction of a few ulps means converged (bisecting on to adjacent floats would cost
        // ~50 more evaluations for digits the noise does not have). Checked before the bracket
        // test: a correction below half an ulp leaves `newton` equal to `t`, which the bracket
        // test would reject as outside (t is an end of it) and so bisect on.
        let noise = 8.0 * f64::EPSILON * t.abs().max(f64::MIN_POSITIVE);
        let c = (newton - t).abs();
        if c <= noise && newton >= l && newton <= h {
            return Some(newton);
        }
        // Two successive Newton corrections c_prev, c with c ≤ c_prev/2: while the iteration
        // contracts at least as fast (Newton near a simple root does, quadratically), the
        // corrections still to come sum to at most r c/(1 − r) ≤ 2 c²/c_prev (r = c/c_prev).
        // When that is within the noise, `newton` is the root and the evaluation that would
        // confirm it is saved.
        let converged =
            last_newton.is_some_and(|c_prev| c <= 0.5 * c_prev && 2.0 * c * c <= noise * c_prev);
        if converged && newton >= l && newton <= h {
            return Some(newton);
        }
        let next = if !(newton > l && newton < h) || (2.0 * v).abs() > (dx_old * d).abs() {
            dx_old = dx;
            dx = 0.5 * (h - l);
            last_newton = None;
            l + dx
        } else {
            dx_old = dx;
            dx = c;
            last_newton = Some(c);
            newton
        };
        if (next - t).abs() <= noise || h - l <= 2.0 * f64::EPSILON * h.abs().max(l.abs()) {
            return Some(next);
        }
        t = next;
    }
    Some(t)
}

/// Whether going from `before` to `after` is a crossing in `dir`.
pub fn crosses(dir: Direction, before: f64, after: f64) -> bool {
    match dir {
        Direction::Rising => before < 0.0 && after >= 0.0,
        Direction::Falling => before > 0.0 && after <= 0.0,
    }
}

/// Brent's root finder on `[a, b]` with `f(a)`, `f(b)` of opposite signs (or one zero).
/// Iterates until the bracket is as narrow as f64 allows; at most 2,200 iterations (`MAX_ITERATIONS`).
/// (R. P. Brent, *Algorithms for Minimization without Derivatives*, 1973, ch. 4, `zero`.)
pub fn brent(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64, mut fa: f64, mut fb: f64) -> f64 {
    if fa == 0.0 {
        return a;
    }
    if fb == 0.0 {
        return b;
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..MAX_ITERATIONS {
        if (fb > 0.0) == (fc > 0.0) {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol = 2.0 * f64::EPSILON * b.abs() + f64::MIN_POSITIVE;
        let m = 0.5 * (c - b);
        if m.abs() <= tol || fb == 0.0 {
            return b;
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            // Inverse quadratic (or secant) interpolation.
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else {
                let qa = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
                q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        fb = f(b);
    }
    b
}
