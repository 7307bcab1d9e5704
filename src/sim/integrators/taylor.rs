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
//! generic over [`Scalar`](crate::scalar::Scalar), so they run in f64, in exact rationals (where the tests give s0, c0
//! as a rational point of the circle) and in the error-bound scalar. The f64 stepper carries
//! (sin θ, cos θ) from step to step by evaluating their own series, so `sin_cos` is taken once,
//! at the start of each phase (each phase starts a stepper of its own).
//!
//! **Order and step** (Á. Jorba and M. Zou, "A software package for the numerical integration of
//! ODEs by means of high-order Taylor methods", *Experimental Mathematics* 14 (2005), sec. 3.2):
//! with a relative tolerance ε their order is p = ⌈−ln(ε)/2⌉ + 1 (this crate takes a higher one,
//! [`order_for`]) and the step is h = ρ ε^{1/p} exp(−0.7/(p−1)), with ρ the radius of
//! convergence estimated from the coefficients: ρ_m = e_m^{−1/m}, where e_m is the largest
//! coefficient of order m in units of the model's scale ([`Ode::scale`]). Jorba and Zou take
//! ρ = min(ρ_{p−1}, ρ_p); this crate takes the least of the last [`STEP_ORDERS`] = 6
//! ([`step_from_orders`]). Why (finding F13): from rest the ladder's θ series is even in τ
//! and θ̇'s odd, and the scaled e_m of θ̇ at order m is (m + 1)/Ω times θ's at m + 1, so orders
//! p − 1 and p both read the one even coefficient of θ among them. The coefficients oscillate
//! in sign (the solution's singularities are complex), and where that one coefficient passes
//! near zero the step came out far too long: from rest at θ0 = 0.366 with ε = 1e-9 the
//! separation angle was 16 ε off (dop853: 0.03 ε), and over starts from rest on a 0.001 rad
//! grid with ε = 1e-4 to 1e-14 a first step's error reached 62 times its bound (θ0 = 1.193,
//! ε = 1e-7). Six orders read three independent coefficients: on that grid the error stays
//! below 0.2 of the bound (`tests/sim/integrators/taylor/step.rs`), and the steps are about as long as before
//! (median 0.97 of the two orders' step).
//! There is no rejected step: the step is chosen before it is taken. The order is the least
//! work per unit time with the fixed cost of a step counted ([`order_for`]). The step is
//! capped by the model's [`Ode::taylor_max_step`] (event safety; wider than other methods' in
//! the wall phase).
//!
//! **Speed.** The wall phase's recursion runs in f64 through [`super::taylor_f64`] (same sums,
//! same bits, no bounds checks); events read sin/cos as carried ([`Stepper::trig`]) instead of
//! calling them per step, and are refined by Newton on the step's polynomials
//! ([`separation_factor_on`]). The recursions are in [`super::taylor_series`], the step's
//! polynomials in [`super::taylor_poly`].
//!
//! Models opt in through [`Ode::taylor_series`]; the rigid wall phase ([`wall_series`]) and the
//! floor phase ([`floor_series`]) do. Others (penalty, Lagrange multipliers) return `false` and
//! the stepper stops with [`StepError::NoTaylorSeries`].
//!
//! Why by hand: no Rust crate offers a Taylor integrator (taylor-series crates stop at jets of
//! elementary functions; heyoka and TaylorIntegration.jl are C++ and Julia).

pub use super::taylor_poly::{
    complement_floor_series_f64, complement_series_f64, floor_series_f64, horner,
    separation_factor_on, value_and_rate_on, wall_series_f64, Series, MAX_ORDER,
};
pub use super::taylor_series::{
    complement_floor_series, complement_series, dot, floor_series, product, reciprocals,
    sin_cos_coefficient, wall_series, FloorScratch,
};
use super::{Control, Integrator};
use super::{all_finite, Ode, Stats, StepError, Stepper};
use std::cell::Cell;
use super::card::{Card, ControlKind, Stiffness, Sweep};

/// Lowest order it accepts.
pub const MIN_ORDER: usize = 2;

/// The fixed cost of one step (step size, end values, the event's check, the stepper's moves)
/// in units of one term of the recursion's convolutions: measured on the wall phase
/// (`benches/integrators.rs`' scenes, orders 16 to 26 given by hand) a step costs about
/// 150 ns + 0.4 p² ns, so C ≈ 350; 340 puts the order at 1e-11 on 22, the fastest of the
/// measured orders whose separation meets the bench's 1e-12 (21 is 4 % faster but misses it).
/// Measured with the last two orders' step; with the six orders' (finding F13) θ0 = 0.1 at
/// 1e-11 misses 1e-12 narrowly (1.05e-12), so the bench takes 1e-12 (order 23) there.
pub const STEP_COST: f64 = 340.0;

/// The order for relative tolerance `tol`: the least work per unit time with the fixed cost of a
/// step counted. Jorba-Zou's step is h(p) ∝ tol^{1/p} e^{−0.7/(p−1)} and a step costs
/// p² + C ([`STEP_COST`]), so ln(work per unit time) = ln(p² + C) + L/p + 0.7/(p − 1) + const
/// with L = −ln tol, convex in p; its slope 2p/(p² + C) − L/p² − 0.7/(p − 1)² turns positive at
/// the least work. The order is the first p (from Jorba-Zou's ⌈L/2⌉, which is the least work
/// when C = 0 and lies below it otherwise) whose slope at p + ½ is ≥ 0, within the stored range:
/// 22 at 1e-11, 19 at 1e-8 (Jorba-Zou's rule, C = 0: 14 and 11). Higher orders are safe at
/// any time unit because the coefficients are scaled by the step's unit
/// ([`super::taylor_poly`]); the step cap of the model ([`Ode::taylor_max_step`]) is not in
/// this model, so at loose tolerances, where the cap sets the step, the order is higher than it
/// needs to be (harmless: the error only falls).
pub fn order_for(tol: f64) -> usize {
    // A run asks once per phase, a sweep the same tolerance again and again: the last answer
    // is kept (the search costs a logarithm and a dozen iterations, 3 % of a separation solve).
    thread_local!(static LAST: Cell<(u64, usize)> = const { Cell::new((u64::MAX, 0)) });
    let bits = tol.to_bits();
    if let Some(p) = LAST.with(|c| (c.get().0 == bits).then_some(c.get().1)) {
        return p;
    }
    let p = least_work_order(tol);
    LAST.with(|c| c.set((bits, p)));
    p
}

/// [`order_for`] without the memo.
fn least_work_order(tol: f64) -> usize {
    let l = -tol.ln();
    let start = ((l / 2.0).floor().max(MIN_ORDER as f64) as usize).min(MAX_ORDER);
    for p in start..MAX_ORDER {
        let q = p as f64 + 0.5;
        let (q2, d2) = (q * q, (q - 1.0) * (q - 1.0));
        // Slope ≥ 0 with the positive denominators (q² + C) q² (q − 1)² cleared.
        if 2.0 * q * q2 * d2 >= (q2 + STEP_COST) * (l * d2 + 0.7 * q2) {
            return p;
        }
    }
    MAX_ORDER
}


/// The card of Taylor series ([`mod@super::card`]).
pub const CARD: Card = Card {
    name: "taylor",
    title: "Taylor series",
    control: ControlKind::Tolerance,
    order: None,
    // Its step's own polynomial, of the order the run chooses.
    dense_order: None,
    // Not used: the method runs on the rigid phases only, which have no stiff oscillation.
    stiffness: Stiffness::Explicit { oscillation_limit: 0.0 },
    rigid_only: true,
    sweep: Sweep::Tolerances { from: 3, to: 16, per_decade: 1 },
    penalty_fit: None,
    stiff_case: None,
};
/// The Taylor-series integrator (adaptive step, order from the tolerance or given).
#[derive(Clone, Debug)]
pub struct Taylor<const N: usize> {
    tol: f64,
    t: f64,
    y: [f64; N],
    /// (sin, cos) of y[0], carried along the series.
    trig: (f64, f64),
    t_prev: f64,
    /// The rounding of `t` so far (`adaptive::advance_time`).
    t_lo: f64,
    series: Series<N>,
    stats: Stats,
}

impl<const N: usize> Taylor<N> {
    /// Start at `(t0, y0)` with relative tolerance `tol` and the order it implies.
    #[inline]
    pub fn new(t0: f64, y0: [f64; N], tol: f64) -> Self {
        Self::with_order(t0, y0, tol, order_for(tol))
    }

    /// Start at `(t0, y0)` with relative tolerance `tol` and order `order` (clamped to
    /// `MIN_ORDER..=MAX_ORDER`).
    #[inline]
    pub fn with_order(t0: f64, y0: [f64; N], tol: f64, order: usize) -> Self {
        Taylor {
            tol,
            t: t0,
            y: y0,
            trig: y0[0].sin_cos(),
            t_prev: t0,
            t_lo: 0.0,
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

    /// The step for the current series ([`step_from_orders`] on the last [`STEP_ORDERS`]
    /// orders), in time.
    fn step_size(&self, scale: &[f64; N]) -> f64 {
        let p = self.series.order;
        let orders = p.saturating_sub(STEP_ORDERS - 1).max(1)..=p;
        step_from_orders(&self.series, scale, self.tol, orders) * self.series.unit()
    }
}

/// How many of the last orders the step reads (see the module docs, finding F13).
pub const STEP_ORDERS: usize = 6;

/// The Jorba-Zou step for `series` (of order p) in its unit H, with the radius of convergence
/// estimated from the orders `orders`: ρ = min_m e_m^{−1/m} over m in `orders` (e_m: the largest
/// coefficient of order m over the components, each divided by its `scale`), and
/// h/H = ρ tol^{1/p} exp(−0.7/(p−1)). Orders whose coefficients all vanish are skipped; if all
/// do (an equilibrium), the step is infinite. The stepper takes the last [`STEP_ORDERS`]; the
/// last two are Jorba and Zou's choice (what `tests/sim/integrators/taylor/step.rs` shows to fail).
pub fn step_from_orders<const N: usize>(
    series: &Series<N>,
    scale: &[f64; N],
    tol: f64,
    orders: std::ops::RangeInclusive<usize>,
) -> f64 {
    let p = series.order;
    let inv_scale = scale.map(|s| 1.0 / s.max(f64::MIN_POSITIVE));
    // ln ρ = min over m of −ln(e_m)/m: one exp at the end, no pow.
    let mut ln_rho = f64::INFINITY;
    for m in orders {
        let mut e: f64 = 0.0;
        for i in 0..N {
            e = e.max(series.y[i][m].abs() * inv_scale[i]);
        }
        if e > 0.0 {
            ln_rho = ln_rho.min(-e.ln() / m as f64);
        }
    }
    (ln_rho + tol.ln() / p as f64 - 0.7 / (p - 1) as f64).exp()
}

impl<const N: usize> Integrator<N> for Taylor<N> {
    fn start(t0: f64, y0: [f64; N], control: Control, order: Option<usize>) -> Option<Self> {
        match (control, order) {
            (Control::Tolerance(tol), None) => Some(Taylor::new(t0, y0, tol)),
            (Control::Tolerance(tol), Some(p)) => Some(Taylor::with_order(t0, y0, tol, p)),
            (Control::Fixed(_), _) => None,
        }
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
        // The coefficients' time unit: the model's longest step, the scale of its motion.
        let h_max = sys.taylor_max_step(&self.y);
        self.series.set_unit(h_max);
        if !sys.taylor_series(&mut self.series) {
            return Err(StepError::NoTaylorSeries { t });
        }
        // One pass of the recursion per order: counted as one evaluation each.
        self.stats.rhs_evals += p as u64;
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
        (self.t, self.t_lo) = super::adaptive::advance_time(t, self.t_lo, h, last, t_stop);
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
        let tau = (t - self.t_prev) * self.series.inv_unit();
        let p = self.series.order;
        std::array::from_fn(|i| horner(&self.series.y[i][..=p], tau))
    }

    fn interpolate_rate(&self, t: f64) -> Option<[f64; N]> {
        let inv_unit = self.series.inv_unit();
        let tau = (t - self.t_prev) * inv_unit;
        let p = self.series.order;
        Some(std::array::from_fn(|i| {
            let c = &self.series.y[i];
            let mut acc = 0.0;
            for k in (1..=p).rev() {
                acc = acc * tau + k as f64 * c[k];
            }
            acc * inv_unit
        }))
    }

    fn stats(&self) -> Stats {
        self.stats
    }
}
