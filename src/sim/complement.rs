//! The wall phase near the floor (θ0 close to π/2), in the complement φ = π/2 − θ.
//!
//! **Why.** f64 spaces its values near π/2 by 2.2e-16, so a start at θ0 = π/2 − ε moves, until
//! separation at cos θ_s = (2/3) cos θ0 (footnote 4), only about ε/3 — a handful of ulps of θ
//! for small ε — and the separation factor Ω² cos θ − θ̇² (`rigid::separation_factor`) is
//! evaluated from a θ that carries an absolute error of an ulp. Integrating in θ therefore gives
//! relative time errors of about u/ε whatever the tolerance (measured before this module, at
//! tolerance 1e-14: 1.5e-8 at ε = 1e-9, 2.5e-5 at 1e-12, 3.5e-2 at 1.1e-15; issue 17). In φ the
//! same motion is φ̈ = −Ω² cos φ, the factor is Ω² sin φ − φ̇², and φ near 0 carries full
//! relative precision.
//!
//! **The floor phase** ([`ComplementFloor`]) always runs in φ: it ends at θ = π/2, and from a
//! start near the floor the whole phase is a few ulps of θ long, so in θ the flat time would
//! carry the same u/ε error.
//!
//! **When.** For θ0 > π/4 the complement is the smaller of the two angles, and the wall phase
//! only moves θ up (θ_s > θ0), so φ stays the better-resolved variable throughout. The start's
//! complement is exact: for θ0 in [π/4, π/2], FRAC_PI_2 − θ0 is exact (Sterbenz), and the part
//! of π/2 that FRAC_PI_2 misses ([`HALF_PI_LO`]) is added with one rounding.

use super::event::{Direction, Event};
use super::integrators::taylor::{separation_factor_on, value_and_rate_on, Series};
use super::integrators::Ode;
use super::rigid::event_safe_step;

use super::run::Observer;
use crate::ladder::Ladder;
use num_dual::DualNum;
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};

/// π/2 − FRAC_PI_2: the low part of π/2 (π/2 = FRAC_PI_2 + HALF_PI_LO to about 1e-33).
pub const HALF_PI_LO: f64 = 6.123_233_995_736_766e-17;

/// Whether the wall phase from θ0 runs in the complement (θ0 > π/4).
pub fn applies(theta0: f64) -> bool {
    theta0 > FRAC_PI_4
}

/// φ = π/2 − θ (exact for θ in [π/4, π/2] up to one rounding of the sum); also θ from φ.
pub fn complement(angle: f64) -> f64 {
    (FRAC_PI_2 - angle) + HALF_PI_LO
}

/// The wall phase in the complement: y = [φ, φ̇], y' = [φ̇, −Ω² cos φ] (eq. (5), sin θ = cos φ).
#[derive(Clone, Copy, Debug)]
pub struct ComplementWall {
    /// Ω² = 3g/(4l).
    pub big_omega2: f64,
    big_omega: f64,
}

impl ComplementWall {
    /// The complement wall phase of `ladder`.
    pub fn new(ladder: &Ladder<f64>) -> Self {
        let big_omega2 = ladder.big_omega2();
        ComplementWall {
            big_omega2,
            big_omega: big_omega2.sqrt(),
        }
    }
}

impl Ode<2> for ComplementWall {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 2]) -> [D; 2] {
        [y[1], -(y[0].cos() * self.big_omega2)]
    }
    /// |Δφ| = |Δθ|: the same event-safe limit as the wall phase in θ.
    fn max_step(&self, y: &[f64; 2]) -> f64 {
        event_safe_step(self.big_omega, y[1])
    }
    /// As in `rigid::WallPhase`: |φ̈| = Ω²|cos φ| ≤ Ω² gives the same bound.
    fn taylor_max_step(&self, y: &[f64; 2]) -> f64 {
        super::rigid::taylor_event_safe_step(self.big_omega, y[1])
    }
    /// φ and φ̇/Ω on one relative scale, as for θ in `rigid::WallPhase`.
    fn scale(&self, y: &[f64; 2]) -> [f64; 2] {
        let s = y[0].abs().max(y[1].abs() / self.big_omega);
        [s, self.big_omega * s]
    }
    fn accel_uses_velocity(&self) -> bool {
        false
    }
    fn taylor_series(&self, series: &mut super::integrators::taylor::Series<2>) -> bool {
        super::integrators::taylor::complement_series_f64(self.big_omega2, series);
        true
    }
}

/// Separation in the complement: the factor Ω² sin φ − φ̇² (= Ω² cos θ − θ̇²) falls through 0.
pub struct ComplementSeparation(pub f64);

impl Event<2> for ComplementSeparation {
    fn value(&self, _t: f64, y: &[f64; 2]) -> f64 {
        self.0 * y[0].sin() - y[1] * y[1]
    }
    fn direction(&self) -> Direction {
        Direction::Falling
    }
    /// d/dt (Ω² sin φ − φ̇²) = Ω² cos φ φ̇ − 2 φ̇ φ̈.
    fn rate(&self, _t: f64, y: &[f64; 2], dy: &[f64; 2]) -> Option<f64> {
        Some(self.0 * y[0].cos() * dy[0] - 2.0 * y[1] * dy[1])
    }
    /// Ω² sin φ − φ̇² and its rate on the step's polynomials of sin φ and φ̇.
    fn on_series(&self, s: &Series<2>, tau: f64) -> Option<(f64, f64)> {
        Some(separation_factor_on(
            self.0,
            &s.sin,
            &s.y[1],
            s.order,
            s.inv_unit(),
            tau,
        ))
    }
    /// Ω² sin φ − φ̇² with the carried sin φ.
    fn value_with_trig(&self, _t: f64, y: &[f64; 2], trig: (f64, f64)) -> f64 {
        self.0 * trig.0 - y[1] * y[1]
    }
}

/// The state (φ, φ̇) as (θ, θ̇) = (π/2 − φ, −φ̇).
pub fn to_theta(y: &[f64; 2]) -> [f64; 2] {
    [complement(y[0]), -y[1]]
}

/// An observer of (θ, θ̇) fed from a run in the complement.
pub struct InTheta<'a, O>(pub &'a mut O);

impl<O: Observer<2>> Observer<2> for InTheta<'_, O> {
    fn samples_per_step(&self) -> usize {
        self.0.samples_per_step()
    }
    fn observe(&mut self, t: f64, y: &[f64; 2]) {
        self.0.observe(t, &to_theta(y));
    }
    fn wants_steps(&self) -> bool {
        self.0.wants_steps()
    }
    fn step(&mut self, t0: f64, t1: f64, dense: &dyn Fn(f64) -> [f64; 2]) {
        self.0.step(t0, t1, &|t| to_theta(&dense(t)));
    }
}

/// Phase-2 θ̈ written in the complement: cos φ (g/l − sin φ φ̇²) / (cos² φ + 1/3)
/// (`floor::angular_acceleration` with sin θ = cos φ, cos θ = sin φ); φ̈ is its negative.
pub fn floor_theta_acceleration<D: DualNum<Primitive = f64> + Copy>(
    g_over_l: f64,
    phi: D,
    rate: D,
) -> D {
    let (s, c) = phi.sin_cos();
    c * (-(s * rate * rate) + g_over_l) / (c * c + 1.0 / 3.0)
}

/// The floor force of phase 2 (`floor::floor_force`) from (φ, φ̇):
/// F_f = m (g − l (cos φ θ̈ + sin φ φ̇²)).
pub fn floor_force(ladder: &Ladder<f64>, phi: f64, rate: f64) -> f64 {
    let (m, l, g) = (ladder.m, ladder.l, ladder.g);
    let acc = floor_theta_acceleration(g / l, phi, rate);
    let (s, c) = phi.sin_cos();
    m * (g - l * (c * acc + s * rate * rate))
}

/// Phase 2 in the complement: y = [φ, X, φ̇, Ẋ], y' = [φ̇, Ẋ, −θ̈, 0] (`floor::FloorPhase`).
#[derive(Clone, Copy, Debug)]
pub struct ComplementFloor {
    g_over_l: f64,
    big_omega: f64,
    half_length: f64,
}

impl ComplementFloor {
    /// The complement floor phase of `ladder`.
    pub fn new(ladder: &Ladder<f64>) -> Self {
        ComplementFloor {
            g_over_l: ladder.g / ladder.l,
            big_omega: ladder.big_omega2().sqrt(),
            half_length: ladder.l,
        }
    }
}

impl Ode<4> for ComplementFloor {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 4]) -> [D; 4] {
        let acc = floor_theta_acceleration(self.g_over_l, y[0], y[2]);
        [y[2], y[3], -acc, D::from(0.0)]
    }
    fn max_step(&self, y: &[f64; 4]) -> f64 {
        event_safe_step(self.big_omega, y[2])
    }
    /// As `floor::FloorPhase`'s scale, with φ for θ.
    fn scale(&self, y: &[f64; 4]) -> [f64; 4] {
        let a = y[0].abs().max(y[2].abs() / self.big_omega);
        let x = (y[1].abs().max(y[3].abs() / self.big_omega)).max(self.half_length * a);
        [a, x, self.big_omega * a, self.big_omega * x]
    }
    fn taylor_series(&self, series: &mut super::integrators::taylor::Series<4>) -> bool {
        super::integrators::taylor::complement_floor_series_f64(self.g_over_l, series);
        true
    }
}

/// Phase-2 start in the complement from the separation (φ_s, θ̇_s): X = l cos φ (= l sin θ),
/// φ̇ = −θ̇, Ẋ = l sin φ θ̇ (eq. (7), `floor::state_at_separation`).
pub fn floor_state_at_separation(ladder: &Ladder<f64>, phi: f64, rate: f64) -> [f64; 4] {
    let l = ladder.l;
    [phi, l * phi.cos(), -rate, l * phi.sin() * rate]
}

/// The phase-2 state (φ, X, φ̇, Ẋ) as (θ, X, θ̇, Ẋ).
pub fn floor_to_theta(y: &[f64; 4]) -> [f64; 4] {
    [complement(y[0]), y[1], -y[2], y[3]]
}

/// Flat: φ falls through 0.
pub struct Flat;

impl Event<4> for Flat {
    fn value(&self, _t: f64, y: &[f64; 4]) -> f64 {
        y[0]
    }
    fn direction(&self) -> Direction {
        Direction::Falling
    }
    fn rate(&self, _t: f64, _y: &[f64; 4], dy: &[f64; 4]) -> Option<f64> {
        Some(dy[0])
    }
    /// φ and φ̇ on the step's polynomial of φ.
    fn on_series(&self, s: &Series<4>, tau: f64) -> Option<(f64, f64)> {
        Some(value_and_rate_on(&s.y[0], s.order, s.inv_unit(), tau))
    }
}

impl<O: Observer<4>> Observer<4> for InTheta<'_, O> {
    fn samples_per_step(&self) -> usize {
        self.0.samples_per_step()
    }
    fn observe(&mut self, t: f64, y: &[f64; 4]) {
        self.0.observe(t, &floor_to_theta(y));
    }
    fn wants_steps(&self) -> bool {
        self.0.wants_steps()
    }
    fn step(&mut self, t0: f64, t1: f64, dense: &dyn Fn(f64) -> [f64; 4]) {
        self.0.step(t0, t1, &|t| floor_to_theta(&dense(t)));
    }
}
