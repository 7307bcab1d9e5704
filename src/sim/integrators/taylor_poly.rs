//! The f64 series of one Taylor step ([`Series`]): the state's coefficients and those of sin and
//! cos of the angle, filled by the models' recursions ([`super::taylor_series`] in f64, the
//! wall phase by [`super::taylor_f64`]), and read as polynomials: end values, dense output and
//! the separation factor on which events are refined ([`separation_factor_on`]).
//!
//! **Scaled time.** The coefficients are stored in a time unit H of the step ([`Series::unit`]):
//! y(t0 + H σ) = Σ_k y_k σ^k, i.e. y_k = x_k H^k for the plain coefficients x_k. Plain, they
//! grow as (1/ρ)^k with ρ the series' radius of convergence, which is proportional to the
//! model's time unit: in a model run in seconds with T = 2⁻⁵⁰ s an order-22 coefficient
//! overflows f64. With H near the model's time scale they stay of the order of (H/ρ)^k, whatever
//! the units. Every recursion gives the scaled coefficients when run with H/k in place of 1/k
//! (each order is one integration, d/dσ = H d/dt, and products of series scale alike), so the
//! models' recursions read their "reciprocals" H/k from `unit_over_k`. H is a power of two, so
//! the scaling and σ = τ/H are exact: the bits are those of the plain recursion scaled.
use super::taylor_f64::FloorPairs;

/// Highest order the f64 stepper stores.
pub const MAX_ORDER: usize = 40;

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

/// The f64 series of one step: state components, and sin/cos of the angle `y[0]`, in the time
/// unit [`Series::unit`] (see the module docs).
#[derive(Clone, Debug)]
pub struct Series<const N: usize> {
    /// The order p (coefficients 0..=p are valid).
    pub order: usize,
    /// The time unit H of the coefficients (a power of two): y_i(t0 + H σ) = Σ_k y[i][k] σ^k.
    unit: f64,
    /// 1/H (exact: H is a power of two).
    inv_unit: f64,
    /// H/k for k = 0..=MAX_ORDER+1 (entry 0 is 0): the recursions' "reciprocals".
    unit_over_k: [f64; MAX_ORDER + 2],
    /// `y[i][k]`: coefficient k of component i.
    pub y: [[f64; MAX_ORDER + 1]; N],
    /// Coefficients of sin `y[0]`.
    pub sin: [f64; MAX_ORDER + 1],
    /// Coefficients of cos `y[0]`.
    pub cos: [f64; MAX_ORDER + 1],
    /// Scratch of the f64 fast path ([`super::taylor_f64`]): (cos, sin) of each order.
    pairs: [super::taylor_f64::Pair; MAX_ORDER + 1],
}

impl<const N: usize> Series<N> {
    /// Zeroed series of order `order` (at most [`MAX_ORDER`]).
    #[inline]
    pub fn new(order: usize) -> Self {
        Series {
            order,
            unit: 1.0,
            inv_unit: 1.0,
            unit_over_k: INV,
            y: [[0.0; MAX_ORDER + 1]; N],
            sin: [0.0; MAX_ORDER + 1],
            cos: [0.0; MAX_ORDER + 1],
            pairs: [[0.0; 2]; MAX_ORDER + 1],
        }
    }

    /// The time unit H of the coefficients.
    pub fn unit(&self) -> f64 {
        self.unit
    }

    /// 1/H: σ = τ/H = τ · `inv_unit()` exactly.
    pub fn inv_unit(&self) -> f64 {
        self.inv_unit
    }

    /// H/k for k = 0..=MAX_ORDER+1 (entry 0 is 0): the "reciprocals" a model's own recursion
    /// reads to give its coefficients in the unit H (`sim::near_release`).
    pub fn unit_over_k(&self) -> &[f64; MAX_ORDER + 2] {
        &self.unit_over_k
    }

    /// Take the time unit `unit` for the next recursion: the power of two at or below it (1 if
    /// it is not a positive finite number).
    pub fn set_unit(&mut self, unit: f64) {
        let h = power_of_two_below(unit);
        if h != self.unit {
            self.unit = h;
            self.inv_unit = 1.0 / h;
            for (u, inv) in self.unit_over_k.iter_mut().zip(&INV) {
                *u = h * inv;
            }
        }
    }

    /// The state and (sin, cos) of y[0] at τ = h: [`horner`]'s even/odd rule on every series in
    /// one loop (the 2(N + 2) chains run side by side; each series gets the value of its own
    /// [`horner`]).
    pub(super) fn end_values(&self, h: f64) -> ([f64; N], (f64, f64)) {
        let p = self.order;
        let x = h * self.inv_unit;
        let x2 = x * x;
        // With p even the top coefficient starts the even chain and the odd chain starts at 0.
        let top = |c: &[f64; MAX_ORDER + 1]| if p % 2 == 0 { c[p] } else { 0.0 };
        let (mut ye, mut yo) = (self.y.each_ref().map(top), [0.0; N]);
        let (mut se, mut so, mut ce, mut co) = (top(&self.sin), 0.0, top(&self.cos), 0.0);
        // Then the pairs (c_2i, c_2i+1) below it, from the top.
        for i in (0..p.div_ceil(2)).rev() {
            let (k0, k1) = (2 * i, 2 * i + 1);
            for j in 0..N {
                ye[j] = ye[j] * x2 + self.y[j][k0];
                yo[j] = yo[j] * x2 + self.y[j][k1];
            }
            se = se * x2 + self.sin[k0];
            so = so * x2 + self.sin[k1];
            ce = ce * x2 + self.cos[k0];
            co = co * x2 + self.cos[k1];
        }
        let y = std::array::from_fn(|j| ye[j] + x * yo[j]);
        (y, (se + x * so, ce + x * co))
    }
}

/// The largest power of two ≤ `x` for a positive normal `x` (its exponent bits alone); 1 for
/// anything else (0, subnormal, infinite, NaN).
pub fn power_of_two_below(x: f64) -> f64 {
    if x.is_normal() && x > 0.0 {
        f64::from_bits(x.to_bits() & 0xfff0_0000_0000_0000)
    } else {
        1.0
    }
}

/// Σ c_k τ^k by Horner's rule split by parity: E(τ²) + τ O(τ²), E and O the even and odd
/// coefficients. The two chains are independent and half as long, so the latency (the cost:
/// an order-22 chain is ~23 dependent multiply-adds) halves for the same arithmetic.
#[inline(always)]
pub fn horner(c: &[f64], tau: f64) -> f64 {
    let x2 = tau * tau;
    let (pairs, top) = c.split_at(c.len() & !1);
    let (mut e, mut o) = (top.first().copied().unwrap_or(0.0), 0.0);
    for pair in pairs.chunks_exact(2).rev() {
        e = e * x2 + pair[0];
        o = o * x2 + pair[1];
    }
    e + tau * o
}

/// The separation factor Ω² t(τ) − r(τ)² and its τ-derivative on a step's polynomials, each
/// to order `p` in the unit H (`inv_unit` = 1/H): `trig` that of cos θ (in the complement, of
/// sin φ), `rate` that of θ̇ (φ̇). Its root is the separation event of the Taylor method. The
/// four Horner chains (t, t', r, r') are independent, so one loop costs about the latency of one.
pub fn separation_factor_on(
    big_omega2: f64,
    trig: &[f64],
    rate: &[f64],
    p: usize,
    inv_unit: f64,
    tau: f64,
) -> (f64, f64) {
    let x = tau * inv_unit;
    let (t, dt) = value_and_slope(&trig[..=p], x);
    let (r, dr) = value_and_slope(&rate[..=p], x);
    (
        big_omega2 * t - r * r,
        (big_omega2 * dt - 2.0 * r * dr) * inv_unit,
    )
}

/// One series' value and its τ-derivative at τ into a step (order `p`, unit H with
/// `inv_unit` = 1/H): an event that is a component of the state (flat: φ = 0) refined by Newton
/// on the step's polynomial.
pub fn value_and_rate_on(c: &[f64], p: usize, inv_unit: f64, tau: f64) -> (f64, f64) {
    let (v, d) = value_and_slope(&c[..=p], tau * inv_unit);
    (v, d * inv_unit)
}

/// c(x) and c'(x) by the even/odd rule of [`horner`]: with c(x) = E(s) + x O(s), s = x²,
/// c'(x) = O(s) + 2x (E'(s) + x O'(s)); E, E', O, O' are four independent Horner chains (each
/// with its derivative by the usual recurrence), half as long as one on c.
#[inline(always)]
fn value_and_slope(c: &[f64], x: f64) -> (f64, f64) {
    let s = x * x;
    let (pairs, top) = c.split_at(c.len() & !1);
    let (mut e, mut de) = (top.first().copied().unwrap_or(0.0), 0.0);
    let (mut o, mut dox) = (0.0, 0.0);
    for pair in pairs.chunks_exact(2).rev() {
        de = de * s + e;
        e = e * s + pair[0];
        dox = dox * s + o;
        o = o * s + pair[1];
    }
    (e + x * o, o + 2.0 * x * (de + x * dox))
}

/// The wall phase's series in f64, for `WallPhase::taylor_series`: [`super::taylor_series::wall_series`]'s sums in
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
        &s.unit_over_k[..p + 2],
        &mut angle[..=p],
        &mut rate[..=p],
        &mut s.sin[..=p],
        &mut s.cos[..=p],
        &mut s.pairs[..=p],
    );
}

/// The complement wall phase's series in f64, for `ComplementWall::taylor_series`: as
/// [`wall_series_f64`], [`super::taylor_series::complement_series`]'s sums by the fast path (same bits).
pub fn complement_series_f64(big_omega2: f64, s: &mut Series<2>) {
    fast_wall_series(true, big_omega2, s);
}

/// The floor phase's series in f64, for `FloorPhase::taylor_series`: [`super::taylor_series::floor_series`]'s
/// sums in its order by the fast path [`super::taylor_f64::floor_series`] (same bits).
pub fn floor_series_f64(g_over_l: f64, s: &mut Series<4>) {
    floor_series_f64_in(false, g_over_l, s);
}

/// The complement floor phase's series in f64, for `ComplementFloor::taylor_series`.
pub fn complement_floor_series_f64(g_over_l: f64, s: &mut Series<4>) {
    floor_series_f64_in(true, g_over_l, s);
}

fn floor_series_f64_in(complement: bool, g_over_l: f64, s: &mut Series<4>) {
    let p = s.order;
    let (mut rate_sq, mut inertia, mut accel) = (
        [0.0; MAX_ORDER + 1],
        [0.0; MAX_ORDER + 1],
        [0.0; MAX_ORDER + 1],
    );
    let mut crs_s = [[0.0; 2]; MAX_ORDER + 1];
    let [theta, x, rate, xdot] = &mut s.y;
    super::taylor_f64::floor_series(
        complement,
        g_over_l,
        &s.unit_over_k[..p + 2],
        [
            &mut theta[..=p],
            &mut x[..=p],
            &mut rate[..=p],
            &mut xdot[..=p],
        ],
        &mut s.sin[..=p],
        &mut s.cos[..=p],
        FloorPairs {
            cs: &mut s.pairs[..=p],
            rate_sq: &mut rate_sq[..=p],
            crs_s: &mut crs_s[..=p],
            inertia: &mut inertia[..=p],
            accel: &mut accel[..=p],
        },
    );
}
