//! Tests of `sliding_ladder::sim::penalty::plan` (src/sim/penalty/plan.rs).

use sliding_ladder::sim::exact::separation_cos;
use sliding_ladder::sim::penalty::plan::too_close_to_flat;
use sliding_ladder::sim::penalty::start::OMEGA2;
use std::f64::consts::FRAC_PI_2;

/// The least κ a refusal states ("allowed: κ > …").
fn stated_least_kappa(message: &str) -> f64 {
    let after = message.split("κ > ").nth(1).expect("a least κ");
    after.split(' ').next().unwrap().parse().unwrap()
}

#[test]
fn starts_the_springs_cannot_tell_from_flat_are_refused_and_the_rest_run() {
    // Scene 418: π/2 − 2.1e-7 at κ = 1.6e6 is refused; κ = 1e12 runs.
    let near = (FRAC_PI_2 - 2.1e-7, 0.0);
    let m = too_close_to_flat(1.6e6, near).expect("refused");
    assert!(
        m.contains("cannot tell this start's separation from flat"),
        "{m}"
    );
    assert_eq!(too_close_to_flat(1e12, near), None);
    // The stated least κ: just above it runs, just below it is refused.
    let least = stated_least_kappa(&m);
    assert!(too_close_to_flat(least * 1.01, near).is_none());
    assert!(too_close_to_flat(least * 0.99, near).is_some());
    // A start at rest from 1.17 rad separates at θ_r = 1.31 (sin θ_r = 0.966, not 1), 0.26
    // rad from flat: its least κ is near the softest springs, and the shift's κ sin θ_r
    // is tried there 1 % either side (mutation testing: κ + sin θ_r and κ/sin θ_r, which
    // near flat agree with κ sin θ_r, went unseen).
    let (far, soft) = (
        (1.17, 0.0),
        too_close_to_flat(1.0, (1.17, 0.0)).expect("κ = 1"),
    );
    let least = stated_least_kappa(&soft);
    assert!((3.0..10.0).contains(&least), "{least}");
    assert!(too_close_to_flat(least * 1.01, far).is_none());
    assert!(too_close_to_flat(least * 0.99, far).is_some());
    // The last float below π/2 cannot be told from flat at any κ ≤ 1e15.
    let last = f64::from_bits(FRAC_PI_2.to_bits() - 1);
    assert!(too_close_to_flat(1e15, (last, 0.0)).is_some());
    // Ordinary starts at the softest springs scenes allow (κ = 5) run.
    assert_eq!(too_close_to_flat(5.0, (0.6, 0.0)), None);
    assert_eq!(too_close_to_flat(5.0, (1e-12, 0.0)), None);
    // A start the wall cannot hold is left to the run (it leaves at once).
    assert_eq!(too_close_to_flat(1e6, (0.3, 2.0)), None);
    // So is the limiting push θ̇0² = Ω² cos θ0, where cos θ_r is 1 and the top leaves at
    // t = 0: from θ0 = 0 with θ̇0 = √(3/4), cos θ_r comes out exactly 1 in f64
    // (mutation testing: `cos_r < 1` → `<= 1` refused it as "cannot tell from flat").
    let limiting = (0.0, OMEGA2.sqrt());
    assert_eq!(separation_cos(limiting.0, limiting.1, OMEGA2), 1.0);
    assert_eq!(too_close_to_flat(1e6, limiting), None);
}
