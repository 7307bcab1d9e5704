//! The Taylor method's coefficient recursions, generic over the scalar ([`Scalar`]): f64,
//! exact rationals (for the tests' exact coefficients), the error-bound scalar. The recurrences
//! for sin and cos of an angle and the laws of the wall and floor phases are derived in
//! [`super::taylor`]'s module docs; the f64 stepper runs the wall phase through the fast path
//! [`super::taylor_f64`] (same sums, same bits) and the floor phase through these.

use crate::scalar::Scalar;

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

/// Σ_{j=0}^{k} a_j b_{k−j}, the k-th coefficient of a product of series ([`dot`] of the first
/// k + 1 coefficients).
#[inline(always)]
pub fn product<S: Scalar>(k: usize, a: &[S], b: &[S]) -> S {
    dot(&a[..=k], &b[..=k])
}

/// Σ_{i<n} a_i b_{n−1−i} for slices of one length n: a read forwards against b backwards, the
/// sum every convolution of the recursions is made of.
///
/// Order of summation (the only freedom; exact scalars give the same value in any order): the
/// inner terms 0 < i < n − 1 in four chains by (i − 1) mod 4, combined as
/// (c0 + c1) + (c2 + c3), then a_{n−1} b_0, then a_0 b_{n−1}. In a recursion the end terms hold
/// the newest coefficients (b_{n−1} was computed just before), so in f64 they are added last
/// and the inner sums, on older coefficients, run ahead of them: the recursion's critical path
/// is one product and two additions per convolution, and the four chains keep the inner sum
/// from being bound by the latency of one addition per term. The f64 fast path
/// ([`super::taylor_f64`]) sums in exactly this order, so both give the same bits.
#[inline(always)]
pub fn dot<S: Scalar>(a: &[S], b: &[S]) -> S {
    let n = a.len();
    let b = &b[..n];
    if n == 1 {
        return a[0].clone() * b[0].clone();
    }
    let mut acc: [S; 4] = std::array::from_fn(|_| S::int(0));
    for i in 1..n - 1 {
        let c = &mut acc[(i - 1) % 4];
        *c = c.clone() + a[i].clone() * b[n - 1 - i].clone();
    }
    let [c0, c1, c2, c3] = acc;
    (((c0 + c1) + (c2 + c3)) + a[n - 1].clone() * b[0].clone()) + a[0].clone() * b[n - 1].clone()
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
/// every slice holds its series to order p. `inv[k]` = 1/k for k ≤ p + 1 gives the plain
/// coefficients; H/k gives them in the time unit H (x_k H^k, see [`super::taylor_poly`]).
pub fn wall_series<S: Scalar>(
    big_omega2: &S,
    inv: &[S],
    theta: &mut [S],
    rate: &mut [S],
    sin: &mut [S],
    cos: &mut [S],
) {
    angle_series(inv, theta, rate, sin, cos, |k, sin, _| {
        sin[k].clone() * (big_omega2.clone() * inv[k + 1].clone())
    });
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
    angle_series(inv, phi, rate, sin, cos, |k, _, cos| {
        -(cos[k].clone() * (big_omega2.clone() * inv[k + 1].clone()))
    });
}

/// The recursion of an angle whose acceleration's coefficient k is `accel_over(k, sin, cos)`
/// divided by k + 1 (so read off sin and cos of orders ≤ k): sin and cos of order k, then the
/// angle and its rate of order k + 1.
fn angle_series<S: Scalar>(
    inv: &[S],
    angle: &mut [S],
    rate: &mut [S],
    sin: &mut [S],
    cos: &mut [S],
    accel_over: impl Fn(usize, &[S], &[S]) -> S,
) {
    let p = angle.len() - 1;
    for k in 0..=p {
        if k > 0 {
            let (s, c) = sin_cos_coefficient(&inv[k], &rate[..k], &sin[..k], &cos[..k]);
            sin[k] = s;
            cos[k] = c;
        }
        if k < p {
            angle[k + 1] = rate[k].clone() * inv[k + 1].clone();
            rate[k + 1] = accel_over(k, sin, cos);
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
/// θ̈ = sin θ (g/l − cos θ θ̇²) / (sin² θ + 1/3), Ẍ = 0, to order p = `theta.len() − 1`
/// (`inv` as for [`wall_series`]: 1/k, or H/k in the time unit H).
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
            // a_k = (n_k − Σ_{j=1}^{k} q_j a_{k−j}) / q_0.
            let r = n - dot(&w.inertia[1..=k], &w.accel[..k]);
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
