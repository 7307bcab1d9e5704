//! Phase 1 of the fall: the ladder held by the wall and the floor (rigid, frictionless contacts),
//! one degree of freedom θ. The note's sec. 2.1: equation of motion (5), wall force (6)/(14),
//! floor force (15), energy (2)-(3), (9)-(10) and footnote 4.
//!
//! State layout for the integrators: `[θ, θ̇]`.

use super::integrators::Ode;
use crate::ladder::Ladder;
use num_dual::DualNum;

/// Eq. (5): θ̈ = (3g/4l) sin θ = Ω² sin θ.
pub fn angular_acceleration<D: DualNum<Primitive = f64> + Copy>(big_omega2: f64, theta: D) -> D {
    theta.sin() * big_omega2
}

/// The factor of the wall force that changes sign at separation: g(θ, θ̇) = Ω² cos θ − θ̇².
///
/// From eqs. (5) and (14), F_w = m l (cos θ θ̈ − sin θ θ̇²) = m l sin θ (Ω² cos θ − θ̇²): the
/// factor sin θ vanishes at θ = 0 and π, which are not separations, so events watch this factor.
pub fn separation_factor(big_omega2: f64, theta: f64, rate: f64) -> f64 {
    big_omega2 * theta.cos() - rate * rate
}

/// Eq. (14) on the motion (5): the wall force F_w = m l sin θ (Ω² cos θ − θ̇²), along +x at C.
pub fn wall_force(ladder: &Ladder<f64>, theta: f64, rate: f64) -> f64 {
    ladder.m * ladder.l * theta.sin() * separation_factor(ladder.big_omega2(), theta, rate)
}

/// Eq. (15) on the motion (5): the floor force F_f = m g − m l (sin θ θ̈ + cos θ θ̇²), along +y at D.
pub fn floor_force(ladder: &Ladder<f64>, theta: f64, rate: f64) -> f64 {
    let acc = angular_acceleration(ladder.big_omega2(), theta);
    ladder.m * (ladder.g - ladder.l * (theta.sin() * acc + theta.cos() * rate * rate))
}

/// Eqs. (2)-(3): E = T + V = (2/3) m l² θ̇² + m g l cos θ.
pub fn energy(ladder: &Ladder<f64>, theta: f64, rate: f64) -> f64 {
    let (m, l) = (ladder.m, ladder.l);
    2.0 / 3.0 * m * l * l * rate * rate + m * ladder.g * l * theta.cos()
}

/// Footnote 4, generalised to a start with θ̇0 ≠ 0 by the energy integral (9):
/// cos θ_s = (2 Ω² cos θ0 + θ̇0²) / (3 Ω²). Above 1 the wall would have to pull at the start.
pub fn separation_cosine(big_omega2: f64, theta0: f64, rate0: f64) -> f64 {
    (2.0 * big_omega2 * theta0.cos() + rate0 * rate0) / (3.0 * big_omega2)
}

/// The wall phase as an ODE for the integrators: y = [θ, θ̇], y' = [θ̇, Ω² sin θ].
#[derive(Clone, Copy, Debug)]
pub struct WallPhase {
    /// Ω² = 3g/(4l).
    pub big_omega2: f64,
    big_omega: f64,
}

impl WallPhase {
    /// The wall phase of `ladder`.
    pub fn new(ladder: &Ladder<f64>) -> Self {
        let big_omega2 = ladder.big_omega2();
        WallPhase {
            big_omega2,
            big_omega: big_omega2.sqrt(),
        }
    }
}

/// Longest step that keeps |Δθ| ≤ 0.625 rad when |θ̈| ≤ Ω²: h (|θ̇| + Ω) ≤ 1/2 gives
/// |Δθ| ≤ h|θ̇| + h²Ω²/2 ≤ 1/2 + 1/8. Used by both phases (see `sim::event` for why).
pub fn event_safe_step(big_omega: f64, rate: f64) -> f64 {
    0.5 / (rate.abs() + big_omega)
}

/// The Taylor method's longest wall-phase step: h (|θ̇| + Ω) ≤ 3/2 gives a path of
/// |Δθ| ≤ h|θ̇| + h²Ω²/2 ≤ 3/2 + 9/8 = 2.625 rad < π along the motion (|θ̈| = Ω²|sin θ| ≤ Ω²),
/// still less than the π between the separation factor's two roots (see `sim::event`), so a
/// sign check at the step ends cannot miss a crossing. Three times [`event_safe_step`]: at
/// tolerance 1e-12 the Taylor method's own step (order 15) is longer than 0.5/(|θ̇| + Ω), and
/// that bound, not the accuracy, set its number of steps. The other methods keep the
/// narrower bound (their error control rarely reaches it; their tested behaviour is unchanged).
pub fn taylor_event_safe_step(big_omega: f64, rate: f64) -> f64 {
    1.5 / (rate.abs() + big_omega)
}

impl Ode<2> for WallPhase {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 2]) -> [D; 2] {
        [y[1], angular_acceleration(self.big_omega2, y[0])]
    }
    fn max_step(&self, y: &[f64; 2]) -> f64 {
        event_safe_step(self.big_omega, y[1])
    }
    fn taylor_max_step(&self, y: &[f64; 2]) -> f64 {
        taylor_event_safe_step(self.big_omega, y[1])
    }
    /// θ and θ̇/Ω are both angles: one relative scale for the pair, so that a start at θ = 0
    /// (or θ̇ = 0) is measured against the motion's size, not against an absolute tolerance.
    fn scale(&self, y: &[f64; 2]) -> [f64; 2] {
        let s = y[0].abs().max(y[1].abs() / self.big_omega);
        [s, self.big_omega * s]
    }
    fn accel_uses_velocity(&self) -> bool {
        false
    }
    fn taylor_series(&self, series: &mut super::integrators::taylor::Series<2>) -> bool {
        super::integrators::taylor::wall_series_f64(self.big_omega2, series);
        true
    }
}
