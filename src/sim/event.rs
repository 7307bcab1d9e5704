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
//! the fall anyway. Events that may touch zero and turn back (lift-off: the floor force) ask for
//! interior samples of the dense output as well ([`Event::interior_samples`]).
//!
//! **Refinement.** The root is found by Brent's method ([`brent`]) on the interpolant of the step
//! that brackets it, iterated until the bracket is two adjacent floats (tolerance zero).

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
}

/// Whether going from `before` to `after` is a crossing in `dir`.
pub fn crosses(dir: Direction, before: f64, after: f64) -> bool {
    match dir {
        Direction::Rising => before < 0.0 && after >= 0.0,
        Direction::Falling => before > 0.0 && after <= 0.0,
    }
}

/// Brent's root finder on `[a, b]` with `f(a)`, `f(b)` of opposite signs (or one zero).
/// Iterates until the bracket is as narrow as f64 allows; at most 200 iterations.
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
    for _ in 0..200 {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brent_finds_cos_root_to_the_last_ulp() {
        let r = brent(f64::cos, 1.0, 2.0, 1f64.cos(), 2f64.cos());
        assert!((r - std::f64::consts::FRAC_PI_2).abs() <= 2.0 * f64::EPSILON * 2.0);
    }

    #[test]
    fn crossing_needs_the_right_direction() {
        assert!(crosses(Direction::Falling, 1.0, -1.0));
        assert!(!crosses(Direction::Falling, -1.0, 1.0));
        assert!(crosses(Direction::Rising, -1.0, 0.0));
        assert!(!crosses(Direction::Rising, 0.0, 1.0));
    }
}
