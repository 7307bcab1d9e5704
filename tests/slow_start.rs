//! The penalty run's start on the slow manifold (`sim::penalty_start::slow_forces`): the rates
//! it gives are the time derivatives of the forces it gives, along the rigid motion (5). The
//! motion is the exact closed form (`sim::exact::PhaseOne`), and the derivative a Richardson
//! extrapolation of central differences, R = (4 D(δ) − D(2δ))/3 with D(δ) = (F(t + δ) −
//! F(t − δ))/(2δ). Error model: R's truncation is O(δ⁴), below |D(δ) − D(2δ)| (3/4 of D(2δ)'s
//! own O(δ²) error, by the same expansion), and the rounding of the differences is a few ulps of
//! |F| over δ. Soft springs (κ = 5, 50) make the first-order part F₁/κ a fifth or a fiftieth of
//! the force, so its rate shows. (Mutation testing: θ⁗ = Ω² (cos θ θ̈ − sin θ θ̇²) with + for
//! − went unseen: the rate is used only to start a run, whose later motion forgives it.)

use sliding_ladder::sim::exact::PhaseOne;
use sliding_ladder::sim::penalty_start::{slow_forces, OMEGA2};

#[test]
fn the_slow_start_s_rates_are_the_derivatives_of_its_forces() {
    let motion = PhaseOne::new(0.3, 0.2, OMEGA2).unwrap();
    for kappa in [5.0, 50.0, 1e4] {
        for t in [0.3, 0.8, 1.3] {
            let force = |t: f64| slow_forces(kappa, motion.theta(t), motion.rate(t)).0;
            let diff = |d: f64| {
                let (a, b) = (force(t + d), force(t - d));
                [(a[0] - b[0]) / (2.0 * d), (a[1] - b[1]) / (2.0 * d)]
            };
            let delta = 1e-3;
            let (d1, d2) = (diff(delta), diff(2.0 * delta));
            let rate = slow_forces(kappa, motion.theta(t), motion.rate(t)).1;
            let f = force(t);
            for i in 0..2 {
                let richardson = (4.0 * d1[i] - d2[i]) / 3.0;
                let bound = (d1[i] - d2[i]).abs() + 16.0 * f64::EPSILON * f[i].abs() / delta;
                assert!(
                    (rate[i] - richardson).abs() <= bound,
                    "κ = {kappa}, t = {t}, force {i}: {} against {richardson} (± {bound:e})",
                    rate[i]
                );
            }
        }
    }
}
