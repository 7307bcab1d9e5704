//! Error-free transformations (Dekker, Knuth; Muller et al., Handbook of Floating-Point
//! Arithmetic, ch. 4) for the one difference of phase one that is small by nature.

/// a·b = hi + lo exactly (via the fused multiply-add).
pub fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let hi = a * b;
    (hi, a.mul_add(b, -hi))
}

/// a + b = hi + lo exactly (Knuth's TwoSum).
pub fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let hi = a + b;
    let bb = hi - a;
    (hi, (a - (hi - bb)) + (b - bb))
}

/// cos θ₀ − θ̇₀²/Ω², the wall-force margin Ω⁻²(Ω² cos θ₀ − θ̇₀²) at the start, with the
/// square and the quotient carried in double-double: the only error left is that of `cos0`.
pub fn cos_minus_ratio(cos0: f64, rate0: f64, big_omega2: f64) -> f64 {
    let (p, p_lo) = two_prod(rate0, rate0);
    if !p.is_finite() {
        return f64::NEG_INFINITY;
    }
    let q = p / big_omega2;
    // Remainder of the division, exact by fma: p + p_lo − q Ω² = r.
    let r = (-q).mul_add(big_omega2, p) + p_lo;
    let q_lo = r / big_omega2;
    let (d, d_lo) = two_sum(cos0, -q);
    d + (d_lo - q_lo)
}
