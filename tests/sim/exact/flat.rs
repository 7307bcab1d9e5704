//! Tests of `sliding_ladder::sim::exact::flat` (src/sim/exact/flat.rs).

use sliding_ladder::sim::exact::flat::{floor_duration, floor_duration_from, gauss, rule, OMEGA2};

#[test]
fn the_rule_integrates_polynomials_of_degree_19_exactly() {
    let r = rule();
    let f = |x: f64| x.powi(18) + x.powi(19);
    // ∫_0^1 x^18 + x^19 = 1/19 + 1/20.
    let got = gauss(&f, 0.0, 1.0, &r);
    assert!((got - (1.0 / 19.0 + 1.0 / 20.0)).abs() <= 4.0 * f64::EPSILON);
    // and not degree 20: the check can fail.
    let g = |x: f64| x.powi(20);
    assert!((gauss(&g, 0.0, 1.0, &r) - 1.0 / 21.0).abs() > 1e-12);
}

#[test]
fn a_start_at_the_floor_takes_no_time_and_the_duration_grows_with_height() {
    // φ_s → 0: the duration scales as √φ_s (θ̇ ~ √φ_s over a distance φ_s).
    let (d1, d2) = (floor_duration(1e-8), floor_duration(4e-8));
    assert!((d2 / d1 - 2.0).abs() < 1e-6, "{d1} {d2}");
    assert!(floor_duration(2.0 / 3.0) > floor_duration(0.5));
}

/// The duration against the energy integral's ∫ dφ/φ̇ from separation to flat, evaluated
/// independently with mpmath's tanh-sinh quadrature at 40 digits (the integrand from
/// ½ (cos²φ + 1/3) φ̇² + sin φ = ½ (cos²φ_s + 1/3) φ̇_s² + sin φ_s, φ̇_s² = Ω² sin φ_s, in
/// units of l, g). Error model: the adaptive rule stops where two levels agree to 4 ε and
/// its panels' integrands carry a few ulps each, so 16 ε relative (measured: 2-3 ε). A
/// single 10-point rule on the whole span misses by 5.7e-13 at cos θ_s = 2/3: the
/// integrand's branch point, where K + sin φ_s − sin φ = 0, lies near the span (mutation
/// testing: the midpoint 0.5 (a + b) → 0.5 a b, which leaves one rule on [0, φ_s], went
/// unseen).
#[test]
fn the_duration_is_the_energy_integral_to_rounding() {
    for (cos_s, want) in [
        (2.0 / 3.0, 0.793_179_439_617_207_5),
        (0.5, 0.642_359_278_102_382_1),
        (0.1, 0.268_016_187_072_680_76),
        (1e-4, 0.008_452_994_638_527_993),
        (1.0, 1.554_342_476_209_089_8),
    ] {
        let got = floor_duration(cos_s);
        assert!(
            (got - want).abs() <= 16.0 * f64::EPSILON * want,
            "cos θ_s {cos_s}: {got} against {want}"
        );
    }
}

/// From upright at θ̇0 = 0.9 per √(l/g) (past the release push Ω = 0.866): 1.527855663419451
/// by mpmath (`python3 tools/near_release_reference.py --past`), 16 ε as above; and the
/// general form agrees with the separation's at θ̇_s² = Ω² cos θ_s.
#[test]
fn the_duration_from_any_start_is_the_energy_integral() {
    let got = floor_duration_from(std::f64::consts::FRAC_PI_2, 0.9);
    let want = 1.527_855_663_419_451_5;
    assert!((got - want).abs() <= 16.0 * f64::EPSILON * want, "{got}");
    let c: f64 = 0.5;
    let from = floor_duration_from(c.asin(), (OMEGA2 * c).sqrt());
    assert!((from - floor_duration(c)).abs() <= 16.0 * f64::EPSILON * from);
}
