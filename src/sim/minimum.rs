//! The smallest value of a smooth function on one step's span, from its dense output: samples
//! find the basin, golden-section search refines it. Outputs such as the floor phase's minimum
//! floor force were the smallest of a few samples per step, which misses an interior minimum by
//! O(h²) (1.4e-5 relative at tolerance 1e-14 in issue 17); the search finds it to rounding.
//!
//! Golden section rather than Brent's parabolic `fmin`: the function is cheap, the search stops
//! when the bracket is 1e-9 of the span (the value near a minimum is flat: an error δ in t moves
//! it by O(δ²), far below f64's resolution), about 45 evaluations. Written by hand: a dozen lines,
//! no crate in the dependency list does it on a closure.

/// Smallest value of `f` on [a, b]: `samples` interior samples and both ends, then golden-section
/// search between the neighbours of the smallest sample. Never above the smallest sample.
///
/// The search stops at a bracket of 1e-9 of the span or when it can no longer shrink in f64:
/// on a span far from t = 0 (t ≈ 2e15 s and a span of 1e-3 s, a slow scene's last step),
/// 1e-9 of the span is below the spacing of the floats there and a loop on the width alone
/// never ends (the reliability campaign's hang, 1e6 scenes of seed 1, ninth chunk of 1e5).
pub fn minimum_on(f: impl Fn(f64) -> f64, a: f64, b: f64, samples: usize) -> f64 {
    let n = samples + 1;
    let at = |j: usize| {
        if j == n {
            b
        } else {
            a + (b - a) * j as f64 / n as f64
        }
    };
    let (mut best_j, mut best) = (0, f(a));
    for j in 1..=n {
        let v = f(at(j));
        if v < best {
            (best_j, best) = (j, v);
        }
    }
    let (mut lo, mut hi) = (at(best_j.saturating_sub(1)), at((best_j + 1).min(n)));
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let tol = 1e-9 * (b - a).abs();
    let (mut x1, mut x2) = (hi - r * (hi - lo), lo + r * (hi - lo));
    let (mut f1, mut f2) = (f(x1), f(x2));
    // Each pass shrinks the bracket by 0.618 while it is wider than a few ulps; 200 passes
    // shrink any finite span by 1e-41, so the cap only ends a bracket stuck at rounding.
    for _ in 0..200 {
        if hi - lo <= tol || !(x1 > lo && x2 < hi && x1 <= x2) {
            break;
        }
        if f1 <= f2 {
            (hi, x2, f2) = (x2, x1, f1);
            x1 = hi - r * (hi - lo);
            f1 = f(x1);
        } else {
            (lo, x1, f1) = (x1, x2, f2);
            x2 = lo + r * (hi - lo);
            f2 = f(x2);
        }
    }
    best.min(f1).min(f2)
}
