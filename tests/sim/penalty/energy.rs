//! The penalty model's energy (`sim::penalty::energy`, units of m g l), the blow-up detector of
//! explicit methods and the energy output of a penalty run, against the rigid ladder's energy
//! written out here: with the springs unloaded (f = v = 0) the state is the rigid one and
//! E = ½ (l θ̇)² + ½ (l²/3) θ̇² + l cos θ = (2/3) θ̇² + cos θ (centre B at speed l θ̇ and
//! height l cos θ, the rod's moment of inertia m l²/3 about B). A term dropped or combined
//! wrongly (the mutation sample's `penalty.rs:168`: the kinetic terms multiplied) fails it.

use sliding_ladder::sim::penalty::{energy, Contact};

#[test]
fn the_unloaded_penalty_energy_is_the_rigid_ladders() {
    let c = Contact {
        kappa: 1e4,
        gamma: 0.0,
    };
    for (theta, rate) in [(0.3f64, 0.0f64), (0.7, 0.9), (1.2, -0.4), (0.01, 2.0)] {
        let e = energy(&c, &[theta, 0.0, 0.0, rate, 0.0, 0.0]);
        let rigid = 2.0 / 3.0 * rate * rate + theta.cos();
        // Error model: a dozen roundings of O(1) terms, ≤ 16 u of the largest.
        let bound = 16.0 * f64::EPSILON * (1.0 + rate * rate);
        assert!(
            (e - rigid).abs() <= bound,
            "θ = {theta}, θ̇ = {rate}: {e} vs {rigid}"
        );
    }
    // A compressed wall spring adds f_w²/(2κ) (with x moved so that θ and the height stay):
    // f_w = 2 m g at κ = 1e4 stores 2e-4 m g l.
    let loaded = energy(&c, &[0.3, 2.0, 0.0, 0.0, 0.0, 0.0]);
    let stored = loaded - 0.3f64.cos();
    assert!((stored - 2e-4).abs() <= 1e-15, "{stored}");
}
