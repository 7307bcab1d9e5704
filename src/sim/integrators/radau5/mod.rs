//! RADAU5: the 3-stage Radau IIA collocation method of order 5, implicit and L-stable, for stiff
//! problems (the penalty contact model); simplified Newton iterations with the Jacobian by
//! automatic differentiation (`num_dual::Dual64`, one column per dual evaluation), kept across
//! steps while Newton contracts fast and the LU factors kept while the step size stays
//! (radau5.f's strategy), and the error estimate's second, filtered form whenever the first
//! fails (stiff springs no longer reject every first trial).
//!
//! Source: E. Hairer and G. Wanner, *Solving Ordinary Differential Equations II*, 2nd ed.,
//! sec. IV.5 (Table 5.6: the Radau IIA tableau), IV.8 (Newton iteration, error estimate with the
//! constants `DD1..DD3` and `U1` of the Fortran code `radau5.f`, step-size rule). Unlike
//! radau5.f, the stage system is solved directly as one real 3N x 3N system (no transformation
//! to a real and a complex system): for the ladder N is 2 or 4, where that is simplest and fast.
//! The dense output is the collocation polynomial itself.

mod stages;

use super::adaptive::{advance_time, start_step, trial_step};
use super::Integrator;
use super::dense_lu::lu_factor;
use super::{all_finite, Ode, Stats, StepError, Stepper};
use num_dual::Dual64;
use super::card::{Card, ControlKind, Stiffness, Sweep};
use super::Control;

const SQ6: f64 = 2.449_489_742_783_178;
/// Collocation nodes c1, c2, c3 = 1.
pub(super) const C: [f64; 3] = [(4.0 - SQ6) / 10.0, (4.0 + SQ6) / 10.0, 1.0];
/// The Radau IIA(5) matrix (Hairer-Wanner II, Table IV.5.6).
pub const A: [[f64; 3]; 3] = [
    [
        (88.0 - 7.0 * SQ6) / 360.0,
        (296.0 - 169.0 * SQ6) / 1800.0,
        (-2.0 + 3.0 * SQ6) / 225.0,
    ],
    [
        (296.0 + 169.0 * SQ6) / 1800.0,
        (88.0 + 7.0 * SQ6) / 360.0,
        (-2.0 - 3.0 * SQ6) / 225.0,
    ],
    [(16.0 - SQ6) / 36.0, (16.0 + SQ6) / 36.0, 1.0 / 9.0],
];
/// Error-estimate weights of radau5.f (`DD1`, `DD2`, `DD3`).
pub(super) const DD: [f64; 3] = [
    -(13.0 + 7.0 * SQ6) / 3.0,
    (-13.0 + 7.0 * SQ6) / 3.0,
    -1.0 / 3.0,
];
/// Newton iterations allowed per step.
pub(super) const MAX_NEWTON: usize = 7;

/// The real eigenvalue of A⁻¹ (radau5.f `U1`), 30 / (6 + 81^(1/3) - 9^(1/3)).
pub fn u1() -> f64 {
    30.0 / (6.0 + 81f64.cbrt() - 9f64.cbrt())
}

/// The Jacobian ∂f/∂y at `(t, y)`, one column per dual-number evaluation.
pub fn jacobian<const N: usize, S: Ode<N>>(sys: &S, t: f64, y: &[f64; N]) -> [[f64; N]; N] {
    let mut jac = [[0.0; N]; N];
    for j in 0..N {
        let yd: [Dual64; N] =
            std::array::from_fn(|i| Dual64::new(y[i], if i == j { 1.0 } else { 0.0 }));
        let f = sys.rhs(t, &yd);
        for i in 0..N {
            jac[i][j] = f[i].eps;
        }
    }
    jac
}

/// The weighted RMS norm of [`super::error_norm`] with the index-2 components' weights
/// ([`Ode::index2`]) divided by min(h, 1): their values are known only to (rounding)/h, and a
/// fixed weight would make the error estimate grow as h shrinks (a step-size collapse).
pub(super) fn step_norm<const N: usize, S: Ode<N>>(
    sys: &S,
    err: &[f64; N],
    y0: &[f64; N],
    y1: &[f64; N],
    rtol: f64,
    h: f64,
) -> f64 {
    let (s0, s1, idx2) = (sys.scale(y0), sys.scale(y1), sys.index2());
    let hfac = h.abs().min(1.0);
    let ratio: [f64; N] = std::array::from_fn(|i| {
        let mut sk = rtol * s0[i].max(s1[i]);
        if idx2[i] {
            sk /= hfac;
        }
        // The floor keeps the weight positive at an exact equilibrium (all scales zero).
        err[i] / sk.max(f64::MIN_POSITIVE)
    });
    super::rms(&ratio)
}


/// The card of Radau IIA 5 ([`mod@super::card`]).
pub const CARD: Card = Card {
    name: "radau5",
    title: "Radau IIA 5",
    control: ControlKind::Tolerance,
    order: Some(5),
    // The collocation polynomial of degree 3 (stage order 3).
    dense_order: Some(4),
    stiffness: Stiffness::Implicit,
    rigid_only: false,
    sweep: Sweep::Tolerances { from: 3, to: 13, per_decade: 1 },
    penalty_fit: None,
    stiff_case: Some(Control::Tolerance(1e-10)),
};
/// The Radau IIA(5) integrator.
#[derive(Clone, Debug)]
pub struct Radau5<const N: usize> {
    rtol: f64,
    newton_rtol: f64,
    eta: f64,
    t: f64,
    y: [f64; N],
    h: f64,
    t_prev: f64,
    /// The rounding of `t` so far (`adaptive::advance_time`).
    t_lo: f64,
    y_prev: [f64; N],
    z: [[f64; N]; 3],
    have_prev: bool,
    lu: Vec<f64>,
    piv: Vec<usize>,
    e1: Vec<f64>,
    piv1: Vec<usize>,
    /// The Jacobian in use and whether it was formed at the current point.
    jac: Option<[[f64; N]; N]>,
    jac_fresh: bool,
    /// The step the factors `lu` and `e1` belong to (0: none).
    lu_h: f64,
    stats: Stats,
}

impl<const N: usize> Radau5<N> {
    /// Start at `(t0, y0)` with relative tolerance `rtol`.
    pub fn new(t0: f64, y0: [f64; N], rtol: f64) -> Self {
        Radau5 {
            rtol,
            newton_rtol: rtol,
            eta: 1.0,
            t: t0,
            y: y0,
            h: 0.0,
            t_prev: t0,
            t_lo: 0.0,
            y_prev: y0,
            z: [[0.0; N]; 3],
            have_prev: false,
            lu: vec![0.0; 9 * N * N],
            piv: vec![0; 3 * N],
            e1: vec![0.0; N * N],
            piv1: vec![0; N],
            jac: None,
            jac_fresh: false,
            lu_h: 0.0,
            stats: Stats::default(),
        }
    }

    /// Solve the stage equations to `newton_rtol` instead of the step tolerance (for tests that
    /// hold the step fixed with a loose tolerance and still want the method's own accuracy).
    pub fn with_newton_rtol(mut self, newton_rtol: f64) -> Self {
        self.newton_rtol = newton_rtol;
        self
    }

    /// Form the Jacobian at `(t, y)` (the factors of the old one are void).
    fn refresh_jacobian<S: Ode<N>>(&mut self, sys: &S, t: f64, y: &[f64; N]) {
        self.jac = Some(jacobian(sys, t, y));
        self.jac_fresh = true;
        self.lu_h = 0.0;
        self.stats.jacobians += 1;
    }

    /// Factor the iteration matrix I − h (A ⊗ J) and the error estimate's U1/h I − J for the
    /// step `h`; false when either is singular.
    fn factor(&mut self, jac: &[[f64; N]; N], h: f64) -> bool {
        let n3 = 3 * N;
        for a in 0..3 {
            for i in 0..N {
                for b in 0..3 {
                    for j in 0..N {
                        let delta = if a == b && i == j { 1.0 } else { 0.0 };
                        self.lu[(a * N + i) * n3 + b * N + j] = delta - h * A[a][b] * jac[i][j];
                    }
                }
            }
        }
        let fac1 = u1() / h;
        for i in 0..N {
            for j in 0..N {
                self.e1[i * N + j] = if i == j { fac1 } else { 0.0 } - jac[i][j];
            }
        }
        self.lu_h = 0.0;
        let ok = lu_factor(&mut self.lu, &mut self.piv, n3)
            && lu_factor(&mut self.e1, &mut self.piv1, N);
        if ok {
            self.lu_h = h;
        }
        ok
    }

    /// The collocation polynomial of the last step at `s = (t - t_prev) / h` (may extrapolate).
    pub(super) fn collocation(&self, s: f64) -> [f64; N] {
        let mut out = self.y_prev;
        for a in 0..3 {
            let mut l = s / C[a];
            for b in 0..3 {
                if b != a {
                    l *= (s - C[b]) / (C[a] - C[b]);
                }
            }
            for (o, z) in out.iter_mut().zip(&self.z[a]) {
                *o += l * z;
            }
        }
        out
    }
}

impl<const N: usize> Integrator<N> for Radau5<N> {
    fn start(t0: f64, y0: [f64; N], control: Control, _order: Option<usize>) -> Option<Self> {
        match control {
            Control::Tolerance(rtol) => Some(Radau5::new(t0, y0, rtol)),
            Control::Fixed(_) => None,
        }
    }
}

impl<const N: usize> Stepper<N> for Radau5<N> {
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
        let (t, y) = (self.t, self.y);
        let (f0, h_max) = start_step(sys, t, &y, None, self.rtol, 5, &mut self.h, &mut self.stats)?;
        if self.jac.is_none() {
            self.refresh_jacobian(sys, t, &y);
        }
        loop {
            let (h, last) = trial_step(self.h, h_max, t, t_stop)?;
            let Some(jac) = self.jac else {
                return Err(StepError::NewtonFailed { t });
            };
            if h != self.lu_h && !self.factor(&jac, h) {
                self.h = h * 0.5;
                self.stats.rejected += 1;
                continue;
            }
            let mut z = self.predict(&y, h);
            let Some(contraction) = self.newton(sys, t, &y, h, &mut z) else {
                self.stats.rejected += 1;
                // An old Jacobian first: form it here and retry the same step (radau5.f).
                if !self.jac_fresh {
                    self.refresh_jacobian(sys, t, &y);
                    continue;
                }
                self.h = h * 0.5;
                if self.h < 1e-14 * t.abs().max(1.0) {
                    return Err(StepError::NewtonFailed { t });
                }
                continue;
            };
            let y1: [f64; N] = std::array::from_fn(|i| y[i] + z[2][i]);
            let err = self.error_estimate(sys, t, (&y, &y1), &f0, &z, h);
            let quot = (err.powf(0.25) / 0.9).clamp(0.125, 5.0);
            let h_new = h / quot;
            if err < 1.0 && all_finite(&y1) {
                // Simplified Newton across steps (Hairer-Wanner II, IV.8; radau5.f's THET and
                // QUOT1/QUOT2): a fast contraction keeps the Jacobian, and a step that would
                // change by less than 20 % upward keeps its size and so the LU factors too.
                let keep_jac = contraction <= 1e-3;
                let grow = h_new / h;
                self.t_prev = t;
                self.y_prev = y;
                self.z = z;
                self.have_prev = true;
                (self.t, self.t_lo) = advance_time(t, self.t_lo, h, last, t_stop);
                self.y = y1;
                if !last {
                    self.h = if keep_jac && (1.0..=1.2).contains(&grow) {
                        h
                    } else {
                        h_new
                    };
                }
                self.jac_fresh = false;
                if !keep_jac {
                    self.jac = None;
                }
                self.stats.steps += 1;
                return Ok(());
            }
            self.stats.rejected += 1;
            self.h = if err.is_finite() { h_new } else { h * 0.1 };
            if !self.jac_fresh {
                self.refresh_jacobian(sys, t, &y);
            }
        }
    }

    fn prepare_dense<S: Ode<N>>(&mut self, _sys: &S) {}

    fn interpolate(&self, t: f64) -> [f64; N] {
        let h = self.t - self.t_prev;
        if h == 0.0 {
            return self.y;
        }
        self.collocation((t - self.t_prev) / h)
    }

    fn stats(&self) -> Stats {
        self.stats
    }
}
