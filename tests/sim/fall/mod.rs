//! `sim::fall`: whole falls, wall phase then floor phase, from every kind of start.

mod floor_minima;
mod floor_starts;
mod momentum_balance;
mod near_flat_starts;
mod observer;
mod plan;
mod scale;
mod tiny_starts;
mod top_clearance;
mod wall_phase;

// Unit tests of `sim::fall`: the events' rates and values.

use num_dual::DualNum;
use sliding_ladder::ladder::Ladder;
use sliding_ladder::sim::complement;
use sliding_ladder::sim::event::Event;
use sliding_ladder::sim::fall::floor_phase::LiftOffEvent;
use sliding_ladder::sim::fall::wall_phase::SeparationEvent;
use sliding_ladder::sim::integrators::AnyStepper;
use sliding_ladder::sim::integrators::{Control, Ode};
use sliding_ladder::sim::run::integrate_phase;
use std::cell::Cell;

/// `SeparationEvent::rate` is the derivative of its value along the state rate: a central
/// difference of the value, g = Ω² cos θ − θ̇², along y ± ε dy. Error model: g's third
/// derivative along (a, b) is Ω² sin θ a³ (θ̇² is quadratic, its part is exact), so the
/// truncation is at most ε² Ω² |a|³ / 6; each of the two values is rounded to a few ulps of
/// Ω² + θ̇², divided by 2ε. A wrong term (2 θ̇ / θ̈ for 2 θ̇ θ̈, a sign) is off by O(1). The
/// complement's event, Ω² sin φ − φ̇² in φ = π/2 − θ, has the same model (its third derivative
/// is −Ω² cos φ a³); mutation testing found its rate → None unseen, as the root it steers is
/// the same to rounding (Brent's method takes over).
#[test]
fn the_separation_rate_is_the_derivative_of_the_value() {
    let eps = 1e-5;
    for (omega2, y, dy) in [
        (0.75, [0.3, 0.2], [0.2, 0.7]),
        (7.4, [1.1, -1.9], [-1.9, 2.6]),
        (0.02, [0.05, 0.13], [0.13, -0.3]),
    ] {
        let events: [&dyn Event<2>; 2] = [
            &SeparationEvent(omega2),
            &complement::ComplementSeparation(omega2),
        ];
        for (name, ev) in ["wall", "complement"].into_iter().zip(events) {
            let at = |s: f64| ev.value(0.0, &[y[0] + s * dy[0], y[1] + s * dy[1]]);
            let central = (at(eps) - at(-eps)) / (2.0 * eps);
            let rate = ev.rate(0.0, &y, &dy).expect("an exact rate");
            let scale = omega2 + (y[1].abs() + eps * dy[1].abs()).powi(2);
            let tol = eps * eps * omega2 * dy[0].abs().powi(3) / 6.0
                + 8.0 * f64::EPSILON * scale / (2.0 * eps);
            assert!(
                (rate - central).abs() <= tol,
                "{name}: Ω² {omega2}, y {y:?}, dy {dy:?}: rate {rate}, central difference {central}, tol {tol:e}"
            );
            // The check can fail: the rate without its θ̇ term is off by far more than tol.
            assert!((rate + 2.0 * y[1] * dy[1] - central).abs() > 100.0 * tol);
        }
    }
}

/// A toy motion in the floor phase's state [φ, ·, φ̇, ·]: φ = 1/2 held, and the rate the cubic
/// φ̇ = K t (1 − t)², 0 at both ends of [0, 1] and largest (4K/27) at t = 1/3, carried by
/// the state [φ, φ̇'', φ̇, φ̇'] with φ̇''' = 6K. One rk4 step covers [0, 1] and its dense output
/// (cubic Hermite) is exact on a cubic.
struct CubicRate(f64);

impl Ode<4> for CubicRate {
    fn rhs<D: DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 4]) -> [D; 4] {
        [y[0] * 0.0, y[0] * 0.0 + 6.0 * self.0, y[3], y[1]]
    }
}

/// The lift-off watch samples the floor force inside each step: a force that dips below 0 and
/// recovers within one step is found. The floor phase's floor force is
/// m (g − l sin φ φ̇²)/(3 cos²φ + 1) (its φ̈ written in), so it is negative exactly while
/// φ̇² > g/(l sin φ). K puts that threshold at 0.135 K: the rate is above it only between
/// t = 0.225 and 0.456, around the sample at 0.4 of the four at j/5 and away from the step's
/// ends and its middle (0.125 K there). The event ends the phase where that window opens. (Mutation
/// testing: `LiftOffEvent::interior_samples` → 0 and → 1 went unseen: the rigid floor phase
/// never lifts off, so no run had a dip to find.)
#[test]
fn the_lift_off_watch_finds_a_dip_inside_one_step() {
    let ladder = Ladder {
        m: 1.0,
        l: 1.0,
        g: 1.0,
    };
    let phi = 0.5f64;
    let threshold = (1.0 / phi.sin()).sqrt();
    let k = threshold / 0.135;
    let lift = LiftOffEvent {
        ladder,
        evals: Cell::new(0),
    };
    let y0 = [phi, -4.0 * k, 0.0, k];
    let mut stepper = AnyStepper::new("rk4", Control::Fixed(1.0), 0.0, y0).unwrap();
    let events = [&lift as &dyn Event<4>];
    let end = integrate_phase(&CubicRate(k), &mut stepper, &events, 1.0, 10, &mut ()).unwrap();
    assert_eq!(end.event, Some(0), "the dip was not seen");
    assert!(end.t > 0.22 && end.t < 0.23, "{}", end.t);
    let rate = k * end.t * (1.0 - end.t) * (1.0 - end.t);
    // Brent's root is within a few ulps of t, and |dφ̇/dt| ≤ K: 16 ulps of K.
    assert!(
        (rate - threshold).abs() <= 16.0 * f64::EPSILON * k,
        "{rate} against {threshold}"
    );
}

/// The flat event's rate is the derivative of its value φ along the state rate: φ is linear
/// in the state, so a central difference along y ± ε dy is exact up to the rounding of the two
/// values (a few ulps of |φ| + ε |φ̇|, over 2ε). Mutation testing: `Flat::rate` → None and
/// → Some(0.0) went unseen; the root it steers is the same (Brent's method or bisection takes
/// over), at more evaluations.
#[test]
fn the_flat_rate_is_the_derivative_of_the_value() {
    let eps = 1e-3;
    let flat = complement::Flat;
    for (y, dy) in [
        ([0.4, 0.2, -1.3, 0.5], [-1.3, 0.5, 0.7, 0.0]),
        ([1e-3, 1.1, -2.9, 0.8], [-2.9, 0.8, 0.2, 0.0]),
    ] {
        let at = |s: f64| {
            let shifted: [f64; 4] = std::array::from_fn(|i| y[i] + s * dy[i]);
            flat.value(0.0, &shifted)
        };
        let central = (at(eps) - at(-eps)) / (2.0 * eps);
        let rate = flat.rate(0.0, &y, &dy).expect("an exact rate");
        let tol = 4.0 * f64::EPSILON * (y[0].abs() + eps * dy[0].abs()) / (2.0 * eps);
        assert!(
            (rate - central).abs() <= tol,
            "y {y:?}: rate {rate}, central difference {central}"
        );
        // The check can fail: a rate of 0 is off by |φ̇| ≫ tol.
        assert!(central.abs() > 1e3 * tol);
    }
}
