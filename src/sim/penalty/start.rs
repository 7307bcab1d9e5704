//! The start of a penalty run on the contact's *slow manifold*, so that the springs begin in
//! equilibrium with the motion and no contact oscillation is excited by the start itself.
//!
//! In force coordinates (see [`crate::sim::penalty`]) the springs obey ε f̈ = P(θ, θ̇, F) with
//! ε = 1/κ and P the penetrations' accelerations p̈ (linear in the forces F = (F_w, F_f)). The
//! rigid forces F₀ (eqs. (14), (15)) solve P = 0. Expanding F = F₀ + ε F₁ + O(ε²):
//! ε F̈₀ = ε M F₁, with M = ∂P/∂F = [[−1 − 3cos²θ, 3 sin θ cos θ], [3 sin θ cos θ, −1 − 3sin²θ]]
//! (det M = 4), so F₁ = M⁻¹ F̈₀. The start takes F₀ + ε F₁ and its rate Ḟ₀ + ε Ḟ₁: the
//! mismatch with the true slow solution is O(ε²) in force and O(ε^2.5) in the rate, and so is
//! the contact oscillation it excites (a start with F₀ alone excites one of O(ε) m g, which a
//! tolerance below 1/κ then has to resolve at ~√κ steps per unit time).
//!
//! The derivatives of F₀ along the rigid motion (θ̈ = Ω² sin θ, eq. (5)) come from automatic
//! differentiation: θ and θ̇ are lifted to third-order jets (`num_dual::Dual3_64`) carrying
//! their derivatives along the motion, and M⁻¹'s rate from a first-order one.

use num_dual::{Dual3_64, Dual64, DualNum};

/// Ω² = 3g/(4l) in units where l = g = 1 (eq. (5)); the penalty model's unit
/// (re-exported by [`crate::sim::penalty`]), here below it because the slow start needs it too.
pub const OMEGA2: f64 = 0.75;

/// The rigid model's forces (eqs. (14), (15), dimensionless, on the motion (5)) at (θ, θ̇),
/// generic over the scalar so that jets give their derivatives along the motion.
pub fn rigid_forces<D: DualNum<Primitive = f64> + Copy>(theta: D, rate: D) -> (D, D) {
    let (s, c) = theta.sin_cos();
    let acc = s * OMEGA2;
    let w2 = rate * rate;
    (c * acc - s * w2, -(s * acc + c * w2) + 1.0)
}

/// M⁻¹ = ¼ [[−1 − 3 sin²θ, −3 sin θ cos θ], [−3 sin θ cos θ, −1 − 3 cos²θ]] (det M = 4).
pub fn m_inverse<D: DualNum<Primitive = f64> + Copy>(theta: D) -> [[D; 2]; 2] {
    let (s, c) = theta.sin_cos();
    let off = -(s * c) * 0.75;
    [
        [-(s * s * 3.0 + 1.0) * 0.25, off],
        [off, -(c * c * 3.0 + 1.0) * 0.25],
    ]
}

/// The slow-manifold forces and their rates at (θ, θ̇) for stiffness κ: ([F_w, F_f],
/// [Ḟ_w, Ḟ_f]) to first order in 1/κ, in units of m g and m g √(g/l).
pub fn slow_forces(kappa: f64, theta: f64, rate: f64) -> ([f64; 2], [f64; 2]) {
    // Derivatives of θ along (5): θ̈ = Ω² sin θ, θ⃛ = Ω² cos θ θ̇, θ⁗ = Ω² (cos θ θ̈ − sin θ θ̇²).
    let (s, c) = theta.sin_cos();
    let acc = OMEGA2 * s;
    let jerk = OMEGA2 * c * rate;
    let snap = OMEGA2 * (c * acc - s * rate * rate);
    let th = Dual3_64::new(theta, rate, acc, jerk);
    let w = Dual3_64::new(rate, acc, jerk, snap);
    let (fw, ff) = rigid_forces(th, w);
    let minv = m_inverse(Dual64::new(theta, rate));
    let (dd, ddd) = ([fw.v2, ff.v2], [fw.v3, ff.v3]);
    let eps = 1.0 / kappa;
    let f1 = |i: usize| minv[i][0].re * dd[0] + minv[i][1].re * dd[1];
    let f1_rate = |i: usize| {
        minv[i][0].eps * dd[0]
            + minv[i][1].eps * dd[1]
            + minv[i][0].re * ddd[0]
            + minv[i][1].re * ddd[1]
    };
    (
        [fw.re + eps * f1(0), ff.re + eps * f1(1)],
        [fw.v1 + eps * f1_rate(0), ff.v1 + eps * f1_rate(1)],
    )
}
