//! Tests of `sliding_ladder::sim::exact::near_flat` (src/sim/exact/near_flat.rs).

use sliding_ladder::sim::exact::near_flat::{near_flat, NEAR_FLAT_SIZE};
use sliding_ladder::sim::exact::PhaseOne;
use std::f64::consts::FRAC_PI_2;

/// At a start both forms can hold exactly (θ0 an f64 whose complement is exact), the
/// near-flat times agree with Carlson's closed form (`PhaseOne`) to its conditioning, and
/// a wrong constant acceleration (Ω² for the floor's 3g/4l taken as g/l) is seen.
#[test]
fn the_near_flat_fall_is_the_closed_form_where_both_hold() {
    let big_omega2 = 0.75;
    for k in [1u64, 1000, 3_000_000] {
        let theta0 = f64::from_bits(FRAC_PI_2.to_bits() - k);
        let phi0 = (FRAC_PI_2 - theta0) + 6.123_233_995_736_766e-17;
        for rate0 in [0.0, 0.3 * (big_omega2 * phi0).sqrt()] {
            let nf = near_flat(big_omega2, phi0, rate0).unwrap();
            let sep = PhaseOne::new(theta0, rate0, big_omega2)
                .unwrap()
                .separation()
                .unwrap();
            let rel = (nf.separation_time - sep.time).abs() / sep.time;
            // PhaseOne near π/2 carries u/φ0 relative in its time (θ0's rounding).
            let bound = 16.0 * f64::EPSILON * (1.0 + 1e-16 / phi0);
            assert!(rel <= bound, "{k} {rate0}: {rel:e} > {bound:e}");
            let rel_rate = (nf.separation_rate - sep.rate).abs() / sep.rate;
            assert!(rel_rate <= bound, "{k}: rate {rel_rate:e}");
        }
    }
    // Flat: the continued fall with −Ω² from rest takes √(2 φ0)/Ω; the same fall under g/l
    // (the floor phase's 3g/4l misread) would be shorter by √(3/4), far outside rounding.
    let nf = near_flat(0.75, 1e-200, 0.0).unwrap();
    let want = (2.0 * 1e-200f64).sqrt() / 0.75f64.sqrt();
    assert!((nf.flat_time - want).abs() <= 4.0 * f64::EPSILON * want);
    let wrong = (2.0 * 1e-200f64).sqrt(); // Ω² = g/l = 1
    assert!((nf.flat_time - wrong).abs() > 0.1 * want);
}

#[test]
fn subnormal_starts_keep_their_digits_and_large_ones_are_declined() {
    let nf = near_flat(0.75, 5e-324, 0.0).unwrap();
    assert!(nf.flat_time > 0.0 && nf.separation_time > 0.0);
    assert!(nf.separation_time < nf.flat_time);
    // φ0 = 1e-320 and θ̇0 = 3e-161 (θ̇0² = 9e-322) are subnormal: the push must still
    // shorten the fall by its share, (w_f − w0 against w_f at rest, w = θ̇/Ω).
    let pushed = near_flat(0.75, 1e-320, 3e-161).unwrap();
    let rest = near_flat(0.75, 1e-320, 0.0).unwrap();
    // t_f/t_f,rest = √2/(√(v² + 2) + v) with v = w0/√φ0 (normal numbers: no underflow).
    let v = 3e-161 / 0.75f64.sqrt() / 1e-320f64.sqrt();
    let want = 2f64.sqrt() / ((v * v + 2.0).sqrt() + v);
    let got = pushed.flat_time / rest.flat_time;
    assert!((got - want).abs() <= 16.0 * f64::EPSILON, "{got} {want}");
    assert!(want < 0.9);
    assert!(near_flat(0.75, 1e-3, 0.0).is_none());
    assert!(near_flat(0.75, 1e-12, 1e-3).is_none());
    // The size is a = φ0 + (θ̇0/Ω)², not its parts: 0.7 S and (0.6 √S)² are each inside,
    // their sum 1.06 S is not, and 0.5 S with (0.7 √S)² (0.99 S) is; both push less than
    // the top's limit θ̇0² < Ω² φ0 (mutation testing: the size test reduced to its parts,
    // φ0 > S or θ̇0/Ω > √S, went unseen).
    let (size, omega) = (NEAR_FLAT_SIZE, 0.75f64.sqrt());
    assert!(near_flat(0.75, 0.7 * size, 0.6 * size.sqrt() * omega).is_none());
    assert!(near_flat(0.75, 0.5 * size, 0.7 * size.sqrt() * omega).is_some());
    // a = S itself is inside: None is for a > S.
    assert!(near_flat(0.75, size, 0.0).is_some());
    // The top leaves at once: θ̇0² ≥ Ω² φ0.
    assert!(near_flat(0.75, 1e-20, 1e-9).is_none());
}

/// The contract's refusals: a start at or past flat (φ0 ≤ 0), a backward push, and an Ω²
/// that is not a positive finite number each give None, while a start just inside them is
/// answered (mutation testing: the guard's last `&&` → `||`, which let every finite Ω²
/// through, went unseen: the callers pass only valid starts).
#[test]
fn starts_outside_the_contract_have_no_answer() {
    assert!(near_flat(0.75, 1e-12, 0.0).is_some());
    for (omega2, phi0, rate0) in [
        (0.75, 0.0, 0.0),
        (0.75, -1e-12, 0.0),
        (0.75, 1e-12, -1e-9),
        (0.0, 1e-12, 0.0),
        (-0.75, 1e-12, 0.0),
        (f64::INFINITY, 1e-12, 0.0),
        (f64::NAN, 1e-12, 0.0),
    ] {
        assert!(
            near_flat(omega2, phi0, rate0).is_none(),
            "{omega2} {phi0} {rate0}"
        );
    }
}

/// The separation's complement is footnote 4 in φ = π/2 − θ: sin φ_s = (2/3) sin φ0 +
/// θ̇0²/(3Ω²), and below 1e-9 rad sin φ = φ to a relative φ²/6 < 1e-18, so
/// φ_s = (2 φ0 + w0²)/3 with w0 = θ̇0/Ω, a sum of positive terms: to a few ulps.
/// Mutation testing: `w_s · w_s` → `w_s + w_s` went unseen; the times and rates were
/// checked, the angle only through them.
#[test]
fn the_separation_complement_is_footnote_4_near_flat() {
    let big_omega2 = 0.75f64;
    for (phi0, w0) in [(1e-10, 0.0), (4e-12, 1e-6), (1e-300, 1e-151), (8e-10, 1e-5)] {
        let nf = near_flat(big_omega2, phi0, w0 * big_omega2.sqrt()).unwrap();
        let want = (2.0 * phi0 + w0 * w0) / 3.0;
        assert!(
            (nf.separation_complement - want).abs() <= 8.0 * f64::EPSILON * want,
            "φ0 {phi0:e}, w0 {w0:e}: {} against {want}",
            nf.separation_complement
        );
    }
}

/// The flat rate of the uniformly accelerated fall (φ̈ = −Ω² once the wall is left, and
/// linear in φ before): by the energy of a uniform acceleration over the distance φ0,
/// θ̇_f² = θ̇0² + 2 Ω² φ0, at rest and pushed, normal and subnormal. A square root and a
/// hypot: 4 ε. (Mutation testing: `Ω · w_f` → `Ω + w_f` went unseen, no test read the
/// flat rate.)
#[test]
fn the_flat_rate_is_the_uniform_accelerations() {
    let big_omega2: f64 = 0.75;
    for (phi0, rate0) in [(1e-200, 0.0), (1e-12, 3e-7), (1e-320, 3e-161)] {
        let nf = near_flat(big_omega2, phi0, rate0).unwrap();
        let want = rate0.hypot((2.0 * big_omega2).sqrt() * phi0.sqrt());
        assert!(
            (nf.flat_rate - want).abs() <= 4.0 * f64::EPSILON * want,
            "φ0 = {phi0:e}, θ̇0 = {rate0:e}: {} against {want}",
            nf.flat_rate
        );
    }
}
