//! The linearised start: from a tiny or subnormal angle the wall phase is θ̈ = Ω² θ to f64
//! precision, solved in closed form up to an amplitude where integrators can take over. Its own
//! module with no imports, so that both the rigid phases ([`super::extreme`]) and the penalty
//! model ([`super::penalty`]) can use it without importing each other.

/// Amplitude below which the wall phase is linear to f64 precision: sin θ = θ (1 − θ²/6 + …)
/// and θ²/6 ≤ 1.5e-19 < u/700 for |θ| ≤ 2⁻³⁰, so (5) is θ̈ = Ω² θ there.
pub const LINEAR_AMPLITUDE: f64 = 9.313_225_746_154_785e-10;

/// For a start (θ0, θ̇0) smaller than [`LINEAR_AMPLITUDE`] (in θ and θ̇/Ω), the state where the
/// motion reaches that amplitude, from the exact solution of the linearised (5):
/// θ = ½ a e^{Ωt} + ½ b e^{−Ωt}, a = θ0 + θ̇0/Ω, b = θ0 − θ̇0/Ω. Integrators cannot start at
/// subnormal or tiny θ themselves: a relative tolerance there measures nothing (5e-324 has one
/// significant bit) and a fixed step needs ~ln(1/θ0) growth before anything happens.
/// Returns (t, θ, θ̇), or None when the start is not tiny or does not move away from 0.
pub fn linear_lead_in(big_omega2: f64, theta0: f64, rate0: f64) -> Option<(f64, f64, f64)> {
    let big_omega = big_omega2.sqrt();
    // a and b scaled by 2^600 (exact), so that θ̇0/Ω cannot underflow for a subnormal θ̇0.
    let scale = 2f64.powi(600);
    let (p, q) = (theta0 * scale, rate0 * scale / big_omega);
    let amp = LINEAR_AMPLITUDE;
    if !(p.abs() < amp * scale && q.abs() < amp * scale && big_omega > 0.0 && big_omega.is_finite())
    {
        return None;
    }
    let (a, b) = ((p + q) / scale, (p - q) / scale);
    if p + q <= 0.0 || p < 0.0 {
        return None;
    }
    // e^{Ωt} = 2A/a, formed through logarithms so that a subnormal a cannot overflow it.
    let t = ((2.0 * amp * scale).ln() - (p + q).ln()) / big_omega;
    if t <= 0.0 {
        return None;
    }
    let back = b * (a / (4.0 * amp)); // ½ b e^{−Ωt}
    Some((t, amp + back, big_omega * (amp - back)))
}

/// The state (θ, θ̇) of the linearised motion at time `t` after a tiny start (θ0, θ̇0): for a
/// run that ends (`[end] time`) before [`linear_lead_in`] hands over, the whole run is this
/// closed form (the campaign's seed 1 scene 129565: radau5 at τ = 1.6e-16 took 1.1e6 steps to
/// integrate 474 √(l/g) of growth from θ0 = 2.2e-249 that the formula gives exactly). Formed
/// scaled by 2^600 like [`linear_lead_in`], so a subnormal start keeps its digits; `t` must
/// not pass the hand-over (then θ ≤ [`LINEAR_AMPLITUDE`] and nothing overflows).
pub fn linear_state_at(big_omega2: f64, theta0: f64, rate0: f64, t: f64) -> (f64, f64) {
    let big_omega = big_omega2.sqrt();
    let scale = 2f64.powi(600);
    let (p, q) = (theta0 * scale, rate0 * scale / big_omega);
    // e^{ωt} reaches 2A/a (4e314 for a subnormal a): applied in two halves, so that no
    // factor overflows while the product stays below the amplitude.
    let half = (0.5 * big_omega * t).exp();
    let (a, b) = (0.5 * (p + q) * half * half, 0.5 * (p - q) / half / half);
    ((a + b) / scale, big_omega * ((a - b) / scale))
}
