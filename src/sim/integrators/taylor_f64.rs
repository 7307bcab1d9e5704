//! The wall phase's Taylor recursion in f64, written for speed: the same sums as the generic
//! [`super::taylor::wall_series`] and [`super::taylor::complement_series`], in the same order,
//! so they give the same bits (`tests/taylor_f64.rs` checks it), at a fraction of the cost.
//!
//! **Why a second copy.** Each order k needs the convolutions Σ_j θ̇_j c_{k−1−j} and
//! Σ_j θ̇_j s_{k−1−j}; the generic code indexes one factor backwards, with a bounds check per
//! term, and was 58 % of the instructions of a whole separation solve at tolerance 1e-12
//! (callgrind). Here cos and sin of each order are stored side by side ([`Pair`]), so both
//! convolutions run as one on two lanes, sharing the loads of θ̇, read by iterators without
//! bounds checks. The recursion is bound by latency (order k needs order k − 1), so the newest
//! terms are summed last (see [`super::taylor::product`]).

/// (cos, sin) coefficients of one order side by side: both convolutions of an order take the
/// same factor θ̇_j, so one pair product serves both (two lanes of one SSE2 instruction).
pub type Pair = [f64; 2];

/// `acc + d x` lane by lane (a product, then a sum: rounded as the generic code rounds).
#[inline(always)]
fn mul_add(acc: Pair, d: f64, x: &Pair) -> Pair {
    [acc[0] + d * x[0], acc[1] + d * x[1]]
}

/// Σ_{j<n} d_j cs_{n−1−j} (n = `d.len()` = `cs.len()`) for both lanes, in the order of
/// [`super::taylor::product`]: the inner terms 0 < j < n − 1 in two chains by the parity of j,
/// then j = n − 1, then j = 0.
#[inline(always)]
fn convolve(d: &[f64], cs: &[Pair]) -> Pair {
    let n = d.len();
    let cs = &cs[..n];
    if n == 1 {
        return [d[0] * cs[0][0], d[0] * cs[0][1]];
    }
    let (mut odd, mut even) = ([0.0; 2], [0.0; 2]);
    // Term j takes cs[n − 1 − j]: d forwards against cs backwards, two terms at a time.
    let (dc, cc) = (d[1..n - 1].chunks_exact(2), cs[1..n - 1].rchunks_exact(2));
    let (dr, cr) = (dc.remainder(), cc.remainder());
    for (d2, c2) in dc.zip(cc) {
        odd = mul_add(odd, d2[0], &c2[1]);
        even = mul_add(even, d2[1], &c2[0]);
    }
    if let (Some(d1), Some(c1)) = (dr.first(), cr.first()) {
        odd = mul_add(odd, *d1, c1);
    }
    let inner = [odd[0] + even[0], odd[1] + even[1]];
    mul_add(mul_add(inner, d[n - 1], &cs[0]), d[0], &cs[n - 1])
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
            let acc = convolve(&rate[..k], &cs[..k]);
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
