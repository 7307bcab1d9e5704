//! `sim::near_release`: pushes just below the release push, against mpmath references.

mod pushes;
mod pushes_below;

use sliding_ladder::sim::event::Event;
use sliding_ladder::sim::integrators::taylor::wall_series;
use sliding_ladder::sim::integrators::taylor::Series;
use sliding_ladder::sim::integrators::Ode;
use sliding_ladder::sim::near_release::{applies, NearRelease, NearSeparation};
use sliding_ladder::sim::rigid::separation_factor;
use sliding_ladder::sim::start_margin::Lean;

const OMEGA2: f64 = 0.75;

/// The deviation form's Taylor series is the wall phase's in θ (an independent recursion,
/// `taylor_series::wall_series`, itself checked in exact arithmetic) shifted by the start:
/// u_k = θ_k and v_k = θ̇_k for k ≥ 1. Error model: both sum the same products in another
/// order (sin θ = sin θ0 cos u + cos θ0 sin u here), so each coefficient agrees to a few
/// ulps of the sum of its terms' magnitudes, bounded by 64 u (|c_k| + Ω^k) at H = 1. A
/// coefficient of the wrong sign of sin θ0 (angle subtraction) is off by far more.
#[test]
fn the_series_is_the_wall_series_shifted_by_the_start() {
    let p = 20;
    for (theta0, rate0, u0, v0) in [
        (0.0, 0.8, 0.1, 0.02),
        (0.4, 0.6, 0.05, -0.01),
        (1.2, 0.3, 0.2, 0.1),
    ] {
        let model = NearRelease::new(OMEGA2, Lean::Theta(theta0), rate0, 0.1);
        let mut s = Series::<2>::new(p);
        (s.y[0][0], s.y[1][0]) = (u0, v0);
        (s.sin[0], s.cos[0]) = (u0.sin(), u0.cos());
        assert!(model.taylor_series(&mut s));
        let inv: Vec<f64> = (0..=p + 1)
            .map(|k| if k == 0 { 0.0 } else { 1.0 / k as f64 })
            .collect();
        let (mut th, mut w, mut sn, mut cs) = (
            vec![0.0; p + 1],
            vec![0.0; p + 1],
            vec![0.0; p + 1],
            vec![0.0; p + 1],
        );
        (th[0], w[0]) = (theta0 + u0, rate0 + v0);
        (sn[0], cs[0]) = (th[0].sin(), th[0].cos());
        wall_series(&OMEGA2, &inv, &mut th, &mut w, &mut sn, &mut cs);
        for k in 1..=p {
            let scale = 64.0 * f64::EPSILON * (th[k].abs() + 1.0);
            assert!((s.y[0][k] - th[k]).abs() <= scale, "θ0 {theta0}: u_{k}");
            let scale = 64.0 * f64::EPSILON * (w[k].abs() + 1.0);
            assert!((s.y[1][k] - w[k]).abs() <= scale, "θ0 {theta0}: v_{k}");
        }
        if theta0 > 0.0 {
            // The check can fail: with sin θ0 of the wrong sign v_1 = Ω² sin(u − θ0) ≠ θ̇_1.
            let wrong = OMEGA2 * (u0 - theta0).sin();
            assert!((wrong - w[1]).abs() > 0.1);
        }
    }
}

/// The factor in the deviation form is Ω² cos θ − θ̇² (`rigid::separation_factor`) at
/// θ = θ0 + u, θ̇ = θ̇0 + v when D0 is the start's factor: away from the release push both
/// are sums of terms of size Ω² + θ̇², rounded a few times: 16 u of that. A sign slip in the
/// fall term is off by O(Ω² u²).
#[test]
fn the_factor_is_the_wall_force_factor() {
    for (theta0, rate0, y) in [(0.0, 0.5, [0.3, 0.04]), (0.7, 0.2, [0.2, 0.15])] {
        let d0 = separation_factor(OMEGA2, theta0, rate0);
        let model = NearRelease::new(OMEGA2, Lean::Theta(theta0), rate0, d0);
        let got = model.factor(&y);
        let want = separation_factor(OMEGA2, theta0 + y[0], rate0 + y[1]);
        let scale = OMEGA2 + (rate0 + y[1]).powi(2);
        assert!(
            (got - want).abs() <= 16.0 * f64::EPSILON * scale,
            "{got} {want}"
        );
        let half = (0.5 * y[0]).sin();
        let wrong = d0 + OMEGA2 * 2.0 * model.cos0 * half * half
            - OMEGA2 * model.sin0 * y[0].sin()
            - y[1] * (2.0 * rate0 + y[1]);
        assert!((wrong - want).abs() > 1e-3);
    }
}

/// The event's rate is the derivative of its value along the state rate (central
/// difference along y ± ε dy: truncation ε² times the third derivative, here below
/// Ω² + θ̇² times |dy|³, plus the values' rounding over 2ε). Dropping the θ̇ θ̈ term is
/// off by far more.
#[test]
fn the_event_rate_is_the_derivative_of_the_value() {
    let eps = 1e-5;
    let model = NearRelease::new(OMEGA2, Lean::Theta(0.3), 0.8, 0.05);
    let ev = NearSeparation(&model);
    let y = [0.2, 0.05];
    let dy: [f64; 2] = model.rhs(0.0, &y);
    let at = |s: f64| ev.value(0.0, &[y[0] + s * dy[0], y[1] + s * dy[1]]);
    let central = (at(eps) - at(-eps)) / (2.0 * eps);
    let rate = ev.rate(0.0, &y, &dy).expect("an exact rate");
    let scale = OMEGA2 + (0.8f64 + 0.05).powi(2);
    let tol = eps * eps * scale * (dy[0].abs() + dy[1].abs()).powi(3)
        + 8.0 * f64::EPSILON * scale / (2.0 * eps);
    assert!((rate - central).abs() <= tol, "{rate} {central}");
    let partial = rate + 2.0 * (0.8 + y[1]) * dy[1];
    assert!((partial - central).abs() > 100.0 * tol);
}

/// The error control's floors are the separation's travel and rate gain, from the energy:
/// from upright (cos θ0 − cos θ_s = D0/(3Ω²) = 2 sin²(θ_s/2)) the travel is θ_s to second
/// order in θ_s, and θ̇_s² − θ̇0² = 2D0/3. Checked to the second-order term's size.
#[test]
fn the_floors_are_the_separation_sizes() {
    let (rate0, d0) = (0.8660254, 1.5e-9);
    let model = NearRelease::new(OMEGA2, Lean::Theta(0.0), rate0, d0);
    let theta_s = 2.0 * (d0 / (6.0 * OMEGA2)).sqrt().asin();
    assert!((model.size[0] - theta_s).abs() <= theta_s * theta_s);
    let gain = (rate0 * rate0 + 2.0 * d0 / 3.0).sqrt() - rate0;
    assert!((model.size[1] - gain).abs() <= 1e-6 * gain);
    assert_eq!(model.scale(&[0.0, 0.0]), model.size);
    assert!(applies(OMEGA2, 1.0, rate0) && !applies(OMEGA2, 1.0, 0.5));
}
