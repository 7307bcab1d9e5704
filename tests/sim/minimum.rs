//! Tests of `sliding_ladder::sim::minimum` (src/sim/minimum.rs).

use sliding_ladder::sim::minimum::minimum_on;

#[test]
fn an_interior_minimum_is_found_to_rounding() {
    // cos on [2.95, 3.5]: minimum −1 at π, between samples.
    let m = minimum_on(f64::cos, 2.95, 3.5, 4);
    assert!((m + 1.0).abs() <= 2.0 * f64::EPSILON, "{m}");
    // The samples alone (the old monitor) miss it by O(h²) ≈ 1e-4.
    let sampled = (0..=5)
        .map(|j| (2.95 + 0.55 * j as f64 / 5.0).cos())
        .fold(f64::INFINITY, f64::min);
    assert!(sampled + 1.0 > 1e-5, "{sampled}");
    // An end minimum stays at the end.
    assert_eq!(minimum_on(|t| t, 1.0, 2.0, 4), 1.0);
    assert_eq!(minimum_on(|t| -t, 1.0, 2.0, 4), -2.0);
}

#[test]
fn a_span_finer_than_the_floats_there_ends() {
    // 1e-9 of the span (1e-12) is far below the float spacing at 2e15 (0.25): the old loop on
    // the width alone never ended here. The minimum of (t − c)² on the span is found to the
    // spacing of t there, so its value is at most (0.25)².
    let (a, b) = (2.0e15, 2.0e15 + 1e-3 * 2.0e15 * f64::EPSILON * 1e3);
    let c = 0.5 * (a + b);
    let m = minimum_on(|t| (t - c) * (t - c), a, b, 4);
    assert!(m.is_finite() && m <= 0.0625, "{m}");
    // A NaN everywhere comes out as NaN (for the caller's non-finite check), not a loop.
    assert!(minimum_on(|_| f64::NAN, a, b, 4).is_nan());
}

#[test]
fn the_search_starts_from_the_smallest_of_the_promised_samples() {
    // The contract: `samples` interior samples at a + (b − a) j/(samples + 1) and both ends,
    // the result never above the smallest. A narrow dip of depth 1 sits on the first
    // interior sample and a broad shallow basin (depth 0) near 0.7; any other grid (j/samples,
    // j/(samples − 1): mutation testing) misses the dip, whose half-width is a tenth of the
    // distance to the nearest point of such a grid, and returns the basin's 0.
    for samples in 1..=6 {
        let n = (samples + 1) as f64;
        let (dip, width) = (1.0 / n, 0.1 / (n * (n - 1.0)));
        let f = |t: f64| 0.1 * (t - 0.7) * (t - 0.7) - (-((t - dip) / width).powi(2)).exp();
        let promised = (0..=samples + 1)
            .map(|j| f(j as f64 / n))
            .fold(f64::INFINITY, f64::min);
        let m = minimum_on(f, 0.0, 1.0, samples);
        assert!(
            promised < -0.9 && m <= promised,
            "{samples}: {m} > {promised}"
        );
    }
}

/// The search stops at a bracket of 1e-9 of the span, wherever the span lies: the minimum
/// of ((t − c)/w)² on [a, a + w] is then found to within 1e-9 w in t, so its value is at
/// most (1e-9 + 4 ulp(a)/w)² (the ulps: t − c near a). A stop read off the span's position
/// (1e-9 (b + a): far too loose on [1e6, 1e6 + 1]) or its reciprocal (1e-9/(b − a): wider
/// than a span of 1e-6, so no search at all) leaves it 1e-7 or more (mutation testing).
#[test]
fn the_search_stops_at_a_fixed_fraction_of_the_span() {
    for (a, w) in [(1e6, 1.0), (0.0, 1e-6), (-3.0, 0.25), (1e-6, 1e-6)] {
        let c = a + 0.37 * w;
        let m = minimum_on(|t| ((t - c) / w).powi(2), a, a + w, 4);
        let bound = (1e-9 + 4.0 * (a.abs() * f64::EPSILON) / w).powi(2);
        assert!(m <= bound, "[{a}, {a} + {w}]: {m:e} above {bound:e}");
    }
}

/// The search's cost: the samples (both ends and `samples` inside), the first two golden
/// points, and one evaluation a pass until the bracket, at most 2/(samples + 1) of the span,
/// is within 1e-9 of the span: ⌈ln(1e-9 (samples + 1)/2)/ln r⌉ passes (r = 0.618), 42 for
/// four samples. A search that went on to rounding after that (mutation testing: the stop
/// `width ≤ tol || degenerate` → `&&` went unseen, its answer is as good) costs some 30 more.
#[test]
fn the_search_stops_once_the_bracket_is_within_its_tolerance() {
    for (a, b) in [(2.95, 3.5), (0.0, 1e-6), (1e6, 1e6 + 1.0)] {
        let c = a + 0.37 * (b - a);
        let count = std::cell::Cell::new(0u32);
        let f = |t: f64| {
            count.set(count.get() + 1);
            (t - c) * (t - c)
        };
        minimum_on(f, a, b, 4);
        let r = 0.5 * (5f64.sqrt() - 1.0);
        let passes = ((1e-9 * 5.0 / 2.0f64).ln() / r.ln()).ceil() as u32;
        assert_eq!(passes, 42);
        assert!(
            count.get() <= 6 + 2 + passes,
            "[{a}, {b}]: {} evaluations",
            count.get()
        );
    }
}

/// On a span of a few dozen to a few hundred floats, far from t = 0 (where 1e-9 of the span
/// is below the spacing of the floats), the search stops once its bracket can no longer
/// shrink: after the samples, two golden points and one pass for each factor 1/r = 1.618
/// between the span and the float spacing there (mutation testing: the degenerate-bracket
/// stop `x1 > lo && x2 < hi && x1 ≤ x2` with `||` for its second `&&` went unseen: it ran the
/// search on to its 200-pass cap, some 190 evaluations more, on every such span).
#[test]
fn the_search_stops_when_the_bracket_is_down_to_the_float_spacing() {
    let r = 0.5 * (5f64.sqrt() - 1.0);
    for (a, b) in [
        (1e10f64, 1e10 + 1e-3),
        (2e15, 2e15 + 3.0),
        (1e6, 1e6 + 1e-8),
        (-1e12, -1e12 + 1e-2),
    ] {
        let spacing = f64::from_bits(a.abs().to_bits() + 1) - a.abs();
        let tol = 1e-9 * (b - a);
        assert!(
            tol < spacing,
            "[{a}, {b}]: the width test alone never stops"
        );
        let passes = ((b - a) / spacing).ln() / (1.0 / r).ln();
        for frac in [0.01, 0.2, 0.37, 0.5, 0.99] {
            let c = a + frac * (b - a);
            let count = std::cell::Cell::new(0u32);
            let f = |t: f64| {
                count.set(count.get() + 1);
                (t - c) * (t - c)
            };
            minimum_on(f, a, b, 4);
            assert!(
                count.get() as f64 <= 6.0 + 2.0 + passes.ceil(),
                "[{a}, {b}], minimum at {frac}: {} evaluations for {passes:.1} passes",
                count.get()
            );
        }
    }
}
