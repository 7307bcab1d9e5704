//! The wall phase's Taylor recursion in f64, written for speed: the same sums as the generic
//! [`super::taylor::wall_series`] and [`super::taylor::complement_series`], in the same order,
//! so they give the same bits (`tests/taylor_f64.rs` checks it), at a fraction of the cost.
//!
//! **Why a second copy.** Each order k needs the convolutions Σ_j θ̇_j c_{k−1−j} and
//! Σ_j θ̇_j s_{k−1−j}; the generic code indexes one factor backwards, with a bounds check per
//! term, and was 58 % of the instructions of a whole separation solve at tolerance 1e-12
//! (callgrind). Here sin and cos are also stored reversed (`rev[p − i]` = coefficient i), so
//! both factors of every convolution are read forwards in pairs, without bounds checks, and
//! the two convolutions share the loads of θ̇. The recursion is bound by latency (order k needs
//! order k − 1), so the newest terms are summed last (see [`super::taylor::product`]).

/// Σ_j a_j b_j and Σ_j a_j c_j (j < n = `a.len()`) in the order of
/// [`super::taylor::product`] when `b` and `c` hold the second factors reversed: the inner
/// terms 0 < j < n − 1 in two chains by the parity of j, then j = n − 1, then j = 0.
#[inline(always)]
fn dot2(a: &[f64], b: &[f64], c: &[f64]) -> (f64, f64) {
    let n = a.len();
    let (b, c) = (&b[..n], &c[..n]);
    if n == 1 {
        return (a[0] * b[0], a[0] * c[0]);
    }
    let (ai, bi, ci) = (&a[1..n - 1], &b[1..n - 1], &c[1..n - 1]);
    // Element i of the inner slices is term j = i + 1: even i is odd j.
    let (mut ob, mut eb, mut oc, mut ec) = (0.0, 0.0, 0.0, 0.0);
    let (ac, bc, cc) = (ai.chunks_exact(2), bi.chunks_exact(2), ci.chunks_exact(2));
    let (ar, br, cr) = (ac.remainder(), bc.remainder(), cc.remainder());
    for ((a2, b2), c2) in ac.zip(bc).zip(cc) {
        ob += a2[0] * b2[0];
        oc += a2[0] * c2[0];
        eb += a2[1] * b2[1];
        ec += a2[1] * c2[1];
    }
    if let (Some(a1), Some(b1), Some(c1)) = (ar.first(), br.first(), cr.first()) {
        ob += a1 * b1;
        oc += a1 * c1;
    }
    let last = n - 1;
    (
        ((ob + eb) + a[last] * b[last]) + a[0] * b[0],
        ((oc + ec) + a[last] * c[last]) + a[0] * c[0],
    )
}

/// Longest series the fast path takes (orders 0..=63; the stepper stores at most 41).
const CAP: usize = 64;

/// The wall phase's series: θ̈ = Ω² sin θ (eq. (5)), or in the complement φ̈ = −Ω² cos φ, to
/// order p = `angle.len() − 1` ≤ 63. On entry entry 0 of every slice holds the start (sin and
/// cos of the angle in `sin[0]`, `cos[0]`); `inv[k]` = 1/k for k ≤ p + 1. Same conventions as
/// [`super::taylor::wall_series`], which this module does not import (no cycle: the generic
/// module calls this one).
pub fn wall_series(
    complement: bool,
    big_omega2: f64,
    inv: &[f64],
    angle: &mut [f64],
    rate: &mut [f64],
    sin: &mut [f64],
    cos: &mut [f64],
) {
    let p = angle.len() - 1;
    assert!(p < CAP && rate.len() > p && sin.len() > p && cos.len() > p && inv.len() > p + 1);
    // rev[p − i] = coefficient i, so the window of order k is rev[p + 1 − k ..= p].
    let (mut srev, mut crev) = ([0.0; CAP], [0.0; CAP]);
    srev[p] = sin[0];
    crev[p] = cos[0];
    for k in 0..=p {
        if k > 0 {
            // k s_k = Σ_j θ̇_j c_{k−1−j},  k c_k = −Σ_j θ̇_j s_{k−1−j}.
            let w = p + 1 - k;
            let (sc, ss) = dot2(&rate[..k], &crev[w..=p], &srev[w..=p]);
            let (sk, ck) = (sc * inv[k], -(ss * inv[k]));
            (sin[k], cos[k]) = (sk, ck);
            (srev[p - k], crev[p - k]) = (sk, ck);
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
