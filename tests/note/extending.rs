//! The extensions that equations/EXTENDING.md walks through, each done as a user would and each
//! shown to catch a planted mistake: a new point (in markdown, in a copy of `equations/`), a new
//! derivation method and a new integrator (from outside the crate, through its public API).
//! The first extension, a display in markdown alone, is `tests/note/registry/markdown_alone.rs`.

use crate::common::copy_of_equations;
use serde_json::Value;
use sliding_ladder::derivation::{check_derivation, Derivation};
use sliding_ladder::ladder::analysis::{torque_equation, AngularMomentum, Reference};
use sliding_ladder::ladder::{Ladder, State};
use sliding_ladder::registry::check::{CheckReport, Config};
use sliding_ladder::scalar::Scalar;
use sliding_ladder::sim::exact::PhaseOne;
use sliding_ladder::sim::integrators::fixed::{FixedMethod, FixedStep};
use sliding_ladder::sim::integrators::{eval, Ode, Stepper};
use sliding_ladder::sim::rigid::WallPhase;
use std::process::Command;

/// A fixed point R of the lab, at (l/2, 3l/2), and the torque law about it (display (92)).
/// Reference (sympy, docs/note-as-source.md): dL_R/dt − τ_R = −lm(3g sin θ − 4lθ̈)/3, zero on the
/// motion (5) only; about the moving point Q = ladder:1/4 the same law leaves a θ̇² term.
const LAB_POINT: &str = r#"# Sec. 2.9 — The torque law about a fixed point of the lab, eq. (92)

*Points:* R = lab:1/2,3/2

*Symbols:*
- $L_R$ = `angular_momentum:R.z` [M L^2 T^-1]: angular momentum about R, lab velocities
- $\tau_R$ = `torque:R.z` [M L^2 T^-2]: torque of gravity and the contact forces about R

### (92) Torque equation about R

$$
\frac{dL_R}{dt} = \tau_R
$$

*Kind:* on-shell

*Law:* the 1st `=` is the law of motion: dL_R/dt = τ_R, the torque law (35) about a fixed point.
"#;

fn verify_only(dir: &std::path::Path, n: &str) -> (Option<i32>, Value, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args([
            "verify",
            "--equations",
            dir.to_str().expect("utf-8"),
            "--only",
            n,
            "--json",
        ])
        .output()
        .expect("ladder runs");
    let v: Value = serde_json::from_slice(&out.stdout).unwrap_or(Value::Null);
    (
        out.status.code(),
        v,
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn a_new_point_of_the_lab_is_data_and_the_fixed_point_law_about_a_moving_one_is_caught() {
    let dir = copy_of_equations("lab-point");
    std::fs::write(dir.join("92-lab-point.md"), LAB_POINT).expect("write");
    let (code, v, err) = verify_only(&dir, "92");
    assert_eq!(code, Some(0), "{err}");
    let r = &v["equations"][0];
    assert_eq!(
        (&r["label"], &r["status"]),
        (&"(92)".into(), &"verified".into()),
        "{r}"
    );
    assert_eq!(
        (&r["law_step"], &r["off_motion"]),
        (&1.into(), &"fails".into()),
        "{r}"
    );
    // Planted: the same law about a point of the ladder, which moves.
    let moving = LAB_POINT.replace("R = lab:1/2,3/2", "R = ladder:1/4");
    std::fs::write(dir.join("92-lab-point.md"), moving).expect("write");
    let (code, v, err) = verify_only(&dir, "92");
    assert_eq!(code, Some(1), "{v}");
    assert!(err.contains("failed: (92)"), "{err}");
    assert_eq!(v["equations"][0]["status"], "failed");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A method the note does not make: the torque law about the lab point R = (l/2, 3l/2).
#[derive(Default)]
struct AboutLabPoint;

impl Derivation for AboutLabPoint {
    const NAME: &'static str = "about the lab point (l/2, 3l/2), L_P and (38)";
    fn residual<T: Scalar>(&self, l: &Ladder<T>, s: &State<T>) -> T {
        let (lhs, rhs) = torque_equation(&Reference::Lab(1, 3, 2), AngularMomentum::Absolute, l, s);
        lhs - rhs
    }
}

/// Planted: the rate of L about R set equal to the torque side about the moving point Q.
#[derive(Default)]
struct MixedPoints;

impl Derivation for MixedPoints {
    const NAME: &'static str = "planted: dL/dt about R, torque about Q";
    fn residual<T: Scalar>(&self, l: &Ladder<T>, s: &State<T>) -> T {
        let (lhs, _) = torque_equation(&Reference::Lab(1, 3, 2), AngularMomentum::Absolute, l, s);
        let (_, rhs) = torque_equation(&Reference::OnLadder(1, 4), AngularMomentum::Absolute, l, s);
        lhs - rhs
    }
}

#[test]
fn a_new_method_is_checked_like_the_notes_and_a_mixed_up_one_fails() {
    let cfg = Config {
        float_cases: 200,
        ..Config::default()
    };
    let good = check_derivation::<AboutLabPoint>(&cfg);
    assert!(good.iter().all(CheckReport::passed), "{:?}", names(&good));
    let bad = check_derivation::<MixedPoints>(&cfg);
    eprintln!("planted method: {:?}", names(&bad));
    assert!(
        !bad.iter().all(CheckReport::passed),
        "the planted method passed"
    );
}

fn names(r: &[CheckReport]) -> Vec<(&str, bool)> {
    r.iter().map(|c| (c.name, c.passed())).collect()
}

/// Heun's method (the explicit trapezoidal rule, order 2), or with `EULER_WEIGHTS` the planted
/// mistake of weighting its two slopes (1, 0), which is Euler's method (order 1).
struct Heun<const PLANTED: bool>;

impl<const PLANTED: bool, const N: usize> FixedMethod<N> for Heun<PLANTED> {
    fn advance<S: Ode<N>>(
        sys: &S,
        t: f64,
        y: &[f64; N],
        k1: &[f64; N],
        h: f64,
        evals: &mut u64,
    ) -> ([f64; N], Option<[f64; N]>) {
        let k2 = eval(sys, t + h, &std::array::from_fn(|i| y[i] + h * k1[i]));
        *evals += 1;
        let (w1, w2) = if PLANTED { (1.0, 0.0) } else { (0.5, 0.5) };
        (
            std::array::from_fn(|i| y[i] + h * (w1 * k1[i] + w2 * k2[i])),
            None,
        )
    }
}

/// |θ(T) − θ_exact(T)| for the fall from θ0 = 0.3 at rest, g/l = 4/3 (Ω² = 1), T = 1 (before the
/// ladder leaves the wall), with step h.
fn error_at_end<M: FixedMethod<2>>(h: f64) -> f64 {
    let scene = Ladder {
        m: 1.0,
        l: 0.75,
        g: 1.0,
    };
    let exact = PhaseOne::new(0.3, 0.0, scene.big_omega2()).expect("a fall");
    let end = 1.0;
    assert!(exact.separation().is_none_or(|s| s.time > end));
    let mut st = FixedStep::<M, 2>::new(0.0, [0.3, 0.0], h);
    let sys = WallPhase::new(&scene);
    while st.t() < end {
        st.step(&sys, end).expect("a step");
    }
    (st.y()[0] - exact.theta(end)).abs()
}

/// The observed order from steps h and h/2: log2 of the error ratio. For a method of order p it
/// is p + O(h) (the next term of the error expansion); at h = 1/50 on this smooth fall the
/// window p ± 0.15 holds it, and Euler's order 1 is far outside Heun's window.
fn observed_order<M: FixedMethod<2>>() -> f64 {
    let h = 1.0 / 50.0;
    (error_at_end::<M>(h) / error_at_end::<M>(h / 2.0)).log2()
}

#[test]
fn a_new_integrator_shows_its_order_against_the_exact_fall_and_a_wrong_weight_is_caught() {
    let heun = observed_order::<Heun<false>>();
    assert!((heun - 2.0).abs() < 0.15, "Heun's observed order {heun}");
    let planted = observed_order::<Heun<true>>();
    eprintln!("observed orders: Heun {heun:.4}, planted weights {planted:.4}");
    assert!(
        (planted - 2.0).abs() > 0.5,
        "the planted weights look second order: {planted}"
    );
    assert!(
        (planted - 1.0).abs() < 0.15,
        "Euler's observed order {planted}"
    );
}
