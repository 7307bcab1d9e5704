//! The wall phase's Taylor recursion in f64, written for speed: the same sums as the generic
//! [`super::taylor::wall_series`] and [`super::taylor::complement_series`], in the same order,
//! so they give the same bits (`tests/sim/integrators/taylor/f64_paths.rs` checks it), at a fraction of the cost.
//!
//! **Why a second copy.** Each order k needs the convolutions Σ_j θ̇_j c_{k−1−j} and
//! Σ_j θ̇_j s_{k−1−j}; the generic code indexes one factor backwards, with a bounds check per
//! term, and was 58 % of the instructions of a whole separation solve at tolerance 1e-12
//! (callgrind). Here cos and sin of each order are stored side by side ([`Pair`]), so both
//! convolutions run as one on two lanes, sharing the loads of θ̇, read by iterators without
//! bounds checks, in four chains. The recursion is bound by latency (order k needs order
//! k − 1), so the newest terms are summed last (see [`super::taylor_series::dot`]).
//!
//! The floor phase ([`floor_series`]) has five convolutions per order (θ̇², cos θ θ̇², the
//! numerator's and the inertia's products with sin θ, the quotient's sum) besides sin and cos;
//! the generic code ran them one term at a time in two chains (half of a whole fall's run time,
//! perf). Here the two products with sin θ share one two-lane pass.

/// (cos, sin) coefficients of one order side by side: both convolutions of an order take the
/// same factor θ̇_j, so one pair product serves both (two lanes of one SSE2 instruction).
pub type Pair = [f64; 2];

/// What a convolution sums: one f64, or two side by side ([`Pair`]) sharing the other factor.
trait Lanes: Copy {
    const ZERO: Self;
    /// `self + d x` lane by lane (a product, then a sum: rounded as the generic code rounds).
    fn mul_add(self, d: f64, x: Self) -> Self;
    /// `self + o` lane by lane.
    fn plus(self, o: Self) -> Self;
    /// `d x` lane by lane.
    fn times(d: f64, x: Self) -> Self;
}

impl Lanes for f64 {
    const ZERO: Self = 0.0;
    #[inline(always)]
    fn mul_add(self, d: f64, x: f64) -> f64 {
        self + d * x
    }
    #[inline(always)]
    fn plus(self, o: f64) -> f64 {
        self + o
    }
    #[inline(always)]
    fn times(d: f64, x: f64) -> f64 {
        d * x
    }
}

impl Lanes for Pair {
    const ZERO: Self = [0.0; 2];
    #[inline(always)]
    fn mul_add(self, d: f64, x: Pair) -> Pair {
        [self[0] + d * x[0], self[1] + d * x[1]]
    }
    #[inline(always)]
    fn plus(self, o: Pair) -> Pair {
        [self[0] + o[0], self[1] + o[1]]
    }
    #[inline(always)]
    fn times(d: f64, x: Pair) -> Pair {
        [d * x[0], d * x[1]]
    }
}

/// Σ_{i<n} a_i b_{n−1−i} (n = `a.len()` ≤ `b.len()`) on every lane, in the order of
/// [`super::taylor_series::dot`]: the inner terms 0 < i < n − 1 in four chains by (i − 1) mod 4,
/// combined as (c0 + c1) + (c2 + c3), then i = n − 1, then i = 0.
#[inline(always)]
fn dot<L: Lanes>(a: &[f64], b: &[L]) -> L {
    let n = a.len();
    let b = &b[..n];
    if n == 1 {
        return L::times(a[0], b[0]);
    }
    // Four accumulators in registers (an array indexed by the remainder's position would be
    // kept in memory, a store and a load per term).
    let (mut c0, mut c1, mut c2, mut c3) = (L::ZERO, L::ZERO, L::ZERO, L::ZERO);
    // Term i takes b[n − 1 − i]: a forwards against b backwards, four terms at a time.
    let (ac, bc) = (a[1..n - 1].chunks_exact(4), b[1..n - 1].rchunks_exact(4));
    let (ar, br) = (ac.remainder(), bc.remainder());
    for (a4, b4) in ac.zip(bc) {
        c0 = c0.mul_add(a4[0], b4[3]);
        c1 = c1.mul_add(a4[1], b4[2]);
        c2 = c2.mul_add(a4[2], b4[1]);
        c3 = c3.mul_add(a4[3], b4[0]);
    }
    // The last 0 to 3 inner terms continue chains 0, 1, 2.
    match (ar, br) {
        ([x0], [y0]) => c0 = c0.mul_add(*x0, *y0),
        ([x0, x1], [y1, y0]) => {
            c0 = c0.mul_add(*x0, *y0);
            c1 = c1.mul_add(*x1, *y1);
        }
        ([x0, x1, x2], [y2, y1, y0]) => {
            c0 = c0.mul_add(*x0, *y0);
            c1 = c1.mul_add(*x1, *y1);
            c2 = c2.mul_add(*x2, *y2);
        }
        _ => {}
    }
    let inner = c0.plus(c1).plus(c2.plus(c3));
    inner.mul_add(a[n - 1], b[0]).mul_add(a[0], b[n - 1])
}

/// The wall phase's series: θ̈ = Ω² sin θ (eq. (5)), or in the complement φ̈ = −Ω² cos φ, to
/// order p = `angle.len() − 1`. On entry entry 0 of every slice holds the start (sin and cos of
/// the angle in `sin[0]`, `cos[0]`); `inv[k]` = 1/k for k ≤ p + 1 (or H/k: coefficients in the
/// time unit H); `cs` (length > p) is
/// scratch, left holding (cos, sin) of every order. Same conventions as
/// [`super::taylor::wall_series`], which this module does not import (no cycle: the generic
/// module calls this one).
#[allow(clippy::too_many_arguments)]
pub fn wall_series(
    complement: bool,
    big_omega2: f64,
    inv: &[f64],
    angle: &mut [f64],
    rate: &mut [f64],
    sin: &mut [f64],
    cos: &mut [f64],
    cs: &mut [Pair],
) {
    let p = angle.len() - 1;
    let (rate, sin, cos, cs, inv) = (
        &mut rate[..=p],
        &mut sin[..=p],
        &mut cos[..=p],
        &mut cs[..=p],
        &inv[..p + 2],
    );
    cs[0] = [cos[0], sin[0]];
    for k in 0..=p {
        if k > 0 {
            // k s_k = Σ_j θ̇_j c_{k−1−j},  k c_k = −Σ_j θ̇_j s_{k−1−j}.
            let acc = dot(&rate[..k], &cs[..k]);
            let (sk, ck) = (acc[0] * inv[k], -(acc[1] * inv[k]));
            (sin[k], cos[k]) = (sk, ck);
            cs[k] = [ck, sk];
        }
        if k < p {
            let w = big_omega2 * inv[k + 1];
            angle[k + 1] = rate[k] * inv[k + 1];
            rate[k + 1] = if complement {
                -(cos[k] * w)
            } else {
                sin[k] * w
            };
        }
    }
}

/// Scratch series of the floor phase's fast path: (cos, sin) of each order, θ̇², c θ̇²
/// (c = cos θ), (c θ̇², s) side by side (s = sin θ), the inertia s² + 1/3 and θ̈.
pub struct FloorPairs<'a> {
    /// (cos, sin) of the carried angle, each order.
    pub cs: &'a mut [Pair],
    /// θ̇².
    pub rate_sq: &'a mut [f64],
    /// (cos θ θ̇², sin θ) of each order.
    pub crs_s: &'a mut [Pair],
    /// sin² θ + 1/3.
    pub inertia: &'a mut [f64],
    /// θ̈.
    pub accel: &'a mut [f64],
}

/// The floor phase's series, θ̈ = sin θ (g/l − cos θ θ̇²) / (sin² θ + 1/3), Ẍ = 0, or in the
/// complement φ = π/2 − θ (φ̈ = −θ̈ with sin θ = cos φ, cos θ = sin φ), to order
/// p = `y[0].len() − 1`: the sums of [`super::taylor_series::floor_series`] in its order (same
/// bits). Entry conventions as there: `y = [angle, X, rate, Ẋ]`, `sin`, `cos` of the carried
/// angle hold their start values in entry 0; `inv[k]` = H/k for k ≤ p + 1.
pub fn floor_series(
    complement: bool,
    g_over_l: f64,
    inv: &[f64],
    y: [&mut [f64]; 4],
    sin: &mut [f64],
    cos: &mut [f64],
    w: FloorPairs<'_>,
) {
    let [angle, x, rate, xdot] = y;
    let p = angle.len() - 1;
    let (x, rate, xdot, sin, cos, inv) = (
        &mut x[..=p],
        &mut rate[..=p],
        &mut xdot[..=p],
        &mut sin[..=p],
        &mut cos[..=p],
        &inv[..p + 2],
    );
    let (cs, rate_sq, crs_s, inertia, accel) = (
        &mut w.cs[..=p],
        &mut w.rate_sq[..=p],
        &mut w.crs_s[..=p],
        &mut w.inertia[..=p],
        &mut w.accel[..=p],
    );
    cs[0] = [cos[0], sin[0]];
    let mut inv_q0 = 0.0;
    for k in 0..=p {
        if k > 0 {
            let acc = dot(&rate[..k], &cs[..k]);
            let (sk, ck) = (acc[0] * inv[k], -(acc[1] * inv[k]));
            (sin[k], cos[k]) = (sk, ck);
            cs[k] = [ck, sk];
        }
        if k == p {
            break;
        }
        // sin θ and cos θ: those of the angle carried, or swapped in the complement.
        let (st, ct): (&[f64], &[f64]) = if complement {
            (&cos[..=k], &sin[..=k])
        } else {
            (&sin[..=k], &cos[..=k])
        };
        rate_sq[k] = dot(&rate[..=k], &rate[..=k]);
        let crs = dot(ct, &rate_sq[..=k]);
        crs_s[k] = [crs, st[k]];
        // (Σ s_j (c θ̇²)_{k−j}, Σ s_j s_{k−j}) in one pass.
        let both = dot(st, &crs_s[..=k]);
        let n = g_over_l * st[k] - both[0];
        if k == 0 {
            inertia[0] = both[1] + 1.0 / 3.0;
            inv_q0 = 1.0 / inertia[0];
            accel[0] = n * inv_q0;
        } else {
            inertia[k] = both[1];
            accel[k] = (n - dot(&inertia[1..=k], &accel[..k])) * inv_q0;
        }
        angle[k + 1] = rate[k] * inv[k + 1];
        x[k + 1] = xdot[k] * inv[k + 1];
        rate[k + 1] = if complement {
            -(accel[k] * inv[k + 1])
        } else {
            accel[k] * inv[k + 1]
        };
        xdot[k + 1] = 0.0;
    }
}
