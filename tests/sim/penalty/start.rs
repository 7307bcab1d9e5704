//! The penalty run's start on the slow manifold (`sim::penalty::start::slow_forces`): the rates
//! it gives are the time derivatives of the forces it gives, along the rigid motion (5). The
//! motion is the exact closed form (`sim::exact::PhaseOne`), and the derivative a Richardson
//! extrapolation of central differences, R = (4 D(δ) − D(2δ))/3 with D(δ) = (F(t + δ) −
//! F(t − δ))/(2δ). Error model: R's truncation is O(δ⁴), below |D(δ) − D(2δ)| (3/4 of D(2δ)'s
//! own O(δ²) error, by the same expansion), and the rounding of the differences is a few ulps of
//! |F| over δ. Soft springs (κ = 5, 50) make the first-order part F₁/κ a fifth or a fiftieth of
//! the force, so its rate shows. (Mutation testing: θ⁗ = Ω² (cos θ θ̈ − sin θ θ̇²) with + for
//! − went unseen: the rate is used only to start a run, whose later motion forgives it.)

use sliding_ladder::sim::exact::PhaseOne;
use sliding_ladder::sim::penalty::start::m_inverse;
use sliding_ladder::sim::penalty::start::{rigid_forces, slow_forces, OMEGA2};
use sliding_ladder::sim::scene::work::wall_force_rate;

/// The Richardson derivative of `force` at `t` and its error bound (module docs).
fn richardson(force: impl Fn(f64) -> f64, t: f64) -> (f64, f64) {
    let delta = 1e-3;
    let diff = |d: f64| (force(t + d) - force(t - d)) / (2.0 * d);
    let (d1, d2) = (diff(delta), diff(2.0 * delta));
    let bound = (d1 - d2).abs() + 16.0 * f64::EPSILON * force(t).abs() / delta;
    ((4.0 * d1 - d2) / 3.0, bound)
}

#[test]
fn the_slow_start_s_rates_are_the_derivatives_of_its_forces() {
    let motion = PhaseOne::new(0.3, 0.2, OMEGA2).unwrap();
    for kappa in [5.0, 50.0, 1e4] {
        for t in [0.3, 0.8, 1.3] {
            let rate = slow_forces(kappa, motion.theta(t), motion.rate(t)).1;
            for (i, got) in rate.into_iter().enumerate() {
                let force = |t: f64| slow_forces(kappa, motion.theta(t), motion.rate(t)).0[i];
                let (want, bound) = richardson(force, t);
                assert!(
                    (got - want).abs() <= bound,
                    "κ = {kappa}, t = {t}, force {i}: {got} against {want} (± {bound:e})"
                );
            }
        }
    }
}

/// `scene::work::wall_force_rate` is the time derivative of the rigid wall force along (5) at
/// any (θ, θ̇), not only at θ = 0 where the penalty refusal asks for it (there θ̈ = 0 and the
/// force's θ̇-derivative −2 θ̇ sin θ is 0, so mutation testing's Ω² + sin θ for Ω² sin θ in the
/// dual number's θ̈ went unseen). Same reference and error model as above.
#[test]
fn the_wall_force_rate_is_the_derivative_of_the_wall_force() {
    let motion = PhaseOne::new(0.3, 0.2, OMEGA2).unwrap();
    for t in [0.0, 0.3, 0.8, 1.3] {
        let force = |t: f64| rigid_forces(motion.theta(t), motion.rate(t)).0;
        let (want, bound) = richardson(force, t);
        let rate = wall_force_rate(motion.theta(t), motion.rate(t));
        assert!(
            (rate - want).abs() <= bound,
            "t = {t}: {rate} against {want} (± {bound:e})"
        );
    }
}

/// M⁻¹ is the inverse of M = ∂P/∂F: M M⁻¹ = I to rounding at any θ (a wrong entry fails).
#[allow(clippy::needless_range_loop)]
#[test]
fn m_inverse_inverts_m() {
    for theta in [0.0, 0.3, 1.0, 1.5] {
        let (s, c) = f64::sin_cos(theta);
        let m = [
            [-1.0 - 3.0 * c * c, 3.0 * s * c],
            [3.0 * s * c, -1.0 - 3.0 * s * s],
        ];
        let mi = m_inverse(theta);
        for i in 0..2 {
            for j in 0..2 {
                let p = m[i][0] * mi[0][j] + m[i][1] * mi[1][j];
                let want = if i == j { 1.0 } else { 0.0 };
                assert!((p - want).abs() <= 8.0 * f64::EPSILON, "{theta} {i}{j} {p}");
            }
        }
    }
}
