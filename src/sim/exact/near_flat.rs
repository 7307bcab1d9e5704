//! The fall from a start almost flat on the floor, in closed form: an independent reference for
//! starts given as `angle_from_floor = φ0` far below what θ0 can hold (1e-273 rad and down).
//!
//! **The model.** In φ = π/2 − θ the wall phase (5) is φ̈ = −Ω² cos φ, and the floor phase
//! (`sim::floor`, written in φ in `sim::complement`) is
//! φ̈ = −cos φ (g/l − sin φ φ̇²)/(cos² φ + 1/3). While φ and φ̇²/Ω² stay below a size a, cos φ =
//! 1 − O(a²), sin φ φ̇² = O(a²) Ω², and both accelerations are −Ω² (3g/4l = Ω²) to a relative
//! O(a²): the ladder falls flat with the constant acceleration −Ω², wall phase and floor phase
//! alike. From (φ0, θ̇0 = −φ̇0 ≥ 0), φ(t) = φ0 − θ̇0 t − Ω² t²/2:
//! * separation (footnote 4 in φ: the factor Ω² sin φ − φ̇² falls through 0, with the energy
//!   integral φ̇² = θ̇0² + 2Ω² (φ0 − φ)) at φ_s = (2Ω² φ0 + θ̇0²)/(3Ω²), θ̇_s = Ω √φ_s,
//!   t_s = (θ̇_s − θ̇0)/Ω² = (2/3)(Ω² φ0 − θ̇0²)/(Ω² (θ̇_s + θ̇0)) (no cancellation);
//! * flat (φ = 0) at t_f = 2 φ0/(√(θ̇0² + 2Ω² φ0) + θ̇0), with θ̇_f = √(θ̇0² + 2Ω² φ0).
//!
//! **Where it is exact to f64.** The neglected terms are relative O(a²) with a = φ0 + θ̇0²/Ω²
//! (the largest φ and φ̇²/Ω² on the way); [`NEAR_FLAT_SIZE`] = 2⁻³⁰ keeps a² below u/250.
//! Derived from the equations of motion, not from the integrators' code: the simulator
//! integrates the full nonlinear phases and never calls this.

/// Largest a = φ0 + θ̇0²/Ω² for which the constant-acceleration fall is exact to f64 (a² ≤
/// 8.7e-19 < u/100).
pub const NEAR_FLAT_SIZE: f64 = 9.313_225_746_154_785e-10;

/// The near-flat fall's separation and flat, times from the start.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NearFlat {
    /// φ_s = π/2 − θ_s, rad.
    pub separation_complement: f64,
    /// θ̇_s, rad per unit of time.
    pub separation_rate: f64,
    /// t_s.
    pub separation_time: f64,
    /// θ̇ at flat.
    pub flat_rate: f64,
    /// t_f.
    pub flat_time: f64,
}

/// The fall from φ0 = π/2 − θ0 > 0 with θ̇0 ≥ 0 under Ω² (see the module docs), or None when
/// the start is not near flat (a > [`NEAR_FLAT_SIZE`]) or the wall force is not positive at the
/// start (Ω² φ0 ≤ θ̇0²: the top leaves at once).
pub fn near_flat(big_omega2: f64, phi0: f64, rate0: f64) -> Option<NearFlat> {
    let big_omega = big_omega2.sqrt();
    let ratio = rate0 / big_omega;
    if !(phi0 > 0.0 && rate0 >= 0.0 && big_omega > 0.0 && big_omega.is_finite()) {
        return None;
    }
    // a = φ0 + (θ̇0/Ω)², compared without squaring a ratio that could underflow.
    if phi0 > NEAR_FLAT_SIZE
        || ratio > NEAR_FLAT_SIZE.sqrt()
        || phi0 + ratio * ratio > NEAR_FLAT_SIZE
    {
        return None;
    }
    // In units of Ω: s = Ω t, w = θ̇/Ω. Then φ = φ0 − w0 s − s²/2, and the squares w0² and 2φ0
    // are formed with √ and hypot so that a subnormal w0 or φ0 does not vanish.
    let (w0, sqrt_phi0) = (ratio, phi0.sqrt());
    // Start factor Ω² φ0 − θ̇0² = Ω² (√φ0 − w0)(√φ0 + w0).
    let factor = (sqrt_phi0 - w0) * (sqrt_phi0 + w0);
    if factor <= 0.0 {
        return None;
    }
    // φ_s = (2 φ0 + w0²)/3; w_s = √φ_s.
    let w_s = (2.0 / 3.0f64).sqrt() * (sqrt_phi0).hypot(w0 / 2f64.sqrt());
    let phi_s = w_s * w_s;
    let s_s = (2.0 / 3.0) * factor / (w_s + w0);
    // Flat: w_f = √(w0² + 2 φ0), s_f = 2 φ0 / (w_f + w0).
    let w_f = w0.hypot(2f64.sqrt() * sqrt_phi0);
    let s_f = 2.0 * phi0 / (w_f + w0);
    Some(NearFlat {
        separation_complement: phi_s,
        separation_rate: big_omega * w_s,
        separation_time: s_s / big_omega,
        flat_rate: big_omega * w_f,
        flat_time: s_f / big_omega,
    })
}
