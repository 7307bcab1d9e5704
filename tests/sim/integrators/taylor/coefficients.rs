//! The Taylor method: its coefficients are exact (rationals, against an independent series), its
//! error falls as its order predicts, and it finds the separation and the flat events.

use num_traits::Zero;
use sliding_ladder::scalar::{Rational, Scalar};
use sliding_ladder::sim::exact::PhaseOne;
use sliding_ladder::sim::fall;
use sliding_ladder::sim::integrators::taylor::{
    floor_series, reciprocals, wall_series, FloorScratch, Taylor,
};
use sliding_ladder::sim::integrators::{Control, Stepper};
use sliding_ladder::sim::rigid::WallPhase;

use sliding_ladder::ladder::Ladder;
use sliding_ladder::sim::scene::End;

type Q = Rational;

fn q(n: i64, d: i64) -> Q {
    Q::ratio(n, d)
}

/// a·b truncated after order p.
fn mul(a: &[Q], b: &[Q]) -> Vec<Q> {
    let p = a.len() - 1;
    (0..=p)
        .map(|k| (0..=k).fold(Q::zero(), |acc, j| acc + a[j].clone() * b[k - j].clone()))
        .collect()
}

/// sin and cos of a series θ by composition (independent of the recursions under test):
/// with δ = θ − θ0, sin θ = s0 cos δ + c0 sin δ and cos θ = c0 cos δ − s0 sin δ, where cos δ and
/// sin δ are their power series in δ (δ has no constant term, so p + 1 terms suffice).
fn sin_cos_by_composition(theta: &[Q], s0: &Q, c0: &Q) -> (Vec<Q>, Vec<Q>) {
    let p = theta.len() - 1;
    let mut delta = theta.to_vec();
    delta[0] = Q::zero();
    let (mut sin_d, mut cos_d) = (vec![Q::zero(); p + 1], vec![Q::zero(); p + 1]);
    let mut power = vec![Q::zero(); p + 1];
    power[0] = Q::int(1);
    let mut fact = Q::int(1);
    for n in 0..=p {
        if n > 0 {
            power = mul(&power, &delta);
            fact *= Q::int(n as i64);
        }
        let sign = if (n / 2) % 2 == 0 { 1 } else { -1 };
        let target = if n % 2 == 0 { &mut cos_d } else { &mut sin_d };
        for k in 0..=p {
            target[k] = target[k].clone() + Q::int(sign) * power[k].clone() / fact.clone();
        }
    }
    let s = (0..=p)
        .map(|k| s0.clone() * cos_d[k].clone() + c0.clone() * sin_d[k].clone())
        .collect();
    let c = (0..=p)
        .map(|k| c0.clone() * cos_d[k].clone() - s0.clone() * sin_d[k].clone())
        .collect();
    (s, c)
}

/// The wall phase's series by Picard iteration on θ̈ = ω² sin θ with sin by composition:
/// each pass fixes at least one more order.
fn wall_by_picard(big_omega2: &Q, theta0: &Q, rate0: &Q, s0: &Q, c0: &Q, p: usize) -> Vec<Q> {
    let mut theta = vec![Q::zero(); p + 1];
    theta[0] = theta0.clone();
    theta[1] = rate0.clone();
    for _ in 0..=p {
        let (s, _) = sin_cos_by_composition(&theta, s0, c0);
        for k in 0..p - 1 {
            theta[k + 2] = big_omega2.clone() * s[k].clone() / Q::int(((k + 1) * (k + 2)) as i64);
        }
    }
    theta
}

/// A rational start: (s0, c0) = (3/5, 4/5) is on the unit circle; θ0 itself only enters as θ_0.
fn start() -> (Q, Q, Q, Q, Q) {
    (q(7, 4), q(2, 3), q(-1, 3), q(3, 5), q(4, 5))
}

fn wall_exact(inv: &[Q], p: usize) -> (Vec<Q>, Vec<Q>, Vec<Q>, Vec<Q>) {
    let (big_omega2, theta0, rate0, s0, c0) = start();
    let (mut th, mut v) = (vec![Q::zero(); p + 1], vec![Q::zero(); p + 1]);
    let (mut s, mut c) = (vec![Q::zero(); p + 1], vec![Q::zero(); p + 1]);
    (th[0], v[0], s[0], c[0]) = (theta0, rate0, s0, c0);
    wall_series(&big_omega2, inv, &mut th, &mut v, &mut s, &mut c);
    (th, v, s, c)
}

#[test]
fn wall_coefficients_are_exact_against_picard_iteration() {
    let p = 12;
    let (big_omega2, theta0, rate0, s0, c0) = start();
    let want = wall_by_picard(&big_omega2, &theta0, &rate0, &s0, &c0, p);
    let (th, v, s, c) = wall_exact(&reciprocals(p + 2), p);
    assert_eq!(th, want, "θ series");
    for k in 0..p {
        assert_eq!(v[k], want[k + 1].clone() * Q::int(k as i64 + 1), "θ̇_{k}");
    }
    let (s_want, c_want) = sin_cos_by_composition(&th, &s0, &c0);
    assert_eq!((s, c), (s_want, c_want), "sin/cos series");
    // The coefficients are not trivially zero: order 12 is a genuine check.
    assert!(!th[p].is_zero() && !th[p - 1].is_zero());
}

#[test]
fn a_wrong_recursion_coefficient_is_caught() {
    let p = 12;
    let (big_omega2, theta0, rate0, s0, c0) = start();
    let want = wall_by_picard(&big_omega2, &theta0, &rate0, &s0, &c0, p);
    for wrong in [2usize, 5, 11] {
        let mut inv = reciprocals::<Q>(p + 2);
        inv[wrong] = q(1, wrong as i64 + 1);
        let (th, ..) = wall_exact(&inv, p);
        assert_ne!(th, want, "1/{wrong} replaced by 1/{}", wrong + 1);
    }
}

fn floor_exact(inv: &[Q], p: usize) -> [Vec<Q>; 6] {
    let (g_over_l, theta0, rate0, s0, c0) = start();
    let z = || vec![Q::zero(); p + 1];
    let (mut th, mut x, mut v, mut xd, mut s, mut c) = (z(), z(), z(), z(), z(), z());
    (th[0], x[0], v[0], xd[0]) = (theta0, q(1, 7), rate0, q(-2, 9));
    (s[0], c[0]) = (s0, c0);
    let (mut a, mut b, mut d, mut e) = (z(), z(), z(), z());
    floor_series(
        &g_over_l,
        inv,
        [&mut th, &mut x, &mut v, &mut xd],
        &mut s,
        &mut c,
        FloorScratch {
            rate_sq: &mut a,
            cos_rate_sq: &mut b,
            inertia: &mut d,
            accel: &mut e,
        },
    );
    [th, x, v, xd, s, c]
}

/// The floor-phase series satisfy (sin² θ + 1/3) θ̈ + sin θ cos θ θ̇² − (g/l) sin θ = 0 order by
/// order, with sin and cos recomputed by composition and θ̈, θ̇ read off θ's own coefficients.
fn floor_residual(series: &[Vec<Q>; 6], p: usize) -> Vec<Q> {
    let (g_over_l, _, _, s0, c0) = start();
    let th = &series[0];
    let (s, c) = sin_cos_by_composition(th, &s0, &c0);
    let rate: Vec<Q> = (0..=p)
        .map(|k| {
            if k < p {
                th[k + 1].clone() * Q::int(k as i64 + 1)
            } else {
                Q::zero()
            }
        })
        .collect();
    let acc: Vec<Q> = (0..=p)
        .map(|k| {
            if k + 2 <= p {
                th[k + 2].clone() * Q::int(((k + 1) * (k + 2)) as i64)
            } else {
                Q::zero()
            }
        })
        .collect();
    let mut inertia = mul(&s, &s);
    inertia[0] = inertia[0].clone() + q(1, 3);
    let lhs = mul(&inertia, &acc);
    let cent = mul(&mul(&s, &c), &mul(&rate, &rate));
    (0..=p - 2)
        .map(|k| lhs[k].clone() + cent[k].clone() - g_over_l.clone() * s[k].clone())
        .collect()
}

#[test]
fn floor_coefficients_satisfy_the_law_of_motion_exactly() {
    let p = 10;
    let series = floor_exact(&reciprocals(p + 2), p);
    let res = floor_residual(&series, p);
    assert!(res.iter().all(Zero::is_zero), "residuals {res:?}");
    let [th, x, v, xd, s, c] = &series;
    // X moves uniformly; θ̇ is θ's derivative; sin and cos are those of θ.
    assert_eq!(x[1], xd[0]);
    assert!(x[2..].iter().chain(&xd[1..]).all(Zero::is_zero));
    for k in 0..p {
        assert_eq!(v[k], th[k + 1].clone() * Q::int(k as i64 + 1));
    }
    let (_, _, _, s0, c0) = start();
    assert_eq!((s.clone(), c.clone()), sin_cos_by_composition(th, &s0, &c0));
    assert!(!th[p].is_zero());
    // A wrong reciprocal in the recursion leaves a residual.
    let mut inv = reciprocals::<Q>(p + 2);
    inv[4] = q(1, 5);
    let bad = floor_residual(&floor_exact(&inv, p), p);
    assert!(bad.iter().any(|r| !r.is_zero()));
}

const LADDER: Ladder<f64> = Ladder {
    m: 1.0,
    l: 1.0,
    g: 9.81,
};

/// |θ(h) − exact| after one step of order p from θ0 = 0.3 at rest.
fn one_step_error(p: usize, h: f64) -> f64 {
    let sys = WallPhase::new(&LADDER);
    let exact = PhaseOne::new(0.3, 0.0, LADDER.big_omega2()).unwrap();
    // A tolerance of 1 with the step limited by t_stop: the step is exactly h.
    let mut st = Taylor::with_order(0.0, [0.3, 0.0], 1.0, p);
    st.step(&sys, h).unwrap();
    assert_eq!(st.t(), h);
    (st.y()[0] - exact.theta(h)).abs()
}

/// Halving the step divides the local error by 2^q, q the order of the first omitted term: from
/// rest θ is even in t (its odd coefficients vanish), so q = p + 1 for odd p and p + 2 for even p.
#[test]
fn error_falls_as_the_order_predicts() {
    for p in [3usize, 4, 5, 6] {
        let (h1, h2) = (0.16, 0.08);
        let (e1, e2) = (one_step_error(p, h1), one_step_error(p, h2));
        // Errors well above the reference's 2 ulps, so the slope is the truncation's.
        assert!(e2 > 1e-12, "p = {p}: {e2:e} too close to rounding");
        let observed = (e1 / e2).log2();
        println!("order {p}: errors {e1:.3e}, {e2:.3e}, observed {observed:.2}");
        let q = if p % 2 == 0 { p + 2 } else { p + 1 };
        assert!(
            (observed - q as f64).abs() < 0.5,
            "order {p}: observed {observed:.2}"
        );
    }
}

#[test]
fn separation_matches_the_exact_reference() {
    for (theta0, rate0) in [(0.1, 0.0), (0.3, 0.0), (1.0, 0.0), (0.0, 1e-6)] {
        let exact = PhaseOne::new(theta0, rate0, LADDER.big_omega2())
            .unwrap()
            .separation()
            .unwrap();
        let mut sc = sliding_ladder::report::work_precision::scene_at(theta0, rate0);
        sc.method = "taylor".into();
        for tol in [1e-8, 1e-12] {
            sc.control = Some(Control::Tolerance(tol));
            let out = fall::run(&sc, fall::MAX_STEPS).unwrap();
            let s = out.separation.unwrap();
            let ea = (s.angle - exact.angle).abs() / exact.angle;
            let et = (s.time - exact.time).abs() / exact.time;
            println!(
                "θ0 {theta0} tol {tol:e}: angle {ea:.2e}, time {et:.2e}, steps {}",
                out.work.wall.steps
            );
            // A relative tolerance per step, over fewer than 100 steps.
            assert!(
                ea < 100.0 * tol && et < 100.0 * tol,
                "θ0 {theta0} tol {tol:e}: {ea:e} {et:e}"
            );
        }
    }
}

#[test]
fn the_fall_to_flat_agrees_with_dop853() {
    let mut sc = sliding_ladder::report::work_precision::scene_at(0.3, 0.0);
    sc.end = End::Flat;
    sc.control = Some(Control::Tolerance(1e-13));
    sc.method = "dop853".into();
    let a = fall::run(&sc, fall::MAX_STEPS).unwrap().flat.unwrap();
    sc.method = "taylor".into();
    sc.control = Some(Control::Tolerance(1e-12));
    let b = fall::run(&sc, fall::MAX_STEPS).unwrap().flat.unwrap();
    println!("flat: dop853 {a:?}\n      taylor {b:?}");
    assert!((a.time - b.time).abs() < 1e-10 * a.time);
    assert!((a.rate - b.rate).abs() < 1e-10 * a.rate.abs());
    assert!((a.centre_x - b.centre_x).abs() < 1e-10 * a.centre_x.abs());
}

#[test]
fn scenes_accept_taylor_for_rigid_contact_only() {
    let rigid = std::fs::read_to_string("scenes/taylor.toml").unwrap();
    let sc = sliding_ladder::sim::scene::parse("scenes/taylor.toml", &rigid).unwrap();
    assert_eq!(sc.method, "taylor");
    let out = fall::run(&sc, fall::MAX_STEPS).unwrap();
    assert!(out.flat.is_some() && out.separation.is_some());
    let penalty = std::fs::read_to_string("scenes/penalty.toml")
        .unwrap()
        .replace("method = \"radau5\"", "method = \"taylor\"");
    let err = sliding_ladder::sim::scene::parse("penalty.toml", &penalty).unwrap_err();
    let msg = err.to_string();
    assert!(
        msg.contains("[integrator] method") && msg.contains("rigid phases only"),
        "{msg}"
    );
}

/// A model without recursions stops the Taylor stepper with a clear error, never a wrong answer.
#[test]
fn models_without_recursions_are_refused() {
    struct Linear;
    impl sliding_ladder::sim::integrators::Ode<2> for Linear {
        fn rhs<D: num_dual::DualNum<Primitive = f64> + Copy>(&self, _t: f64, y: &[D; 2]) -> [D; 2] {
            [y[1], y[0]]
        }
    }
    let mut st = Taylor::new(0.0, [1.0, 0.0], 1e-10);
    let e = st.step(&Linear, 1.0).unwrap_err();
    assert!(e.to_string().contains("no recursion"), "{e}");
}
