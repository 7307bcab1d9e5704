//! Tests of `sliding_ladder::sim::start_margin` (src/sim/start_margin.rs).

// The references keep the digits mpmath printed: more than f64 holds, on purpose.
#![allow(clippy::excessive_precision)]

use num_traits::ToPrimitive;
use sliding_ladder::ladder::Ladder;
use sliding_ladder::sim::start_margin::{fixed_series, start_margin, start_margin_f64, Lean};
use std::f64::consts::FRAC_PI_2;

const UNIT: Ladder<f64> = Ladder {
    m: 1.0,
    l: 1.0,
    g: 1.0,
};

/// The fixed-point cosine and sine/x against f64's (libm, within an ulp): the series is
/// summed right, whatever its last bits. And a wrong series (o swapped) is far off.
#[test]
fn the_series_are_cos_and_sin_over_x() {
    for x in [0.0, 1e-300, 1e-8, 0.3, 1.0, FRAC_PI_2] {
        let c = fixed_series(x, 0).to_f64().expect("finite");
        assert!((c - x.cos()).abs() <= f64::EPSILON, "cos {x}: {c}");
        let s = fixed_series(x, 1).to_f64().expect("finite");
        let want = if x == 0.0 { 1.0 } else { x.sin() / x };
        assert!((s - want).abs() <= 2.0 * f64::EPSILON, "sin/x {x}: {s}");
    }
    assert!((fixed_series(1.0, 1).to_f64().unwrap() - 1f64.cos()).abs() > 0.1);
}

/// From upright, D0 = 3/4 − θ̇0² exactly (cos 0 = 1): its value is checked against the
/// exact product of the inputs, one ulp below fl(Ω) where the f64 form is off by 19 %
/// (mpmath: D0 = 2.792026472903680882473642e-16, tools/near_release_reference.py).
#[test]
fn the_margin_from_upright_is_exact() {
    let w = 0.8660254037844385;
    let want = 2.792_026_472_903_681e-16;
    let got = start_margin(&UNIT, Lean::Theta(0.0), w);
    assert!((got - want).abs() <= f64::EPSILON * want, "{got}");
    let naive = start_margin_f64(&UNIT, Lean::Theta(0.0), w);
    assert!((naive - want).abs() > 0.1 * want, "{naive}");
}

/// In SI (g = 9.81, l = 0.7) and leaning (θ0 = 0.3), against mpmath at 120 digits
/// (tools/near_release_reference.py): within 2 ulps, where the f64 form keeps no digit.
#[test]
fn the_margin_in_si_and_leaning_matches_mpmath() {
    let si = Ladder {
        m: 1.0,
        l: 0.7,
        g: 9.81,
    };
    for (ladder, lean, w, want) in [
        (
            si,
            Lean::Theta(0.0),
            3.242023177849641,
            2.660_039_704_541_903_5e-15,
        ),
        (
            UNIT,
            Lean::Theta(0.3),
            0.8464646282297946,
            9.048_415_678_994_155e-17,
        ),
        (
            UNIT,
            Lean::Phi(1e-12),
            8.660254037844386e-07,
            1.191_560_109_419_765_8e-28,
        ),
    ] {
        let got = start_margin(&ladder, lean, w);
        assert!(
            (got - want).abs() <= 2.0 * f64::EPSILON * want,
            "{lean:?}: {got}"
        );
        let naive = start_margin_f64(&ladder, lean, w);
        assert!((naive - want).abs() > 0.1 * want, "{lean:?}: {naive}");
    }
}
