//! The Taylor step's polynomial evaluations (`sim::integrators::taylor_poly`): Horner's rule
//! split by parity and the separation factor with its slope, in the step's time unit. With
//! small integer coefficients at dyadic points every operation is exact, so each must equal the
//! direct sum Σ c_k x^k (and Σ k c_k x^{k−1}) exactly; a wrong term in the even/odd split (an
//! x² where an x belongs, a dropped top coefficient) changes the value.

use sliding_ladder::sim::integrators::taylor::{horner, separation_factor_on};

fn direct(c: &[f64], x: f64) -> (f64, f64) {
    let value = c.iter().rev().fold(0.0, |acc, ck| acc * x + ck);
    let slope = (1..c.len())
        .rev()
        .fold(0.0, |acc, k| acc * x + k as f64 * c[k]);
    (value, slope)
}

/// Coefficients −4..4 in a pattern with no symmetry, `n` of them.
fn coefficients(n: usize, shift: usize) -> Vec<f64> {
    (0..n)
        .map(|k| ((k * 7 + shift * 3) % 9) as f64 - 4.0)
        .collect()
}

#[test]
fn horner_by_parity_is_the_direct_sum() {
    for n in 1..=9 {
        let c = coefficients(n, 1);
        for x in [0.75, -0.5, 1.25, 0.0] {
            assert_eq!(horner(&c, x), direct(&c, x).0, "{n} coefficients at {x}");
        }
    }
}

#[test]
fn the_separation_factor_and_its_slope_are_exact_in_any_unit() {
    let big_omega2 = 3.0;
    for p in 0..=8 {
        let (trig, rate) = (coefficients(p + 1, 2), coefficients(p + 1, 5));
        for inv_unit in [1.0, 0.5, 4.0] {
            for tau in [0.375, -0.25, 0.5] {
                let x = tau * inv_unit;
                let (t, dt) = direct(&trig, x);
                let (r, dr) = direct(&rate, x);
                let want = (
                    big_omega2 * t - r * r,
                    (big_omega2 * dt - 2.0 * r * dr) * inv_unit,
                );
                let got = separation_factor_on(big_omega2, &trig, &rate, p, inv_unit, tau);
                assert_eq!(got, want, "p = {p}, 1/H = {inv_unit}, τ = {tau}");
            }
        }
    }
}

#[test]
fn a_changed_coefficient_changes_the_values() {
    let c = coefficients(8, 1);
    let mut d = c.clone();
    d[7] += 1.0;
    assert_ne!(horner(&c, 0.75), horner(&d, 0.75));
    let got = separation_factor_on(3.0, &c, &c, 7, 1.0, 0.75);
    assert_ne!(got.1, separation_factor_on(3.0, &d, &c, 7, 1.0, 0.75).1);
}
