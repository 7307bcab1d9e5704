//! A Taylor-series integrator: the solution's Taylor coefficients to order p by recursion, the
//! step from the size of the last coefficients, and the same polynomial as dense output.
//!
//! **Coefficients.** Write every series as x(t0 + τ) = Σ x_k τ^k (x_k = x^(k)(t0)/k!). For an
//! angle θ with s = sin θ, c = cos θ, differentiating s' = c θ' and c' = −s θ' and comparing
//! powers of τ gives, for k ≥ 1,
//!
//! k s_k = Σ_{j=0}^{k−1} d_j c_{k−1−j},   k c_k = −Σ_{j=0}^{k−1} d_j s_{k−1−j},
//!
//! where d_j are the coefficients of θ' (here θ' = θ̇, so d = the rate's series). The second-order
//! laws then give the next orders: θ_{k+1} = θ̇_k/(k+1) and θ̇_{k+1} = a_k/(k+1), with a_k the
//! k-th coefficient of the acceleration, a product/quotient of series built from s, c and θ̇.
//! Only sin θ0 and cos θ0 enter; nothing else transcendental. The recursions are written once,
//! generic over [`Scalar`], so they run in f64, in exact rationals (where the tests give s0, c0
//! as a rational point of the circle) and in the error-bound scalar. The f64 stepper carries
//! (sin θ, cos θ) from step to step by evaluating their own series, so `sin_cos` is taken once,
//! at the start (and after an event restarts the stepper).
//!
//! **Order and step** (Á. Jorba and M. Zou, "A software package for the numerical integration of
//! ODEs by means of high-order Taylor methods", *Experimental Mathematics* 14 (2005), sec. 3.2):
//! with a relative tolerance ε the order is p = ⌈−ln(ε)/2⌉ + 1 (the order that minimises work
//! p² per unit time when the step is ρ ε^{1/p}), and the step is
//! h = min_{m ∈ {p−1, p}} (ε / e_m)^{1/m} · exp(−0.7/(p−1)), where e_m is the largest
//! coefficient of order m in units of the model's scale ([`Ode::scale`]). The last two orders
//! are used because one of them may vanish by symmetry (from rest, θ's odd coefficients do).
//! There is no rejected step: the step is chosen before it is taken. It is capped by the
//! model's [`Ode::taylor_max_step`] (event safety; wider than other methods' in the wall phase).
//!
//! **Speed.** The wall phase's recursion runs in f64 through [`super::taylor_f64`] (same sums,
//! same bits, no bounds checks); events read sin/cos as carried ([`Stepper::trig`]) instead of
//! calling them per step.
//!
//! Models opt in through [`Ode::taylor_series`]; the rigid wall phase ([`wall_series`]) and the
//! floor phase ([`floor_series`]) do. Others (penalty, Lagrange multipliers) return `false` and
//! the stepper stops with [`StepError::NoTaylorSeries`].
//!
//! Why by hand: no Rust crate offers a Taylor integrator (taylor-series crates stop at jets of
//! elementary functions; heyoka and TaylorIntegration.jl are C++ and Julia).

use super::{all_finite, Ode, Stats, StepError, Stepper};
use crate::scalar::Scalar;

/// Highest order the f64 stepper stores.
pub const MAX_ORDER: usize = 40;
/// Lowest order it accepts.
pub const MIN_ORDER: usize = 2;

/// 1/k for k = 0..=MAX_ORDER+1 (entry 0 unused), so the f64 recursions multiply, never divide.
const INV: [f64; MAX_ORDER + 2] = {
    let mut t = [0.0; MAX_ORDER + 2];
    let mut k = 1;
    while k < MAX_ORDER + 2 {
        t[k] = 1.0 / k as f64;
        k += 1;
    }
    t
};

/// The reciprocals 1/k, k = 0..n (entry 0 is 0), in any scalar.
pub fn reciprocals<S: Scalar>(n: usize) -> Vec<S> {
    (0..n)
        .map(|k| {
            if k == 0 {
                S::int(0)
            } else {
                S::ratio(1, k as i64)
            }
        })
        .collect()
}

/// The order for relative tolerance `tol` (Jorba-Zou): ⌈−ln(tol)/2⌉ + 1, within the stored range.
pub fn order_for(tol: f64) -> usize {
    let p = (-tol.ln() / 2.0).ceil() + 1.0;
    (p.max(MIN_ORDER as f64) as usize).min(MAX_ORDER)
}

/// Σ_{j=0}^{k} a_j b_{k−j}, the k-th coefficient of a product of series.
///
/// Order of summation (the only freedom; exact scalars give the same value in any order): the
/// inner terms 0 < j < k in two chains by parity, then a_k b_0, then a_0 b_k. In a recursion the
/// end terms hold the newest coefficients (b_k was computed just before), so in f64 they are
/// added last and the inner sums, on older coefficients, run ahead of them: the recursion's
/// critical path is one product and two additions per order. The f64 fast path
/// ([`super::taylor_f64`]) sums in exactly this order, so both give the same bits.
#[inline(always)]
pub fn product<S: Scalar>(k: usize, a: &[S], b: &[S]) -> S {
    let (a, b) = (&a[..=k], &b[..=k]);
    if k == 0 {
        return a[0].clone() * b[0].clone();
    }
    let (mut odd, mut even) = (S::int(0), S::int(0));
    for j in 1..k {
        let t = a[j].clone() * b[k - j].clone();
        if j % 2 == 1 {
            odd = odd + t;
        } else {
            even = even + t;
        }
    }
    ((odd + even) + a[k].clone() * b[0].clone()) + a[0].clone() * b[k].clone()
}

/// The k-th coefficients (k ≥ 1) of s = sin θ and c = cos θ from the series `d` of θ' and the
/// lower orders of s and c: k s_k = Σ d_j c_{k−1−j}, k c_k = −Σ d_j s_{k−1−j}. `inv_k` = 1/k.
#[inline(always)]
pub fn sin_cos_coefficient<S: Scalar>(inv_k: &S, d: &[S], sin: &[S], cos: &[S]) -> (S, S) {
    let k = d.len();
    let s = product(k - 1, d, cos);
    let c = product(k - 1, d, sin);
    (s * inv_k.clone(), -(c * inv_k.clone()))
}

/// Taylor coefficients of the wall phase, eq. (5) θ̈ = Ω² sin θ, to order p = `theta.len() − 1`.
///
/// On entry `theta[0]`, `rate[0]`, `sin[0] = sin θ0`, `cos[0] = cos θ0` hold the start; on return
/// every slice holds its series to order p. `inv[k] = 1/k` for k ≤ p.
pub fn wall_series<S: Scalar>(
    big_omega2: &S,
    inv: &[S],
    theta: &mut [S],
    rate: &mut [S],
    sin: &mut [S],
    cos: &mut [S],
) {
    let p = theta.len() - 1;
    for k in 0..=p {
        if k > 0 {
            let (s, c) = sin_cos_coefficient(&inv[k], &rate[..k], &sin[..k], &cos[..k]);
            sin[k] = s;
            cos[k] = c;
        }
        if k < p {
            theta[k + 1] = rate[k].clone() * inv[k + 1].clone();
            rate[k + 1] = sin[k].clone() * (big_omega2.clone() * inv[k + 1].clone());
        }
    }
}

/// Scratch series the floor phase needs besides the state: θ̇², c θ̇², the denominator
/// sin² θ + 1/3 and the acceleration.
pub struct FloorScratch<'a, S> {
    /// θ̇².
    pub rate_sq: &'a mut [S],
    /// cos θ θ̇².
    pub cos_rate_sq: &'a mut [S],
    /// sin² θ + 1/3.
    pub inertia: &'a mut [S],
    /// θ̈.
    pub accel: &'a mut [S],
}

/// Taylor coefficients of the floor phase ([`crate::sim::floor`]):
/// θ̈ = sin θ (g/l − cos θ θ̇²) / (sin² θ + 1/3), Ẍ = 0, to order p = `theta.len() − 1`.
///
/// State series `y = [θ, X, θ̇, Ẋ]` and `sin`, `cos` hold their start values in entry 0; the
/// quotient is the series division a_k = (n_k − Σ_{j≥1} q_j a_{k−j}) / q_0 with q = sin² θ + 1/3.
pub fn floor_series<S: Scalar>(
    g_over_l: &S,
    inv: &[S],
    y: [&mut [S]; 4],
    sin: &mut [S],
    cos: &mut [S],
    w: FloorScratch<'_, S>,
) {
    floor_series_in(false, g_over_l, inv, y, sin, cos, w);
}

/// The floor phase in the complement φ = π/2 − θ (`crate::sim::complement`): state series
/// `y = [φ, X, φ̇, Ẋ]`, `sin`, `cos` those of φ; φ̈ = −θ̈ with sin θ = cos φ, cos θ = sin φ.
pub fn complement_floor_series<S: Scalar>(
    g_over_l: &S,
    inv: &[S],
    y: [&mut [S]; 4],
    sin: &mut [S],
    cos: &mut [S],
    w: FloorScratch<'_, S>,
) {
    floor_series_in(true, g_over_l, inv, y, sin, cos, w);
}

fn floor_series_in<S: Scalar>(
    complement: bool,
    g_over_l: &S,
    inv: &[S],
    y: [&mut [S]; 4],
    sin: &mut [S],
    cos: &mut [S],
    w: FloorScratch<'_, S>,
) {
    let [angle, x, rate, xdot] = y;
    let p = angle.len() - 1;
    let third = S::ratio(1, 3);
    let mut inv_q0 = S::int(0);
    for k in 0..=p {
        if k > 0 {
            let (s, c) = sin_cos_coefficient(&inv[k], &rate[..k], &sin[..k], &cos[..k]);
            sin[k] = s;
            cos[k] = c;
        }
        if k == p {
            break;
        }
        // sin θ and cos θ: those of the angle carried, or swapped in the complement.
        let (st, ct): (&[S], &[S]) = if complement {
            (&cos[..], &sin[..])
        } else {
            (&sin[..], &cos[..])
        };
        w.rate_sq[k] = product(k, rate, rate);
        w.cos_rate_sq[k] = product(k, ct, w.rate_sq);
        // Numerator n = s (g/l − c θ̇²).
        let n = g_over_l.clone() * st[k].clone() - product(k, st, w.cos_rate_sq);
        w.inertia[k] = product(k, st, st);
        if k == 0 {
            w.inertia[0] = w.inertia[0].clone() + third.clone();
            inv_q0 = S::int(1) / w.inertia[0].clone();
            w.accel[0] = n * inv_q0.clone();
        } else {
            let mut r = n;
            for j in 1..=k {
                r = r - w.inertia[j].clone() * w.accel[k - j].clone();
            }
            w.accel[k] = r * inv_q0.clone();
        }
        angle[k + 1] = rate[k].clone() * inv[k + 1].clone();
        x[k + 1] = xdot[k].clone() * inv[k + 1].clone();
        // θ̈'s series; φ̈ = −θ̈.
        rate[k + 1] = if complement {
            -(w.accel[k].clone() * inv[k + 1].clone())
        } else {
            w.accel[k].clone() * inv[k + 1].clone()
        };
        xdot[k + 1] = S::int(0);
    }
}

/// The f64 series of one step: state components, and sin/cos of the angle `y[0]`.
#[derive(Clone, Debug)]
pub struct Series<const N: usize> {
    /// The order p (coefficients 0..=p are valid).
    pub order: usize,
    /// `y[i][k]`: coefficient k of component i.
    pub y: [[f64; MAX_ORDER + 1]; N],
    /// Coefficients of sin y[0].
    pub sin: [f64; MAX_ORDER + 1],
    /// Coefficients of cos y[0].
    pub cos: [f64; MAX_ORDER + 1],
}

impl<const N: usize> Series<N> {
    /// Zeroed series of order `order` (at most [`MAX_ORDER`]).
    pub fn new(order: usize) -> Self {
        Series {
            order,
            y: [[0.0; MAX_ORDER + 1]; N],
            sin: [0.0; MAX_ORDER + 1],
            cos: [0.0; MAX_ORDER + 1],
        }
    }

    /// The state and (sin, cos) of y[0] at τ = h: Horner's rule on every series in one loop
    /// (the N + 2 chains run side by side; each gives the value of its own [`horner`]).
    fn end_values(&self, h: f64) -> ([f64; N], (f64, f64)) {
        let p = self.order;
        let (mut y, mut s, mut c) = ([0.0; N], 0.0, 0.0);
        for k in (0..=p).rev() {
            for i in 0..N {
                y[i] = y[i] * h + self.y[i][k];
            }
            s = s * h + self.sin[k];
            c = c * h + self.cos[k];
        }
        (y, (s, c))
    }

    /// 1/k for k = 0..=p+1 in f64 (for models' [`Ode::taylor_series`]).
    pub fn inv(&self) -> &'static [f64] {
        &INV[..self.order + 2]
    }
}

/// Σ c_k τ^k by Horner's rule.
#[inline(always)]
pub fn horner(c: &[f64], tau: f64) -> f64 {
    let mut acc = 0.0;
    for &ck in c.iter().rev() {
        acc = acc * tau + ck;
    }
    acc
}

/// (Σ c_k τ^k, Σ k c_k τ^(k−1)): the polynomial and its derivative in one Horner pass.
#[inline(always)]
pub fn horner_with_rate(c: &[f64], tau: f64) -> (f64, f64) {
    let (mut v, mut d) = (0.0, 0.0);
    for &ck in c.iter().rev() {
        d = d * tau + v;
        v = v * tau + ck;
    }
    (v, d)
}

/// The series of the separation factor over a step, Ω² t(τ) − r(τ)², into `out[k]`, k ≤ p =
/// `out.len() − 1`: `trig` is the series of cos θ (or, in the complement, of sin φ) and `rate`
/// that of θ̇ (φ̇). The root of this polynomial is the separation event of the Taylor method.
pub fn separation_factor_series(big_omega2: f64, trig: &[f64], rate: &[f64], out: &mut [f64]) {
    for (k, o) in out.iter_mut().enumerate() {
        *o = big_omega2 * trig[k] - square(k, rate);
    }
}

/// Σ_{j=0}^{k} r_j r_{k−j}, the k-th coefficient of r², by its symmetry in half the products.
#[inline(always)]
fn square(k: usize, r: &[f64]) -> f64 {
    let mut acc = 0.0;
    for j in 0..k.div_ceil(2) {
        acc += r[j] * r[k - j];
    }
    acc *= 2.0;
    if k % 2 == 0 {
        acc += r[k / 2] * r[k / 2];
    }
    acc
}

/// The wall phase's series in f64, for `WallPhase::taylor_series`: [`wall_series`]'s sums in
/// its order by the fast path [`super::taylor_f64::wall_series`] (same bits).
pub fn wall_series_f64(big_omega2: f64, s: &mut Series<2>) {
    fast_wall_series(false, big_omega2, s);
}

fn fast_wall_series(complement: bool, big_omega2: f64, s: &mut Series<2>) {
    let p = s.order;
    let [angle, rate] = &mut s.y;
    super::taylor_f64::wall_series(
        complement,
        big_omega2,
        &INV[..p + 2],
        &mut angle[..=p],
        &mut rate[..=p],
        &mut s.sin[..=p],
        &mut s.cos[..=p],
    );
}

/// Taylor coefficients of the wall phase in the complement φ = π/2 − θ, φ̈ = −Ω² cos φ (eq. (5)
/// with sin θ = cos φ), to order p = `phi.len() − 1`; `sin`, `cos` are those of φ. Same entry
/// and return conventions as [`wall_series`].
pub fn complement_series<S: Scalar>(
    big_omega2: &S,
    inv: &[S],
    phi: &mut [S],
    rate: &mut [S],
    sin: &mut [S],
    cos: &mut [S],
) {
    let p = phi.len() - 1;
    for k in 0..=p {
        if k > 0 {
            let (s, c) = sin_cos_coefficient(&inv[k], &rate[..k], &sin[..k], &cos[..k]);
            sin[k] = s;
            cos[k] = c;
        }
        if k < p {
            phi[k + 1] = rate[k].clone() * inv[k + 1].clone();
            rate[k + 1] = -(cos[k].clone() * (big_omega2.clone() * inv[k + 1].clone()));
        }
    }
}

/// The complement wall phase's series in f64, for `ComplementWall::taylor_series`: as
/// [`wall_series_f64`], [`complement_series`]'s sums by the fast path (same bits).
pub fn complement_series_f64(big_omega2: f64, s: &mut Series<2>) {
    fast_wall_series(true, big_omega2, s);
}

/// The floor phase's series in f64, for `FloorPhase::taylor_series`
pub fn floor_series_f64(g_over_l: f64, s: &mut Series<4>) {
    floor_series_f64_in(false, g_over_l, s);
}

/// The complement floor phase's series in f64, for `ComplementFloor::taylor_series`.
pub fn complement_floor_series_f64(g_over_l: f64, s: &mut Series<4>) {
    floor_series_f64_in(true, g_over_l, s);
}

fn floor_series_f64_in(complement: bool, g_over_l: f64, s: &mut Series<4>) {
    let p = s.order;
    let inv = &INV[..p + 2];
    let mut scratch = [[0.0; MAX_ORDER + 1]; 4];
    let [a, b, c, d] = &mut scratch;
    let [theta, x, rate, xdot] = &mut s.y;
    floor_series_in(
        complement,
        &g_over_l,
        inv,
        [
            &mut theta[..=p],
            &mut x[..=p],
            &mut rate[..=p],
            &mut xdot[..=p],
        ],
        &mut s.sin[..=p],
        &mut s.cos[..=p],
        FloorScratch {
            rate_sq: &mut a[..=p],
            cos_rate_sq: &mut b[..=p],
            inertia: &mut c[..=p],
            accel: &mut d[..=p],
        },
    );
}

/// The Taylor-series integrator (adaptive step, order from the tolerance or given).
#[derive(Clone, Debug)]
pub struct Taylor<const N: usize> {
    tol: f64,
    t: f64,
    y: [f64; N],
    /// (sin, cos) of y[0], carried along the series.
    trig: (f64, f64),
    t_prev: f64,
    series: Series<N>,
    stats: Stats,
}

impl<const N: usize> Taylor<N> {
    /// Start at `(t0, y0)` with relative tolerance `tol` and the order it implies.
    pub fn new(t0: f64, y0: [f64; N], tol: f64) -> Self {
        Self::with_order(t0, y0, tol, order_for(tol))
    }

    /// Start at `(t0, y0)` with relative tolerance `tol` and order `order` (clamped to
    /// `MIN_ORDER..=MAX_ORDER`).
    pub fn with_order(t0: f64, y0: [f64; N], tol: f64, order: usize) -> Self {
        Taylor {
            tol,
            t: t0,
            y: y0,
            trig: y0[0].sin_cos(),
            t_prev: t0,
            series: Series::new(order.clamp(MIN_ORDER, MAX_ORDER)),
            stats: Stats::default(),
        }
    }

    /// The order in use.
    pub fn order(&self) -> usize {
        self.series.order
    }

    /// The series of the last step (valid after a step).
    pub fn series(&self) -> &Series<N> {
        &self.series
    }

    /// Jorba-Zou step for the current series: min over m ∈ {p−1, p} of (tol/e_m)^{1/m}, times
    /// exp(−0.7/(p−1)); infinite when both orders vanish (e.g. at an equilibrium).
    fn step_size(&self, scale: &[f64; N]) -> f64 {
        let p = self.series.order;
        // The smaller of (tol/e_m)^{1/m} is the smaller of ln(tol/e_m)/m: one exp, no pow.
        let mut ln_h = f64::INFINITY;
        for m in [p - 1, p] {
            let mut e: f64 = 0.0;
            for i in 0..N {
                e = e.max(self.series.y[i][m].abs() / scale[i].max(f64::MIN_POSITIVE));
            }
            if e > 0.0 {
                ln_h = ln_h.min((self.tol / e).ln() / m as f64);
            }
        }
        (ln_h - 0.7 / (p - 1) as f64).exp()
    }
}

impl<const N: usize> Stepper<N> for Taylor<N> {
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
        let t = self.t;
        let p = self.series.order;
        for i in 0..N {
            self.series.y[i][0] = self.y[i];
        }
        (self.series.sin[0], self.series.cos[0]) = self.trig;
        if !sys.taylor_series(&mut self.series) {
            return Err(StepError::NoTaylorSeries { t });
        }
        // One pass of the recursion per order: counted as one evaluation each.
        self.stats.rhs_evals += p as u64;
        let h_max = sys.taylor_max_step(&self.y);
        let h_jz = self.step_size(&sys.scale(&self.y));
        if h_jz.is_nan() {
            return Err(StepError::NotFinite { t });
        }
        let mut h = h_jz.min(h_max);
        let last = t + h >= t_stop || t_stop - (t + h) <= 1e-8 * h;
        if last {
            h = t_stop - t;
        }
        if h <= 10.0 * f64::EPSILON * t.abs().max(1e-300) || h <= 0.0 {
            return Err(StepError::StepTooSmall { t, h });
        }
        let (y1, trig1) = self.series.end_values(h);
        if !all_finite(&y1) || !trig1.0.is_finite() || !trig1.1.is_finite() {
            return Err(StepError::NotFinite { t });
        }
        self.t_prev = t;
        self.t = if last { t_stop } else { t + h };
        self.y = y1;
        self.trig = trig1;
        self.stats.steps += 1;
        Ok(())
    }

    fn prepare_dense<S: Ode<N>>(&mut self, _sys: &S) {}

    fn step_series(&self) -> Option<&Series<N>> {
        Some(&self.series)
    }

    fn trig(&self) -> Option<(f64, f64)> {
        Some(self.trig)
    }

    fn interpolate(&self, t: f64) -> [f64; N] {
        let tau = t - self.t_prev;
        let p = self.series.order;
        std::array::from_fn(|i| horner(&self.series.y[i][..=p], tau))
    }

    fn interpolate_rate(&self, t: f64) -> Option<[f64; N]> {
        let tau = t - self.t_prev;
        let p = self.series.order;
        Some(std::array::from_fn(|i| {
            let c = &self.series.y[i];
            let mut acc = 0.0;
            for k in (1..=p).rev() {
                acc = acc * tau + k as f64 * c[k];
            }
            acc
        }))
    }

    fn restart(&mut self, t: f64, y: [f64; N]) {
        let order = self.series.order;
        let stats = self.stats;
        *self = Taylor::with_order(t, y, self.tol, order);
        self.stats = stats;
    }

    fn stats(&self) -> Stats {
        self.stats
    }
}
