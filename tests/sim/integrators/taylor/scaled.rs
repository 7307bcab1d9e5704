//! The Taylor method's coefficients in scaled time (issue 13): the stepper stores x_k H^k, H a
//! time unit of the step (a power of two near the model's time scale), so that high orders do
//! not overflow f64 whatever unit the model is run in.
//!
//! **Why this can fail.** Unscaled, the coefficients grow as Ω^k: a wall phase run in seconds
//! with T = 2⁻⁵⁰ s has Ω ≈ 2⁵⁰ s⁻¹, and its order-22 coefficient (≈ 2^1100) overflows: the
//! step comes out 0 and the stepper stops ([`high_orders_are_unit_free`] fails so with the time
//! unit held at 1 s, checked by that mutation). The exact test below checks the rule the scaling rests on (each recursion run
//! with H/k in place of 1/k gives x_k H^k), and that a wrong H is seen.

use num_traits::Zero;
use sliding_ladder::scalar::{Rational, Scalar};
use sliding_ladder::sim::complement::{ComplementFloor, ComplementWall};
use sliding_ladder::sim::floor::FloorPhase;
use sliding_ladder::sim::integrators::taylor::{
    floor_series, reciprocals, wall_series, FloorScratch, Taylor,
};
use sliding_ladder::sim::integrators::{Ode, Stepper};
use sliding_ladder::sim::rigid::WallPhase;

use sliding_ladder::ladder::Ladder;
type Q = Rational;

/// (steps, θ, θ̇ T, t / T) after integrating `sys` from `y0` to t = 2 T with order `p` at
/// tolerance 1e-12, everything in seconds (the model built from a ladder of time unit T).
fn run_in_seconds<const N: usize, S: Ode<N>>(
    sys: &S,
    unit: f64,
    y0: [f64; N],
    p: usize,
) -> Result<(u64, [f64; N], f64), String> {
    let mut st = Taylor::with_order(0.0, y0, 1e-12, p);
    let t_end = 2.0 * unit;
    while st.t() < t_end {
        st.step(sys, t_end)
            .map_err(|e| format!("T = {unit:e} s, order {p}: {e}"))?;
    }
    // Angles as they are; rates (the second half of the state) times T; positions are in
    // units of l, which scales as T² here (g = 1): divide by T².
    let y = std::array::from_fn(|i| match (N, i) {
        (4, 1) => st.y()[i] / (unit * unit),
        (4, 3) => st.y()[i] / unit,
        (2, 1) | (4, 2) => st.y()[i] * unit,
        _ => st.y()[i],
    });
    Ok((st.stats().steps, y, st.t() / unit))
}

/// Ladders of time unit T = 2⁻⁵⁰, 1 and 2⁵⁰ s (g = 1, l = T²: every conversion exact).
fn ladders() -> [(Ladder<f64>, f64); 3] {
    [-50, 0, 50].map(|e: i32| {
        let unit = 2f64.powi(e);
        (
            Ladder {
                m: 1.0,
                l: unit * unit,
                g: 1.0,
            },
            unit,
        )
    })
}

/// Orders 22 (the least-work order at 1e-11) and 40 (the highest stored), on the wall phase in θ
/// and in the complement and on the floor phase, in seconds at T = 2⁻⁵⁰, 1 and 2⁵⁰ s: every run
/// finishes, with the same steps and the same bits once converted to units of T (all the
/// scalings are by powers of two).
#[test]
fn high_orders_are_unit_free() {
    let mut checked = 0;
    for p in [22, 40] {
        let mut wall = Vec::new();
        let mut comp = Vec::new();
        let mut floor = Vec::new();
        for (ladder, unit) in ladders() {
            wall.push(run_in_seconds(
                &WallPhase::new(&ladder),
                unit,
                [0.3, 0.0],
                p,
            ));
            comp.push(run_in_seconds(
                &ComplementWall::new(&ladder),
                unit,
                [1.2, 0.0],
                p,
            ));
            let l = ladder.l;
            let y0 = [0.9, l * 0.9f64.sin(), -0.8 / unit, 0.2 * l / unit];
            floor.push(run_in_seconds(&FloorPhase::new(&ladder), unit, y0, p));
            let y0 = [0.6, l * 0.6f64.cos(), 0.8 / unit, 0.2 * l / unit];
            floor.push(run_in_seconds(&ComplementFloor::new(&ladder), unit, y0, p));
        }
        for (name, runs, stride) in [("wall", wall, 1), ("complement", comp, 1)] {
            let runs: Vec<_> = runs
                .into_iter()
                .collect::<Result<_, _>>()
                .unwrap_or_else(|e| panic!("{name}: {e}"));
            for r in &runs[1..] {
                assert_eq!(
                    *r, runs[0],
                    "{name}, order {p}: {r:?} against {:?}",
                    runs[0]
                );
            }
            assert!(runs[0].0 > 1, "{name}: several steps");
            checked += stride;
        }
        let floor: Vec<_> = floor
            .into_iter()
            .collect::<Result<_, _>>()
            .unwrap_or_else(|e| panic!("floor: {e}"));
        for model in 0..2 {
            let first = floor[model];
            for r in floor.iter().skip(model).step_by(2) {
                assert_eq!(*r, first, "floor model {model}, order {p}");
            }
            checked += 1;
        }
    }
    assert_eq!(checked, 8);
}

fn q(n: i64, d: i64) -> Q {
    Q::ratio(n, d)
}

/// H/k for k = 0..n (entry 0 is 0).
fn unit_reciprocals(h: &Q, n: usize) -> Vec<Q> {
    reciprocals::<Q>(n)
        .into_iter()
        .map(|r| r * h.clone())
        .collect()
}

/// The wall phase's series from (θ0, θ̇0) = (7/4, −1/3), (sin, cos) = (3/5, 4/5), Ω² = 2/3,
/// with `inv` as the recursion's H/k.
fn wall(inv: &[Q], p: usize) -> [Vec<Q>; 4] {
    let z = || vec![Q::zero(); p + 1];
    let mut v = [z(), z(), z(), z()];
    let [th, r, s, c] = &mut v;
    (th[0], r[0], s[0], c[0]) = (q(7, 4), q(-1, 3), q(3, 5), q(4, 5));
    wall_series(&q(2, 3), inv, th, r, s, c);
    v
}

/// The floor phase's series (θ, X, θ̇, Ẋ, sin, cos) from a rational start, with `inv` as H/k.
fn floor(inv: &[Q], p: usize) -> [Vec<Q>; 6] {
    let z = || vec![Q::zero(); p + 1];
    let mut v = [z(), z(), z(), z(), z(), z()];
    let [th, x, r, xd, s, c] = &mut v;
    (th[0], x[0], r[0], xd[0]) = (q(7, 4), q(1, 7), q(-1, 3), q(-2, 9));
    (s[0], c[0]) = (q(3, 5), q(4, 5));
    let (mut a, mut b, mut d, mut e) = (z(), z(), z(), z());
    floor_series(
        &q(2, 3),
        inv,
        [th, x, r, xd],
        s,
        c,
        FloorScratch {
            rate_sq: &mut a,
            cos_rate_sq: &mut b,
            inertia: &mut d,
            accel: &mut e,
        },
    );
    v
}

/// `series` with coefficient k multiplied by H^k.
fn scaled<const M: usize>(series: &[Vec<Q>; M], h: &Q) -> [Vec<Q>; M] {
    series.clone().map(|c| {
        let mut power = Q::int(1);
        c.into_iter()
            .map(|x| {
                let y = x * power.clone();
                power = power.clone() * h.clone();
                y
            })
            .collect()
    })
}

/// Run with H/k in place of 1/k, the wall and floor recursions give exactly x_k H^k; with a
/// different H in one entry they do not.
#[test]
fn the_recursions_with_unit_over_k_give_the_scaled_coefficients_exactly() {
    let p = 10;
    let h = q(3, 7);
    let plain = reciprocals::<Q>(p + 2);
    let with_unit = unit_reciprocals(&h, p + 2);
    assert_eq!(wall(&with_unit, p), scaled(&wall(&plain, p), &h));
    assert_eq!(floor(&with_unit, p), scaled(&floor(&plain, p), &h));
    assert!(!wall(&plain, p)[0][p].is_zero() && !floor(&plain, p)[0][p].is_zero());
    let mut wrong = with_unit.clone();
    wrong[6] = q(1, 6);
    assert_ne!(wall(&wrong, p), scaled(&wall(&plain, p), &h));
    assert_ne!(floor(&wrong, p), scaled(&floor(&plain, p), &h));
}
