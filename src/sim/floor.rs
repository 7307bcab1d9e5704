//! Phase 2 of the fall: after the wall force reaches zero the top leaves the wall and the ladder
//! moves with the floor alone. **An extension beyond the note** (the note stops at separation);
//! derivation in `equations/phase2.md`.
//!
//! Two degrees of freedom: θ (from the vertical, as before) and X, the centre's abscissa. The
//! foot stays on the floor, so the centre's height is l cos θ. No horizontal force acts, so
//! Ẍ = 0: the centre keeps the horizontal velocity it had at separation. Lagrange's equation for
//! θ with T = ½ m Ẋ² + ½ m l² (sin² θ + 1/3) θ̇², V = m g l cos θ gives
//! (sin² θ + 1/3) θ̈ + sin θ cos θ θ̇² = (g/l) sin θ.
//!
//! State layout for the integrators: `[θ, X, θ̇, Ẋ]`.

use super::integrators::Ode;
use super::rigid::event_safe_step;

use crate::ladder::Ladder;
use num_dual::DualNum;

/// Phase-2 equation of motion: θ̈ = sin θ (g/l − cos θ θ̇²) / (sin² θ + 1/3).
/// At separation (θ̇² = Ω² cos θ) it equals the wall phase's Ω² sin θ, so θ̈ is continuous.
pub fn angular_acceleration<D: DualNum<Primitive = f64> + Copy>(
    g_over_l: f64,
    theta: D,
    rate: D,
) -> D {
    let (s, c) = theta.sin_cos();
    s * (-(c * rate * rate) + g_over_l) / (s * s + 1.0 / 3.0)
}

/// Horizontal acceleration of the centre: zero, no horizontal force acts (frictionless floor).
pub fn centre_acceleration_x() -> f64 {
    0.0
}

/// Floor force while only the floor holds: F_f = m (g − l sin θ θ̈ − l cos θ θ̇²), from
/// F_f − m g = m ÿ with y = l cos θ. Lift-off would be F_f < 0.
pub fn floor_force(ladder: &Ladder<f64>, theta: f64, rate: f64) -> f64 {
    let (m, l, g) = (ladder.m, ladder.l, ladder.g);
    let acc = angular_acceleration(g / l, theta, rate);
    m * (g - l * (theta.sin() * acc + theta.cos() * rate * rate))
}

/// Energy in phase 2: E = ½ m Ẋ² + ½ m l² (sin² θ + 1/3) θ̇² + m g l cos θ.
pub fn energy(ladder: &Ladder<f64>, theta: f64, rate: f64, centre_velocity_x: f64) -> f64 {
    let (m, l, g) = (ladder.m, ladder.l, ladder.g);
    let s = theta.sin();
    0.5 * m * centre_velocity_x.powi(2)
        + 0.5 * m * l * l * (s * s + 1.0 / 3.0) * rate * rate
        + m * g * l * theta.cos()
}

/// Abscissa of the top C: X − l sin θ (the wall is x = 0; the top is clear of it when > 0).
pub fn top_x(ladder: &Ladder<f64>, theta: f64, centre_x: f64) -> f64 {
    centre_x - ladder.l * theta.sin()
}

/// Phase-2 state at separation from the wall phase's (θ, θ̇): X = l sin θ, Ẋ = l cos θ θ̇ (eq. 7).
pub fn state_at_separation(ladder: &Ladder<f64>, theta: f64, rate: f64) -> [f64; 4] {
    let l = ladder.l;
    [theta, l * theta.sin(), rate, l * theta.cos() * rate]
}

/// The floor phase as an ODE: y = [θ, X, θ̇, Ẋ], y' = [θ̇, Ẋ, θ̈, 0].
#[derive(Clone, Copy, Debug)]
pub struct FloorPhase {
    g_over_l: f64,
    big_omega: f64,
    half_length: f64,
}

impl FloorPhase {
    /// The floor phase of `ladder`.
    pub fn new(ladder: &Ladder<f64>) -> Self {
        FloorPhase {
            g_over_l: ladder.g / ladder.l,
            big_omega: ladder.big_omega2().sqrt(),
            half_length: ladder.l,
        }
    }
}

impl Ode<4> for FloorPhase {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 4]) -> [D; 4] {
        let acc = angular_acceleration(self.g_over_l, y[0], y[2]);
        [y[2], y[3], acc, D::from(centre_acceleration_x())]
    }
    fn max_step(&self, y: &[f64; 4]) -> f64 {
        event_safe_step(self.big_omega, y[2])
    }
    fn scale(&self, y: &[f64; 4]) -> [f64; 4] {
        let a = y[0].abs().max(y[2].abs() / self.big_omega);
        let x = (y[1].abs().max(y[3].abs() / self.big_omega)).max(self.half_length * a);
        [a, x, self.big_omega * a, self.big_omega * x]
    }
    fn taylor_series(&self, series: &mut super::integrators::taylor::Series<4>) -> bool {
        super::integrators::taylor::floor_series_f64(self.g_over_l, series);
        true
    }
}
