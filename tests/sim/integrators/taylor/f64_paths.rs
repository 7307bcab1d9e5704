//! The f64 fast paths of the wall and floor phases' Taylor recursions
//! (`sim::integrators::taylor_f64`) give the same bits as the generic recursions run in f64
//! (whose coefficients `tests/sim/integrators/taylor/coefficients.rs` checks exactly in rationals): same sums, same order of
//! summation, in the time unit H = 1 and in the scaled units the stepper uses (H a power of
//! two, `inv` = H/k). A changed input changes the bits, so the comparison is not blind.

use sliding_ladder::sim::integrators::taylor::{
    complement_floor_series, complement_floor_series_f64, complement_series, complement_series_f64,
    floor_series, floor_series_f64, wall_series, wall_series_f64, FloorScratch, Series,
};

/// (angle, rate, sin, cos) series to order p in the time unit `unit` by the generic recursion
/// in f64.
fn generic(complement: bool, big_omega2: f64, y0: [f64; 2], p: usize, unit: f64) -> [Vec<f64>; 4] {
    let inv: Vec<f64> = (0..p + 2)
        .map(|k| if k == 0 { 0.0 } else { unit * (1.0 / k as f64) })
        .collect();
    let mut v = [
        vec![0.0; p + 1],
        vec![0.0; p + 1],
        vec![0.0; p + 1],
        vec![0.0; p + 1],
    ];
    let [a, r, s, c] = &mut v;
    (a[0], r[0]) = (y0[0], y0[1]);
    (s[0], c[0]) = y0[0].sin_cos();
    if complement {
        complement_series(&big_omega2, &inv, a, r, s, c);
    } else {
        wall_series(&big_omega2, &inv, a, r, s, c);
    }
    v
}

fn fast(complement: bool, big_omega2: f64, y0: [f64; 2], p: usize, unit: f64) -> [Vec<f64>; 4] {
    let mut s = Series::<2>::new(p);
    s.set_unit(unit);
    assert_eq!(s.unit(), unit, "a power of two is taken as it is");
    (s.y[0][0], s.y[1][0]) = (y0[0], y0[1]);
    (s.sin[0], s.cos[0]) = y0[0].sin_cos();
    if complement {
        complement_series_f64(big_omega2, &mut s);
    } else {
        wall_series_f64(big_omega2, &mut s);
    }
    [
        s.y[0][..=p].to_vec(),
        s.y[1][..=p].to_vec(),
        s.sin[..=p].to_vec(),
        s.cos[..=p].to_vec(),
    ]
}

fn bits(v: &[Vec<f64>; 4]) -> Vec<Vec<u64>> {
    v.iter()
        .map(|c| c.iter().map(|x| x.to_bits()).collect())
        .collect()
}

#[test]
fn the_fast_recursion_gives_the_generic_bits_at_every_order() {
    for complement in [false, true] {
        for y0 in [[0.3, 0.0], [0.1, 0.02], [1.2, -0.7], [1e-9, 1e-6]] {
            for p in [2, 3, 5, 8, 15, 16, 17, 22, 40] {
                for unit in [1.0, 0.5, 4.0, 2f64.powi(-10)] {
                    let (g, f) = (
                        generic(complement, 0.75, y0, p, unit),
                        fast(complement, 0.75, y0, p, unit),
                    );
                    assert_eq!(
                        bits(&f),
                        bits(&g),
                        "complement {complement}, {y0:?}, p = {p}, unit {unit:e}"
                    );
                }
            }
        }
    }
}

#[test]
fn a_changed_input_changes_the_bits() {
    // Ω² one ulp larger: the comparison above would see it.
    let om = 0.75f64;
    let up = f64::from_bits(om.to_bits() + 1);
    for complement in [false, true] {
        let (g, f) = (
            generic(complement, om, [0.3, 0.1], 15, 0.5),
            fast(complement, up, [0.3, 0.1], 15, 0.5),
        );
        assert_ne!(bits(&f), bits(&g));
        // Another time unit: other bits.
        let (g, f) = (
            generic(complement, om, [0.3, 0.1], 15, 0.5),
            fast(complement, om, [0.3, 0.1], 15, 0.25),
        );
        assert_ne!(bits(&f), bits(&g));
    }
}

/// (angle, X, rate, Ẋ, sin, cos) series of the floor phase to order p by the generic recursion
/// in f64.
fn floor_generic(complement: bool, g: f64, y0: [f64; 4], p: usize, unit: f64) -> [Vec<f64>; 6] {
    let inv: Vec<f64> = (0..p + 2)
        .map(|k| if k == 0 { 0.0 } else { unit * (1.0 / k as f64) })
        .collect();
    let mut v: [Vec<f64>; 6] = std::array::from_fn(|_| vec![0.0; p + 1]);
    let mut w: [Vec<f64>; 4] = std::array::from_fn(|_| vec![0.0; p + 1]);
    let [a, x, r, xd, s, c] = &mut v;
    (a[0], x[0], r[0], xd[0]) = (y0[0], y0[1], y0[2], y0[3]);
    (s[0], c[0]) = y0[0].sin_cos();
    let [w0, w1, w2, w3] = &mut w;
    let scratch = FloorScratch {
        rate_sq: w0,
        cos_rate_sq: w1,
        inertia: w2,
        accel: w3,
    };
    let y = [&mut a[..], &mut x[..], &mut r[..], &mut xd[..]];
    if complement {
        complement_floor_series(&g, &inv, y, s, c, scratch);
    } else {
        floor_series(&g, &inv, y, s, c, scratch);
    }
    v
}

fn floor_fast(complement: bool, g: f64, y0: [f64; 4], p: usize, unit: f64) -> [Vec<f64>; 6] {
    let mut s = Series::<4>::new(p);
    s.set_unit(unit);
    for (i, v) in y0.iter().enumerate() {
        s.y[i][0] = *v;
    }
    (s.sin[0], s.cos[0]) = y0[0].sin_cos();
    if complement {
        complement_floor_series_f64(g, &mut s);
    } else {
        floor_series_f64(g, &mut s);
    }
    let mut out: [Vec<f64>; 6] = std::array::from_fn(|i| {
        if i < 4 {
            s.y[i][..=p].to_vec()
        } else {
            Vec::new()
        }
    });
    out[4] = s.sin[..=p].to_vec();
    out[5] = s.cos[..=p].to_vec();
    out
}

fn bits6(v: &[Vec<f64>; 6]) -> Vec<Vec<u64>> {
    v.iter()
        .map(|c| c.iter().map(|x| x.to_bits()).collect())
        .collect()
}

#[test]
fn the_fast_floor_recursion_gives_the_generic_bits_at_every_order() {
    // (angle, X, rate, Ẋ): a separation-like start, one near flat, one with a negative rate.
    let starts = [
        [0.69, 0.89, -2.16, 1.37],
        [1e-3, 1.0, -3.5, 1.4],
        [1.2, 0.3, 0.7, -0.2],
    ];
    for complement in [false, true] {
        for y0 in starts {
            for p in [2, 3, 4, 5, 6, 7, 8, 9, 15, 22, 40] {
                for unit in [1.0, 0.125, 2f64.powi(-10)] {
                    let (g, f) = (
                        floor_generic(complement, 1.0, y0, p, unit),
                        floor_fast(complement, 1.0, y0, p, unit),
                    );
                    assert_eq!(
                        bits6(&f),
                        bits6(&g),
                        "complement {complement}, {y0:?}, p = {p}, unit {unit:e}"
                    );
                }
            }
        }
    }
}

#[test]
fn a_changed_floor_input_changes_the_bits() {
    let y0 = [0.69, 0.89, -2.16, 1.37];
    for complement in [false, true] {
        let g = floor_generic(complement, 1.0, y0, 15, 0.5);
        // g/l changed in its 12th digit (an ulp may vanish in n = (g/l) s − s c θ̇², whose terms
        // cancel to a larger binade).
        let up = 1.0 + 1e-12;
        assert_ne!(bits6(&floor_fast(complement, up, y0, 15, 0.5)), bits6(&g));
        assert_ne!(bits6(&floor_fast(complement, 1.0, y0, 15, 0.25)), bits6(&g));
    }
}
