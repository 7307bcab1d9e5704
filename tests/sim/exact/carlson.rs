//! Carlson's R_F where the `ellip` crate's iteration cap is reached (two unequal arguments some
//! 1e-250 times the third) and `sim::exact::carlson_rf` applies duplication steps first (DLMF
//! 19.26.18). Held against R_F's limit for two small arguments (DLMF §19.27(ii)):
//! R_F(x, y, z) = ln(16 z/(√x + √y)²)/(2√z) + O(√((x + y)/z) ln), here 1e-125 off (mpmath's
//! elliprf at 50 digits agreed to all of them when this was written). The duplication's
//! rounding and `ellip`'s few ulps: 16 ulps. (Mutation testing: λ = √x√y + √y√z + √z√x with −
//! for its last + went unseen; the fallback had only a finiteness check.)

use sliding_ladder::sim::exact::carlson_rf;

#[test]
fn r_f_with_two_tiny_arguments_is_its_limit() {
    let x = 1e-250f64;
    let y = 2.0 * x;
    // ln(16/(√x (1 + √2))²)/2 with ln x = −250 ln 10, formed without the tiny numbers.
    let want = 0.5 * (16f64.ln() + 250.0 * 10f64.ln() - 2.0 * (1.0 + 2f64.sqrt()).ln());
    for (a, b, c) in [(x, y, 1.0), (1.0, x, y), (y, 1.0, x)] {
        let got = carlson_rf(a, b, c);
        assert!(
            (got - want).abs() <= 16.0 * f64::EPSILON * want,
            "R_F({a:e}, {b:e}, {c:e}) = {got} against {want}"
        );
    }
}

/// A third argument 1e600 times the other two: R_F(1e-300, 1e-300, 1e300) and its
/// permutation. One duplication step gives (2, 2, 1e300): the two small arguments come out
/// equal (their difference is below the rounding of λ ≥ √(x z)), and `ellip` accepts two equal
/// small arguments at any ratio (probed down to 1e-316), so the fallback never takes a second
/// step. With two equal arguments R_F is Carlson's R_C (DLMF 19.2.17):
/// R_C(z, x) = acosh(√(z/x))/√(z − x) = ln(2 · 1e300)/1e150 to 1e-600 relative. 16 ulps.
#[test]
fn r_f_at_a_ratio_of_1e600_is_carlson_s_r_c() {
    let want = (2f64.ln() + 300.0 * 10f64.ln()) / 1e150;
    for (a, b, c) in [(1e-300, 1e-300, 1e300), (1e300, 1e-300, 1e-300)] {
        let got = carlson_rf(a, b, c);
        assert!(
            (got - want).abs() <= 16.0 * f64::EPSILON * want,
            "R_F({a:e}, {b:e}, {c:e}) = {got:e} against {want:e}"
        );
    }
}
