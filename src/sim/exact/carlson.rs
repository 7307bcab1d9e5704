//! Elapsed time between two angles of the both-contacts motion, in Carlson's symmetric form.
//!
//! With s = sin(θ/2) the energy integral reads θ̇² = 4Ω²(s² − a) (see the parent module), and
//! with x = s² the time is a cubic elliptic integral,
//!
//!   Ω t = ½ ∫_{s₁²}^{s₂²} dx / √(x (1 − x) (x − a)).
//!
//! DLMF 19.29.4 (with its fourth factor equal to 1) evaluates any such integral between two
//! points *directly*: with X₁ = s₂, X₂ = c₂ = cos(θ₂/2), X₃ = √(s₂² − a) and Y₁, Y₂, Y₃ the same
//! at θ₁,
//!
//!   Ω t = R_F(U₁₂², U₁₃², U₁₄²),  (s₂² − s₁²) U₁₂ = X₁X₂Y₃ + Y₁Y₂X₃,
//!   (s₂² − s₁²) U₁₃ = X₁X₃Y₂ + Y₁Y₃X₂,  (s₂² − s₁²) U₁₄ = X₁Y₂Y₃ + Y₁X₂X₃,
//!
//! and by homogeneity of R_F (DLMF 19.16.1: degree −½)
//!
//!   Ω t = (s₂² − s₁²) · R_F(W₁₂², W₁₃², W₁₄²),   W = (s₂² − s₁²) U.
//!
//! Every W is a sum of products of non-negative numbers, R_F has relative condition at most ½
//! in each argument, so the result carries the relative errors of its inputs plus a few ulps,
//! whatever a is: on the separatrix, near it, or far from it. Compare the textbook route
//! t = [F(ψ₂|k) − F(ψ₁|k)]/Ω with sin²ψ = (s² − k'²)/(k² s²): it subtracts two logarithmically
//! large integrals, forms k² = 1 − k'² and evaluates arcsin near 1, each of which loses digits
//! as k' → 0.
//!
//! R_F itself comes from the `ellip` crate (Carlson's duplication algorithm, a few ulps).
//! Its iteration cap is reached when two arguments are some 1e-200 times the third; then a few
//! duplication steps (DLMF 19.26.18) are applied here first.

/// R_F(x, y, z) (DLMF 19.16.1) for non-negative arguments, at most one of them zero.
pub fn carlson_rf(x: f64, y: f64, z: f64) -> f64 {
    let (mut x, mut y, mut z, mut factor) = (x, y, z, 1.0);
    for _ in 0..16 {
        if let Ok(r) = ellip::elliprf(x, y, z) {
            return factor * r;
        }
        // DLMF 19.26.18: R_F(x, y, z) = 2 R_F(x + λ, y + λ, z + λ).
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lambda = sx * sy + sy * sz + sz * sx;
        (x, y, z, factor) = (x + lambda, y + lambda, z + lambda, 2.0 * factor);
    }
    f64::NAN
}

/// One end of a time interval, in half-angle variables of the start (θ₁) or the end (θ₂).
#[derive(Clone, Copy, Debug)]
pub struct End {
    /// sin(θ/2).
    pub s: f64,
    /// cos(θ/2).
    pub c: f64,
    /// √(s² − a) = θ̇/(2Ω), from the energy integral.
    pub r: f64,
}

/// Ω times the time from `from` to `to`, given d = s_to² − s_from² computed by the caller
/// without cancellation.
pub fn omega_time(from: End, to: End, d: f64) -> f64 {
    if d == 0.0 {
        return 0.0;
    }
    let (x1, x2, x3) = (to.s, to.c, to.r);
    let (y1, y2, y3) = (from.s, from.c, from.r);
    let w12 = x1 * x2 * y3 + y1 * y2 * x3;
    let w13 = x1 * x3 * y2 + y1 * y3 * x2;
    let w14 = x1 * y2 * y3 + y1 * x2 * x3;
    d * carlson_rf(w12 * w12, w13 * w13, w14 * w14)
}
