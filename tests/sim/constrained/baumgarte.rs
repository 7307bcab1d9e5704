//! The constrained wall phase (`sim::constrained`) obeys Baumgarte's law off the constraint
//! manifold: each constraint g (top on the wall g₁ = x − sin θ, foot on the floor
//! g₂ = y − cos θ) satisfies g̈ + 2α ġ + β² g = 0 along the model's motion, which is what turns
//! the index-1 drift into a damped oscillator. The derivatives are written out here from the
//! constraints alone: ġ₁ = ẋ − cos θ θ̇, g̈₁ = ẍ + sin θ θ̇² − cos θ θ̈, ġ₂ = ẏ + sin θ θ̇,
//! g̈₂ = ÿ + cos θ θ̇² + sin θ θ̈, with (ẍ, ÿ, θ̈) the model's right-hand side.
//!
//! Error model: each residual sums terms of size at most 1 + θ̇² + 2α|ġ| + β²|g| + |q̈|, each
//! carrying a few roundings (the multipliers' closed form, products, sums): 32 u of that scale.
//! Mutation testing found the gain 2α → 2 + α in the multipliers unseen.

use sliding_ladder::sim::constrained::Constrained;
use sliding_ladder::sim::integrators::eval;

const U: f64 = f64::EPSILON / 2.0;

/// The two residuals g̈ + 2α ġ + β² g of the motion of `model` at state `y`, judged with the
/// gains of `c`, and their rounding bound.
fn residuals(model: &Constrained, c: &Constrained, y: &[f64; 6]) -> ([f64; 2], f64) {
    let f = eval(model, 0.0, y);
    let (s, co) = y[2].sin_cos();
    let w = y[5];
    let g = [y[0] - s, y[1] - co];
    let gd = [y[3] - co * w, y[4] + s * w];
    let gdd = [f[3] + s * w * w - co * f[5], f[4] + co * w * w + s * f[5]];
    let r = [0, 1].map(|i| gdd[i] + 2.0 * c.alpha * gd[i] + c.beta * c.beta * g[i]);
    let scale = 1.0
        + w * w
        + 2.0 * c.alpha * gd[0].abs().max(gd[1].abs())
        + c.beta * c.beta * g[0].abs().max(g[1].abs())
        + f[3].abs().max(f[4].abs()).max(f[5].abs());
    (r, 32.0 * U * scale)
}

/// States off the manifold (constraint errors of 1e-3..1e-1 and rates of them).
const STATES: [[f64; 6]; 3] = [
    [0.5, 0.9, 0.45, 0.2, -0.1, 0.7],
    [0.05, 0.98, 0.1, 0.01, 0.03, 0.2],
    [0.9, 0.3, 1.3, -0.4, 0.5, 1.1],
];

#[test]
fn each_constraint_is_a_damped_oscillator_off_the_manifold() {
    for (alpha, beta) in [(0.0, 0.0), (1.0, 1.0), (5.0, 3.0), (0.3, 20.0)] {
        let c = Constrained { alpha, beta };
        for y in STATES {
            let (r, bound) = residuals(&c, &c, &y);
            for (i, ri) in r.iter().enumerate() {
                assert!(
                    ri.abs() <= bound,
                    "α = {alpha}, β = {beta}, g{}: residual {ri:e} > {bound:e} at {y:?}",
                    i + 1
                );
            }
        }
    }
}

/// The check sees a wrong gain: the residuals of the model with gain α, judged as if it were
/// α + 1, are 2 ġ, far outside the bound.
#[test]
fn a_wrong_gain_fails_the_check() {
    let c = Constrained {
        alpha: 5.0,
        beta: 3.0,
    };
    let judged = Constrained {
        alpha: 6.0,
        beta: 3.0,
    };
    for y in STATES {
        let (r, bound) = residuals(&c, &judged, &y);
        let r = r[0];
        assert!(r.abs() > bound, "{r:e} within {bound:e} at {y:?}");
    }
}

/// The consistent start (`constrained::start`) lies on the manifold with both constraint rates
/// zero: g and ġ = (d/dt) g(q + t q̇) at t = 0, the latter by automatic differentiation of the
/// constraints themselves (not the hand-written ġ above), at rest and pushed, either side of
/// π/4. The position is (sin θ, cos θ) to an ulp, so g is within u, and ġ sums two products of
/// size |θ̇|: within 4 u |θ̇|. Mutation testing: the start's ẋ = cos θ θ̇ → cos θ + θ̇ went
/// unseen (the drift tests measured the unstabilised drift, and a start off the velocity
/// manifold drifts too).
#[test]
fn the_consistent_start_has_both_constraints_and_their_rates_zero() {
    use num_dual::Dual64;
    use sliding_ladder::sim::constrained::{constraints, start};
    for (theta0, rate0) in [(0.3, 0.0), (1.2, 0.0), (0.3, 0.7), (1.2, -2.5), (0.0, 1.0)] {
        let y = start(theta0, rate0);
        assert_eq!((y[2], y[5]), (theta0, rate0), "θ and θ̇ as given");
        let moving: [Dual64; 6] =
            std::array::from_fn(|i| Dual64::new(y[i], if i < 3 { y[i + 3] } else { 0.0 }));
        let (g1, g2) = constraints(&moving);
        assert!(
            g1.re.abs() <= U && g2.re.abs() <= U,
            "g = ({}, {})",
            g1.re,
            g2.re
        );
        let bound = 4.0 * U * rate0.abs();
        assert!(
            g1.eps.abs() <= bound && g2.eps.abs() <= bound,
            "θ0 = {theta0}, θ̇0 = {rate0}: ġ = ({:e}, {:e})",
            g1.eps,
            g2.eps
        );
    }
}
